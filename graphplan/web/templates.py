"""The page's templates: each mechanism of the course as a form of its values (the lab's symbols,
units, Ukrainian and English words) and the scene TOML those values make (docs/scenes.md,
docs/cams.md, docs/gears.md). The TOML is written here, on the server, so the page and the command
line read one scene format; every number is checked finite and every text is written as a TOML
string."""
from __future__ import annotations

import json
import math
from dataclasses import asdict, dataclass
from typing import Any, Callable

from graphplan.util.errors import GraphplanError, said_error


@dataclass(frozen=True)
class Field:
    key: str
    symbol: str          # the lab's symbol: "l_OA" is l with the subscript OA
    unit: str            # "m", "rpm", "kg", "N", "", "deg"
    default: float | str
    uk: str
    en: str
    choices: tuple[str, ...] = ()


def F(key, symbol, unit, default, uk, en, choices=()):
    return Field(key, symbol, unit, default, uk, en, tuple(choices))


COMMON = [F("title", "", "", "", "назва на аркуші", "title on the sheet"),
          F("student", "", "", "", "студент", "student"),
          F("group", "", "", "", "група", "group")]
SPEED = [F("n1", "n_1", "rpm", 120, "частота обертання кривошипа", "crank speed"),
         F("direction", "", "", "ccw", "напрям обертання", "sense of rotation", ("ccw", "cw"))]
POSITIONS = [F("count", "N", "", 12, "кількість положень", "number of positions")]
LOAD = [F("stroke", "", "", "working", "хід, на якому діє сила", "the stroke the force acts on",
          ("working", "idle", "both")),
        F("delta", "δ", "", 0.04, "коефіцієнт нерівномірності ходу", "coefficient of unevenness")]


def _s(v: Any) -> str:
    """A TOML basic string (JSON's escaping is TOML's for these characters)."""
    return json.dumps(str(v), ensure_ascii=False)


def _head(v: dict[str, Any], uk: str, en: str, designation: str) -> str:
    title = v.get("title") or ""
    # a title typed on the page names the mechanism in its own words: no title_en (an English sheet
    # romanises a Ukrainian one, util/romanize.py); the template's own title has both
    lines = ([f"title = {_s(title)}"] if title else [f"title = {_s(uk)}", f"title_en = {_s(en)}"]) \
        + [f"designation = {_s(designation)}"]
    sheet = {k: v[k] for k in ("student", "group") if v.get(k)}
    if sheet:
        lines.append("\n[sheet]")
        lines += [f"{k} = {_s(x)}" for k, x in sheet.items()]
    return "\n".join(lines) + "\n"


def _tail(v: dict[str, Any], branch: dict[str, int], dynamics: str = "") -> str:
    out = f"\n[dynamics]\ndelta = {v['delta']:g}\n{dynamics}" if "delta" in v else ""
    if branch:
        out += "\n[branch]\n" + "".join(f"{k} = {int(s)}\n" for k, s in branch.items())
    return out


def _crank(name: str, pivot: str, pin: str, length: str, v: dict[str, Any], extra: str = "") -> str:
    return (f'\n[crank]\nname = "{name}"\npivot = "{pivot}"\npin = "{pin}"\nlength = {length}\n'
            f'rpm = {v["n1"]:g}\ndirection = {_s(v["direction"])}\npoints = {{ S1 = 0.5 }}\n{extra}')


