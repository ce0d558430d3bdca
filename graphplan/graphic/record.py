"""The construction record: what a draftsman draws, in drawing millimetres (x right, y up).

Every plan, diagram and sheet is a ``Record`` of primitives; renderers (SVG, DXF, PDF, terminal)
only view it. Each primitive carries its kind, its role (absolute, relative, normal n, tangential τ,
Coriolis k, construction, …), the step it belongs to (the vector equation it solves, written as on
a sheet: "v_B = v_A + v_BA") and the layer it is drawn on.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from functools import lru_cache

from graphplan.util.markup import SMALL, SUB_SHIFT, Run, baseline_shift, is_plain, runs

Point = tuple[float, float]

# roles → line style: thick lines for links and result vectors, thin for construction (GOST 2.303)
THICK = 0.7
THIN = 0.25
ROLES = {
    "link": THICK, "absolute": THICK, "result": THICK, "frame": THICK,
    "relative": 0.5, "normal": 0.5, "tangential": 0.5, "coriolis": 0.5,
    "construction": THIN, "arc": THIN, "direction": THIN, "axis": THIN, "trajectory": THIN,
    "projection": THIN, "chord": 0.35, "ray": THIN, "curve": 0.5, "grid": 0.18, "label": THIN,
    "table": THIN, "hatch": THIN, "head": THIN,
}
DASHED_ROLES = {"axis": "dashdot", "trajectory": "dashdot", "projection": "dashed"}
LAYERS = ("frame", "mechanism", "construction", "vectors", "labels", "diagrams", "tables")


POINT_INK = {"joint": 1.0 + 0.175, "dot": 0.6 + 0.175}    # a point mark's ink radius, mm (drawing.svg)


@dataclass(frozen=True)
class Primitive:
    """One drawn thing. ``kind``: segment, vector (arrow at the end), polyline, polygon, circle,
    arc (centre, radius, start and end angles in degrees, counter-clockwise), point, text."""
    kind: str
    points: tuple[Point, ...]
    role: str = "construction"
    layer: str = "construction"
    step: str = ""
    text: str = ""
    size: float = 3.5            # text height h, mm: the capitals' height (GOST 2.304 series)
    radius: float = 0.0
    angles: tuple[float, float] = (0.0, 360.0)
    anchor: str = "start"        # text: start, middle, end
    width: float | None = None   # line width override, mm
    turn: float = 0.0            # text: degrees counter-clockwise about its anchor point (a vertical
    #                              dimension's number reads along its line, GOST 2.307: 90)

    @property
    def line_width(self) -> float:
        return self.width if self.width is not None else ROLES.get(self.role, THIN)

    def moved(self, dx: float, dy: float, k: float = 1.0) -> Primitive:
        """The primitive scaled by ``k`` about the origin, then shifted by (dx, dy)."""
        pts = tuple((x * k + dx, y * k + dy) for x, y in self.points)
        # every field by position: dataclasses.replace() took five times as long (a key sheet moves
        # 400 table primitives)
        return Primitive(self.kind, pts, self.role, self.layer, self.step, self.text, self.size,
                         self.radius * k, self.angles, self.anchor, self.width, self.turn)

    def bounds(self) -> tuple[float, float, float, float]:
        """The primitive's box (x0, y0, x1, y1), mm: its lines' (an arrowhead's corners included), a
        text's advance box and ink. Once per primitive (it is frozen): a sheet's layout asks the same
        drawings' boxes again and again (a cam sheet's search, a tenth of its time)."""
        got = self.__dict__.get("_bounds")
        if got is None:
            got = self.__dict__["_bounds"] = self._bounds()
        return got

    def _bounds(self) -> tuple[float, float, float, float]:
        if len(self.points) == 2 and self.kind not in ("circle", "arc", "text"):     # a segment, a vector
            (ax, ay), (bx, by) = self.points
            if self.kind == "vector":
                # the arrowhead's corners stand out of the shaft's box by up to its half width (a
                # horizontal vector's head 0.6 mm over the field of PUMP45's A3 force set)
                tri, _ = vector_arrow(self.points[0], self.points[1], self.line_width, self.role == "head")
                xs, ys = (ax, bx, tri[1][0], tri[2][0]), (ay, by, tri[1][1], tri[2][1])
                return min(xs), min(ys), max(xs), max(ys)
            return min(ax, bx), min(ay, by), max(ax, bx), max(ay, by)
        xs = [p[0] for p in self.points]
        ys = [p[1] for p in self.points]
        if self.kind == "point":
            # the mark as drawn (drawing.svg): a pair's ring r 1 mm, a dot r 0.6 mm, with half its
            # 0.35 mm stroke — COULISSE8's A1 force scheme set its top joint B flush with the field
            # (its box a bare point), the ring 1 mm over the field's edge
            r = POINT_INK["joint" if self.role == "joint" else "dot"]
            (cx, cy) = self.points[0]
            return cx - r, cy - r, cx + r, cy + r
        if self.kind == "circle" or (self.kind == "arc" and (self.angles[1] - self.angles[0]) % 360.0 == 0):
            (cx, cy), r = self.points[0], self.radius
            return cx - r, cy - r, cx + r, cy + r
        if self.kind == "arc":
            # the ends and whichever of the four axis points (0°, 90°, 180°, 270°) the arc passes
            (cx, cy), r = self.points[0], self.radius
            a0 = self.angles[0]
            sweep = (self.angles[1] - a0) % 360.0
            angles = [a0, a0 + sweep] + [q for q in (0.0, 90.0, 180.0, 270.0, 360.0, 450.0, 540.0, 630.0)
                                         if a0 % 360.0 <= q <= a0 % 360.0 + sweep]
            xs = [cx + r * math.cos(math.radians(a)) for a in angles]
            ys = [cy + r * math.sin(math.radians(a)) for a in angles]
            return min(xs), min(ys), max(xs), max(ys)
        if self.kind == "text":
            x, y = self.points[0]
            w = text_width(self.text, self.size)
            x0 = x - {"start": 0.0, "middle": w / 2, "end": w}[self.anchor]
            _, lo, _, hi = _ink(self.text, self.size, self.anchor, self.points[0])
            return turned((x0, min(y, lo), x0 + w, max(y + self.size, hi)), self.points[0], self.turn)
        return min(xs), min(ys), max(xs), max(ys)

    def ink(self) -> tuple[float, float, float, float]:
        """Where a text's letters put ink (the union of their glyph boxes, ``ink_boxes``), in drawing
        mm: lower than the baseline for descenders and subscripts, narrower than the advance box.
        Other primitives: their bounds."""
        if self.kind != "text":
            return self.bounds()
        got = self.__dict__.get("_ink")
        if got is None:
            got = self.__dict__["_ink"] = turned(_ink(self.text, self.size, self.anchor, self.points[0]),
                                                 self.points[0], self.turn)
        return got


def turned(box: tuple[float, float, float, float], at: Point, turn: float) -> tuple[float, float, float, float]:
    """The box (x0, y0, x1, y1) turned ``turn`` degrees counter-clockwise about ``at``: the box of its
    four corners turned (the turned box itself for the quarter turns lettering uses)."""
    if not turn:
        return box
    c, s = math.cos(math.radians(turn)), math.sin(math.radians(turn))
    xs, ys = [], []
    for x, y in ((box[0], box[1]), (box[2], box[1]), (box[0], box[3]), (box[2], box[3])):
        dx, dy = x - at[0], y - at[1]
        xs.append(at[0] + c * dx - s * dy)
        ys.append(at[1] + s * dx + c * dy)
    return min(xs), min(ys), max(xs), max(ys)


# characters osifont lacks, replaced on the drawing (records keep the real text). The minus sign
# (U+2212, which osifont lacks) is drawn as the en dash: in osifont a bar as long as the plus's
# (0.40 em against its 0.37) at the plus's height, and in the font a viewer falls back to when it
# ignores the sheet's @font-face (DejaVu Sans) a 0.40-em bar that fits the same advance — where its
# hyphen is a short dash (0.26 em) and its own minus (0.63 em) runs into the next figure, set at
# osifont's advances (docs/language.md, "The minus sign")
LETTERING = {"−": "–", "→": "->", "∑": "Σ", "√": "sqrt", "∆": "Δ", "ᵏ": "k", "ⁿ": "n", "ᵗ": "t",
             "₀": "0", "₁": "1", "₂": "2", "₃": "3", "₄": "4", "₅": "5", "₆": "6", "₇": "7", "₈": "8", "₉": "9",
             "“": '"', "”": '"', "„": '"'}     # English quotes: osifont has « » only (review 13: boxes on a cam's notes)
_LETTERING = str.maketrans(LETTERING)


# a hyphen-minus that begins a number — at the text's start or after a space, a bracket or "=" —
# is a sign typed as a hyphen ("-10" on an axis): drawn as the minus
_SIGN = re.compile(r"(?<![^\s(\[{=/;:])-(?=[0-9]|[.,][0-9])")


def lettering(text: str) -> str:
    """The text as drawn with the GOST font (osifont): missing characters replaced, the minus sign
    (typed as U+2212 or as a hyphen before a number) as the en dash (``LETTERING``)."""
    if "-" in text:
        text = _SIGN.sub("−", text)
    return text.translate(_LETTERING)


FONTS = ("graphplan-symbols.ttf", "osifont.ttf")     # osifont's own glyphs win over the symbols'
FOOT = 0.1        # ems: a glyph's "foot", its ink this low, is what a comma after it sits beside
METRICS = "metrics.json"      # what the lettering needs of the fonts, read once from them (metrics_from_fonts)
FALLBACK = "fallback.json"    # the ink boxes of the font a viewer letters with when it lacks ours (fallback_from_font)
FALLBACK_FAMILY = "DejaVu Sans"   # the sheets' font-family's second name: Debian's and most viewers' sans


def metrics_from_fonts() -> dict:
    """The packaged fonts' metrics in ems: each character's advance and ink box (x_min, y_min,
    x_max, y_max from the baseline at its origin; None for a blank such as the space), and the
    missing-glyph box's width — osifont's own glyphs over the symbols' font (graphplan/data/fonts).
    Stored in ``metrics.json`` beside the fonts, so that lettering is measured without parsing the
    fonts (tests/test_sheet.py checks the file against the fonts)."""
    from importlib import resources

    from fontTools.ttLib import TTFont
    folder = resources.files("graphplan") / "data" / "fonts"
    advance: dict[str, float] = {}
    boxes: dict[str, list[float] | None] = {}
    feet: dict[str, float | None] = {}
    missing = 0.5
    for name in FONTS:
        with TTFont(str(folder / name)) as font:              # read whole, the file closed at once
            em, widths, glyf = font["head"].unitsPerEm, font["hmtx"], font["glyf"]
            for code, g in sorted(font.getBestCmap().items()):
                advance[chr(code)] = round(widths[g][0] / em, 9)
                gl = glyf[g]
                if not getattr(gl, "numberOfContours", 0):
                    boxes[chr(code)], feet[chr(code)] = None, None
                    continue
                boxes[chr(code)] = [round(v / em, 9) for v in (gl.xMin, gl.yMin, gl.xMax, gl.yMax)]
                low = [x for x, y in _outline(gl, glyf) if y <= FOOT * em]
                feet[chr(code)] = round(max(low) / em, 9) if low else None
            missing = round(widths[".notdef"][0] / em, 9)
    return {"advance": advance, "boxes": boxes, "feet": feet, "missing": missing}


def _outline(gl, glyf, steps: int = 8) -> list[tuple[float, float]]:
    """Points along a TrueType glyph's outline: its quadratic curves sampled, not their control
    points (a round letter's ink near the baseline lies well inside its control polygon)."""
    coords, ends, flags = gl.getCoordinates(glyf)
    out: list[tuple[float, float]] = []
    start = 0
    for end in ends:
        pts = [(float(x), float(y), bool(f & 1)) for (x, y), f in zip(coords[start:end + 1], flags[start:end + 1])]
        start = end + 1
        if not pts:
            continue
        # the implied on-curve points between two off-curve ones
        full = []
        for i, p in enumerate(pts):
            q = pts[i - 1]
            if not p[2] and not q[2]:
                full.append(((p[0] + q[0]) / 2, (p[1] + q[1]) / 2, True))
            full.append(p)
        first = next((i for i, p in enumerate(full) if p[2]), 0)
        ring = full[first:] + full[:first] + [full[first]]
        i = 0
        while i < len(ring) - 1:
            a = ring[i]
            if ring[i + 1][2]:
                out += [(a[0], a[1]), (ring[i + 1][0], ring[i + 1][1])]
                i += 1
                continue
            c, b = ring[i + 1], ring[min(i + 2, len(ring) - 1)]
            for k in range(steps + 1):
                t = k / steps
                out.append(((1 - t) ** 2 * a[0] + 2 * t * (1 - t) * c[0] + t * t * b[0],
                            (1 - t) ** 2 * a[1] + 2 * t * (1 - t) * c[1] + t * t * b[1]))
            i += 2
    return out


def fallback_font() -> str | None:
    """The file of the fallback family (``FALLBACK_FAMILY``) on this machine, None when absent."""
    import shutil
    import subprocess
    from pathlib import Path
    known = Path("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf")
    if known.is_file():
        return str(known)
    if shutil.which("fc-match"):
        out = subprocess.run(["fc-match", "-f", "%{family}\t%{file}", FALLBACK_FAMILY],
                             capture_output=True, text=True, check=False).stdout
        family, _, file = out.partition("\t")
        if family.split(",")[0] == FALLBACK_FAMILY and Path(file).is_file():
            return file
    return None


def fallback_from_font(path: str) -> dict:
    """The fallback font's ink boxes in ems (x_min, y_min, x_max, y_max from the baseline at the
    glyph's origin) for every character the packaged fonts letter (``metrics_from_fonts``): a
    viewer without our font (Inkscape, rsvg, cairosvg, ImageMagick ignore the embedded @font-face)
    letters each character with this one at the x our font's advances gave it (drawing.svg), at
    the same em — so a label kept clear of lines by the union of both boxes is clear in either.
    Stored in ``fallback.json`` (tests/test_gallery.py checks it against the font when installed)."""
    from fontTools.ttLib import TTFont
    ours = _metrics()["boxes"]
    boxes: dict[str, list[float] | None] = {}
    with TTFont(path) as font:
        em, glyf, cmap = font["head"].unitsPerEm, font["glyf"], font.getBestCmap()
        for c in sorted(ours):
            g = cmap.get(ord(c))
            if g is None:
                continue
            gl = glyf[g]
            if not getattr(gl, "numberOfContours", 0):
                boxes[c] = None
                continue
            boxes[c] = [round(v / em, 9) for v in (gl.xMin, gl.yMin, gl.xMax, gl.yMax)]
    return {"family": FALLBACK_FAMILY, "boxes": boxes}


@lru_cache(maxsize=1)
def _fallback() -> dict[str, list[float] | None]:
    import json
    from importlib import resources
    path = resources.files("graphplan") / "data" / "fonts" / FALLBACK
    try:
        return json.loads(path.read_text(encoding="utf-8"))["boxes"]
    except OSError:               # a checkout without the derived file: the font itself, or none
        font = fallback_font()
        return fallback_from_font(font)["boxes"] if font else {}


@lru_cache(maxsize=1)
def _metrics() -> dict:
    import json
    from importlib import resources
    path = resources.files("graphplan") / "data" / "fonts" / METRICS
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except OSError:               # a checkout without the derived file: read the fonts themselves
        return metrics_from_fonts()


def left_bearing(text: str, size: float) -> float:
    """How much farther in, mm, a line's first glyph sets its ink than a capital's stem (Н: osifont's
    left side bearing 0.08 em; its R 0.22 em, N 0.19 em), 0 where not farther — taken off, lines of
    notes start their ink flush."""
    stem = (_metrics()["boxes"].get("Н") or [0.0])[0]
    for c in lettering(text):
        box = _metrics()["boxes"].get(c)
        if box is not None:       # a letter's (a figure's bearing is its tabular width's: left as set)
            return max(box[0] - stem, 0.0) * size if c.isalpha() else 0.0
        if c not in " \u00a0":
            return 0.0
    return 0.0


@lru_cache(maxsize=1)
def _advances() -> tuple[dict[str, float], float]:
    """The advance widths, in ems, of the lettering font that comes with the package (osifont,
    graphplan/data/fonts), and the width of its missing-glyph box."""
    m = _metrics()
    return m["advance"], m["missing"]


LOW = ",."          # punctuation on the baseline
JOINS = 1.2         # mm: a comma this close to the letter's foot reads as one word with it
APART = 1.0         # mm: a comma that cannot join its letter stands this far clear of its ink …
ENOUGH = 0.9        # … unless it already stands this far


BARRED = "ГТT"      # capitals with a bar over an open right side …
UNDER = "авгдежзиклмнопрстухцчшщъыьэюяєacemnopqrsuvwxyz"   # … and the small letters (no ascender, no dot) that tuck under it
UNDER_BAR = 0.04    # ems: how far inside the bar's end its ink then begins (osifont leaves 0.09–0.16 em between
                    # them, at 5 mm a gap the eye, and the ink check, take for a word break; DejaVu kerns T–a 0.17 em)


SUPERSCRIPTS = "⁰¹²³⁴⁵⁶⁷⁸⁹ⁿ"   # superscripts typed as characters: before a comma or full stop spaced as the markup's
#  (``kern``): osifont's ² left 0.53 mm to the comma's ink, set 1.0 mm apart by the ink rule; a viewer without the
#  font draws a wider ² and left 0.5 mm (the crusher's A2 Table 3, «I_rotor·i²,»: overprint.py --no-font's 1 word)


SCRIPT_SPACE = 0.1    # ems: a thin space between an index and the base letters after it (twice TeX's \scriptspace):
                      # "μ_φ·H" reads as two factors, the dot not tucked against the φ; twice that before a comma
                      # after a superscript ("M^Φ, N·m": the Φ's foot came within 0.3 mm of the comma)


def script_space(level: int, text: str, size: float) -> float:
    """The space (mm) before base letters ``text`` that follow an index of ``level`` (0: none):
    ``SCRIPT_SPACE``, twice that for a comma or full stop after a superscript."""
    if not level or not text:
        return 0.0
    return SCRIPT_SPACE * (2.0 if level == 1 and text[0] in LOW else 1.0) * em(size)


SIGNS = "+=±×"
SIGN_GAP = 0.04     # ems: the least paper between a sign's ink and a letter's beside it, in either font


def sign_gap(prev: str, c: str) -> float:
    """Extra space (ems) between a sign (+ = ± ×) and a letter it touches (no blank between), so
    that a viewer without our font keeps ``SIGN_GAP`` of paper between their ink. Such a sign is
    drawn centred on its osifont advance (drawing.svg): osifont's glyph exactly where its advance
    puts it, DejaVu Sans' (the fallback, ``FALLBACK``: 0.63 em wide on osifont's 0.47 em advance,
    symmetric in its own advance) overhanging it by 0.08 em each side — where, set from the same
    start, it ran 0.27 em into the next letter ("+5", "=–0,23")."""
    if not (prev in SIGNS or c in SIGNS) or not prev.strip() or not c.strip():
        return 0.0
    m, fb = _metrics(), _fallback()
    if fb.get(c) is None or fb.get(prev) is None:
        return 0.0
    adv = m["advance"].get(prev, m["missing"])

    def ink(ch: str) -> tuple[float, float]:       # its fallback ink from its osifont slot's start
        box = fb[ch]
        if ch not in SIGNS:
            return box[0], box[2]
        half, mid = (box[2] - box[0]) / 2, m["advance"].get(ch, m["missing"]) / 2
        return mid - half, mid + half
    return max(0.0, SIGN_GAP - (adv - ink(prev)[1] + ink(c)[0]))


@lru_cache(maxsize=65536)
def kern(prev: str, c: str, size: float, before: str = "") -> float:
    """Extra space (mm) before ``c`` after ``prev``: a comma or full stop after a letter with no ink
    near the baseline on its right (°, Г, Т, P, 7 …) stands apart from it, beside its box rather
    than tucked under it — the eye reads "60,2° , 93,2°" as two values, where a comma hidden under
    the degree sign reads as a stray mark. A small letter after Г, Т or T tucks under the bar,
    its ink beginning ``UNDER_BAR`` inside the bar's end (pairs osifont does not kern). Nothing otherwise (the font sets text by its
    advances). A sign (+ = ± ×) touching a letter stands ``sign_gap`` apart from it. ``before`` is the
    character before ``prev`` (a letter after an apostrophe tucked over b, h, k stands clear of it)."""
    # an ASCII ' after a letter is tucked only over b, h, k's open right (the lab's, the crank's): after
    # another letter it may be a prime (z'_2, whose index stands under it as z₂'s, review 48) — set as before
    prime = c == "'" and prev not in OPEN_RIGHT
    if prev == "'" and c.isalpha() and before and before in OPEN_RIGHT:
        return _after_tucked_apostrophe(c, size)
    if (prev in APOSTROPHES or c in APOSTROPHES) and prev.isalpha() != c.isalpha() and not prime:
        return _apostrophe_kern(prev, c, size)
    if prev in SIGNS or c in SIGNS:
        return sign_gap(prev, c) * em(size)
    if prev and c in UNDER and prev in BARRED:
        m = _metrics()
        bar, ink = m["boxes"][prev], m["boxes"].get(c)
        if ink is not None:            # the small letter's ink begins UNDER_BAR inside the bar's end
            return -(m["advance"][prev] - bar[2] + ink[0] + UNDER_BAR) * em(size)
    if c not in LOW or not prev.strip():
        return 0.0
    if prev in SUPERSCRIPTS:           # «I_rotor·i², kg·m²»: a superscript digit typed as such is a superscript,
        return script_space(1, c, size)   # its comma spaced by the markup's rule (``script_space``)
    m = _metrics()
    box, foot, cb = m["boxes"].get(prev), m["feet"].get(prev), m["boxes"].get(c)
    if box is None or cb is None:
        return 0.0
    e = em(size)
    adv = m["advance"].get(prev, m["missing"])
    if foot is not None and (adv - foot + cb[0]) * e <= JOINS:
        return 0.0
    gap = (adv - box[2] + cb[0]) * e
    return 0.0 if gap >= ENOUGH else APART - gap


APOSTROPHE = "\u2019"   # the Ukrainian apostrophe (м’які, п’ять): set close to its letters …
APOSTROPHE_GAP = 0.03    # ems: … its ink this far across from a small letter's on either side. osifont's
#  side bearings (0.13 em from м's ink, 0.08 em to я's) left it, high above the x-height, 1.3 mm across the
#  diagonal from both at 4.7-mm letters: a reader's eye (and overprint.py's 0.8-mm closing) took it for
#  a mark of its own inside the word's box (stop 55 lettered «нежорсткі» instead; stop 56: tucked in —
#  at 0.05 em it still stood apart at 10 of 75 placings on the 4-px/mm grid, at 0.04 and less at none)


APOSTROPHES = APOSTROPHE + "'"   # … and the English one (the lab's, the crank's), typed as ASCII
OPEN_RIGHT = "bhk"  # ascenders whose ink right of the stem ends at the x-height: an apostrophe after them
#  stands over that bowl, shoulder or arm as over a small letter. Set as a capital's, the YOKE11 English
#  notes' «lab's» (4.7-mm letters) left it 0.75 mm across and 1 mm above b's bowl: overprint.py's
#  0.8-mm closing took it for a mark of its own inside «lab»'s box (review 58)
OPEN_TUCK = 0.08    # ems: over such a letter the apostrophe's ink begins this far inside its box's right: b's
#  bowl curves away from its box's corner under it (tucked only to APOSTROPHE_GAP, «lab's» at 4.7-mm letters
#  still split at 3 of 9 placings on the 4-px/mm grid; at 0.07 em and more at none, its ink still apart)


ROUND_TOP = "acegmnopqs"   # small letters whose ink at the x-height curves away from their box's top right (a
#  bowl or shoulder): an apostrophe after them tucks OPEN_TUCK further, as over b, h, k. Tucked by the box alone,
#  «rise's» and «plan's» (4.7-mm letters) left the apostrophe 0.7 mm above and across the curve: overprint.py's
#  0.8-mm closing took it for a mark of its own inside the word's box (review 60: cam and forces sheets, en)


AFTER_APOSTROPHE = 0.16   # ems: a letter after an English apostrophe tucked over b, h or k's open right
#  stands this far across from the apostrophe's box. Tucked under it too, as after a prime (pair's) or the
#  Ukrainian one, the apostrophe — already moved left over k's arm — hung over the letter's shoulder: «crank's»
#  read «crankś» (stops 59, 60). Only after a tucked apostrophe: stop 59 set every letter after an English
#  apostrophe apart, and after a prime's full advance (pair's, train's) the s then stood a word of its own
#  (2 overprinted words on the English type-B gear sheet; reverted)


def _after_tucked_apostrophe(c: str, size: float) -> float:
    """``kern`` of a letter after an apostrophe tucked over b, h, k: the boxes ``AFTER_APOSTROPHE`` apart."""
    m = _metrics()
    a, b = m["boxes"].get("'"), m["boxes"].get(c)
    if a is None or b is None:
        return 0.0
    return (AFTER_APOSTROPHE - (m["advance"]["'"] - a[2] + b[0])) * em(size)


def _apostrophe_kern(prev: str, c: str, size: float) -> float:
    """``kern`` of an apostrophe after a letter or of a letter after it: tucked in (negative) until the
    two inks stand APOSTROPHE_GAP apart across — where the letter's ink stays under the apostrophe's
    (a small letter, or ``OPEN_RIGHT``'s before it; a capital or an ascender's top would meet it: left
    as set)."""
    m = _metrics()
    a, b = m["boxes"].get(prev), m["boxes"].get(c)
    if a is None or b is None:
        return 0.0
    mark, letter = (b, a) if c in APOSTROPHES else (a, b)
    top = letter[3]
    if c in APOSTROPHES and prev in OPEN_RIGHT and "n" in m["boxes"]:
        top = m["boxes"]["n"][3]               # the bowl's (shoulder's, arm's) height: the x-height
    if top >= mark[1]:
        return 0.0
    gap = m["advance"].get(prev, m["missing"]) - a[2] + b[0]
    if top < letter[3] or (c in APOSTROPHES and prev in ROUND_TOP):   # over a bowl's (shoulder's) curve:
        gap += OPEN_TUCK                       # its box's corner is not its ink's
    return -max(gap - APOSTROPHE_GAP, 0.0) * em(size)


TUCKED = "PРГТT7F"   # letters whose right side is open below a bar or bowl at half height or more
BOWLED = "PРF"       # … of them those whose bowl or bar ends at about half the height (0.45 in osifont)
BOWL_TOP = 0.35      # an index reaching higher than this (of the letter height) would meet that bowl (a capital, b, d: 0.4; з 0.30)
BOWL_GAP = 0.08      # the gap it keeps from the letter's ink then, of the letter height
TUCK_MORE = {**dict.fromkeys("COGQS", 0.06), **dict.fromkeys("AА", 0.25)}
#  capitals whose ink nearest a bowl lies off their box's top-left corner — round ones (their curve), A (its
#  slant, the box's corner is its foot's) — tuck this much more (of the letter height): set by the box, P_C's C
#  stood 0.89 mm from the bowl (P_D's D 0.59) and, in a viewer without our font hinted at 4 px/mm, read as a
#  word of its own under the P's box (stop 54's knee press); tucked, 0.73 mm
PRIMES = "'′″"       # a prime's index stands under it (``sub_kern``)
ARMED = "r"          # lowercase letters open below an arm at their top: the index starts under the arm's end


def sub_kern(prev: str, size: float, c: str, sub: float) -> float:
    """The shift (mm, negative: to the left) of a subscript ``c`` (letters ``sub`` high) after the
    letter ``prev``: after a letter open below on its right (P, Г, Т, F, 7) the index tucks in under
    its bowl or bar, its ink starting 0.15 of the letter height inside the letter's box, as a
    typesetter kerns it — set at the full advance it hangs apart, belonging to neither word. A tall
    letter index (a capital, b, d) after a bowl or a middle bar (P, Р, F) would reach up into it (the D
    of P_D touched the P's bowl): it keeps ``BOWL_GAP`` of the letter height clear of the letter's ink
    box — a round capital or an A (``TUCK_MORE``) tucked further, its curved or slanted top-left keeping
    about as near the bowl as a D's flat one, in our font and in the fallback; a digit (P₁ of the cam's pole) tucks in as before, its flag clear of the bowl. After a prime
    (z′₂, p′_ω, μ′_ω) the index stands under the prime, as a typesetter stacks z'_2 (the prime high,
    the index low, both after the letter): set after the prime's advance it hangs apart from its
    letter, read as a word of its own beside the primed letter (GEARS_B47's notes). After a lowercase
    r (``ARMED``: open below its arm, at the x-height) the index's ink starts under the arm's end, not
    tucked further (r_a would read as a ligature "ra")."""
    if prev in PRIMES:
        m = _metrics()
        return -m["advance"].get(prev, m["missing"]) * em(size)
    if prev in ARMED:             # (stop 53: the a of r_a at the full advance hung 0,6 mm right of the
        m = _metrics()            # arm, 1,7 mm off the stem, read as a word apart — a short index
        box, cb = m["boxes"].get(prev), m["boxes"].get(c)     # after an open r, as P's once)
        if box is None or cb is None:
            return 0.0
        adv = m["advance"].get(prev, m["missing"])
        return min(0.0, box[2] * em(size) - (adv * em(size) + cb[0] * em(sub)))
    if prev not in TUCKED:
        return 0.0
    m = _metrics()
    box, cb = m["boxes"].get(prev), m["boxes"].get(c)
    if box is None or cb is None:
        return 0.0
    adv = m["advance"].get(prev, m["missing"])
    inside = -0.15 * size
    if prev in BOWLED and c.isalpha() and cb[3] * em(sub) - SUB_SHIFT * size > BOWL_TOP * size:
        inside = BOWL_GAP * size
        inside -= TUCK_MORE.get(c, 0.0) * size      # a round capital's curved top-left, A's slant
    return min(0.0, (box[2] * em(size) + inside) - (adv * em(size) + cb[0] * em(sub)))


@lru_cache(maxsize=1)
def _glyph_boxes() -> dict[str, tuple[float, float, float, float] | None]:
    """Each character's ink box in ems, (x_min, y_min, x_max, y_max) from the baseline at its origin,
    where the packaged fonts or the fallback a viewer without them letters with (``fallback_from_font``)
    put ink — the union of both boxes (None: a blank, such as the space)."""
    other = _fallback()
    out: dict[str, tuple[float, float, float, float] | None] = {}
    for c, b in _metrics()["boxes"].items():
        f = other.get(c)
        if b is None or f is None:
            out[c] = tuple(b) if b is not None else None
        else:
            out[c] = (min(b[0], f[0]), min(b[1], f[1]), max(b[2], f[2]), max(b[3], f[3]))
    return out


@lru_cache(maxsize=16384)
def ink_boxes(text: str, size: float) -> tuple[tuple[float, float, float, float], ...]:
    """The ink of each drawn character (mm, from the text's start on its baseline): the font's glyph
    boxes at their advances, sub- and superscripts at their size and shift — where the letters
    really put ink (a lowercase line reaches only half the height of its capitals)."""
    advance, missing = _advances()
    boxes = _glyph_boxes()
    runs_ = [(text, 0.0, size, 0.0)] if is_plain(text) else [(r.text, x0, s, shift)
                                                             for r, x0, s, shift in run_offsets(text, size)]
    out = []
    for t, x, s, shift in runs_:
        before, prev = "", ""
        for c in lettering(t):
            e = em(s)
            x += kern(prev, c, s, before)
            b = boxes.get(c, (0.0, 0.0, missing, 0.72))
            if b is not None:
                out.append((x + b[0] * e, shift + b[1] * e, x + b[2] * e, shift + b[3] * e))
            x += advance.get(c, missing) * e
            before, prev = prev, c
    return tuple(out)


def _ink(text: str, size: float, anchor: str, at: Point) -> tuple[float, float, float, float]:
    x, y = at
    w = text_width(text, size)
    x0 = x - {"start": 0.0, "middle": w / 2, "end": w}[anchor]
    b = _ink_extent(text, size)
    return (x0, y, x0, y) if b is None else (x0 + b[0], y + b[1], x0 + b[2], y + b[3])


@lru_cache(maxsize=16384)
def _ink_extent(text: str, size: float) -> tuple[float, float, float, float] | None:
    """The union of a text's letters' ink boxes from its start on the baseline (None: no ink)."""
    boxes = ink_boxes(text, size)
    if not boxes:
        return None
    return (min(b[0] for b in boxes), min(b[1] for b in boxes), max(b[2] for b in boxes), max(b[3] for b in boxes))


@lru_cache(maxsize=1)
def cap_height() -> float:
    """The lettering font's capitals' height in ems (osifont's H: 0.737)."""
    return _metrics()["boxes"]["H"][3]


def em(size: float) -> float:
    """The font size (em, mm) that letters capitals ``size`` mm high: GOST 2.304's letter height h
    is the capitals' height, not the em."""
    return size / cap_height()


def line_pitch(size: float) -> float:
    """Baseline to baseline of lines of ``size`` mm lettering set one under another: the capitals,
    a subscript's depth and 2 mm of paper between one line's ink and the next (closer lines read as
    one block of ink, GOST 2.304 asks for at least the letter height between lines' bases anyway)."""
    return 1.6 * size + 2.0


@lru_cache(maxsize=32768)
def plain_width(text: str, size: float) -> float:
    """Width of ``text`` taken literally (no markup): the sum of the packaged font's advance widths ×
    the em and of ``kern``'s pairs (every letter is set at its own x, drawing.svg), a missing
    character as the font's box."""
    advance, box = _advances()
    drawn = lettering(text)
    return em(size) * sum(advance.get(c, box) for c in drawn) + sum(
        kern(a, b, size, z) for z, a, b in zip(" " + drawn, drawn, drawn[1:]))


def kerned(text: str, size: float) -> list[tuple[str, float]]:
    """The drawn text (``lettering``) cut where ``kern`` adds or takes space: (piece, extra space
    before it, negative where a letter tucks in)."""
    drawn = lettering(text)
    out: list[tuple[str, float]] = []
    start, extra = 0, 0.0
    for i in range(1, len(drawn)):
        k = kern(drawn[i - 1], drawn[i], size, drawn[i - 2] if i > 1 else "")
        if k:
            out.append((drawn[start:i], extra))
            start, extra = i, k
    out.append((drawn[start:], extra))
    return out


def run_offsets(text: str, size: float) -> list[tuple[Run, float, float, float]]:
    """Each run of the markup (util.markup) with its x offset from the text's start, its letter
    height and its baseline shift (mm, + up): sub- and superscripts 0.7 high, stacked ones over
    each other."""
    out = []
    x = 0.0
    start = 0.0
    prev: tuple[str, float] = ("", size)
    level = 0
    for r in runs(text):
        s = size * SMALL if r.level else size
        if r.stacked:
            x0 = start
        else:
            if r.level == -1 and level == 0 and prev[0] and r.text:
                x += sub_kern(prev[0][-1], prev[1], r.text[0], s)     # an index beside a P, Г, Т
            if r.level == 0:
                x += script_space(level, r.text, size)
            x0 = start = x
        level = r.level
        shift = baseline_shift(r.level, size)
        if r.level == 0:
            prev = (r.text, s)
        out.append((r, x0, s, shift))
        x = max(x, x0 + plain_width(r.text, s))
    return out


@lru_cache(maxsize=32768)
def text_width(text: str, size: float) -> float:
    """Width of GOST type-B lettering: about 0.6 of the height per character, plus the gaps;
    sub- and superscripts of the markup (util.markup) at their smaller size, stacked ones once."""
    if is_plain(text):
        return plain_width(text, size)
    return max((x0 + plain_width(r.text, s) for r, x0, s, _ in run_offsets(text, size)), default=0.0)


@dataclass
class Record:
    """A construction: its primitives in drawing mm, a title and the scale coefficients used."""
    title: str = ""
    items: list[Primitive] = field(default_factory=list)
    scales: dict[str, float] = field(default_factory=dict)

    def add(self, kind: str, points, **kw) -> Primitive:
        prim = Primitive(kind, tuple([(float(x), float(y)) for x, y in points]), **kw)
        self.items.append(prim)
        return prim

    # textbook-flavoured helpers ------------------------------------------------------------
    def segment(self, a: Point, b: Point, **kw) -> Primitive:
        return self.add("segment", [a, b], **kw)

    def vector(self, a: Point, b: Point, **kw) -> Primitive:
        """An arrow from a to b (the arrowhead at b)."""
        return self.add("vector", [a, b], **kw)

    def arc(self, centre: Point, radius: float, start: float, end: float, **kw) -> Primitive:
        """A compass arc ("засічка"): angles in degrees, counter-clockwise from start to end."""
        return self.add("arc", [centre], radius=radius, angles=(start, end), **kw)

    def circle(self, centre: Point, radius: float, **kw) -> Primitive:
        return self.add("circle", [centre], radius=radius, **kw)

    def label(self, at: Point, text: str, size: float = 3.5, anchor: str = "start", **kw) -> Primitive:
        kw.setdefault("role", "label")
        kw.setdefault("layer", "labels")
        return self.add("text", [at], text=text, size=size, anchor=anchor, **kw)

    def point(self, at: Point, **kw) -> Primitive:
        return self.add("point", [at], **kw)

    def bounds(self) -> tuple[float, float, float, float]:
        if not self.items:
            return 0.0, 0.0, 0.0, 0.0
        b = [p.bounds() for p in self.items]
        return min(x[0] for x in b), min(x[1] for x in b), max(x[2] for x in b), max(x[3] for x in b)

    def moved(self, dx: float, dy: float, k: float = 1.0) -> Record:
        return Record(self.title, [p.moved(dx, dy, k) for p in self.items], dict(self.scales))

    def extend(self, other: Record) -> None:
        self.items.extend(other.items)


LABEL_GAP = 0.8    # mm between an anchor and its label's box


@dataclass
class LabelRequest:
    """A label the construction asks for; the drawing room places it clear of the lines."""
    at: complex            # the anchor (a plan point, a joint), drawing mm
    text: str
    toward: complex = 1j   # preferred side (any non-zero complex)
    size: float = 3.5
    optional: bool = False
    step: str = ""
    gap: float = LABEL_GAP
    breaks: bool = False   # a joint's letter at a crowded point: set beside it, the thin lines under it broken
    sight: bool = False    # set beside its point only where no line passes between them (a hodograph's
                           # number across another branch of the curve reads as that branch's)
    across: bool = True    # its leader may cross a thick line (a link, a vector); False on the force
                           # drawings, where a force's name across a link reads as the other side's
    rivals: tuple = ()     # other points its label must not be read as (the same path's other positions):
                           # beside it only nearer its own point than any of them, else on a leader to it



def vector_arrow(a: Point, b: Point, line_width: float, head: bool = False) -> tuple[tuple[Point, Point, Point], Point]:
    """A vector's filled head and where its shaft ends. A thick vector's (0.5 mm and more) head is
    4 mm long and 2 mm wide, about three times its line, as the seeds' plans draw them (a 1.2 mm head
    on a 0.7 mm line hardly shows); a thin one's 2.5 × 1.2 mm (``arrowhead``, shorter on a short
    vector). The shaft ends halfway into the head: its round cap hidden, the point sharp.
    ``head`` (the role "head": an arc's arrow, ``arc_head``): the vector is all head, as long as it is."""
    thick = line_width >= 0.5
    if head:
        n = math.hypot(b[0] - a[0], b[1] - a[1])
        if n == 0:
            return (b, b, b), b
        ux, uy = (b[0] - a[0]) / n, (b[1] - a[1]) / n
        w = min(1.0 if thick else 0.6, n / 2.5)
        return (b, (a[0] - uy * w, a[1] + ux * w), (a[0] + uy * w, a[1] - ux * w)), b
    tip = arrowhead(a, b, length=4.0 if thick else 2.5, half_width=1.0 if thick else 0.6)
    base = ((tip[1][0] + tip[2][0]) / 2, (tip[1][1] + tip[2][1]) / 2)
    return tip, ((tip[0][0] + base[0]) / 2, (tip[0][1] + base[1]) / 2)


def arc_head(centre: complex, r: float, end_deg: float, sense: int, length: float = 3.0) -> tuple[Point, Point]:
    """Where an arc's arrowhead lies (tail, tip; draw it as a vector of role "head"): the tip at the
    arc's end (``end_deg``), the tail ``length`` mm back along the arc against ``sense`` (+1
    counter-clockwise), so the head sits on the arc — 3 × 1.2 mm on a thin arc, 3 × 2 on a thick one
    (an arc's 3 mm tangent drawn as a vector had a 1.2 × 0.6 mm head, too faint to read its sense)."""
    import cmath
    end = math.radians(end_deg)
    tip = centre + r * cmath.exp(1j * end)
    tail = centre + r * cmath.exp(1j * (end - sense * min(length / r, 1.0)))
    return (tail.real, tail.imag), (tip.real, tip.imag)


def arrowhead(a: Point, b: Point, length: float = 3.0, half_width: float = 0.6) -> tuple[Point, Point, Point]:
    """The filled triangle of an arrow at b (GOST: about 2.5–4 mm long)."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    n = math.hypot(dx, dy)
    if n == 0:
        return b, b, b
    ux, uy = dx / n, dy / n
    length = min(length, 0.4 * n)
    half_width = min(half_width, length / 4)
    base = (b[0] - ux * length, b[1] - uy * length)
    return b, (base[0] - uy * half_width, base[1] + ux * half_width), (base[0] + uy * half_width, base[1] - ux * half_width)
