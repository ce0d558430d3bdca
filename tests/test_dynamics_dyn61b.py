"""A dynamics set reads in the order of the work on every format (review 61 finding 4: the hopper
gate's A3 set put Tables 1–3 and ω(φ) on its first sheet, form 1, and the construction after them —
M*(φ) and A(φ) on sheet 2, ΔT(φ), the energy–mass diagram and I*(φ) on sheet 3 — where its A2 set
read M*/A, then the band, then ω(φ) and the tables): the drawings first appear sheet by sheet as the
work makes them — the moments and the work, then ΔT(φ), the energy–mass diagram and I*(φ), then
ω(φ) and the results' tables (Tables 2 and 3) — and a |kl| the order costs is said in the notes."""
from __future__ import annotations

import re

import pytest
from conftest import scene_sheet
from review_scenes import DYN61B_GATE, LINK53
from test_dynamics_set_scales import COMPRESSOR

# the stages of the work, each the drawings (and the results' tables) it makes, in the order made
STAGES = (("moments",), ("energy", "wittenbauer", "inertia"), ("speed", "flywheel table", "motor table"))


def _first_sheet(sheet) -> dict[str, int]:
    """Each block's first sheet, read by the sheets' own lettered numbers (form 1's, then form 2a's)."""
    at: dict[str, int] = {}
    for page in sorted(sheet.pages, key=lambda p: int(p.fields["sheet"])):
        for p in page.placed:
            at.setdefault(p.name, int(page.fields["sheet"]))
    return at


@pytest.mark.slow                     # three A3/A2 sets composed: ~3 min of CPU
@pytest.mark.parametrize("scene, fmt, lang", [(DYN61B_GATE, "A3", "en"), (DYN61B_GATE, "A2", "en"),
                                              (COMPRESSOR, "A3", "en"), (LINK53, "A3", "uk")],
                         ids=["gate-A3", "gate-A2", "compressor-A3", "link53-A3"])
def test_a_dynamics_set_reads_the_construction_before_the_results(scene, fmt, lang):
    sheet = scene_sheet(scene, "dynamics", fmt, lang, numbered=True)
    assert len(sheet.pages) > 1
    at = _first_sheet(sheet)
    stage = [min(at[name] for name in names) for names in STAGES]
    last = [max(at[name] for name in names) for names in STAGES]
    assert at["moments"] == min(at.values()), at          # the set opens (form 1) with M*(φ) and A(φ)
    assert last[0] <= stage[1] and last[1] <= stage[2], at   # each stage's drawings before the next's
    # what the order costs is said: a |kl| shorter than the A1 sheet's carries the A1 sheet's in the notes
    kl = [t.text for page in sheet.pages for p in page.placed for t in p.record.items
          if t.kind == "text" and (t.text or "").startswith("|kl| = ")]
    drawn = float(re.match(r"\|kl\| = ([\d.,]+)", kl[0]).group(1).replace(",", "."))
    assert drawn >= 0.5 / 0.02 - 1e-9, kl                  # the ruler's 0.5 mm within 2 % of |kl|
