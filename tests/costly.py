"""Write ``tests/costly.txt``: the tests the default run leaves to ``-m slow`` for their cost.

The brief keeps the default suite within three minutes on two cores and sends long runs to the slow
suite. This picks them by measurement, not by guess: from a log of each test's cost — the
``GRAPHPLAN_TEST_CPU`` file (node id, phase, CPU seconds, pid; see conftest) or the output of
``pytest --durations=0`` — the costliest tests are marked slow, most costly first, until what is left
fits the budget (a share of the whole). Every module keeps its cheapest test in the default run, so
each file's behaviour is still exercised there; a module fixture's cost falls on the first test that
asks for it, so a second measurement after the first list shows what moved.

    python -m pytest --durations=0 > LOG; python tests/costly.py LOG 0.25 [--add]
"""
from __future__ import annotations

import re
import sys
from collections import Counter, defaultdict
from pathlib import Path

LIST = Path(__file__).with_name("costly.txt")
# the checks of issue 32's "done when" list stay in the default run whatever they cost: the cam's drawn
# phase angles, the phases' largest pressure angles, form 2a on continuation sheets
ALWAYS = ("test_the_phase_diagram_draws_the_printed_pressure_angles", "test_the_largest_pressure_angle_is_the_phases_maximum",
          "test_a_set_carries_form_1_then_form_2a")
DURATION = re.compile(r"\s*([\d.]+)s (?:call|setup|teardown)\s+(\S.*?)\s*$")


def costs(log: str) -> Counter:
    """Each test's cost (setup + call + teardown) from a CPU log or a ``--durations`` log."""
    out: Counter = Counter()
    for line in Path(log).read_text(encoding="utf-8").splitlines():
        parts = line.split("\t")
        if len(parts) == 4 and parts[1] in ("setup", "call", "teardown"):
            out[parts[0]] += float(parts[2])
        elif m := DURATION.match(line):
            out[m.group(2)] += float(m.group(1))
    return out


def costly(cost: Counter, share: float) -> list[tuple[str, float]]:
    """The tests to leave to the slow suite, costliest first, until the rest is ``share`` of the whole;
    each module's cheapest test stays."""
    by_module: dict[str, list[tuple[float, str]]] = defaultdict(list)
    for test, c in cost.items():
        by_module[test.split("::")[0]].append((c, test))
    kept = {min(tests)[1] for tests in by_module.values()} | {t for t in cost if any(a in t for a in ALWAYS)}
    left, budget = sum(cost.values()), share * sum(cost.values())
    out = []
    for test, c in cost.most_common():
        if left <= budget:
            break
        if test not in kept:
            out.append((test, c))
            left -= c
    return out


if __name__ == "__main__":
    old = set(LIST.read_text(encoding="utf-8").splitlines()) - {""} if LIST.exists() and "--add" in sys.argv else set()
    picked = costly(costs(sys.argv[1]), float(sys.argv[2]))
    names = sorted(t for t in old | {t for t, _ in picked}
                   if "/" not in t.split("::", 1)[-1] and not any(a in t for a in ALWAYS))   # ids that name no clone's path
    LIST.write_text("".join(f"{t}\n" for t in names), encoding="utf-8")
    print(f"{len(names)} tests in {LIST.name} ({len(picked)} from this log)")
