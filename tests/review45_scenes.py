"""The fourth and fifth reviews' scenes (review4: a six-bar press, uk; review5: an offset crank-slider press,
en), as the reviewers wrote them; kept apart from review_scenes.py."""

OFFSET_PRESS = '''
# An offset (desaxial) crank-slider of a sheet-metal press, ram moving vertically (my own, review5).
title = "Дезаксіальний кривошипно-повзунний механізм преса"
title_en = "Offset crank-slider mechanism of a press"
designation = "ТММ.КП.15.000"
lang = "en"

[sheet]
student = "Reviewer"
teacher = "Teacher"
group = "MB-41"
organisation = "NUBiP"

[params]
r = 0.09
l = 0.24
e = 0.06

[frame.points]
O = [0, 0]

[frame.guides]
ram = { through = ["e", 0], angle_deg = -90, title_en = "of the ram", title_uk = "повзуна" }

[crank]
name = "OA"
pivot = "O"
pin = "A"
length = "r"
rpm = 90
direction = "cw"
mass = 8
inertia = 0.06
points = { S1 = 0.25 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = "l"
mass = 6
inertia = 0.035
points = { S2 = 0.4 }

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "ram"
mass = 25

[branch]
B = 1

[positions]
count = 12
start = "min"
accel = [2, 7]
force_phi_deg = 150
working_stroke = "to_max"

[loads]
g = 9.81

[[force]]
point = "B"
magnitude = 8000
stroke = "working"
direction = "oppose"
profile = [[0, 0], [0.11, 0], [0.15, 0.7], [0.17, 1], [0.19, 1]]

[dynamics]
delta = 0.05
efficiency = 0.9
synchronous_rpm = 1000
'''

SIXBAR_PRESS = '''
# A six-bar press (own mechanism, review4): crank-rocker O1A-AB-O2B, the rocker's arm O2D drives the
# ram E on a vertical guide through the rod DE.
title = "Важільний механізм кривошипного преса"
title_en = "Lever mechanism of a crank press"
designation = "ТММ.ПР.00.000"
lang = "uk"

[sheet]
student = "Рецензент"
teacher = "Викладач"
group = "МБ-41"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.28, 0.06]

[frame.guides]
ram = { through = [0.50, 0], angle_deg = 90, title_uk = "повзуна", title_en = "of the ram" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.08
rpm = 90
direction = "cw"
points = { S1 = 0.5 }
mass = 3
inertia = 0.004

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.30
points = { S2 = 0.5 }
mass = 7
inertia = 0.06

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.22
shape = { D = [0, -0.20] }
points = { S3 = 0.5 }
mass = 9
inertia = 0.07

[[link]]
name = "DE"
number = 4
joints = ["D", "E"]
length = 0.26
points = { S4 = 0.5 }
mass = 5
inertia = 0.03

[[link]]
name = "E"
number = 5
joints = ["E"]
slides_on = "ram"
mass = 40

[branch]
B = 1
E = -1

[positions]
count = 12
start = "max"
working_stroke = "to_min"
accel = [5]
force_phi_deg = 160

[loads]
g = 9.81

[[force]]
point = "E"
magnitude = 6000
stroke = "working"
direction = "oppose"
profile = [[0, 0], [0.08, 0], [0.12, 0.5], [0.145, 1], [0.155, 1]]

[dynamics]
delta = 0.05
efficiency = 0.9
synchronous_rpm = 1000
'''
