"""The HTTP interface of `graphplan serve` (the contract's "HTTP" table, docs/serve.md).

Scenes travel as TOML text in the request body; answers are the files graphplan writes, or JSON
``{"error": "one line"}`` with the command line's text: 422 bad input, 413 a body over its limit (a
scene 1 MB, a table 10 MB), 503 with Retry-After when every worker is busy. Work runs in worker
processes (web/pool.py) or, for a teacher's keys, in a `graphplan key` process of its own; nothing
the client sends becomes a path; every answer carries a Content-Security-Policy.
"""
from __future__ import annotations

import asyncio
import hmac
import json
import os
import re
import secrets
import shutil
import sys
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

from starlette.applications import Starlette
from starlette.middleware import Middleware
from starlette.middleware.base import BaseHTTPMiddleware
from starlette.requests import Request
from starlette.responses import FileResponse, RedirectResponse, Response
from starlette.routing import Mount, Route
from starlette.staticfiles import StaticFiles

from graphplan.util.errors import GraphplanError
from graphplan.util.words import word
from graphplan.web.pool import Busy, Pool, TimedOut, WorkerDied

STATIC = Path(__file__).parent / "static"
SCENE_LIMIT = 1024 * 1024            # bytes of a scene (model.bounds.MAX_SCENE_BYTES)
TABLE_LIMIT = 10 * 1024 * 1024       # bytes of a table (variants, a student's table, a key)
CSP = ("default-src 'none'; script-src 'self'; style-src 'self'; img-src 'self' blob: data:; "
       "connect-src 'self'; font-src 'self'; form-action 'self'; base-uri 'none'; frame-ancestors 'none'")
COOKIE = "graphplan_token"


@dataclass
class Config:
    """How the server runs: ``token`` None on loopback (no token asked), else the one printed."""
    host: str = "127.0.0.1"
    port: int = 8000
    token: str | None = None
    workers: int = 2
    timeout: float = 120.0           # s a sheet, the explorer or a grading may take
    key_jobs: int = 2                # processes one key batch uses
    batches: int = 1                 # key batches at once
    batch_seconds: float = 1800.0    # a batch's time bound; its zip kept this long after it ends
    lang: str | None = None          # the page's first language
    allowed_hosts: list[str] = field(default_factory=list)


class Refused(Exception):
    """A request refused with ``status`` and one line: ``line`` as given (a text, or the text in each
    language — util.words.said — of which the answer speaks the request's, ``told``); ``lang`` the
    scene's language, spoken when the request names none."""

    def __init__(self, status: int, line: str | dict[str, str], headers: dict[str, str] | None = None,
                 lang: str | None = None):
        self.said = dict(line) if isinstance(line, dict) else {}
        text = self.said.get("en", "") if self.said else str(line)
        super().__init__(text)
        self.status, self.line, self.headers, self.lang = status, text, headers or {}, lang

    def told(self, lang: str) -> str:
        """The line in ``lang`` (as given where it says itself in one language only)."""
        return self.said.get(lang, self.line)


def refusal(status: int, key: str, /, where: str = "", headers: dict[str, str] | None = None,
            **fields: object) -> Refused:
    """A refusal worded by the catalogue (util.words ``key``), "where: text" in each language."""
    from graphplan.util.words import said
    texts = {lang: f"{where}: {text}" if where else text for lang, text in said(key, **fields).items()}
    return Refused(status, texts, headers)


def refused_error(status: int, exc: GraphplanError, folder: Path | None = None) -> Refused:
    """A GraphplanError as a refusal in both languages (its scene's language kept), without the
    request's folder."""
    from graphplan.util.words import LANGS
    texts = {}
    for lang in LANGS:
        text = exc.line(lang)
        if folder is not None:
            text = text.replace(f"{folder}/", "").replace(str(folder), ".")
        texts[lang] = text
    return Refused(status, texts, lang=exc.lang)