def crank_slider(v, branch, offset=False):
    e = v.get("e", 0.0) if offset else 0.0
    return (_head(v, "Кривошипно-повзунний механізм", "Crank-slider mechanism", "ТММ.01.00.000")
            + f"\n[params]\nr = {v['r']:g}\nl = {v['l']:g}\ne = {e:g}\n"
            + '\n[frame.points]\nO = [0, 0]\n\n[frame.guides]\nx = { through = [0, "e"], angle_deg = 0 }\n'
            + _crank("OA", "O", "A", '"r"', v, f"mass = {v['m1']:g}\n")
            + f'\n[[link]]\nname = "AB"\nnumber = 2\njoints = ["A", "B"]\nlength = "l"\n'
              f"points = {{ S2 = {v['s2']:g} }}\nmass = {v['m2']:g}\n"
            + f'\n[[link]]\nname = "B"\nnumber = 3\njoints = ["B"]\nslides_on = "x"\nmass = {v["m3"]:g}\n'
            + f"\n[positions]\ncount = {int(v['count'])}\nstart = \"max\"\naccel = [1]\n"
            + "\n[loads]\ng = 9.81\ninertia_factor = 0.1\n"
            + f'\n[[force]]\npoint = "B"\nmagnitude = {v["F"]:g}\nstroke = {_s(v["stroke"])}\ndirection = "oppose"\n'
            + _tail(v, branch))


def four_bar(v, branch):
    return (_head(v, "Шарнірний чотириланковий механізм", "Four-bar linkage", "ТММ.03.00.000")
            + f"\n[frame.points]\nO1 = [0, 0]\nO2 = [{v['d']:g}, 0]\n"
            + _crank("O1A", "O1", "A", f"{v['r']:g}", v, f"mass = {v['m1']:g}\n")
            + f'\n[[link]]\nname = "AB"\nnumber = 2\njoints = ["A", "B"]\nlength = {v["l2"]:g}\n'
              f"points = {{ S2 = 0.5 }}\nmass = {v['m2']:g}\n"
            + f'\n[[link]]\nname = "O2B"\nnumber = 3\njoints = ["O2", "B"]\nlength = {v["l3"]:g}\n'
              f"points = {{ S3 = 0.5 }}\nmass = {v['m3']:g}\n"
            + f"\n[positions]\ncount = {int(v['count'])}\nstart = \"max\"\naccel = [1]\n"
            + "\n[loads]\ng = 9.81\ninertia_factor = 0.1\n"
            + f'\n[[force]]\npoint = "B"\nmagnitude = {v["F"]:g}\nstroke = {_s(v["stroke"])}\ndirection = "oppose"\n'
            + _tail(v, branch))


def four_bar_slider(v, branch):
    return (_head(v, "Шарнірний чотириланковий механізм з повзуном", "Four-bar linkage driving a slider",
                  "ТММ.05.00.000")
            + f"\n[frame.points]\nO1 = [0, 0]\nO2 = [{v['d']:g}, 0]\n"
            + f"\n[frame.guides]\nx = {{ through = [0, {v['h']:g}], angle_deg = 0 }}\n"
            + _crank("O1A", "O1", "A", f"{v['r']:g}", v, f"mass = {v['m1']:g}\n")
            + f'\n[[link]]\nname = "AB"\nnumber = 2\njoints = ["A", "B"]\nlength = {v["l2"]:g}\n'
              f"points = {{ S2 = 0.5 }}\nmass = {v['m2']:g}\n"
            + f'\n[[link]]\nname = "O2B"\nnumber = 3\njoints = ["O2", "B"]\nlength = {v["l3"]:g}\n'
              f"points = {{ S3 = 0.5 }}\nmass = {v['m3']:g}\n"
            + f'\n[[link]]\nname = "BC"\nnumber = 4\njoints = ["B", "C"]\nlength = {v["l4"]:g}\n'
              f"points = {{ S4 = 0.5 }}\nmass = {v['m4']:g}\n"
            + f'\n[[link]]\nname = "C"\nnumber = 5\njoints = ["C"]\nslides_on = "x"\nmass = {v["m5"]:g}\n'
            + f"\n[positions]\ncount = {int(v['count'])}\nstart = \"max\"\naccel = [1]\n"
            + "\n[loads]\ng = 9.81\ninertia_factor = 0.1\n"
            + f'\n[[force]]\npoint = "C"\nmagnitude = {v["F"]:g}\nstroke = {_s(v["stroke"])}\ndirection = "oppose"\n'
            + _tail(v, branch))


