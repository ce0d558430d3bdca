"""`graphplan serve`: the lab's web page on this machine (graphplan/web, docs/serve.md).

The web room sits beside the command line (neither imports the other): this command checks its
options, then has uvicorn start the application by its name, ``graphplan.web.app:from_env``, with the
configuration in the environment — as uvicorn starts any application."""
from __future__ import annotations

import argparse
import ipaddress
import json
import math
import os
import secrets
import sys

from graphplan.cli.common import lang_of, option_error, range_fields
from graphplan.util.errors import GraphplanError, said_error
from graphplan.util.words import word

APP = "graphplan.web.app:from_env"
ENV = "GRAPHPLAN_SERVE_CONFIG"


def is_loopback(host: str) -> bool:
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host.strip("[]")).is_loopback
    except ValueError:
        return False


def _reachable(host: str) -> str:
    """The address to print: for every interface (0.0.0.0, ::) the one a classroom reaches this machine
    by (the interface a route out leaves by; no packet is sent), else the host as given."""
    if host not in ("0.0.0.0", "::", ""):
        return host
    import socket
    try:
        with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
            s.connect(("192.0.2.1", 9))              # TEST-NET-1: nothing is sent by a UDP connect
            return s.getsockname()[0]
    except OSError:
        return socket.gethostname()


def can_listen(host: str, port: int) -> None:
    """The address can be listened on (bound once here, then let go): else one line — a host that is
    no address of this machine, a port in use or not allowed — before anything is printed."""
    import errno
    import socket
    try:
        infos = socket.getaddrinfo(host or None, port, type=socket.SOCK_STREAM, flags=socket.AI_PASSIVE)
    except (socket.gaierror, UnicodeError):
        raise said_error(GraphplanError, "sv cannot listen", None, None, host=host, port=port,
                         why=lambda lang: word("sv no such host", lang)) from None
    family, kind, proto, _, address = infos[0]
    try:
        with socket.socket(family, kind, proto) as s:
            s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)        # as uvicorn binds
            s.bind(address)
    except OSError as exc:
        key = {errno.EADDRINUSE: "sv port in use", errno.EACCES: "sv port denied",
               errno.EADDRNOTAVAIL: "sv no such host"}.get(exc.errno)
        raise said_error(GraphplanError, "sv cannot listen", None, None, host=host, port=port,
                         why=(lambda lang: word(key, lang)) if key else str(exc.strerror or exc)) from None


def cmd_serve(args: argparse.Namespace) -> int:
    try:
        import uvicorn
        import starlette  # noqa: F401
        import multipart  # noqa: F401
    except ImportError as exc:
        raise said_error(GraphplanError, "sv needs", None, None, name=exc.name) from None
    if not 1 <= args.port <= 65535:
        raise option_error("--port", "op whole", lo=1, hi=65535, got=args.port)
    if not 1 <= args.workers <= 16:
        raise option_error("--workers", "op whole", lo=1, hi=16, got=args.workers)
    if not (math.isfinite(args.timeout) and 1 <= args.timeout <= 3600):
        raise option_error("--timeout", "op range", **range_fields(1, 3600, "s", False, args.timeout))
    can_listen(args.host, args.port)
    local = is_loopback(args.host)
    token = None if local else secrets.token_urlsafe(24)
    shown = _reachable(args.host)
    shown = f"[{shown}]" if ":" in shown else shown
    url = f"http://{shown}:{args.port}/" + (f"?token={token}" if token else "")
    if args.lang:
        url += ("&" if token else "?") + f"lang={args.lang}"
    config = {"host": args.host, "port": args.port, "token": token, "workers": args.workers,
              "timeout": args.timeout, "lang": args.lang,
              "allowed_hosts": ["127.0.0.1", "localhost", "::1"] if local else []}
    os.environ[ENV] = json.dumps(config)
    lang = lang_of(args)
    print(word("sv started", lang, url=url, shared="" if local else word("sv shared", lang)), file=sys.stderr,
          flush=True)
    if args.open:
        import threading
        import webbrowser
        threading.Timer(1.0, webbrowser.open, (url,)).start()
    uvicorn.run(APP, factory=True, host=args.host, port=args.port, log_level="warning",
                timeout_graceful_shutdown=5)
    return 0


def register(sub) -> None:
    p = sub.add_parser("serve")
    p.add_argument("--host", default="127.0.0.1")
    p.add_argument("--port", type=int, default=8000)
    p.add_argument("--open", action="store_true")
    p.add_argument("--workers", type=int, default=2)
    p.add_argument("--timeout", type=float, default=120.0, metavar="S")
    p.add_argument("--lang", choices=("uk", "en"), default=None)
    p.set_defaults(handler=cmd_serve)