def told_lang(request: Request, scene: str | None = None) -> str:
    """The language an answer's line speaks: the request's ``?lang=``, else the scene's, else the
    server's --lang, else Ukrainian."""
    from graphplan.util.words import pick
    asked = request.query_params.get("lang")
    config = getattr(request.app.state, "config", None)
    return pick(asked if asked in ("uk", "en") else None, scene if scene in ("uk", "en") else None,
                getattr(config, "lang", None) if getattr(config, "lang", None) in ("uk", "en") else None)


def safe_json(doc: Any) -> bytes:
    """JSON with <, > and & as \\u escapes: no answer carries markup a browser could run."""
    text = json.dumps(doc, ensure_ascii=False)
    return text.replace("<", "\\u003c").replace(">", "\\u003e").replace("&", "\\u0026").encode("utf-8")


def error(status: int, line: str, headers: dict[str, str] | None = None) -> Response:
    return Response(safe_json({"error": line}), status, headers=headers, media_type="application/json")


def ok_json(doc: Any, status: int = 200) -> Response:
    return Response(safe_json(doc), status, media_type="application/json")


# -- reading the request ----------------------------------------------------------------------------

async def body(request: Request, limit: int, what: str) -> bytes:
    """The body, refused with 413 past ``limit`` bytes (before reading it when Content-Length says so)."""
    declared = request.headers.get("content-length")
    if declared and declared.isdigit() and int(declared) > limit:
        raise too_large(what, limit)
    chunks, size = [], 0
    async for chunk in request.stream():
        size += len(chunk)
        if size > limit:
            raise too_large(what, limit)
        chunks.append(chunk)
    data = b"".join(chunks)
    request._body = data                     # the form parser reads it again
    return data