def shaper(v, branch):
    return (_head(v, "Важільний механізм поперечно-стругального верстата", "Lever mechanism of a shaping machine",
                  "ТММ.КП.00.000")
            + f'\n[synthesis]\ntype = "quick_return"\nK = {v["K"]:g}\nstroke = {v["H"]:g}\n'
              f"centre_distance = {v['lc']:g}\n"
            + f'\n[params]\nX = {v["X"]:g}\nlambda1 = {v["lam"]:g}\nrod = "lambda1 * rocker"\n'
            + '\n[frame.points]\nO = [0, 0]\nO1 = [0, "centre_distance"]\n'
            + '\n[frame.guides]\nram = { through = [0, "X"], angle_deg = 0, title_uk = "повзуна", title_en = "of the ram" }\n'
            + _crank("O1A", "O1", "A", '"crank"', v)
            + '\n[[link]]\nname = "2"\nnumber = 2\njoints = ["A"]\nslides_on = "OB"\n'
            + '\n[[link]]\nname = "OB"\nnumber = 3\njoints = ["O", "B"]\nlength = "rocker"\npoints = { S3 = 0.5 }\n'
            + '\n[[link]]\nname = "BC"\nnumber = 4\njoints = ["B", "C"]\nlength = "rod"\npoints = { S4 = 0.5 }\n'
            + f'\n[[link]]\nname = "C"\nnumber = 5\njoints = ["C"]\nslides_on = "ram"\nmass = {v["m5"]:g}\n'
            + f"\n[positions]\ncount = {int(v['count'])}\nstart = \"idle\"\naccel = [1]\n"
            + f"\n[loads]\ng = 9.81\nmass_per_length = {v['q']:g}\ninertia_factor = 0.1\n"
            + f'\n[[force]]\npoint = "C"\nmagnitude = {v["F"]:g}\nstroke = {_s(v["stroke"])}\ndirection = "oppose"\n'
            + _tail(v, branch, "efficiency = 0.92\nsynchronous_rpm = 1500\n"))


def slotter(v, branch):
    return (_head(v, "Важільний механізм довбального верстата", "Lever mechanism of a slotting machine",
                  "ТММ.ДВ.00.000")
            + f"\n[frame.points]\nO = [0, 0]\nB = [{v['b']:g}, 0]\n"
            + f'\n[frame.guides]\nram = {{ through = [{v["xg"]:g}, 0], angle_deg = 90, title_uk = "повзуна", title_en = "of the ram" }}\n'
            + _crank("OA", "O", "A", f"{v['r']:g}", v, f"mass = {v['m1']:g}\n")
            + '\n[[link]]\nname = "2"\nnumber = 2\njoints = ["A"]\nslides_on = "BC"\n'
            + f'\n[[link]]\nname = "BC"\nnumber = 3\njoints = ["B", "C"]\nlength = {v["l3"]:g}\n'
              f"points = {{ S3 = 0 }}\nmass = {v['m3']:g}\n"
            + f'\n[[link]]\nname = "CD"\nnumber = 4\njoints = ["C", "D"]\nlength = {v["l4"]:g}\n'
              f"points = {{ S4 = 0.5 }}\nmass = {v['m4']:g}\n"
            + f'\n[[link]]\nname = "D"\nnumber = 5\njoints = ["D"]\nslides_on = "ram"\nmass = {v["m5"]:g}\n'
            + f"\n[positions]\ncount = {int(v['count'])}\nstart = \"max\"\nworking_stroke = \"to_min\"\naccel = [1]\n"
            + "\n[loads]\ng = 9.81\ninertia_factor = 0.1\n"
            + f'\n[[force]]\npoint = "D"\nmagnitude = {v["F"]:g}\nstroke = {_s(v["stroke"])}\ndirection = "oppose"\n'
            + _tail(v, branch))


