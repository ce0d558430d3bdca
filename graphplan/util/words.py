"""The one catalogue of words a person reads (sheets, tables, terminal, warnings, keys and grading),
Ukrainian and English, with the lab's terms; the units in both languages; and the one number
formatter (the decimal comma in Ukrainian, the same significant figures everywhere).

Plain data and tiny functions: every room may import it. JSON never goes through here (it stays SI
with decimal points). Text may carry the typesetting markup of ``util.markup`` ("a^τ_BA", "M_зр").
"""
from __future__ import annotations

import math
import re

from graphplan.util.errors import GraphplanError

LANGS = ("uk", "en")
DEFAULT_LANG = "uk"


def check_lang(lang: str | None) -> str:
    """``lang`` if it is one of LANGS (None → the default, Ukrainian)."""
    if lang is None:
        return DEFAULT_LANG
    if lang not in LANGS:
        from graphplan.util.errors import keyed_error
        raise keyed_error(GraphplanError, None, "--lang", "op lang", None, got=repr(lang))
    return lang


def pick(lang: str | None, *candidates: str | None) -> str:
    """The first language given: the command line's, then the scene's ``lang``, then Ukrainian."""
    for c in (lang, *candidates):
        if c:
            return check_lang(c)
    return DEFAULT_LANG


# -- units ------------------------------------------------------------------------------------------
# key → (Ukrainian, English); scale units are "real value per drawn millimetre"
UNITS: dict[str, tuple[str, str]] = {
    "m": ("м", "m"), "mm": ("мм", "mm"), "s": ("с", "s"), "rad": ("рад", "rad"), "deg": ("°", "°"),
    "N": ("Н", "N"), "N·m": ("Н·м", "N·m"), "N·mm": ("Н·мм", "N·mm"), "kg": ("кг", "kg"),
    "kg·m²": ("кг·м²", "kg·m²"), "J": ("Дж", "J"), "W": ("Вт", "W"), "kW": ("кВт", "kW"),
    "m/s": ("м/с", "m/s"), "m/s²": ("м/с²", "m/s²"), "rad/s": ("рад/с", "rad/s"),
    "rad/s²": ("рад/с²", "rad/s²"), "rpm": ("об/хв", "rpm"), "1/s": ("с⁻¹", "s⁻¹"),
    "m/mm": ("м/мм", "m/mm"), "s/mm": ("с/мм", "s/mm"), "rad/mm": ("рад/мм", "rad/mm"),
    "deg/mm": ("°/мм", "°/mm"),
    "(m/s)/mm": ("(м/с)/мм", "(m/s)/mm"), "(m/s²)/mm": ("(м/с²)/мм", "(m/s²)/mm"),
    "(rad/s)/mm": ("(рад/с)/мм", "(rad/s)/mm"), "(rad/s²)/mm": ("(рад/с²)/мм", "(rad/s²)/mm"),
    "N/mm": ("Н/мм", "N/mm"), "N·m/mm": ("Н·м/мм", "N·m/mm"), "J/mm": ("Дж/мм", "J/mm"),
    "kg·m²/mm": ("кг·м²/мм", "kg·m²/mm"), "%": ("%", "%"),
}


def unit(key: str, lang: str) -> str:
    """A unit in the sheet's language: unit("(m/s)/mm", "uk") → "(м/с)/мм"."""
    uk, en = UNITS[key]
    return uk if lang == "uk" else en


# -- pair kinds -------------------------------------------------------------------------------------
# R (обертальна, В) and P (поступальна, П): RPR is the lab's ВПВ, the slotted link ("куліса")
PAIR_LETTERS = {"R": "В", "P": "П"}


def pair_kind(kind: str, lang: str) -> str:
    """A dyad's kind by its pairs: "RPR" → "ВПВ" in Ukrainian, unchanged in English."""
    if lang != "uk":
        return kind
    return "".join(PAIR_LETTERS.get(c, c) for c in kind)


# -- the lab's symbols -------------------------------------------------------------------------------
_FORCE = re.compile(r"^(MΦ|Φ|G|R|P_|M_)([0-9]+(?:-[0-9]+)?|[A-Za-z][A-Za-z0-9]*)(τ|n|\^⊥|\^∥)?('*)$")


def force_symbol(name: str, lang: str) -> str:
    """A force's name as the lab writes it (markup): G2 → G_2, Φ2 → Φ_2, MΦ3 → M^Φ_3, R12 → R_12,
    R34τ → R^τ_34, R34n → R^n_34, R34^⊥ → R^⊥_34, P_b and M_b → P_зр, M_зр in Ukrainian, P_bal
    and M_b in English (P_b would read as a point B's P_B)."""
    if name in ("M_b", "P_b"):
        return word(name, lang)
    m = _FORCE.match(name)
    if not m:
        return name
    letter, index, mark, primes = m.groups()
    letter = {"MΦ": "M", "P_": "P", "M_": "M"}.get(letter, letter)
    top = "Φ" if m.group(1) == "MΦ" else (mark or "").lstrip("^")
    low = "{" + index + "}"
    return (f"{letter}^{{{top}}}_{low}" if top else f"{letter}_{low}") + primes


# -- numbers ----------------------------------------------------------------------------------------
SUPER = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")
DIGITS = 4     # significant figures of every value a person reads (tables, sheets, terminal)


def _comma(text: str, lang: str) -> str:
    return text.replace(".", ",") if lang == "uk" else text


def num(v: float | None, lang: str = "en", digits: int = DIGITS) -> str:
    """A value as the lab writes it: ``digits`` significant figures, no trailing zeros, ·10ⁿ for
    very small or large numbers, the decimal comma in Ukrainian; "—" for none or not finite."""
    if v is None:
        return "—"
    v = float(v)
    if not math.isfinite(v):
        return "—"
    if v == 0:
        return "0"
    e = math.floor(math.log10(abs(v)))
    rounded = float(f"{v:.{digits - 1}e}")        # the exponent after rounding (9.9996 → 10)
    e = math.floor(math.log10(abs(rounded))) if rounded else e
    if -4 <= e < 6:
        text = f"{rounded:.{max(digits - 1 - e, 0)}f}"
        if "." in text:
            text = text.rstrip("0").rstrip(".")
    else:
        m = f"{rounded / 10 ** e:.{digits - 1}f}".rstrip("0").rstrip(".")
        text = f"{m}·10{str(e).translate(SUPER)}"
    return _comma("0" if text in ("-0", "") else text, lang)


def resolution(values, digits: int = DIGITS) -> float:
    """A column's resolution: one unit of the (``digits`` + 1)-th significant figure of its largest
    |value| (a column led by 37,19 resolves 0,001). Below it a value is rounding noise of the
    computation (4,8·10⁻¹² beside 37,19), not a number a reader can use: the column prints 0."""
    big = max((abs(float(v)) for v in values if v is not None and math.isfinite(float(v))), default=0.0)
    return 10.0 ** (math.floor(math.log10(big)) - digits) if big > 0 else 0.0


def column(values, lang: str = "en", digits: int = DIGITS) -> list[str]:
    """A table's column of values (``num``, a true minus), each below the column's ``resolution``
    written 0."""
    res = resolution(values, digits)
    return [num(0.0 if v is not None and math.isfinite(float(v)) and abs(float(v)) < res else v,
                lang, digits).replace("-", "−") for v in values]


MEANINGFUL = 0.01   # a value below this share of its column's largest |value| is not the one the decimals are set by
LEAST_FIGURES = 3   # significant figures the column's smallest meaningful value keeps …
MOST_FIGURES = 4    # … unless its largest would then show more than these (DIGITS: a sheet's every number)