def too_large(what: str, limit: int) -> Refused:
    if what == "scene":
        return refusal(413, "wb scene large", where="scene.toml", kb=limit // 1024)
    return refusal(413, "wb table large", where=what, kb=limit // 1024)


def scene_text(data: bytes) -> str:
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise refusal(422, "wb scene not utf8", where="scene.toml") from None


def lang_of(request: Request) -> str | None:
    lang = request.query_params.get("lang")
    if lang in (None, ""):
        return None
    if lang not in ("uk", "en"):
        raise refusal(422, "ap choice", arg="--lang", got=repr(lang[:20]), choices="'uk', 'en'")
    return lang


def number(request: Request, name: str, default: float, lo: float, hi: float, unit: str = "") -> float:
    raw = request.query_params.get(name)
    if raw in (None, ""):
        return default
    from graphplan.util.words import WORDS, unit as unit_in
    try:
        v = float(raw)
    except ValueError:
        raise refusal(422, "ap invalid", arg=f"--{name}", got=repr(raw[:20]),
                      kind=lambda lang: WORDS["ap kind float"][0 if lang == "uk" else 1]) from None
    import math
    if not (math.isfinite(v) and lo <= v <= hi):
        def said_unit(lang: str) -> str:
            text = unit_in(unit, lang) if unit else ""
            return text if text in ("", "°") else " " + text
        raise refusal(422, "op range", where=f"--{name}", lo=f"{lo:g}", open="", hi=f"{hi:g}", unit=said_unit,
                      got=f"{v:g}")
    return v


async def in_worker(request: Request, name: str, *args: Any) -> Response:
    """Run a job (web/jobs.py) in a worker; its Answer as the response."""
    pool: Pool = request.app.state.pool
    try:
        answer = await pool.run(name, *args)
    except Busy as exc:
        raise refusal(503, "wb busy", headers={"Retry-After": str(exc.retry_after)}) from None
    except TimedOut:
        raise refusal(422, "wb timeout", s=f"{pool.timeout:g}") from None
    except WorkerDied:
        raise refusal(500, "wb worker died") from None
    if answer.status != 200:
        return error(answer.status, answer.line)
    return Response(answer.body, 200, headers=answer.headers, media_type=answer.media)


# -- the routes ----------------------------------------------------------------------------------------

async def index(request: Request) -> Response:
    lang = request.app.state.config.lang
    if lang in ("uk", "en") and "lang" not in request.query_params:      # graphplan serve --lang
        return RedirectResponse(f"/?lang={lang}", 303)
    return FileResponse(STATIC / "index.html", media_type="text/html; charset=utf-8")


async def templates_(request: Request) -> Response:
    from graphplan.web.templates import catalogue
    return ok_json(catalogue())


async def toml_(request: Request) -> Response:
    """The form's values (JSON) → the scene's TOML (web/templates.py)."""
    from graphplan.web.templates import scene_toml
    data = await body(request, SCENE_LIMIT, "scene")
    lang_of(request)
    try:
        doc = json.loads(data.decode("utf-8"))
    except (UnicodeDecodeError, json.JSONDecodeError, RecursionError):
        raise refusal(422, "wb form json", where="form") from None
    try:
        text = scene_toml(doc)
    except GraphplanError as exc:
        raise refused_error(422, exc) from None
    return Response(text, media_type="text/plain; charset=utf-8")


async def preview(request: Request) -> Response:
    phi = number(request, "phi", 0.0, -1e6, 1e6, "deg")
    lang = lang_of(request)
    text = scene_text(await body(request, SCENE_LIMIT, "scene"))
    stack = request.query_params.get("stack", "") == "1"       # a phone's column: the assemblies one above the other
    answer = await in_worker(request, "preview", text, phi, lang, stack)
    from graphplan.web.jobs import file_stem
    answer.headers["X-File-Stem"] = file_stem(text)      # the page names the TOML it saves so
    return answer


async def check(request: Request) -> Response:
    lang = lang_of(request)
    text = scene_text(await body(request, SCENE_LIMIT, "scene"))
    return await in_worker(request, "check", text, lang)


def _kinds(request: Request) -> list[str]:
    from graphplan.web.jobs import KINDS
    raw = request.query_params.get("kind", "")
    kinds = [k.strip() for k in raw.split(",") if k.strip()]
    for k in kinds:
        if k not in KINDS:
            raise refusal(422, "ap choice", arg="--sheet", got=repr(k[:20]), choices=", ".join(KINDS))
    if len(set(kinds)) != len(kinds):
        raise refusal(422, "wb kind twice", where="--sheet")
    return kinds


async def sheet(request: Request) -> Response:
    from graphplan.web.jobs import TYPES
    kinds = _kinds(request)
    fmt = request.query_params.get("format", "A1")
    if fmt.upper() not in ("A1", "A2", "A3", "A4"):
        raise refusal(422, "op sheet format", where="--format", got=repr(fmt[:20]), formats="A1, A2, A3, A4")
    kind_of_file = request.query_params.get("type", "svg").lower()
    if kind_of_file not in TYPES:
        raise refusal(422, "op out format", where=f"-o sheet.{kind_of_file[:10]}", formats=".svg, .pdf, .png, .dxf")
    dpi = number(request, "dpi", 300.0, 30.0, 600.0)
    lang = lang_of(request)
    text = scene_text(await body(request, SCENE_LIMIT, "scene"))
    return await in_worker(request, "sheet", text, kinds, fmt.upper(), kind_of_file, lang, dpi)


def explorer_csp(page: bytes) -> str:
    """The explorer is one file with its script inline: the policy allows exactly that script (its
    hash), nothing else runs."""
    import base64
    import hashlib
    text = page.decode("utf-8")
    hashes = ["'sha256-" + base64.b64encode(hashlib.sha256(m.encode("utf-8")).digest()).decode() + "'"
              for m in re.findall(r"<script[^>]*>(.*?)</script>", text, flags=re.S)]
    return (f"default-src 'none'; script-src {' '.join(hashes) or chr(39) + 'none' + chr(39)}; "
            "style-src 'unsafe-inline'; img-src data: blob:; base-uri 'none'; form-action 'none'")


async def view(request: Request) -> Response:
    lang = lang_of(request)
    text = scene_text(await body(request, SCENE_LIMIT, "scene"))
    answer = await in_worker(request, "view", text, lang)
    if answer.status_code == 200:
        answer.headers["Content-Security-Policy"] = explorer_csp(answer.body)
    return answer


async def tables(request: Request) -> Response:
    lang = lang_of(request)
    text = scene_text(await body(request, SCENE_LIMIT, "scene"))
    return await in_worker(request, "tables", text, lang)


async def form_files(request: Request, names: dict[str, tuple[int, str]]) -> dict[str, bytes]:
    """The multipart parts ``names`` (each with its limit and what it is), refused when missing or
    too large; a part's own file name is never used."""
    await body(request, sum(limit for limit, _ in names.values()) + 64 * 1024, "upload")
    ctype = request.headers.get("content-type", "")
    if not ctype.startswith("multipart/form-data"):
        raise refusal(422, "wb multipart", names=", ".join(names))
    try:
        form = await request.form(max_files=len(names) + 2, max_fields=20)
    except Exception as exc:                 # the parser's own refusal (a malformed body)
        raise refusal(422, "wb form unreadable", why=" ".join(str(exc).split())[:120]) from None
    out: dict[str, bytes] = {}
    for name, (limit, what) in names.items():
        part = form.get(name)
        if part is None:
            raise refusal(422, "wb no part", name=repr(name), what=what)
        data = await part.read() if hasattr(part, "read") else str(part).encode("utf-8")
        if len(data) > limit:
            raise too_large("scene" if limit == SCENE_LIMIT else what, limit)
        out[name] = data
    await form.close()
    return out


async def check_students(request: Request) -> Response:
    lang = lang_of(request)
    parts = await form_files(request, {"key": (TABLE_LIMIT, "key.json"), "student": (TABLE_LIMIT, "student.csv")})
    signed = request.query_params.get("signed") in ("1", "true", "yes")
    answer = await in_worker(request, "grade", parts["key"], parts["student"], signed, lang)
    if answer.status_code == 200 and request.query_params.get("format") == "csv":
        return Response(grades_csv(json.loads(answer.body)), media_type="text/csv; charset=utf-8",
                        headers={"Content-Disposition": 'attachment; filename="grades.csv"'})
    return answer


def grades_csv(doc: dict[str, Any]) -> str:
    """The graded rows of `check --json` as CSV (one row each, the same fields)."""
    import csv
    import io
    cols = ["line", "variant", "position", "quantity", "value", "exact", "error_pct", "tolerance_pct",
            "status", "note"]
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(cols)
    for r in doc["rows"]:
        w.writerow(["" if r.get(c) is None else _cell(r.get(c)) for c in cols])
    return buf.getvalue()


def _cell(v: Any) -> str:
    text = str(v)
    return "'" + text if text[:1] in ("=", "+", "@") or (text[:1] == "-" and not _is_number(text)) else text


def _is_number(text: str) -> bool:
    try:
        float(text)
        return True
    except ValueError:
        return False


# -- teachers' keys: a `graphplan key` process per batch -------------------------------------------------

@dataclass
class Batch:
    id: str
    folder: Path
    total: int
    started: float
    state: str = "running"           # running, done, failed
    error: str = ""                  # why it failed, in ``lang``
    lang: str = "uk"
    ended: float = 0.0
    proc: Any = None
    stem: str = "keys"               # the zip's name: the base scene's designation and a fingerprint

    def done_count(self) -> int:
        if self.state == "done":
            return self.total
        return sum(1 for _ in self.folder.rglob("key.json"))

    def status(self) -> dict[str, Any]:
        return {"job": self.id, "state": self.state, "done": self.done_count(), "total": self.total,
                "error": self.error}


_BASE_DIRECTIVE = re.compile(r"^\s*#\s*base\s*=", re.I)


def variants_text(data: bytes) -> str:
    """The variants table with its base scene the uploaded one: a '# base =' line is replaced, a
    'base' column refused (it would name a file on the server)."""
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise refusal(422, "wb table not utf8", where="variants.csv") from None
    lines = [ln for ln in text.splitlines() if not _BASE_DIRECTIVE.match(ln)]
    header = next((ln for ln in lines if ln.strip() and not ln.strip().startswith("#")), "")
    delim = ";" if ";" in header else "\t" if "\t" in header else ","
    if "base" in [h.strip().strip('"') for h in header.split(delim)]:
        raise refusal(422, "wb base column", where="variants.csv")
    return "# base = base.toml\n" + "\n".join(lines) + "\n"


def _strip(line: str, folder: Path) -> str:
    line = line.strip()
    if line.startswith("graphplan: "):
        line = line[len("graphplan: "):]
    return line.replace(f"{folder}/", "").replace(str(folder), ".")


async def start_batch(request: Request) -> Batch:
    from graphplan.model import variants as vt
    state = request.app.state
    expire(state)
    parts = await form_files(request, {"variants": (TABLE_LIMIT, "variants.csv"), "base": (SCENE_LIMIT, "base.toml")})
    lang = lang_of(request)
    table = variants_text(parts["variants"])
    running = [b for b in state.batches.values() if b.state == "running"]
    if len(running) >= state.config.batches:
        raise refusal(503, "wb keys busy", headers={"Retry-After": "30"})
    folder = state.pool.root / ("key-" + secrets.token_hex(8))
    folder.mkdir()
    (folder / "variants.csv").write_text(table, encoding="utf-8")
    (folder / "base.toml").write_bytes(parts["base"])
    try:
        total = len((await asyncio.to_thread(vt.read, folder / "variants.csv")).variants)
    except GraphplanError as exc:
        shutil.rmtree(folder, ignore_errors=True)
        raise refused_error(422, exc, folder) from None
    from graphplan.web.jobs import file_stem
    base = parts["base"].decode("utf-8-sig", "replace")
    batch = Batch(secrets.token_hex(12), folder, total, time.monotonic(),
                  lang=told_lang(request, vt.base_lang(folder / "variants.csv", table)),
                  stem=file_stem(base, parts["variants"].decode("utf-8-sig", "replace")) + "-keys")
    state.batches[batch.id] = batch
    args = [sys.executable, "-m", "graphplan", "key", "variants.csv", "-o", "keys", "--quiet",
            "--jobs", str(state.config.key_jobs)]
    if lang:
        args += ["--lang", lang]
    env = dict(os.environ)
    here = str(Path(__file__).resolve().parents[2])          # the graphplan this server runs
    env["PYTHONPATH"] = here + (os.pathsep + env["PYTHONPATH"] if env.get("PYTHONPATH") else "")
    batch.proc = await asyncio.create_subprocess_exec(*args, cwd=folder, env=env, stdin=asyncio.subprocess.DEVNULL,
                                                      stdout=asyncio.subprocess.DEVNULL,
                                                      stderr=asyncio.subprocess.PIPE, start_new_session=True,
                                                      preexec_fn=_die_with_server)
    batch.task = asyncio.create_task(finish_batch(batch, state.config.batch_seconds))  # type: ignore[attr-defined]
    return batch


def _die_with_server() -> None:
    """In the key process before it runs: killed when the server dies, even by SIGKILL (Linux's
    PR_SET_PDEATHSIG; its own workers die with it the same way, cli/key.py)."""
    import signal
    try:
        import ctypes
        ctypes.CDLL(None, use_errno=True).prctl(1, int(signal.SIGKILL), 0, 0, 0)
    except (OSError, AttributeError):
        pass


async def finish_batch(batch: Batch, bound: float) -> None:
    """Wait for the key process (killed past ``bound`` s); the folder zipped when it succeeds."""
    try:
        _, err = await asyncio.wait_for(batch.proc.communicate(), bound)
    except asyncio.TimeoutError:
        kill(batch)
        batch.state, batch.error = "failed", word("wb keys timeout", batch.lang, s=f"{bound:g}")
        batch.ended = time.monotonic()
        shutil.rmtree(batch.folder, ignore_errors=True)
        return
    except asyncio.CancelledError:
        kill(batch)
        raise
    lines = [ln for ln in err.decode("utf-8", "replace").splitlines() if ln.strip()]
    if batch.proc.returncode != 0:
        batch.state = "failed"
        batch.error = (_strip(lines[-1], batch.folder) if lines
                       else word("wb key ended", batch.lang, code=batch.proc.returncode))
        shutil.rmtree(batch.folder, ignore_errors=True)
    else:
        await asyncio.to_thread(zip_folder, batch.folder / "keys", batch.folder / "keys.zip")
        batch.state = "done"
    batch.ended = time.monotonic()


def zip_folder(folder: Path, target: Path) -> None:
    from graphplan.web.jobs import zipped
    files = [(p.relative_to(folder).as_posix(), p.read_bytes()) for p in sorted(folder.rglob("*")) if p.is_file()]
    target.write_bytes(zipped(files))
    shutil.rmtree(folder, ignore_errors=True)


def kill(batch: Batch) -> None:
    import signal
    if batch.proc is not None and batch.proc.returncode is None:
        try:
            os.killpg(batch.proc.pid, signal.SIGKILL)
        except (ProcessLookupError, PermissionError):
            pass


def expire(state) -> None:
    """Forget batches whose zip has waited longer than the bound (their folder removed)."""
    now = time.monotonic()
    for bid, b in list(state.batches.items()):
        if b.state != "running" and now - b.ended > state.config.batch_seconds:
            shutil.rmtree(b.folder, ignore_errors=True)
            del state.batches[bid]


def take_zip(state, batch: Batch) -> Response:
    data = (batch.folder / "keys.zip").read_bytes()
    shutil.rmtree(batch.folder, ignore_errors=True)
    state.batches.pop(batch.id, None)
    return Response(data, media_type="application/zip",
                    headers={"Content-Disposition": f'attachment; filename="{batch.stem}.zip"'})


async def key(request: Request) -> Response:
    """The key folder as a zip (waits for it); with ?wait=0 the job's id at once (202) to poll."""
    batch = await start_batch(request)
    if request.query_params.get("wait") == "0":
        return ok_json(batch.status(), 202)
    try:
        await asyncio.shield(batch.task)                       # type: ignore[attr-defined]
    except asyncio.CancelledError:
        kill(batch)
        raise
    if batch.state != "done":
        request.app.state.batches.pop(batch.id, None)
        return error(422, batch.error)
    return take_zip(request.app.state, batch)


def _batch(request: Request) -> Batch:
    expire(request.app.state)
    b = request.app.state.batches.get(request.path_params["job"])
    if b is None:
        raise refusal(404, "wb no batch")
    return b


async def key_status(request: Request) -> Response:
    return ok_json(_batch(request).status())


async def key_zip(request: Request) -> Response:
    b = _batch(request)
    if b.state == "running":
        raise refusal(409, "wb not ready")
    if b.state == "failed":
        request.app.state.batches.pop(b.id, None)
        return error(422, b.error)
    return take_zip(request.app.state, b)


# -- the middleware: token, origin, the security headers -----------------------------------------------

def loopback(host: str) -> bool:
    import ipaddress
    if host in ("localhost",):
        return True
    try:
        return ipaddress.ip_address(host.strip("[]")).is_loopback
    except ValueError:
        return False


class Guard(BaseHTTPMiddleware):
    async def dispatch(self, request: Request, call_next):
        cfg: Config = request.app.state.config
        try:
            response = await self.guarded(request, call_next, cfg)
        except Refused as exc:
            response = error(exc.status, exc.told(told_lang(request, exc.lang)), exc.headers)
        response.headers.setdefault("Content-Security-Policy", CSP)
        response.headers["X-Content-Type-Options"] = "nosniff"
        response.headers["Referrer-Policy"] = "no-referrer"
        response.headers["X-Frame-Options"] = "DENY"
        if request.url.path.startswith("/api/"):
            response.headers["Cache-Control"] = "no-store"
        return response

    async def guarded(self, request: Request, call_next, cfg: Config):
        host = (request.headers.get("host") or "").rsplit(":", 1)[0].strip("[]")
        if cfg.allowed_hosts and host not in cfg.allowed_hosts:
            raise refusal(421, "wb host", host=repr(host[:60]))
        origin = request.headers.get("origin")
        if origin and origin != "null" and origin.split("://", 1)[-1] != request.headers.get("host"):
            raise refusal(403, "wb other site")
        if cfg.token:
            given = request.headers.get("authorization", "")
            bearer = given[7:] if given.lower().startswith("bearer ") else ""
            cookie = request.cookies.get(COOKIE, "")
            if not (hmac.compare_digest(bearer, cfg.token) or hmac.compare_digest(cookie, cfg.token)):
                asked = request.query_params.get("token", "")
                if request.method == "GET" and request.url.path == "/" and hmac.compare_digest(asked, cfg.token):
                    r = RedirectResponse("/", 303)
                    r.set_cookie(COOKIE, cfg.token, httponly=True, samesite="strict")
                    return r
                raise refusal(401, "wb token")
        try:
            return await call_next(request)
        except Refused as exc:
            return error(exc.status, exc.told(told_lang(request, exc.lang)), exc.headers)


async def refused_handler(request: Request, exc: Exception) -> Response:
    assert isinstance(exc, Refused)
    return error(exc.status, exc.told(told_lang(request, exc.lang)), exc.headers)


async def not_found(request: Request, exc: Exception) -> Response:
    from graphplan.util.words import word
    status = getattr(exc, "status_code", 404)
    key = "wb not found" if status == 404 else "wb not allowed" if status == 405 else "wb refused"
    return error(status, word(key, told_lang(request)))


def create_app(config: Config | None = None, pool: Pool | None = None) -> Starlette:
    config = config or Config()
    from contextlib import asynccontextmanager

    @asynccontextmanager
    async def lifespan(app):
        app.state.pool = pool or Pool(config.workers, config.timeout)
        await app.state.pool.warm()
        app.state.batches = {}

        async def sweep():                       # batches not downloaded: removed after their time
            while True:
                await asyncio.sleep(60)
                expire(app.state)
        sweeper = asyncio.create_task(sweep())
        try:
            yield
        finally:
            sweeper.cancel()
            for b in list(app.state.batches.values()):
                kill(b)
                if b.proc is not None:             # reaped while the loop runs: no pipe left to a closed loop
                    try:
                        await asyncio.wait_for(b.proc.wait(), 2)
                    except (asyncio.TimeoutError, ProcessLookupError):
                        pass
            await app.state.pool.close()

    routes = [
        Route("/", index, methods=["GET"]),
        Route("/api/templates", templates_, methods=["GET"]),
        Route("/api/toml", toml_, methods=["POST"]),
        Route("/api/scene/preview", preview, methods=["POST"]),
        Route("/api/scene/check", check, methods=["POST"]),
        Route("/api/sheet", sheet, methods=["POST"]),
        Route("/api/view", view, methods=["POST"]),
        Route("/api/tables", tables, methods=["POST"]),
        Route("/api/key", key, methods=["POST"]),
        Route("/api/key/{job}", key_status, methods=["GET"]),
        Route("/api/key/{job}/zip", key_zip, methods=["GET"]),
        Route("/api/check", check_students, methods=["POST"]),
        Mount("/static", StaticFiles(directory=STATIC), name="static"),
    ]
    app = Starlette(routes=routes, middleware=[Middleware(Guard)], lifespan=lifespan,
                    exception_handlers={Refused: refused_handler, 404: not_found, 405: not_found})
    app.state.config = config
    return app


ENV = "GRAPHPLAN_SERVE_CONFIG"


def from_env() -> Starlette:
    """The application uvicorn starts by name (`graphplan serve`): its Config from $GRAPHPLAN_SERVE_CONFIG."""
    raw = os.environ.get(ENV, "{}")
    return create_app(Config(**json.loads(raw)))


def config_json(config: Config) -> str:
    return json.dumps(asdict(config))