def scotch_yoke(v, branch):
    return (_head(v, "Кулісний механізм (синусний)", "Scotch yoke", "ТММ.06.00.000")
            + "\n[frame.points]\nO = [0, 0]\n"
            + "\n[frame.guides]\ng = { through = [0, 0], angle_deg = 0 }\n"
            + _crank("OA", "O", "A", f"{v['r']:g}", v, f"mass = {v['m1']:g}\n")
            + f'\n[[link]]\nname = "2"\nnumber = 2\njoints = ["A"]\nslides_on = "yoke"\nmass = {v["m2"]:g}\n'
            + f'\n[[link]]\nname = "yoke"\nnumber = 3\njoints = []\nref = "B"\nslides_on = "g"\n'
              f"guide = {{ through = [0, 0], angle_deg = 90 }}\npoints = {{ S3 = [0, 0] }}\nmass = {v['m3']:g}\n"
            + f"\n[positions]\ncount = {int(v['count'])}\nstart = \"max\"\naccel = [1]\n"
            + "\n[loads]\ng = 9.81\ninertia_factor = 0.1\n"
            + f'\n[[force]]\npoint = "B"\nmagnitude = {v["F"]:g}\nstroke = {_s(v["stroke"])}\ndirection = "oppose"\n'
            + _tail(v, branch))


LAWS = ("cosine", "cycloidal", "parabolic", "trapezoidal", "linear")


def _cam_tail(v):
    return (f'phases_deg = {{ rise = {v["rise"]:g}, dwell_far = {v["far"]:g}, return = {v["ret"]:g}, '
            f'dwell_near = {v["near"]:g} }}\n'
            f'laws = {{ rise = {_s(v["law_rise"])}, return = {_s(v["law_return"])} }}\n'
            f'pressure_angle_deg = {{ rise = {v["theta"]:g}, return = {v["theta"]:g} }}\n'
            f'rpm = {v["n1"]:g}\ndirection = {_s(v["direction"])}\ndivisions = {int(v["divisions"])}\n')


def cam_translating(v, branch):
    return (_head(v, "Кулачковий механізм з поступальним роликовим штовхачем",
                  "Disc cam with a translating roller follower", "ТММ.04.00.000")
            + f'\n[cam]\nfollower = "translating"\nstroke = {v["h"]:g}\noffset = {v["e"]:g}\n'
              f"roller_radius = {v['rr']:g}\n" + _cam_tail(v))


def cam_rocking(v, branch):
    return (_head(v, "Кулачковий механізм з коромисловим роликовим штовхачем",
                  "Disc cam with a rocking roller follower", "ТММ.04.00.000")
            + f'\n[cam]\nfollower = "rocking"\nswing_deg = {v["psi"]:g}\narm = {v["arm"]:g}\n'
              f"centre_distance = {v['a']:g}\nroller_radius = {v['rr']:g}\n" + _cam_tail(v))


def gear_pair_and_train(v, branch, kind: str):
    """An external involute pair (docs/gears.md: shifts given or "auto") and a planetary train of
    ``kind`` A or B chosen for its ratio u1H with K planets."""
    shifts = '"auto"' if v["shifts"] == "auto" else f"[{v['x1']:g}, {v['x2']:g}]"
    uk, en = (("Зубчаста передача і планетарний редуктор", "A gear pair and a planetary reducer") if kind == "A"
              else ("Зубчаста передача і дворядний планетарний редуктор", "A gear pair and a two-row planetary reducer"))
    return (_head(v, uk, en, "ТММ.03.00.000")
            + f"\n[gears]\nz = [{v['z1']:g}, {v['z2']:g}]\nmodule = {v['m']:g}\nshifts = {shifts}\n"
              f"pressure_angle_deg = 20\naddendum = 1.0\nclearance = 0.25\n"
            + f'\n[planetary]\ntype = "{kind}"\nratio = {v["u"]:g}\nplanets = {v["K"]:g}\nmodule = {v["mp"]:g}\n'
              f"omega = {v['omega']:g}\n")


