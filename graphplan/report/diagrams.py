"""`graphplan diagrams`: the contract's JSON and the tables for the terminal (Ukrainian or English)."""
from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from graphplan.drawing.diagrams import fmt, method_words, mu, scale_lines, scale_symbols, units  # noqa: F401
from graphplan.graphic.diagrams import judged_pct
from graphplan.util.markup import plain, subscripted
from graphplan.util.words import fixed, num, pct, unit, word
from graphplan.util.romanize import scene_title

if TYPE_CHECKING:
    from graphplan.graphic.diagrams import Diagrams


def _num(v) -> float | None:
    """A finite number, or None (JSON null) for a value that is not one (no amplification, no error)."""
    if v is None:
        return None
    v = float(v)
    return v if math.isfinite(v) else None


def _entry(values: dict, pct: dict, truth: dict, key: str, k: int, mm: float, big: float | None = None) -> dict[str, Any]:
    """A reading: mm, value, analytic, error_pct (of the analytic value) and, where ``big`` (the
    cycle's maximum) is given, error_pct_judged as the sheet's diagrams table prints it (``judged_pct``)."""
    out = {"mm": float(mm), "value": float(values[key][k]), "analytic": float(truth[key][k]),
           "error_pct": _num(pct[key][k])}
    if big is not None:
        out["error_pct_judged"] = float(judged_pct(values[key][k], truth[key][k], big))
    return out


def diagrams_json(d: Diagrams) -> dict[str, Any]:
    """The contract's ``diagrams --json`` document, with the lab's table and the diagnostics."""
    from graphplan.graphic.diagrams import ruler_effect
    n = d.divisions
    r = d.drawn
    values, truth = d.values(), d.truth
    pct = {key: d.errors_pct(key) for key in ("s", "v_mid", "a_mid", "v_at", "a_at")}
    cell = lambda key, k, mm: _entry(values, pct, truth, key, k, mm)  # noqa: E731
    at = lambda phi, t: {"phi_deg": float(phi), "t": float(t)}  # noqa: E731
    s = [at(d.phi[k], d.t[k]) | cell("s", k, r.s[k]) for k in range(n + 1)]
    v = [at(d.phi_mid[k], d.t_mid[k]) | cell("v_mid", k, r.v[k]) for k in range(n)]
    a = [at(d.phi_mid[k], d.t_mid[k]) | cell("a_mid", k, r.a[k]) for k in range(n)]
    positions = []
    for k in range(n):
        positions.append({"index": k, "position": d.position[k]} | at(d.phi[k], d.t[k]) | {
            "s": _entry(values, pct, truth, "s", k, r.s[k], d.maxima["s"]),
            "v": _entry(values, pct, truth, "v_at", k, r.v_at[k], d.maxima["v"]),
            "a": _entry(values, pct, truth, "a_at", k, r.a_at[k], d.maxima["a"])})
    ex = d.exact
    integration = {
        "v_from_a": _integral(r.v_int, r.v_at, d.maxima["v"] / d.mu_v),
        "s_from_a": _integral(r.s_int, r.s, d.maxima["s"] / d.mu_s),
        "s_from_v": _integral(r.s_int_v, r.s, d.maxima["s"] / d.mu_s),
    }
    return {
        "scene": d.study.mech.title,
        "point": d.point,
        "method": d.method,
        "angle_error_deg": d.angle_error_deg,
        "correct": d.correct,
        "output": {"kind": d.output.kind, "name": d.output.name, "unit": d.unit},
        "sign": d.sign,
        "divisions": n,
        "L_mm": d.L, "H1_mm": d.H1, "H2_mm": d.H2,
        "precision_mm": d.precision,
        "adaptive": d.adaptive,
        "mu_s": d.mu_s, "mu_t": d.mu_t, "mu_v": d.mu_v, "mu_a": d.mu_a,
        "s": s, "v": v, "a": a,
        "positions": positions,
        "chosen": list(d.chosen),
        "max_error_pct_of_max": {
            "v": float(np.max(np.abs(d.errors_of_max("v_mid")))),
            "a": float(np.max(np.abs(d.errors_of_max("a_mid")))),
            "v_at": float(np.max(np.abs(d.errors_of_max("v_at")))),
            "a_at": float(np.max(np.abs(d.errors_of_max("a_at"))))},
        "chord_error": {
            "v_max_pct_of_max": float(np.max(np.abs(d.errors_of_max("v_mid", ex)))),
            "a_max_pct_of_max": float(np.max(np.abs(d.errors_of_max("a_mid", ex)))),
            "v_estimate_mm": [float(e) for e in d.estimate["v_mm"]],
            "a_estimate_mm": [float(e) for e in d.estimate["a_mm"]]},
        "ruler": None if (ruler := ruler_effect(d)) is None else {k: _num(x) for k, x in ruler.items()},
        "integration": integration,
        "redrawn": None if d.redrawn is None else d.redrawn.to_json(),
        "warnings": [{k: (float(x) if isinstance(x, (np.floating,)) else x) for k, x in w.items()}
                     for w in d.warnings],
    }


