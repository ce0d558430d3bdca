"""Worker processes with a time bound and a bound on how many work at once.

Each worker is a process of its own (``python -m graphplan.web.pool``: no fork of the server's threads,
no re-import of its main module) that imports the solver and the sheets once and then runs web.jobs
one at a time, talking in pickled frames over its stdin and stdout. A job that
outlives its time bound — seconds of the processor's time it used, or four times as many on the wall
clock — has its worker killed (and a fresh one started in its place) — so a scene of
3600 positions cannot hold the server. When every worker is busy, ``Busy`` (the route answers 503 with
Retry-After). Every job works in a folder of its own under the server's one temporary folder
(``graphplan-serve-PID-…``), removed after the job, and the whole folder when the server stops; a
server killed outright leaves it behind, and the next start removes the folders of dead servers.
"""
from __future__ import annotations

import asyncio
import os
import re
import secrets
import shutil
import sys
import tempfile
from pathlib import Path
from typing import Any

PREFIX = "graphplan-serve-"


class Busy(Exception):
    """Every worker is busy: try again after ``retry_after`` seconds."""

    def __init__(self, retry_after: int = 2):
        super().__init__("the server is busy")
        self.retry_after = retry_after


class TimedOut(Exception):
    """A job ran past its time bound (its worker was stopped)."""


class WorkerDied(Exception):
    """A worker ended in the middle of a job (killed from outside, or crashed)."""


WALL = 4.0                    # a job's wall-clock bound, in times its bound of processor time
MEMORY = 4 * 1024 ** 3        # bytes of address space a worker may take (an A1 PNG at 600 dpi needs ~1.2 GB)


def _die_with_parent(parent: int) -> None:
    """Linux's PR_SET_PDEATHSIG: the worker is killed when the server dies, even by SIGKILL."""
    import signal
    try:
        import ctypes
        ctypes.CDLL(None, use_errno=True).prctl(1, int(signal.SIGKILL), 0, 0, 0)
    except (OSError, AttributeError):
        pass
    if os.getppid() != parent:
        os._exit(1)


def _frame(obj: Any) -> bytes:
    import pickle
    data = pickle.dumps(obj, protocol=pickle.HIGHEST_PROTOCOL)
    return len(data).to_bytes(8, "big") + data


def main() -> None:
    """A worker's loop (``python -m graphplan.web.pool PARENT``): (name, folder, args) frames in on
    stdin, Answer frames out on the original stdout; anything printed goes to stderr."""
    import pickle
    import signal
    signal.signal(signal.SIGINT, signal.SIG_IGN)       # the server's Ctrl-C is the server's to handle
    _die_with_parent(int(sys.argv[1]))
    try:
        import resource
        resource.setrlimit(resource.RLIMIT_AS, (MEMORY, MEMORY))
    except (ImportError, ValueError, OSError):
        pass
    out = os.fdopen(os.dup(1), "wb")
    os.dup2(2, 1)                                      # a stray print cannot break the frames
    src = sys.stdin.buffer
    from graphplan.util.memory import collect_less_often, keep_freed_memory
    keep_freed_memory()
    collect_less_often()
    from graphplan.web import jobs
    for module in ("graphplan.exact.positions", "graphplan.model.scene", "graphplan.sheets.sheet",
                   "graphplan.drawing.svg", "graphplan.drawing.plans"):
        __import__(module)
    while True:
        head = src.read(8)
        if len(head) < 8:
            return
        name, folder, args = pickle.loads(src.read(int.from_bytes(head, "big")))
        try:
            answer = jobs.run(name, folder, *args)
        finally:
            shutil.rmtree(folder, ignore_errors=True)
        out.write(_frame(answer))
        out.flush()


class Worker:
    """One worker process and its pipes (asyncio)."""

    def __init__(self, proc):
        self.proc = proc

    @classmethod
    async def start(cls) -> "Worker":
        env = dict(os.environ)
        here = str(Path(__file__).resolve().parents[2])          # the graphplan this server runs
        env["PYTHONPATH"] = here + (os.pathsep + env["PYTHONPATH"] if env.get("PYTHONPATH") else "")
        proc = await asyncio.create_subprocess_exec(
            sys.executable, "-m", "graphplan.web.pool", str(os.getpid()), env=env,
            stdin=asyncio.subprocess.PIPE, stdout=asyncio.subprocess.PIPE)
        return cls(proc)

    async def ask(self, msg: Any, timeout: float) -> Any:
        """Send a job and wait for its answer while the job has used less than ``timeout`` seconds of
        the processor (``cpu_seconds``) and the wall clock is under ``WALL`` times that; then
        asyncio.TimeoutError. A machine shared by a class makes a sheet of 25 s of work take 80 s
        (stop 55: the six-bar's kinematics sheet, stopped at 120 s while it still worked): the bound
        is what the job costs, the wall's only against a job that waits on nothing."""
        import pickle
        import time
        self.proc.stdin.write(_frame(msg))
        await self.proc.stdin.drain()

        async def answer():
            head = await self.proc.stdout.readexactly(8)
            return pickle.loads(await self.proc.stdout.readexactly(int.from_bytes(head, "big")))
        task = asyncio.ensure_future(answer())
        start, used = time.monotonic(), self.cpu_seconds()
        try:
            while True:
                wall = time.monotonic() - start
                left = min(timeout, WALL * timeout - wall)
                if left <= 0:
                    raise asyncio.TimeoutError
                done, _ = await asyncio.wait({task}, timeout=min(left, max(0.05, timeout / 4)))
                if done:
                    return task.result()
                now = self.cpu_seconds()
                if now is None or used is None:       # no /proc: the wall clock alone
                    if time.monotonic() - start >= timeout:
                        raise asyncio.TimeoutError
                elif now - used >= timeout:
                    raise asyncio.TimeoutError
        finally:
            if not task.done():
                task.cancel()

    def cpu_seconds(self) -> float | None:
        """The worker's processor time so far (user + system, /proc/PID/stat), None where unknown."""
        try:
            with open(f"/proc/{self.proc.pid}/stat", "rb") as f:
                fields = f.read().rsplit(b")", 1)[1].split()
            return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")
        except (OSError, ValueError, IndexError):
            return None

    def kill(self) -> None:
        if self.proc.returncode is None:
            try:
                self.proc.kill()
            except ProcessLookupError:
                pass

    async def stop(self) -> None:
        try:
            self.proc.stdin.close()
            await asyncio.wait_for(self.proc.wait(), 2)
        except (asyncio.TimeoutError, OSError, RuntimeError):
            self.kill()
            try:                                   # reaped while the loop runs (no pipe left to a closed loop)
                await asyncio.wait_for(self.proc.wait(), 5)
            except (asyncio.TimeoutError, OSError, RuntimeError):
                pass