def gear_fields(z1, z2, m, shifts, x1, x2, u, k, mp, omega) -> list[Field]:
    return [F("z1", "z_1", "", z1, "число зубців шестірні", "teeth of the pinion"),
            F("z2", "z_2", "", z2, "число зубців колеса", "teeth of the wheel"),
            F("m", "m", "m", m, "модуль зачеплення", "module of the pair"),
            F("shifts", "", "", shifts, "зміщення: задані чи вибрані за правилом (auto)",
              "shifts: given or chosen by the rule (auto)", ("given", "auto")),
            F("x1", "x_1", "", x1, "коефіцієнт зміщення шестірні", "shift coefficient of the pinion"),
            F("x2", "x_2", "", x2, "коефіцієнт зміщення колеса", "shift coefficient of the wheel"),
            F("u", "u_1H", "", u, "потрібне передаточне відношення планетарної передачі",
              "wanted ratio of the planetary train"),
            F("K", "K", "", k, "кількість сателітів", "number of planets"),
            F("mp", "m", "m", mp, "модуль планетарної передачі", "module of the planetary train"),
            F("omega", "ω_1", "rad/s", omega, "кутова швидкість центрального колеса 1",
              "angular velocity of the sun gear 1"),
            *COMMON]


MASS = "маса ланки {}", "mass of link {}"


def _m(k: int, default: float) -> Field:
    return F(f"m{k}", f"m_{k}", "kg", default, MASS[0].format(k), MASS[1].format(k))


CAM_FIELDS = [F("rise", "φ_п", "deg", 120, "фаза піднімання", "rise phase"),
              F("far", "φ_дв", "deg", 30, "фаза дальнього стояння", "far dwell"),
              F("ret", "φ_оп", "deg", 120, "фаза опускання", "return phase"),
              F("near", "φ_бл", "deg", 90, "фаза ближнього стояння", "near dwell"),
              F("law_rise", "", "", "cosine", "закон піднімання", "rise law", LAWS),
              F("law_return", "", "", "parabolic", "закон опускання", "return law", LAWS),
              F("theta", "[ϑ]", "deg", 30, "допустимий кут тиску", "allowed pressure angle"),
              F("rr", "r_р", "m", 0.01, "радіус ролика", "roller radius"),
              F("divisions", "", "", 8, "поділок фази", "divisions of a phase")]


@dataclass(frozen=True)
class Template:
    id: str
    uk: str
    en: str
    fields: list[Field]
    build: Callable[..., str]


