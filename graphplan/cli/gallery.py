"""The gallery: `python -m graphplan.cli.gallery` redraws drawings/ from examples/ (the test
tests/test_gallery.py checks the committed sheets are current)."""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

# (scene, sheet kind, language, file name)
SHEETS = [
    ("crank_slider", "kinematics", "uk", "crank_slider.svg"),
    ("lab_crank_slider", "kinematics", "uk", "lab_crank_slider.svg"),
    ("four_bar", "kinematics", "uk", "four_bar.svg"),
    ("shaper", "kinematics", "uk", "shaper.svg"),
    ("shaper", "kinematics", "en", "shaper_en.svg"),
    ("slotter", "kinematics", "uk", "slotter.svg"),
    ("shaper", "forces", "uk", "shaper_forces.svg"),
    ("slotter", "forces", "uk", "slotter_forces.svg"),
    ("shaper", "dynamics", "uk", "shaper_dynamics.svg"),
    ("slotter", "dynamics", "uk", "slotter_dynamics.svg"),
]


def build(scene: str, kind: str, lang: str) -> str:
    """One gallery sheet as SVG text (A1, default precision)."""
    from graphplan.exact.positions import study
    from graphplan.model.scene import load
    from graphplan.sheets.sheet import BUILDERS
    from graphplan.sheets.form import form
    args = argparse.Namespace(positions=None, accel=None, precision=0.5, lang=lang, sheet=kind)
    st = study(load(ROOT / "examples" / f"{scene}.toml"))
    return BUILDERS[kind](st, form("A1"), args).svg()


# the interactive explorer of each example (graphplan view), on a 2° grid to keep each page small
EXPLORERS = ["crank_slider", "lab_crank_slider", "four_bar", "shaper", "slotter"]
EXPLORER_STEP = 2.0


def explorer(scene: str, lang: str = "uk") -> str:
    """One example's offline explorer page (HTML text)."""
    from graphplan.exact.positions import study
    from graphplan.model.scene import load
    from graphplan.report.explorer import explorer_html
    st = study(load(ROOT / "examples" / f"{scene}.toml"))
    return explorer_html(st, precision=0.5, step=EXPLORER_STEP, lang=lang)


def available() -> list[tuple[str, str, str, str]]:
    from graphplan.sheets.sheet import BUILDERS
    return [s for s in SHEETS if s[1] in BUILDERS]


def main(argv: list[str] | None = None) -> int:
    from graphplan.util.files import write_atomic
    parser = argparse.ArgumentParser(prog="python -m graphplan.cli.gallery", description=__doc__)
    parser.add_argument("-o", "--out", default=str(ROOT / "drawings"), help="folder (default: drawings/)")
    args = parser.parse_args(argv)
    for scene, kind, lang, name in available():
        path = write_atomic(Path(args.out) / name, build(scene, kind, lang))
        print(path, file=sys.stderr)
    for scene in EXPLORERS:
        path = write_atomic(Path(args.out) / f"{scene}.html", explorer(scene))
        print(path, file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
