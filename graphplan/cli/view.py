"""`graphplan view`: the offline interactive explorer, one self-contained HTML file."""
from __future__ import annotations

import argparse
from pathlib import Path

from graphplan.cli.common import lang_arg, lang_of, load_study, scene_arg, option_error, range_fields
from graphplan.util.errors import GraphplanError
from graphplan.util.files import write_atomic


def cmd_view(args: argparse.Namespace) -> int:
    """The page written atomically; the command's own refusals in the language asked for (--lang, else
    the scene's)."""
    import math

    from graphplan.report.explorer import explorer_html
    from graphplan.util.words import pick, word
    out = Path(args.output)
    lang = pick(getattr(args, "lang", None), None)
    if out.suffix.lower() not in (".html", ".htm"):
        raise GraphplanError(word("view html", lang, name=out))
    if out.exists() and out.is_dir():
        raise GraphplanError(word("view folder", lang, name=out))
    from graphplan.cli.sheet import _cam_scene
    cam = _cam_scene(args.scene)
    if cam is not None:
        return view_cam(cam, args, out)
    st = load_study(args.scene, getattr(args, "lang", None))
    lang = lang_of(args, st)
    if not (math.isfinite(args.step) and 0.05 <= args.step <= 30):
        raise GraphplanError(word("view step", lang, step=f"{args.step:g}"))
    if not (math.isfinite(args.precision) and 0 <= args.precision <= 10):
        raise GraphplanError(word("view precision", lang, p=f"{args.precision:g}"))
    plans = sheet_plans(st, args.format, args.precision)
    write_atomic(out, explorer_html(st, precision=args.precision, step=args.step, lang=lang, plans=plans,
                                          sheet=args.format if plans is not None else None))
    return 0


def view_cam(cam, args: argparse.Namespace, out: Path) -> int:
    """A cam scene's page: the cam turning, the pressure angle live, the phase diagram, the diagrams and
    the profile by inversion (report.camview), the construction of `graphplan cam` (its precision)."""
    import math

    from graphplan.exact.cam import solve
    from graphplan.report.camview import cam_html
    from graphplan.sheets.cam import construct_on
    from graphplan.sheets.form import form
    from graphplan.util.words import pick
    lang = pick(getattr(args, "lang", None), dict(cam.meta).get("lang"))
    if not (math.isfinite(args.step) and 0.05 <= args.step <= 30):
        raise option_error("--step", "op range", **range_fields(0.05, 30, "deg", False, args.step))
    if not (math.isfinite(args.precision) and 0 <= args.precision <= 10):
        raise option_error("--precision", "op range", **range_fields(0, 10, "mm", False, args.precision))
    try:
        sol = solve(cam)
        g = construct_on(sol, form("A1"), None, args.precision)    # the numbers of `graphplan cam`
    except GraphplanError as exc:
        raise GraphplanError(str(exc), exc.where or args.scene, exc.said, exc.lang) from None
    write_atomic(out, cam_html(sol, g, step=args.step, lang=lang, scene=args.scene))
    return 0


def sheet_plans(st, format: str | None, precision: float):
    """The plans at the scales the kinematics sheet of ``format`` draws with (the page's graphical
    readings equal `plans --json` and the sheet's), or at the plans' own scales for None."""
    from graphplan.graphic.plans import build_plans
    if not format:
        return None
    from graphplan.sheets.kinematics import sheet_scales
    drawn = sheet_scales(st, format, precision=precision)
    return build_plans(st, precision=precision, mu_l=drawn["mu_l"], mu_v=drawn["mu_v"], mu_a=drawn["mu_a"])


def register(sub) -> None:
    p = sub.add_parser("view")
    scene_arg(p, optional=True)
    p.add_argument("-o", "--output", required=True, metavar="FILE.html")
    lang_arg(p)
    p.add_argument("--precision", type=float, default=0.5, metavar="MM")
    from graphplan.cli.plans import _format_arg
    p.add_argument("--format", default="A1", type=_format_arg, metavar="A1")
    p.add_argument("--step", type=float, default=1.0, metavar="DEG")
    p.set_defaults(handler=cmd_view)