def column_decimals(values, least: int = LEAST_FIGURES, most: int = MOST_FIGURES,
                    meaningful: float = MEANINGFUL, typical: bool = False) -> int:
    """One count of decimals for a table's column (or for the columns of one quantity, graphical
    beside exact): enough that the smallest value at least ``meaningful`` of the largest keeps
    ``least`` significant figures, no more than leave the largest ``most`` (ΔT 60,93 / −38,08 /
    −323,7 → one decimal: 60,9 / −38,1 / −323,7; A_c 22,85 … 1021 → none: 23 … 1021). ``typical``:
    the figures are set by the column's median meaningful |value| instead of its smallest, so a
    column's typical values keep ``least`` figures and the few near zero (a dead centre's v 0,004
    among 0,080 … 0,160) are written to the same decimals with fewer — not the column's decimals
    raised for them."""
    vals = [abs(float(v)) for v in values if v is not None and math.isfinite(float(v)) and v != 0]
    if not vals:
        return 0
    big = max(vals)
    kept = sorted(v for v in vals if v >= meaningful * big)
    small = kept[(len(kept) - 1) // 2] if typical else kept[0]
    order = lambda v: math.floor(math.log10(float(f"{v:.{least - 1}e}")))     # noqa: E731  after rounding (9.996 → 10.0)
    return max(0, min(least - 1 - order(small), most - 1 - order(big)))


def decimals_column(values, lang: str = "en", decimals: int | None = None) -> list[str]:
    """A table's column to one count of decimals (``column_decimals`` unless given), trailing zeros
    kept, a true minus; a value that rounds to zero the number 0, "—" for none."""
    d = column_decimals(values) if decimals is None else decimals
    return ["—" if v is None or not math.isfinite(float(v)) else
            "0" if round(float(v), d) == 0 else fixed(v, lang, d).replace("-", "−") for v in values]


def fixed(v: float | None, lang: str = "en", decimals: int = 1, plus: bool = False) -> str:
    """A value with a fixed count of decimals (angles, drawn millimetres, percents); ``plus``
    writes the sign of positive values too; "—" for none."""
    if v is None or not math.isfinite(float(v)):
        return "—"
    text = f"{float(v) + 0.0:{'+' if plus else ''}.{decimals}f}"
    if text.lstrip("+-").strip("0.") == "":
        text = text.replace("-", "+" if plus else "")
    return _comma(text, lang)


def pct(v: float | None, lang: str = "en", decimals: int = 2) -> str:
    """A signed percent error: "+1,08" (no % sign: the column says it); "—" for none."""
    return fixed(v, lang, decimals, plus=True)


def scale_text(symbol: str, mu: float, unit_key: str, lang: str) -> str:
    """"μ_v = 0,2 (м/с)/мм" — a scale coefficient with its (markup) symbol and unit."""
    return f"{symbol} = {num(mu, lang)} {unit(unit_key, lang)}"


# -- the catalogue ----------------------------------------------------------------------------------
# key → (Ukrainian, English). Keys name the idea; a value may hold {fields} for str.format.
# tomllib's own messages (Python 3.11–3.13) in Ukrainian: a scene's syntax error said in one language
# ("bad toml at"; model.bounds.toml_why) — an unknown one stays as tomllib words it
TOML_SAID = {
    "Escaped character is not a Unicode scalar value": "екранований символ не є скалярним значенням Юнікоду",
    "Expected ']' at the end of a table declaration": "бракує «]» наприкінці назви таблиці",
    "Expected ']]' at the end of an array declaration": "бракує «]]» наприкінці назви масиву таблиць",
    "Expected newline or end of document after a statement": "після значення очікувався кінець рядка",
    "Invalid date or datetime": "недійсна дата чи час",
    "Invalid hex value": "недійсне шістнадцяткове значення",
    "Invalid initial character for a key part": "недійсний перший символ ключа",
    "Invalid statement": "недійсний рядок сцени",
    "Unclosed array": "незакритий масив (бракує «]»)",
    "Unclosed inline table": "незакрита таблиця в рядку (бракує «}»)",
    "Unescaped '\\' in a string": "неекранований «\\» у тексті",
    "Unterminated string": "незакриті лапки",
}


WORDS: dict[str, tuple[str, str]] = {
    # sheets: captions and tables
    "position plan": ("План положень", "Position plan"),
    "velocity plan": ("План швидкостей", "Velocity plan"),
    "acceleration plan": ("План прискорень", "Acceleration plan"),
    "position": ("положення", "position"),
    "positions": ("положення", "positions"),
    "diagrams": ("Кінематичні діаграми", "Kinematic diagrams"),
    "velocity table": ("Таблиця 1. Швидкості, {m/s}; ω, {rad/s}", "Table 1. Velocities, {m/s}; ω, {rad/s}"),
    "acceleration table": ("Таблиця 2. Прискорення, {m/s²}; ε, {rad/s²}, положення",
                           "Table 2. Accelerations, {m/s²}; ε, {rad/s²}, position"),
    "graphical": ("графічно", "graphical"),
    "analytic": ("аналітично", "analytic"),
    "quantity": ("величина", "quantity"),
    "structure formula": ("Структурна формула", "Structural formula"),
    "mobility": ("Ступінь рухомості", "Mobility"),
    "scales": ("Масштабні коефіцієнти", "Scale coefficients"),
    "precision": ("Точність креслення", "Drafting precision"),
    "max error": ("Найбільша похибка планів швидкостей (вектори від 20 мм)",
                  "Largest error of the velocity plans (vectors from 20 mm)"),
    # the force sheet (sheets/forces.py)
    "fs group": ('Група', 'Group'),
    "fs polygon": ('План сил групи', 'Force plan of group'),
    "fs table": ('Сили групи', 'Forces of group'),
    "fs lever": ('Важіль Жуковського', 'Zhukovsky lever'),
    "fs results": ('Зрівноважувальний момент', 'Balancing moment'),
    "fs moment": ('Зрівноважувальний момент за оберт', 'Balancing moment over a turn'),
    "fs hodograph": ('Годограф реакції', 'Hodograph of reaction'),
    "fs subtitle": ('Силовий аналіз', 'Force analysis'),
    "fs at": ('кут кривошипа φ =', 'crank angle φ ='),
    "fs acceleration": ('План прискорень', 'Acceleration plan'),
    "fs position": ('положення силового розрахунку', 'position of the force analysis'),
    "fs inertia": ('Таблиця 5. Маси, моменти інерції, сили та моменти сил інерції', 'Table 5. Masses, moments of inertia, inertia forces and moments'),
    "fs link": ('ланка', 'link'),
    "fs mechanism": ('Схема механізму з прикладеними силами', 'The mechanism with the applied forces'),
    "fs reaction": ('Реакція стояка на повзун', 'Reaction of the frame on the slider'),
    "fs resistance": ('Діаграма сили корисного опору за хід', 'Resistance force over the stroke'),
    "fs resistance of": ('Діаграма сили корисного опору {p} за хід', 'Resistance force {p} over the stroke'),
    "fs resistance moment": ('Діаграма моменту корисного опору за хід', 'Resistance moment over the swing'),
    "fs jump": ("пунктир — стрибок від {what}", "dashed: the jump due to {what}"),
    "fs coincide": ("Годографи: номер «0–2» — точки, що збігаються з точністю лінійки 0,5 мм",
                    "Hodographs: a number \"0–2\" marks points that coincide to the ruler's 0.5 mm"),
    "fs couple": ("{what} на важелі — моментом M·l_{{xy}}/l_{{XY}}: відрізок {seg} коротший за {mm} мм",
                   "{what} on the lever as a moment M·l_{{xy}}/l_{{XY}}: its image {seg} is under {mm} mm"),
    "fs small": ('Сили, коротші за 10 мм (довжина, частка найбільшої на своєму плані): ', "Forces drawn under 10 mm (length, share of the largest on their plan): "),
    # the kinematics sheet (sheets/kinematics.py)
    "kin positions": ('План положень', 'Position plan'),
    "kin velocity": ('План швидкостей', 'Velocity plan'),
    "kin acceleration": ('План прискорень', 'Acceleration plan'),
    "kin position": ('положення', 'position'),
    "kin diagrams": ('Кінематичні діаграми', 'Kinematic diagrams'),
    "kin vel_table": ('Таблиця 1. Швидкості, м/с; ω, рад/с', 'Table 1. Velocities, m/s; ω, rad/s'),
    "kin acc_table": ('Таблиця 2.{n}. Прискорення, м/с²; ε, рад/с², положення {i}', 'Table 2.{n}. Accelerations, m/s²; ε, rad/s², position {i}'),
    "kin graphical": ('графічно', 'graphical'),
    "kin analytic": ('аналітично', 'analytic'),
    "kin error": ('δ, %', 'δ, %'),
    "kin quantity": ('величина', 'quantity'),
    "kin structure": ('Структурна формула', 'Structural formula'),
    "kin mobility": ('Ступінь рухомості', 'Mobility'),
    "kin scales": ('Масштабні коефіцієнти', 'Scale coefficients'),
    "kin precision": ('Точність креслення', 'Drafting precision'),
    "kin forces": ('Силовий аналіз', 'Force analysis'),
    "kin max_error": ('Найбільша похибка в таблицях {t}', 'Largest error in tables {t}'),
    "kin max_error_20": ('векторів від 20 мм', 'vectors from 20 mm'),
    "kin subtitle": ('Кінематичний аналіз', 'Kinematic analysis'),
    "kin dims yoke angle": ("α_{{{n}}} — кут паза ланки {n} до напрямної її штока",
                            "α_{{{n}}}: the angle of link {n}'s slot to its rod's guide"),
    "kin dims wedge angle": ("α_{{{n}}} — кут похилої грані клина {n} до його напрямної",
                             "α_{{{n}}}: the angle of the wedge {n}'s inclined face to its guide"),
    "kin dims yoke": ("α_{{{n}}} — кут паза ланки {n} до напрямної її штока; e_{{{n}}} — від {d} до осі паза вздовж штока",
                      "α_{{{n}}}: the angle of link {n}'s slot to its rod's guide; e_{{{n}}}: from {d} to the slot's line along the rod"),
    "kin dims": ('Таблиця {n}. Розміри ланок', 'Table {n}. Dimensions of the links'),
    "kin short_pole": ('{seg} = {mm} мм (менше {least} мм): найдовший вектор планів {kind} — {vec} плану {n}, {long} мм; '
                       'за {seg} = {least} мм він мав би {at} мм',
                       '{seg} = {mm} mm (under {least} mm): the longest vector of the {kind} plans is plan {n}\'s {vec}, '
                       '{long} mm; at {seg} = {least} mm it would be {at} mm'),
    "kin swing": ('Кут розмаху ланки {link} між крайніми положеннями {a} і {b}: ψ_max = {deg}° = {rad} рад',
                  'Swing of link {link} between its extreme positions {a} and {b}: ψ_max = {deg}° = {rad} rad'),
    "kin dims middles": ('{names} — посередині ланок', '{names}: at the middles of their links'),
    "kin dims middle": ('{names} — посередині ланки', '{names}: at the middle of its link'),
    "kin link": ('ланка', 'link'),
    "kin dims from": ('{symbol} від {pivot}', '{symbol} from {pivot}'),
    "kin dims from point": ('{symbol}: {pivot} — напрямна {point}', '{symbol}: {pivot} to guide {point}'),
    "kin dims guide angle": ('напрямна {point} до осі x', 'guide {point} to the x axis'),
    "kin real": ('l, м', 'l, m'),
    "kin drawn": ('l, мм (μ_l)', 'l, mm (μ_l)'),
    "kin lab": ('Таблиця {n}. s, v, a у заданих положеннях', 'Table {n}. s, v, a at the given positions'),
    "kin no": ('№', 'No.'),      # review 53 #11: "№" is not an English sign
    "kin readings": ('Таблиця {n}. Діаграми в положеннях поруч з планами', 'Table {n}. Diagrams read at the positions, beside the plans'),
    "kin readings_plan": ('план', 'plan'),
    "kin readings_exact": ('точно', 'exact'),
    "kin readings_delta": ('δ — від точного (від |max|, де |значення| < 10 % |max|)',
                           'δ: of the exact value (of |max| where |value| < 10 % of it)'),
    "kin readings_max": ('; |max| {tops}', '; |max| {tops}'),
    "kin readings_mark": ('; * — понад 5 %', "; * — over 5 %"),
    "kin readings_signs_cw": ('Тут {sym}_{{{n}}}, −ω_{{{n}}}, −ε_{{{n}}} (і рядки «план»): +\u00a0за годинниковою стрілкою, '
                              'як на діаграмах; ω_{{{n}}}, ε_{{{n}}} у таблицях {t}: +\u00a0проти годинникової стрілки',
                              'Here {sym}_{{{n}}}, −ω_{{{n}}}, −ε_{{{n}}} (the "plan" rows too): +\u00a0clockwise, as '
                              'on the diagrams; ω_{{{n}}}, ε_{{{n}}} in Tables {t}: +\u00a0counter-clockwise'),
    "kin readings_signs_back": ('Знаки s, v, a тут (і рядки «план»): +\u00a0від положення 0, проти напрямної, як на '
                                'діаграмах; таблиці {t} дають модулі |v|, |a| (довжина вектора × μ)',
                                'Signs of s, v, a here (the "plan" rows too): +\u00a0away from position 0, against the '
                                'guide, as on the diagrams; Tables {t} give the magnitudes |v|, |a| (a vector\'s length × μ)'),
    "kin other_lead": ('Діаграми точки {c} не креслено: {c} рухається, як {b}, з випередженням на {deg}° '
                       '(s_{{{c}}}(φ)\u00a0=\u00a0s_{{{b}}}(φ\u00a0+\u00a0{deg}°)) — її діаграми ті самі, зсунуті на {deg}° ліворуч; '
                       'v_{{{c}}}, a_{{{c}}} — у таблицях {t}',
                       '{c}\'s diagrams are not drawn: {c} moves as {b} does, {deg}° earlier '
                       '(s_{{{c}}}(φ)\u00a0=\u00a0s_{{{b}}}(φ\u00a0+\u00a0{deg}°)) — its diagrams are the same shifted {deg}° to the left; '
                       'v_{{{c}}}, a_{{{c}}} are in Tables {t}'),
    "kin other_lag": ('Діаграми точки {c} не креслено: {c} рухається, як {b}, із запізненням на {deg}° '
                      '(s_{{{c}}}(φ)\u00a0=\u00a0s_{{{b}}}(φ\u00a0−\u00a0{deg}°)) — її діаграми ті самі, зсунуті на {deg}° праворуч; '
                      'v_{{{c}}}, a_{{{c}}} — у таблицях {t}',
                      '{c}\'s diagrams are not drawn: {c} moves as {b} does, {deg}° later '
                      '(s_{{{c}}}(φ)\u00a0=\u00a0s_{{{b}}}(φ\u00a0−\u00a0{deg}°)) — its diagrams are the same shifted {deg}° to the right; '
                      'v_{{{c}}}, a_{{{c}}} are in Tables {t}'),
    "kin other_drawn": ('Діаграми — для вихідної точки {b} завдання; точки {c}: v_{{{c}}}, a_{{{c}}} — у таблицях {t} '
                        'і на планах',
                        'The diagrams are of the task\'s output {b}; of {c}: v_{{{c}}}, a_{{{c}}} in Tables {t} '
                        'and on the plans'),
    "kin dash": ('«—» у таблицях: мм для ε немає; δ не обчислено, де вектор коротший за півподілки лінійки або '
                 'точне значення ≈ 0',
                 '"—" in the tables: ε has no mm; δ not computed where a vector is under half a ruler division or '
                 'the exact value is ≈ 0'),
    "kin signs": ('Знаки s, v, a (діаграми, таблиця діаграм): + у напрямку напрямної {guide}; таблиці планів дають модулі |v|, |a|',
                  'Signs of s, v, a (diagrams, the diagrams\' table): + along the guide {guide}; the plans\' tables give the magnitudes |v|, |a|'),
    "kin signs_back": ('Таблиці планів дають модулі |v|, |a| (довжина вектора × μ). s — переміщення від крайнього '
                       'положення 0; знаки s, v, a на діаграмах і в таблиці діаграм: + від положення 0, тобто проти '
                       'напрямної {guide}',
                       'The plans\' tables give the magnitudes |v|, |a| (a vector\'s length × μ). s is the displacement '
                       'from the extreme position 0; signs of s, v, a on the diagrams and in the diagrams\' table: + away '
                       'from position 0, i.e. against the guide {guide}'),
    "kin signs_link": ('Знаки {sym}_{{{n}}} (кут ланки {link} від положення 0), ω_{{{n}}}, ε_{{{n}}} (таблиці, діаграми): + проти годинникової стрілки', 'Signs of {sym}_{{{n}}} (the angle of link {link} from position 0), ω_{{{n}}}, ε_{{{n}}} (tables, diagrams): + counter-clockwise'),
    "kin signs_link_cw": ('Знаки ω_{{{n}}}, ε_{{{n}}} в таблицях планів: + проти годинникової стрілки. {sym}_{{{n}}} — '
                          'кут повороту ланки {link} від крайнього положення 0; знаки {sym}_{{{n}}}, ω_{{{n}}}, '
                          'ε_{{{n}}} на діаграмах і в таблиці діаграм: + за годинниковою стрілкою',
                          'Signs of ω_{{{n}}}, ε_{{{n}}} in the plans\' tables: + counter-clockwise. {sym}_{{{n}}} is '
                          'the turn of link {link} from the extreme position 0; signs of {sym}_{{{n}}}, ω_{{{n}}}, '
                          'ε_{{{n}}} on the diagrams and in the diagrams\' table: + clockwise'),
    "lever unreadable": ("  pa читається як 0 мм при цьому μ_v: важіль не дає P_зр (візьміть точнішу --precision)",
                         "  pa reads 0 mm at this μv: the lever gives no P_bal (choose a finer --precision)"),
    "sheet page written": ("{path} ({form} {size}, аркуш {k} з {m}, {blocks}: {n})",
                           "{path} ({form} {size}, sheet {k} of {m}, {n} {blocks})"),
    "sheet written": ("{path} ({form} {size}, {blocks}: {n})", "{path} ({form} {size}, {n} {blocks})"),
    "kinematics subtitle": ("Кінематичний аналіз", "Kinematic analysis"),
    "forces subtitle": ("Силовий аналіз", "Force analysis"),
    "group": ("Група", "Group"),
    "force plan of group": ("План сил групи", "Force plan of group"),
    "reactions of group": ("Реакції групи", "Reactions of group"),
    "lever": ("Важіль Жуковського", "Zhukovsky lever"),
    "balancing moment": ("Зрівноважувальний момент", "Balancing moment"),
    "balancing moment turn": ("Зрівноважувальний момент за оберт", "Balancing moment over a turn"),
    "hodograph": ("Годограф реакції", "Hodograph of reaction"),
    "hodographs": ("Годографи реакцій в обертальних парах", "Hodographs of the reactions in the revolute pairs"),
    "pair": ("пара", "pair"),
    "chart turn": ("поворот кривошипа від положення 0, ° (робочий хід затінено)",
                   "crank turn from position 0, ° (working stroke shaded)"),
    "balancing moment crank": ("Зрівноважувальний момент на кривошипі", "Balancing moment on the crank"),
    "force": ("сила", "force"),
    "force value": ("значення, {N} ({N·m})", "value, {N} ({N·m})"),
    "drawn mm": ("на кресленні, {mm}", "drawn, {mm}"),
    "angle deg": ("кут, °", "angle, °"),
    "exact N": ("точно, {N}", "exact, {N}"),
    "exact deg": ("точно, °", "exact, °"),
    "closed form": ("аналітично (кінетостатика)", "closed form (kinetostatics)"),
    "closed form short": ("аналітично", "closed form"),
    "by force plans": ("за планами сил", "force plans"),
    "by lever": ("важіль Жуковського", "Zhukovsky lever"),
    "by power": ("баланс потужностей", "power balance"),
    "crank group": ("(кривошип)", "(the crank)"),
    "rotating output": ("ланки", "link"),
    "sliding output": ("точки", "point"),
    # title block (GOST 2.104)
    "tb rev": ("Зм.", "Ch."), "tb sheet": ("Арк.", "Sh."), "tb doc": ("№ докум.", "Doc. No."),
    "tb sign": ("Підпис", "Sign."), "tb date": ("Дата", "Date"), "tb drawn": ("Розроб.", "Drawn"),
    "tb checked": ("Перевір.", "Checked"), "tb tech": ("Т.контр.", "T.ctrl"),
    "tb norm": ("Н.контр.", "N.ctrl"), "tb approved": ("Затв.", "Approved"), "tb letter": ("Літ.", "Lit."),
    "tb mass": ("Маса", "Mass"), "tb scale": ("Масштаб", "Scale"), "tb sheet no": ("Аркуш", "Sheet"),
    "tb sheets": ("Аркушів", "Sheets"), "tb study letter": ("Н", "S"),
    # diagrams
    "diagrams title": ("Кінематичні діаграми {what} {how}", "Kinematic diagrams of {what} {how}"),
    "method chords": ("методом хорд", "by the method of chords"),
    "method corrected": ("методом хорд з корекцією площ", "by the method of chords with the area correction"),
    "method tangents": ("методом дотичних (дзеркало, ±{e}°)", "by the method of tangents (mirror, ±{e}°)"),
    "divisions count": ("{n} {n_divisions}", "{n} {n_divisions}"),
    "tangent ordinates": ("Ординати методу дотичних (на ординатах поділу)",
                          "The tangents' ordinates (at the division ordinates)"),
    "judged note": ("δ у положеннях — як у таблиці аркуша «Діаграми в положеннях поруч з планами»: від точного значення, "
                    "а де |точне| < 10 % |max| — від |max|",
                    "δ at the ordinates as the sheet's table “Diagrams read at the positions, beside the plans” gives it: "
                    "of the exact value, of |max| where |exact| < 10 % of |max|"),
    "at ordinates": ("На ординатах поділу (крива, прочитана на ординатах)",
                     "At the division ordinates (the curves read there)"),
    "chord ordinates": ("Ординати методу хорд (посередині інтервалів)",
                        "The chords' ordinates (at the middles of the intervals)"),
    "chosen": ("У двох заданих положеннях", "At the two chosen positions"),
    "no": ("№", "No."), "interval": ("інт.", "int."), "graph short": ("графічно", "graph."),
    "exact": ("точно", "exact"), "error pct": ("δ, %", "δ, %"),
    "integration": ("Графічне інтегрування (зворотна побудова)",
                    "Graphical integration (the reverse construction)"),
    "warnings": ("Попередження", "Warnings"), "none": ("немає", "none"),
    "v from a": ("v з a", "v from a"), "s from a": ("s з a через v", "s from a through v"),
    "s from v": ("s з ординат v", "s from the v ordinates"),
    "deviation": ("найбільше відхилення {mm} мм ({pct} % від максимуму), незамикання {cl} мм",
                  "largest deviation {mm} mm ({pct} % of the maximum), closure {cl} mm"),
    "period": ("T = 2π/ω_1 = {T} с на L = {L} мм", "T = 2π/ω_1 = {T} s over L = {L} mm"),
    "letters": ("а) б) в)", "a) b) c)"),
    # plans (terminal)
    "plans title": ("графічні плани", "graphical plans"),
    "ruler": ("лінійка", "ruler"),
    "structure": ("будова", "structure"),
    "velocities read": ("Швидкості, виміряні на планах швидкостей, {m/s} (ω, {rad/s}, + проти годинникової стрілки)",
                        "Velocities read off the velocity plans, {m/s} (ω, {rad/s}, + counter-clockwise)"),
    "errors exact": ("Похибки відносно точного розв'язку, % (— де точне значення ≈ 0)",
                     "Errors against the exact solution, % (— where the exact value is ~0)"),
    "accelerations at": ("Прискорення в положенні", "Accelerations at position"),
    "turn col": ("пов., °", "turn, °"),
    "turn note": ("φ — кут кривошипа від осі x; пов. — поворот кривошипа від положення 0 у бік його обертання "
                  "(φ аркушів)",
                  "φ: the crank angle from the x axis; turn: the crank's turn from position 0 in its sense "
                  "(the sheets' φ)"),
    "plan": ("план", "plan"),
    "error": ("похибка, %", "error, %"),
    "rates": ("ε, {rad/s²}, + проти годинникової стрілки", "ε, {rad/s²}, + counter-clockwise"),
    # plan warnings
    "warn lines": ("{plan}, {group} ({step}): напрямні лінії перетинаються під кутом {angle}° "
                   "(< {limit}°); зсув на 0,5 мм переміщує {what} на {slip} мм",
                   "{plan}, {group} ({step}): the direction lines cross at {angle}° "
                   "(< {limit}°); a 0.5 mm slip moves {what} by {slip} mm"),
    "warn position": ("план положень, {group}: {what} під кутом {angle}° (< {limit}°), {how}",
                      "position plan, {group}: {what} at {angle}° (< {limit}°), {how}"),
    "nearly tangent": ("майже дотичні", "nearly tangent"),
    "nearly parallel": ("майже паралельні", "nearly parallel"),
    "warn dead centre": ("мертве положення {groups} при φ = {phi}°{near}: {names} {verb}; "
                         "їхні похибки у відсотках не наводяться",
                         "dead centre of {groups} at φ = {phi}°{near}: {names} {verb}; "
                         "their percent errors are left out"),
    "and": ("і", "and"),
    "vanishes": ("дорівнює нулю", "vanishes"),
    "vanish": ("дорівнюють нулю", "vanish"),
    "near extreme": (", {angle}° від крайнього положення φ = {phi}°", ", {angle}° from the extreme position φ = {phi}°"),
    "velocity plan lower": ("план швидкостей", "velocity plan"),
    "acceleration plan lower": ("план прискорень", "acceleration plan"),
    "position plan lower": ("план положень", "position plan"),
    # analyze (terminal), the study's warnings
    "dyad title": ("група {label} {kind} (ланки {a}, {b})", "dyad {label} {kind} (links {a}, {b})"),
    "warn near locking": ("{dyad}: напрямні лінії перетинаються лише під кутом {angle}° біля кута кривошипа "
                          "{phi}° (майже заклинювання; плани там погано обумовлені)",
                          "{dyad}: its direction lines cross at only {angle}° near crank angle {phi}° "
                          "(close to locking; plans there are ill-conditioned)"),
    "warn block near pivot": ("{dyad}: повзун {block} проходить на відстані {mm} мм від опори {pivot} біля "
                              "кута кривошипа {phi}°; ω куліси сягає {w} рад/с",
                              "{dyad}: the block {block} passes within {mm} mm of the pivot {pivot} near "
                              "crank angle {phi}°; the slotted link's ω reaches {w} rad/s"),
    "warn past slot end": ("{dyad}: повзун {block} виходить за кінець {end} ланки {link} на {mm} мм "
                           "(|{pivot}{block}| до {reach} мм при {pivot}{end} = {length} мм) при кутах кривошипа "
                           "{ranges} ({positions}); подовжте ланку {link}",
                           "{dyad}: the block {block} runs {mm} mm past the end {end} of the link {link} "
                           "(|{pivot}{block}| up to {reach} mm against {pivot}{end} = {length} mm) at crank angles "
                           "{ranges} ({positions}); lengthen the link {link}"),
    "ccw": ("проти годинникової стрілки", "counter-clockwise"),
    "cw": ("за годинниковою стрілкою", "clockwise"),
    "dyad line": ("  {label}: {kind}, ланки {a} і {b}", "  {label}: {kind}, links {a} and {b}"),
    "derived": ("  обчислено {key} = {value}", "  derived {key} = {value}"),
    "turns fully": ("немає (ланка повертається повністю)", "none (the output turns fully)"),
    "output line": ("вихідна ланка {name}; крайні положення при φ = {ex}; положення 0 при φ = {phi0}°",
                    "output {name}; extreme positions at φ = {ex}; position 0 at φ = {phi0}°"),
    "point velocities": ("Швидкості точок |v|, {m/s}", "Velocities of points |v|, {m/s}"),
    "point accelerations": ("Прискорення точок |a|, {m/s²}", "Accelerations of points |a|, {m/s²}"),
    "angular velocities": ("Кутові швидкості ω (+ проти годинникової стрілки), {rad/s}",
                           "Angular velocities ω (+ counter-clockwise), {rad/s}"),
    "angular accelerations": ("Кутові прискорення ε, {rad/s²}", "Angular accelerations ε, {rad/s²}"),
    "slide table": ("Повзун {key} ({slider} на {carrier}): s від положення 0, {m}; v, a вздовж напрямної; "
                    "коріолісове |a^k|",
                    "Slide {key} ({slider} on {carrier}): s from position 0, {m}; v, a along the guide; "
                    "Coriolis |a^k|"),
    "the frame": ("стояку", "the frame"),
    # forces (terminal)
    "forces at": ("силовий аналіз при φ = {phi}° ({turn}° повороту кривошипа від положення 0, {stroke})",
                  "force analysis at φ = {phi}° ({turn}° of crank turn from position 0, {stroke})"),
    "working stroke": ("робочий хід", "working stroke"),
    "idle stroke": ("холостий хід", "idle stroke"),
    "forces scales": ("ω_1 = {w} {rad/s}; точність креслення {p} {mm}; μ_l = {ml} {m/mm}, "
                      "μ_F = {mf} {N/mm}, μ_v = {mv} {(m/s)/mm}",
                      "ω_1 = {w} {rad/s}; drafting precision {p} {mm}; μ_l = {ml} {m/mm}, "
                      "μ_F = {mf} {N/mm}, μ_v = {mv} {(m/s)/mm}"),
    "loads": ("Навантаження: G = m·g, Φ = −m·a_S, M^Φ = −I_S·ε (+ проти годинникової стрілки), зовнішні сили",
              "Loads: G = m·g, Φ = −m·a_S, M^Φ = −I_S·ε (+ counter-clockwise), external forces"),
    "loads from plan": ("  a_S, ε — з плану прискорень (μ_a = {ma} {(m/s²)/mm}), як у планах сил і на важелі; «точно» — аналітично",
                        "  a_S, ε from the acceleration plan (μ_a = {ma} {(m/s²)/mm}), as the force plans and the lever take "
                        "them; \"exact\": the analytic solution"),
    "no loads": ("немає: у сцені немає ні мас, ні сил, тож усі реакції нульові",
                 "none: the scene gives no masses and no forces, so every reaction is zero"),
    "load": ("навантаження", "load"), "link": ("ланка", "link"), "value": ("значення", "value"),
    "group line": ("Група {label} {kind}, ланки {links}", "Group {label} {kind}, links {links}"),
    "moment eq balancing": ("  ΣM_{about} = 0: M_зр {terms} = 0 (сили × плечі в мм × μ_l) → M_зр = {r} {N·m}",
                            "  ΣM_{about} = 0: M_b {terms} = 0 (forces × arms in mm × μ_l) → M_b = {r} {N·m}"),
    "forces on group": ("  сили, що діють на групу:", "  forces on the group:"),
    "normal component": ("  {sym} = {mm} {mm_} · μ_F = {v} {N} (уздовж ланки, з плану сил)",
                         "  {sym} = {mm} {mm_} · μ_F = {v} {N} (along the link, from the force plan)"),
    "tau opposite": ("знак «−»: {sym} спрямована протилежно прийнятому",
                     "the minus: {sym} acts opposite to the sense assumed"),
    "reactions from plan": ("  реакції з плану сил:", "  reactions from the force plan:"),
    "lever head": ("Важіль Жуковського (план швидкостей, повернутий на 90°, μ_v = {mv} {(m/s)/mm}, pa = {pa} {mm}):",
                   "Zhukovsky lever (velocity plan turned 90°, μ_v = {mv} {(m/s)/mm}, pa = {pa} {mm}):"),
    "image": ("образ", "image"),
    "lever sum": ("  ΣF·h = {s} {N·mm} (h + проти годинникової стрілки відносно полюса)",
                  "  ΣF·h = {s} {N·mm} (h + counter-clockwise about the pole)"),
    "lever result": ("  P_зр = ΣF·h / pa = {p} {N};  M_зр = P_зр·l_OA = {m} {N·m}",
                     "  P_bal = ΣF·h / pa = {p} {N};  M_b = P_bal·l_OA = {m} {N·m}"),
    "balancing head": ("Зрівноважувальний момент на кривошипі M_зр ({N·m}, + проти годинникової стрілки):",
                       "Balancing moment on the crank M_b ({N·m}, + counter-clockwise):"),
    "M_b": ("M_зр", "M_b"), "P_b": ("P_зр", "P_bal"),   # not P_b beside a point B's P_B (review 13 #4)
    # keys, grading, bench
    "variant": ("варіант", "variant"), "student": ("студент", "student"), "status": ("стан", "status"),
    "ok": ("готово", "ok"), "skipped": ("пропущено", "skipped"),
    "keys title": ("Ключі відповідей: {table} — варіантів {n}, записано {written}",
                   "Answer keys: {table} — {n} variants, {written} written"),
    "keys skipped": (", пропущено {k}", ", {k} skipped"),
    "page of": ("аркуш {k} з {n}", "page {k} of {n}"),
    "variant note": ("варіант {v}: {note}", "variant {v}: {note}"),
    "rows in": ("{n} рядків за {t} с → {path}", "{n} rows in {t} s → {path}"),
    "bench head": ("розділ|метод|умови|час, с|похибка, %|стан", "section|method|setting|time, s|error, %|status"),
    "bench speed": ("швидкодія", "speed"), "bench stability": ("стійкість", "stability"),
    "bench chords": ("хорди", "chords"), "bench plans": ("плани", "plans"), "bench sheet": ("аркуш", "sheet"),
    "bench analytic": ("аналітично", "analytic"), "bench plans velocity": ("план швидк.", "plans velocity"),
    "bench plans acceleration": ("план приск.", "plans acceleration"), "bench chords v": ("хорди v", "chords v"),
    "bench chords a": ("хорди a", "chords a"),
    "bench ok": ("гаразд", "ok"), "bench warning": ("попередження", "warning"), "bench refused": ("відмова", "refused"),
    "bench precision": ("точність", "precision"),
    "bench external": ("зовнішні", "external"), "bench not installed": ("не встановлено", "not installed"),
    "bench closed-form dyads, vectorised over the angles (the reference)": (
        "групи в замкненій формі, векторизовано за кутами (еталон)",
        "closed-form dyads, vectorised over the angles (the reference)"),
    "bench positions": ("положення", "positions"), "bench velocities": ("швидкості", "velocities"),
    "bench accelerations": ("прискорення", "accelerations"),
    "bench sweep four_bar": ("чотириланковик до мертвого положення (O2B → 0,15 м)",
                             "four_bar toward its toggle (O2B → 0.15 m)"),
    "bench sweep crank_slider": ("кривошипно-повзунний l/r → 1", "crank_slider l/r → 1"),
    "bench sweep slotted": ("куліса, опора куліси → коло кривошипа (c/r → 1)",
                            "slotted link, rocker pivot → crank circle (c/r → 1)"),
    # every other word a bench row says (bench/run.py says a row by these phrases, English → the language)
    "bench differentiation": ("диференціювання", "differentiation"), "bench flywheel": ("маховик", "flywheel"),
    "bench cam": ("кулачок", "cam"), "bench processes": ("процеси", "processes"),
    "bench chords+correction": ("хорди з корекцією", "chords+correction"), "bench tangents": ("дотичні", "tangents"),
    "bench wittenbauer": ("Віттенбауер", "wittenbauer"), "bench exact": ("точно", "exact"),
    "bench graphical": ("графічно", "graphical"), "bench ruler": ("лінійка", "ruler"),
    "bench tangents=exact": ("дотичні=точні", "tangents=exact"),
    "bench tangents=course": ("дотичні=як у курсі", "tangents=course"),
    "bench equation of motion": ("рівняння руху", "equation of motion"),
    "bench law shocks": ("{law} закон (жорсткі удари)", "{law} law (rigid shocks)"),
    "bench near 90": ("(близько 90°)", "(near 90°)"), "bench roller": ("ролик", "roller"),
    "bench undercut": ("(підрізання)", "(undercut)"),
    "bench scene crank_slider": ("кривошипно-повзунний", "crank_slider"),
    "bench scene four_bar": ("чотириланковик", "four_bar"),
    "bench scene shaper": ("поперечно-стругальний", "shaper"), "bench scene slotter": ("довбальний", "slotter"),
    "bench scene lab": ("лабораторний", "lab"),
    "bench whole process": ("цілий процес", "whole process"), "bench bare import": ("від самого імпорту", "bare import"),
    "bench MB": ("МБ", "MB"), "bench set": ("комплект", "set"), "bench forces": ("сили", "forces"),
    "bench dynamics": ("динаміка", "dynamics"), "bench diagrams": ("діаграми", "diagrams"),
    "bench view": ("дослідник", "view"),
    "bench failed": ("збій:", "failed:"), "bench not compared": ("не порівняно:", "not compared:"),
    "bench one dyad": ("порівнюємо лише кривошип з однією групою ВВВ або ВВП",
                       "only a crank with one RRR or RRP dyad is compared"),
    "bench not driven": ("групу веде не палець кривошипа", "the dyad is not driven by the crank pin"),
    "bench rocker not pinned": ("коромисло не закріплене на стояку", "the rocker is not pinned to the frame"),
    "bench guide not on frame": ("напрямна повзуна не на стояку", "the slider's guide is not on the frame"),
    "bench disagrees": ("НЕ ЗБІГАЄТЬСЯ з graphplan: інша збірка або невдалий розв'язок",
                        "DISAGREES with graphplan: another branch, or a failed solve"),
    "bench pure": ("чистий", "pure"), "bench absent": ("немає", "absent"),
    "bench nearest root": ("бере корінь, найближчий до попереднього положення",
                           "keeps the root nearest the previous position"),
    "bench previous root": ("кожен розв'язок починає з попереднього кореня", "each solve started from the previous root"),
    "bench did not converge": ("не збігся", "did not converge"),
    "bench progress": ("вимірювання", "bench"), "bench done": ("готово", "done"),
    "bench unknown section": ("--section {name}: один із розділів {known}", "--section {name}: one of {known}"),
    # the bench's charts (bench/run.py says each text of a chart by these phrases)
    "bench chart speed": ("Швидкодія аналітичного розв'язувача", "Speed of the analytic solver"),
    "bench vectorised": ("векторизовано", "vectorised"),
    "bench chart solver": ("аналітичний розв'язувач", "analytic solver"),
    "bench chart per call": ("положень за виклик", "positions per call"),
    "bench chart per second": ("положень за секунду", "positions per second"),
    "bench chart chords": ("Метод хорд: похибка залежно від кількості поділок (суцільні: точна лінійка, штрихові: 0,5 мм)",
                           "Method of chords: error against divisions (solid: exact ruler, dashed: 0.5 mm)"),
    "bench chart chords time": ("… і залежно від часу однієї побудови (найбільше H)",
                                "… and against the wall time of one construction (largest H)"),
    "bench chart divisions": ("поділок періоду", "divisions of the period"),
    "bench chart error of max": ("найбільша похибка, % від максимуму за цикл", "max error, % of the cycle's maximum"),
    "bench chart time": ("час однієї побудови, с", "wall time of one construction, s"),
    "bench chart lab limit": ("межа лаб. 5 %", "lab's 5 %"),
    "bench chart plans": ("Плани: похибка залежно від точності креслення", "Plans: error against the drafting precision"),
    "bench chart drafting exact": ("точність креслення, мм (0: точно, похибка ~1e-12 %)",
                                   "drafting precision, mm (0: exact, error ~1e-12 %)"),
    "bench chart drafting": ("точність креслення, мм", "drafting precision, mm"),
    "bench chart vectors": ("найбільша похибка векторів ≥ 20 мм, %", "max error of vectors ≥ 20 mm, %"),
    "bench velocity": ("швидкості", "velocity"), "bench acceleration": ("прискорення", "acceleration"),
    "bench chart angle": ("найменший кут між напрямними лініями, °", "smallest angle between direction lines, °"),
    "bench chart omega": ("найбільша |ω| ланки, рад/с", "max |ω| of the link, rad/s"),
    "bench chart plans error": ("найбільша похибка планів при 0,5 мм, %", "plans' max error at 0.5 mm, %"),
    "bench chart swept": ("змінюваний параметр (червоні: відмова, помаранчеві: попередження)",
                          "swept parameter (red: refused, orange: warned)"),
    "bench chart against divisions": ("похибка залежно від кількості поділок (бліді: точне креслення; яскраві: "
                                      "лінійка 0,5 мм, дотичні ±1°)",
                                      "error against divisions (faint: exact drawing; bold: ruler 0.5 mm, tangents ±1°)"),
    "bench chart against precision": ("похибка залежно від точності креслення (яскраві N = 12, бліді N = 24)",
                                      "error against the drafting precision (bold N = 12, faint N = 24)"),
    "bench chart against angle": ("метод дотичних залежно від його кутової похибки",
                                  "method of tangents against its angular error"),
    "bench chart ruler division": ("поділка лінійки, мм (0 показано при 0,02; дотичні ±1°)",
                                   "ruler's division, mm (0 drawn at 0.02; tangents ±1°)"),
    "bench chart angle bound": ("межа кутової похибки дотичних, ° (0 показано при 0,1)",
                                "tangents' angular error bound, ° (0 drawn at 0.1)"),
    "bench chart as the lab": ("(лаб.)", "(lab)"), "bench chart exact": ("(точно)", "(exact)"),
    "bench chart flywheel": ("Маховик за Віттенбауером проти рівняння руху (суцільні: точна лінійка, штрихові: 0,5 мм)",
                             "Wittenbauer flywheel against the equation of motion (solid: exact ruler, dashed: 0.5 mm)"),
    "bench chart turn": ("поділок оберту", "divisions of the turn"),
    "bench chart flywheel error": ("|похибка маховика|, % від точного", "|flywheel error|, % of the exact one"),
    "bench chart phase": ("поділок кожної фази", "divisions of each phase"),
    "bench chart R0": ("|похибка R0|, %", "|R0 error|, %"),
    "bench chart profile": ("похибка радіуса профілю (найбільша), %", "profile radius error (max), %"),
    "bench chart eps": ("похибка εα, % (модуль на кресленні, мм)", "εα error, % (module drawn, mm)"),
    "bench chart u1H": ("похибка u1H, % (радіус вінця на кресленні, мм)", "u1H error, % (ring's radius drawn, mm)"),
    # answer keys
    "key title": ("Ключ відповідей, варіант {variant}", "Answer key, variant {variant}"),
    "key heading": ("Ключ відповідей — варіант {variant}", "Answer key — variant {variant}"),
    "student cap": ("Студент", "Student"),
    "variant data": ("Дані варіанта", "Variant data"),
    "unit": ("одиниця", "unit"),
    "key output": ("вихідна ланка {name}, положення 0 при φ = {phi}°", "output {name}, position 0 at φ = {phi}°"),
    "key tolerance": ("Допуск ±{tol} %{special}; де |точне| менше за {zero} % від найбільшого значення величини "
                      "за оберт — у межах ±допуску від цього значення. Швидкості та прискорення точок — модулі; "
                      "ω, ε + проти годинникової стрілки; an, at, ak, ar: нормальне, дотичне, коріолісове, "
                      "відносне; s, v, a: вихідна ланка вздовж напрямної від положення 0.",
                      "Tolerance ±{tol} %{special}; where |exact| is below {zero} % of the quantity's largest "
                      "value over the turn, within ±tolerance of that value. Velocities and accelerations of "
                      "points are magnitudes; ω, ε + counter-clockwise; an, at, ak, ar: normal, tangential, "
                      "Coriolis, relative; s, v, a: the output along its guide from position 0."),
    "key velocities": ("{n}. Швидкості в положеннях 0–{last}", "{n}. Velocities at positions 0–{last}"),
    "key acceleration": ("{n}. Прискорення в положенні {where}", "{n}. Accelerations at position {where}"),
    "key accelerations": ("{n}. Прискорення в положеннях {where}", "{n}. Accelerations at positions {where}"),
    "key diagrams": ("{n}. Діаграми {name} методом хорд, поділок: {k}", "{n}. Diagrams of {name} by chords, {k} divisions"),
    "key diagrams note": ("s і a на поділках k, v посередині хорд k + {half}",
                          "s and a at the divisions k, v at the chord midpoints k + {half}"),
    "key curves": ("{n}. Точні s, v, a ланки {name} за один оберт від положення 0",
                   "{n}. The exact s, v, a of {name} over one turn from position 0"),
    "key axis note": ("k: поділки; ординати ключа позначено", "k: divisions; ordinates of the key marked"),
    "summary note": ("φ_0: кут кривошипа в положенні 0; H, K розр.: хід (розмах) вихідної ланки та коефіцієнт "
                     "зміни середньої швидкості; |v|_max, |a|_max: найбільші за оберт; стовпці від «пол. a»: "
                     "у першому положенні плану прискорень.",
                     "φ_0: the crank angle of position 0; H, K calc: the output's stroke (swing) and time-ratio "
                     "coefficient; |v|_max, |a|_max: the output's largest over the turn; the columns from pos. a on: "
                     "at the first acceleration-plan position."),
    # grading notes and the report
    "grade no key": ("немає ключа для варіанта {variant} (ключі: {known})", "no key for variant {variant} (keys: {known})"),
    "grade not a number": ("положення {text} не є числом", "position {text} is not a number"),
    "grade abscissae": ("абсциси діаграми: 0, {half}, … {n}", "the diagram's abscissae are 0, {half}, … {n}"),
    "grade positions": ("положення: 0 … {last}", "positions are 0 … {last}"),
    "grade position is 0": ("положення {count} — це положення 0", "position {count} is position 0"),
    "grade unknown quantity": ("невідома величина {q}", "unknown quantity {q}"),
    "grade no value": ("немає значення", "no value"),
    "grade no scene": ("немає в ключі (і немає сцени, щоб обчислити)", "not in the key (and no scene to compute it)"),
    "grade computed": ("немає в ключі: обчислено", "not in the key: computed"),
    "grade near zero": ("майже нуль: допуск ±{bound} ({tol} % від {floor})",
                        "near zero: within ±{bound} ({tol} % of {floor})"),
    "grade zero": ("нуль при кожному куті кривошипа: допуск ±{bound} (як для {like} поблизу нуля)",
                   "zero at every crank angle: within ±{bound} (as {like} near zero)"),
    "grade cam division": ("ключ кулачка порівнює значення лише в поділці {k} (кут повороту кулачка {turn}° "
                           "від початку підйому, {phase})",
                           "a cam key compares the value at division {k} only (the cam's angle {turn}° "
                           "from the start of the rise, {phase})"),
    "grade cam rise": ("фаза підйому", "the rise"), "grade cam return": ("фаза опускання", "the return"),
    "grade key no scene": ("у ключі немає сцени: інші кути кривошипа не перевірено",
                           "the key has no scene: other crank angles not searched"),
    "grade constant": ("{name} дорівнює {v} при кожному куті кривошипа", "{name} is {v} at every crank angle"),
    "grade no angle": ("жоден кут кривошипа не дає {name} = {v} (за оберт {lo} … {hi})",
                       "no crank angle gives {name} = {v} (over the turn {lo} … {hi})"),
    "grade inaccurate": ("найближчий кут кривошипа з цим значенням — {turn}° від положення 0: "
                         "неточне значення для цього положення",
                         "the nearest crank angle with this value is {turn}° from position 0: "
                         "an inaccurate value for this position"),
    "grade fits position": ("відповідає положенню {at} ({turn}° від положення 0; точно там {there}), "
                            "а не положенню {claimed}",
                            "fits position {at} ({turn}° from position 0; exact there {there}), not position {claimed}"),
    "grade fits division": ("відповідає поділці {at} ({turn}° від положення 0; точно там {there}), "
                            "а не поділці {claimed}",
                            "fits division {at} ({turn}° from position 0; exact there {there}), not division {claimed}"),
    "graded against": ("{student}: перевірено за ключем {key}", "{student} graded against {key}"),
    "grade head": ("рядок|варіант|пол.|величина|значення|точно|похибка %|допуск %|результат|примітка",
                   "line|variant|pos|quantity|value|exact|error %|tol %|result|note"),
    "pass": ("зарах.", "pass"), "fail": ("НЕ ЗАРАХ.", "FAIL"),
    "grade summary": ("{rows}: зараховано {passed}, не зараховано {failed}, не оцінено {unknown}; "
                      "частка зарахованих {rate}; {other} іншому положенню",
                      "{rows}: {passed} passed, {failed} failed, {unknown} not graded; "
                      "pass rate {rate}; {other} another position"),
    # the rows counted, the noun and the verb agreeing with the number (uk_count): 1 рядок, 2 рядки, 5 рядків
    "rows one": ("{n} рядок", "{n} row"), "rows few": ("{n} рядки", "{n} rows"), "rows many": ("{n} рядків", "{n} rows"),
    "rows fit one": ("{n} рядок відповідає", "{n} row fits"), "rows fit few": ("{n} рядки відповідають", "{n} rows fit"),
    "rows fit many": ("{n} рядків відповідають", "{n} rows fit"),
    "grade variant": ("  варіант {v}: зараховано {passed}/{total} ({rate})", "  variant {v}: {passed}/{total} passed ({rate})"),
    "grade variant unknown": (", не оцінено {n}", ", {n} not graded"),
    "grade variant other": (", {n} відповідають іншому положенню", ", {n} fit another position"),
    # issue 24 (one set of numbers, the lab's notation, every check said on the sheet)
    # the sign's parenthesis with no-break spaces: a title wraps before it, never inside it
    "kin vel_table_signed": ("Таблиця 1. Швидкості: |v|, м/с; ω, рад/с (+\u00a0проти\u00a0год.\u00a0стр.)",
                             "Table 1. Velocities: |v|, m/s; ω, rad/s (+\u00a0counter-clockwise)"),
    "kin acc_table_signed": ("Таблиця {n}. Прискорення |a|, м/с²; ε, рад/с² (+\u00a0проти\u00a0год.\u00a0стр.), "
                             "положення\u00a0{i}",
                             "Table {n}. Accelerations |a|, m/s²; ε, rad/s² (+\u00a0counter-clockwise), position\u00a0{i}"),
    "sheet phi": ("φ — поворот кривошипа від положення 0 у бік його обертання; положення 0: кут кривошипа {phi0}° "
                  "від осі x",
                  "φ: the crank's turn from position 0 in its sense of rotation; position 0: crank angle {phi0}° "
                  "from the x axis"),
    "kin turn_at": ("φ = {turn}° від положення 0", "φ = {turn}° from position 0"),
    "kin why_short": ("{sym}: короткий вектор ({mm} мм)", "{sym}: a short vector ({mm} mm)"),
    "kin why_short_from": ("{sym}: прочитано з короткого вектора ({mm} мм): пів поділки лінійки — {share} % його, "
                           "а знайдений перетином, він несе похибки векторів перед ним",
                           "{sym}: read from a short vector ({mm} mm): half a ruler division is {share} % of it, "
                           "and found by the intersection it carries the errors of the vectors before it"),
    "kin why_angle": ("{sym}: напрямні лінії перетинаються під малим кутом ({angle}°)",
                      "{sym}: the direction lines cross at a small angle ({angle}°)"),
    "kin why_ruler": ("{sym}: точність лінійки", "{sym}: the ruler's precision"),
    "kin why_chords": ("{sym}: крупні поділки — хорди самі дають {e} % ({n} поділок)",
                       "{sym}: coarse divisions — the chords alone miss by {e} % ({n} divisions)"),
    "kin why_ordinate": ("{sym}: коротка ордината ({mm} мм)", "{sym}: a short ordinate ({mm} mm)"),
    "kin mark_head": ("* — похибка понад 5 % (межа лабораторної роботи):", "* — an error over 5 % (the limit the lab sets):"),
    "kin mark_row": ("положення {n}: {why}", "position {n}: {why}"),
    "kin mark_cell": ("{why}", "{why}"),
    "kin group": ("гр.\u00a0{g}", "group\u00a0{g}"),
    "fs inertia note": ("a_S, ε — з плану прискорень (табл. {n}); Φ = m·a_S (напрям проти a_S на плані) і M^Φ = −I_S·ε "
                        "з них діють у планах сил і на важелі; «точно» — з аналітичного розв'язку; ε, M^Φ: + проти год. стрілки",
                        "a_S, ε from the acceleration plan (Table {n}); Φ = m·a_S (directed against a_S as drawn) and "
                        "M^Φ = −I_S·ε from them act on the force plans and the lever; \"exact\": the analytic solution; "
                        "ε, M^Φ: + counter-clockwise"),
    "fs inertia exact rows": ("ланки {links}: a_S, ε не побудовані на плані — з аналітичного розв'язку",
                              "links {links}: a_S, ε not constructed on the plan, from the analytic solution"),
    "fs force position": ("φ = {turn}° від положення 0 (кут кривошипа {phi}° від осі x)",
                    "φ = {turn}° from position 0 (crank angle {phi}° from the x axis)"),
    "fs force position short": ("φ = {turn}° від положення 0 ({phi}° від осі x)",
                                "φ = {turn}° from position 0 ({phi}° from the x axis)"),
    "fs why detail": ("{sym}: на плані коротший за поділку ({mm} мм), прочитано на виносному елементі I, де план "
                      "побудовано знову при μ_F = {mu} Н/мм; похибку дає округлення відомих сил там ({n} сил по "
                      "±{half} мм)",
                      "{sym}: shorter than a division on its plan ({mm} mm), read off detail I, where the plan is "
                      "laid again at μ_F = {mu} N/mm; its error is the known forces rounded there ({n} forces, "
                      "±{half} mm each)"),
    "fs why detail tau": ("{sym}: на плані коротший за поділку ({mm} мм), прочитано на виносному елементі I, де план "
                          "побудовано знову при μ_F = {mu} Н/мм; похибку дає округлення відомих сил там ({n} сил по "
                          "±{half} мм) і {tau}, знайдена з плечима, виміряними на кресленні групи",
                          "{sym}: shorter than a division on its plan ({mm} mm), read off detail I, where the plan is "
                          "laid again at μ_F = {mu} N/mm; its error is the known forces rounded there ({n} forces, "
                          "±{half} mm each) and {tau}, found with the arms measured on the group's drawing"),
    "fs why short": ("{sym}: короткий вектор на плані ({mm} мм): пів поділки лінійки — {share} % його, а як сторона, "
                     "що замикає план, він несе округлення відомих сил ({n} сил по ±{half} мм)",
                     "{sym}: a short vector on its plan ({mm} mm): half a ruler division is {share} % of it, and as "
                     "the side closing the plan it carries the known forces' rounding ({n} forces, ±{half} mm each)"),
    "fs why angle": ("{sym}: лінії реакцій перетинаються під малим кутом ({angle}°)",
                     "{sym}: the reactions' lines cross at a small angle ({angle}°)"),
    "fs why pa": ("{sym}: короткий відрізок pa на важелі ({mm} мм)", "{sym}: a short pa on the lever ({mm} mm)"),
    "fs slide arm": ("{h} = {mm} мм: {r} діє на відстані {m} м від {p} уздовж напрямної (точно {e} м, δ = {d} %), "
                     "з ΣM_{p} = 0 ланки {n} групи {g}",
                     "{h} = {mm} mm: {r} acts {m} m from {p} along the guide (exact {e} m, δ = {d} %), "
                     "from ΣM_{p} = 0 of link {n} of group {g}"),
    "fs why arms": ("{sym}: плечі, прочитані лінійкою до {p} мм", "{sym}: arms read with a {p} mm ruler"),
    "fs why carried": ("{sym}: {r} = {f} Н (точно {fe}) з плану групи {g} (R^τ — з плечей, прочитаних при μ_l = {ml} м/мм), "
                       "її лінія відхилена на {da}°: плече {h} мм (точно {he}), момент {m} Н·м (точно {me}); решта "
                       "моментів кривошипа ({rest} Н·м) віднімається від нього — відносна похибка результату у {k} раза більша",
                       "{sym}: {r} = {f} N (exact {fe}) from group {g}'s plan (R^τ by arms read at μ_l = {ml} m/mm), "
                       "its line {da}° off: arm {h} mm (exact {he}), moment {m} N·m (exact {me}); the crank's other "
                       "moments ({rest} N·m) cancel against it — the result's relative error {k} times that moment's"),
    "fs idle": ("холостий хід", "idle stroke"),
    "fs working": ("робочий хід", "working stroke"),
    "fs path": ("шлях {s} від положення 0, {u}", "path of {s} from position 0, {u}"),
    # issue 25: the explorer's command (`graphplan view`) in the scene's language
    "view html": ("-o {name}: сторінка дослідника — файл .html, дайте ім'я з цим розширенням",
                  "-o {name}: the explorer is an HTML file, give a name ending in .html"),
    "view folder": ("-o {name}: потрібне ім'я файлу, а це тека", "-o {name}: a file name is needed, this is a folder"),
    "view step": ("--step: крок сітки кутів має бути від 0,05 до 30°, задано {step}",
                  "--step: the angle grid's step must be from 0.05 to 30 degrees, got {step}"),
    "view precision": ("--precision: точність креслення має бути від 0 до 10 мм, задано {p}",
                       "--precision: the drafting precision must be from 0 to 10 mm, got {p}"),

    # gears: graphplan bench --section gears (bench/gears.py)
    "bench gears": ("зубчасті", "gears"), "bench contact ratio": ("перекриття εα", "contact ratio"),
    "bench ratio u1H": ("відношення u1H", "ratio u1H"), "bench failure": ("межа методу", "failure"),
    # sheet set
    "tb changes": ("Змн.", "Rev."),
    "tb no scale": ("—", "—"),
    "asm group at": ("група {label} не складається при куті кривошипа {phi}°",
                     "group {label} cannot be assembled at crank angle {phi}°"),
    "asm locks direction": ("{dyad} заклинює при куті кривошипа {phi}°: її напрямні лінії збігаються (кут передачі "
                            "0°), кривошип не може провести її далі",
                            "{dyad} locks at crank angle {phi}°: its direction lines coincide (transmission angle "
                            "0°), the crank cannot drive it through"),
    "asm beyond": ("{dyad} відкидає ланки далі ніж на {km} км при куті кривошипа {phi}°: вона майже заклинена "
                   "(куліса майже вздовж своєї напрямної?)",
                   "{dyad} throws its links beyond {km} km at crank angle {phi}°: it is nearly locked (a slot "
                   "almost along its guide?)"),
    "asm never": ("{dyad} не складається за жодного кута кривошипа", "{dyad} cannot be assembled at any crank angle"),
    "asm locks line": ("{dyad} заклинює при куті кривошипа {where}: її ланки стають в одну лінію, кривошип не може "
                       "провести її далі",
                       "{dyad} locks at crank angle {where}: its links come into line, the crank cannot drive it "
                       "through"),
    "asm ranges": ("{dyad} не складається для кутів кривошипа {ranges}",
                   "{dyad} cannot be assembled for crank angles {ranges}"),
    "asm through pivot": ("{dyad}: повзун {block} проходить через опору {pivot} при куті кривошипа {phi}° (ближче "
                          "ніж {mm} мм): напрям куліси там невизначений, її ω необмежена, кривошип не може "
                          "провести механізм далі",
                          "{dyad}: the block {block} passes through the pivot {pivot} at crank angle {phi}° "
                          "(within {mm} mm): the slotted link's direction is undefined there and its ω unbounded, "
                          "the crank cannot drive it through"),
}


# the program's own words inside a text: a file's column and key names, formats, commands (a "{@name}"
# field, filled in every language alike: the Ukrainian text names them as the file and the program do)
LITERALS: dict[str, str] = {
    "variant": "variant", "base": "base", "position": "position", "quantity": "quantity", "value": "value",
    "divisions": "divisions", "tolerance": "tolerance", "accel": "accel", "positions_accel": "positions.accel",
    "params": "params", "values": "values", "branch": "branch", "key": "key", "gears": "gears", "serve": "serve",
    "gears_md": "docs/gears.md", "summary_json": "summary.json", "key_json": "key.json",
    "SCENE_toml": "SCENE.toml", "JSON": "JSON", "CSV": "CSV", "UTF-8": "UTF-8", "zip": "zip", "dpi": "dpi",
    "multipart": "multipart/form-data", "token": "…/?token=…", "bearer": "Authorization: Bearer TOKEN",
    "GRAPHPLAN_DEBUG=1": "GRAPHPLAN_DEBUG=1", "Ctrl-C": "Ctrl-C",
    "pip": "pip install starlette uvicorn python-multipart",
}


def word(key: str, lang: str, /, **fields: object) -> str:
    """The catalogue's text for ``key`` in ``lang``; {m/s}-style fields are units in that language,
    other {fields} are filled from ``fields``."""
    uk, en = WORDS[key]
    text = uk if lang == "uk" else en
    if "{" not in text:
        return text
    units = {k: unit(k, lang) for k in UNITS}
    if "{@" in text:
        units.update({"@" + k: v for k, v in LITERALS.items()})
    if "{n_divisions}" in text:           # the noun agreeing with its number
        try:
            n = int(str(fields.get("n")))
        except ValueError:
            n = 5                         # not a count: the plural
        fields = {**fields, "n_divisions": uk_count(n, "поділка", "поділки", "поділок") if lang == "uk"
                  else ("division" if n == 1 else "divisions")}
    return text.format_map(_Fields({**units, **{k: str(v) for k, v in fields.items()}}))


def uk_count(n: int, one: str, few: str, many: str) -> str:
    """The Ukrainian noun after the number n: 1, 21 поділка; 2–4, 22–24 поділки; 0, 5–20, 25 поділок."""
    n = abs(int(n))
    if n % 10 == 1 and n % 100 != 11:
        return one
    if 2 <= n % 10 <= 4 and not 12 <= n % 100 <= 14:
        return few
    return many


class Fixed(float):
    """A value ``said`` writes with a fixed count of decimals (an angle: 12.5°)."""

    def __new__(cls, value: float, decimals: int = 1):
        obj = super().__new__(cls, value)
        obj.decimals = decimals
        return obj


def said(key: str, /, **fields: object) -> dict[str, str]:
    """The catalogue's text in every language at once (for a message stored before anyone knows who
    reads it): floats through ``num`` (``Fixed`` through ``fixed``), in each language's writing."""
    def cell(v: object, lang: str) -> str:
        if callable(v):                       # a name that depends on the language
            return str(v(lang))
        if isinstance(v, Fixed):
            return fixed(v, lang, v.decimals)
        if isinstance(v, float):
            return num(v, lang)
        return str(v)
    return {lang: word(key, lang, **{k: cell(v, lang) for k, v in fields.items()}) for lang in LANGS}


class _Fields(dict):
    def __missing__(self, key: str) -> str:
        raise KeyError(f"words: no value for {{{key}}}")


# -- refusals of a bad scene (util.errors.keyed_error: "key: text", the key as the file writes it) -------------
# TOML names and the program's words stay as written: they are fields ({omega}, {rpm}), not text.
WORDS.update({
    # model/scene.py: a lever mechanism's scene
    "sc table": ("має бути таблицею", "must be a table"),
    "sc unknown key": ("невідомий ключ (дозволені: {allowed})", "unknown key (allowed: {allowed})"),
    "sc number": ("має бути числом", "must be a number"),
    "sc number or expression": ("має бути числом або виразом", "must be a number or an expression"),
    "sc finite": ("має бути скінченним числом", "must be finite"),
    "sc positive": ("має бути додатним{within}, задано {got}", "must be positive{within}, got {got}"),
    "sc pair": ("має бути парою [x, y]", "must be a pair [x, y]"),
    "sc name": ("має бути ім'ям", "must be a name"),
    "sc bad name": ("{why}, задано {got}", "{why}, got {got}"),
    "sc cam scene": ("це сцена кулачкового механізму: її креслять {cmd1} і {cmd2} ({doc}); ця команда приймає "
                     "важільний механізм",
                     "a cam scene: {cmd1} and {cmd2} draw it ({doc}); this command takes a lever mechanism"),
    "sc gear scene": ("це сцена зубчастої передачі: її креслять {cmd1} і {cmd2} ({doc}); ця команда приймає "
                      "важільний механізм",
                      "a gear scene: {cmd1} and {cmd2} draw it ({doc}); this command takes a lever mechanism"),
    "sc no crank": ("відсутній: сцені потрібен вхідний кривошип", "missing: a scene needs its input crank"),
    "sc array": ("має бути масивом таблиць {table}", "must be an array of tables {table}"),
    "sc name twice": ("ім'я {name} використано двічі", "the name {name} is used twice"),
    "sc number twice": ("номер ланки {number} використано двічі", "link number {number} is used twice"),
    "sc guide twice": ("ім'я напрямної {name} використано двічі", "the guide name {name} is used twice"),
    "sc no guide": ("немає напрямної з іменем {name} (напрямні: {known})", "no guide named {name} (guides: {known})"),
    "sc param name": ("ім'я параметра — слово, як-от r чи {example}",
                      "a parameter's name is a word such as r or {example}"),
    "sc synthesis type": ("відомий лише тип {known}", "only {known} is known"),
    "sc missing": ("відсутній", "missing"),
    "sc time ratio": ("коефіцієнт зміни середньої швидкості має бути більшим за 1, задано {got}",
                      "the time-ratio coefficient must exceed 1, got {got}"),
    "sc no frame": ("відсутній: сцені потрібна таблиця {table}", "missing: a scene needs {table}"),
    "sc no fixed point": ("має назвати хоча б одну нерухому точку", "must name at least one fixed point"),
    "sc point twice": ("точку вже задано на цій ланці", "the point is already defined on this link"),
    "sc fraction": ("частка потребує довжини ланки; задайте {pair} у метрах",
                    "a fraction needs the link's length; give {pair} in metres"),
    "sc not frame point": ("{name} не є точкою стояка ({known})", "{name} is not a frame point ({known})"),
    "sc speed once": ("задайте швидкість рівно одним із {omega} (рад/с) або {rpm} (об/хв)",
                      "give the speed as exactly one of {omega} (rad/s) or {rpm}"),
    "sc one of": ("має бути {choices}, задано {got}", "must be {choices}, got {got}"),
    "sc frame name crank": ("{name} — ім'я стояка; назвіть кривошип інакше",
                            "{name} is the frame's name; call the crank otherwise"),
    "sc frame name link": ("{name} — ім'я стояка; назвіть ланку інакше",
                           "{name} is the frame's name; call the link otherwise"),
    "sc point list": ("має бути списком імен точок", "must be a list of point names"),
    "sc joint twice": ("шарнір указано двічі", "a joint is listed twice"),
    "sc no joint": ("ланці потрібен хоча б один шарнір", "a link needs at least one joint"),
    "sc no ref": ("ланці, що ковзає без шарнірів, потрібна опорна точка",
                  "a sliding link without joints needs a reference point"),
    "sc no length": ("відсутня: відстань {dist}", "missing: the distance {dist}"),
    "sc no shape": ("відсутнє: де на ланці лежить шарнір {joint}", "missing: where the joint {joint} lies on the link"),
    "sc com": ("{name} не є точкою цієї ланки", "{name} is not a point of this link"),
    "sc branch": ("має бути +1 або -1, задано {got}", "must be +1 or -1, got {got}"),
    "sc start": ("має бути {choices} або кутом кривошипа, задано {got}",
                 "must be {choices} or a crank angle, got {got}"),
    "sc no link": ("немає ланки з таким іменем чи номером: {name} (ланки: {known})",
                   "no link named or numbered {name} (links: {known})"),
    "sc profile": ("має бути списком пар {pair}", "must be a list of {pair} pairs"),
    "sc increase": ("відстані мають зростати", "the distances must increase"),
    "sc delta": ("коефіцієнт нерівномірності руху має лежати в (0; 0,5), задано {got}",
                 "the coefficient of unevenness must lie in (0, 0.5), got {got}"),
    "sc motor": ("має бути назвою з каталогу або таблицею даних двигуна",
                 "must be a catalogue name or a table of the motor's data"),
    "sc efficiency": ("має лежати в (0; 1], задано {got}", "must lie in (0, 1], got {got}"),
    "sc nonnegative": ("має бути ≥ 0, задано {got}", "must be ≥ 0, got {got}"),
    "sc shafts": ("має бути моментами інерції {list}, {kg·m²}", "must be {list} moments of inertia, {kg·m²}"),
    "sc shafts nonnegative": ("моменти інерції мають бути ≥ 0", "the moments of inertia must be ≥ 0"),
    "sc first stage": ("відсутнє: швидкість проміжного вала потребує передавального відношення першого ступеня "
                       "i1 = ω_дв/ω_пр",
                       "missing: the intermediate shaft's speed needs the first stage's ratio i1 = ω_motor/ω_intermediate"),
    "sc also frame": ("{name} — також точка стояка; імена точок стояка й ланок неповторні",
                      "{name} is also a frame point; names are unique across the frame's and the links' points"),
    "sc also link": ("{name} — також точка ланки {link}; дайте кожній точці своє ім'я",
                     "{name} is also a point of link {link}; give each point its own name"),
    "sc joint on sliding": ("шарнір {name} нічого не з'єднує: це точка ланки {link}, що ковзає по напрямній, а не її "
                            "шарнір; шарніром іншої ланки точка такої ланки буває лише як її власний шарнір — запишіть "
                            "у ланці {link} {joints} (її початок, замість {ref} та точки) і розмістіть її прорізи через "
                            "{through} відносно нього",
                            "joint {name} joins nothing: it is a point of the link {link}, which slides on a guide, not "
                            "its joint; a sliding link's point joins another link only as its own joint — write "
                            "{joints} in link {link} (its origin, in place of {ref} and the point) and place its slots "
                            "by {through} relative to it"),
    "sc joins nothing": ("шарнір {name} нічого не з'єднує: жодна інша ланка чи точка стояка його не має",
                         "joint {name} joins nothing: no other link or frame point has it"),
    "sc no point": ("такої точки немає", "no such point"),
    "sc output": ("{name} не є ні точкою, ні ланкою", "{name} is neither a point nor a link"),
    "sc no point named": ("немає точки з іменем {name}", "no point named {name}"),
    "sc pin frame": ("палець кривошипа не може бути точкою стояка", "the crank pin cannot be a frame point"),
    # model/cam.py: a cam's scene
    "cm not utf8": ("файл сцени не є текстом {utf}", "the scene is not {utf} text"),
    "cm gear scene": ("у сцені немає таблиці {table}: вона описує зубчастий механізм (його креслять {cmd1} і "
                      "{cmd2}, {doc})", "the scene has no {table} table: it describes a gear mechanism ({cmd1} and "
                      "{cmd2} draw it, {doc})"),
    "cm lever scene": ("у сцені немає таблиці {table}: вона описує важільний механізм ({cmd} читає сцену "
                       "кулачкового механізму, {doc})", "the scene has no {table} table: it describes a lever "
                       "mechanism ({cmd} reads a cam scene, {doc})"),
    "cm unknown top": ("невідомий ключ у сцені кулачкового механізму (дозволені: {allowed})",
                       "unknown key in a cam scene (allowed: {allowed})"),
    "cm number": ("має бути числом, задано {got}", "must be a number, got {got}"),
    "cm phases table": ("має бути таблицею {table} у градусах", "must be a table {table} in degrees"),
    "cm unknown phase": ("невідома фаза (дозволені: {allowed})", "unknown phase (allowed: {allowed})"),
    "cm angle": ("має бути від {lo} до {hi}°, задано {got}", "must be from {lo} to {hi}°, got {got}"),
    "cm short phase": ("фази підйому й опускання тривають щонайменше по 5°",
                       "the rise and the return take at least 5° each"),
    "cm phases sum": ("сума чотирьох фаз має бути 360°, а вона {got}°", "the four phases must sum to 360°, they sum to {got}°"),
    "cm laws table": ("має бути назвою закону руху або таблицею {table}", "must be a law's name or a table {table}"),
    "cm unknown law": ("невідомий закон руху {got} (відомі: {known})", "unknown law {got} (known: {known})"),
    "cm pressure table": ("має бути кутом або таблицею {table} у градусах",
                          "must be an angle or a table {table} in degrees"),
    "cm speed both": ("задайте {omega} або {rpm}, не обидва", "give {omega} or {rpm}, not both"),
    "cm roller tiny": ("має бути 0 (гострий штовхач) або від 1e-05 {m}, задано {got}",
                       "must be 0 (a knife-edge) or from 1e-05 {m}, got {got}"),
    "cm divisions": ("має бути цілим числом від 2 до 360 (поділок кожної фази), задано {got}",
                     "must be a whole number from 2 to 360 (intervals of each phase), got {got}"),
    "cm translating only": ("стосується поступального штовхача; коромисло має {keys}",
                            "is for a translating follower; a rocking one has {keys}"),
    "cm rocking only": ("стосується коромисла; поступальний штовхач має {keys}",
                        "is for a rocking follower; a translating one has {keys}"),
    "cm roller base": ("ролик ({roller} {m}) має бути меншим за основну шайбу ({base} {m})",
                       "the roller ({roller} {m}) must be smaller than the base circle ({base} {m})"),
    "cm offset base": ("|e| = {e} {m} має бути меншим за радіус основної шайби {base} {m}",
                       "|e| = {e} {m} must be smaller than the base radius {base} {m}"),
    "cm arm reach": ("коромисло {arm} {m} на відстані {centre} {m} від центра кулачка досягає лише радіусів від {lo} "
                     "до {hi} {m}", "the arm {arm} {m} at {centre} {m} from the cam's centre reaches radii from {lo} "
                     "to {hi} {m} only"),
    # model/structure.py: the structure of a lever mechanism
    "st crank pivot": ("кривошип {crank} не з'єднаний зі стояком обертальною парою в точці {pivot}",
                       "the crank {crank} is not pinned to the frame at {pivot}"),
    "st mobility": ("ступінь рухомості W = 3·{n} − 2·{p5} = {w}, кривошипному механізму потрібен W = 1 "
                    "(перевірте {joints} і {slides_on} ланок)",
                    "mobility W = 3·{n} − 2·{p5} = {w}, a crank mechanism needs W = 1 (check the {joints} and "
                    "{slides_on} of the links)"),
    "st no groups": ("механізм не розкладається на структурні групи II класу: ланки {links} не утворюють "
                     "двоповідкову групу на відомих ланках (чи кожен вхід групи приєднано до ланок, знайдених "
                     "раніше?)", "cannot decompose into class-II groups: links {links} do not form a dyad on "
                     "the known links (is every input of a dyad joined to links solved before it?)"),
    "st ppp": ("ланки {x} і {y}: група з трьох поступальних пар не має певного положення",
               "links {x} and {y}: a group of three sliding pairs has no fixed position"),
    # model/motors.py: the motor of the dynamics
    "mo no motor": ("двигуна {name} немає в каталозі ({first} … {last})", "no motor {name} in the catalogue ({first} … {last})"),
    "mo no line": ("у каталозі немає серії на {speed} {rpm} ({lines})", "the catalogue has no {speed} {rpm} line ({lines})"),
    "mo too weak": ("циклу потрібно {power} {kW}, більше, ніж дає найбільший двигун каталогу на {speed} {rpm} ({name}, "
                    "{largest} {kW})", "the cycle needs {power} {kW}, more than the largest {speed} {rpm} motor of the "
                    "catalogue ({name}, {largest} {kW})"),
    "mo positive": ("має бути додатним числом до {hi} {unit}, задано {got}", "must be a positive number up to {hi} {unit}, got {got}"),
    "mo number": ("має бути числом до {hi} {unit}, задано {got}", "must be a number up to {hi} {unit}, got {got}"),
    "mo missing": ("відсутній (або назвіть двигун з каталогу)", "missing (or name a catalogue motor)"),
    "mo rated": ("номінальна частота обертання {rated} {rpm} має бути меншою за синхронну {sync} {rpm}",
                 "the rated speed {rated} {rpm} must be below the synchronous {sync} {rpm}"),
    # exact/positions.py and exact/kinetostatics.py: the output, the start, the loads
    "ps output slides": ("ланка {name} ковзає вздовж напрямної стояка й не обертається; назвіть її "
                         "точку, що ковзає, або ланку, що обертається",
                         "the link {name} slides along a frame guide and never turns; name its "
                         "sliding point, or a link that turns"),
    "ps output still": ("вихідна ланка {name} не рухається за оберт кривошипа (її хід {reach} мм): "
                        "група зібрана в іншу збірку — змініть знак її точки в [{table}]",
                        "the output {name} does not move over the crank's turn (its travel {reach} mm): "
                        "a group is assembled the other way — change the sign of its point in [{table}]"),
    "ps output still turn": ("вихідна ланка {name} не повертається за оберт кривошипа (її хід {reach}°): "
                             "група зібрана в іншу збірку — змініть знак її точки в [{table}]",
                             "the output {name} does not turn over the crank's turn (its swing {reach}°): "
                             "a group is assembled the other way — change the sign of its point in [{table}]"),
    "ps output neither": ("{name} не є ні ланкою, ні точкою, що ковзає",
                          "{name} is neither a link nor a sliding point"),
    "ps start inner": ("внутрішнє й зовнішнє мертві положення має повзун; вихідна ланка "
                       "{name} задана кутом (візьміть {use})",
                       "inner and outer dead centres belong to a slider; the output "
                       "{name} is a link's angle (use {use})"),
    "ps start no extremes": ("вихідна ланка {name} не має крайніх положень (вона "
                             "обертається повністю); задайте початок кутом кривошипа",
                             "the output {name} has no extreme positions (it turns "
                             "fully); give the start as a crank angle"),
    "ks frame force": ("{name} — точка стояка; сила на стояк не навантажує механізм",
                       "{name} is a frame point; a force on the frame does not load the mechanism"),
    "ks not finite": ("група {group}: силовий розрахунок не скінченний при куті кривошипа {phi}° (навантаження чи "
                      "геометрія поза межами)", "group {group}: the force analysis is not finite at crank angle "
                      "{phi}° (loads or geometry out of range)"),
    # exact/dynamics.py: a cycle the dynamics cannot take
    "dy no masses": ("сцена не задає мас і моментів інерції ланок ({keys} у {crank} і {link} або {loads}): "
                     "зведеного моменту інерції немає", "the scene gives no masses or moments of inertia of its links "
                     "({keys} in {crank} and {link}, or {loads}): there is no reduced moment of inertia"),
    "dy no work": ("сили опору не виконують роботи за цикл (A_c = {work} {J}); задайте {force}, що опирається "
                   "руху вихідної ланки", "the resistance does no work over a cycle (A_c = {work} {J}); give a "
                   "{force} that resists the output's motion"),
    # model/gears.py: a gear scene
    "gr teeth list": ("має бути списком із {n} чисел зубців, задано {got}", "must be a list of {n} numbers of teeth, got {got}"),
    "gr teeth": ("число зубців має бути цілим від {lo} до {hi}, задано {got}",
                 "a number of teeth must be a whole number from {lo} to {hi}, got {got}"),
    "gr z missing": ("відсутній ({z})", "missing ({z})"),
    "gr shifts": ("має бути {pair} або {auto}, задано {got}", "must be {pair} or {auto}, got {got}"),
    "gr shift": ("коефіцієнт зміщення має бути від {lo} до {hi}, задано {got}",
                 "a shift coefficient must be from {lo} to {hi}, got {got}"),
    "gr type": ("має бути {a} (однорядний) або {b} (дворядний), задано {got}",
                "must be {a} (one row) or {b} (two rows), got {got}"),
    "gr planets": ("число сателітів K має бути цілим від {lo} до {hi}, задано {got}",
                   "K must be a whole number from {lo} to {hi}, got {got}"),
    "gr ratio or teeth": ("задайте бажане передавальне відношення ({ratio}) або зубці ({z}), одне з двох",
                          "give the ratio wanted ({ratio}) or the teeth ({z}), one of them"),
    "gr type A ratio": ("однорядний механізм типу A має u1H = 1 + z3/z1 > 2, задано {got}",
                        "a type A train has u1H = 1 + z3/z1 > 2, got {got}"),
    "gr lever scene": ("у сцені немає таблиці {t1} чи {t2}: вона описує важільний механізм ({cmd} читає сцену "
                       "зубчастого механізму, {doc})", "the scene has no {t1} or {t2} table: it describes a lever "
                       "mechanism ({cmd} reads a gear scene, {doc})"),
    "gr cam scene": ("сцена кулачкового механізму не має таблиці {table} (її креслить {cmd}, {doc})",
                     "a cam scene has no {table} table ({cmd} draws it, {doc})"),
    "gr unknown top": ("невідомий ключ у сцені зубчастого механізму (дозволені: {allowed})",
                       "unknown key in a gear scene (allowed: {allowed})"),
    # exact/cam.py: a cam that cannot be built
    "ec arm reach": ("коромисло {arm} {m} на відстані {centre} {m} від центра кулачка не дістає основної шайби "
                     "R0 = {base} {m}", "the arm {arm} {m} at {centre} {m} from the cam's centre cannot reach the "
                     "base circle R0 = {base} {m}"),
    "ec offset base": ("ексцентриситет |e| = {e} {m} має бути меншим за радіус основної шайби {base} {m}",
                       "the offset |e| = {e} {m} must be smaller than the base radius {base} {m}"),
    "ec no base": ("жоден радіус основної шайби не тримає кути тиску в допустимих межах",
                   "no base radius keeps the pressure angles within the allowed ones"),
    "ec rise pressure": ("кут тиску фази підйому лишається більшим за допустимий {allowed}° за кожного радіуса "
                         "основної шайби, якого досягає коромисло (щонайменше {least}° при R0 = {R0} {mm}); "
                         "дозвольте більший кут або змініть довжину коромисла чи міжосьову відстань",
                         "the rise's pressure angle stays above its allowed {allowed}° at every base radius the "
                         "rocking arm reaches (at best {least}° at R0 = {R0} {mm}); allow a larger angle or change "
                         "the arm or the centre distance"),
    "ec return pressure": ("кут тиску фази опускання лишається більшим за допустимий {allowed}° за кожного радіуса "
                           "основної шайби, якого досягає коромисло (щонайменше {least}° при R0 = {R0} {mm}); "
                           "дозвольте більший кут або змініть довжину коромисла чи міжосьову відстань",
                           "the return's pressure angle stays above its allowed {allowed}° at every base radius the "
                           "rocking arm reaches (at best {least}° at R0 = {R0} {mm}); allow a larger angle or change "
                           "the arm or the centre distance"),
    # model/expressions.py: a scene's arithmetic
    "ex long": ("вираз {text} довший за {most} символів", "the expression {text} is longer than {most} characters"),
    "ex unreadable": ("не вдається прочитати вираз {text}", "cannot read the expression {text}"),
    "ex deep": ("вираз {text} вкладено глибше ніж на {most} рівні", "the expression {text} is nested more than {most} deep"),
    "ex underscore": ("{text}: пишіть числа без «_»", "{text}: write numbers without '_'"),
    "ex bare word": ("{name} — не число: задайте число або вираз (імена з {params}: {known})",
                     "{name} is not a number: give a number or an expression (names of {params}: {known})"),
    "bad toml twice": ("таблицю {t} оголошено двічі (рядок {line}); у сцені вона одна",
                       "the table {t} is declared twice (line {line}); a scene has one"),
    "bad toml overwrite": ("ключ задано двічі (рядок {line})", "a key is given twice (line {line})"),
    "bad toml invalid": ("значення не читається (рядок {line}); текст пишіть у лапках", "invalid value (line {line}); "
                         "write text in quotes"),
    "bad toml end": ("файл уривається посеред значення: чи закрито дужки й лапки?",
                     "the file ends inside a value: are the brackets and quotes closed?"),
    "bad toml equals": ("після ключа бракує «=» (рядок {line})", "'=' missing after a key (line {line})"),
    "bad toml at": ("{what} (рядок {line}, стовпець {col})", "{what} (at line {line}, column {col})"),
    "ex unknown name": ("невідоме ім'я {name} у {text}", "unknown name {name} in {text}"),
    "ex arithmetic": ("у {text} дозволена лише арифметика", "only arithmetic is allowed in {text}"),
    "ex cannot": ("не вдається обчислити {text}: {why}", "cannot evaluate {text}: {why}"),
    "ex infinite": ("{text} не є скінченним числом", "{text} is not a finite number"),
    # model/bounds.py: the reading's bounds
    "bad range": ("має бути {range}, задано {got}", "must be {range}, got {got}"),
    "bad count": ("має бути цілим числом від {lo} до {hi}, задано {got}",
                  "must be a whole number from {lo} to {hi}, got {got}"),
    "bad large integer": ("ціле число завелике (|значення| ≤ {most})", "the integer is too large (|value| ≤ {most})"),
    "bad name long": ("ім'я має щонайбільше 40 символів", "a name has at most 40 characters"),
    "bad name spaces": ("ім'я без пропусків і керівних символів", "a name has no spaces or control characters"),
    "bad scene size": ("файл сцени більший за {kb} кБ", "the scene is larger than {kb} kB"),
    "bad toml syntax": ("синтаксична помилка {toml}: {why}", "{toml} syntax error: {why}"),
    "bad toml depth": ("{toml} вкладено надто глибоко (щонайбільше {most} рівнів)",
                       "{toml} nested too deeply (at most {most} levels)"),
    "bad toml value": ("значення {toml} не читається: {why}", "{toml} value cannot be read: {why}"),
})


# -- the last English refusals: rare solver ones, files, the command line's options (util.errors.said_error) --
WORDS.update({
    # exact/: the solver
    "kn no point": ("немає точки {point}", "no point named {point}"),
    "kn known slider": ("{dyad}: ланка, знайдена раніше, що ковзає по напрямній групи, не підтримується",
                        "{dyad}: a known body sliding on the dyad's guide is not supported"),
    "kn yoke slot": ("{dyad}: паз, у якому ковзає повзун, має бути на кулісі",
                     "{dyad}: the yoke must carry the slot its block slides in"),
    "ec unknown law": ("невідомий закон руху {name}", "unknown law {name}"),
    "ec no bracket": ("найменший радіус основної шайби не вдається обмежити (допустимі кути тиску не досягнуто ні "
                      "при {lo} {mm}, ні при {hi} {mm})", "the smallest base radius could not be bracketed (the "
                      "allowed pressure angles are reached neither at {lo} {mm} nor at {hi} {mm})"),
    "dy divisions": ("має бути цілим числом від {lo} до {hi} (побудова ділить оберт щонайбільше на {hi} частин, по "
                     "1°; креслення тонше не розрізняє), задано {got}", "must be a whole number from {lo} to {hi} "
                     "(the construction divides the turn into at most {hi} parts, 1° each; a drawing resolves no "
                     "finer), got {got}"),
    "dy delta": ("коефіцієнт нерівномірності має бути в межах (0; 0,5), задано {got}",
                 "the coefficient of unevenness must lie in (0, 0.5), got {got}"),
    "dy motor slows": ("двигун {name} ({power} {kW}, i = {ratio}) не може вести цикл: навіть у кінці робочої гілки "
                       "характеристики кривошип за оберт сповільнюється; оберіть потужніший двигун",
                       "the motor {name} ({power} {kW}, i = {ratio}) cannot drive the cycle: even at the end of "
                       "its working branch the crank slows down over a turn; choose a larger motor"),
    "dy motor moment": ("двигун {name} не може вести цикл: момент на його валу сягає {moment} {N·m}, більше за "
                        "M_max = {max} {N·m} (поза робочою гілкою); оберіть потужніший двигун",
                        "the motor {name} cannot drive the cycle: its moment reaches {moment} {N·m} on its shaft, "
                        "above M_max = {max} {N·m} (off the working branch); choose a larger motor"),
    "gr inv": ("{inv} має бути додатним", "{inv} must be positive"),
    # util/files.py: reading and writing files ({what}: "fl scene", "fl table" …)
    "fl file": ("файл", "file"),
    "fl missing": ("не знайдено {of}", "no such {of}"),
    "fl folder": ("це тека, а не {what}", "the {what} is a folder, not a file"),
    "fl not regular": ("це не звичайний файл ({what})", "the {what} is not a regular file"),
    "fl cannot read": ("{what} не читається: {why}", "cannot read the {what}: {why}"),
    "fl too large": ("файл завеликий: понад {mb} МБ ({what})", "the {what} is larger than {mb} MB"),
    "fl not utf8": ("{what} не є текстом {utf} (байт {byte}); збережіть файл у кодуванні {utf}",
                    "cannot read the {what}: not {utf} text (byte {byte}); save the file as {utf}"),
    "fl write folder": ("це тека; назвіть файл, який записати", "is a folder; name a file to write"),
    "fl write not folder": ("не вдається записати: {parent} — не тека", "cannot write: {parent} is not a folder"),
    "fl cannot write": ("не вдається записати: {why}", "cannot write: {why}"),
    "fl no permission": ("немає дозволу", "permission denied"),
    "fl no folder": ("такої теки немає", "no such folder"),
    # cli/: the command line's options
    "op usage": ("{text} (див. --help)", "{text} (see --help)"),
    "op many values": ("щонайбільше {most} значень, задано {got}", "at most {most} values, got {got}"),
    "op range": ("має бути від {lo}{open} до {hi}{unit}, задано {got}", "must be from {lo}{open} to {hi}{unit}, got {got}"),
    "op exclusive": (" (не включно)", " (exclusive)"),
    "op divisions": ("ціле число або перелік обертів кривошипа через кому, задано {got}",
                     "a whole number or comma-separated crank turns, got {got}"),
    "op precision": ("має бути довжиною ≥ 0 мм, задано {got}", "must be a length ≥ 0 in mm, got {got}"),
    "op angle": ("має бути скінченним кутом у градусах, задано {got}", "must be a finite angle in degrees, got {got}"),
    "op whole": ("має бути цілим числом від {lo} до {hi}, задано {got}", "must be a whole number from {lo} to {hi}, got {got}"),
    "op at least": ("має бути щонайменше {lo}, задано {got}", "must be at least {lo}, got {got}"),
    "op svg folder": ("потрібна тека, а це файл", "needs a folder, this is a file"),
    "op output folder": ("вихід має бути текою", "the output must be a folder"),
    "op out format": ("невідомий формат; використайте {formats}", "unknown format; use {formats}"),
    "op out suffix": ("невідомий формат {got}; використайте {formats}", "unknown format {got}; use {formats}"),
    "op sheet format": ("невідомий формат аркуша {got} ({formats})", "unknown sheet format {got} ({formats})"),
    "op no gears": ("у сцені немає таблиці {gears} чи {planetary} ({doc})", "the scene has no {gears} or {planetary} table ({doc})"),
    "op gears only": ("сцена зубчастого механізму має лише аркуш {sheet}", "a gear scene has the {sheet} sheet only"),
    "op no cam": ("у сцені немає таблиці {cam} ({doc})", "the scene has no {cam} table ({doc})"),
    "op cam only": ("сцена кулачкового механізму має лише аркуш {sheet}", "a cam scene has the {sheet} sheet only"),
    "op not available": ("недоступний", "not available"),
    "op lang": ("має бути uk або en, задано {got}", "must be uk or en, got {got}"),
    "op tol": ("{item}: пишіть ВЕЛИЧИНА=ВІДСОТОК, напр. --tol 'a_*=8'", "{item}: write QUANTITY=PERCENT, e.g. --tol 'a_*=8'"),
    "op tolerance": ("має бути відсотком у межах (0; 100], задано {got}", "must be a percentage in (0, 100], got {got}"),
    "op interrupted": ("перервано", "interrupted"),
    # argparse's own usage errors, translated (cli.common.Parser.error)
    "ap required": ("бракує аргументів: {names}", "the following arguments are required: {names}"),
    "ap unrecognized": ("невідомі аргументи: {names}", "unrecognized arguments: {names}"),
    "ap choice": ("аргумент {arg}: недопустиме значення {got} (оберіть з {choices})",
                  "argument {arg}: invalid choice: {got} (choose from {choices})"),
    "ap invalid": ("аргумент {arg}: {got} — не {kind}", "argument {arg}: invalid {kind} value: {got}"),
    "ap one": ("аргумент {arg}: потрібне одне значення", "argument {arg}: expected one argument"),
    "ap some": ("аргумент {arg}: потрібне щонайменше одне значення", "argument {arg}: expected at least one argument"),
    "ap not allowed": ("аргумент {arg}: не можна разом з аргументом {other}", "argument {arg}: not allowed with argument {other}"),
    "ap ambiguous": ("неоднозначний параметр {got}, підходять {names}", "ambiguous option: {got} could match {names}"),
    "ap other": ("помилка в параметрах: {text}", "{text}"),
    "ap kind int": ("ціле число", "int"),
    "ap kind float": ("число", "float"),
})


# -- cautions: a scene's likely slips, warned on stderr (model.cautions) -----------------------------------
WORDS.update({
    "caution": ("попередження", "warning"),
    "caution com outside": ("ланка {link}: центр мас {point} лежить поза ланкою, за {dist} {m} від шарніра {joint} "
                            "(найбільша відстань між її шарнірами {span} {m}); частка довжини — від 0 до 1",
                            "link {link}: the centre of mass {point} lies outside the link, {dist} {m} from the joint "
                            "{joint} (its joints span {span} {m}); a fraction of the length is from 0 to 1"),
    "caution units": ("довжина ланки {long} {big} {m}, а ланки {short} — {small} {m}: чи не задано якісь довжини в "
                      "міліметрах? Сцена задає довжини в метрах",
                      "the link {long} is {big} {m} long and the link {short} {small} {m}: are some lengths in "
                      "millimetres? A scene gives lengths in metres"),
    "caution far point": ("ланка {link}: точка {point} лежить за {dist} {m} від найближчого шарніра {joint}, далеко "
                          "поза ланкою (її шарніри — у межах {span} {m}); точку задано в метрах чи часткою довжини?",
                          "link {link}: the point {point} lies {dist} {m} from the nearest joint {joint}, far beyond "
                          "the link (its joints span {span} {m}); is it in metres or a fraction of the length?"),
})


# -- sheets/: drawings that a format cannot hold --------------------------------------------------------
WORDS.update({
    "sh forces fit": ("силові креслення не вміщаються на аркуші {form}; оберіть більший формат ({option})",
                      "the force drawings do not fit a {form} sheet; choose a larger {option}"),
    "sh drawing larger": ("креслення більше за цілий аркуш {form}; оберіть більший формат ({option})",
                          "a drawing is larger than a whole {form} sheet; choose a larger {option}"),
    "sh kin fit": ("креслення не вміщаються на аркуші {form} навіть у найдрібніших масштабах; оберіть більший "
                   "формат ({option})", "the drawings do not fit a {form} sheet even at the smallest scales; choose "
                   "a larger {option}"),
    "sh cam larger": ("креслення кулачка більше за цілий аркуш {form} навіть у половинному розмірі; оберіть більший "
                      "формат ({option})", "a cam drawing is larger than a whole {form} sheet even at half its size; "
                      "choose a larger {option}"),
})


# -- tables a person writes: numbers, variant tables, students' tables, keys (model.variants, teach/) -------
# column, directive and TOML names stay as the file writes them ({column}, variant, base …)
WORDS.update({
    # model/bounds.py: one reader of every table's numbers (util.errors.SaidValueError)
    "nb radix": ("шістнадцятковий, вісімковий чи двійковий запис: пишіть число десятковими цифрами",
                 "a hexadecimal, octal or binary literal: write the number in decimal digits"),
    "nb underscore": ("пишіть числа без «_» (7_2 — не 72)", "write numbers without '_' (7_2 is not 72)"),
    "nb not finite": ("не скінченне число", "not a finite number"),
    "nb spaces": ("пробіли — лише між групами з трьох цифр (5 346,1)",
                  "spaces only between groups of three digits (5 346,1)"),
    "nb point and comma": ("і десяткова крапка, і кома: пишіть 5346.1 або 5346,1",
                           "both a decimal point and a comma: write 5346.1 or 5346,1"),
    "nb comma thousands": ("кома десяткова чи між тисячами? Пишіть 1.234 або 1234",
                           "is the comma a decimal comma or between thousands? write 1.234 or 1234"),
    "nb two commas": ("більше ніж одна десяткова кома", "more than one decimal comma"),
    "nb dot thousands": ("крапка десяткова чи між тисячами? У таблиці, розділеній «;» чи табуляцією, пишіть 5,351 "
                         "або 5351", "is the dot a decimal point or between thousands? in a ';' or tab-separated "
                         "table write 5,351 or 5351"),
    "nb not number": ("не число", "not a number"),
    "nb too large": ("|значення| ≤ {most}", "|value| ≤ {most}"),
    "nb underflow": ("замале: воно перетворюється на 0", "too small: it underflows to 0"),
    "nb in cell": ("{text}: {why}", "{text}: {why}"),
    # model/variants.py: a group's variant table (docs/keys.md)
    "vt where": ("{table}: варіант {id}", "{table}: variant {id}"),
    "vt at line": ("рядок {line}: ", "line {line}: "),
    "vt line": ("рядок {line}: {why}", "line {line}: {why}"),
    "vt toml line": ("рядок {line}{key}: {why}", "line {line}{key}: {why}"),
    "vt no header": ("у таблиці немає рядка заголовків (стовпець {@variant} і стовпці, що змінюють базову сцену)",
                     "the table has no header row (a '{@variant}' column and the overrides)"),
    "vt column twice": ("стовпець {name} записано двічі", "column {name} appears twice"),
    "vt cells": ("рядок {line}: {n} клітинок на {width} стовпців{hint}", "line {line}: {n} cells for {width} columns{hint}"),
    "vt cell": ("рядок {line}, стовпець {column}: {why}", "line {line}, column {column}: {why}"),
    "vt no name": ("стовпець без назви", "a column has no name"),
    "vt no variant column": ("таблиці потрібен стовпець {@variant}", "the table needs a '{@variant}' column"),
    "vt no entries": ("таблиці потрібні записи [[{@variant}]]", "the table needs [[{@variant}]] entries"),
    "vt entry table": ("{@variant}[{k}] має бути таблицею", "{@variant}[{k}] must be a table"),
    "vt tolerance": ("{at}{key}: допуск має бути відсотком у межах (0; 100], задано {got}",
                     "{at}{key}: a tolerance must be a percentage in (0, 100], got {got}"),
    "vt divisions": ("{at}{@divisions}: кількість поділок має бути цілим числом від 2 до 720, задано {got}",
                     "{at}{@divisions} must be a whole number from 2 to 720, got {got}"),
    "vt directive": ("невідома директива {key} (відомі: {@base}, {@divisions}, {@tolerance}, {@tolerance}.<величина>)",
                     "unknown directive {key} (known: {@base}, {@divisions}, {@tolerance}, {@tolerance}.<quantity>)"),
    "vt no variants": ("у таблиці немає варіантів", "the table has no variants"),
    "vt too many": ("варіантів {n}; таблиця вміщує щонайбільше {most} (розділіть таблицю групи)",
                    "{n} variants; a table holds at most {most} (split the group's table)"),
    "vt no id": ("{at}варіант без позначення (стовпець {@variant} порожній)", "{at}the variant has no id (its {@variant} is empty)"),
    "vt bad id": ("{at}позначення варіанта {id}: лише літери, цифри, «.», «_» або «-»",
                  "{at}variant id {id}: use letters, digits, '.', '_' or '-'"),
    "vt summary id": ("{at}позначення варіанта {id} — це ім'я файла зведення; назвіть варіант інакше",
                      "{at}variant id {id} is the name of a summary file; call the variant otherwise"),
    "vt id twice": ("{at}варіант {id} записано двічі", "{at}variant {id} appears twice"),
    "vt no base": ("{at}немає базової сцени: додайте рядок «# {@base} = {@SCENE_toml}» або стовпець {@base}",
                   "{at}no base scene: add '# {@base} = {@SCENE_toml}' or a '{@base}' column"),
    "vt unknown column": ("стовпець {column}: це не ім'я з [{@params}], не скорочення ({short}) і не шлях у базовій сцені",
                          "column {column}: not a [{@params}] name, a shorthand ({short}) or a path in the base scene"),
    "vt unknown column in": ("стовпець {column} (варіант {id}): це не ім'я з [{@params}] сцени {base}, не скорочення "
                             "({short}) і не шлях через крапку в ній",
                             "column {column} (variant {id}): not a [{@params}] name of {base}, a shorthand ({short}) "
                             "or a dotted path in it"),
    "vt accel": ("{@accel}: номери положень через «;» або пробіл, задано {got}",
                 "{@accel}: position numbers separated by ';' or spaces, got {got}"),
    # teach/tables.py, teach/grading.py: a student's table
    "st encoding": ("таблиця не читається як текст {encoding} (байт {byte}); збережіть її як {@CSV} {@UTF-8}",
                    "cannot read the table as {encoding} text (byte {byte}); save it as {@CSV} {@UTF-8}"),
    "st zero bytes": ("{what} — не текст (містить нульові байти)", "the {what} is not text (it holds zero bytes)"),
    "st empty": ("{what} порожня", "the {what} is empty"),
    "st too many rows": ("{what}: рядків {n}; за раз оцінюється щонайбільше {most} (розділіть таблицю)",
                         "the {what} has {n} rows; at most {most} are graded at once (split the table)"),
    "st quote": ("рядок {line}: лапки не закрито", "line {line}: a quote is not closed"),
    "st comma hint": (" — десяткова кома в таблиці, розділеній комами? Розділяйте «;» або пишіть 7.2",
                      " — a decimal comma in a comma-separated table? Separate with ';' or write 7.2"),
    "st columns": ("таблиці студента потрібні стовпці {@variant}, {@position}, {@quantity}, {@value} (бракує {need})",
                   "the student table needs the columns {@variant}, {@position}, {@quantity}, {@value} (missing {need})"),
    "st column twice": ("рядок 1: стовпець {name} записано двічі (стовпці {cols}); залиште один",
                        "line 1: the column {name} appears twice (columns {cols}); keep one"),
    "st cell": ("рядок {line}: {column} {text}{at}: {why}", "line {line}: {column} {text}{at}: {why}"),
    "st at column": (" (стовпець {k})", " (column {k})"),
    "st split": ("рядок {line}: {a}, а далі {b} (стовпці {k1} і {k2}) — десяткову кому розбито на дві клітинки? "
                 "Запишіть число з крапкою, візьміть його в лапки (\"11,09\") або розділяйте таблицю «;»",
                 "line {line}: {a} and then {b} (columns {k1} and {k2}) — a decimal comma split across cells? "
                 "Write the number with a point, quote it (\"11,09\") or separate the table with ';'"),
    "st no position": ("рядок 1: у таблиці немає стовпця положень (її перший стовпець — варіант): назвіть стовпець "
                       "положень {@position}", "line 1: the table has no position column (its first column is the "
                       "variant): name the positions' column {@position}"),
    # teach/grading.py, teach/keys.py, cli/key.py: keys
    "ky no written": ("у теці ключів немає жодного записаного варіанта", "the key folder holds no written variants"),
    "ky not folder": ("це не тека ключів (немає {@summary_json} чи {@key_json})", "not a key folder (no {@summary_json} or {@key_json})"),
    "ky not json": ("ключ не читається: це не {@JSON} (рядок {line}, позиція {col}); дайте теку ключів, "
                    "яку записала команда graphplan {@key}, або {@key_json} варіанта",
                    "cannot read the key: not {@JSON} (line {line}, column {col}); give the key folder graphplan "
                    "{@key} wrote or a variant's {@key_json}"),
    "ky cannot read": ("ключ не читається: {why}", "cannot read the key: {why}"),
    "ky not object": ("це не ключ graphplan (не об'єкт {@JSON})", "not a graphplan key (not a {@JSON} object)"),
    "ky format": ("це не ключ graphplan (формат {got}, потрібен {want})",
                  "not a graphplan key (format {got}, expected {want})"),
    "ky accel": ("{@positions_accel}: положення {p} немає (положень {count}: 0–{last})",
                 "{@positions_accel}: position {p} does not exist ({count} positions, 0–{last})"),
    "ky none built": ("жоден варіант не вдалося побудувати, нічого не записано: {first}{more}",
                      "no variant could be built, nothing written: {first}{more}"),
    "ky more": (" (і ще {n})", " (and {n} more)"),
    "ky skipped": ("{where}: пропущено: {note}", "{where}: skipped: {note}"),
    "op internal": ("внутрішня помилка: {name}: {text} (задайте {@GRAPHPLAN_DEBUG=1}, щоб побачити трасування)",
                    "internal error: {name}: {text} (set {@GRAPHPLAN_DEBUG=1} for the traceback)"),
})


# -- web/ and cli/serve.py: the page's server (its HTTP errors speak the request's ?lang=) -----------------
WORDS.update({
    "wb scene not utf8": ("сцена не є текстом {@UTF-8}; збережіть файл у кодуванні {@UTF-8}",
                          "the scene is not {@UTF-8} text; save the file as {@UTF-8}"),
    "wb table not utf8": ("таблиця не є текстом {@UTF-8}; збережіть її як {@CSV} {@UTF-8}",
                          "the table is not {@UTF-8} text; save it as {@CSV} {@UTF-8}"),
    "wb scene large": ("сцена більша за {kb} кБ", "the scene is larger than {kb} kB"),
    "wb table large": ("таблиця більша за {kb} кБ", "the table is larger than {kb} kB"),
    "wb busy": ("сервер зайнятий: усі обчислювальні процеси працюють; спробуйте ще раз за мить",
                "the server is busy: every worker is computing; try again in a moment"),
    "wb timeout": ("обчислення тривало довше за {s} с процесорного часу і його зупинено (з меншою кількістю "
                   "положень чи поділок креслення будується швидше)", "the work took longer than {s} s of "
                   "processor time and was stopped (fewer positions or divisions draw faster)"),
    "wb worker died": ("внутрішня помилка: процес, що це обчислював, несподівано завершився; наступний запит "
                       "візьме новий", "internal error: the worker computing this ended unexpectedly; a fresh one "
                       "takes the next request"),
    "wb kind twice": ("вид аркуша задано двічі", "a kind is asked twice"),
    "wb multipart": ("тіло запиту має бути {@multipart} з частинами {names}",
                     "the body must be {@multipart} with {names}"),
    "wb form unreadable": ("форма не читається: {why}", "cannot read the form: {why}"),
    "wb no part": ("у формі немає частини {name} ({what})", "the form has no {name} part ({what})"),
    "wb base column": ("стовпець {@base} називає файли на сервері; завантажте базову сцену окремим файлом ({@base})",
                       "a '{@base}' column names files on the server; upload the base scene as '{@base}' instead"),
    "wb keys busy": ("сервер зайнятий ключами іншого викладача; спробуйте ще раз за хвилину",
                     "the server is busy with a teacher's batch of keys; try again in a minute"),
    "wb keys timeout": ("ключі складалися довше за {s} с, і їх зупинено", "the keys took longer than {s} s and were stopped"),
    "wb key ended": ("graphplan {@key} завершився з кодом {code}", "graphplan {@key} ended with {code}"),
    "wb no batch": ("такого набору ключів немає (його вже завантажено, або строк зберігання минув)",
                    "no such batch of keys (downloaded already, or expired)"),
    "wb not ready": ("ключі ще не готові", "the keys are not ready yet"),
    "wb host": ("{host} — не ім'я цього сервера", "host {host} is not this server's name"),
    "wb other site": ("запит з іншого сайту відхилено", "a request from another site is refused"),
    "wb token": ("цей сервер вимагає свій токен: відкрийте адресу, яку він надрукував під час запуску "
                 "({@token}), або надішліть «{@bearer}»",
                 "this server asks for its token: open the address it printed at start ({@token}) or send "
                 "'{@bearer}'"),
    "wb not found": ("не знайдено", "not found"),
    "wb not allowed": ("метод не дозволено", "method not allowed"),
    "wb refused": ("відхилено", "refused"),
    "wb form json": ("не об'єкт {@JSON}", "not a {@JSON} object"),
    "wb form object": ("форма має бути об'єктом {@JSON}", "the form must be a {@JSON} object"),
    "wb template": ("шаблон {got}: оберіть один з {known}", "template {got}: use one of {known}"),
    "wb values": ("{@values}: має бути об'єктом {@JSON}", "{@values}: must be a {@JSON} object"),
    "wb choice": ("{key}: {got} — не одне з {choices}", "{key}: {got} is not one of {choices}"),
    "wb not number": ("{key}: {got} — не число", "{key}: {got} is not a number"),
    "wb not finite": ("{key}: {got} — не скінченне число", "{key}: {got} is not a finite number"),
    "wb branch": ("{@branch}: таблиця імен точок зі значеннями +1 або -1", "{@branch}: a table of point names with +1 or -1"),
    "wb explorer gears": ("інтерактивна сторінка показує важільні й кулачкові механізми; сцену зубчастого механізму "
                          "креслять graphplan {@gears} і його аркуш ({@gears_md})",
                          "the explorer shows lever mechanisms and cams; a gear scene has graphplan {@gears} and its "
                          "sheet ({@gears_md})"),
    "wb zip": ("{@zip} ключів не читається: {why}", "cannot read the key's {@zip}: {why}"),
    "wb zip files": ("{@zip} ключів містить {n} файлів (щонайбільше {most})", "the key's {@zip} holds {n} files (at most {most})"),
    "wb zip size": ("{@zip} ключів розпаковується в понад {mb} МБ", "the key's {@zip} unpacks to more than {mb} MB"),
    "wb nested": ("вкладено надто глибоко", "nested too deeply"),
    "wb memory": ("обчисленню потрібно більше пам'яті, ніж має обчислювальний процес ({gb} ГБ); оберіть менший "
                  "формат чи {@dpi}, менше положень", "the work needs more memory than a worker has ({gb} GB); a "
                  "smaller format or {@dpi}, fewer positions"),
    "wb internal": ("внутрішня помилка: {name}: {text}", "internal error: {name}: {text}"),
    "wb assembly": ("складання", "assembly"),
    "wb default": ("типове", "the default"),
    "sv needs": ("graphplan {@serve} потребує {name}: {@pip}",
                 "graphplan {@serve} needs {name}: {@pip}"),
    "sv started": ("graphplan {@serve}: {url}{shared} — {@Ctrl-C} зупиняє сервер", "graphplan {@serve}: {url}{shared} — {@Ctrl-C} stops it"),
    "sv cannot listen": ("не вдається слухати {host}:{port}: {why}", "cannot listen on {host}:{port}: {why}"),
    "sv port in use": ("порт уже зайнятий (інший сервер?); оберіть інший --port",
                       "the port is in use (another server?); choose another --port"),
    "sv port denied": ("немає дозволу на цей порт (порти до 1024 — лише для адміністратора); оберіть інший --port",
                       "this port is not allowed (ports below 1024 need root); choose another --port"),
    "sv no such host": ("такої адреси на цьому комп'ютері немає (--host)", "no such address on this machine (--host)"),
    "sv shared": ("  (токен запитується в кожного відвідувача; дайте цю адресу групі)",
                  "  (the token is asked of every visitor; share this address with the class)"),
})