def sheet_notes(d: Diagrams, lang: str, table: int | None = None,
                printed: dict[str, np.ndarray] | None = None) -> list[str]:
    """The lines a sheet's notes give the diagrams: which method drew them, and what they get
    qualitatively wrong (spurious or missed extrema and zero crossings, by crank angle); the
    readings past 5 % by the δ the table prints (``printed``, see ``short_limit_note``)."""
    what = word("sliding output" if d.output.kind == "slide" else "rotating output", lang) + f" {subscripted(d.point)}"
    lines = [word("diagrams title", lang, what=what, how=method_words(d, lang))
             + ", " + word("divisions count", lang, n=d.divisions)]
    said = redrawn_note(d, lang, short=True, largest=_largest_printed(printed))
    lines += [said] if said else []
    lines += [item["note_uk" if lang == "uk" else "note"] for item in d.warnings if item["kind"] == "qualitative"]
    said = short_limit_note(d, lang, table, printed)
    lines += [said] if said else []
    return lines


def _largest_printed(printed: dict[str, np.ndarray] | None) -> float | None:
    """The largest |δ| of v and a as the sheet's table prints them (NaN where it prints none), so the
    redrawing's line quotes the table's figure (not the search's unrounded one: 7,67 beside 7,66)."""
    vals = [np.abs(np.asarray(printed[k], dtype=float)) for k in ("v_at", "a_at") if printed and k in printed]
    vals = [v[np.isfinite(v)] for v in vals]
    vals = [v for v in vals if v.size]
    return float(max(v.max() for v in vals)) if vals else None