TEMPLATES: dict[str, Template] = {t.id: t for t in [
    Template("crank_slider", "Кривошипно-повзунний (центральний)", "Crank-slider (centric)",
             [F("r", "l_OA", "m", 0.064, "довжина кривошипа", "crank length"),
              F("l", "l_AB", "m", 0.307, "довжина шатуна", "connecting rod length"),
              F("s2", "l_AS2/l_AB", "", 0.35, "положення центра мас шатуна", "rod's centre of mass"),
              *SPEED, _m(1, 5), _m(2, 10), _m(3, 20),
              F("F", "F_B", "N", 1000, "сила корисного опору", "useful resistance force"), *LOAD, *POSITIONS, *COMMON],
             crank_slider),
    Template("crank_slider_offset", "Кривошипно-повзунний (дезаксіальний)", "Crank-slider (offset)",
             [F("r", "l_OA", "m", 0.064, "довжина кривошипа", "crank length"),
              F("l", "l_AB", "m", 0.307, "довжина шатуна", "connecting rod length"),
              F("e", "e", "m", 0.02, "ексцентриситет (зміщення напрямної)", "offset of the guide"),
              F("s2", "l_AS2/l_AB", "", 0.35, "положення центра мас шатуна", "rod's centre of mass"),
              *SPEED, _m(1, 5), _m(2, 10), _m(3, 20),
              F("F", "F_B", "N", 1000, "сила корисного опору", "useful resistance force"), *LOAD, *POSITIONS, *COMMON],
             lambda v, b: crank_slider(v, b, offset=True)),
    Template("four_bar", "Шарнірний чотириланковий", "Four-bar linkage",
             [F("r", "l_O1A", "m", 0.10, "довжина кривошипа", "crank length"),
              F("l2", "l_AB", "m", 0.35, "довжина шатуна", "coupler length"),
              F("l3", "l_O2B", "m", 0.25, "довжина коромисла", "rocker length"),
              F("d", "l_O1O2", "m", 0.30, "міжосьова відстань", "frame length"),
              *SPEED, _m(1, 2), _m(2, 5), _m(3, 4),
              F("F", "F_B", "N", 200, "сила корисного опору", "useful resistance force"), *LOAD, *POSITIONS, *COMMON],
             four_bar),
    Template("four_bar_slider", "Чотириланковий з повзуном", "Four-bar driving a slider",
             [F("r", "l_O1A", "m", 0.10, "довжина кривошипа", "crank length"),
              F("l2", "l_AB", "m", 0.35, "довжина шатуна", "coupler length"),
              F("l3", "l_O2B", "m", 0.25, "довжина коромисла", "rocker length"),
              F("d", "l_O1O2", "m", 0.30, "міжосьова відстань", "frame length"),
              F("l4", "l_BC", "m", 0.40, "довжина шатуна BC", "rod BC length"),
              F("h", "h", "m", 0.15, "висота напрямної повзуна", "height of the slider's guide"),
              *SPEED, _m(1, 2), _m(2, 5), _m(3, 4), _m(4, 5), _m(5, 10),
              F("F", "F_C", "N", 300, "сила корисного опору", "useful resistance force"), *LOAD, *POSITIONS, *COMMON],
             four_bar_slider),
    Template("shaper", "Поперечно-стругальний верстат (за K)", "Shaper (from K)",
             [F("K", "K", "", 1.8, "коефіцієнт зміни середньої швидкості", "time-ratio coefficient"),
              F("H", "H", "m", 0.5, "хід повзуна", "ram stroke"),
              F("lc", "l_O1O", "m", 0.48, "міжосьова відстань", "centre distance"),
              F("X", "X", "m", 0.45, "висота напрямної повзуна над O", "height of the ram's guide above O"),
              F("lam", "λ = l_BC/l_OB", "", 0.7, "відношення довжин", "length ratio"),
              F("n1", "n_1", "rpm", 195, "частота обертання кривошипа", "crank speed"),
              F("direction", "", "", "ccw", "напрям обертання", "sense of rotation", ("ccw", "cw")),
              F("q", "q", "kg/m", 150, "погонна маса ланок", "mass per length of the links"),
              _m(5, 40), F("F", "P_C", "N", 5800, "сила різання", "cutting force"), *LOAD, *POSITIONS, *COMMON],
             shaper),
    Template("slotter", "Довбальний верстат", "Slotting machine",
             [F("r", "l_OA", "m", 0.12, "довжина кривошипа", "crank length"),
              F("b", "l_OB", "m", 0.04, "відстань між опорами O і B", "distance between the pivots O and B"),
              F("l3", "l_BC", "m", 0.08, "довжина куліси", "slotted link length"),
              F("l4", "l_CD", "m", 0.35, "довжина шатуна", "rod length"),
              F("xg", "x_D", "m", 0.01, "положення напрямної повзуна", "position of the ram's guide"),
              F("n1", "n_1", "rpm", 120, "частота обертання кривошипа", "crank speed"),
              F("direction", "", "", "ccw", "напрям обертання", "sense of rotation", ("ccw", "cw")),
              _m(1, 5), _m(3, 22), _m(4, 6), _m(5, 34),
              F("F", "P_D", "N", 1500, "сила різання", "cutting force"), *LOAD, *POSITIONS, *COMMON],
             slotter),
    Template("scotch_yoke", "Кулісний (синусний) механізм", "Scotch yoke",
             [F("r", "l_OA", "m", 0.1, "довжина кривошипа", "crank length"),
              *SPEED, _m(1, 2), _m(2, 1), _m(3, 8),
              F("F", "F_B", "N", 300, "сила корисного опору", "useful resistance force"), *LOAD, *POSITIONS, *COMMON],
             scotch_yoke),
    Template("cam_translating", "Кулачковий, поступальний штовхач", "Cam, translating follower",
             [F("h", "h", "m", 0.04, "хід штовхача", "follower's stroke"),
              F("e", "e", "m", 0.005, "ексцентриситет", "offset"),
              *CAM_FIELDS, F("n1", "n_1", "rpm", 95.5, "частота обертання кулачка", "cam speed"),
              F("direction", "", "", "ccw", "напрям обертання", "sense of rotation", ("ccw", "cw")), *COMMON],
             cam_translating),
    Template("cam_rocking", "Кулачковий, коромисловий штовхач", "Cam, rocking follower",
             [F("psi", "ψ_max", "deg", 20, "кут розмаху коромисла", "follower's swing"),
              F("arm", "l", "m", 0.1, "довжина коромисла", "arm length"),
              F("a", "a", "m", 0.12, "міжосьова відстань", "centre distance"),
              *CAM_FIELDS, F("n1", "n_1", "rpm", 120, "частота обертання кулачка", "cam speed"),
              F("direction", "", "", "cw", "напрям обертання", "sense of rotation", ("ccw", "cw")), *COMMON],
             cam_rocking),
    Template("gears_a", "Зубчаста передача і планетарна типу A", "Gear pair and a type A planetary train",
             gear_fields(12, 30, 0.005, "given", 0.5, 0.3, 6, 3, 0.004, 150),
             lambda v, b: gear_pair_and_train(v, b, "A")),
    Template("gears_b", "Зубчаста передача і планетарна типу B", "Gear pair and a type B planetary train",
             gear_fields(14, 35, 0.004, "auto", 0, 0, 12, 3, 0.003, 100),
             lambda v, b: gear_pair_and_train(v, b, "B")),
]}