def clean_stale(root: Path | None = None) -> list[Path]:
    """Remove the temporary folders of servers that are no longer running (killed outright)."""
    root = Path(root or tempfile.gettempdir())
    removed = []
    for d in root.glob(PREFIX + "*"):
        m = re.match(re.escape(PREFIX) + r"(\d+)-", d.name)
        if not m or not d.is_dir():
            continue
        pid = int(m.group(1))
        try:
            os.kill(pid, 0)
            continue                                   # its server is alive
        except ProcessLookupError:
            pass
        except PermissionError:
            continue
        shutil.rmtree(d, ignore_errors=True)
        removed.append(d)
    return removed


class Pool:
    """``size`` workers, each job bounded by ``timeout`` seconds."""

    def __init__(self, size: int = 2, timeout: float = 120.0, root: Path | None = None,
                 queue_wait: float = 20.0, queue: int | None = None):
        self.size, self.timeout = max(1, size), timeout
        self.queue_wait = queue_wait              # s a request waits for a free worker before 503
        self.queue = 16 * self.size if queue is None else queue   # requests that may wait at once
        self.waiting = 0
        self.freed: asyncio.Event | None = None
        clean_stale(root)
        self.root = Path(tempfile.mkdtemp(prefix=f"{PREFIX}{os.getpid()}-", dir=root))
        self.idle: list[Worker] = []
        self.dead: list[Worker] = []               # killed mid-job: reaped on close (their pipes closed in the loop)
        self.busy = 0

    async def warm(self) -> None:
        """Start the workers now (their imports take a second) instead of at the first request."""
        while len(self.idle) + self.busy < self.size:
            self.idle.append(await Worker.start())

    def folder(self) -> Path:
        """A fresh job folder's path under the server's temporary folder (a random name)."""
        return self.root / secrets.token_hex(8)

    async def take(self) -> Worker:
        """An idle worker, a new one below ``size``, or — when all work — a wait of at most
        ``queue_wait`` s in a queue of at most ``queue`` requests; then Busy."""
        import time
        deadline = time.monotonic() + self.queue_wait
        while not self.idle and self.busy >= self.size:
            left = deadline - time.monotonic()
            if left <= 0 or self.waiting >= self.queue:
                raise Busy(max(1, round(self.queue_wait / 4)))
            self.freed = self.freed or asyncio.Event()
            self.waiting += 1
            try:
                await asyncio.wait_for(self.freed.wait(), left)
            except asyncio.TimeoutError:
                pass
            finally:
                self.waiting -= 1
        return await self._take()

    def _release(self) -> None:
        if self.freed is not None:
            self.freed.set()
            self.freed = None

    async def _take(self) -> Worker:
        if self.idle:
            self.busy += 1
            return self.idle.pop()
        if self.busy + len(self.idle) < self.size:
            self.busy += 1
            try:
                return await Worker.start()
            except BaseException:
                self.busy -= 1
                raise
        raise Busy()

    async def run(self, name: str, *args: Any, timeout: float | None = None):
        """Run job ``name`` in a worker; Busy when all are working, TimedOut past the bound."""
        worker = await self.take()
        folder = self.folder()
        ok = False
        try:
            answer = await worker.ask((name, str(folder), args), timeout or self.timeout)
            ok = True
            return answer
        except asyncio.TimeoutError:
            raise TimedOut() from None
        except (asyncio.IncompleteReadError, OSError, BrokenPipeError, ConnectionResetError):
            raise WorkerDied() from None
        finally:
            self.busy -= 1
            if ok:
                self.idle.append(worker)
            else:                  # stopped mid-job (time bound, a cancelled request): a fresh one later
                worker.kill()
                self.dead = [w for w in self.dead if w.proc.returncode is None] + [worker]
                shutil.rmtree(folder, ignore_errors=True)
            self._release()

    async def close(self) -> None:
        for w in self.idle + self.dead:
            await w.stop()
        self.idle.clear()
        self.dead.clear()
        shutil.rmtree(self.root, ignore_errors=True)


if __name__ == "__main__":
    main()