def as_drawn(d: Diagrams, errs: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
    """δ, % at the positions (``Diagrams.position_errors``' keys, signed along the guide) as the
    sheet's readings table prints them, beside s, v, a times the diagrams' sense ``d.sign``: δ of its
    own exact value, 100·(g − e)/e, is the same in either frame; δ of |max| (|exact| < ``MEANINGFUL``
    of it), 100·(g − e)/|max|, changes its sign with the pair (review 54 #1: the note and the table
    must agree with the numbers printed beside them)."""
    from graphplan.graphic.diagrams import MEANINGFUL
    k = d.at_positions
    return {key: np.where(np.abs(d.truth[key][k]) >= MEANINGFUL * max(float(d.maxima[key[0]]), 1e-300), e, d.sign * e)
            for key, e in errs.items()}


def short_limit_note(d: Diagrams, lang: str, table: int | None = None,
                     printed: dict[str, np.ndarray] | None = None) -> str | None:
    """The sheet's short form of ``limit_note`` (a teacher reads a statement, not the search): the
    readings past the lab's 5 % by symbol — its worst positions with their δ — and, for each symbol,
    its one cause, measured: the chords' (or tangents') own error where the same construction with an
    exact ruler misses 5 % too at the worst of them (that δ given), else the ruler's half division on
    s amplified by the differentiations where that alone misses 5 % (the δ of the ruler on s alone,
    ``ruler_on_s``), else the ruler's readings all told (the exact ruler's δ given); then
    whether another construction the lab allows reaches 5 % (named) or none does. The terminal's
    ``diagrams`` keeps the long form with every number. None where all are within. ``printed``: δ
    of v and a (keys "v_at", "a_at", NaN where none is printed) as the sheet's table prints them,
    of its printed pair (sheets.kintables.printed_readings); else δ in the table's frame
    (``as_drawn``)."""
    from graphplan.graphic.diagrams import LAB_LIMIT, ruler_on_s
    on_s = ruler_on_s(d)
    errs, own = as_drawn(d, d.position_errors()), as_drawn(d, d.position_errors(d.exact))
    errs |= {key: np.nan_to_num(np.asarray(e, dtype=float), nan=0.0) for key, e in (printed or {}).items()}
    on_s = None if on_s is None else as_drawn(d, on_s)
    idx = d.at_positions
    uk = lang == "uk"
    said: list[tuple[str, str, float | None]] = []     # (the readings, the cause, its δ) a symbol
    for key, sym in (("s", d.symbols[0]), ("v_at", d.symbols[1]), ("a_at", d.symbols[2])):
        past = [i for i in np.argsort(-np.abs(errs[key])) if abs(errs[key][i]) > LAB_LIMIT]
        if not past:
            continue
        bad = past[:NAMED]
        name = f"{sym}_{{{d.sub}}}"
        more = " …" if len(past) > len(bad) else ""
        where = ", ".join(f"{d.position[idx[i]]} ({_signed(errs[key][i], lang, 2)} %)" for i in sorted(bad)) + more
        one = len(past) == 1                             # "at position 7", not "at positions 7"
        reading = (f"{name} у положенн{'і' if one else 'ях'} {where}" if uk
                   else f"{name} at position{'' if one else 's'} {where}")
        worst = bad[0]
        small = [] if key == "s" else _small_near_extreme(d, key, [idx[i] for i in past])
        if small:           # every reading past 5 % a small value beside an extreme position (issue 32 #2)
            big = float(d.maxima[key[0]])
            shares = _and([f"{100.0 * abs(d.truth[key][k]) / big:.0f}" for k in small], uk)
            off = _and([_signed(_of_max(d, key, idx[i], float(errs[key][i])), lang, 1) for i in sorted(past)], uk)
            # "on a sharp bend" where the chords miss there with an exact ruler too (their own error)
            bend = all(abs(float(own[key][i])) > LAB_LIMIT for i in past)
            many = len(small) > 1
            reading += (f" (мал{'і' if many else 'е'} значенн{'я' if many else 'я'}"
                        + (" на крутому згині" if bend else "") + f" біля крайн{'іх' if many else 'ього'} "
                        f"положен{'ь' if many else 'ня'}: {shares} % від |{name}|max; від |max| {off} %)" if uk else
                        f" (small value{'s' if many else ''}" + (" on a sharp bend" if bend else "")
                        + f" by {'' if many else 'an '}extreme position{'s' if many else ''}: {shares} % of "
                        f"|{name}|max; {off} % of |max|)")
        if key == "s":
            said.append((reading, "", None))
        elif abs(own[key][worst]) > LAB_LIMIT or on_s is None or key not in on_s:
            said.append((reading, "own", float(own[key][worst])))
        elif abs(on_s[key][worst]) > LAB_LIMIT:
            said.append((reading, "ruler", float(on_s[key][worst])))
        else:           # neither alone past 5 %: the ruler's readings (of s, and of v off its diagram)
            said.append((reading, "both", float(own[key][worst])))
    if not said:
        return None
    step = num(360.0 / d.divisions, lang, 3)
    s0, p = f"{d.symbols[0]}_{{{d.sub}}}", num(d.precision, lang)
    if d.method == "tangents":
        own_what = "власна похибка дотичних" if uk else "the tangents' own error"
    elif d.adaptive:
        own_what = "власна похибка хорд" if uk else "the chords' own error"
    else:
        own_what = f"власна похибка хорд при кроці {step}°" if uk else f"the chords' own error at the {step}° step"
    parts = []
    for cause in ("", "own", "ruler", "both"):      # one cause said once, after the readings it explains
        group = [x for x in said if x[1] == cause]
        if not group:
            continue
        readings = "; ".join(x[0] for x in group)
        named = len(group) > 1          # each cause's δ by its symbol where it explains two
        values = ", ".join((f"{x[0].split(' ')[0]} " if named else "") + _signed(x[2], lang, 1) + " %"
                           for x in group if x[2] is not None)
        if cause == "own":
            readings += (f" — {own_what} (з точною лінійкою {values})" if uk else
                         f" — {own_what} ({values} with an exact ruler)")
        elif cause == "both":
            readings += (f" — відліки лінійкою {p} мм (з точною лінійкою {values})" if uk else
                         f" — the {p}-mm ruler's readings ({values} with an exact ruler)")
        elif cause == "ruler":
            readings += (f" — відлік {s0} лінійкою {p} мм, підсилений диференціюванням (лише від нього {values})"
                         if uk else f" — the {p}-mm ruler on {s0}, amplified by the differentiation "
                                    f"({values} from it alone)")
        parts.append(readings)
    ref = (f" (табл. {table}, *)" if uk else f" (Table {table}, *)") if table else ""
    trials = [t for t in d.alternatives() if t.key != "adaptive none"]
    within = [t for t in trials if t.worst_pct <= LAB_LIMIT]
    if within:
        names = ", ".join(_short(t, uk) for t in within)
        tail = f"; у межах 5 % дає: {names}" if uk else f"; within 5 % with: {names}"
    elif trials or (d.redrawn is not None and d.redrawn.off_after is not None):
        tail = ("; жодна інша випробувана побудова не вкладається в 5 %" if uk
                else "; no other construction tried keeps within 5 %")
    else:
        tail = ""
    tail = _finer_worse(d, trials, lang) + _scales_tried(d, lang) + tail
    return ((f"Значення з діаграм виходять за межу 5 % лабораторної роботи{ref}: " if uk else
             f"Values read off the diagrams exceed the 5 % the lab allows{ref}: ") + "; ".join(parts) + tail)


def _scales_tried(d: Diagrams, lang: str) -> str:
    """The other s scales the sheet tried for these diagrams (``Diagrams.s_tried``, kinlayout
    ``taller_in_place``), each with its largest |δ| at the positions or why it is not drawn — a
    teacher asks a diagram past 5 % whether a larger s was tried (review 62 F4: the offset pump's s
    60 mm high at μs 0,002 in a 300-mm zone, the notes silent). Empty where none was."""
    uk = lang == "uk"
    us = unit(d.unit if d.unit == "m" else "rad", lang) + "/" + unit("mm", lang)
    said, why_not = [], {}
    for mu_s, why in d.s_tried:
        if isinstance(why, float) and not math.isfinite(why):
            continue
        if isinstance(why, float):
            said.append(f"{num(mu_s, lang, 4)} {us}: {fixed(why, lang, 1)} %")
        else:
            why_not.setdefault(why, []).append(num(mu_s, lang, 4))
    for why, values in why_not.items():     # one reason said once: "0,01 і 0,005 рад/мм: аркуш не вміщує"
        many = len(values) > 1
        said.append(f"{_and(values, uk)} {us}: " + {
            "room": "аркуш не вміщує" if uk else f"the sheet does not hold {'them' if many else 'it'}",
            "flat": "діаграми v, a нижчі" if uk else "v, a drawn lower",
            "wrong": "якісно хибні" if uk else "qualitatively wrong"}[why])
    if not said:
        return ""
    sym = mu(scale_symbols(d)[0])
    return (f"; також за {sym} " if uk else f"; also tried at {sym} ") + "; ".join(said)


SMALL_SHARE = 0.25   # a reading's exact value under this share of the cycle's |max|: a small value


def _small_near_extreme(d: Diagrams, key: str, ks: list[int]) -> list[int]:
    """The division ordinates ``ks`` (the readings of ``key``, "v_at" or "a_at", past 5 %) where
    each is a small value — its exact value under ``SMALL_SHARE`` of the cycle's |max| — within one
    interval of an extreme position of the output (its velocity's zero: the curve runs steeply
    through small values there, and a ruler's or a chord's fraction of a millimetre is a large share
    of a short ordinate); empty unless every one of ``ks`` is such (then the note says so instead
    of a cause the larger readings have)."""
    big = float(d.maxima[key[0]])
    if big <= 0 or not ks:
        return []
    turns = [float(d.study.from_position0(e)) % 360.0 for e in d.study.extremes]
    step = 360.0 / max(d.divisions, 1)
    out = []
    for k in ks:
        if abs(float(d.truth[key][k])) >= SMALL_SHARE * big:
            return []
        u = float(d.turn[k]) % 360.0
        if not any(min(abs(u - t), 360.0 - abs(u - t)) <= step + 1e-9 for t in turns):
            return []
        out.append(k)
    return sorted(out)


def _of_max(d: Diagrams, key: str, k: int, pct_: float) -> float:
    """δ, % (as the table prints it, in its frame — the diagrams' sense ``d.sign`` — of the exact
    value, or of |max| below ``MEANINGFUL`` of it) at ordinate k as a share of the cycle's |max|:
    100·(g − e)/|max| = δ·e/|max| with e signed in that frame."""
    from graphplan.graphic.diagrams import MEANINGFUL
    big, e = float(d.maxima[key[0]]), d.sign * float(d.truth[key][k])
    return pct_ * e / big if abs(e) >= MEANINGFUL * big else pct_


def _and(items: list[str], uk: bool) -> str:
    """Items joined as a note lists them: "a і b", "a, b і c" (en: "and")."""
    if len(items) <= 1:
        return "".join(items)
    return ", ".join(items[:-1]) + (" і " if uk else " and ") + items[-1]


def _finer_worse(d: Diagrams, trials, lang: str) -> str:
    """Why the sheet keeps its divisions where twice as many read worse (a trial "double" past the
    drawing's largest |δ| while its own exact drawing reads closer): in one sentence a student accepts —
    the ruler's half division on s over a smaller step (docs/diagrams.md: σ·μs/(h²·μt²) on a); where
    they read closer but still past 5 %, their |δ| (the trial a student would make first). Empty
    otherwise. (The dynamics sheet draws more divisions where they read within the lab's 5 %:
    graphic.flywheel.redrawn; this sheet's diagrams keep the plans' positions as divisions.)"""
    from graphplan.graphic.diagrams import LAB_LIMIT
    from graphplan.util.words import uk_count
    uk = lang == "uk"
    for t in trials:
        if t.key == "double" and t.exact_pct < t.worst_pct and t.worst_pct > d.worst_pct():
            n, e = t.divisions, fixed(t.worst_pct, lang, 1)
            return (f"; {n} {uk_count(n, 'поділка', 'поділки', 'поділок')} дають {e} %: на меншому кроці більша "
                    f"похибка лінійки" if uk else f"; {n} divisions read {e} %: the ruler errs more at the smaller step")
        if t.key == "double" and t.worst_pct > LAB_LIMIT:     # closer, still past 5 %: not worth 24 columns
            n, e = t.divisions, fixed(t.worst_pct, lang, 1)
            return (f"; {n} {uk_count(n, 'поділка', 'поділки', 'поділок')} дають {e} %, теж понад 5 %"
                    if uk else f"; {n} divisions read {e} %, past 5 % too")
    return ""


NAMED = 2     # the worst readings a note names a diagram, and a third where the chords' own error is past 5 %


def limit_note(d: Diagrams, lang: str, table: int | None = None) -> str | None:
    """Where the values read off the diagrams at the positions miss the lab's 5 % (δ of the exact
    value; of the cycle's |max| where the value is below ``MEANINGFUL`` of it): which, by how much,
    and why — the chords' own error (the exact drawing misses too: smaller intervals would be
    needed) or the ruler's half division amplified by the differentiations — and, where
    graphic.redraw searched, that nothing the lab allows reaches it. None where all are within."""
    from graphplan.graphic.diagrams import LAB_LIMIT
    from graphplan.graphic.diagrams import ruler_on_s
    errs, own, on_s = d.position_errors(), d.position_errors(d.exact), ruler_on_s(d)
    idx = d.at_positions
    uk = lang == "uk"
    parts, owns, s_only, sharp = [], [], [], False
    for key, sym in (("s", d.symbols[0]), ("v_at", d.symbols[1]), ("a_at", d.symbols[2])):
        past = [i for i in np.argsort(-np.abs(errs[key])) if abs(errs[key][i]) > LAB_LIMIT]
        if not past:
            continue
        # the worst, and one where the chords' own error is past 5 % too (the cause differs there)
        bad = past[:NAMED] + [i for i in past[NAMED:] if abs(own[key][i]) > LAB_LIMIT][:1]
        name = f"{sym}_{{{d.sub}}}"
        more = " …" if len(past) > len(bad) else ""   # Table 5 marks every one
        parts.append(f"{name} " + ", ".join(f"{d.position[idx[i]]} ({_signed(errs[key][i], lang, 2)} %)"
                                            for i in bad) + more)
        owns.append(f"{name} " + ", ".join(_signed(own[key][i], lang, 1) for i in bad) + " %")
        sharp |= any(abs(own[key][i]) > LAB_LIMIT for i in bad)
        if on_s is not None and key in on_s:
            s_only.append(f"{name} " + ", ".join(_signed(on_s[key][i], lang, 1) for i in bad) + " %")
    if not parts:
        return None
    where = "; ".join(parts)
    ref = (f" (табл. {table})" if uk else f" (Table {table})") if table else ""
    n, p = d.divisions, num(d.precision, lang)
    # each reading beside the same construction with an exact ruler (the chords' own error) and with
    # the ruler on s alone (what no H1, H2 or L changes): review 12's six-bar read ε5 +16.25 % at 2,
    # the chords' own −0.5 % there — the note blamed the chords
    bend = ""
    if sharp and not d.adaptive:
        step = num(360.0 / n, lang, 3)
        bend = f"; згин, крутий для кроку {step}°" if uk else f"; a bend sharp for the {step}° step"
    own_of = ("дотичних" if uk else "tangents'") if d.method == "tangents" else ("хорд" if uk else "chords'")
    why = (f" — з точною лінійкою (власна похибка {own_of}{bend}): {'; '.join(owns)}" if uk else
           f" — with an exact ruler (the {own_of} own error{bend}): {'; '.join(owns)}")
    if s_only:
        s0 = f"{d.symbols[0]}_{{{d.sub}}}"
        why += (f"; лише з відліком {s0} лінійкою {p} мм (не залежить від H_{{1}}, H_{{2}} і L): {'; '.join(s_only)}"
                if uk else f"; with the {p}-mm ruler on {s0} alone (independent of H_{{1}}, H_{{2}} and L): "
                           f"{'; '.join(s_only)}")
    return ((f"Значення з діаграм у положеннях виходять за межу 5 % лабораторної роботи{ref}: {where}" if uk else
             f"Values read off the diagrams at the positions exceed the 5 % the lab allows{ref}: {where}")
            + why + _tried(d, lang))


def _signed(value: float, lang: str, places: int) -> str:
    """A signed percent as the notes print it (the minus sign typeset)."""
    return fixed(value, lang, places, plus=True).replace("-", "−")


SHORT = {"adaptive": ("smaller intervals", "менші інтервали"), "double": ("{n} divisions", "{n} {many}"),
         "correct": ("the correction", "корекція площ"), "tangents": ("tangents", "дотичні"), "chords": ("chords", "хорди")}


def _short(t, uk: bool) -> str:
    """A trial (graphic.diagrams.Trial) named as short as a note names it."""
    from graphplan.util.words import uk_count
    return SHORT[t.key][1 if uk else 0].format(n=t.divisions, many=uk_count(t.divisions, "поділка", "поділки", "поділок"))


def _tried(d: Diagrams, lang: str) -> str:
    """What else was tried, measured and short (a note costs the sheet's room): each of
    graphic.diagrams.alternatives with its largest |δ| at the positions — more divisions marked
    where the ruler's half division, amplified by the smaller step, is why they read worse — and
    graphic.redraw's search where the sheet redrew; then whether any reaches 5 % (one that does is
    named: the sheet draws at its positions' divisions)."""
    from graphplan.graphic.diagrams import LAB_LIMIT
    uk = lang == "uk"
    trials = [t for t in d.alternatives() if t.key != "adaptive none"]
    items = []
    for t in trials:
        item = f"{_short(t, uk)} {fixed(t.worst_pct, lang, 1)} %"
        if t.key == "double" and t.exact_pct < t.worst_pct and t.worst_pct > d.worst_pct():
            item += " (похибка лінійки)" if uk else " (the ruler's error)"
        items.append(item)
    if d.redrawn is not None and d.redrawn.off_after is not None:
        items.append(f"H_{{1}}, H_{{2}} 15–50 мм, вища {d.symbols[0]}_{{{d.sub}}}" if uk else
                     f"H_{{1}}, H_{{2}} 15–50 mm, a taller {d.symbols[0]}_{{{d.sub}}}")
    if not items:
        return ""
    within = [t for t in trials if t.worst_pct <= LAB_LIMIT]
    if within:
        names = ", ".join(_short(t, uk) for t in within)
        verdict = f"у межах 5 %: {names}" if uk else f"within 5 %: {names}"
    else:
        verdict = "жодна не вкладається в 5 %" if uk else "none keeps within 5 %"
    return (f"; випробувано: {', '.join(items)} — {verdict}" if uk else f"; tried: {', '.join(items)} — {verdict}")


def redrawn_note(d: Diagrams, lang: str, short: bool = False, largest: float | None = None) -> str | None:
    """What graphic.redraw did, in one line (markup): the options the diagrams were redrawn with so
    that they are qualitatively right, or read closer to the exact at the positions (the largest
    |δ| before → after), or that nothing the lab allows made them right. ``short`` (the sheet's):
    where the first drawing was qualitatively wrong, the why without the δ before → after (Table 4
    prints the δ drawn). None where the first drawing was kept."""
    rd = d.redrawn
    if rd is None or not (rd.wrong_before or rd.changed):
        return None
    uk = lang == "uk"
    mm = unit("mm", lang)
    if rd.wrong_before and not rd.right:
        syms = ", ".join(d.symbols[1 if key == "v" else 2] for key in rd.wrong_before)
        longer = "L" in rd.searched
        return (f"{syms}: жодна з {rd.tried} побудов заново, які дозволяє лабораторна і вміщує аркуш (корекція площ, "
                f"H_{{1}}, H_{{2}} від 15 до 50 {mm}, {'довша L, ' if longer else ''}менші інтервали, вища діаграма "
                f"{d.symbols[0]}_{{{d.sub}}}), не робить діаграму якісно правильною" if uk else
                f"{syms}: none of the {rd.tried} redrawings the lab allows and the sheet holds (the area correction, "
                f"H_{{1}}, H_{{2}} from 15 to 50 {mm}, {'a longer L, ' if longer else ''}smaller intervals, a taller "
                f"{d.symbols[0]}_{{{d.sub}}}) makes the diagram qualitatively right")
    parts = []
    for key, value in rd.changed.items():
        was = rd.first.get(key)
        if key in ("H1", "H2", "L"):
            name = {"H1": "H_{1}", "H2": "H_{2}", "L": "L"}[key]
            given = _given(d, key)
            if short:           # the sheet states the value drawn; a departure only from the scene's own
                parts.append(f"{name} = {num(value, lang, 3)} {mm}" + (
                    "" if given is None or abs(given - value) < 1e-9 else
                    f" (у сцені {num(given, lang, 3)})" if uk else f" (the scene's {num(given, lang, 3)})"))
                continue
            parts.append(f"{name} = {num(value, lang, 3)} {mm} " + (f"(не {num(was, lang, 3)})" if uk else
                                                                    f"(not {num(was, lang, 3)})"))
        elif key == "height":
            if was is not None and _mu_s_at(d, was) == d.mu_s:
                continue            # the allowance changed, not the drawing: μs as first chosen
            s0 = f"{d.symbols[0]}_{{{d.sub}}}"
            up = was is None or value > was
            if short:
                parts.append(f"{mu(scale_symbols(d)[0])} = {fmt(d.mu_s, lang)} {units(d, lang)[0]}/{mm}")
                continue
            parts.append(f"діаграма {s0} {'вища' if up else 'нижча'}: {mu(scale_symbols(d)[0])} = {fmt(d.mu_s, lang)}"
                         if uk else f"the {s0} diagram {'taller' if up else 'lower'}: "
                                    f"{mu(scale_symbols(d)[0])} = {fmt(d.mu_s, lang)}")
        elif key == "fit":      # the series' next finer μs: the s diagram taller than its allowance
            if short:
                parts.append(f"{mu(scale_symbols(d)[0])} = {fmt(d.mu_s, lang)} {units(d, lang)[0]}/{mm}")
                continue
            s0 = f"{d.symbols[0]}_{{{d.sub}}}"
            parts.append(f"діаграма {s0} вища: {mu(scale_symbols(d)[0])} = {fmt(d.mu_s, lang)}" if uk else
                         f"the {s0} diagram taller: {mu(scale_symbols(d)[0])} = {fmt(d.mu_s, lang)}")
        elif key == "correct":
            parts.append("з корекцією площ" if uk else "with the area correction")
        elif key == "adaptive":
            from graphplan.util.words import uk_count
            many = uk_count(d.divisions, "поділка", "поділки", "поділок")
            parts.append(f"менші інтервали там, де крива згинається ({d.divisions} {many})" if uk else
                         f"smaller intervals where the curve bends ({d.divisions} divisions)")
    how = ", ".join(parts)
    if short:
        return _chosen_note(d, rd, how, lang, largest)
    off = ""
    if rd.off_before is not None and rd.off_after is not None:
        a, b = fixed(rd.off_before, lang, 2), fixed(rd.off_after, lang, 2)     # as Table 5's δ, two decimals
        off = (f"найбільша |δ| у положеннях: {a} % → {b} %" if uk else f"the largest |δ| at the positions: {a} % → {b} %")
    if not rd.wrong_before:
        return (f"Діаграми побудовано заново: {how} — {off}" if uk else f"Diagrams redrawn: {how} — {off}")
    syms = ", ".join(f"{d.symbols[1 if key == 'v' else 2]}_{{{d.sub}}}" for key in rd.wrong_before)
    many = len(rd.wrong_before) > 1
    tail = f"; {off}" if off and not short else ""     # the sheet's short form: the why, not the δ (Table 4 has it)
    if uk:
        return (f"Діаграми {syms} побудовано заново: {how} — перші мали екстремуми, нулі чи уступи, яких немає в русі{tail}"
                if many else
                f"Діаграму {syms} побудовано заново: {how} — перша мала екстремуми, нулі чи уступи, яких немає в русі{tail}")
    return (f"Diagram{'s' if many else ''} {syms} redrawn: {how} — the first had extrema, zero crossings or "
            f"shoulders the motion lacks{tail}")


def _given(d: Diagrams, key: str) -> float | None:
    """The scene's own value of a drawing option (its [diagrams] ``H1_mm``, ``H2_mm``, ``L_mm``), or None."""
    dg = getattr(getattr(getattr(d.study, "mech", None), "task", None), "diagram", None) or {}
    value = dg.get(f"{key}_mm")
    return None if value is None else float(value)


def _chosen_note(d: Diagrams, rd, how: str, lang: str, largest: float | None = None) -> str | None:
    """The sheet's line for a redrawing (``redrawn_note`` short): what was drawn and why it was chosen —
    a statement, not the search: the options drawn (``how``, the values on the sheet), and either that
    they make the diagrams qualitatively right (the options first taken gave extrema, zero crossings or
    shoulders the motion lacks) or that of the redrawings the lab allows and the sheet holds this one
    reads closest to the exact at the positions (its largest |δ|, as Table 5 prints δ: two decimals).
    Review 54 #3: «H₁ = 20 мм (не 25) … 32,19 % → 15,52 %» named values the student never chose."""
    uk = lang == "uk"
    if not how:
        return None                 # nothing the sheet draws differs from the options first taken
    head = f"Діаграми: {how} — " if uk else f"Diagrams: {how} — "
    if rd.wrong_before:
        syms = ", ".join(f"{d.symbols[1 if key == 'v' else 2]}_{{{d.sub}}}" for key in rd.wrong_before)
        many = len(rd.wrong_before) > 1
        return head + (f"обрано, щоб діаграм{'и' if many else 'а'} {syms} не мал{'и' if many else 'а'} екстремумів, "
                       f"нулів чи уступів, яких немає в русі" if uk else
                       f"chosen so that the {syms} diagram{'s' if many else ''} "
                       f"{'have' if many else 'has'} no extrema, zero crossings or shoulders the motion lacks")
    if rd.off_after is None:
        return head.rstrip(" —")
    off = fixed(rd.off_after if largest is None else largest, lang, 2)     # the table's figure where it prints one
    if rd.within:
        return head + (f"обрано, щоб значення з діаграм у положеннях вкладалися в 5 % лабораторної "
                       f"(найбільша |δ| {off} %)" if uk else
                       f"chosen so that the values read off the diagrams at the positions keep within the lab's "
                       f"5 % (the largest |δ| {off} %)")
    return head + (f"з побудов, які дозволяє лабораторна і вміщує аркуш, найточніша в положеннях "
                   f"(найбільша |δ| {off} %)" if uk else
                   f"of the constructions the lab allows and the sheet holds, the one read closest to the exact "
                   f"at the positions (the largest |δ| {off} %)")


def _mu_s_at(d: Diagrams, height: float) -> float:
    """The μs the s diagram takes fitted to ``height`` mm (graphic.diagrams.choose_mu_s): the
    output's range over the exact cycle."""
    from graphplan.exact.positions import exact_motion
    from graphplan.graphic.diagrams import CYCLE, choose_mu_s
    s = exact_motion(d.study, d.output, np.arange(CYCLE + 1) * 360.0 / CYCLE)[0]
    return choose_mu_s(d.study, d.unit, float(np.ptp(s)), height)


def _integral(got: np.ndarray, ref: np.ndarray, max_mm: float) -> dict[str, Any]:
    dev = got - ref
    return {"mm": [float(g) for g in got], "max_dev_mm": float(np.max(np.abs(dev))),
            "max_dev_pct_of_max": float(100 * np.max(np.abs(dev)) / max_mm),
            "closure_mm": float(dev[-1])}


# -- tables ----------------------------------------------------------------------------------------

def _pct(p, lang: str = "en") -> str:
    return pct(p, lang)


def mirrored_note(d: Diagrams, lang: str) -> str | None:
    """Where the diagrams are drawn mirrored (``d.sign`` < 0: + against the guide, or clockwise for an
    angle), what the terminal's columns mean: the mm are the ordinates as drawn, the values signed
    along the guide (counter-clockwise), value = −mm·μ; the sheet's table writes s, v, a as drawn, so
    a δ of |max| there has the opposite sign to the one here (δ = 100·(g − e)/|max|, review 54 #1).
    None for diagrams drawn in the values' sense."""
    if d.sign >= 0:
        return None
    uk = lang == "uk"
    if d.output.kind == "slide":
        how = "проти напрямної" if uk else "against the guide"
        own = "уздовж напрямної" if uk else "along the guide"
    else:
        how = "за годинниковою стрілкою" if uk else "clockwise"
        own = "проти годинникової стрілки" if uk else "counter-clockwise"
    if uk:
        return (f"Діаграми накреслено дзеркально (+ {how}): мм — ординати як на кресленні, значення — «+ {own}» "
                "(значення = −мм·μ); таблиця аркуша пише s, v, a як на діаграмах, тож δ від |max| там має протилежний знак")
    return (f"The diagrams are drawn mirrored (+ {how}): mm are the ordinates as drawn, the values + {own} "
            "(value = −mm·μ); the sheet's table writes s, v, a as the diagrams do, so a δ of |max| there has the "
            "opposite sign")


def diagrams_table(d: Diagrams, lang: str = "uk") -> str:
    w = lambda k_, **kw: plain(word(k_, lang, **kw))  # noqa: E731
    s_, v_, a_ = d.symbols
    us, uv, ua = units(d, lang)
    what = f"{w('sliding output' if d.output.kind == 'slide' else 'rotating output')} {d.point}"
    mech = d.study.mech
    lines = [scene_title(mech.task.meta, mech.title, lang),
             w("diagrams title", what=what, how=method_words(d, lang)),
             w("period", T=num(mech.period, lang), L=num(d.L, lang)), f"{w('scales')}:"]
    lines += ["  " + plain(t) for t in scale_lines(d, lang)]
    lines += ["", w("turn note")]
    vals = d.values()

    def block(title: str, head: list[str], rows: list[list[str]]) -> None:
        widths = [max(len(h), *(len(r[i]) for r in rows)) for i, h in enumerate(head)]
        lines.append("")
        lines.append(title)
        lines.append("  ".join(h.rjust(wd) for h, wd in zip(head, widths)))
        for r in rows:
            lines.append("  ".join(c.rjust(wd) for c, wd in zip(r, widths)))

    def turn(phi: float) -> str:
        """The sheets' φ: the crank's turn from position 0 in its sense of rotation."""
        return fixed(float(d.study.from_position0(phi % 360.0)) % 360.0, lang, 2)

    def g(x: float, key: str) -> str:
        """5 significant digits; round-off below 1e-9 of the cycle's maximum shows as 0."""
        return num(0.0 if abs(x) <= 1e-9 * d.maxima[key] else x + 0.0, lang, 5)

    judged = {key: judged_pct(vals[key], d.truth[key], d.maxima[key[0]]) for key in ("v_at", "a_at")}

    def row_at(k: int) -> list[str]:
        """A division ordinate's reading, δ judged as the sheet's diagrams table judges it (``judged_pct``:
        of |max| where |exact| < 10 % of it — a reading near a zero is not 949 % off)."""
        r = d.drawn
        pos = d.position[k]
        f1 = lambda v: fixed(v, lang, 1)  # noqa: E731
        return [str(pos if pos is not None else f"({k})"), fixed(d.phi[k], lang, 2), turn(d.phi[k]), f1(r.s[k]),
                g(vals['s'][k], "s"), g(d.truth['s'][k], "s"),
                f1(r.v_at[k]), g(vals['v_at'][k], "v"), g(d.truth['v_at'][k], "v"),
                _pct(judged['v_at'][k], lang),
                f1(r.a_at[k]), g(vals['a_at'][k], "a"), g(d.truth['a_at'][k], "a"),
                _pct(judged['a_at'][k], lang)]

    mm = unit("mm", lang)
    head = [w("no"), "φ, °", w("turn col"), f"{s_}, {mm}", f"{s_}, {us}", w("exact"), f"{v_}, {mm}", f"{v_}, {uv}", w("exact"),
            w("error pct"), f"{a_}, {mm}", f"{a_}, {ua}", w("exact"), w("error pct")]
    block(w("at ordinates"), head, [row_at(k) for k in range(d.divisions)])
    lines.append(w("judged note"))
    said = mirrored_note(d, lang)
    lines += [said] if said else []
    chosen = [k for k in range(d.divisions) if d.position[k] in d.chosen]
    if chosen:
        block(w("chosen"), head, [row_at(k) for k in chosen])
    rows = []
    tangents = d.method == "tangents"
    for k in range(d.divisions):
        r = d.drawn
        rows.append([str(k) if tangents else f"{k}–{k + 1}", fixed(d.phi_mid[k], lang, 2), turn(d.phi_mid[k]),
                     fixed(r.v[k], lang, 1), g(vals['v_mid'][k], "v"),
                     g(d.truth['v_mid'][k], "v"), _pct(d.errors_pct('v_mid')[k], lang),
                     fixed(r.a[k], lang, 1), g(vals['a_mid'][k], "a"), g(d.truth['a_mid'][k], "a"),
                     _pct(d.errors_pct('a_mid')[k], lang)])
    block(w("tangent ordinates" if tangents else "chord ordinates"), [w("no") if tangents else w("interval"), "φ, °",
                                                                       w("turn col"), f"{v_}, {mm}", f"{v_}, {uv}", w("exact"), w("error pct"),
                                 f"{a_}, {mm}", f"{a_}, {ua}", w("exact"), w("error pct")], rows)
    lines.append("")
    lines.append(w("integration") + ":")
    r = d.drawn
    for key, got, ref, mx in (("v_from_a", r.v_int, r.v_at, d.maxima["v"] / d.mu_v),
                              ("s_from_a", r.s_int, r.s, d.maxima["s"] / d.mu_s),
                              ("s_from_v", r.s_int_v, r.s, d.maxima["s"] / d.mu_s)):
        dev = got - ref
        lines.append(f"  {w(key.replace('_', ' '))}: " + w("deviation", mm=fixed(float(np.max(np.abs(dev))), lang, 2),
                                                             pct=fixed(float(100 * np.max(np.abs(dev)) / mx), lang, 2),
                                                             cl=fixed(float(dev[-1]), lang, 2, plus=True)))
    said = [s for s in (redrawn_note(d, lang), limit_note(d, lang)) if s]
    if said:
        lines += [""] + [plain(s) for s in said]
    lines.append("")
    lines.append(w("warnings") + ":" + ("" if d.warnings else " " + w("none")))
    for item in d.warnings:
        lines.append("  - " + item["message_uk" if lang == "uk" else "message"])
    return "\n".join(lines) + "\n"