def catalogue() -> list[dict[str, Any]]:
    """The templates as the page reads them (GET /api/templates)."""
    return [{"id": t.id, "uk": t.uk, "en": t.en, "fields": [asdict(f) for f in t.fields]}
            for t in TEMPLATES.values()]


def scene_toml(doc: Any) -> str:
    """The scene of ``{"template": id, "values": {...}, "branch": {"B": 1}}``; one line naming the
    field for anything that is not a value of it."""
    if not isinstance(doc, dict):
        raise said_error(GraphplanError, "wb form object", None, None)
    t = TEMPLATES.get(str(doc.get("template", "")))
    if t is None:
        raise said_error(GraphplanError, "wb template", None, None, got=repr(str(doc.get("template"))[:40]),
                         known=", ".join(TEMPLATES))
    given = doc.get("values") or {}
    if not isinstance(given, dict):
        raise said_error(GraphplanError, "wb values", None, None)
    values: dict[str, Any] = {}
    for f in t.fields:
        raw = given.get(f.key, f.default)
        if isinstance(f.default, str):
            text = " ".join(str(raw).split())[:200]
            if f.choices and text not in f.choices:
                raise said_error(GraphplanError, "wb choice", "form", None, key=f.key, got=repr(text[:40]),
                                 choices=", ".join(f.choices))
            values[f.key] = text
            continue
        try:
            x = float(str(raw).replace(",", ".").strip())
        except ValueError:
            raise said_error(GraphplanError, "wb not number", "form", None, key=f.key, got=repr(str(raw)[:40])) from None
        if not math.isfinite(x) or abs(x) > 1e12:
            raise said_error(GraphplanError, "wb not finite", "form", None, key=f.key, got=repr(str(raw)[:40]))
        values[f.key] = x
    branch = doc.get("branch") or {}
    if not isinstance(branch, dict) or any(v not in (1, -1) for v in branch.values()) \
            or any(not isinstance(k, str) or not k.isalnum() or len(k) > 40 for k in branch):
        raise said_error(GraphplanError, "wb branch", "form", None)
    return t.build(values, branch)
