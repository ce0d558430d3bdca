"""Stop 55 (misc55): a `graphplan serve` job is bounded by the processor time it uses, not by the wall
clock of a machine a class shares — the six-bar's kinematics sheet (about 25 s of work) was stopped
at 120 s while it still worked, the page saying it took too long. The wall clock bounds a job at
``pool.WALL`` times its bound, against a job that waits on nothing.

Each case is a stand-in worker (a small process speaking the pool's frames) that waits, or computes,
for a known time: what the bound does is read from what the process really did."""
from __future__ import annotations

import asyncio
import sys
import time

import pytest

from graphplan.web import pool as P

# a worker reading one frame, then sleeping (no processor) or spinning (all processor) for SECONDS
STAND_IN = r"""
import pickle, sys, time
src = sys.stdin.buffer
n = int.from_bytes(src.read(8), "big"); pickle.loads(src.read(n))
how, seconds = sys.argv[1], float(sys.argv[2])
t0 = time.monotonic()
if how == "sleep":
    time.sleep(seconds)
else:
    t = time.process_time()
    while time.process_time() - t < seconds:
        pass
data = pickle.dumps("answered")
sys.stdout.buffer.write(len(data).to_bytes(8, "big") + data); sys.stdout.buffer.flush()
"""


async def _ask(how: str, seconds: float, timeout: float):
    proc = await asyncio.create_subprocess_exec(sys.executable, "-c", STAND_IN, how, str(seconds),
                                                stdin=asyncio.subprocess.PIPE, stdout=asyncio.subprocess.PIPE)
    worker = P.Worker(proc)
    t0 = time.monotonic()
    try:
        out = await worker.ask(("job", "folder", ()), timeout)
    except asyncio.TimeoutError:
        out = "timed out"
    took = time.monotonic() - t0
    worker.kill()
    await proc.wait()
    return out, took


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="the processor time is read from /proc")
def test_a_job_waiting_past_its_bound_on_a_busy_machine_is_answered():
    """1.5 s on the wall with no processor used, under a 1 s bound: answered (a loaded machine's
    sheet), not stopped."""
    out, took = asyncio.run(_ask("sleep", 1.5, 1.0))
    assert out == "answered" and took >= 1.5


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="the processor time is read from /proc")
def test_a_job_computing_past_its_bound_is_stopped_by_the_processor_time(monkeypatch):
    """Computing 30 s of the processor under a 1 s bound, the wall's bound put out of reach (50 s):
    stopped by the processor time it used — on a machine that gives it a fifth of a core, within
    about 5 s — long before it would end."""
    monkeypatch.setattr(P, "WALL", 50.0)
    out, took = asyncio.run(_ask("spin", 30.0, 1.0))
    assert out == "timed out" and took < 20.0, took


def test_a_job_waiting_on_nothing_is_stopped_at_the_wall_bound():
    """Sleeping far past ``WALL`` times its bound: stopped at the wall bound."""
    out, took = asyncio.run(_ask("sleep", 30.0, 0.5))
    assert out == "timed out" and P.WALL * 0.5 - 0.1 <= took < P.WALL * 0.5 + 2.0, took
