"""`graphplan diagrams`: s–v–a diagrams by graphical differentiation, measured and compared."""
from __future__ import annotations

import argparse
import sys

from graphplan.cli.common import lang_arg, lang_of, load_study, scene_arg, option_error
from graphplan.util.errors import GraphplanError
from graphplan.util.files import json_text, write_atomic

def _divisions_arg(text: str) -> int | list[float]:
    try:
        if "," in text:
            return [float(v) for v in text.split(",") if v.strip()]
        return int(text)
    except ValueError:
        raise option_error("--divisions", "op divisions", got=repr(text)) from None


def _format_arg(text: str) -> str | None:
    from graphplan.cli.plans import _format_arg as sheet_format
    return sheet_format(text)


def cmd_diagrams(args) -> int:
    from graphplan.drawing.diagrams import diagrams_svg
    from graphplan.graphic.diagrams import chord_diagrams
    from graphplan.graphic.tangents import ANGLE_ERROR_DEG
    from graphplan.report.diagrams import diagrams_json, diagrams_table
    st = load_study(args.scene, getattr(args, "lang", None))
    lang = lang_of(args, st)
    scene = st.mech.task.diagram          # the scene's [diagrams] table gives the defaults
    pick = lambda given, key, default: given if given is not None else scene.get(key, default)  # noqa: E731
    from graphplan.sheets.kinematics import A1_POSITIONS
    # the sheet's L, height and pole distances unless given; a scene of more positions than a sheet
    # holds has no kinematics sheet, and its diagrams are drawn at their own scales
    drawn = None
    if args.format and st.mech.task.count <= A1_POSITIONS:
        from graphplan.sheets.kinematics import PlansUndrawable, sheet_scales
        try:
            drawn = sheet_scales(st, args.format, None, None, args.precision)
        except PlansUndrawable:           # no sheet draws its plans: the diagrams at their own scales
            drawn = None
    extra = {}
    if drawn is not None:
        sheet = {"L_mm": drawn["L"], "H1_mm": drawn["H1"], "H2_mm": drawn["H2"]}
        pick = lambda given, key, default: given if given is not None else sheet.get(key, scene.get(key, default))  # noqa: E731
        if args.height is None and args.divisions is None and args.L is None:
            args.height = drawn["height"]
        # no option that shapes the drawing given: the diagrams exactly as the sheet draws them —
        # redrawn, where the first drawing is qualitatively wrong, with what the lab allows
        given = (args.point, args.divisions, args.L, args.h1, args.h2, args.method, args.angle_error)
        if (all(g is None for g in given) and not (args.adaptive or args.correct) and args.tolerance == 0.5
                and scene.get("method", "chords") == "chords"):
            chosen = drawn["diagrams"]
            extra = {"redrawn": chosen["redrawn"], "fit": chosen.get("fit", False)}   # the finer series μs where redrawn so
            args.adaptive, args.correct = chosen.get("adaptive", False), chosen.get("correct", False)
            args.tolerance = chosen.get("tolerance", args.tolerance)
    d = chord_diagrams(st, point=pick(args.point, "point", None), divisions=pick(args.divisions, "divisions", None),
                       L=pick(args.L, "L_mm", 240.0), H1=pick(args.h1, "H1_mm", 30.0),
                       H2=pick(args.h2, "H2_mm", 30.0),
                       precision=args.precision, adaptive=args.adaptive, height=args.height,
                       tolerance=args.tolerance, chosen=args.at, lang=lang,
                       method=pick(args.method, "method", "chords"), angle_error_deg=ANGLE_ERROR_DEG if args.angle_error is None else args.angle_error,
                       correct=args.correct, **extra)
    if args.svg:
        write_atomic(args.svg, diagrams_svg(d))
    if args.json:
        sys.stdout.write(json_text(diagrams_json(d)))
    else:
        sys.stdout.write(diagrams_table(d, lang))
    return 0


def register(sub) -> None:
    p = sub.add_parser("diagrams")
    scene_arg(p, optional=True)
    p.add_argument("--point", metavar="P")
    p.add_argument("--divisions", type=_divisions_arg, metavar="N")
    p.add_argument("--h1", type=float, metavar="MM")
    p.add_argument("--h2", type=float, metavar="MM")
    p.add_argument("--L", type=float, metavar="MM")
    p.add_argument("--precision", type=float, default=0.5, metavar="MM")
    p.add_argument("--adaptive", action="store_true")
    p.add_argument("--tolerance", type=float, default=0.5, metavar="MM")
    p.add_argument("--method", choices=("chords", "tangents"))
    p.add_argument("--angle-error", type=float, metavar="DEG")
    p.add_argument("--correct", action="store_true")
    p.add_argument("--height", type=float, metavar="MM")
    p.add_argument("--at", type=int, nargs="+", metavar="K")
    lang_arg(p)
    p.add_argument("--format", default="A1", type=_format_arg, metavar="A1")
    p.add_argument("--json", action="store_true")
    p.add_argument("--svg", metavar="FILE")
    p.set_defaults(handler=cmd_diagrams)

