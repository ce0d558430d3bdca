"""Coursework mechanisms nobody has drawn: scenes of the examples' four kinds (crank-slider, four-bar,
the shaping machine's and the slotting machine's slotted links) with random lengths, offsets,
speeds, masses and resistances, as scene text — for the composition's property tests.

Each builder takes plain numbers (a hypothesis strategy draws them) and returns the scene's text."""
from __future__ import annotations

SHEET = '''title = "{title}"
title_en = "{title_en}"
designation = "ТММ.{code}.00.000"

[sheet]
student = "Студент"
teacher = "Викладач"
group = "МБ-22"
organisation = "НУБіП України"
'''


def _loads(mass_per_length: float, force: float | None, point: str, working: str = "") -> str:
    text = f"\n[loads]\ng = 9.81\nmass_per_length = {mass_per_length}\ninertia_factor = 0.1\n"
    if force:
        text += (f"\n[[force]]\npoint = \"{point}\"\nmagnitude = {force}\nstroke = \"working\"\n"
                 "direction = \"oppose\"\n")
    return text + working


def _dynamics(delta: float, sync: int) -> str:
    return f"\n[dynamics]\ndelta = {delta}\nefficiency = 0.92\nsynchronous_rpm = {sync}\n"


def crank_slider(r: float, ratio: float, offset: float, rpm: float, kg_per_m: float, force: float,
                 slider_kg: float, delta: float = 0.05) -> str:
    """r: the crank (m); ratio = l/r; offset: the guide's height above O as a share of r."""
    return (SHEET.format(title="Кривошипно-повзунний механізм", title_en="Crank-slider mechanism", code="01")
            + f"""
[frame.points]
O = [0, 0]

[frame.guides]
x = {{ through = [0, {offset * r:.6g}], angle_deg = 0 }}

[crank]
name = "OA"
pivot = "O"
pin = "A"
length = {r:.6g}
rpm = {rpm:.6g}
points = {{ S1 = 0.4 }}

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = {r * ratio:.6g}
points = {{ S2 = 0.35 }}

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "x"
mass = {slider_kg:.6g}

[branch]
B = 1

[positions]
count = 12
start = "max"
accel = [1]
force_phi_deg = 200
""" + _loads(kg_per_m, force, "B") + _dynamics(delta, 1500))


def four_bar(r: float, d: float, coupler: float, rocker: float, rpm: float, kg_per_m: float,
             beta_deg: float = 0.0, cw: bool = False, plate: tuple[float, float] | None = None,
             force: float | None = None) -> str:
    """A crank-rocker O1A–AB–O2B, O1O2 = d at β to the x axis (lengths in m; the caller keeps
    Grashof's condition so that the crank turns fully); the crank clockwise where ``cw``; the coupler
    a plate ABC where ``plate`` gives C = (along AB, across) in shares of AB, loaded at C by ``force``
    on the working stroke."""
    import math
    b = math.radians(beta_deg)
    points = "{ S2 = 0.5 }" if plate is None else f"{{ S2 = 0.5, C = [{plate[0]:.4g}, {plate[1]:.4g}] }}"
    return (SHEET.format(title="Шарнірний чотириланковий механізм", title_en="Crank-rocker four-bar linkage",
                         code="03")
            + f"""
[frame.points]
O1 = [0, 0]
O2 = [{d * math.cos(b):.6g}, {d * math.sin(b):.6g}]

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = {r:.6g}
rpm = {rpm:.6g}
direction = "{'cw' if cw else 'ccw'}"

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = {coupler:.6g}
points = {points}

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = {rocker:.6g}
points = {{ S3 = 0.5 }}

[branch]
B = 1

[positions]
count = 12
start = "max"
accel = [1]
""" + _loads(kg_per_m, force if plate is not None else None, "C"))


def shaper(K: float, stroke: float, centre: float, height: float, lam: float, rpm: float, kg_per_m: float,
           force: float, ram_kg: float, delta: float = 0.04) -> str:
    """Seed 000's quick-return shaping machine from its time-ratio coefficient K, the ram's stroke H,
    the centre distance ℓ, the ram's guide height X (a share of the rocker) and λ = BC/OB."""
    return (SHEET.format(title="Важільний механізм поперечно-стругального верстата",
                         title_en="Lever mechanism of a shaping machine", code="КП")
            + f"""
[synthesis]
type = "quick_return"
K = {K:.6g}
stroke = {stroke:.6g}
centre_distance = {centre:.6g}

[params]
X = "{height:.6g} * rocker"
lambda1 = {lam:.6g}
rod = "lambda1 * rocker"

[frame.points]
O = [0, 0]
O1 = [0, "centre_distance"]

[frame.guides]
ram = {{ through = [0, "X"], angle_deg = 0 }}

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = "crank"
rpm = {rpm:.6g}
direction = "ccw"
points = {{ S1 = 0.5 }}

[[link]]
name = "2"
number = 2
joints = ["A"]
slides_on = "OB"

[[link]]
name = "OB"
number = 3
joints = ["O", "B"]
length = "rocker"
points = {{ S3 = 0.5 }}

[[link]]
name = "BC"
number = 4
joints = ["B", "C"]
length = "rod"
points = {{ S4 = 0.5 }}

[[link]]
name = "C"
number = 5
joints = ["C"]
slides_on = "ram"
mass = {ram_kg:.6g}

[branch]
A = 1
C = -1

[positions]
count = 12
start = "idle"
accel = [1]
force_phi_deg = 200
""" + _loads(kg_per_m, force, "C") + _dynamics(delta, 1500))


def slotter(r: float, pivot: float, arm: float, rod: float, ram_x: float, rpm: float, kg_per_m: float,
            force: float, ram_kg: float, delta: float = 0.04) -> str:
    """Seed 003's slotting machine: crank r, the rocker's pivot ``pivot`` (a share of r) right of O
    (a rotating slotted link), its arm BC, the rod CD to the ram D on a vertical guide at x =
    ``ram_x`` (a share of r)."""
    return (SHEET.format(title="Важільний механізм довбального верстата",
                         title_en="Lever mechanism of a slotting machine", code="ДВ")
            + f"""
[frame.points]
O = [0, 0]
B = [{pivot * r:.6g}, 0]

[frame.guides]
ram = {{ through = [{ram_x * r:.6g}, 0], angle_deg = 90 }}

[crank]
name = "OA"
pivot = "O"
pin = "A"
length = {r:.6g}
rpm = {rpm:.6g}
points = {{ S1 = 0.5 }}

[[link]]
name = "2"
number = 2
joints = ["A"]
slides_on = "BC"

[[link]]
name = "BC"
number = 3
joints = ["B", "C"]
length = {arm:.6g}
points = {{ S3 = 0 }}

[[link]]
name = "CD"
number = 4
joints = ["C", "D"]
length = {rod:.6g}
points = {{ S4 = 0.5 }}

[[link]]
name = "D"
number = 5
joints = ["D"]
slides_on = "ram"
mass = {ram_kg:.6g}

[branch]
A = -1
D = 1

[positions]
count = 12
start = "max"
working_stroke = "to_min"
accel = [1]
""" + _loads(kg_per_m, force, "D") + _dynamics(delta, 1500))
