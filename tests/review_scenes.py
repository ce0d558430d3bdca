"""The teacher's review scenes (the six-bar I(0-1) → II(2-3) RRR → II(4-5) RRP with a slider driven
by a rocker's extension; the offset crank-slider press turning clockwise; the second review's
slotted-lever coulisse, K = 1.5, its crank clockwise, and crank-rocker four-bar) as scene text, for the
tests of the reviews' corrections."""

SIXBAR = '''# Review scene 1: a six-bar — crank-rocker four-bar O1ABO2 whose rocker extension C drives a slider D
# through rod CD (structural formula I(0-1) -> II(2-3) -> II(4-5)).
title = "Шестиланковий важільний механізм з повзуном"
title_en = "Six-bar linkage with a slider"
designation = "ТММ.РВ1.00.000"

[sheet]
student = "Рецензент"
teacher = "Викладач"
group = "МБ-31"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.28, 0.02]

[frame.guides]
x = { through = [0, 0.30], angle_deg = 0, title_uk = "повзуна", title_en = "of the slider" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.08
rpm = 90
direction = "ccw"
points = { S1 = 0.5 }
mass = 3
inertia = 0.004

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.30
points = { S2 = 0.5 }
mass = 6
inertia = 0.05

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.20
shape = { C = [0.30, 0.0] }
points = { S3 = 0.5 }
mass = 7
inertia = 0.06

[[link]]
name = "CD"
number = 4
joints = ["C", "D"]
length = 0.32
points = { S4 = 0.5 }
mass = 5
inertia = 0.045

[[link]]
name = "D"
number = 5
joints = ["D"]
slides_on = "x"
mass = 25

[branch]
B = 1
D = 1

[positions]
count = 12
start = "max"
accel = [2]
force_phi_deg = 120

[loads]
g = 9.81

[[force]]
point = "D"
magnitude = 900
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.9
synchronous_rpm = 1500
'''

OFFSET_SLIDER = '''# Review scene 2: an offset (eccentric) crank-slider press with a heavy load, 1000 rpm motor line.
title = "Дезаксіальний кривошипно-повзунний механізм преса"
title_en = "Offset crank-slider mechanism of a press"
designation = "ТММ.РВ2.00.000"

[sheet]
student = "Рецензент"
teacher = "Викладач"
group = "МБ-31"
organisation = "НУБіП України"

[params]
r = 0.09
l = 0.36
e = -0.03

[frame.points]
O = [0, 0]

[frame.guides]
x = { through = [0, "e"], angle_deg = 0 }

[crank]
name = "OA"
pivot = "O"
pin = "A"
length = "r"
rpm = 60
direction = "cw"
points = { S1 = 0.3 }
mass = 12
inertia = 0.05

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = "l"
points = { S2 = 0.3 }
mass = 18
inertia = 0.25

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "x"
mass = 60

[branch]
B = 1

[positions]
count = 12
start = "outer"
accel = [3]
force_phi_deg = 60
working_stroke = "to_min"

[loads]
g = 9.81

[[force]]
point = "B"
magnitude = 25000
stroke = "working"
direction = "oppose"
profile = [[0, 0], [0.05, 0], [0.08, 1], [0.18, 1], [0.19, 0]]

[dynamics]
delta = 0.03
efficiency = 0.9
synchronous_rpm = 1000
'''

# The second review (issue 32's sheets of new mechanisms): a translating roller follower turning
# counter-clockwise with a positive offset, and a gear pair with a type-B planetary train.
CAM_TR = '''title = "Кулачковий механізм з поступальним роликовим штовхачем (варіант рецензента)"
title_en = "Disc cam with an offset translating roller follower"
designation = "ТММ.КП.09.000"

[sheet]
student = "Рецензент"
teacher = "Викладач"
group = "МБ-31"
organisation = "НУБіП України"

[cam]
follower = "translating"
stroke = 0.03
offset = 0.008
roller_radius = 0.008
phases_deg = { rise = 100, dwell_far = 40, return = 90, dwell_near = 130 }
laws = { rise = "trapezoidal", return = "cycloidal" }
pressure_angle_deg = { rise = 30, return = 30 }
omega = 12
direction = "ccw"
divisions = 10
'''

GEARS_REVIEW = '''title = "Зубчаста передача і планетарний редуктор (варіант рецензента)"
title_en = "A gear pair and a planetary reducer (reviewer's variant)"
designation = "ТММ.КП.10.000"

[sheet]
student = "Рецензент"
teacher = "Викладач"
group = "МБ-31"
organisation = "НУБіП України"

[gears]
z = [14, 23]
module = 0.006
shifts = [0.4, 0.2]
pressure_angle_deg = 20
addendum = 1.0
clearance = 0.25

[planetary]
type = "B"
ratio = 12.0
planets = 3
module = 0.003
rpm = 960
'''

COULISSE = '''# Review scene (b): a slotted-lever quick-return mechanism, proportions unlike examples/shaper.toml.
title = "Кулісний механізм довбального верстата"
title_en = "Slotted-lever quick-return mechanism of a slotting machine"
designation = "TMM.CP.08.000"
lang = "en"

[sheet]
student = "Reviewer"
teacher = "Teacher"
group = "MB-31"
organisation = "NULES of Ukraine"

[synthesis]
type = "quick_return"
K = 1.5
stroke = 0.35
centre_distance = 0.36

[params]
X = 0.50
lambda1 = 0.5
rod = "lambda1 * rocker"

[frame.points]
O = [0, 0]
O1 = [0, "centre_distance"]

[frame.guides]
ram = { through = [0, "X"], angle_deg = 0, title_uk = "повзуна", title_en = "of the ram" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = "crank"
rpm = 120
direction = "cw"
points = { S1 = 0.5 }

[[link]]
name = "2"
number = 2
joints = ["A"]
slides_on = "OB"
mass = 3

[[link]]
name = "OB"
number = 3
joints = ["O", "B"]
length = "rocker"
points = { S3 = 0.5 }

[[link]]
name = "BC"
number = 4
joints = ["B", "C"]
length = "rod"
points = { S4 = 0.5 }

[[link]]
name = "C"
number = 5
joints = ["C"]
slides_on = "ram"
mass = 25

[branch]
A = 1
C = 1

[positions]
count = 12
start = "idle"
accel = [3]
force_phi_deg = 90

[loads]
g = 9.81
mass_per_length = 100
inertia_factor = 0.1

[[force]]
point = "C"
magnitude = 3200
stroke = "working"
direction = "oppose"
profile = [[0, 0], [0.03, 1], [0.32, 1], [0.35, 0]]

[dynamics]
delta = 0.03
efficiency = 0.9
synchronous_rpm = 1500
'''

FOURBAR = '''# Review scene (a): a crank-rocker four-bar with a resistance on the rocker and masses.
title = "Шарнірний чотириланковий механізм привода гойдального конвеєра"
title_en = "Crank-rocker four-bar of a rocking conveyor drive"
designation = "ТММ.КП.07.000"

[sheet]
student = "Рецензент"
teacher = "Викладач"
group = "МБ-31"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.30, 0.04]

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.08
rpm = 90
direction = "ccw"
points = { S1 = 0.5 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.32
points = { S2 = 0.5 }

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.22
points = { S3 = 0.5, D = 1.3 }

[branch]
B = 1

[positions]
count = 12
start = "max"
accel = [2]
force_phi_deg = 270
working_stroke = "slow"

[loads]
g = 9.81
mass_per_length = 30
inertia_factor = 0.1

[[force]]
point = "D"
magnitude = 400
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.9
synchronous_rpm = 1000
'''


SIEVE = '''# A four-bar driving a sieve: the coupler carries the sieve's point C off the line AB (my own, lead's review).
title = "Шарнірний чотириланковий механізм привода сита"
title_en = "Four-bar linkage of a sieve drive"
designation = "ТММ.КП.11.000"
lang = "uk"

[sheet]
student = "Лід"
teacher = "Викладач"
group = "МБ-42"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.36, -0.12]

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.09
rpm = 120
direction = "cw"
points = { S1 = 0.5 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.34
points = { S2 = 0.5, C = [0.6, 0.15] }

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.22
points = { S3 = 0.5 }

[branch]
B = 1

[positions]
count = 12
start = "max"
accel = [3]
force_phi_deg = 150

[loads]
g = 9.81
mass_per_length = 30
inertia_factor = 0.1

[[force]]
point = "C"
magnitude = 900
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.04
synchronous_rpm = 1500
'''


CAM_KN = '''title = "Кулачковий механізм з поступальним загостреним штовхачем"
title_en = "Disc cam with a translating knife-edge follower"
designation = "ТММ.КМ.00.000"
lang = "uk"

[sheet]
student = "Рецензент"
teacher = "Викладач"
group = "МБ-41"
organisation = "НУБіП України"

[cam]
follower = "translating"
stroke = 0.032
offset = -0.006
roller_radius = 0
phases_deg = { rise = 100, dwell_far = 40, return = 140, dwell_near = 80 }
laws = { rise = "cycloidal", return = "trapezoidal" }
pressure_angle_deg = { rise = 28, return = 35 }
omega = 12
direction = "cw"
divisions = 10
'''


PRESS_EN = '''title = "Дезаксіальний кривошипно-повзунний механізм преса"
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


PRESS4 = '''# A six-bar press (own mechanism, review4): crank-rocker O1A-AB-O2B, the rocker's arm O2D drives the
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


# The third review's gear scene (z 12/31 with "auto" shifts, a type-A train for u = 7.3), and two gear
# scenes of the gear-set round (issue 32): 17/40 with "auto" shifts and a type-B train for u = 9
# (rpm given), 10/25 shifted against undercut (x1 = 0.45 > (17 − 10)/17) with a type-A train of
# four planets, in English.
GEARS12 = '''title = "Зубчаста передача і планетарний редуктор"
title_en = "A gear pair and a planetary reducer"
designation = "ТММ.КП.10.000"
lang = "en"

[sheet]
student = "Reviewer"
teacher = "Teacher"
group = "MB-41"
organisation = "NUBiP"

[gears]
z = [12, 31]
module = 0.004
shifts = "auto"

[planetary]
type = "A"
ratio = 7.3
planets = 3
module = 0.003
omega = 100.0
'''


GEARS_17_40 = '''title = "Зубчаста передача 17/40 і дворядний планетарний редуктор"
title_en = "A gear pair 17/40 and a two-row planetary reducer"
designation = "ТММ.КП.21.000"

[sheet]
student = "Студент"
teacher = "Викладач"
group = "МБ-41"
organisation = "НУБіП України"

[gears]
z = [17, 40]
module = 0.005
shifts = "auto"

[planetary]
type = "B"
ratio = 9.0
planets = 3
module = 0.0025
rpm = 1450
'''


GEARS_10_25 = '''title = "Зубчаста передача 10/25 з корекцією і планетарний редуктор"
title_en = "A shifted gear pair 10/25 and a planetary reducer"
designation = "TMM.CP.22.000"
lang = "en"

[sheet]
student = "Student"
teacher = "Teacher"
group = "MB-42"
organisation = "NULES of Ukraine"

[gears]
z = [10, 25]
module = 0.003
shifts = [0.45, 0.2]

[planetary]
type = "A"
ratio = 5.5
planets = 4
module = 0.002
omega = 120.0
'''


SIXBAR7 = '''# Review 7 scene (a): a crank-rocker six-bar — crank O1A turning counter-clockwise, coupler AB, rocker O2B;
# the rocker's end B drives the slider D on a vertical guide through the rod BD (I(0-1) -> II(2-3) -> II(4-5)).
title = "Шестиланковий важільний механізм з вертикальним повзуном"
title_en = "Six-bar linkage with a vertical slider"
designation = "ТММ.РВ7.00.000"
lang = "uk"

[sheet]
student = "Рецензент"
teacher = "Викладач"
group = "МБ-42"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.30, 0.22]

[frame.guides]
ram = { through = [0.135, 0], angle_deg = 90, title_uk = "повзуна", title_en = "of the slider" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.07
rpm = 110
direction = "ccw"
points = { S1 = 0.5 }
mass = 2.5
inertia = 0.003

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.28
points = { S2 = 0.5 }
mass = 6
inertia = 0.045

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.20
points = { S3 = 0.5 }
mass = 5
inertia = 0.03

[[link]]
name = "BD"
number = 4
joints = ["B", "D"]
length = 0.22
points = { S4 = 0.5 }
mass = 4
inertia = 0.025

[[link]]
name = "D"
number = 5
joints = ["D"]
slides_on = "ram"
mass = 30

[branch]
B = 1
D = 1

[positions]
count = 12
start = "max"
working_stroke = "to_min"
accel = [3, 8]
force_phi_deg = 100

[loads]
g = 9.81

[[force]]
point = "D"
magnitude = 2500
stroke = "working"
direction = "oppose"
profile = [[0, 0], [0.03, 0], [0.06, 1], [0.11, 1], [0.13, 0.3]]

[dynamics]
delta = 0.06
efficiency = 0.88
synchronous_rpm = 750
'''


SIXBAR6 = '''# Review 6: a six-bar — a crank-rocker four-bar O1ABO2 whose coupler plate ABC carries C off the
# line AB; C drives the connecting rod CD to a slider D on an inclined guide (I(0-1) -> II(2-3) RRR -> II(4-5) RRP).
title = "Шестиланковий механізм з шатунною точкою і повзуном на похилій напрямній"
title_en = "Six-bar linkage: coupler point driving a slider on an inclined guide"
designation = "TMM.RV6.00.000"
lang = "en"

[sheet]
student = "Reviewer 6"
teacher = "Teacher"
group = "MB-41"
organisation = "NUBiP of Ukraine"

[frame.points]
O1 = [0, 0]
O2 = [0.24, 0]

[frame.guides]
g = { through = [0.35, 0.17], angle_deg = 15, title_uk = "повзуна", title_en = "of the slider" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.06
rpm = 110
direction = "cw"
points = { S1 = 0.5 }
mass = 2.5
inertia = 0.002

[[link]]
name = "ABC"
number = 2
joints = ["A", "B"]
length = 0.22
shape = { C = [0.12, 0.09] }
points = { S2 = [0.113, 0.03] }
mass = 5
inertia = 0.03

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.18
points = { S3 = 0.5 }
mass = 4
inertia = 0.012

[[link]]
name = "CD"
number = 4
joints = ["C", "D"]
length = 0.32
points = { S4 = 0.5 }
mass = 3.5
inertia = 0.03

[[link]]
name = "D"
number = 5
joints = ["D"]
slides_on = "g"
mass = 18

[branch]
B = 1
D = 1

[positions]
count = 12
start = "working"
accel = [3, 8]
force_phi_deg = 110   # on the working stroke under the full load (s_D ≈ 0.06 m)

[loads]
g = 9.81

[[force]]
point = "D"
magnitude = 1200
stroke = "working"
direction = "oppose"
profile = [[0, 0], [0.03, 0], [0.04, 1], [0.10, 1], [0.11, 0]]

[dynamics]
delta = 0.04
efficiency = 0.88
synchronous_rpm = 750
'''

SIXBAR_REV7 = SIXBAR7     # the same scene (its dynamics tests name it so)


# Review 8: a coulisse quick-return of a slotting machine, K = 1.5, its crank clockwise, the guide pivot O
# 0.30 m below the crank's O1, the ram's guide 0.62 m above O (the plan 1:10 on the A1, a shoulder on the A3's a).
COULISSE8 = '''# Coulisse (rocking guide) quick-return mechanism of a slotting press: K = 1.5, crank turning clockwise.
title = "Кулісний механізм довбального верстата"
title_en = "Coulisse mechanism of a slotting machine"
designation = "ТММ.КП.08.000"
lang = "uk"

[sheet]
student = "Коваленко"
teacher = "Петренко"
group = "МБ-22"
organisation = "НУБіП України"

[synthesis]
type = "quick_return"
K = 1.5
stroke = 0.36
centre_distance = 0.30

[params]
X = 0.62
rod = "0.3 * rocker"

[frame.points]
O = [0, 0]
O1 = [0, "centre_distance"]

[frame.guides]
ram = { through = [0, "X"], angle_deg = 0, title_uk = "повзуна", title_en = "of the ram" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = "crank"
rpm = 110
direction = "cw"
points = { S1 = 0.5 }

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
points = { S3 = 0.5 }

[[link]]
name = "BC"
number = 4
joints = ["B", "C"]
length = "rod"
points = { S4 = 0.5 }

[[link]]
name = "C"
number = 5
joints = ["C"]
slides_on = "ram"
mass = 32

[branch]
A = 1
C = 1

[positions]
count = 12
start = "working"
accel = [2, 9]
force_phi_deg = 100

[loads]
g = 9.81
mass_per_length = 120
inertia_factor = 0.1

[[force]]
point = "C"
magnitude = 3200
stroke = "working"
direction = "oppose"
profile = [[0, 0], [0.03, 1], [0.31, 1], [0.35, 0]]

[dynamics]
delta = 0.05
efficiency = 0.9
synchronous_rpm = 1000
'''

# the lead's own look (stop 41), a compressor: an offset crank-slider on a guide inclined at 150°
COMPRESSOR = '''title = "Кривошипно-повзунний механізм компресора з похилою напрямною"
title_en = "Compressor crank-slider with an inclined guide"
designation = "ТММ.КП.21.000"
lang = "uk"
[params]
r = 0.065
l = 0.26
e = -0.025
[frame.points]
O = [0, 0]
[frame.guides]
piston = { through = ["e", 0], angle_deg = 150, title_en = "of the piston", title_uk = "поршня" }
[crank]
name = "OA"
pivot = "O"
pin = "A"
length = "r"
rpm = 240
direction = "ccw"
mass = 5
inertia = 0.02
points = { S1 = 0.3 }
[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = "l"
mass = 4
inertia = 0.03
points = { S2 = 0.35 }
[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "piston"
mass = 6
[branch]
B = 1
[positions]
count = 12
start = "min"
accel = [3, 8]
force_phi_deg = 60
working_stroke = "to_max"
[loads]
g = 9.81
[[force]]
point = "B"
magnitude = 3500
stroke = "working"
direction = "oppose"
profile = [[0, 0], [0.06, 0.1], [0.10, 0.4], [0.12, 1], [0.13, 1]]
'''

# … with its flywheel, for the dynamics set's order (test_dynamics_set_order)
COMPRESSOR_DYN = COMPRESSOR + """
[dynamics]
delta = 0.04
efficiency = 0.85
synchronous_rpm = 1500
"""


COMPRESSOR42 = '''# Lead's check, stop 42: a compressor crank-slider on a guide inclined at 30°, offset +20 mm, ccw.
title = "Кривошипно-повзунний механізм компресора з похилою напрямною"
title_en = "Compressor crank-slider on an inclined guide"
designation = "ТММ.КП.42.000"

[sheet]
student = "Перевірка"
teacher = "Викладач"
group = "МБ-42"
organisation = "НУБіП України"

[params]
r = 0.07
l = 0.26
e = 0.02

[frame.points]
O = [0, 0]

[frame.guides]
g = { through = [0, "e"], angle_deg = 30, title_uk = "поршня", title_en = "of the piston" }

[crank]
name = "OA"
pivot = "O"
pin = "A"
length = "r"
rpm = 180
direction = "ccw"
points = { S1 = 0.25 }
mass = 4.0
inertia = 0.006

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = "l"
points = { S2 = 0.35 }
mass = 3.0
inertia = 0.02

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "g"
mass = 6.0

[branch]
B = 1

[positions]
count = 12
start = "working"
accel = [3, 9]
force_phi_deg = 130
working_stroke = "to_min"

[loads]
g = 9.81

[[force]]
point = "B"
magnitude = 3500
stroke = "working"
direction = "oppose"
profile = [[0, 0.05], [0.06, 0.3], [0.1, 1], [0.14, 1]]

[dynamics]
delta = 0.04
efficiency = 0.85
synchronous_rpm = 1500
'''

# Review 9's crank-rocker (rev9:out/m2.toml): its ε3 misses 5 % at the positions whatever the lab draws
ROCKER9 = '''# Review 9: a crank-rocker four-bar whose rocker carries a resistance moment (a loom's batten shaft).
title = "Шарнірний чотириланковий механізм з моментом опору на коромислі (рецензія 9)"
title_en = "Crank-rocker four-bar with a resistance moment on the rocker (review 9)"
designation = "TMM.RV9.02.000"
lang = "en"

[sheet]
student = "Reviewer 9"
teacher = "Teacher"
group = "MB-41"
organisation = "NUBiP of Ukraine"

[frame.points]
O1 = [0, 0]
O2 = [0.27, -0.05]

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.075
rpm = 150
direction = "ccw"
points = { S1 = 0.5 }
mass = 1.8
inertia = 0.0015

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.29
points = { S2 = 0.5 }
mass = 3.4
inertia = 0.025

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.19
points = { S3 = 0.45 }
mass = 2.8
inertia = 0.012

[branch]
B = 1

[positions]
count = 12
start = "working"
accel = [3, 9]
force_phi_deg = 90

[loads]
g = 9.81

[[moment]]
link = 3
magnitude = 95
stroke = "working"
direction = "oppose"
profile = [[0, 0.3], [15, 1], [40, 1]]

[dynamics]
delta = 0.06
efficiency = 0.92
synchronous_rpm = 1000
'''


# Review 11 (b): a Scotch-yoke pump with an inclined slot (the RPP group; test_yoke)
YOKE11 = '''# Review 11 (b): a Scotch-yoke pump (sinus mechanism) with an inclined slot: the block at the crank pin A
# slides in the yoke's slot at 75° to the yoke's guide; the yoke's rod D pumps against a pressure force.
title = "Кулісний (синусний) механізм насоса з похилою кулісою (рецензія 11)"
title_en = "Scotch-yoke pump with an inclined slot (review 11)"
designation = "TMM.RV11.02.000"
lang = "en"

[sheet]
student = "Reviewer 11"
teacher = "Teacher"
group = "MB-41"
organisation = "NUBiP of Ukraine"

[frame.points]
O = [0, 0]

[frame.guides]
rod = { through = [0, 0], angle_deg = 0, title_uk = "штока", title_en = "of the rod" }

[crank]
name = "OA"
pivot = "O"
pin = "A"
length = 0.08
rpm = 150
direction = "ccw"
points = { S1 = 0.5 }
mass = 3.5
inertia = 0.006

[[link]]
name = "2"
number = 2
joints = ["A"]
slides_on = "yoke"
mass = 0.8

[[link]]
name = "yoke"
number = 3
joints = []
ref = "D"
slides_on = "rod"
guide = { through = [-0.02, 0], angle_deg = 75 }
points = { S3 = [0.06, 0.0] }
mass = 6.0
inertia = 0.03

[positions]
count = 12
start = "max"
accel = [2, 8]
force_phi_deg = 60
output = "D"
working_stroke = "to_max"

[loads]
g = 9.81

[[force]]
point = "D"
magnitude = 1800
stroke = "working"
direction = "oppose"
profile = [[0, 0.2], [0.02, 1], [0.14, 1], [0.16, 0.2]]

[dynamics]
delta = 0.06
efficiency = 0.9
synchronous_rpm = 1000
'''


GEARS_REV10 = '''# Review 10: a shifted gear pair z = 19/31 with unequal shifts (x2 negative) and a type-A planetary train.
title = "Зубчаста передача і планетарний редуктор (рецензія 10)"
title_en = "A gear pair and a planetary reducer (review 10)"
designation = "ТММ.РВ10.04.000"
lang = "uk"

[sheet]
student = "Рецензент 10"
teacher = "Викладач"
group = "МБ-41"
organisation = "НУБіП України"

[gears]
z = [19, 31]
module = 0.004
shifts = [0.35, -0.2]
pressure_angle_deg = 20

[planetary]
type = "A"
ratio = 5.5
planets = 4
module = 0.003
rpm = 1450
'''


SIXBAR10 = '''# Review 10: a six-bar of a sieve (grader) drive — crank-rocker four-bar O1ABO2 whose coupler plate ABE
# drives through rod EF a slider F on an inclined guide (60°); crank turning clockwise.
# Structural formula I(0-1) -> II(2-3) RRR -> II(4-5) RRP.
title = "Шестиланковий важільний механізм привода сита (рецензія 10)"
title_en = "Six-bar linkage of a sieve drive (review 10)"
designation = "ТММ.РВ10.01.000"
lang = "uk"

[sheet]
student = "Рецензент 10"
teacher = "Викладач"
group = "МБ-41"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.22, -0.05]

[frame.guides]
f = { through = [0.10, 0.30], angle_deg = 60, title_uk = "сита", title_en = "of the sieve" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.06
rpm = 120
direction = "cw"
points = { S1 = 0.5 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.25
shape = { E = [0.12, 0.08] }
points = { S2 = [0.12, 0.03] }

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.18
points = { S3 = 0.5 }

[[link]]
name = "EF"
number = 4
joints = ["E", "F"]
length = 0.26
points = { S4 = 0.5 }

[[link]]
name = "F"
number = 5
joints = ["F"]
slides_on = "f"
mass = 18

[branch]
B = 1
F = 1

[positions]
count = 12
start = "max"
accel = [4]
force_phi_deg = 150

[loads]
g = 9.81
mass_per_length = 40
inertia_factor = 0.12

[[force]]
point = "F"
magnitude = 650
stroke = "working"
direction = "oppose"
profile = [[0, 0.3], [0.02, 1], [0.05, 1], [0.06, 0.5]]

[dynamics]
delta = 0.06
efficiency = 0.85
synchronous_rpm = 1000
'''


COMPRESSOR11 = '''# Review 11 (a): a horizontal offset crank-slider of a single-acting air compressor, crank clockwise,
# positive offset; the gas force from an indicator diagram on the compression stroke (toward the crank).
title = "Кривошипно-повзунний механізм компресора (рецензія 11)"
title_en = "Offset crank-slider of an air compressor (review 11)"
designation = "TMM.RV11.01.000"
lang = "en"

[sheet]
student = "Reviewer 11"
teacher = "Teacher"
group = "MB-41"
organisation = "NUBiP of Ukraine"

[params]
r = 0.045
l = 0.180
e = 0.012

[frame.points]
O = [0, 0]

[frame.guides]
x = { through = [0, "e"], angle_deg = 0, title_uk = "поршня", title_en = "of the piston" }

[crank]
name = "OA"
pivot = "O"
pin = "A"
length = "r"
rpm = 720
direction = "cw"
points = { S1 = 0.25 }
mass = 2.4
inertia = 0.0025

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = "l"
points = { S2 = 0.32 }
mass = 1.6
inertia = 0.0062

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "x"
mass = 2.1

[branch]
B = 1

[positions]
count = 12
start = "outer"
accel = [4, 9]
force_phi_deg = 130
working_stroke = "to_min"

[loads]
g = 9.81

[[force]]
point = "B"
magnitude = 3200
stroke = "working"
direction = "oppose"
# indicator diagram: compression rises slowly, discharge at full pressure over the last quarter
profile = [[0, 0.03], [0.03, 0.12], [0.05, 0.3], [0.065, 0.7], [0.07, 1], [0.09, 1]]

[dynamics]
delta = 0.03
efficiency = 0.85
synchronous_rpm = 1500
motor = "4АМ90L4"
'''


# Review 11 (b), the Scotch-yoke pump: the same scene as YOKE11 (test_dynamics_review10 names it so)
REVIEW11_B = YOKE11


# Review 11 (a) as test_forces_review11 reads it: COMPRESSOR11 without its title block's [sheet] fields
REV11_A = COMPRESSOR11.replace(COMPRESSOR11[COMPRESSOR11.index('[sheet]\n'):COMPRESSOR11.index('\n\n', COMPRESSOR11.index('[sheet]\n')) + 1], '', 1)


CAM_REV10 = '''
# Review 10: a disc cam turning clockwise with an offset translating roller follower;
# parabolic (uniform acceleration–deceleration) rise, linear (constant velocity) return.
title = "Кулачковий механізм з поступальним роликовим штовхачем (рецензія 10)"
title_en = "Disc cam with a translating roller follower (review 10)"
designation = "ТММ.РВ10.05.000"
lang = "uk"

[sheet]
student = "Рецензент 10"
teacher = "Викладач"
group = "МБ-41"
organisation = "НУБіП України"

[cam]
follower = "translating"
stroke = 0.030
offset = 0.010
roller_radius = 0.012
phases_deg = { rise = 150, dwell_far = 20, return = 110, dwell_near = 80 }
laws = { rise = "parabolic", return = "linear" }
pressure_angle_deg = { rise = 28, return = 35 }
omega = 15
direction = "cw"
'''


CAM_REV11 = '''
# Review 11 (c): a disc cam with a rocking knife-edge follower, the cam turning counter-clockwise;
# parabolic rise, cosine return, long far dwell.
title = "Кулачковий механізм з коромисловим загостреним штовхачем (рецензія 11)"
title_en = "Disc cam with a rocking knife-edge follower (review 11)"
designation = "TMM.RV11.05.000"
lang = "en"

[sheet]
student = "Reviewer 11"
teacher = "Teacher"
group = "MB-41"
organisation = "NUBiP of Ukraine"

[cam]
follower = "rocking"
swing_deg = 18
arm = 0.085
centre_distance = 0.11
roller_radius = 0
phases_deg = { rise = 110, dwell_far = 60, return = 90, dwell_near = 100 }
laws = { rise = "parabolic", return = "cosine" }
pressure_angle_deg = { rise = 35, return = 45 }
rpm = 200
direction = "ccw"
'''


# Review 13 (a): a V-twin compressor, both rods on the one crank pin (two dyads on the crank).
VTWIN13 = """# Review 13 (a): a V-twin (90°) single-acting compressor: both connecting rods on the one crank pin A;
# piston B on a guide at 45°, piston C on a guide at 135° offset 30 mm (I(0-1) -> II(2-3) RRP, I(0-1) -> II(4-5) RRP).
title = "V-подібний двоциліндровий компресор (варіант рецензента 13)"
title_en = "V-twin compressor with two rods on one crank pin (review 13)"
designation = "TMM.RV13.01.000"
lang = "en"

[sheet]
student = "A. Reviewer"
teacher = "Strict Teacher"
group = "MB-41"
organisation = "NULES of Ukraine"

[params]
r = 0.055
l = 0.22
e = 0.03

[frame.points]
O = [0, 0]

[frame.guides]
left = { through = [0, 0], angle_deg = 45, title_uk = "поршня 3", title_en = "of piston 3" }
right = { through = [0, "e"], angle_deg = 135, title_uk = "поршня 5", title_en = "of piston 5" }

[crank]
name = "OA"
pivot = "O"
pin = "A"
length = "r"
rpm = 360
direction = "ccw"
mass = 6
inertia = 0.025
points = { S1 = 0.25 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = "l"
mass = 2.8
inertia = 0.016
points = { S2 = 0.3 }

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "left"
mass = 3.5

[[link]]
name = "AC"
number = 4
joints = ["A", "C"]
length = "l"
mass = 2.8
inertia = 0.016
points = { S4 = 0.3 }

[[link]]
name = "C"
number = 5
joints = ["C"]
slides_on = "right"
mass = 3.5

[branch]
B = 1
C = 1

[positions]
count = 12
start = "outer"
accel = [2, 7]
output = "C"
force_phi_deg = 150
working_stroke = "to_min"

[loads]
g = 9.81

[[force]]
point = "C"
magnitude = 2600
stroke = "working"
direction = "oppose"
profile = [[0, 0], [0.04, 0.15], [0.07, 0.45], [0.09, 1], [0.11, 1]]

[[force]]
point = "B"
magnitude = 900
stroke = "both"
direction = 225

[dynamics]
delta = 0.035
efficiency = 0.88
synchronous_rpm = 750
"""


# Review 12 (c): the pair 13/29 with "auto" shifts (εα = 1,2033 by the formula, 1,196 read at 5:1) and a
# type-B train for u = 16; review 13 (c): 23/48 with shifts +0.45/−0.25 and a type-B train for u = 27.
GEARS_REV12 = '''# Review 12 (c): a pair with a small pinion z1 = 13 and shifts "auto", and a two-row planetary
# train (type B) given by its teeth.
title = "Зубчаста передача 13/29 і дворядний планетарний редуктор (рецензія 12)"
title_en = "Gear pair 13/29 and a two-row planetary reducer (review 12)"
designation = "ТММ.РВ12.04.000"
lang = "uk"

[sheet]
student = "Рецензент 12"
teacher = "Викладач"
group = "МБ-41"
organisation = "НУБіП України"

[gears]
z = [13, 29]
module = 0.005
shifts = "auto"
pressure_angle_deg = 20
addendum = 1.0
clearance = 0.25

[planetary]
type = "B"
ratio = 16.0
planets = 3
module = 0.0025
omega = 152.0
'''


GEARS_REV13 = '''# Review 13 (c): a shifted pair z = 23/48 with unequal explicit shifts (x2 negative) and a two-row
# planetary reducer (type B) for a large ratio.
title = "Зубчаста передача 23/48 і дворядний планетарний редуктор (варіант рецензента 13)"
title_en = "A gear pair 23/48 and a two-row planetary reducer (review 13)"
designation = "TMM.RV13.04.000"
lang = "en"

[sheet]
student = "A. Reviewer"
teacher = "Strict Teacher"
group = "MB-41"
organisation = "NULES of Ukraine"

[gears]
z = [23, 48]
module = 0.005
shifts = [0.45, -0.25]
pressure_angle_deg = 20

[planetary]
type = "B"
ratio = 27.0
planets = 3
module = 0.0025
rpm = 1440
'''


# Review 12 (a): the six-bar with an oscillating slotted lever (RRR + RPR, crank cw), O3E made 0.46 m
SIXBAR12 = '''# Review 12 (a): a six-bar of a press-feed lever — crank-rocker four-bar O1ABO2 (RRR) whose rocker's
# extension carries a pin C with a sliding block in the slot of an oscillating slotted lever O3E (RPR,
# the 3rd kind, as the second group). Crank clockwise; O3E 0.46 m (the review's 0.42 let the block run 1.5 mm
# past E, mark 9: SIXBAR12_SHORT keeps that); a resistance moment on the slotted lever with a profile.
title = "Шестиланковий механізм з кулісою, що коливається (рецензія 12)"
title_en = "Six-bar with an oscillating slotted lever (review 12)"
designation = "ТММ.РВ12.01.000"
lang = "uk"

[sheet]
student = "Рецензент 12"
teacher = "Викладач"
group = "МБ-41"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.26, -0.02]
O3 = [0.52, 0.16]

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.07
rpm = 90
direction = "cw"
points = { S1 = 0.5 }
mass = 1.8
inertia = 0.0012

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.27
points = { S2 = 0.5 }
mass = 3.2
inertia = 0.021

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.20
points = { C = 1.35, S3 = 0.6 }
mass = 4.0
inertia = 0.035

[[link]]
name = "4"
number = 4
joints = ["C"]
slides_on = "O3E"
mass = 0.8

[[link]]
name = "O3E"
number = 5
joints = ["O3"]
length = 0.46
points = { E = 1.0, S5 = 0.5 }
mass = 5.5
inertia = 0.09

[branch]
B = 1
C = 1

[positions]
count = 12
start = "max"
accel = [3, 8]
output = "O3E"
force_phi_deg = 110
working_stroke = "slow"

[loads]
g = 9.81

[[moment]]
link = 5
magnitude = 95
stroke = "working"
direction = "oppose"
profile = [[0, 0.2], [6, 1], [14, 1], [20, 0.4]]

[dynamics]
delta = 0.05
efficiency = 0.88
synchronous_rpm = 1000
'''


# Review 12 (a) as the reviewer drew it: O3E = 0.42 m, so the block runs 1.5 mm past E (mark 9's warning)
SIXBAR12_SHORT = SIXBAR12.replace('length = 0.46\npoints = { E = 1.0', 'length = 0.42\npoints = { E = 1.0', 1)


PUMP45 = """# Lead's check, stop 45: a crank-slider whose connecting rod's point C drives a rocker O2D
# (I(0-1) -> II(2-3) RRP -> II(4-5) RRR): a pump's crank train with a rocking valve arm.
title = "Шестиланковий механізм насоса з коромислом від шатунної точки (перевірка 45)"
title_en = "Pump six-bar: a crank-slider whose coupler point drives a rocker (check 45)"
designation = "ТММ.НС.45.000"

[sheet]
student = "Перевірка"
teacher = "Викладач"
group = "МБ-45"
organisation = "НУБіП України"

[frame.points]
O = [0, 0]
O2 = [0.16, 0.30]

[frame.guides]
x = { through = [0, 0], angle_deg = 0, title_uk = "плунжера", title_en = "of the plunger" }

[crank]
name = "OA"
pivot = "O"
pin = "A"
length = 0.07
rpm = 180
direction = "cw"
points = { S1 = 0.3 }
mass = 3
inertia = 0.004

[[link]]
name = "ABC"
number = 2
joints = ["A", "B"]
length = 0.28
shape = { C = [0.12, 0.08] }
points = { S2 = [0.13, 0.025] }
mass = 4.5
inertia = 0.035

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "x"
mass = 6

[[link]]
name = "CD"
number = 4
joints = ["C", "D"]
length = 0.20
points = { S4 = 0.5 }
mass = 2
inertia = 0.008

[[link]]
name = "O2D"
number = 5
joints = ["O2", "D"]
length = 0.16
points = { S5 = 0.5 }
mass = 3
inertia = 0.007

[branch]
B = 1
D = 1

[positions]
count = 12
output = "B"
start = "max"
accel = [3]
force_phi_deg = 210

[loads]
g = 9.81

[[force]]
point = "B"
magnitude = 1800
stroke = "working"
direction = "oppose"

[[moment]]
link = 5
magnitude = 25
stroke = "both"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.9
synchronous_rpm = 1000
"""


COMPRESSOR45 = '''# Stop 45 (crank45's teacher look, A1 forces): an offset single-cylinder air compressor (crank-slider, offset e = 18 mm),
# the crank turning clockwise, gas pressure on the piston over the compression stroke (a profile).
title = "Одноциліндровий компресор з дезаксіальним кривошипно-повзунним механізмом"
title_en = "Single-cylinder compressor with an offset crank-slider"
designation = "TMM.C45.01.000"
lang = "en"

[sheet]
student = "C. Helper"
teacher = "Strict Teacher"
group = "MB-42"
organisation = "NULES of Ukraine"

[frame.points]
O = [0, 0]

[frame.guides]
x = { through = [0, 0.018], angle_deg = 0, title_uk = "поршня", title_en = "of the piston" }

[crank]
name = "OA"
pivot = "O"
pin = "A"
length = 0.05
rpm = 480
direction = "cw"
mass = 4.2
inertia = 0.012
points = { S1 = 0.35 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.2
mass = 2.4
inertia = 0.011
points = { S2 = 0.32 }

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "x"
mass = 3.1

[branch]
B = 1

[positions]
count = 12
start = "outer"
accel = [2, 8]
output = "B"
force_phi_deg = 130
working_stroke = "to_min"

[loads]
g = 9.81

[[force]]
point = "B"
magnitude = 3200
stroke = "working"
direction = "oppose"
profile = [[0, 0.04], [0.03, 0.1], [0.06, 0.3], [0.08, 0.65], [0.09, 1], [0.103, 1]]

[dynamics]
delta = 0.04
efficiency = 0.9
synchronous_rpm = 1000
'''


CAM_ROCKING46 = '''# Stop 46 (the lead's check): a rocking roller follower, the cam counter-clockwise, a parabolic rise
# 120° and a cosine return 90°, a long far dwell, 8 divisions
[cam]
follower = "rocking"
swing_deg = 24
arm = 0.09
centre_distance = 0.11
roller_radius = 0.01
phases_deg = { rise = 120, dwell_far = 60, return = 90, dwell_near = 90 }
laws = { rise = "parabolic", return = "cosine" }
pressure_angle_deg = { rise = 40, return = 50 }
rpm = 90
direction = "ccw"
divisions = 8
'''

CAM_TRANSLATING46 = '''# Stop 46 (cam46's second look): a translating roller follower, the cam clockwise, a negative
# offset, a trapezoidal rise and a cycloidal return: the return's [ϑ] line through the point seen at the
# largest angle (16) cut the phase curve, a hatched place of O seeing 17 at 32.4° > [ϑ] = 32°
[cam]
follower = "translating"
stroke = 0.032
offset = -0.006
roller_radius = 0.008
phases_deg = { rise = 100, dwell_far = 40, return = 130, dwell_near = 90 }
laws = { rise = "trapezoidal", return = "cycloidal" }
pressure_angle_deg = { rise = 28, return = 32 }
omega = 12
direction = "cw"
divisions = 10
'''

ROCKER46 = '''# Lead's check, stop 46: a crank-rocker four-bar O1ABO2 whose rocker's arm O2C drives a vertical slider D
# through the rod CD (I(0-1) -> II(2-3) RRR -> II(4-5) RRP): a vertical feed mechanism, the crank ccw.
title = "Шестиланковий механізм подачі з вертикальним повзуном"
title_en = "Six-bar feed mechanism with a vertical slider"
designation = "ТММ.ПД.46.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-46"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.26, -0.05]

[frame.guides]
y = { through = [0.32, 0], angle_deg = 90, title_uk = "повзуна", title_en = "of the slider" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.065
rpm = 140
direction = "ccw"
points = { S1 = 0.5 }
mass = 2.5
inertia = 0.003

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.24
points = { S2 = 0.5 }
mass = 4
inertia = 0.02

[[link]]
name = "O2BC"
number = 3
joints = ["O2", "B"]
length = 0.15
shape = { C = [0.2, 0.0] }
points = { S3 = 0.5 }
mass = 5
inertia = 0.03

[[link]]
name = "CD"
number = 4
joints = ["C", "D"]
length = 0.22
points = { S4 = 0.5 }
mass = 2
inertia = 0.009

[[link]]
name = "D"
number = 5
joints = ["D"]
slides_on = "y"
mass = 8

[branch]
B = 1
D = 1

[positions]
count = 12
output = "D"
start = "max"
accel = [4]
force_phi_deg = 60

[loads]
g = 9.81

[[force]]
point = "D"
magnitude = 900
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.06
efficiency = 0.85
synchronous_rpm = 750
'''


GEARS46 = '''# Stop 46's check: an external pair 11/29 (the pinion under 17 teeth: shifts "auto"), m = 5 mm, and a
# two-row planetary train of type B for a ratio of 9, in English (the lead's /work/wt/gears.toml).
title = "Зубчаста передача 11/29 і дворядний планетарний редуктор (перевірка 46)"
title_en = "A gear pair 11/29 and a two-row planetary reducer (check 46)"
designation = "TMM.GR.46.000"
lang = "en"

[sheet]
student = "Check N."
teacher = "Teacher T."
group = "MB-46"
organisation = "NULES of Ukraine"

[gears]
z = [11, 29]
module = 0.005
shifts = "auto"

[planetary]
type = "B"
ratio = 9.0
planets = 3
module = 0.0025
omega = 120.0
'''


LINK47 = '''# Stop 47 (the lead's check): an offset crank-slider O-A-B (a horizontal compressor slider B) whose
# connecting rod's point C drives a rocker O2D through the rod CD (I(0-1) -> II(2-3) RRP -> II(4-5) RRR),
# the crank clockwise; dynamics to a 1000-rpm motor.
title = "Шестиланковий механізм компресора з коромислом"
title_en = "Six-bar compressor mechanism with a rocker"
designation = "ТММ.КМ.47.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-47"
organisation = "НУБіП України"

[frame.points]
O = [0, 0]
O2 = [0.16, 0.22]

[frame.guides]
x = { through = [0, -0.02], angle_deg = 0, title_uk = "повзуна", title_en = "of the slider" }

[crank]
name = "OA"
pivot = "O"
pin = "A"
length = 0.06
rpm = 180
direction = "cw"
points = { S1 = 0.5 }
mass = 2
inertia = 0.002

[[link]]
name = "ABC"
number = 2
joints = ["A", "B"]
length = 0.25
shape = { C = [0.1, 0.05] }
points = { S2 = 0.4 }
mass = 5
inertia = 0.03

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "x"
mass = 6

[[link]]
name = "CD"
number = 4
joints = ["C", "D"]
length = 0.18
points = { S4 = 0.5 }
mass = 2.5
inertia = 0.008

[[link]]
name = "O2D"
number = 5
joints = ["O2", "D"]
length = 0.12
points = { S5 = 0.5 }
mass = 3
inertia = 0.006

[branch]
B = 1
D = 1

[positions]
count = 12
output = "B"
start = "max"
accel = [3]
force_phi_deg = 120

[loads]
g = 9.81

[[force]]
point = "B"
magnitude = 1500
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.04
efficiency = 0.8
synchronous_rpm = 1000
'''


COUPLER47 = '''# Stop 47 (kin47's second mechanism): a crank-rocker four-bar O1ABO2 with a coupler point E off the
# coupler AB (its path drawn on the position plan), the crank counter-clockwise, the frame's pivots at
# different heights; the rocker's swing is the output.
title = "Шарнірний чотириланковий механізм з шатунною точкою"
title_en = "Four-bar linkage with a coupler point"
designation = "ТММ.КМ.47.100"

[frame.points]
O1 = [0, 0]
O2 = [0.28, -0.06]

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.08
rpm = 120
direction = "ccw"
points = { S1 = 0.5 }

[[link]]
name = "ABE"
number = 2
joints = ["A", "B"]
length = 0.30
shape = { E = [0.15, 0.10] }
points = { S2 = 0.5 }

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.22
points = { S3 = 0.5 }

[branch]
B = 1

[positions]
count = 12
start = "max"
accel = [2]
'''


CAM47 = '''# Stop 47 (the lead's check): a translating roller follower, the cam counter-clockwise, the offset chosen
# by the program, a trapezoidal rise 100° and a cycloidal return 110°, 12 divisions
title = "Кулачковий механізм з поступальним роликовим штовхачем (перевірка 47)"
title_en = "Cam with a translating roller follower (check 47)"
designation = "ТММ.КМ.47.100"
[cam]
follower = "translating"
stroke = 0.035
offset = "auto"
roller_radius = 0.008
phases_deg = { rise = 100, dwell_far = 40, return = 110, dwell_near = 110 }
laws = { rise = "trapezoidal", return = "cycloidal" }
pressure_angle_deg = { rise = 30, return = 35 }
rpm = 120
direction = "ccw"
divisions = 12
'''


CAM_ROCKING_CW47 = '''# Stop 47 (cam47's own look): a rocking roller follower, the cam clockwise, a trapezoidal rise 110° and
# a parabolic return 90° (its d²ψ/dφ² steps), a short far dwell, 10 divisions
title = "Кулачковий механізм з коромисловим роликовим штовхачем (перевірка 47)"
title_en = "Cam with a rocking roller follower (check 47)"
[cam]
follower = "rocking"
swing_deg = 20
arm = 0.1
centre_distance = 0.12
roller_radius = 0.009
phases_deg = { rise = 110, dwell_far = 20, return = 90, dwell_near = 140 }
laws = { rise = "trapezoidal", return = "parabolic" }
pressure_angle_deg = { rise = 35, return = 45 }
rpm = 150
direction = "cw"
divisions = 10
'''


GEARS47 = '''# Stop 47 (the lead's check): an external pair 14/35 with given shifts, m = 4 mm, and a one-row
# planetary train of type A for a ratio of 7 with three planets (/work/lead/s47/gears.toml).
title = "Зубчаста передача 14/35 і планетарний редуктор (перевірка 47)"
title_en = "A gear pair 14/35 and a planetary reducer (check 47)"
designation = "ТММ.ЗП.47.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-47"
organisation = "НУБіП України"

[gears]
z = [14, 35]
module = 0.004
shifts = [0.35, 0.1]

[planetary]
type = "A"
ratio = 7.0
planets = 3
module = 0.003
omega = 150.0
'''


GEARS_B47 = '''# Stop 47's own check (gear47): an external pair 21/50 with given shifts 0.5/0.2, m = 8 mm (a larger
# module: the meshing at 2.5:1 with seven teeth), and a two-row planetary train of type B with given
# teeth 20/40 - 40/100 (u1H = 6), three planets, n1 = 1450 rpm, in English.
title = "Зубчаста передача 21/50 і дворядний планетарний редуктор (перевірка 47)"
title_en = "A gear pair 21/50 and a two-row planetary reducer (check 47)"
designation = "TMM.GR.47.001"
lang = "en"

[sheet]
student = "Check N."
teacher = "Teacher T."
group = "MB-47"
organisation = "NULES of Ukraine"

[gears]
z = [21, 50]
module = 0.008
shifts = [0.5, 0.2]

[planetary]
type = "B"
z = [20, 40, 40, 100]
planets = 3
module = 0.004
rpm = 1450
'''


SIEVE47 = '''# Stop 47 (helper dyn47's own check): a sieve drive — a crank-rocker O1-A-B-O2 whose rocker's point C
# drives a vertical slider D (the sieve) through CD (I(0-1) -> II(2-3) RRR -> II(4-5) RRP), the crank
# counter-clockwise; a resisting force on D on its upward stroke; dynamics to a 1500-rpm motor.
title = "Механізм привода сита"
title_en = "Sieve drive mechanism"
designation = "ТММ.КП.47.000"

[sheet]
student = "Перевірка Д. Д."
teacher = "Викладач В. В."
group = "МБ-47"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.28, 0.04]

[frame.guides]
y = { through = [0.2, 0], angle_deg = 90, title_uk = "сита", title_en = "of the sieve" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.08
rpm = 120
direction = "ccw"
points = { S1 = 0.5 }
mass = 3
inertia = 0.004

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.30
points = { S2 = 0.5 }
mass = 6
inertia = 0.05

[[link]]
name = "O2BC"
number = 3
joints = ["O2", "B"]
length = 0.20
shape = { C = [0.28, 0.0] }
points = { S3 = 0.5 }
mass = 5
inertia = 0.04

[[link]]
name = "CD"
number = 4
joints = ["C", "D"]
length = 0.22
points = { S4 = 0.5 }
mass = 2
inertia = 0.01

[[link]]
name = "D"
number = 5
joints = ["D"]
slides_on = "y"
mass = 12

[branch]
B = 1
D = 1

[positions]
count = 12
output = "D"
start = "max"
accel = [4]
force_phi_deg = 90

[loads]
g = 9.81

[[force]]
point = "D"
magnitude = 900
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.85
synchronous_rpm = 1500
'''


WATT47 = '''# Stop 47 (frc47's own check): a Watt six-bar of a swing-feed drive — a crank-rocker four-bar O1ABO2 (RRR)
# whose rocker's extension O2C drives an output rocker O3D through the rod CD (I(0-1) -> II(2-3) RRR ->
# II(4-5) RRR, no slider); crank counter-clockwise; a resistance moment on the output rocker on its working stroke.
title = "Шестиланковий механізм Ватта з двома коромислами"
title_en = "Watt six-bar with two rockers"
designation = "ТММ.ВТ.47.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-47"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.21, 0.06]
O3 = [0.04, 0.46]

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.06
rpm = 120
direction = "ccw"
points = { S1 = 0.5 }
mass = 2
inertia = 0.002

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.24
points = { S2 = 0.5 }
mass = 4
inertia = 0.02

[[link]]
name = "O2BC"
number = 3
joints = ["O2", "B"]
length = 0.14
points = { C = 1.5, S3 = 0.6 }
mass = 4.5
inertia = 0.03

[[link]]
name = "CD"
number = 4
joints = ["C", "D"]
length = 0.20
points = { S4 = 0.5 }
mass = 2.5
inertia = 0.009

[[link]]
name = "O3D"
number = 5
joints = ["O3", "D"]
length = 0.15
points = { S5 = 0.5 }
mass = 3.5
inertia = 0.012

[branch]
B = 1
D = 1

[positions]
count = 12
start = "max"
accel = [2]
output = "O3D"
force_phi_deg = 75

[loads]
g = 9.81

[[moment]]
link = 5
magnitude = 60
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.85
synchronous_rpm = 1000
'''


CAM48 = '''# Stop 48 (the lead's check): a rocking knife-edge follower, the cam counter-clockwise, a cycloidal rise
# 120° and a cosine return 90°, 8 divisions (/work/lead/s48/cam.toml).
title = "Кулачковий механізм з коливним загостреним штовхачем (перевірка 48)"
title_en = "Cam with a rocking knife-edge follower (check 48)"
designation = "ТММ.КМ.48.100"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-48"
organisation = "НУБіП України"

[cam]
follower = "rocking"
swing_deg = 22
arm = 0.11
centre_distance = 0.13
roller_radius = 0
phases_deg = { rise = 120, dwell_far = 30, return = 90, dwell_near = 120 }
laws = { rise = "cycloidal", return = "cosine" }
pressure_angle_deg = { rise = 35, return = 40 }
rpm = 90
direction = "ccw"
divisions = 8
'''


CAM_OWN48 = '''# Stop 48 (cam48's own look): a translating roller follower, the cam counter-clockwise, a given negative
# offset (raising the rise's pressure angle), a parabolic rise 90° and a cosine return 150°, 6 divisions.
title = "Кулачковий механізм з поступальним роликовим штовхачем (перевірка 48, власна)"
title_en = "Cam with a translating roller follower (check 48, own)"
designation = "ТММ.КМ.48.200"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-48"
organisation = "НУБіП України"

[cam]
follower = "translating"
stroke = 0.025
offset = -0.008
roller_radius = 0.01
phases_deg = { rise = 90, dwell_far = 60, return = 150, dwell_near = 60 }
laws = { rise = "parabolic", return = "cosine" }
pressure_angle_deg = { rise = 30, return = 30 }
rpm = 300
direction = "ccw"
divisions = 6
'''


GEARS48 = '''# Stop 48 (the lead's check): an external pair 12/31 with the shifts chosen by the rule, m = 5 mm, and a
# two-row planetary train of type B for a ratio of 16 with three planets (/work/lead/s48/gears.toml).
title = "Зубчаста передача 12/31 і планетарний редуктор (перевірка 48)"
title_en = "A gear pair 12/31 and a planetary reducer (check 48)"
designation = "ТММ.ЗП.48.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-48"
organisation = "НУБіП України"

[gears]
z = [12, 31]
module = 0.005
shifts = "auto"

[planetary]
type = "B"
ratio = 16.0
planets = 3
module = 0.0025
omega = 100.0
'''


GEARS_A48 = '''# Stop 48's own check (gear48): a pair 9/27 — far under 17 teeth, the shifts by the rule — with a
# large module m = 6 mm, and a one-row planetary train of type A with given teeth 18 - 36 - 90
# (u1H = 1 + 90/18 = 6; the ring at least 85 teeth), three planets, n1 = 960 rpm.
title = "Зубчаста передача 9/27 і планетарний редуктор типу A (перевірка 48)"
title_en = "A gear pair 9/27 and a type A planetary reducer (check 48)"
designation = "ТММ.ЗП.48.001"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-48"
organisation = "НУБіП України"

[gears]
z = [9, 27]
module = 0.006
shifts = "auto"

[planetary]
type = "A"
z = [18, 36, 90]
planets = 3
module = 0.002
rpm = 960
'''


LINK48 = '''# Stop 48 (the lead's check): a V-compressor — two connecting rods on the one crank pin A, each driving a
# piston on its own guide, the guides at ±45° from the vertical (I(0-1) -> II(2-3) RRP and II(4-5) RRP,
# both groups on the crank); the crank counter-clockwise, the working force on piston B; dynamics to a
# 1500-rpm motor.
title = "V-подібний двоциліндровий компресор"
title_en = "V-type two-cylinder compressor"
designation = "ТММ.КМ.48.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-48"
organisation = "НУБіП України"

[frame.points]
O = [0, 0]

[frame.guides]
b = { through = [0, 0], angle_deg = 45, title_uk = "лівого поршня", title_en = "of the left piston" }
c = { through = [0, 0], angle_deg = 135, title_uk = "правого поршня", title_en = "of the right piston" }

[crank]
name = "OA"
pivot = "O"
pin = "A"
length = 0.05
rpm = 960
direction = "ccw"
points = { S1 = 0.3 }
mass = 3
inertia = 0.004

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.2
points = { S2 = 0.35 }
mass = 2.2
inertia = 0.009

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "b"
mass = 1.8

[[link]]
name = "AC"
number = 4
joints = ["A", "C"]
length = 0.2
points = { S4 = 0.35 }
mass = 2.2
inertia = 0.009

[[link]]
name = "C"
number = 5
joints = ["C"]
slides_on = "c"
mass = 1.8

[branch]
B = 1
C = 1

[positions]
count = 12
output = "B"
start = "max"
accel = [2]
force_phi_deg = 60

[loads]
g = 9.81

[[force]]
point = "B"
magnitude = 2400
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.85
synchronous_rpm = 1500'''


BEATER48 = '''# Stop 48 (helper dyn48's own check): a loom's beater drive — a crank-rocker four-bar O1ABO2, the crank
# clockwise at 180 rpm, the beater (rocker 3) resisting with a moment that rises over the last part of its
# forward swing (the beat-up); dynamics to a 1000-rpm motor, δ = 1/30.
title = "Механізм привода батана ткацького верстата"
title_en = "Loom beater drive"
designation = "ТММ.КП.48.100"

[sheet]
student = "Перевірка Б. Б."
teacher = "Викладач В. В."
group = "МБ-48"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.32, -0.08]

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.06
rpm = 180
direction = "cw"
points = { S1 = 0.5 }
mass = 2
inertia = 0.002

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.30
points = { S2 = 0.5 }
mass = 4
inertia = 0.03

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.22
points = { S3 = 0.4 }
mass = 14
inertia = 0.35

[branch]
B = 1

[positions]
count = 12
output = "O2B"
start = "max"
accel = [3]
force_phi_deg = 120

[loads]
g = 9.81

[[moment]]
link = 3
magnitude = 260
stroke = "working"
direction = "oppose"
profile = [[0, 0.2], [15, 0.4], [25, 1.0], [30, 1.0]]

[dynamics]
delta = 0.0333
efficiency = 0.8
synchronous_rpm = 1000'''



LINK49 = '''# Stop 49 (the lead's check): a rocking-coulisse drive of a planing machine's table feed — the crank O1A
# turns clockwise, its slider stone 2 slides in the coulisse OB, which rocks about O and carries the
# resistance moment of the working stroke (I(0-1) -> II(2-3), a group of the third kind alone); dynamics to
# a 1000-rpm motor.
title = "Кулісний механізм з коливною кулісою і моментом опору"
title_en = "Rocking-coulisse mechanism with a resistance moment"
designation = "ТММ.КМ.49.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-49"
organisation = "НУБіП України"

[frame.points]
O = [0, 0]
O1 = [0, 0.22]

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.09
rpm = 110
direction = "cw"
points = { S1 = 0.5 }
mass = 4
inertia = 0.006

[[link]]
name = "2"
number = 2
joints = ["A"]
slides_on = "OB"
mass = 1.5

[[link]]
name = "OB"
number = 3
joints = ["O"]
length = 0.48
points = { S3 = 0.5, B = 1.0 }
mass = 9
inertia = 0.18

[branch]
A = 1

[positions]
count = 12
start = "working"
accel = [4]
force_phi_deg = 120

[loads]
g = 9.81

[[moment]]
link = 3
magnitude = 160
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.04
efficiency = 0.88
synchronous_rpm = 1000'''



WHITWORTH49 = '''# Stop 49 (frc49's own check): a Whitworth quick-return drive — the crank O1A (longer than O1O) turns the
# coulisse OB fully round O through the stone 2; the rod BC drives the ram C on a horizontal guide through
# O (I(0-1) -> II(2-3) RPR -> II(4-5) RRP); crank counter-clockwise; a cutting force on the ram on its
# working stroke; dynamics to a 1500-rpm motor.
title = "Кулісний механізм з обертовою кулісою (Вітворта) стругального верстата"
title_en = "Whitworth rotating-coulisse mechanism of a shaper"
designation = "ТММ.КП.49.100"

[sheet]
student = "Перевірка Ф. Ф."
teacher = "Викладач В. В."
group = "МБ-49"
organisation = "НУБіП України"

[frame.points]
O = [0, 0]
O1 = [0, 0.07]

[frame.guides]
ram = { through = [0, 0], angle_deg = 0, title_uk = "повзуна", title_en = "of the ram" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.14
rpm = 90
direction = "ccw"
points = { S1 = 0.5 }
mass = 5
inertia = 0.012

[[link]]
name = "2"
number = 2
joints = ["A"]
slides_on = "OB"
mass = 2

[[link]]
name = "OB"
number = 3
joints = ["O", "B"]
length = 0.25
points = { S3 = 0.5 }
mass = 4
inertia = 0.012

[[link]]
name = "BC"
number = 4
joints = ["B", "C"]
length = 0.5
points = { S4 = 0.5 }
mass = 8
inertia = 0.17

[[link]]
name = "C"
number = 5
joints = ["C"]
slides_on = "ram"
mass = 30

[branch]
A = 1
C = 1

[positions]
count = 12
start = "working"
accel = [3]
force_phi_deg = 60

[loads]
g = 9.81

[[force]]
point = "C"
magnitude = 2200
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.9
synchronous_rpm = 1500'''


GEARS49 = '''# Stop 49 (the lead's check): an external pair 9/40 with the shifts chosen by the rule, m = 4 mm, and a
# one-row planetary train of type A for a ratio of 5.2 with four planets, the sun at 1450 rpm.
title = "Зубчаста передача 9/40 і планетарний редуктор (перевірка 49)"
title_en = "A gear pair 9/40 and a planetary reducer (check 49)"
designation = "ТММ.ЗП.49.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-49"
organisation = "НУБіП України"

[gears]
z = [9, 40]
module = 0.004
shifts = "auto"

[planetary]
type = "A"
ratio = 5.2
planets = 4
module = 0.003
rpm = 1450
'''


GEARS_OWN49 = '''# Stop 49's own check (gear49): a pair 13/52 with given equal and opposite shifts x1 = 0,3, x2 = −0,3
# (a height correction: αw = α, aw = a, y = Δy = 0) and a small module m = 2.5 mm, and a one-row
# planetary train of type A for a ratio of 6.3 with three planets, the sun at 960 rpm.
title = "Зубчаста передача 13/52 з рівнозміщеними колесами і планетарний редуктор (перевірка 49)"
title_en = "A gear pair 13/52 with equal and opposite shifts and a planetary reducer (check 49)"
designation = "ТММ.ЗП.49.100"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-49"
organisation = "НУБіП України"

[gears]
z = [13, 52]
module = 0.0025
shifts = [0.3, -0.3]

[planetary]
type = "A"
ratio = 6.3
planets = 3
module = 0.002
rpm = 960
'''


SHEARS49 = '''# Stop 49 (helper dyn49's own check): a sheet-shears feed — a crank-rocker four-bar O1ABO2 whose rocker's
# extension O2C pushes the table D along a horizontal guide through the rod CD (I(0-1) -> II(2-3) RRR ->
# II(4-5) RRP); the crank counter-clockwise at 80 rpm; the cutting force on D over its working stroke;
# dynamics to a 1500-rpm motor, δ = 0.03.
title = "Шестиланковий механізм подачі ножиць"
title_en = "Six-bar feed drive of shears"
designation = "ТММ.НЖ.49.100"

[sheet]
student = "Перевірка Д. Д."
teacher = "Викладач В. В."
group = "МБ-49"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.26, 0.05]

[frame.guides]
table = { through = [0, 0.40], angle_deg = 0, title_uk = "столу", title_en = "of the table" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.07
rpm = 80
direction = "ccw"
points = { S1 = 0.5 }
mass = 3
inertia = 0.004

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.25
points = { S2 = 0.5 }
mass = 5
inertia = 0.03

[[link]]
name = "O2BC"
number = 3
joints = ["O2", "B"]
length = 0.16
points = { C = 1.6, S3 = 0.7 }
mass = 8
inertia = 0.06

[[link]]
name = "CD"
number = 4
joints = ["C", "D"]
length = 0.25
points = { S4 = 0.5 }
mass = 3
inertia = 0.016

[[link]]
name = "D"
number = 5
joints = ["D"]
slides_on = "table"
mass = 25

[branch]
B = 1
D = 1

[positions]
count = 12
start = "max"
working_stroke = "to_min"
accel = [2]
force_phi_deg = 60

[loads]
g = 9.81

[[force]]
point = "D"
magnitude = 2400
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.03
efficiency = 0.85
synchronous_rpm = 1500
'''


CAM49 = '''# Stop 49 (the lead's check): a translating knife-edge follower, the cam clockwise, the offset chosen by the
# rule, a cosine rise of 100° straight into a parabolic return of 140° (no far dwell), 10 divisions.
title = "Кулачковий механізм з поступальним загостреним штовхачем (перевірка 49)"
title_en = "Cam with a translating knife-edge follower (check 49)"
designation = "ТММ.КМ.49.100"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-49"
organisation = "НУБіП України"

[cam]
follower = "translating"
stroke = 0.028
offset = "auto"
roller_radius = 0
phases_deg = { rise = 100, dwell_far = 0, return = 140, dwell_near = 120 }
laws = { rise = "cosine", return = "parabolic" }
pressure_angle_deg = { rise = 28, return = 35 }
rpm = 150
direction = "cw"
divisions = 10
'''


CAM_OWN49 = '''# Stop 49 (cam49's own look): a rocking roller follower, the cam clockwise, a cycloidal rise 90°
# straight into a trapezoidal return 120° (no far dwell), 8 divisions
title = "Кулачковий механізм з коромисловим роликовим штовхачем (власний, 49)"
title_en = "Cam with a rocking roller follower (own, 49)"
designation = "ТММ.КМ.49.200"
[cam]
follower = "rocking"
swing_deg = 18
arm = 0.11
centre_distance = 0.13
roller_radius = 0.01
phases_deg = { rise = 90, dwell_far = 0, return = 120, dwell_near = 150 }
laws = { rise = "cycloidal", return = "trapezoidal" }
pressure_angle_deg = { rise = 40, return = 45 }
rpm = 120
direction = "cw"
divisions = 8
'''


OWN_SIX49 = '''# Stop 49 (kin49's own): a crank-slider-driven six-bar — an offset crank-slider O-A-B whose slider B
# drives the rocker O2C through the rod BC (a press feed's swinging arm); I(0-1) -> II(2-3) RRP -> II(4-5) RRR;
# the crank clockwise.
title = "Шестиланковий механізм з повзуном і коромислом"
title_en = "Six-bar linkage: a crank-slider driving a rocker"
designation = "ТММ.КМ.49.100"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-49"
organisation = "НУБіП України"

[frame.points]
O = [0, 0]
O2 = [0.35, 0.25]

[frame.guides]
g = { through = [0, 0.02], angle_deg = 0, title_uk = "повзуна", title_en = "of the slider" }

[crank]
name = "OA"
pivot = "O"
pin = "A"
length = 0.08
rpm = 150
direction = "cw"
points = { S1 = 0.5 }
mass = 3
inertia = 0.004

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.3
points = { S2 = 0.4 }
mass = 4
inertia = 0.03

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "g"
mass = 2.5

[[link]]
name = "BC"
number = 4
joints = ["B", "C"]
length = 0.22
points = { S4 = 0.5 }
mass = 3
inertia = 0.012

[[link]]
name = "O2C"
number = 5
joints = ["O2", "C"]
length = 0.15
points = { S5 = 0.5 }
mass = 4
inertia = 0.02

[branch]
B = 1
C = 1

[positions]
count = 12
output = "O2C"
start = "max"
accel = [2]
force_phi_deg = 120

[loads]
g = 9.81

[[moment]]
link = 5
magnitude = 60
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.85
synchronous_rpm = 1500
'''

LINK50 = '''
# Stop 50 (the lead's check): a crank-rocker four-bar O1ABO2 whose rocker carries a pin C; a stone 4 on C
# slides in the coulisse O3D, which rocks about O3 and carries the resistance moment of the working
# stroke — I(0-1) -> II(2-3) ВВВ -> II(4-5) ВПВ: a group of the third kind driven by a rocker, not by the
# crank. The crank turns counter-clockwise at 75 rpm; dynamics to a 1500-rpm motor.
title = "Шестиланковий механізм з коливною кулісою"
title_en = "Six-bar linkage with a rocking coulisse"
designation = "ТММ.КМ.50.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-50"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.30, 0.03]
O3 = [0.52, 0.26]

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.07
rpm = 75
direction = "ccw"
points = { S1 = 0.5 }
mass = 3
inertia = 0.003

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.28
points = { S2 = 0.5 }
mass = 5
inertia = 0.04

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.16
shape = { C = [0.24, 0.0] }
points = { S3 = 0.5 }
mass = 6
inertia = 0.05

[[link]]
name = "4"
number = 4
joints = ["C"]
slides_on = "O3D"
mass = 1.2

[[link]]
name = "O3D"
number = 5
joints = ["O3"]
length = 0.46
points = { S5 = 0.5, D = 1.0 }
mass = 7
inertia = 0.07

[branch]
B = 1
C = 1

[positions]
count = 12
start = "working"
accel = [3]
force_phi_deg = 90

[loads]
g = 9.81

[[moment]]
link = 5
magnitude = 120
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.85
synchronous_rpm = 1500
'''

OWN_SLIDER50 = '''
# Stop 50 (kin50's own): a crank-rocker four-bar O1ABO2 whose coupler carries a point E off the line AB;
# the rod EF drives a slider F on a guide inclined at 30° — I(0-1) -> II(2-3) ВВВ -> II(4-5) ВВП, the
# last group driven by a coupler point (a plane-moving link), not by the crank or a rocker.
title = "Шестиланковий механізм з похилою напрямною"
title_en = "Six-bar linkage with an inclined guide"
designation = "ТММ.КМ.50.100"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-50"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.32, -0.04]

[frame.guides]
g = { through = [0.10, 0.30], angle_deg = 30, title_uk = "повзуна", title_en = "of the slider" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.08
rpm = 120
direction = "cw"
points = { S1 = 0.5 }
mass = 2.5
inertia = 0.003

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.30
shape = { E = [0.15, 0.10] }
points = { S2 = 0.5 }
mass = 5
inertia = 0.04

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.20
points = { S3 = 0.5 }
mass = 4
inertia = 0.02

[[link]]
name = "EF"
number = 4
joints = ["E", "F"]
length = 0.26
points = { S4 = 0.5 }
mass = 3
inertia = 0.02

[[link]]
name = "F"
number = 5
joints = ["F"]
slides_on = "g"
mass = 10

[branch]
B = 1
F = 1

[positions]
count = 12
start = "working"
accel = [4]
force_phi_deg = 120

[loads]
g = 9.81

[[force]]
point = "F"
magnitude = 600
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.9
synchronous_rpm = 1500
'''


SLIDER_COULISSE50 = '''# Stop 50 (frc50's own check): a slider-driven rocking coulisse — an offset crank-slider O-A-B whose
# slider B carries a pin with a stone 4 sliding in the coulisse O3D; the coulisse rocks about O3 above the
# guide and carries the resistance moment of its working swing (I(0-1) -> II(2-3) ВВП -> II(4-5) ВПВ:
# a group of the third kind driven by a slider); the crank counter-clockwise; dynamics to a 1000-rpm motor.
title = "Шестиланковий механізм з повзуном і коливною кулісою"
title_en = "Six-bar linkage: a crank-slider rocking a coulisse"
designation = "ТММ.КМ.50.200"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-50"
organisation = "НУБіП України"

[frame.points]
O = [0, 0]
O3 = [0.26, 0.30]

[frame.guides]
g = { through = [0, -0.02], angle_deg = 0, title_uk = "повзуна", title_en = "of the slider" }

[crank]
name = "OA"
pivot = "O"
pin = "A"
length = 0.07
rpm = 120
direction = "ccw"
points = { S1 = 0.5 }
mass = 2.5
inertia = 0.003

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.26
points = { S2 = 0.35 }
mass = 4
inertia = 0.025

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "g"
mass = 3

[[link]]
name = "4"
number = 4
joints = ["B"]
slides_on = "O3D"
mass = 0.8

[[link]]
name = "O3D"
number = 5
joints = ["O3"]
length = 0.42
points = { S5 = 0.4, D = 1.0 }
mass = 6
inertia = 0.06

[branch]
B = 1

[positions]
count = 12
start = "working"
accel = [2]
force_phi_deg = 60

[loads]
g = 9.81

[[moment]]
link = 5
magnitude = 80
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.06
efficiency = 0.85
synchronous_rpm = 1000
'''


DRAGLINK50 = '''# Stop 50 (helper dyn50's own check): a drag-link quick-return drive of a slotting head — a double-crank
# four-bar O1ABO2 (the frame O1O2 the shortest link: both cranks turn full circles, the second one
# unevenly), the crank O2B extended past O2 to C, and the rod CD drives the ram D on a horizontal guide
# through O2: I(0-1) -> II(2-3) ВВВ -> II(4-5) ВВП. The cutting force on the ram's slow stroke; the
# crank counter-clockwise at 60 rpm; dynamics to a 1000-rpm motor.
title = "Механізм довбального верстата з подвійним кривошипом"
title_en = "Drag-link quick-return drive of a slotting machine"
designation = "ТММ.ДК.50.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-50"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.05, 0.0]

[frame.guides]
ram = { through = [0.05, 0.0], angle_deg = 0, title_uk = "повзуна", title_en = "of the ram" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.12
rpm = 60
direction = "ccw"
points = { S1 = 0.5 }
mass = 4
inertia = 0.006

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.14
points = { S2 = 0.5 }
mass = 3
inertia = 0.006

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.13
shape = { C = [-0.10, 0.0] }
points = { S3 = 0.1 }
mass = 5
inertia = 0.012

[[link]]
name = "CD"
number = 4
joints = ["C", "D"]
length = 0.36
points = { S4 = 0.5 }
mass = 6
inertia = 0.07

[[link]]
name = "D"
number = 5
joints = ["D"]
slides_on = "ram"
mass = 25

[branch]
B = 1
D = 1

[positions]
count = 12
start = "working"
accel = [3]
force_phi_deg = 90

[loads]
g = 9.81

[[force]]
point = "D"
magnitude = 1200
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.04
efficiency = 0.9
synchronous_rpm = 1000
'''


CAM50 = '''# Stop 50 (the lead's check): a translating roller follower with a given offset, the cam counter-clockwise,
# a linear (constant-velocity) rise of 90° — hard shocks at its ends — a far dwell of 30°, a cycloidal
# return of 110°, 8 divisions.
title = "Кулачковий механізм з поступальним роликовим штовхачем (перевірка 50)"
title_en = "Cam with a translating roller follower (check 50)"
designation = "ТММ.КМ.50.100"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-50"
organisation = "НУБіП України"

[cam]
follower = "translating"
stroke = 0.032
offset = 0.008
roller_radius = 0.010
phases_deg = { rise = 90, dwell_far = 30, return = 110, dwell_near = 130 }
laws = { rise = "linear", return = "cycloidal" }
pressure_angle_deg = { rise = 30, return = 40 }
rpm = 120
direction = "ccw"
'''


OWN_CAM50 = '''# Stop 50 (cam50's own look): a central translating roller follower (e = 0), the cam clockwise, a given
# base radius R0 = 60 mm above the smallest the pressure angles allow, a cosine rise of 120°, a far dwell
# of 45°, a trapezoidal return of 100°, a near dwell of 95°, 8 divisions.
title = "Кулачковий механізм з центральним роликовим штовхачем і заданим R0 (перевірка 50)"
title_en = "Cam with a central roller follower and a given R0 (check 50)"
designation = "ТММ.КМ.50.200"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-50"
organisation = "НУБіП України"

[cam]
follower = "translating"
stroke = 0.040
offset = 0.0
roller_radius = 0.012
base_radius = 0.060
phases_deg = { rise = 120, dwell_far = 45, return = 100, dwell_near = 95 }
laws = { rise = "cosine", return = "trapezoidal" }
pressure_angle_deg = { rise = 30, return = 35 }
rpm = 90
direction = "cw"
'''


GEARS50 = '''# Stop 50 (the lead's check): an external pair 15/45 with unequal given positive shifts (αw > α), m = 5 mm,
# and a two-row planetary train of type B for a ratio of 12 with three planets, the sun at 960 rpm.
title = "Зубчаста передача 15/45 і дворядний планетарний редуктор (перевірка 50)"
title_en = "A gear pair 15/45 and a two-row planetary reducer (check 50)"
designation = "ТММ.ЗП.50.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-50"
organisation = "НУБіП України"

[gears]
z = [15, 45]
module = 0.005
shifts = [0.5, 0.2]

[planetary]
type = "B"
ratio = 12
planets = 3
module = 0.0025
rpm = 960
'''


GEARS_OWN50 = '''# Stop 50's own check (gear50): a pair 12/33 — the pinion under 17 teeth — with given unequal shifts of
# opposite signs x1 = 0.4, x2 = −0.15 (x1 + x2 = 0.25 > 0), m = 6 mm; a two-row planetary train of type B
# with its teeth given, z = 21/42/22/85 and K = 4 planets (the neighbourhood condition within 1 %), ω1 given.
title = "Зубчаста передача 12/33 і дворядний планетарний редуктор з заданими зубцями (власна перевірка 50)"
title_en = "A gear pair 12/33 and a two-row planetary reducer with given teeth (own check 50)"
designation = "ТММ.ЗП.50.100"

[sheet]
student = "Студент С. С."
teacher = "Викладач В. В."
group = "МБ-50"
organisation = "НУБіП України"

[gears]
z = [12, 33]
module = 0.006
shifts = [0.4, -0.15]

[planetary]
type = "B"
z = [21, 42, 22, 85]
planets = 4
module = 0.002
omega = 150
'''


GEARS51 = '''# Stop 51 (the lead's check): an external pair 14/26 with a large module (8 mm) and the shifts chosen by
# the rule, and a one-row planetary train of type A for a ratio of 5.6 with four planets, the sun at 1440 rpm.
title = "Зубчаста передача 14/26 і однорядний планетарний редуктор (перевірка 51)"
title_en = "A gear pair 14/26 and a one-row planetary reducer (check 51)"
designation = "ТММ.ЗП.51.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-51"
organisation = "НУБіП України"

[gears]
z = [14, 26]
module = 0.008
shifts = "auto"

[planetary]
type = "A"
ratio = 5.6
planets = 4
module = 0.003
rpm = 1440
'''


GEARS_OWN51 = '''# Stop 51's own check (gear51): an unshifted standard pair 18/72 (u = 4, x1 = x2 = 0) with a small module
# m = 2 mm — drawn at 10:1 with the centres far off the sheet —, and a one-row planetary train of type A
# for u = 4,2 with five planets, the sun at 2900 rpm.
title = "Нульова зубчаста передача 18/72 і однорядний планетарний редуктор з п'ятьма сателітами (власна перевірка 51)"
title_en = "An unshifted gear pair 18/72 and a one-row planetary reducer with five planets (own check 51)"
designation = "ТММ.ЗП.51.100"

[sheet]
student = "Студент С. С."
teacher = "Викладач В. В."
group = "МБ-51"
organisation = "НУБіП України"

[gears]
z = [18, 72]
module = 0.002

[planetary]
type = "A"
ratio = 4.2
planets = 5
module = 0.0025
rpm = 2900
'''


LINK51 = '''# Stop 51 (the lead's check): a rocking coulisse driving a rocker — the crank O1A turns clockwise, its
# stone 2 slides in the coulisse O3B, which rocks about O3 below O1; the coulisse's end B drives the rod BD
# to the rocker O4D, which carries the resistance moment of the working stroke —
# I(0-1) -> II(2-3) ВПВ -> II(4-5) ВВВ: a group of the second (ВВВ) kind driven by a coulisse.
title = "Кулісний механізм з коромислом"
title_en = "Coulisse mechanism driving a rocker"
designation = "ТММ.КМ.51.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-51"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0.20]
O3 = [0, 0]
O4 = [0.25, 0.55]

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
name = "2"
number = 2
joints = ["A"]
slides_on = "O3B"
mass = 1.0

[[link]]
name = "O3B"
number = 3
joints = ["O3"]
length = 0.40
points = { S3 = 0.5, B = 1.0 }
mass = 8
inertia = 0.11

[[link]]
name = "BD"
number = 4
joints = ["B", "D"]
length = 0.30
points = { S4 = 0.5 }
mass = 4
inertia = 0.025

[[link]]
name = "O4D"
number = 5
joints = ["O4", "D"]
length = 0.16
points = { S5 = 0.5 }
mass = 5
inertia = 0.02

[branch]
A = 1
D = 1

[positions]
count = 12
start = "working"
accel = [2]
force_phi_deg = 60

[loads]
g = 9.81

[[moment]]
link = 5
magnitude = 90
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.06
efficiency = 0.9
synchronous_rpm = 1000
'''


ROCKING_BLOCK51 = '''# Stop 51 (frc51's own check): a rocking-block drive of a slider — the crank O1A turns counter-clockwise,
# the rod AB slides through the block 3 that rocks about the frame pivot O2; the rod's end B drives the
# connecting rod BC to the slider C on a horizontal guide under the working stroke's resistance —
# I(0-1) -> II(2-3) ВПВ (the block on the frame) -> II(4-5) ВВП.
title = "Механізм з хитним каменем і повзуном"
title_en = "Rocking-block mechanism driving a slider"
designation = "ТММ.ХК.51.000"

[sheet]
student = "Перевірка Ф. С."
teacher = "Викладач В. В."
group = "МБ-51"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.30, 0.0]

[frame.guides]
x = { through = [0, 0.05], angle_deg = 0 }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.10
rpm = 120
direction = "ccw"
points = { S1 = 0.5 }
mass = 2.5
inertia = 0.003

[[link]]
name = "AB"
number = 2
joints = ["A"]
length = 0.55
points = { S2 = 0.5, B = 1.0 }
mass = 6
inertia = 0.15

[[link]]
name = "3"
number = 3
joints = ["O2"]
slides_on = "AB"
mass = 1.5
inertia = 0.002

[[link]]
name = "BC"
number = 4
joints = ["B", "C"]
length = 0.32
points = { S4 = 0.5 }
mass = 3
inertia = 0.03

[[link]]
name = "C"
number = 5
joints = ["C"]
slides_on = "x"
mass = 8

[positions]
count = 12
start = "max"
output = "C"
accel = [2]
force_phi_deg = 240

[loads]
g = 9.81

[[force]]
point = "C"
magnitude = 1500
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.9
synchronous_rpm = 1000
'''


YOKE_ROCKER51 = '''# Stop 51 (helper dyn51's own check): a pump drive — a crank-rocker four-bar O1ABO2 whose rocker's end C
# carries a stone 4 sliding in the horizontal slot of a yoke 5; the yoke's rod D moves on a vertical
# guide and pumps against a force on its up-stroke (I(0-1) -> II(2-3) ВВВ -> II(4-5) ВПП: a Scotch yoke
# driven by a rocker, not by the crank); the crank counter-clockwise at 100 rpm; dynamics to a 750-rpm motor.
title = "Важільний механізм насоса з кулісою, що рухається поступально"
title_en = "Rocker-driven Scotch-yoke pump"
designation = "ТММ.КМ.51.100"

[sheet]
student = "Студент С. С."
teacher = "Викладач В. В."
group = "МБ-51"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.20, 0.10]

[frame.guides]
rod = { through = [0.45, 0], angle_deg = 90, title_uk = "штока", title_en = "of the rod" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.05
rpm = 100
direction = "ccw"
points = { S1 = 0.5 }
mass = 2
inertia = 0.002

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.22
points = { S2 = 0.5 }
mass = 3
inertia = 0.015

[[link]]
name = "O2C"
number = 3
joints = ["O2"]
length = 0.30
points = { B = 0.5, S3 = 0.5, C = 1.0 }
mass = 5
inertia = 0.04

[[link]]
name = "4"
number = 4
joints = ["C"]
slides_on = "yoke"
mass = 0.5

[[link]]
name = "yoke"
number = 5
joints = []
ref = "D"
slides_on = "rod"
guide = { through = [0, 0], angle_deg = 90 }
points = { S5 = [0.0, 0.0] }
mass = 8
inertia = 0.05

[branch]
B = 1

[positions]
count = 12
start = "min"
accel = [2]
force_phi_deg = 60
output = "D"
working_stroke = "to_max"

[loads]
g = 9.81

[[force]]
point = "D"
magnitude = 600
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.04
efficiency = 0.85
synchronous_rpm = 750
'''


OWN_YOKE51 = '''# Stop 51 (kin51's own): a crank-rocker four-bar O1ABO2 whose rocker O2C carries at its end C a stone 4 that
# slides in the vertical slot of a yoke 5; the yoke slides on a horizontal guide and carries the working
# resistance — I(0-1) -> II(2-3) ВВВ -> II(4-5) ВПП: a sinus (Scotch-yoke) group driven by a rocker, not by
# the crank. The crank turns clockwise at 120 rpm.
title = "Шестиланковий механізм з кулісою, що рухається поступально"
title_en = "Six-bar linkage: a rocker driving a Scotch yoke"
designation = "ТММ.КМ.51.100"

[sheet]
student = "Студент С. С."
teacher = "Викладач В. В."
group = "МБ-51"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.30, 0.0]

[frame.guides]
rod = { through = [0.30, 0.34], angle_deg = 0, title_uk = "повзуна", title_en = "of the yoke" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.06
rpm = 120
direction = "cw"
points = { S1 = 0.5 }
mass = 2.5
inertia = 0.003

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.25
points = { S2 = 0.5 }
mass = 4
inertia = 0.03

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.18
shape = { C = [0.30, 0.0] }
points = { S3 = 0.5 }
mass = 6
inertia = 0.05

[[link]]
name = "4"
number = 4
joints = ["C"]
slides_on = "yoke"
mass = 0.8

[[link]]
name = "yoke"
number = 5
joints = []
ref = "D"
slides_on = "rod"
guide = { through = [0.0, 0.0], angle_deg = 90 }
points = { S5 = [0.0, 0.0] }
mass = 7.0
inertia = 0.04

[branch]
B = 1

[positions]
count = 12
start = "max"
accel = [4]
force_phi_deg = 60
output = "D"
working_stroke = "to_max"

[loads]
g = 9.81

[[force]]
point = "D"
magnitude = 1500
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.9
synchronous_rpm = 1500
'''


SLIDER_ROCKER51 = '''# Stop 51 (review51's own): a crank-slider whose slider B drives a rocker O2C through the rod BC —
# I(0-1) -> II(2-3) ВВП -> II(4-5) ВВВ; the crank counter-clockwise; the useful force on the slider B,
# whose pin is shared by the rod AB, the slider and the rod BC.
title = "Шестиланковий механізм з повзуном і коромислом"
title_en = "Six-bar linkage: slider driving a rocker"
designation = "ТММ.КМ.51.200"

[sheet]
student = "Перевірка Р. Р."
teacher = "Викладач В. В."
group = "МБ-51"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.45, 0.15]

[frame.guides]
x = { through = [0, 0], angle_deg = 0 }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.06
rpm = 150
direction = "ccw"
points = { S1 = 0.5 }
mass = 2.0
inertia = 0.002

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.25
points = { S2 = 0.35 }
mass = 4
inertia = 0.025

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "x"
mass = 6

[[link]]
name = "BC"
number = 4
joints = ["B", "C"]
length = 0.20
points = { S4 = 0.5 }
mass = 3
inertia = 0.012

[[link]]
name = "O2C"
number = 5
joints = ["O2", "C"]
length = 0.14
points = { S5 = 0.5 }
mass = 5
inertia = 0.015

[branch]
B = 1
C = 1

[positions]
count = 12
start = "working"
accel = [3]
force_phi_deg = 90

[loads]
g = 9.81

[[force]]
point = "B"
magnitude = 800
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.85
synchronous_rpm = 1500'''


CAM51 = '''# Stop 51 (the lead's check): a rocking roller follower, the cam counter-clockwise, a parabolic rise of
# 120° (soft shocks), a short far dwell of 20°, a cosine return of 90°, 6 divisions.
title = "Кулачковий механізм з коромисловим роликовим штовхачем (перевірка 51)"
title_en = "Cam with a rocking roller follower (check 51)"
designation = "ТММ.КМ.51.100"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-51"
organisation = "НУБіП України"

[cam]
follower = "rocking"
swing_deg = 25
arm = 0.12
centre_distance = 0.15
roller_radius = 0.012
phases_deg = { rise = 120, dwell_far = 20, return = 90, dwell_near = 130 }
laws = { rise = "parabolic", return = "cosine" }
pressure_angle_deg = { rise = 40, return = 45 }
rpm = 150
direction = "ccw"
divisions = 6
'''


OWN_CAM51 = '''# Stop 51 (cam51's own look): a rocking roller follower turned by a clockwise cam, a LINEAR rise of 100°
# (rigid shocks at its ends: dψ/dφ and ϑ jump there), a far dwell of 40°, a cycloidal return of 110°,
# the default 8 divisions.
title = "Кулачковий механізм з коромисловим штовхачем і лінійним підйомом (власна перевірка 51)"
title_en = "Cam with a rocking follower and a linear rise (own check 51)"
designation = "ТММ.КМ.51.200"

[sheet]
student = "Студент С. С."
teacher = "Викладач В. В."
group = "МБ-51"
organisation = "НУБіП України"

[cam]
follower = "rocking"
swing_deg = 20
arm = 0.11
centre_distance = 0.14
roller_radius = 0.01
phases_deg = { rise = 100, dwell_far = 40, return = 110, dwell_near = 110 }
laws = { rise = "linear", return = "cycloidal" }
pressure_angle_deg = { rise = 35, return = 45 }
rpm = 120
direction = "cw"
'''

FORCE_COUPLER51 = '''# Stop 51 (review51's own, for frc51c): crank-rocker four-bar O1ABO2, crank counter-clockwise, heavy rocker; the coupler
# point E (off the line AB) drives, through the rod EF, a slider F on a guide inclined at 135°.
# I(0-1) -> II(2-3) ВВВ -> II(4-5) ВВП.
title = "Шестиланковий механізм з похилою напрямною"
title_en = "Six-bar linkage with a coupler-driven slider on an inclined guide"
designation = "TMM.KM.51.300"
lang = "en"

[sheet]
student = "Check R. R."
teacher = "Teacher T. T."
group = "MB-51"
organisation = "NULES of Ukraine"

[frame.points]
O1 = [0, 0]
O2 = [0.28, 0.05]

[frame.guides]
g = { through = [0.05, 0.32], angle_deg = 135, title_uk = "повзуна", title_en = "of the slider" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.07
rpm = 100
direction = "ccw"
points = { S1 = 0.5 }
mass = 2.0
inertia = 0.002

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.26
shape = { E = [0.13, 0.09] }
points = { S2 = 0.5 }
mass = 4
inertia = 0.03

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.18
points = { S3 = 0.5 }
mass = 12
inertia = 0.08

[[link]]
name = "EF"
number = 4
joints = ["E", "F"]
length = 0.22
points = { S4 = 0.5 }
mass = 2.5
inertia = 0.015

[[link]]
name = "F"
number = 5
joints = ["F"]
slides_on = "g"
mass = 8

[branch]
B = 1
F = 1

[positions]
count = 12
start = "working"
accel = [2]
force_phi_deg = 150

[loads]
g = 9.81

[[force]]
point = "F"
magnitude = 500
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.04
efficiency = 0.88
synchronous_rpm = 1000
'''

SIX_LEVER51 = SLIDER_ROCKER51     # the same six-bar (frc51c's lever tests name it so)

WEDGE52 = '''
# Stop 52 (a blind grading): a wedge press: offset crank-slider drives a wedge (link 3) whose inclined slot lifts a block 4
# pinned to the vertical ram 5.  I(0-1) -> II(2-3) RRP (offset) -> II(4-5) PRP.
title = "Клиновий прес з кривошипно-повзунним приводом"
title_en = "Wedge press with an offset crank-slider drive"
designation = "ТММ.КП.52.100"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-52"
organisation = "НУБіП України"

[frame.points]
O = [0, 0]

[frame.guides]
x = { through = [0, -0.03], angle_deg = 0, title_uk = "клина", title_en = "of the wedge" }
ram = { through = [0.40, 0], angle_deg = 90, title_uk = "повзуна", title_en = "of the ram" }

[crank]
name = "OA"
pivot = "O"
pin = "A"
length = 0.05
rpm = 120
direction = "ccw"
points = { S1 = 0.5 }
mass = 2
inertia = 0.002

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.22
points = { S2 = 0.4 }
mass = 3
inertia = 0.015

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "x"
guide = { through = [0.14, 0], angle_deg = 150 }
mass = 12

[[link]]
name = "C"
number = 4
joints = ["C"]
slides_on = "B"
mass = 1

[[link]]
name = "5"
number = 5
joints = ["C"]
slides_on = "ram"
mass = 20

[branch]
B = 1

[positions]
count = 12
start = "min"
accel = [3]
force_phi_deg = 150
output = "C"
working_stroke = "to_max"

[loads]
g = 9.81

[[force]]
point = "C"
magnitude = 3000
stroke = "working"
direction = "oppose"
profile = [[0, 0], [0.01, 1], [0.05, 1]]

[dynamics]
delta = 0.08
efficiency = 0.85
'''


LINK52 = '''# Stop 52 (the lead's check): an eight-bar — a crank-rocker four-bar whose rocker's end carries a block
# sliding in a rocking coulisse; the coulisse's end drives a rod to a slider on a horizontal guide —
# I(0-1) -> II(2-3) ВВВ -> II(4-5) ВПВ -> II(6-7) ВВП: three groups, a coulisse driven by a rocker.
title = "Восьмиланковий механізм з кулісою"
title_en = "Eight-bar mechanism with a coulisse"
designation = "ТММ.КМ.52.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-52"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.26, 0.04]
O3 = [0.60, 0.10]

[frame.guides]
x = { through = [0, 0.42], angle_deg = 0 }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.06
rpm = 120
direction = "ccw"
points = { S1 = 0.5 }
mass = 2
inertia = 0.002

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.24
points = { S2 = 0.5 }
mass = 3
inertia = 0.015

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.14
points = { S3 = 0.5, C = 1.8 }
mass = 4
inertia = 0.03

[[link]]
name = "4"
number = 4
joints = ["C"]
slides_on = "O3D"
mass = 0.8

[[link]]
name = "O3D"
number = 5
joints = ["O3"]
length = 0.38
points = { S5 = 0.5, D = 1.0 }
mass = 6
inertia = 0.07

[[link]]
name = "DE"
number = 6
joints = ["D", "E"]
length = 0.30
points = { S6 = 0.5 }
mass = 3
inertia = 0.02

[[link]]
name = "E"
number = 7
joints = ["E"]
slides_on = "x"
mass = 10

[branch]
B = 1
C = 1
E = 1

[positions]
count = 12
start = "working"
accel = [3]
force_phi_deg = 120

[loads]
g = 9.81

[[force]]
point = "E"
magnitude = 1200
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.85
synchronous_rpm = 1500
'''


SIX_BELL52 = '''# Stop 52 (kin52's own): a Watt six-bar — a crank-rocker four-bar O1ABO2 whose rocker is a bell crank
# O2BC (a plate: C off the line O2B); its arm C drives, through the rod CD, the output rocker O3D,
# which carries the resistance moment of the working stroke; the crank turns clockwise —
# I(0-1) -> II(2-3) ВВВ -> II(4-5) ВВВ: two groups of the second kind, the second driven by a plate.
title = "Шестиланковий механізм з кутовим важелем"
title_en = "Six-bar linkage with a bell crank"
designation = "ТММ.КМ.52.100"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-52"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.18, 0.08]
O3 = [0.36, 0.38]

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.05
rpm = 90
direction = "cw"
points = { S1 = 0.5 }
mass = 1.5
inertia = 0.001

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.20
points = { S2 = 0.5 }
mass = 2.5
inertia = 0.01

[[link]]
name = "O2BC"
number = 3
joints = ["O2", "B"]
length = 0.12
shape = { C = [0.02, -0.11] }
points = { S3 = [0.04, 0.04] }
mass = 4
inertia = 0.02

[[link]]
name = "CD"
number = 4
joints = ["C", "D"]
length = 0.22
points = { S4 = 0.5 }
mass = 2
inertia = 0.01

[[link]]
name = "O3D"
number = 5
joints = ["O3", "D"]
length = 0.14
points = { S5 = 0.5 }
mass = 3
inertia = 0.015

[branch]
B = 1
D = 1

[positions]
count = 12
start = "working"
accel = [4]
force_phi_deg = 90

[loads]
g = 9.81

[[moment]]
link = 5
magnitude = 40
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.9
synchronous_rpm = 1000
'''


CAM52 = '''# Stop 52 (the lead's check): a translating roller follower with the offset chosen by the program ("auto"),
# the cam clockwise, a cycloidal rise of 150°, a far dwell of 40°, a trapezoidal return of 100°, 8 divisions.
title = "Кулачковий механізм з поступальним роликовим штовхачем (перевірка 52)"
title_en = "Cam with a translating roller follower (check 52)"
designation = "ТММ.КМ.52.100"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-52"
organisation = "НУБіП України"

[cam]
follower = "translating"
stroke = 0.032
offset = "auto"
roller_radius = 0.009
phases_deg = { rise = 150, dwell_far = 40, return = 100, dwell_near = 70 }
laws = { rise = "cycloidal", return = "trapezoidal" }
pressure_angle_deg = { rise = 28, return = 35 }
rpm = 200
direction = "cw"
divisions = 8
'''


OWN_CAM52 = '''# Stop 52 (cam52's own look): a translating roller follower, offset "auto", the cam counter-clockwise, a
# short steep COSINE rise of 80°, a far dwell of 20°, a long PARABOLIC return of 160°, 6 divisions.
title = "Кулачковий механізм з поступальним роликовим штовхачем (власна перевірка 52)"
title_en = "Cam with a translating roller follower (own check 52)"
designation = "ТММ.КМ.52.200"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-52"
organisation = "НУБіП України"

[cam]
follower = "translating"
stroke = 0.025
offset = "auto"
roller_radius = 0.007
phases_deg = { rise = 80, dwell_far = 20, return = 160, dwell_near = 100 }
laws = { rise = "cosine", return = "parabolic" }
pressure_angle_deg = { rise = 30, return = 30 }
rpm = 300
direction = "ccw"
divisions = 6
'''


OWN_INCLINED52 = '''# Stop 52 (frc52's own check): a crank-slider on a guide inclined at 60° whose connecting rod's point C
# (off the line AB) drives a rocker O2D through the rod CD — a rocker's shaft loaded by a resistance
# MOMENT on its working swing: I(0-1) -> II(2-3) ВВП (inclined guide) -> II(4-5) ВВВ from a coupler point.
title = "Шестиланковий механізм з похилим повзуном"
title_en = "Six-bar mechanism with an inclined slider"
designation = "ТММ.КМ.52.100"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-52"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.32, 0.10]

[frame.guides]
g = { through = [0, 0], angle_deg = 60 }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.07
rpm = 150
direction = "cw"
points = { S1 = 0.5 }
mass = 2.5
inertia = 0.003

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.26
points = { S2 = [0.133, -0.03] }
shape = { C = [0.14, -0.09] }
mass = 4
inertia = 0.03

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "g"
mass = 6

[[link]]
name = "CD"
number = 4
joints = ["C", "D"]
length = 0.22
points = { S4 = 0.5 }
mass = 2.5
inertia = 0.012

[[link]]
name = "O2D"
number = 5
joints = ["O2", "D"]
length = 0.16
points = { S5 = 0.5 }
mass = 5
inertia = 0.04

[branch]
B = 1
D = 1

[positions]
count = 12
start = "working"
accel = [2]
force_phi_deg = 60

[loads]
g = 9.81

[[moment]]
link = 5
magnitude = 150
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.04
efficiency = 0.9
synchronous_rpm = 1000
'''


GEARS52 = '''# Stop 52 (the lead's check): an external pair 11/23 (few teeth: the shifts needed against undercut)
# with a module of 6 mm, x1 = 0.5, x2 = 0.3 given; a two-row planetary train of type B for u = 16, K = 3.
title = "Зубчаста передача 11/23 і дворядний планетарний редуктор (перевірка 52)"
title_en = "A gear pair 11/23 and a two-row planetary reducer (check 52)"
designation = "ТММ.ЗП.52.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-52"
organisation = "НУБіП України"

[gears]
z = [11, 23]
module = 0.006
shifts = [0.5, 0.3]

[planetary]
type = "B"
ratio = 16
planets = 3
module = 0.0025
rpm = 960
'''


GEARS_OWN52 = '''# Stop 52's own check (gear52): a pair 15/37 with a module of 4 mm, a positive shift on the pinion and a
# negative one on the wheel (x1 = 0.45, x2 = -0.25: x1 + x2 = 0.2), and a two-row planetary train of type B
# with its teeth given (21, 45, 22, 88: u1H = 9.571) and two planets, the sun at 1450 rpm.
title = "Зубчаста передача 15/37 з від'ємним зміщенням колеса і дворядний планетарний редуктор із заданими числами зубців (власна перевірка 52)"
title_en = "A gear pair 15/37 with a negative shift of the wheel and a two-row planetary reducer with given teeth (own check 52)"
designation = "ТММ.ЗП.52.100"

[sheet]
student = "Студент С. С."
teacher = "Викладач В. В."
group = "МБ-52"
organisation = "НУБіП України"

[gears]
z = [15, 37]
module = 0.004
shifts = [0.45, -0.25]

[planetary]
type = "B"
z = [21, 45, 22, 88]
planets = 2
module = 0.002
rpm = 1450
'''


DYN_OWN52 = '''
# Stop 52, dyn52's own: a six-bar lifting table — a crank-rocker four-bar whose rocker's extension C
# drives the rod CD to the table D on a VERTICAL guide; the table's weight and a 900 N load over the
# lift's middle (a profile), plus a resistance moment on the rocker on both strokes; the crank turns
# clockwise, 16 divisions, δ = 0.08, a 3000-rpm motor through a two-stage reducer (its shafts given).
title = "Шестиланковий механізм підйомного столу"
title_en = "Six-bar mechanism of a lifting table"
designation = "ТММ.КМ.52.100"

[sheet]
student = "Помічник Д. Д."
teacher = "Викладач В. В."
group = "МБ-52"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.30, 0.0]

[frame.guides]
y = { through = [0.36, 0], angle_deg = 90 }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.07
rpm = 90
direction = "cw"
points = { S1 = 0.5 }
mass = 3
inertia = 0.004

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.28
points = { S2 = 0.5 }
mass = 4
inertia = 0.03

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.18
points = { S3 = 0.6, C = 1.6 }
mass = 6
inertia = 0.06

[[link]]
name = "CD"
number = 4
joints = ["C", "D"]
length = 0.30
points = { S4 = 0.5 }
mass = 3
inertia = 0.02

[[link]]
name = "D"
number = 5
joints = ["D"]
slides_on = "y"
mass = 25

[branch]
B = 1
D = 1

[positions]
count = 16
start = "working"
accel = [4]
force_phi_deg = 90

[loads]
g = 9.81

[[force]]
point = "D"
magnitude = 900
stroke = "working"
direction = "oppose"
profile = [[0, 0], [0.01, 1], [0.05, 1], [0.06, 0]]

[[moment]]
link = 3
magnitude = 15
stroke = "both"
direction = "oppose"

[dynamics]
delta = 0.08
efficiency = 0.8
synchronous_rpm = 3000
reducer_shafts = [0.0004, 0.003, 0.08]
first_stage_ratio = 5.0
'''


LOOM52 = '''
title = "Важільний механізм приводу бердильного бруса ткацького верстата"
title_en = "Lever mechanism of a loom beater (batten) drive"
designation = "ТММ.КП.52.000"

[sheet]
student = "Рецензент"
teacher = "Викладач"
group = "МБ-41"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.28, 0.05]
O3 = [0.52, -0.04]

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.07
rpm = 180
direction = "cw"
points = { S1 = 0.5 }
mass = 3
inertia = 0.004

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.26
points = { S2 = 0.5 }
mass = 4
inertia = 0.025

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.16
shape = { C = [0.05, -0.09] }
points = { S3 = 0.5 }
mass = 5
inertia = 0.02

[[link]]
name = "CD"
number = 4
joints = ["C", "D"]
length = 0.30
points = { S4 = 0.5 }
mass = 3.5
inertia = 0.028

[[link]]
name = "O3D"
number = 5
joints = ["O3", "D"]
length = 0.18
points = { S5 = 0.5, E = 1.6 }
mass = 9
inertia = 0.09

[branch]
B = 1
D = 1

[positions]
count = 12
start = "working"
accel = [2, 8]
force_phi_deg = 120
working_stroke = "slow"

[loads]
g = 9.81

[[moment]]
link = 5
magnitude = 60
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.9
synchronous_rpm = 1000
'''


REVIEW_CAM52 = '''# Stop 52's blind review, scene 3 (review52's s3_cam.toml): a translating roller follower, offset "auto",
# the cam clockwise, a cycloidal rise, a trapezoidal return; R0 taken 39 mm over the smallest 38.3 mm.
title = "Кулачковий механізм з поступальним роликовим штовхачем"
title_en = "Disc cam with a translating roller follower"
designation = "ТММ.КП.52.000"

[cam]
follower = "translating"
stroke = 0.032
offset = "auto"
roller_radius = 0.012
phases_deg = { rise = 100, dwell_far = 50, return = 140, dwell_near = 70 }
laws = { rise = "cycloidal", return = "trapezoidal" }
pressure_angle_deg = { rise = 28, return = 35 }
rpm = 300
direction = "cw"
divisions = 10
'''


# Stop 53 (the lead's check, /work/lead/s53/link.toml): a two-cylinder compressor with an articulated rod
# (master rod AKB, slave rod KC on the lug K), crank clockwise; 1800 N on B on its stroke away from O1.
LINK53 = '''# Stop 53 (the lead's check): a two-cylinder compressor with an articulated (master-and-slave) rod —
# the crank O1A turns clockwise; the master rod AKB, a plate, drives the piston B on a guide at 60°;
# the slave rod KC, pinned to the master rod's lug K off its axis, drives the piston C on a guide at 120°
# — I(0-1) -> II(2-3) ВВП -> II(4-5) ВВП: the second group hangs on a point of the first group's rod.
title = "Двоциліндровий компресор з причіпним шатуном"
title_en = "Two-cylinder compressor with an articulated connecting rod"
designation = "ТММ.КМ.53.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-53"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]

[frame.guides]
b = { through = [0, 0], angle_deg = 60 }
c = { through = [0, 0], angle_deg = 120 }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.055
rpm = 360
direction = "cw"
points = { S1 = 0.3 }
mass = 3
inertia = 0.004

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.22
points = { S2 = 0.3 }
shape = { K = [0.045, 0.04] }
mass = 2.5
inertia = 0.012

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "b"
mass = 2

[[link]]
name = "KC"
number = 4
joints = ["K", "C"]
length = 0.17
points = { S4 = 0.5 }
mass = 1.6
inertia = 0.005

[[link]]
name = "C"
number = 5
joints = ["C"]
slides_on = "c"
mass = 2

[branch]
B = 1
C = 1

[positions]
count = 12
start = "outer"
accel = [2]
force_phi_deg = 60
working_stroke = "to_max"
output = "B"

[loads]
g = 9.81

[[force]]
point = "B"
magnitude = 1800
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.04
efficiency = 0.9
synchronous_rpm = 1000
'''


# Helper dyn53's own (stop 53): a rocking screen of a grain cleaner — a crank-rocker whose rocker's arm O2D
# drives the screen box E on a horizontal guide by the rod DE (I(0-1) -> II(2-3) ВВВ -> II(4-5) ВВП); 600 N on
# both strokes, a damper moment on the rocker's working swing, crank clockwise, a 750-rpm motor through a
# two-stage reducer given by its shafts (seed 003 eq. 4).
DYN_OWN53 = '''title = "Механізм коливального решета зерноочисної машини"
title_en = "Rocking screen of a grain cleaner"
designation = "ТММ.КМ.53.100"

[sheet]
student = "Помічник dyn53"
teacher = "Викладач В. В."
group = "МБ-53"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.26, 0.14]

[frame.guides]
e = { through = [0, 0.32], angle_deg = 0 }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.05
rpm = 180
direction = "cw"
points = { S1 = 0.5 }
mass = 2
inertia = 0.002

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.24
points = { S2 = 0.5 }
mass = 2.6
inertia = 0.014

[[link]]
name = "O2D"
number = 3
joints = ["O2", "B"]
length = 0.12
points = { S3 = 0.8 }
shape = { D = [0.2, 0.0] }
mass = 3
inertia = 0.012

[[link]]
name = "DE"
number = 4
joints = ["D", "E"]
length = 0.22
points = { S4 = 0.5 }
mass = 1.8
inertia = 0.007

[[link]]
name = "E"
number = 5
joints = ["E"]
slides_on = "e"
mass = 12

[branch]
B = 1
E = 1

[positions]
count = 12
start = "outer"
accel = [4]
force_phi_deg = 120
output = "E"

[loads]
g = 9.81

[[force]]
point = "E"
magnitude = 600
stroke = "both"
direction = "oppose"

[[moment]]
link = 3
magnitude = 25
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.03
efficiency = 0.85
synchronous_rpm = 750
reducer_shafts = [0.0006, 0.004, 0.06]
first_stage_ratio = 3.2
'''


CAM53 = '''# Stop 53 (the lead's check): a rocking roller follower turned by a counter-clockwise cam, a cosine rise
# of 120° straight into a parabolic return of 90° (no far dwell), a large swing of 30°, 12 divisions, and a
# base radius given larger than the smallest allowed.
title = "Кулачковий механізм з коромисловим роликовим штовхачем (перевірка 53)"
title_en = "Cam with a rocking roller follower (check 53)"
designation = "ТММ.КМ.53.100"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-53"
organisation = "НУБіП України"

[cam]
follower = "rocking"
swing_deg = 30
arm = 0.12
centre_distance = 0.15
roller_radius = 0.012
phases_deg = { rise = 120, dwell_far = 0, return = 90, dwell_near = 150 }
laws = { rise = "cosine", return = "parabolic" }
pressure_angle_deg = { rise = 40, return = 45 }
rpm = 90
direction = "ccw"
base_radius = 0.07
divisions = 12
'''


OWN_CAM53 = '''# Stop 53 (cam53's own look): a translating roller follower, the offset chosen by the program ("auto"),
# the cam counter-clockwise, a cycloidal rise of 160° and a cosine return of 160° round a far dwell of
# 40° — NO near dwell (the return runs straight into the next rise) —, 10 divisions.
title = "Кулачковий механізм з поступальним роликовим штовхачем без ближнього вистою (власний 53)"
title_en = "Cam with a translating roller follower and no near dwell (own 53)"
designation = "ТММ.КМ.53.200"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-53"
organisation = "НУБіП України"

[cam]
follower = "translating"
stroke = 0.04
offset = "auto"
roller_radius = 0.01
phases_deg = { rise = 160, dwell_far = 40, return = 160, dwell_near = 0 }
laws = { rise = "cycloidal", return = "cosine" }
pressure_angle_deg = { rise = 30, return = 40 }
rpm = 120
direction = "ccw"
divisions = 10
'''


GEARS53 = '''# Stop 53 (the lead's check): an external pair 16/21 — a small ratio, a large module (10 mm) — with the
# shifts chosen by the rule ("auto"), and a one-row planetary train of type A for u = 4.2 with K = 5
# satellites.
title = "Зубчаста передача 16/21 і однорядний планетарний редуктор (перевірка 53)"
title_en = "A gear pair 16/21 and a one-row planetary reducer (check 53)"
designation = "ТММ.ЗП.53.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-53"
organisation = "НУБіП України"

[gears]
z = [16, 21]
module = 0.010
shifts = "auto"

[planetary]
type = "A"
ratio = 4.2
planets = 5
module = 0.003
rpm = 1450
'''


GEARS_OWN53 = '''# Stop 53's own check (gear53): a pair of many teeth, 32/41 with a module of 5 mm and the shifts chosen by the
# rule ("auto"), and a one-row planetary train of type A for u = 3.6 with six satellites (K = 6: the
# neighbourhood bounds u below 4), the sun at 960 rpm.
title = "Зубчаста передача 32/41 і однорядний планетарний редуктор із шістьма сателітами (власна перевірка 53)"
title_en = "A gear pair 32/41 and a one-row planetary reducer with six planets (own check 53)"
designation = "ТММ.ЗП.53.100"

[sheet]
student = "Студент С. С."
teacher = "Викладач В. В."
group = "МБ-53"
organisation = "НУБіП України"

[gears]
z = [32, 41]
module = 0.005
shifts = "auto"

[planetary]
type = "A"
ratio = 3.6
planets = 6
module = 0.002
rpm = 960
'''


SLOTTED_CRANK53 = '''# Stop 53 (kin53's own): a slotted crank driving a rotating arm — the crank 1 turns clockwise about O1 and
# carries a slot along itself; the block 2 slides in it, pinned at B to the arm O2B, which turns fully round
# O2 (O1O2 shorter than O2B) with a varying speed; the arm's end B drives the rod BC to the slider C on a
# horizontal guide — I(0-1) -> II(2-3) ВВП (the prismatic pair outer, on the crank) -> II(4-5) ВВП.
title = "Механізм з кулісним кривошипом і повзуном"
title_en = "Slotted-crank drive of a slider"
designation = "ТММ.КМ.53.200"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-53"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.04, -0.03]

[frame.guides]
x = { through = [0, -0.03], angle_deg = 0, title_uk = "повзуна", title_en = "of the slider" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.16
rpm = 100
direction = "cw"
guide = { through = [0, 0], angle_deg = 0 }
points = { S1 = 0.3 }
mass = 4
inertia = 0.01

[[link]]
name = "2"
number = 2
joints = ["B"]
slides_on = "O1A"
mass = 0.5

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.10
points = { S3 = 0.5 }
mass = 2
inertia = 0.004

[[link]]
name = "BC"
number = 4
joints = ["B", "C"]
length = 0.30
points = { S4 = 0.5 }
mass = 3
inertia = 0.02

[[link]]
name = "C"
number = 5
joints = ["C"]
slides_on = "x"
mass = 6

[branch]
B = 1
C = 1

[positions]
count = 12
start = "outer"
accel = [3]
force_phi_deg = 60
output = "C"
working_stroke = "to_max"

[loads]
g = 9.81

[[force]]
point = "C"
magnitude = 500
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.85
synchronous_rpm = 1000
'''


TWO_MOMENTS53 = '''# review53: a rocking-coulisse (slotted-lever) pump drive in English: the crank O1A's block A slides in
# the lever O2D's slot; a LARGE resistance moment on the lever on its IDLE stroke (a return spring/pump),
# a small one on the working stroke.  I(0-1) -> II(2-3) RPR.
title = "Кулісний привод насоса"
title_en = "Slotted-lever pump drive"
designation = "TMM.CP.53.600"
lang = "en"

[sheet]
student = "Reviewer R."
teacher = "Teacher T."
group = "MB-53"
organisation = "NUBiP of Ukraine"

[frame.points]
O1 = [0, 0]
O2 = [0, -0.30]

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.11
rpm = 75
direction = "cw"
points = { S1 = 0.5 }
mass = 3
inertia = 0.006

[[link]]
name = "A"
number = 2
joints = ["A"]
slides_on = "O2D"
mass = 0.8

[[link]]
name = "O2D"
number = 3
joints = ["O2"]
length = 0.5
points = { D = 1.0, S3 = 0.5 }
mass = 7
inertia = 0.15

[positions]
count = 12
start = "working"
accel = [3]
force_phi_deg = 240
output = "O2D"
working_stroke = "slow"

[loads]
g = 9.81

[[moment]]
link = 3
magnitude = 40
stroke = "working"
direction = "oppose"

[[moment]]
link = 3
magnitude = 260
stroke = "idle"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.88
synchronous_rpm = 1500
'''


INCLINED_ROCKER53 = '''# review53: a crank-slider whose slider B runs on an INCLINED guide (20°) that does not pass through the
# crank's pivot; the slider's pin B drives a rod BC and a rocker O3C (RRR hung on the slider).
# I(0-1) -> II(2-3) RRP -> II(4-5) RRR; crank clockwise.
title = "Кривошипно-повзунний механізм з похилою напрямною і коромислом"
title_en = "Crank-slider with an inclined guide and a rocker"
designation = "ТММ.КП.53.300"

[sheet]
student = "Рецензент Р. Р."
teacher = "Викладач В. В."
group = "МБ-53"
organisation = "НУБіП України"

[frame.points]
O = [0, 0]
O3 = [0.36, 0.20]

[frame.guides]
g = { through = [0.05, -0.04], angle_deg = 20, title_uk = "повзуна", title_en = "of the slider" }

[crank]
name = "OA"
pivot = "O"
pin = "A"
length = 0.06
rpm = 240
direction = "cw"
points = { S1 = 0.5 }
mass = 1.5
inertia = 0.001

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.25
points = { S2 = 0.35 }
mass = 2.4
inertia = 0.014

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "g"
mass = 5

[[link]]
name = "BC"
number = 4
joints = ["B", "C"]
length = 0.20
points = { S4 = 0.5 }
mass = 1.8
inertia = 0.007

[[link]]
name = "O3C"
number = 5
joints = ["O3", "C"]
length = 0.14
points = { S5 = 0.5 }
mass = 2.2
inertia = 0.005

[branch]
B = 1
C = 1

[positions]
count = 12
start = "working"
accel = [2, 8]
force_phi_deg = 90
output = "B"
working_stroke = "to_max"

[loads]
g = 9.81

[[force]]
point = "B"
magnitude = 1500
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.03
efficiency = 0.9
synchronous_rpm = 1000
'''


OWN_SPRING_PRESS53 = '''# Stop 53's own check (frc53b): a vertical crank-slider (a press) whose slider carries TWO forces, one per
# stroke: 2400 N against its motion on the working stroke (down) and a return spring's 350 N against
# its motion on the idle stroke; the force position on the idle stroke. I(0-1) -> II(2-3) RRP.
title = "Кривошипно-повзунний прес із пружиною повернення (власна перевірка 53)"
title_en = "Crank press with a return spring (own check 53)"
designation = "ТММ.КП.53.700"

[sheet]
student = "Студент С. С."
teacher = "Викладач В. В."
group = "МБ-53"
organisation = "НУБіП України"

[frame.points]
O = [0, 0]

[frame.guides]
g = { through = [0.02, 0], angle_deg = 90, title_uk = "повзуна", title_en = "of the slider" }

[crank]
name = "OA"
pivot = "O"
pin = "A"
length = 0.07
rpm = 120
direction = "ccw"
points = { S1 = 0.5 }
mass = 2
inertia = 0.002

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.30
points = { S2 = 0.4 }
mass = 3
inertia = 0.025

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "g"
mass = 6

[branch]
B = 1

[positions]
count = 12
start = "working"
accel = [4]
force_phi_deg = 270
output = "B"
working_stroke = "to_min"

[loads]
g = 9.81

[[force]]
point = "B"
magnitude = 2400
stroke = "working"
direction = "oppose"

[[force]]
point = "B"
magnitude = 350
stroke = "idle"
direction = "oppose"
'''


LINK54 = '''# Stop 54 (the lead's check): a Blake jaw crusher — the crank O1A turns counter-clockwise at 250 rpm; the
# pitman AB hangs the toggle plates O2B and BC; the plate BC pushes the swing jaw O3C about its top pivot
# O3 — I(0-1) -> II(2-3) ВВВ -> II(4-5) ВВВ, two all-revolute groups in a row, the toggle near its dead
# centres; a crushing moment on the jaw on its stroke towards the fixed jaw.
title = "Щокова дробарка з простим рухом щоки"
title_en = "Blake jaw crusher"
designation = "ТММ.КМ.54.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-54"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.17, -0.29]
O3 = [-0.24, 0.10]

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.04
rpm = 250
direction = "ccw"
points = { S1 = 0.0 }
mass = 12
inertia = 0.08

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.36
points = { S2 = 0.5 }
mass = 20
inertia = 0.25

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.18
points = { S3 = 0.5 }
mass = 6
inertia = 0.02

[[link]]
name = "BC"
number = 4
joints = ["B", "C"]
length = 0.20
points = { S4 = 0.5 }
mass = 6
inertia = 0.025

[[link]]
name = "O3C"
number = 5
joints = ["O3", "C"]
length = 0.40
points = { S5 = 0.5 }
mass = 40
inertia = 0.9

[branch]
B = -1
C = 1

[positions]
count = 12
start = "max"
accel = [3]
force_phi_deg = 90
working_stroke = "to_min"
output = "O3C"

[loads]
g = 9.81

[[moment]]
link = 5
magnitude = 900
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.85
synchronous_rpm = 750
'''


OWN_KNEE_PRESS54 = '''# Stop 54's own check (forces54): a knee-lever (toggle) press — the crank O1A turns counter-clockwise at
# 90 rpm; the coupler AB swings the knee B of the toggle O2B–BC, whose lower link BC drives the ram C down
# a vertical guide; the toggle comes near straight at the ram's bottom — I(0-1) -> II(2-3) ВВВ -> II(4-5) ВВП,
# the pin B shared by 2, 3 and 4; 15 kN against the ram on its stroke down.
title = "Колінно-важільний прес (власна перевірка 54)"
title_en = "Knee-lever press (own check 54)"
designation = "ТММ.КП.54.700"

[sheet]
student = "Студент С. С."
teacher = "Викладач В. В."
group = "МБ-54"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.40, 0.30]

[frame.guides]
g = { through = [0.40, -0.30], angle_deg = 90, title_uk = "повзуна", title_en = "of the ram" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.06
rpm = 90
direction = "ccw"
points = { S1 = 0.0 }
mass = 8
inertia = 0.02

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.47
points = { S2 = 0.5 }
mass = 15
inertia = 0.3

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.30
points = { S3 = 0.5 }
mass = 10
inertia = 0.08

[[link]]
name = "BC"
number = 4
joints = ["B", "C"]
length = 0.30
points = { S4 = 0.5 }
mass = 10
inertia = 0.08

[[link]]
name = "C"
number = 5
joints = ["C"]
slides_on = "g"
mass = 40

[branch]
B = -1
C = -1

[positions]
count = 12
start = "max"
accel = [4]
force_phi_deg = 120
working_stroke = "to_min"
output = "C"

[loads]
g = 9.81

[[force]]
point = "C"
magnitude = 15000
stroke = "working"
direction = "oppose"
'''


GEARS54 = '''# Stop 54 (the lead's check): a pair 12/29 with a small pinion and shifts GIVEN by hand (x1 = 0.45,
# x2 = -0.15: an unequal, not-zero-sum pair), the pressure angle 20°, and a two-row planetary train of
# type B with its teeth GIVEN (z1 = 18, z2 = 36, z2' = 20, z3 = 74), 3 satellites, 960 rpm.
title = "Зубчаста передача 12/29 і дворядний планетарний редуктор (перевірка 54)"
title_en = "A gear pair 12/29 and a two-row planetary reducer (check 54)"
designation = "ТММ.ЗП.54.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-54"
organisation = "НУБіП України"

[gears]
z = [12, 29]
module = 0.005
shifts = [0.45, -0.15]

[planetary]
type = "B"
z = [18, 36, 20, 74]
planets = 3
module = 0.0025
rpm = 960
'''


GEARS_OWN54 = '''# Stop 54's own check (gears54): a pair of equal wheels 20/20 (u = 1) with equal positive shifts
# x1 = x2 = 0.3 given, m = 4 mm, and a one-row planetary train of type A with its teeth given
# (z = 22, 32, 86: u1H = 4.909), four planets, the sun at 1450 rpm.
title = "Зубчаста передача 20/20 з рівними зміщеннями і однорядний планетарний редуктор із заданими числами зубців (власна перевірка 54)"
title_en = "A gear pair 20/20 with equal shifts and a one-row planetary reducer with given teeth (own check 54)"
designation = "ТММ.ЗП.54.100"

[sheet]
student = "Студент С. С."
teacher = "Викладач В. В."
group = "МБ-54"
organisation = "НУБіП України"

[gears]
z = [20, 20]
module = 0.004
shifts = [0.3, 0.3]

[planetary]
type = "A"
z = [22, 32, 86]
planets = 4
module = 0.002
rpm = 1450
'''


CAM54 = '''# Stop 54 (the lead's check): a translating roller follower, the cam turning CLOCKWISE, the offset set
# NEGATIVE (to the side that raises the rise's pressure angle), a trapezoidal rise of 100° and a cycloidal
# return of 140° with a short far dwell of 20°, 10 divisions, R0 from the pressure-angle condition.
title = "Кулачковий механізм з поступальним роликовим штовхачем (перевірка 54)"
title_en = "Cam with a translating roller follower (check 54)"
designation = "ТММ.КМ.54.100"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-54"
organisation = "НУБіП України"

[cam]
follower = "translating"
stroke = 0.032
offset = -0.008
roller_radius = 0.008
phases_deg = { rise = 100, dwell_far = 20, return = 140, dwell_near = 100 }
laws = { rise = "trapezoidal", return = "cycloidal" }
pressure_angle_deg = { rise = 28, return = 35 }
rpm = 120
direction = "cw"
divisions = 10
'''


OWN_CAM54 = '''# Stop 54 (cam54's own look): a ROCKING KNIFE-EDGE follower turned by a CLOCKWISE cam, a trapezoidal rise
# of 90°, a far dwell of 30°, a parabolic return of 120°, a near dwell of 120°, 12 divisions.
title = "Кулачковий механізм з коромисловим загостреним штовхачем (власна перевірка 54)"
title_en = "Cam with a rocking knife-edge follower (own check 54)"
designation = "ТММ.КМ.54.200"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-54"
organisation = "НУБіП України"

[cam]
follower = "rocking"
swing_deg = 18
arm = 0.09
centre_distance = 0.11
phases_deg = { rise = 90, dwell_far = 30, return = 120, dwell_near = 120 }
laws = { rise = "trapezoidal", return = "parabolic" }
pressure_angle_deg = { rise = 40, return = 45 }
rpm = 90
direction = "cw"
divisions = 12
'''


CYLINDER_REVIEW54 = '''# Stop 54's blind review, scene 1 (review54's s1_cylinder.toml): a slider E driven through an oscillating
# cylinder; the sheet draws s, v, a mirrored (+ away from position 0, against the guide).
# Кривошипний механізм з коливним циліндром (гідроциліндр): кривошип OA, шток AD ковзає в циліндрі,
# що хитається навколо C; кінець штока D через шатун DE рухає повзун E вертикальною напрямною.
title = "Кривошипно-кулісний механізм з коливним циліндром"
title_en = "Crank mechanism with an oscillating cylinder"
designation = "ТММ.КП.54.000"

[sheet]
student = "Петренко І. В."
teacher = "Коваль О. М."
group = "МБ-31"
organisation = "НУБіП України"

[frame.points]
O = [0, 0]
C = [0.22, 0.05]

[frame.guides]
v = { through = [0.40, 0], angle_deg = 90, title_uk = "повзуна", title_en = "of the slider" }

[crank]
name = "OA"
pivot = "O"
pin = "A"
length = 0.07
rpm = 90
direction = "cw"
points = { S1 = 0.5 }
mass = 3
inertia = 0.004

[[link]]
name = "AD"          # шток, ковзає в циліндрі 3
number = 2
joints = ["A", "D"]
length = 0.38
points = { S2 = 0.5 }
mass = 6
inertia = 0.08

[[link]]
name = "3"           # циліндр, хитається навколо C
number = 3
joints = ["C"]
slides_on = "AD"
mass = 10
inertia = 0.05

[[link]]
name = "DE"
number = 4
joints = ["D", "E"]
length = 0.25
points = { S4 = 0.5 }
mass = 4
inertia = 0.025

[[link]]
name = "E"
number = 5
joints = ["E"]
slides_on = "v"
mass = 15

[branch]
E = 1

[positions]
count = 12
start = "max"
accel = [2]
force_phi_deg = 120

[loads]
g = 9.81

[[force]]
point = "E"
magnitude = 900
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.9
synchronous_rpm = 1500
'''


COUPLER_SLIDER_REVIEW54 = '''# Stop 54's blind review, scene 2 (review54's s2_coupler_slider.toml); mirrored diagrams too.
# A crank-rocker four-bar whose coupler point C drives a slider D on an offset horizontal guide
# through the rod CD (a six-bar: I(0-1) -> II(2-3) -> II(4-5)); press feed drive.
title = "Шестиланковий механізм подачі з шатунною точкою"
title_en = "Six-bar feed mechanism driven by a coupler point"
designation = "TMM.CP.54.000"
lang = "en"

[sheet]
student = "O. Hnatiuk"
teacher = "V. Melnyk"
group = "ME-32"
organisation = "NULES of Ukraine"

[frame.points]
O1 = [0, 0]
O2 = [0.26, -0.04]

[frame.guides]
feed = { through = [0, 0.22], angle_deg = 0, title_uk = "повзуна", title_en = "of the slider" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.06
rpm = 150
points = { S1 = 0.0 }
mass = 2.5
inertia = 0.003

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.22
shape = { C = [0.13, 0.09] }
points = { S2 = [0.11, 0.03] }
mass = 5
inertia = 0.03

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.16
points = { S3 = 0.5 }
mass = 3
inertia = 0.008

[[link]]
name = "CD"
number = 4
joints = ["C", "D"]
length = 0.27
points = { S4 = 0.5 }
mass = 3.5
inertia = 0.021

[[link]]
name = "D"
number = 5
joints = ["D"]
slides_on = "feed"
mass = 12

[branch]
B = 1
D = 1

[positions]
count = 12
start = "max"
accel = [3]
force_phi_deg = 90

[loads]
g = 9.81

[[force]]
point = "D"
magnitude = 650
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.03
efficiency = 0.95
synchronous_rpm = 1000
'''


GEARS11_53_54 = '''# Stop 54 (the blind reviewer's scene 4): a pair 11/53 — a large ratio, shifts "auto", m = 4 mm — and a
# one-row planetary train of type A, u1H = 5.5, K = 4.
title = "Зубчаста передача z1 = 11, z2 = 53 і планетарний редуктор"
title_en = "A gear pair 11/53 and a planetary reducer"
designation = "ТММ.КП.54.400"

[sheet]
student = "Бондар Т. С."
teacher = "Коваль О. М."
group = "МБ-31"
organisation = "НУБіП України"

[gears]
z = [11, 53]
module = 0.004
shifts = "auto"

[planetary]
type = "A"
ratio = 5.5
planets = 4
module = 0.0025
omega = 120.0
'''


COUPLER_SLIDER54 = COUPLER_SLIDER_REVIEW54.split('\n', 1)[1]     # the same scene, without its first comment line



CAM55 = '''# Stop 55 (the lead's check; cam55): a translating roller follower, the cam turning CLOCKWISE, the offset "auto",
# a parabolic rise of 150° straight into a LINEAR return of 90° (no far dwell: rigid shocks at the return's ends,
# corners on the centre profile), a near dwell of 120°, 8 divisions.
title = "Кулачковий механізм з поступальним роликовим штовхачем і лінійним поверненням (перевірка 55)"
title_en = "Cam with a translating roller follower and a linear return (check 55)"
designation = "ТММ.КМ.55.100"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-55"
organisation = "НУБіП України"

[cam]
follower = "translating"
stroke = 0.045
offset = "auto"
roller_radius = 0.01
phases_deg = { rise = 150, dwell_far = 0, return = 90, dwell_near = 120 }
laws = { rise = "parabolic", return = "linear" }
pressure_angle_deg = { rise = 30, return = 40 }
rpm = 90
direction = "cw"
divisions = 8
'''


OWN_CAM55 = '''# Stop 55 (cam55's own look): a ROCKING roller follower turned by a COUNTER-CLOCKWISE cam, a cosine rise of
# 110° (soft shocks at its ends), a far dwell of 30°, a cycloidal return of 120°, a near dwell of 100°, 10 divisions.
title = "Кулачковий механізм з коромисловим роликовим штовхачем (косинусоїдальний підйом, циклоїдальне опускання)"
title_en = "Cam with a rocking roller follower (cosine rise, cycloidal return)"
designation = "ТММ.КМ.55.200"

[sheet]
student = "Кулачковий К. К."
teacher = "Викладач В. В."
group = "МБ-55"
organisation = "НУБіП України"

[cam]
follower = "rocking"
swing_deg = 22
arm = 0.11
centre_distance = 0.13
roller_radius = 0.01
phases_deg = { rise = 110, dwell_far = 30, return = 120, dwell_near = 100 }
laws = { rise = "cosine", return = "cycloidal" }
pressure_angle_deg = { rise = 40, return = 40 }
rpm = 100
direction = "ccw"
divisions = 10
'''


# kin55: stop 55's new six-bar (the lead's /work/lead/s55/link55.toml), a crank-rocker whose rocker extension D
# swings a block in an oscillating slotted lever O3E pivoted at O3 (a link with one joint and its own points).



LINK55 = '''# Stop 55 (the lead's check): a six-bar whose crank-rocker four-bar O1ABO2 swings, through the rocker's
# extension D, a block in the slot of a second, oscillating slotted lever O3E (a dosing drive's shutter):
# I(0-1) -> II(2-3) ВВВ -> II(4-5) ВПВ; the crank turns clockwise; a resistance moment on the lever.
title = "Шестиланковий механізм привода дозатора з кулісою"
title_en = "Six-bar dosing drive with a slotted lever"
designation = "ТММ.КП.55.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-55"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.20, 0.04]
O3 = [0.30, 0.26]

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.05
rpm = 140
direction = "cw"
points = { S1 = 0.0 }
mass = 2
inertia = 0.004

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.18
points = { S2 = 0.5 }
mass = 3
inertia = 0.01

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.12
points = { D = 1.6, S3 = 0.6 }
mass = 4
inertia = 0.02

[[link]]
name = "D"
number = 4
joints = ["D"]
slides_on = "O3E"
mass = 1

[[link]]
name = "O3E"
number = 5
joints = ["O3"]
length = 0.30
points = { E = 1.0, S5 = 0.5 }
mass = 6
inertia = 0.06

[positions]
count = 12
start = "working"
accel = [4]
force_phi_deg = 120
output = "O3E"
working_stroke = "slow"

[loads]
g = 9.81

[[moment]]
link = 5
magnitude = 60
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.06
efficiency = 0.85
synchronous_rpm = 1000
'''


KIN55_DOSING = LINK55     # kin55's name for the lead's six-bar


# gears55: the lead's stop-55 check — a pair 14/56 with shifts "auto" (x = 0.65, 1.05), m = 6 mm, and a one-row
# train of type A chosen for u1H = 7.2 with K = 3 (17/43/103, −1.96 %; 20/52/124 gives 7.2 exactly), 1450 rpm.
GEARS55 = '''title = "Зубчаста передача 14/56 і однорядний планетарний редуктор (перевірка 55)"
title_en = "A gear pair 14/56 and a one-row planetary reducer (check 55)"
designation = "ТММ.ЗП.55.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-55"
organisation = "НУБіП України"

[gears]
z = [14, 56]
module = 0.006
shifts = "auto"

[planetary]
type = "A"
ratio = 7.2
planets = 3
module = 0.002
rpm = 1450
'''


# gears55's own check: a pair 16/44 with given unequal positive shifts 0.25/0.1, m = 4 mm, and a two-row
# train of type B chosen for u1H = 20 with K = 3 (17/64/20/101, +0.06 %; 18/72/24/114 gives 20 exactly), 960 rpm.
GEARS_OWN55 = '''title = "Зубчаста передача 16/44 і дворядний планетарний редуктор (власна перевірка 55)"
title_en = "A gear pair 16/44 and a two-row planetary reducer (own check 55)"
designation = "ТММ.ЗП.55.100"

[sheet]
student = "Студент С. С."
teacher = "Викладач В. В."
group = "МБ-55"
organisation = "НУБіП України"

[gears]
z = [16, 44]
module = 0.004
shifts = [0.25, 0.1]

[planetary]
type = "B"
ratio = 20
planets = 3
module = 0.002
rpm = 960
'''


# frc55b: review 55's beam pump (its scene a): the A1 force sheet drew the scheme and the groups at 1:10
# beside ~180 x 85 mm blank where its A2 set draws them at 1:2 (review 55 #1)
BEAM_PUMP55 = r"""
# review55 (a): a beam (walking-beam) pump drive: crank-rocker four-bar O1ABO2 whose balancer O2 sits
# between its pins B and C (a lever of the first kind); C drives the rod CD to the vertical plunger D.
# I(0-1) -> II(2-3) ВВВ -> II(4-5) ВВП; resistance force on the plunger's upward (delivery) stroke.
title = "Балансирний механізм привода поршневого насоса"
title_en = "Walking-beam drive of a reciprocating pump"
designation = "ТММ.КП.77.000"
lang = "uk"

[sheet]
student = "Рецензент Р. Р."
teacher = "Викладач В. В."
group = "МБ-77"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [-0.25, 0.35]

[frame.guides]
pl = { through = [-0.50, 0], angle_deg = 90, title_uk = "плунжера", title_en = "of the plunger" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.07
rpm = 120
direction = "ccw"
points = { S1 = 0.0 }
mass = 3
inertia = 0.006

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.36
points = { S2 = 0.5 }
mass = 5
inertia = 0.055

[[link]]
name = "BC"
number = 3
joints = ["B", "O2"]
length = 0.20
points = { C = 2.25, S3 = 1.0 }
mass = 8
inertia = 0.12

[[link]]
name = "CD"
number = 4
joints = ["C", "D"]
length = 0.30
points = { S4 = 0.5 }
mass = 4
inertia = 0.03

[[link]]
name = "D"
number = 5
joints = ["D"]
slides_on = "pl"
mass = 10

[branch]
B = -1
D = -1

[positions]
count = 12
start = "min"
working_stroke = "to_max"
accel = [2]
force_phi_deg = 60

[loads]
g = 9.81

[[force]]
point = "D"
magnitude = 1800
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.9
synchronous_rpm = 1500
"""
# (kin55b's check of review 55 #3 uses the same scene: the stroke drawn 44 mm high in an 85-mm band)


# Stop 56: the blind reviewer's toggle press of stop 56: a 12 kN pressing force over the last 14 mm of the down stroke (profile), crank clockwise, 1000-rpm motor
TOGGLE_PRESS56 = """
# review56 (a): a knee-lever (toggle) press: crank O1A drives the rod AB to the knee B, where the upper
# toggle lever O2B and the lower toggle rod BC meet (B a joint of three links); C the ram on a VERTICAL
# guide under O2. I(0-1) -> II(2-3) ВВВ -> II(4-5) ВВП; the crank turns CLOCKWISE; the pressing force acts
# only over the last 14 mm of the ram's downward (working) stroke (a profile), with [dynamics].
title = "Колінно-важільний механізм преса"
title_en = "Knee-lever (toggle) press mechanism"
designation = "ТММ.КП.56.200"

[sheet]
student = "Рецензент Р. Р."
teacher = "Викладач В. В."
group = "МБ-56"
organisation = "НУБіП України"

[frame.points]
O1 = [0.28, 0.22]      # crank pivot
O2 = [0, 0.40]         # upper toggle pivot

[frame.guides]
ram = { through = [0, 0], angle_deg = 90, title_uk = "повзуна", title_en = "of the ram" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.04
rpm = 90
direction = "cw"
points = { S1 = 0.0 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.23
points = { S2 = 0.5 }

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.20
points = { S3 = 0.5 }

[[link]]
name = "BC"
number = 4
joints = ["B", "C"]
length = 0.20
points = { S4 = 0.5 }

[[link]]
name = "C"
number = 5
joints = ["C"]
slides_on = "ram"
mass = 40

[branch]
B = 1
C = -1

[positions]
count = 12
start = "max"              # position 0: the ram at its top
working_stroke = "to_min"  # pressing on the way down
accel = [4]
force_phi_deg = 150
output = "C"

[loads]
g = 9.81
mass_per_length = 40
inertia_factor = 0.1

[[force]]
point = "C"
magnitude = 12000
stroke = "working"
direction = "oppose"
profile = [[0, 0], [0.026, 0], [0.030, 1], [0.06, 1]]

[dynamics]
delta = 0.05
efficiency = 0.85
synchronous_rpm = 1000
"""

# Stop 56: the blind reviewer's oscillating slotted lever of stop 56, in English, a 45 N·m resistance moment, dynamics
SLOTTED_LEVER_EN56 = """
# review56 (b): an oscillating slotted-lever (кулісний) four-link mechanism, in English: the crank O1A
# carries a block A sliding in the slot of the lever O2E that swings about O2 below it (a loom's beater /
# a feed pawl's lever). I(0-1) -> II(2-3) RPR; crank counter-clockwise; a resistance moment of 45 N·m on
# the lever's working (slow) swing, masses by length plus the block's own, and [dynamics].
title = "Кулісний механізм з коливною кулісою"
title_en = "Oscillating slotted-lever mechanism of a beater"
designation = "TMM.CW.56.300"
lang = "en"

[sheet]
student = "Reviewer R."
teacher = "Teacher T."
group = "MB-56"
organisation = "NULES of Ukraine"

[frame.points]
O2 = [0, 0]
O1 = [0, 0.15]

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.08
rpm = 100
direction = "ccw"
points = { S1 = 0.5 }

[[link]]
name = "2"
number = 2
joints = ["A"]
slides_on = "O2E"
mass = 1.5

[[link]]
name = "O2E"
number = 3
joints = ["O2"]
length = 0.32
points = { E = 1.0, S3 = 0.5 }

[positions]
count = 12
start = "working"
accel = [2, 8]
force_phi_deg = 60
output = "O2E"

[loads]
g = 9.81
mass_per_length = 25
inertia_factor = 0.1

[[moment]]
link = 3
magnitude = 45
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.03
efficiency = 0.9
synchronous_rpm = 1500
"""

# Stop 56: the blind reviewer's translating knife-edge cam of stop 56: e = 6 mm, given R0 = 48 mm, cam clockwise, trapezoidal/cosine
KNIFE_CAM56 = """
# review56 (c): a translating KNIFE-EDGE follower with a given offset e = 6 mm and a given base radius, the
# cam turning CLOCKWISE; trapezoidal-acceleration rise of 110°, far dwell 40°, cosine return 90°,
# near dwell 120°; [ϑ] 30° on the rise and 35° on the return; 10 divisions.
title = "Кулачковий механізм з поступальним загостреним штовхачем (рецензія 56)"
title_en = "Disc cam with an offset translating knife-edge follower (review 56)"
designation = "ТММ.КМ.56.500"

[sheet]
student = "Рецензент Р. Р."
teacher = "Викладач В. В."
group = "МБ-56"
organisation = "НУБіП України"

[cam]
follower = "translating"
stroke = 0.032
offset = 0.006
roller_radius = 0
phases_deg = { rise = 110, dwell_far = 40, return = 90, dwell_near = 120 }
laws = { rise = "trapezoidal", return = "cosine" }
pressure_angle_deg = { rise = 30, return = 35 }
rpm = 200
direction = "cw"
base_radius = 0.048
divisions = 10
"""

# Stop 56: the blind reviewer's 13/22 pair with given shifts and a type-A train with given teeth 18/27/72 (stop 56)
GEARS_REVIEW56 = """
# review56 (d): a pair 13/22 with GIVEN shifts x1 = 0.35, x2 = 0.25, m = 4 mm, and a one-row planetary train
# of type A with GIVEN teeth 18/27/72 (u1H = 5), K = 3 planets, 1440 rpm.
title = "Зубчаста передача 13/22 із заданими зміщеннями і однорядний планетарний редуктор (рецензія 56)"
title_en = "A gear pair 13/22 with given shifts and a one-row planetary reducer (review 56)"
designation = "ТММ.ЗП.56.600"

[sheet]
student = "Рецензент Р. Р."
teacher = "Викладач В. В."
group = "МБ-56"
organisation = "НУБіП України"

[gears]
z = [13, 22]
module = 0.004
shifts = [0.35, 0.25]

[planetary]
type = "A"
z = [18, 27, 72]
planets = 3
module = 0.003
rpm = 1440
"""


# kin56's (stop 56): review 55's Stephenson III six-bar feeder, whose English kinematics sheet lettered «n₄» 1.6 mm
# over «n₂, a» in position 9's acceleration plan (read as one word without the font: labels.APART 2.0 mm)
KIN56_STEPHENSON = '''# review55 (b): a Stephenson III six-bar of a feeder: crank-rocker four-bar O1ABO2 whose coupler plate
# ABC carries C off the line AB; C drives the rod CD to the output rocker O3D (I(0-1) -> II(2-3) RRR ->
# II(4-5) RRR); the crank turns clockwise; a resistance moment on the output rocker's working swing.
title = "Шестиланковий механізм подавача з шатунною точкою і коромислом"
title_en = "Stephenson six-bar feeder: a coupler point driving an output rocker"
designation = "TMM.CP.78.000"
lang = "en"

[sheet]
student = "Reviewer R. R."
teacher = "Teacher T. T."
group = "MB-78"
organisation = "NUBiP of Ukraine"

[frame.points]
O1 = [0, 0]
O2 = [0.30, -0.05]
O3 = [0.05, 0.38]

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.06
rpm = 180
direction = "cw"
points = { S1 = 0.5 }

[[link]]
name = "ABC"
number = 2
joints = ["A", "B"]
length = 0.28
shape = { C = [0.14, 0.10] }
points = { S2 = [0.14, 0.035] }

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.20
points = { S3 = 0.5 }

[[link]]
name = "CD"
number = 4
joints = ["C", "D"]
length = 0.26
points = { S4 = 0.5 }

[[link]]
name = "O3D"
number = 5
joints = ["O3", "D"]
length = 0.18
points = { S5 = 0.5 }

[positions]
count = 12
start = "working"
accel = [3, 9]
force_phi_deg = 150
output = "O3D"

[loads]
g = 9.81
mass_per_length = 25
inertia_factor = 0.1

[[moment]]
link = 5
magnitude = 45
stroke = "working"
direction = "oppose"
'''

# kin56's own (stop 56): a windscreen-wiper crank-rocker four-bar, the rocker's arm O2C swinging 71.7°
KIN56_WIPER = '''# Stop 56 (kin56's own): a windscreen-wiper drive — a crank-rocker four-bar O1ABO2 (Grashof, the crank
# the shortest link) whose rocker O2B swings the wiper arm O2C; a motor crank at 60 rpm, counter-clockwise.
title = "Чотириланковий механізм привода склоочисника"
title_en = "Windscreen-wiper four-bar drive"
designation = "ТММ.КП.56.100"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-56"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.16, 0.06]

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.04
rpm = 60
points = { S1 = 0.0 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.15
points = { S2 = 0.5 }

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.07
points = { C = -1.5, S3 = 0.0 }

[positions]
count = 12
start = "working"
accel = [2, 8]
output = "O2B"
'''


# frc56: the lead's stop-56 six-bar (a crank-rocker whose rocker point C drives a rod CD and a slider D on a guide at 30°), on which the hodographs' numbers were checked
FRC56_PUSHER = '''# Stop 56 (the lead's check): a six-bar whose crank-rocker four-bar O1ABO2 swings, through the rocker's
# point C, a connecting rod CD and a slider D on a guide INCLINED at 30° (a charging conveyor's pusher):
# I(0-1) -> II(2-3) ВВВ -> II(4-5) ВВП; the crank turns clockwise; a pushing resistance on the slider.
title = "Шестиланковий механізм штовхача з похилою напрямною"
title_en = "Six-bar pusher drive with an inclined guide"
designation = "ТММ.КП.56.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-56"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.25, 0.0]

[frame.guides]
slide = { through = [0.45, 0.05], angle_deg = 30, title_uk = "штовхача", title_en = "of the pusher" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.06
rpm = 120
direction = "cw"
points = { S1 = 0.0 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.22
points = { S2 = 0.5 }

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.15
points = { C = 0.7, S3 = 0.5 }

[[link]]
name = "CD"
number = 4
joints = ["C", "D"]
length = 0.25
points = { S4 = 0.5 }

[[link]]
name = "D"
number = 5
joints = ["D"]
slides_on = "slide"
mass = 15

[positions]
count = 12
start = "working"
accel = [3]
force_phi_deg = 100
output = "D"

[loads]
g = 9.81
mass_per_length = 20
inertia_factor = 0.1

[[force]]
point = "D"
magnitude = 2000
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.04
efficiency = 0.8
synchronous_rpm = 1500
'''

# frc56: own textbook mechanism — a two-plunger pump (central crank-slider, its rod's midpoint C driving a rod CD and a vertical plunger D); forces sheet judged at φ = 60°, M_зр 48.038 N·m checked by virtual power
FRC56_PUMP = '''# frc56's own: a two-plunger pump — a central crank-slider O1AB with a horizontal plunger B, whose
# connecting rod's point C drives a rod CD and a second, vertical plunger D (I(0-1) -> II(2-3) ВВП -> II(4-5) ВВП)
title = "Двоплунжерний насос з кривошипно-повзунним приводом"
title_en = "Two-plunger pump with a crank-slider drive"
designation = "ТММ.КП.56.001"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-56"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]

[frame.guides]
horiz = { through = [0.0, 0.0], angle_deg = 0, title_uk = "плунжера 3", title_en = "of plunger 3" }
vert = { through = [0.12, 0.0], angle_deg = 90, title_uk = "плунжера 5", title_en = "of plunger 5" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.05
rpm = 200
direction = "ccw"
points = { S1 = 0.0 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.20
points = { S2 = 0.35, C = 0.5 }

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "horiz"
mass = 4

[[link]]
name = "CD"
number = 4
joints = ["C", "D"]
length = 0.15
points = { S4 = 0.5 }

[[link]]
name = "D"
number = 5
joints = ["D"]
slides_on = "vert"
mass = 3

[positions]
count = 12
start = "working"
force_phi_deg = 60
output = "B"

[loads]
g = 9.81
mass_per_length = 25
inertia_factor = 0.1

[[force]]
point = "B"
magnitude = 800
stroke = "working"
direction = "oppose"

[[force]]
point = "D"
magnitude = 400
stroke = "working"
direction = "oppose"
'''


# gears56: the lead's stop-56 check — a pair 10/31 "auto" (a 10-tooth pinion shifted against undercut),
# m = 5 mm, and a two-row type-B train chosen for u1H = 11, K = 3, 960 rpm
GEARS56 = '''title = "Зубчаста передача 10/31 і дворядний планетарний редуктор (перевірка 56)"
title_en = "A gear pair 10/31 and a two-row planetary reducer (check 56)"
designation = "ТММ.ЗП.56.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-56"
organisation = "НУБіП України"

[gears]
z = [10, 31]
module = 0.005
shifts = "auto"

[planetary]
type = "B"
ratio = 11
planets = 3
module = 0.0025
rpm = 960
'''


# gears56's own: a textbook reducer stage — a pair 13/27 "auto", m = 6 mm, and a one-row type-A train
# for u1H = 5,6 with K = 4 planets (the neighbourhood tight: 36,77 > 35), 1440 rpm
GEARS_OWN56 = '''title = "Зубчаста передача 13/27 і однорядний планетарний редуктор (власна перевірка 56)"
title_en = "A gear pair 13/27 and a one-row planetary reducer (own check 56)"
designation = "ТММ.ЗП.56.100"

[sheet]
student = "Студент С. С."
teacher = "Викладач В. В."
group = "МБ-56"
organisation = "НУБіП України"

[gears]
z = [13, 27]
module = 0.006
shifts = "auto"

[planetary]
type = "A"
ratio = 5.6
planets = 4
module = 0.003
rpm = 1440
'''


# dyn56's own check (stop 56): the textbook frame saw — an upright centred crank-slider whose saw frame (150 kg) cuts on
# its stroke down and is lifted against its weight; 1000-rpm motor, δ = 1/30. Its dynamics sheet (A1) is sent back:
# J = 267.7 kg·m² ≫ I*_m ≤ 19.5, so the energy–mass diagram's tangents stand at 78° and |kl| = 211.5 mm runs far
# below a small curve; a 197 × 433 mm blank beside the band (report_dyn56.md).
SAW_DYN56 = '''title = "Кривошипно-повзунний механізм лісопильної рами"
title_en = "Crank-slider mechanism of a frame saw"
designation = "ТММ.КП.56.300"

[sheet]
student = "Студент С. С."
teacher = "Викладач В. В."
group = "МБ-56"
organisation = "НУБіП України"

[frame.points]
O = [0, 0]

[frame.guides]
frame = { through = [0, 0], angle_deg = 90, title_uk = "пильної рамки", title_en = "of the saw frame" }

[crank]
name = "OA"
pivot = "O"
pin = "A"
length = 0.3
rpm = 200
direction = "ccw"
points = { S1 = 0.0 }
mass = 40
inertia = 0.6

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 1.5
points = { S2 = 0.4 }
mass = 60
inertia = 11.25

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "frame"
mass = 150

[branch]
B = 1

[positions]
count = 12
start = "max"
working_stroke = "to_min"
accel = [2]
force_phi_deg = 60

[loads]
g = 9.81

[[force]]
point = "B"
magnitude = 2000
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.0333
efficiency = 0.85
synchronous_rpm = 1000
'''

# dyn56 (stop 56): the lead's LINK56 (/work/lead/s56/link56.toml) as dyn56 checked its dynamics sheet — a six-bar
# pusher with a 30° guide; I*_m, M*_c, ΔT, the flywheel (16.016 kg·m²) and the motor's steady state (ω_m = 13.027,
# δ = 0.0392) equal an independent integration of the equation of motion (dyn56-scratch/indep56.py).
LINK_DYN56 = FRC56_PUSHER   # the same scene (the lead's link56.toml), added by frc56 first


CAM56 = '''# Stop 56 (the lead's check, cam56's look): a ROCKING roller follower, the cam counter-clockwise, a parabolic
# rise of 120° into a far dwell of 30°, a cycloidal return of 110°, a near dwell of 100°, 9 divisions
# (/work/lead/s56/cam56.toml).
title = "Кулачковий механізм з коромисловим роликовим штовхачем (перевірка 56)"
title_en = "Cam with a rocking roller follower (check 56)"
designation = "ТММ.КМ.56.100"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-56"
organisation = "НУБіП України"

[cam]
follower = "rocking"
swing_deg = 24
arm = 0.11
centre_distance = 0.14
roller_radius = 0.009
phases_deg = { rise = 120, dwell_far = 30, return = 110, dwell_near = 100 }
laws = { rise = "parabolic", return = "cycloidal" }
pressure_angle_deg = { rise = 40, return = 45 }
rpm = 150
direction = "ccw"
divisions = 9
'''

OWN_CAM56 = '''# Stop 56 (cam56's own look): the textbook's symmetric cam — a CENTRAL translating roller follower (e = 0),
# the cam clockwise, a cosine rise of 120°, a far dwell of 60°, a cosine return of 120°, a near dwell of
# 60°, 8 divisions.
title = "Кулачковий механізм з центральним роликовим штовхачем (власний 56)"
title_en = "Cam with a central translating roller follower (own 56)"
designation = "ТММ.КМ.56.200"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-56"
organisation = "НУБіП України"

[cam]
follower = "translating"
stroke = 0.03
offset = 0
roller_radius = 0.008
phases_deg = { rise = 120, dwell_far = 60, return = 120, dwell_near = 60 }
laws = { rise = "cosine", return = "cosine" }
pressure_angle_deg = { rise = 30, return = 30 }
rpm = 120
direction = "cw"
divisions = 8
'''


# misc56: the lead's stop-56 six-bar (/work/lead/s56/link56.toml): a crank-rocker four-bar whose rocker point C
# drives a rod CD and a slider D on a guide inclined at 30°, crank clockwise — the explorer and the page on it
MISC56 = FRC56_PUSHER   # misc56 checked the same scene (the lead's link56.toml) in serve and the explorer


# frc57: the lead's stop-57 six-bar (/work/lead/s57/link57.toml): an offset crank-slider whose triangular rod
# ABC swings a rocker O3D through CD; 70 N·m on the rocker's working swing, 300 N on the slider both strokes
LINK57 = '''# Stop 57 (the lead's check): an offset crank-slider O1AB whose triangular connecting rod ABC swings,
# through the rod's point C, a link CD and a rocker O3D (a kneading machine's arm):
# I(0-1) -> II(2-3) ВВП (offset) -> II(4-5) ВВВ; the crank turns counter-clockwise; a resistance
# moment on the rocker over its working swing and a force on the slider.
title = "Шестиланковий механізм місильної машини"
title_en = "Six-bar drive of a kneading machine"
designation = "ТММ.КП.57.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-57"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O3 = [0.26, 0.24]

[frame.guides]
x = { through = [0, -0.025], angle_deg = 0, title_uk = "повзуна", title_en = "of the slider" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.07
rpm = 160
direction = "ccw"
points = { S1 = 0.0 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.28
shape = { C = [0.14, 0.09] }
points = { S2 = [0.14, 0.03] }

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "x"
mass = 4

[[link]]
name = "CD"
number = 4
joints = ["C", "D"]
length = 0.17
points = { S4 = 0.5 }

[[link]]
name = "O3D"
number = 5
joints = ["O3", "D"]
length = 0.13
points = { S5 = 0.5 }

[positions]
count = 12
start = "working"
accel = [4]
force_phi_deg = 130
output = "O3D"

[loads]
g = 9.81
mass_per_length = 25
inertia_factor = 0.1

[[moment]]
link = 5
magnitude = 70
stroke = "working"
direction = "oppose"

[[force]]
point = "B"
magnitude = 300
stroke = "both"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.85
synchronous_rpm = 1000
'''


# cam57: the lead's stop-57 cam (/work/lead/s57/cam57.toml): a translating roller follower, offset "auto", the cam
# clockwise, a trapezoidal rise of 100°, a far dwell of 40°, a cosine return of 130°, 8 divisions, [ϑ] 30°/40°
CAM57 = """title = "Кулачковий механізм з поступальним роликовим штовхачем (перевірка 57)"
title_en = "Cam with a translating roller follower (check 57)"
designation = "ТММ.КМ.57.100"
[cam]
follower = "translating"
stroke = 0.032
offset = "auto"
roller_radius = 0.008
phases_deg = { rise = 100, dwell_far = 40, return = 130, dwell_near = 90 }
laws = { rise = "trapezoidal", return = "cosine" }
pressure_angle_deg = { rise = 30, return = 40 }
rpm = 200
direction = "cw"
divisions = 8
"""

# cam57: the blind reviewer's stop-57 cam (/work/wt/review57-scratch/c_cam.toml): e = +8 mm and R0 = 50 mm GIVEN,
# below the smallest 50.4 mm (ϑ_max 25.14° > [ϑ] 25°), the cam clockwise, parabolic rise 90°, cycloidal return 110°
CAM57_SMALL_R0 = """title = "Кулачковий механізм з дезаксіальним роликовим штовхачем (рецензія 57)"
title_en = "Disc cam with an offset translating roller follower (review 57)"
designation = "ТММ.КМ.57.500"
[cam]
follower = "translating"
stroke = 0.03
offset = 0.008
base_radius = 0.05
roller_radius = 0.01
phases_deg = { rise = 90, dwell_far = 60, return = 110, dwell_near = 100 }
laws = { rise = "parabolic", return = "cycloidal" }
pressure_angle_deg = { rise = 25, return = 35 }
rpm = 150
direction = "cw"
divisions = 9
"""


# gears57 (stop 57): the lead's check, /work/lead/s57/gears57.toml — a pair 14/25 with GIVEN shifts 0.3/0.1,
# m = 6 mm, and a single-row type-A train chosen for u1H = 5.5, K = 4, 1450 rpm.
GEARS57 = '''title = "Зубчаста передача 14/25 і однорядний планетарний редуктор (перевірка 57)"
title_en = "A gear pair 14/25 and a single-row planetary reducer (check 57)"
designation = "ТММ.ЗП.57.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-57"
organisation = "НУБіП України"

[gears]
z = [14, 25]
module = 0.006
shifts = [0.3, 0.1]

[planetary]
type = "A"
ratio = 5.5
planets = 4
module = 0.003
rpm = 1450
'''


# Stop 57, the blind reviewer's (b): an English crank-rocker four-bar of a walking-beam conveyor, its coupler
# plate ABE carrying the pusher's point E off AB (600 N at E on the slow swing); its check in test_review57.
CONVEYOR_EN57 = '''# review57 (b): in ENGLISH, a crank-rocker four-bar of a walking-beam conveyor: the crank O1A turns CLOCKWISE,
# the coupler plate ABE carries the pusher's point E off the line AB; a 600 N resistance force at E on the
# rocker's working (slow) swing, opposing E's motion; masses by length, and [dynamics].
title = "Шарнірний чотириланковий механізм крокуючого конвеєра"
title_en = "Crank-rocker four-bar of a walking-beam conveyor"
designation = "TMM.KP.57.800"
lang = "en"

[sheet]
student = "Reviewer R. R."
teacher = "Teacher T. T."
group = "MB-57"
organisation = "NULES of Ukraine"

[frame.points]
O1 = [0, 0]
O2 = [0.32, -0.06]

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.09
rpm = 75
direction = "cw"
points = { S1 = 0.5 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.30
points = { S2 = [0.15, 0.03], E = [0.16, 0.09] }

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.22
points = { S3 = 0.5 }

[branch]
B = 1

[positions]
count = 12
start = "working"
accel = [3]
force_phi_deg = 100

[loads]
g = 9.81
mass_per_length = 30
inertia_factor = 0.1

[[force]]
point = "E"
magnitude = 600
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.04
efficiency = 0.92
synchronous_rpm = 1500
'''

# Stop 57, the blind reviewer's (d): a pair 15/28 "auto" and a type-B train with given teeth 17/40/20/77.
GEARS_REVIEW57 = '''# review57 (d): a pair 15/28 with the shifts chosen by the rule ("auto"), m = 5 mm, and a two-row planetary
# train of type B with GIVEN teeth 17/40/20/77 (u1H = 1 + 40·77/(17·20) = 10.0588), K = 3, 960 rpm.
title = "Зубчаста передача 15/28 і дворядний планетарний редуктор (рецензія 57)"
title_en = "A gear pair 15/28 and a two-row planetary reducer (review 57)"
designation = "ТММ.ЗП.57.600"

[sheet]
student = "Рецензент Р. Р."
teacher = "Викладач В. В."
group = "МБ-57"
organisation = "НУБіП України"

[gears]
z = [15, 28]
module = 0.005
shifts = "auto"

[planetary]
type = "B"
z = [17, 40, 20, 77]
planets = 3
module = 0.0025
rpm = 960
'''


# Stop 57, the blind reviewer's scene a: a Scotch yoke whose rod end C (its joint, off the slot) drives a rocker O3E (test_yoke57)
YOKE_REVIEW57 = '''
# review57 (a): a Scotch-yoke drive of a rocker (a pump's beam): the crank OA turns CLOCKWISE, its block 2 at A
# slides in the vertical slot of the yoke 3, which runs on a horizontal guide through O; the yoke's rod end C (on the guide line)
# drives, through the rod CE, the rocker O3E. I(0-1) -> II(2-3) RPP -> II(4-5) RRR; a 40 N·m resistance moment
# on the rocker's working (slow) swing, masses by length, the yoke 6 kg, and [dynamics].
title = "Кулісний (синусний) механізм привода коромисла насоса"
title_en = "Scotch-yoke drive of a pump's rocker"
designation = "ТММ.КП.57.700"

[sheet]
student = "Рецензент Р. Р."
teacher = "Викладач В. В."
group = "МБ-57"
organisation = "НУБіП України"

[frame.points]
O = [0, 0]
O3 = [0.50, 0.20]

[frame.guides]
x = { through = [0, 0], angle_deg = 0, title_uk = "куліси", title_en = "of the yoke" }

[crank]
name = "OA"
pivot = "O"
pin = "A"
length = 0.08
rpm = 90
direction = "cw"
points = { S1 = 0.5 }

[[link]]
name = "2"
number = 2
joints = ["A"]
slides_on = "3"
mass = 1.5
inertia = 0.0005

[[link]]
name = "3"
number = 3
joints = ["C"]
slides_on = "x"
guide = { through = [-0.25, 0], angle_deg = 90 }
points = { S3 = [-0.11, 0.0] }
mass = 6
inertia = 0.04

[[link]]
name = "CE"
number = 4
joints = ["C", "E"]
length = 0.25
points = { S4 = 0.5 }

[[link]]
name = "O3E"
number = 5
joints = ["O3", "E"]
length = 0.18
points = { S5 = 0.5 }

[branch]
E = -1

[positions]
count = 12
start = "working"
working_stroke = "to_max"
output = "O3E"
accel = [2, 8]
force_phi_deg = 120

[loads]
g = 9.81
mass_per_length = 20
inertia_factor = 0.1

[[moment]]
link = "O3E"
magnitude = 40
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.9
synchronous_rpm = 1000
'''


# kin57 checked the same scene (the lead's link57.toml) on the kinematics sheet (issue 32 #2: ω5 small past 5 % at 1
# and 7); LINK57 above is the text


# dyn57: the lead's stop-57 six-bar (/work/lead/s57/link57.toml): an offset crank-slider whose triangular rod swings a
# rocker through a link; 70 N·m on the rocker's working swing, 300 N on the slider; dynamics to a 1000-rpm motor
LINK_DYN57 = LINK57   # the same scene (the lead's link57.toml), checked by dyn57


# Stop 58: the lead's stop-58 V-twin compressor: one crank, two groups on the crank pin, pistons at 60° and 120° (/work/lead/s58/link58.toml)
LINK58 = '''# Stop 58 (the lead's check): a V-twin compressor: one crank O1A drives two connecting rods AB and AC
# (both pinned at the crank pin A) and two pistons B and C on guides through O1 at 60° and 120° (a 60° V):
# I(0-1) -> II(2-3) ВВП -> II(4-5) ВВП; the crank turns clockwise; the gas forces act on the pistons'
# compression strokes (outwards, towards the cylinder heads: working_stroke = "to_max"); masses by length;
# dynamics to a 1500-rpm motor, δ = 1/40.
title = "V-подібний двоциліндровий компресор"
title_en = "V-twin compressor"
designation = "ТММ.КП.58.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-58"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]

[frame.guides]
x = { through = [0, 0], angle_deg = 60, title_uk = "правого циліндра", title_en = "of the right cylinder" }
y = { through = [0, 0], angle_deg = 120, title_uk = "лівого циліндра", title_en = "of the left cylinder" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.05
rpm = 720
direction = "cw"
points = { S1 = 0.0 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.2
points = { S2 = 0.35 }

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "x"
mass = 2.5

[[link]]
name = "AC"
number = 4
joints = ["A", "C"]
length = 0.2
points = { S4 = 0.35 }

[[link]]
name = "C"
number = 5
joints = ["C"]
slides_on = "y"
mass = 2.5

[positions]
count = 12
start = "working"
working_stroke = "to_max"
accel = [3]
force_phi_deg = 45
output = "B"

[loads]
g = 9.81
mass_per_length = 20
inertia_factor = 0.1

[[force]]
point = "B"
magnitude = 900
stroke = "working"
direction = "oppose"

[[force]]
point = "C"
magnitude = 900
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.025
efficiency = 0.8
synchronous_rpm = 1500
'''


# Stop 58: the lead's stop-58 cam: a rocking roller follower, ccw, no far dwell (trapezoidal rise 150°, cycloidal return 150°) (/work/lead/s58/cam58.toml)
CAM58 = '''# Stop 58 (the lead's check): a ROCKING roller follower, the cam counter-clockwise, NO far dwell: a
# trapezoidal rise of 150° straight into a cycloidal return of 150°, a near dwell of 60°; a swing of 25°,
# 10 divisions, [ϑ] 40°/45°.
title = "Кулачковий механізм з коромисловим роликовим штовхачем (перевірка 58)"
title_en = "Cam with a rocking roller follower (check 58)"
designation = "ТММ.КМ.58.100"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-58"
organisation = "НУБіП України"

[cam]
follower = "rocking"
swing_deg = 25
arm = 0.09
centre_distance = 0.11
roller_radius = 0.01
phases_deg = { rise = 150, dwell_far = 0, return = 150, dwell_near = 60 }
laws = { rise = "trapezoidal", return = "cycloidal" }
pressure_angle_deg = { rise = 40, return = 45 }
rpm = 150
direction = "ccw"
divisions = 10
'''


# Stop 58: the lead's stop-58 gears: a pair 9/35 "auto", m = 4 mm, and a type-B train for u1H = 14, K = 3 (/work/lead/s58/gears58.toml)
GEARS58 = '''# Stop 58 (the lead's check): a pair 9/35 "auto" (a 9-tooth pinion: a large shift against undercut, the
# tip's thickness to check), m = 4 mm, and a two-row type-B train chosen for u1H = 14, K = 3, 1450 rpm.
title = "Зубчаста передача 9/35 і дворядний планетарний редуктор (перевірка 58)"
title_en = "A gear pair 9/35 and a two-row planetary reducer (check 58)"
designation = "ТММ.ЗП.58.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-58"
organisation = "НУБіП України"

[gears]
z = [9, 35]
module = 0.004
shifts = "auto"

[planetary]
type = "B"
ratio = 14
planets = 3
module = 0.003
rpm = 1450
'''


# Stop 58, the blind reviewer's (a): a crank-rocker whose rocker's extension C carries a block 4 (J = 0.001) in the slot of
# a slotted lever O3E (RPR): the block's inertia couple on the Zhukovsky lever (test_lever_block58)
COULISSE_REVIEW58 = '''# review58 (a): a six-bar of a swinging feeder: the crank-rocker four-bar O1A-AB-O2B (crank CLOCKWISE) whose rocker's
# extension carries at C a sliding block 4 in the slot of a second rocker (slotted lever) O3E:
# I(0-1) -> II(2-3) ВВВ -> II(4-5) ВПВ (RPR, coulisse); a 60 N·m resistance moment on the slotted lever over its
# working (slow) swing, masses by length, the block 2 kg, and [dynamics].
title = "Шестиланковий механізм живильника з кулісою"
title_en = "Six-bar feeder drive with a slotted lever"
designation = "ТММ.КП.58.100"

[sheet]
student = "Рецензент Р. Р."
teacher = "Викладач В. В."
group = "МБ-58"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.32, 0.0]
O3 = [0.10, 0.50]

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.08
rpm = 90
direction = "cw"
points = { S1 = 0.5 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.30
points = { S2 = 0.5 }

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.22
shape = { C = [0.34, 0.0] }
points = { S3 = 0.5 }

[[link]]
name = "4"
number = 4
joints = ["C"]
slides_on = "O3E"
mass = 2
inertia = 0.001

[[link]]
name = "O3E"
number = 5
joints = ["O3"]
length = 0.50
points = { E = 1.0, S5 = 0.5 }

[branch]
B = 1

[positions]
count = 12
start = "working"
output = "O3E"
accel = [2, 7]
force_phi_deg = 75

[loads]
g = 9.81
mass_per_length = 20
inertia_factor = 0.1

[[moment]]
link = "O3E"
magnitude = 60
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.04
efficiency = 0.9
synchronous_rpm = 1000
'''


# gears58's own (stop 58): a textbook pair 12/18 "auto" with a large module (10 mm) and the classic one-row
# type-A reducer 24/24/72 given by its teeth (u1H = 4, K = 3; the ring under the lab's 85 teeth, flagged)
GEARS_OWN58 = '''# gears58's own (stop 58): a textbook pair 12/18 with shifts "auto" and a large module (10 mm: a small
# ratio 1,5 with a pinion under 17 teeth), and the classic one-row type-A reducer 24/24/72 (u1H = 4, K = 3)
# given by its teeth, 1500 rpm.
title = "Зубчаста передача 12/18 і однорядний планетарний редуктор 24/24/72"
title_en = "A gear pair 12/18 and a one-row planetary reducer 24/24/72"
designation = "ТММ.ЗП.58.100"

[sheet]
student = "Гелпер Г. Г."
teacher = "Викладач В. В."
group = "МБ-58"
organisation = "НУБіП України"

[gears]
z = [12, 18]
module = 0.010
shifts = "auto"

[planetary]
type = "A"
z = [24, 24, 72]
planets = 3
module = 0.004
rpm = 1500
'''


# Stop 58: frc58's own: an opposed (boxer) two-cylinder compressor — two groups on one crank pin, the pistons'
# dead centres the same crank angles, each piston's gas force on its own compression stroke ("to_max")
BOXER_FRC58 = '''# frc58's own (stop 58): an opposed (boxer) two-cylinder compressor: one crank O1A, two connecting rods
# AB and AC on the one crank pin A, pistons B and C on one line through O1, on either side of it
# (I(0-1) -> II(2-3) ВВП -> II(4-5) ВВП); single-acting: 1200 N of gas on each piston's own compression
# stroke (outwards, away from O1: working_stroke = "to_max" along each cylinder's own axis).
title = "Опозитний двоциліндровий компресор"
title_en = "Opposed two-cylinder compressor"
designation = "ТММ.КП.58.010"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-58"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]

[frame.guides]
right = { through = [0, 0], angle_deg = 0, title_uk = "правого циліндра", title_en = "of the right cylinder" }
left = { through = [0, 0], angle_deg = 180, title_uk = "лівого циліндра", title_en = "of the left cylinder" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.06
rpm = 600
direction = "ccw"
points = { S1 = 0.0 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.24
points = { S2 = 0.3 }

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "right"
mass = 3.0

[[link]]
name = "AC"
number = 4
joints = ["A", "C"]
length = 0.24
points = { S4 = 0.3 }

[[link]]
name = "C"
number = 5
joints = ["C"]
slides_on = "left"
mass = 3.0

[positions]
count = 12
start = "working"
accel = [2]
force_phi_deg = 60
output = "B"
working_stroke = "to_max"

[loads]
g = 9.81
mass_per_length = 20
inertia_factor = 0.1

[[force]]
point = "B"
magnitude = 1200
stroke = "working"
direction = "oppose"

[[force]]
point = "C"
magnitude = 1200
stroke = "working"
direction = "oppose"
'''


# kin58 (stop 58's own kinematics mechanism): a two-slider mechanism of a double pump — an axial crank-slider O1AB and,
# from the point C of its rod, a link CD to a plunger D on a vertical guide; the diagrams of B, D in the tables.
KIN58_TWOSLIDER = '''# kin58 (stop 58's own): a two-slider mechanism of a double pump (a textbook six-bar): an axial crank-slider
# O1AB, and from the point C of its connecting rod a link CD to a second plunger D on a vertical guide:
# I(0-1) -> II(2-3) ВВП -> II(4-5) ВВП; the crank turns counter-clockwise; the diagrams of B (the output),
# D's motion in the tables and plans.
title = "Двоповзунний механізм здвоєного насоса"
title_en = "Two-slider mechanism of a double pump"
designation = "ТММ.КП.58.100"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-58"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]

[frame.guides]
x = { through = [0, 0], angle_deg = 0, title_uk = "повзуна B", title_en = "of the slider B" }
y = { through = [0.16, 0], angle_deg = 90, title_uk = "плунжера D", title_en = "of the plunger D" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.06
rpm = 240
direction = "ccw"
points = { S1 = 0.0 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.26
shape = { C = [0.1, 0.05] }
points = { S2 = [0.13, 0.0] }

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "x"
mass = 3

[[link]]
name = "CD"
number = 4
joints = ["C", "D"]
length = 0.16
points = { S4 = 0.5 }

[[link]]
name = "D"
number = 5
joints = ["D"]
slides_on = "y"
mass = 2

[positions]
count = 12
start = "working"
accel = [2]
force_phi_deg = 60
output = "B"

[loads]
g = 9.81
mass_per_length = 25
inertia_factor = 0.1

[[force]]
point = "B"
magnitude = 600
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.85
synchronous_rpm = 1000
'''



# cam58's own look (stop 58): a ROCKING roller follower turned by a CLOCKWISE cam, a parabolic rise of 120°, a far
# dwell of 40°, a LINEAR return of 100° (rigid shocks at its ends: corners K1 convex, K2 concave), a near dwell of 100°.
OWN_CAM58 = """title = "Кулачковий механізм з коромисловим роликовим штовхачем (власний 58)"
title_en = "Cam with a rocking roller follower (own 58)"
designation = "ТММ.КМ.58.200"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-58"
organisation = "НУБіП України"

[cam]
follower = "rocking"
swing_deg = 20
arm = 0.1
centre_distance = 0.12
roller_radius = 0.01
phases_deg = { rise = 120, dwell_far = 40, return = 100, dwell_near = 100 }
laws = { rise = "parabolic", return = "linear" }
pressure_angle_deg = { rise = 40, return = 45 }
rpm = 100
direction = "cw"
divisions = 8
"""


# gears58b: stop 58's blind reviewer's gear scene (review58-scratch/d_gears.toml): a 13/30 pair with given
# shifts beside a type-A 20/31/82 train — its A1 planetary pictures stood at 1:2 over a 50-mm blank.
GEARS58B = '''# review58 (d): a pair 13/30 with GIVEN shifts x1 = 0.40, x2 = 0.15, m = 5 mm, and a one-row planetary
# train of type A with GIVEN teeth 20/31/82 (u1H = 1 + 82/20 = 5.1), K = 3, 1450 rpm.
title = "Зубчаста передача 13/30 і планетарний редуктор (рецензія 58)"
title_en = "A gear pair 13/30 and a planetary reducer (review 58)"
designation = "ТММ.ЗП.58.600"

[sheet]
student = "Рецензент Р. Р."
teacher = "Викладач В. В."
group = "МБ-58"
organisation = "НУБіП України"

[gears]
z = [13, 30]
module = 0.005
shifts = [0.40, 0.15]

[planetary]
type = "A"
z = [20, 31, 82]
planets = 3
module = 0.002
rpm = 1450
'''



# scales58 (stop 58): the blind reviewer's English crank-rocker of a paddle agitator (review 58 #2: its A2 and A3
# kinematics sets drew the acceleration plans at the lab's own 0.0272 (m/s²)/mm, its A2 forces set group
# II(2-3)'s force plan at 1.5 N/mm — scales off the standard series)
AGITATOR_SCALES58 = '''# review58 (b): in ENGLISH, a crank-rocker four-bar of a paddle agitator: the crank O1A turns counter-clockwise,
# the rocker O2B carries the paddle; a 45 N·m resistance moment on the rocker over its working (slow) swing,
# a 150 N force at the coupler's point E against E's motion on both strokes; masses by length, and [dynamics].
title = "Шарнірний чотириланковий механізм мішалки"
title_en = "Crank-rocker four-bar of a paddle agitator"
designation = "TMM.KP.58.200"
lang = "en"

[sheet]
student = "Reviewer R. R."
teacher = "Teacher T. T."
group = "MB-58"
organisation = "NULES of Ukraine"

[frame.points]
O1 = [0, 0]
O2 = [0.40, 0.10]

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.10
rpm = 60
direction = "ccw"
points = { S1 = 0.5 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.38
points = { S2 = 0.5, E = [0.19, -0.08] }

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.26
points = { S3 = 0.5 }

[branch]
B = 1

[positions]
count = 12
start = "working"
output = "O2B"
accel = [4]
force_phi_deg = 150

[loads]
g = 9.81
mass_per_length = 25
inertia_factor = 0.1

[[moment]]
link = "O2B"
magnitude = 45
stroke = "working"
direction = "oppose"

[[force]]
point = "E"
magnitude = 150
stroke = "both"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.9
synchronous_rpm = 750
'''


# cam58b (review 58 #5): a translating roller follower, a GIVEN negative offset e = −6 mm, the cam clockwise, a
# GIVEN R0 = 40 mm below the smallest (45,88 mm): O_min lettered below O, «*» both meanings in the legend
CAM58B_SMALL_R0 = '''title = "Кулачковий механізм з дезаксіальним роликовим штовхачем (рецензія 58)"
title_en = "Disc cam with an offset translating roller follower (review 58)"
designation = "ТММ.КМ.58.500"

[cam]
follower = "translating"
stroke = 0.035
offset = -0.006
base_radius = 0.04
roller_radius = 0.012
phases_deg = { rise = 110, dwell_far = 30, return = 100, dwell_near = 120 }
laws = { rise = "cosine", return = "parabolic" }
pressure_angle_deg = { rise = 30, return = 40 }
rpm = 120
direction = "cw"
divisions = 8
'''


LINK59 = '''
# Stop 59 (the lead's check): a crank-rocker four-bar whose rocker O2B carries a slot (the lever O2E);
# a block C in the slot is pinned to a ram sliding on a horizontal guide above the rocker's pivot:
# I(0-1) -> II(2-3) ВВВ -> II(4-5) ПВП (PRP); the crank turns clockwise; a 1500 N resistance on the
# ram's working stroke; masses by length; dynamics to a 1000-rpm motor, δ = 1/30.
title = "Важільний привод повзуна через кулісу коромисла"
title_en = "A ram driven by a slotted rocker of a four-bar"
designation = "ТММ.КП.59.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-59"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.24, 0]

[frame.guides]
x = { through = [0, 0.22], angle_deg = 0, title_uk = "повзуна", title_en = "of the ram" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.07
rpm = 95
direction = "cw"
points = { S1 = 0.0 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.26
points = { S2 = 0.5 }

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.18
points = { S3 = 0.5, E = 1.75 }

[[link]]
name = "C"
number = 4
joints = ["C"]
slides_on = "O2B"
mass = 1.5

[[link]]
name = "5"
number = 5
joints = ["C"]
slides_on = "x"
mass = 18

[branch]
B = 1

[positions]
count = 12
start = "working"
accel = [4]
force_phi_deg = 120
output = "C"

[loads]
g = 9.81
mass_per_length = 25
inertia_factor = 0.1

[[force]]
point = "C"
magnitude = 1500
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.033
efficiency = 0.82
synchronous_rpm = 1000
'''


CAM59 = '''
# Stop 59 (the lead's check): a translating roller follower, the cam clockwise, a NEGATIVE offset (to the
# side that raises the rise's pressure angle), a cosine rise of 100°, a far dwell of 40°, a parabolic
# return of 110°, a near dwell of 110°; stroke 35 mm, roller 12 mm, [ϑ] 28°/35°, 8 divisions.
title = "Кулачковий механізм зі зміщеним роликовим штовхачем (перевірка 59)"
title_en = "Cam with an offset translating roller follower (check 59)"
designation = "ТММ.КМ.59.100"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-59"
organisation = "НУБіП України"

[cam]
follower = "translating"
stroke = 0.035
offset = -0.006
roller_radius = 0.012
phases_deg = { rise = 100, dwell_far = 40, return = 110, dwell_near = 110 }
laws = { rise = "cosine", return = "parabolic" }
pressure_angle_deg = { rise = 28, return = 35 }
rpm = 240
direction = "cw"
divisions = 8
'''


GEARS59 = '''
# Stop 59 (the lead's check): a pair 15/32 with given shifts x1 = 0.35, x2 = -0.2 (a negative shift on the
# wheel), m = 5 mm, and a type-A train with given teeth 18/27/72, K = 3, 960 rpm.
title = "Зубчаста передача 15/32 і планетарний редуктор 18/27/72 (перевірка 59)"
title_en = "A gear pair 15/32 and a planetary reducer 18/27/72 (check 59)"
designation = "ТММ.ЗП.59.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-59"
organisation = "НУБіП України"

[gears]
z = [15, 32]
module = 0.005
shifts = [0.35, -0.2]

[planetary]
type = "A"
z = [18, 27, 72]
planets = 3
module = 0.004
rpm = 960
'''


# cam59b: review 59's scene (c): a translating KNIFE-EDGE follower, the offset "auto", the cam counter-clockwise,
# R0 rounded up to 34 mm from the smallest 33,2 — O_min 3 mm above O, lettered on the phase diagram (finding 4).
REVIEW_CAM59C = '''
title = "Кулачковий механізм з поступальним вістряним штовхачем"
title_en = "Disc cam with a translating knife-edge follower"
designation = "ТММ.КП.59.500"

[sheet]
student = "Рецензент Р. Р."
teacher = "Викладач В. В."
group = "МБ-59"
organisation = "НУБіП України"

[cam]
follower = "translating"
stroke = 0.03
offset = "auto"
roller_radius = 0
phases_deg = { rise = 120, dwell_far = 30, return = 90, dwell_near = 120 }
laws = { rise = "cycloidal", return = "cosine" }
pressure_angle_deg = { rise = 30, return = 35 }
rpm = 200
direction = "ccw"
divisions = 12
'''



# Stop 59 (the blind review's): its drag-link six-bar (uk) and Watt-II chain (en), whose A1 kinematics
# sheets drew the position plan at 1:5 in a corner, the smallest drawing (finding 1; kin59b)
DRAGLINK_REVIEW59 = '''
# review59 (a): a six-bar quick-return drive of a ram: a double crank (drag-link) O1A-AB-O2B, the frame O1O2 the
# shortest link, whose driven crank O2B carries (behind O2) the pin C of a rod CD to a slider D on a horizontal
# guide through O2: I(0-1) -> II(2-3) ВВВ -> II(4-5) ВВП; crank CCW at 80 rpm; 1200 N on the slider's working stroke;
# masses by length, the slider 8 kg; [dynamics] to a 750-rpm motor, δ = 0.05.
title = "Шестиланковий механізм поперечно-стругального верстата з подвійним кривошипом"
title_en = "Six-bar quick-return drive with a drag link"
designation = "ТММ.КП.59.700"

[sheet]
student = "Рецензент Р. Р."
teacher = "Викладач В. В."
group = "МБ-59"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.06, 0.0]

[frame.guides]
x = { through = [0.06, 0.0], angle_deg = 0, title_uk = "повзуна", title_en = "of the ram" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.10
rpm = 80
direction = "ccw"
points = { S1 = 0.5 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.15
points = { S2 = 0.5 }

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.13
shape = { C = [-0.12, 0.0] }
points = { S3 = 0.0 }

[[link]]
name = "CD"
number = 4
joints = ["C", "D"]
length = 0.40
points = { S4 = 0.5 }

[[link]]
name = "D"
number = 5
joints = ["D"]
slides_on = "x"
mass = 8

[branch]
B = 1
D = 1

[positions]
count = 12
start = "working"
accel = [3, 8]
force_phi_deg = 210
output = "D"

[loads]
g = 9.81
mass_per_length = 20
inertia_factor = 0.1

[[force]]
point = "D"
magnitude = 1200
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.85
synchronous_rpm = 750
'''


WATT_EN_REVIEW59 = '''
# review59 (b): a Watt-II six-bar of a press-feed lever (lang en): the crank-rocker O1A-AB-O2B whose rocker is a bell
# crank O2-B-C (C behind O2 on the bar's line) driving through the rod CD a second rocker O3D, which carries a 40 N·m resistance
# moment over its working (slow) swing: I(0-1) -> II(2-3) RRR -> II(4-5) RRR; crank CLOCKWISE at 120 rpm;
# masses by length; [dynamics] to a 1000-rpm motor, δ = 0.04.
title = "Шестиланковий важільний механізм Ватта подавача"
title_en = "Watt-II six-bar lever drive of a feeder"
designation = "TMM.KP.59.800"
lang = "en"

[sheet]
student = "Reviewer R. R."
teacher = "Teacher T. T."
group = "MB-59"
organisation = "NULES of Ukraine"

[frame.points]
O1 = [0, 0]
O2 = [0.22, 0.0]
O3 = [0.52, 0.10]

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.06
rpm = 120
direction = "cw"
points = { S1 = 0.5 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.22
points = { S2 = 0.5 }

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.14
shape = { C = [-0.10, 0.0] }
points = { S3 = 0.5 }

[[link]]
name = "CD"
number = 4
joints = ["C", "D"]
length = 0.25
points = { S4 = 0.5 }

[[link]]
name = "O3D"
number = 5
joints = ["O3", "D"]
length = 0.18
points = { S5 = 0.5 }

[branch]
B = 1
D = 1

[positions]
count = 12
start = "working"
accel = [2, 7]
force_phi_deg = 150
output = "O3D"

[loads]
g = 9.81
mass_per_length = 25
inertia_factor = 0.1

[[moment]]
link = "O3D"
magnitude = 40
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.04
efficiency = 0.9
synchronous_rpm = 1000
'''


# frc59c: review 59's Watt-II six-bar (lang en; the reviewer's b_watt_en.toml): its A1 force sheet drew group II(2-3)'s
# plan at 1.5 N/mm, the hodographs of R12, R01 at 7.5 and M_b by the force plans −15 % (review 59 #2)
FRC59C_WATT_EN = WATT_EN_REVIEW59   # the same scene (frc59c added it beside kin59b's copy)


# Stop 60 (the lead's checks; /work/lead/s60): a plunger on a vertical offset guide driving a rocker, a rocking
# roller cam turning clockwise, an 11/23 "auto" pair with a four-planet type-A train.
LINK60 = '''
# Stop 60 (the lead's check): an offset crank-slider on a VERTICAL guide (a plunger B) whose slider drives a
# rocker O2C through the rod BC: I(0-1) -> II(2-3) RRP -> II(4-5) RRR attached to the slider; the crank
# counter-clockwise at 150 rpm; a 60 N·m resistance moment on the rocker over its working swing; masses by
# length; dynamics to a 1500-rpm motor, δ = 1/25.
title = "Механізм плунжера з коромислом"
title_en = "Plunger mechanism driving a rocker"
designation = "ТММ.КП.60.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-60"
organisation = "НУБіП України"

[frame.points]
O = [0, 0]
O2 = [0.22, 0.30]

[frame.guides]
y = { through = [0.03, 0], angle_deg = 90, title_uk = "плунжера", title_en = "of the plunger" }

[crank]
name = "OA"
pivot = "O"
pin = "A"
length = 0.065
rpm = 150
direction = "ccw"
points = { S1 = 0.0 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.24
points = { S2 = 0.35 }

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "y"
mass = 8

[[link]]
name = "BC"
number = 4
joints = ["B", "C"]
length = 0.20
points = { S4 = 0.5 }

[[link]]
name = "O2C"
number = 5
joints = ["O2", "C"]
length = 0.13
points = { S5 = 0.5 }

[branch]
B = 1
C = 1

[positions]
count = 12
start = "working"
accel = [3]
force_phi_deg = 60
output = "O2C"

[loads]
g = 9.81
mass_per_length = 22
inertia_factor = 0.1

[[moment]]
link = "O2C"
magnitude = 60
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.04
efficiency = 0.85
synchronous_rpm = 1500
'''

CAM60 = '''
# Stop 60 (the lead's check): a ROCKING roller follower, the cam CLOCKWISE, a cycloidal
# rise of 120°, a far dwell of 60°, a cosine return of 100°, a near dwell of 80°; a swing of 20°,
# arm 100 mm, 12 divisions, [ϑ] 35°/40°.
title = "Кулачковий механізм з коромисловим роликовим штовхачем (перевірка 60)"
title_en = "Cam with a rocking roller follower (check 60)"
designation = "ТММ.КМ.60.100"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-60"
organisation = "НУБіП України"

[cam]
follower = "rocking"
swing_deg = 20
arm = 0.10
centre_distance = 0.13
roller_radius = 0.012
phases_deg = { rise = 120, dwell_far = 60, return = 100, dwell_near = 80 }
laws = { rise = "cycloidal", return = "cosine" }
pressure_angle_deg = { rise = 35, return = 40 }
rpm = 180
direction = "cw"
divisions = 12
'''

GEARS60 = '''
# Stop 60 (the lead's check): a pair 11/23 with "auto" shifts (the pinion under 17 teeth), m = 6 mm, and a
# type-A train chosen for u1H = 5.6 with FOUR planets (the neighbourhood condition), m = 2.5 mm, 1450 rpm.
title = "Зубчаста передача 11/23 і планетарний редуктор (перевірка 60)"
title_en = "A gear pair 11/23 and a planetary reducer (check 60)"
designation = "ТММ.ЗП.60.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-60"
organisation = "НУБіП України"

[gears]
z = [11, 23]
module = 0.006
shifts = "auto"

[planetary]
type = "A"
ratio = 5.6
planets = 4
module = 0.0025
rpm = 1450
'''


# frc60: LINK60 with the plunger B listed before the rod AB — the pin B is the plunger's, so group II(4-5) is
# attached to the slider (R34 on the rod BC, R43 on the plunger in group II(2-3), R23 the rod AB's on the pin)
FRC60_PLUNGER = LINK60.replace(_PLUNGER_BLOCK := '''[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "y"
mass = 8

''', "").replace('[[link]]\nname = "AB"', _PLUNGER_BLOCK + '[[link]]\nname = "AB"')


# kin60b (stop 60): review 60's scene b — a single-toggle jaw crusher as a crank-rocker, in English; its A1 drew
# ψ3 41 mm high (μψ 0,01, the 80-mm allowance) with 45 mm empty above it, ε3 read 17 % off at a position.
KIN60B_CRUSHER = '''
title = "Щокова дробарка (кривошипно-коромисловий механізм)"
title_en = "Single-toggle jaw crusher (crank-rocker four-bar)"
designation = "TMM.KP.60.800"
lang = "en"

[sheet]
student = "Reviewer R. R."
teacher = "Teacher T. T."
group = "MB-60"
organisation = "NULES of Ukraine"

[frame.points]
O1 = [0, 0]
O2 = [0.21, -0.45]

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.04
rpm = 250
direction = "ccw"
points = { S1 = 0.0 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.50
points = { S2 = 0.5, E = 0.6 }
mass = 60

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.20
points = { S3 = 0.5 }

[branch]
B = -1

[positions]
count = 12
start = "working"
accel = [3, 9]
force_phi_deg = 90
output = "O2B"

[loads]
g = 9.81
mass_per_length = 30
inertia_factor = 0.1

[[force]]
point = "E"
magnitude = 4000
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.9
synchronous_rpm = 750
'''


# dyn60 (stop 60): its own dynamics check — a beam pumping unit: a crank-rocker four-bar whose balanced beam O2B
# runs on past its pivot to the horse head D; the rod load 3000 N at D against its motion on the slow swing; a
# 1000-rpm motor that alone holds δ (no flywheel needed with it), the tangents too flat for a protractor.
DYN60_PUMPJACK = '''
title = "Важільний механізм верстата-качалки"
title_en = "Beam pumping unit linkage"
designation = "ТММ.КП.60.010"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-60"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [-0.40, 0.55]

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.12
rpm = 60
direction = "ccw"
points = { S1 = 0.0 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.55
points = { S2 = 0.5 }

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.40
mass = 24
inertia = 1.28
points = { S3 = 0.0, D = -1.0 }

[branch]
B = 1

[positions]
count = 12
start = "working"
accel = [3]
force_phi_deg = 90
output = "O2B"

[loads]
g = 9.81
mass_per_length = 30
inertia_factor = 0.1

[[force]]
point = "D"
magnitude = 3000
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.85
synchronous_rpm = 1000
'''



CG60_CAM_NO_DWELL = '''
# cg60's (stop 60): a textbook disc cam with no far dwell — a translating roller follower, the cam
# counter-clockwise, the offset "auto", a cycloidal rise of 150° straight into a parabolic return of 120°
# (a soft shock at the top), a near dwell of 90°; stroke 40 mm, roller 15 mm, [ϑ] 30°/35°, 10 divisions.
title = "Кулачковий механізм без дальнього вистою (cg60)"
title_en = "Cam with no far dwell (cg60)"
designation = "ТММ.КМ.60.200"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-60"
organisation = "НУБіП України"

[cam]
follower = "translating"
stroke = 0.040
offset = "auto"
roller_radius = 0.015
phases_deg = { rise = 150, dwell_far = 0, return = 120, dwell_near = 90 }
laws = { rise = "cycloidal", return = "parabolic" }
pressure_angle_deg = { rise = 30, return = 35 }
rpm = 120
direction = "ccw"
divisions = 10
'''


# cam60b (stop 60): review 60's scene c — a translating roller follower, e = −6 mm, the cam clockwise, R0 given 50 mm
# below the smallest; Table 1's row 5 has ϑ = 30,8° > [ϑ] = 30° (the «*» legend and the ϑ cells, review 60 #5)
CAM60B_REVIEW_C = '''
# review60 (c): a translating ROLLER follower with an explicit NEGATIVE offset (to the side that raises the rise's
# pressure angle), the cam CLOCKWISE, a parabolic rise of 100°, far dwell 40°, trapezoidal return 110°, near dwell
# 110°; h = 35 mm, roller 10 mm, [ϑ] 30°/35°; R0 given (50 mm); 10 divisions.
title = "Кулачковий механізм з поступальним роликовим штовхачем (рецензія 60)"
title_en = "Disc cam with a translating roller follower (review 60)"
designation = "ТММ.КП.60.500"

[sheet]
student = "Рецензент Р. Р."
teacher = "Викладач В. В."
group = "МБ-60"
organisation = "НУБіП України"

[cam]
follower = "translating"
stroke = 0.035
offset = -0.006
roller_radius = 0.010
phases_deg = { rise = 100, dwell_far = 40, return = 110, dwell_near = 110 }
laws = { rise = "parabolic", return = "trapezoidal" }
pressure_angle_deg = { rise = 30, return = 35 }
base_radius = 0.060
rpm = 150
direction = "cw"
divisions = 10
'''


# frc60b: review 60's scene (a) — a crank-rocker whose rocker drives a slider on a 30° inclined guide (its crank
# plan's Φ1 1 mm at 5 N/mm, lost in the detail and captioned "< 1 мм": review 60 #2)
FRC60B_INCLINE = '''
# review60 (a): a Stephenson-free six-bar of a feeder: the crank-rocker O1A-AB-O2B whose rocker O2B carries (beyond B,
# on the bar's line) the pin C of a rod CD to a slider D on a guide INCLINED at 30°: I(0-1) -> II(2-3) ВВВ -> II(4-5) ВВП;
# the crank CLOCKWISE at 90 rpm; 800 N against the slider on its working stroke; masses by length, the slider 10 kg;
# [dynamics] to a 1000-rpm motor, δ = 0.05.
title = "Шестиланковий механізм подавача з повзуном на похилій напрямній"
title_en = "Six-bar feeder drive with a slider on an inclined guide"
designation = "ТММ.КП.60.700"

[sheet]
student = "Рецензент Р. Р."
teacher = "Викладач В. В."
group = "МБ-60"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.28, 0.10]

[frame.guides]
d = { through = [0.30, 0.40], angle_deg = 30, title_uk = "повзуна", title_en = "of the slider" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.07
rpm = 90
direction = "cw"
points = { S1 = 0.5 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.25
points = { S2 = 0.5 }

[[link]]
name = "O2C"
number = 3
joints = ["O2", "B"]
length = 0.16
shape = { C = [0.24, 0.0] }
points = { S3 = 0.5 }

[[link]]
name = "CD"
number = 4
joints = ["C", "D"]
length = 0.28
points = { S4 = 0.5 }

[[link]]
name = "D"
number = 5
joints = ["D"]
slides_on = "d"
mass = 10

[branch]
B = 1
D = 1

[positions]
count = 12
start = "working"
accel = [2, 8]
force_phi_deg = 120
output = "D"

[loads]
g = 9.81
mass_per_length = 25
inertia_factor = 0.1

[[force]]
point = "D"
magnitude = 800
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.9
synchronous_rpm = 1000
'''


# Stop 61, the lead's check (link61.toml).
LINK61 = '''
# Stop 61 (the lead's check): a crank-rocker four-bar whose BELL-CRANK rocker O2BD (a triangular link,
# D off the line O2B) drives a slider E on a vertical guide through the rod DE:
# I(0-1) -> II(2-3) RRR -> II(4-5) RRP; the crank CLOCKWISE at 120 rpm; a 900 N resistance force on the
# slider over its working stroke; masses by length; dynamics to a 1000-rpm motor, δ = 1/20.
title = "Шестиланковий механізм з кутовим важелем"
title_en = "Six-bar mechanism with a bell crank"
designation = "ТММ.КП.61.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-61"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.28, 0.0]

[frame.guides]
y = { through = [0.44, 0], angle_deg = 90, title_uk = "повзуна", title_en = "of the slider" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.07
rpm = 120
direction = "cw"
points = { S1 = 0.0 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.26
points = { S2 = 0.5 }

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.16
shape = { D = [-0.06, -0.11] }
points = { S3 = 0.4 }

[[link]]
name = "DE"
number = 4
joints = ["D", "E"]
length = 0.22
points = { S4 = 0.5 }

[[link]]
name = "E"
number = 5
joints = ["E"]
slides_on = "y"
mass = 6

[branch]
B = 1
E = 1

[positions]
count = 12
start = "working"
accel = [2]
force_phi_deg = 75

[loads]
g = 9.81
mass_per_length = 20
inertia_factor = 0.1

[[force]]
point = "E"
magnitude = 900
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.85
synchronous_rpm = 1000
'''


# Stop 61, the lead's check (cam61.toml).
CAM61 = '''
# Stop 61 (the lead's check): a translating KNIFE-EDGE follower, the cam counter-clockwise, a trapezoidal
# rise of 150°, a short far dwell of 20°, a cycloidal return of 130°, a near dwell of 60°; stroke 30 mm,
# offset "auto", 10 divisions, [ϑ] 30°/35°.
title = "Кулачковий механізм з ножовим штовхачем (перевірка 61)"
title_en = "Cam with a knife-edge translating follower (check 61)"
designation = "ТММ.КМ.61.100"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-61"
organisation = "НУБіП України"

[cam]
follower = "translating"
stroke = 0.03
offset = "auto"
roller_radius = 0
phases_deg = { rise = 150, dwell_far = 20, return = 130, dwell_near = 60 }
laws = { rise = "trapezoidal", return = "cycloidal" }
pressure_angle_deg = { rise = 30, return = 35 }
rpm = 200
direction = "ccw"
divisions = 10
'''


# Stop 61, the lead's check (gears61.toml).
GEARS61 = '''
# Stop 61 (the lead's check): a pair 16/41 with GIVEN shifts x1 = 0.3, x2 = -0.1, m = 5 mm, and a type-B
# train with GIVEN teeth z = 20, 44, 22, 86 (u1H = 1 + 44·86/(20·22) = 9.6), three planets, m = 2 mm, 960 rpm.
title = "Зубчаста передача 16/41 і дворядний планетарний редуктор (перевірка 61)"
title_en = "A gear pair 16/41 and a two-row planetary reducer (check 61)"
designation = "ТММ.ЗП.61.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-61"
organisation = "НУБіП України"

[gears]
z = [16, 41]
module = 0.005
shifts = [0.3, -0.1]

[planetary]
type = "B"
z = [20, 44, 22, 86]
planets = 3
module = 0.002
rpm = 960
'''


# Stop 61: kin61's own: an opposed (boxer) twin-cylinder compressor, two pistons on one horizontal line through O1
KIN61_BOXER = '''# kin61's own (stop 61): an opposed (boxer) two-cylinder compressor — one crank O1A drives two connecting
# rods AB and AC pinned at the crank pin A, the pistons B and C on ONE horizontal line through O1, B to the
# right and C to the left (the 180° V of the textbooks' opposed engines): I(0-1) -> II(2-3) ВВП -> II(4-5)
# ВВП; the crank counter-clockwise at 480 rpm; the gas forces on the pistons' compression strokes
# (outwards: working_stroke = "to_max"); masses by length; dynamics to a 1500-rpm motor, δ = 1/30.
title = "Опозитний двоциліндровий компресор"
title_en = "Opposed twin-cylinder compressor"
designation = "ТММ.КП.61.100"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-61"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]

[frame.guides]
x = { through = [0, 0], angle_deg = 0, title_uk = "правого циліндра", title_en = "of the right cylinder" }
y = { through = [0, 0], angle_deg = 180, title_uk = "лівого циліндра", title_en = "of the left cylinder" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.06
rpm = 480
direction = "ccw"
points = { S1 = 0.0 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.24
points = { S2 = 0.35 }

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "x"
mass = 3

[[link]]
name = "AC"
number = 4
joints = ["A", "C"]
length = 0.24
points = { S4 = 0.35 }

[[link]]
name = "C"
number = 5
joints = ["C"]
slides_on = "y"
mass = 3

[positions]
count = 12
start = "working"
working_stroke = "to_max"
accel = [2]
force_phi_deg = 60
output = "B"

[loads]
g = 9.81
mass_per_length = 20
inertia_factor = 0.1

[[force]]
point = "B"
magnitude = 1200
stroke = "working"
direction = "oppose"

[[force]]
point = "C"
magnitude = 1200
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.033
efficiency = 0.8
synchronous_rpm = 1500
'''


# frc61b: a crank-rocker whose rocker O2B, extended past B to C, drives a slider E on a horizontal guide
# through the rod CE (a rocking-conveyor six-bar: I(0-1) -> II(2-3) RRR -> II(4-5) RRP), 700 N against the
# slider's working stroke — test_forces_aux61's generated "rocker-slider", kept for the reviews
FRC61B_ROCKER_SLIDER = '''
title = "Шестиланковий механізм"
title_en = "Six-bar mechanism"
designation = "ТММ.61.02.000"

[frame.points]
O1 = [0, 0]
O2 = [0.2, 0.0]

[frame.guides]
x = { through = [0, 0.2], angle_deg = 0 }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.06
rpm = 100
points = { S1 = 0.0 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.22
points = { S2 = 0.5 }

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.15
shape = { C = [0.21, 0] }
points = { S3 = 0.5 }

[[link]]
name = "CE"
number = 4
joints = ["C", "E"]
length = 0.3
points = { S4 = 0.5 }

[[link]]
name = "E"
number = 5
joints = ["E"]
slides_on = "x"
mass = 5

[branch]
B = 1
E = 1

[positions]
count = 12
start = "working"
accel = [3]
force_phi_deg = 45

[loads]
g = 9.81
mass_per_length = 20
inertia_factor = 0.1

[[force]]
point = "E"
magnitude = 700
stroke = "working"
direction = "oppose"
'''


# dyn61's own (stop 61): a crank-rocker four-bar of lever shears (a textbook flywheel case): the rocker O2B carries
# the upper knife; a 420 N·m cutting moment over a short part of its working swing only (a profile), so the crank's
# resistance is a narrow peak; masses by length; a 1500-rpm motor, δ = 1/12.
DYN61_SHEARS = '''
title = "Шарнірний чотириланковий механізм важільних ножиць"
title_en = "Crank-rocker four-bar of lever shears"
designation = "ТММ.КП.61.610"

[sheet]
student = "Студент С. С."
teacher = "Викладач В. В."
group = "МБ-61"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.30, 0.06]

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.06
rpm = 80
points = { S1 = 0.0 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.28
points = { S2 = 0.5 }

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.16
points = { S3 = 0.5 }

[branch]
B = 1

[positions]
count = 12
start = "working"
accel = [3]
force_phi_deg = 90

[loads]
g = 9.81
mass_per_length = 40
inertia_factor = 0.1

[[moment]]
link = 3
magnitude = 420
stroke = "working"
direction = "oppose"
profile = [[0, 0], [8, 0], [12, 1], [22, 1], [26, 0], [60, 0]]

[dynamics]
delta = 0.0833
efficiency = 0.85
synchronous_rpm = 1500
'''


# gears61's own (stop 61): a ROCKING KNIFE-EDGE follower turned by a CLOCKWISE cam (the mirror of stop 60 on a knife
# edge), a cosine rise of 110° straight into a cycloidal return of 100° (NO far dwell), a near dwell of 150°, a swing
# of 24°, 12 divisions — a combination not in this file before.
GEARS61_OWN_CAM = '''
title = "Кулачковий механізм з коромисловим загостреним штовхачем (власний 61)"
title_en = "Cam with a rocking knife-edge follower (own check 61)"
designation = "ТММ.КМ.61.200"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-61"
organisation = "НУБіП України"

[cam]
follower = "rocking"
swing_deg = 24
arm = 0.1
centre_distance = 0.12
roller_radius = 0
phases_deg = { rise = 110, dwell_far = 0, return = 100, dwell_near = 150 }
laws = { rise = "cosine", return = "cycloidal" }
pressure_angle_deg = { rise = 40, return = 45 }
rpm = 120
direction = "cw"
divisions = 12
'''

# gears61's own (stop 61): a pair 12/20 of small ratio and module 3 mm with the shifts by the rule ("auto"), and a
# type-A train wanted at u1H = 8 (z3/z1 = 7: a large sun-to-ring ratio, the neighbourhood of three large planets
# tested), 1440 rpm — a type-A ratio above any in this file before.
GEARS61_OWN_GEARS = '''
title = "Зубчаста передача 12/20 і однорядний планетарний редуктор (власний 61)"
title_en = "A gear pair 12/20 and a one-row planetary reducer (own check 61)"
designation = "ТММ.ЗП.61.200"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-61"
organisation = "НУБіП України"

[gears]
z = [12, 20]
module = 0.003
shifts = "auto"

[planetary]
type = "A"
ratio = 8.0
planets = 3
module = 0.002
rpm = 1440
'''


# kin61b (stop 61): review 61's crank-rocker of a hopper swing gate (b_gate_en) — its A1 diagrams had
# μψ 0,011 rad/mm (ψmax/h off the series); now 0,01 (ψ 83 mm in the 80-mm allowance).
KIN61B_GATE = '''# review61 (b): a crank-rocker of a hopper's swing gate: O1A 0.08 (ccw, 80 rpm), AB 0.30, O2B 0.20, O2 (0.32, -0.08)
title = "Шарнірний чотириланковий механізм привода засувки бункера"
[frame.points]
O1 = [0, 0]
O2 = [0.32, -0.08]
[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.08
rpm = 80
direction = "ccw"
[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.30
[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.20
[branch]
B = 1
[positions]
count = 12
start = "working"
output = "O2B"
'''



# frc61 (stop 61): frc61's own forces check — a Whitworth rotating-coulisse drive of a slotting machine, the ram on a
# VERTICAL guide through the coulisse's pivot, the crank clockwise, the cut on the downward stroke.
FRC61_SLOTTER = '''# Stop 61 (frc61's own check): a Whitworth quick-return drive of a SLOTTING machine — the crank O1A (longer than
# O1O) turns the coulisse OB fully round O through the stone 2; the rod BC drives the ram C on a VERTICAL guide
# through O (I(0-1) -> II(2-3) RPR -> II(4-5) RRP); the crank CLOCKWISE; the cutting force on the ram on its
# downward (working) stroke; the rod's and the coulisse's masses by length.
title = "Кулісний механізм з обертовою кулісою (Вітворта) довбального верстата"
title_en = "Whitworth rotating-coulisse mechanism of a slotting machine"
designation = "ТММ.КП.61.100"

[sheet]
student = "Перевірка Ф. Ф."
teacher = "Викладач В. В."
group = "МБ-61"
organisation = "НУБіП України"

[frame.points]
O = [0, 0]
O1 = [0.06, 0]

[frame.guides]
ram = { through = [0, 0], angle_deg = 90, title_uk = "повзуна", title_en = "of the ram" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.12
rpm = 75
direction = "cw"
points = { S1 = 0.5 }

[[link]]
name = "2"
number = 2
joints = ["A"]
slides_on = "OB"
mass = 2

[[link]]
name = "OB"
number = 3
joints = ["O", "B"]
length = 0.2
points = { S3 = 0.5 }

[[link]]
name = "BC"
number = 4
joints = ["B", "C"]
length = 0.45
points = { S4 = 0.5 }

[[link]]
name = "C"
number = 5
joints = ["C"]
slides_on = "ram"
mass = 25

[branch]
A = 1
C = 1

[positions]
count = 12
start = "working"
accel = [3]
force_phi_deg = 100
working_stroke = "to_min"

[loads]
g = 9.81
mass_per_length = 25
inertia_factor = 0.1

[[force]]
point = "C"
magnitude = 1800
stroke = "working"
'''


# dyn61b (stop 61): review 61's scene b (in English), a hopper swing-gate's crank-rocker drive — its A3 dynamics
# set put Tables 1–3 and ω(φ) on its first sheet, the construction after them (review 61 finding 4)
DYN61B_GATE = '''# review61 (b): in ENGLISH, a crank-rocker four-bar of a hopper's swing-gate drive: crank O1A (0.08 m, CCW,
# 80 rpm), coupler AB (0.30 m), rocker O2B (0.20 m) carrying the gate's shaft; a resistance MOMENT of 150 N·m
# on the rocker against its turn over the working swing; masses by length 30 kg/m; [dynamics] 1000 rpm, δ = 0.04.
title = "Шарнірний чотириланковий механізм привода засувки бункера"
title_en = "Crank-rocker drive of a hopper swing gate"
designation = "TMM.KP.61.720"
lang = "en"

[sheet]
student = "Reviewer R. R."
teacher = "Teacher T. T."
group = "MB-61"
organisation = "NULES of Ukraine"

[frame.points]
O1 = [0, 0]
O2 = [0.32, -0.08]

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.08
rpm = 80
direction = "ccw"
points = { S1 = 0.0 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.30
points = { S2 = 0.5 }

[[link]]
name = "O2B"
number = 3
joints = ["O2", "B"]
length = 0.20
points = { S3 = 0.5 }

[branch]
B = 1

[positions]
count = 12
start = "working"
accel = [4]
force_phi_deg = 150
output = "O2B"

[loads]
g = 9.81
mass_per_length = 30
inertia_factor = 0.1

[[moment]]
link = 3
magnitude = 150
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.04
efficiency = 0.9
synchronous_rpm = 1000
'''


# Stop 62, the lead's check: a crank-slider on an inclined guide whose slider carries the block of a slotted lever (RRP -> RPR), a resistance moment, a 1500-rpm motor.
LINK62 = """\
# Stop 62 (the lead's check): a crank-slider on an INCLINED guide (20°) whose slider carries the block of a
# slotted lever O3C: I(0-1) -> II(2-3) RRP -> II(4-5) RPR (the block 4 pinned to the slider at B, sliding in
# the lever 5 that swings about O3); the crank ccw at 90 rpm; a 60 N·m resistance moment on the lever over
# its working stroke; masses by length; dynamics to a 1500-rpm motor, δ = 1/25.
title = "Шестиланковий механізм з похилим повзуном і кулісою"
title_en = "Six-bar mechanism with an inclined slider and a slotted lever"
designation = "ТММ.КП.62.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-62"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O3 = [0.30, 0.20]

[frame.guides]
x = { through = [0, -0.04], angle_deg = 20, title_uk = "повзуна", title_en = "of the slider" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.06
rpm = 90
direction = "ccw"
points = { S1 = 0.0 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.25
points = { S2 = 0.4 }

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "x"
mass = 4

[[link]]
name = "O3C"
number = 5
joints = ["O3"]
length = 0.34
points = { C = 1.0, S5 = 0.5 }

[[link]]
name = "B4"
number = 4
joints = ["B"]
slides_on = "O3C"
mass = 1.5

[branch]
B = 1

[positions]
count = 12
start = "working"
accel = [3]
force_phi_deg = 120

[loads]
g = 9.81
mass_per_length = 18
inertia_factor = 0.1

[[moment]]
link = 5
magnitude = 60
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.04
efficiency = 0.8
synchronous_rpm = 1500
"""


# Stop 62, the lead's check: a translating roller follower, clockwise, a negative given offset, parabolic rise / cosine return.
CAM62 = """\
# Stop 62 (the lead's check): a translating ROLLER follower, the cam CLOCKWISE, a NEGATIVE given offset
# (e = −6 mm: to the side that raises the rise's pressure angle), a parabolic rise of 100°, a far dwell of
# 40°, a cosine return of 140°, a near dwell of 80°; stroke 25 mm, roller 8 mm, [ϑ] 30°/40°, 8 divisions.
title = "Кулачковий механізм з роликовим штовхачем і від'ємним зміщенням (перевірка 62)"
title_en = "Cam with a roller translating follower and a negative offset (check 62)"
designation = "ТММ.КМ.62.100"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-62"
organisation = "НУБіП України"

[cam]
follower = "translating"
stroke = 0.025
offset = -0.006
roller_radius = 0.008
phases_deg = { rise = 100, dwell_far = 40, return = 140, dwell_near = 80 }
laws = { rise = "parabolic", return = "cosine" }
pressure_angle_deg = { rise = 30, return = 40 }
rpm = 300
direction = "cw"
divisions = 8
"""


# Stop 62, the lead's check: a 10/32 pair with "auto" shifts and a type-B train synthesised for u1H = 15.
GEARS62 = """\
# Stop 62 (the lead's check): a pair 10/32 with shifts "auto" (z1 = 10, deep in undercut without a shift),
# m = 4 mm, and a type-B train SYNTHESISED for u1H = 15 with K = 3 planets, m = 2.5 mm, 1450 rpm.
title = "Зубчаста передача 10/32 і дворядний планетарний редуктор (перевірка 62)"
title_en = "A gear pair 10/32 and a two-row planetary reducer (check 62)"
designation = "ТММ.ЗП.62.000"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-62"
organisation = "НУБіП України"

[gears]
z = [10, 32]
module = 0.004
shifts = "auto"

[planetary]
type = "B"
ratio = 15
planets = 3
module = 0.0025
rpm = 1450
"""


# dyn62 (stop 62, helper dyn62): its own dynamics mechanism — the ram drive of a hay baler, an offset crank-slider (the
# crank clockwise) whose ram meets a compression force that grows over the second half of its working stroke (to_max),
# a 1000-rpm motor, δ = 1/15; the approximate flywheel +26 % (flagged), the diagrams redrawn on 24 divisions
DYN62_BALER = """\
title = "Кривошипно-повзунний механізм поршня прес-підбирача"
title_en = "Crank-slider ram drive of a hay baler"
designation = "ТММ.КП.62.620"

[sheet]
student = "Студент С. С."
teacher = "Викладач В. В."
group = "МБ-62"
organisation = "НУБіП України"

[frame.points]
O = [0, 0]

[frame.guides]
ram = { through = [0, -0.05], angle_deg = 0, title_uk = "поршня", title_en = "of the ram" }

[crank]
name = "OA"
pivot = "O"
pin = "A"
length = 0.2
rpm = 80
direction = "cw"
points = { S1 = 0.0 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.9
points = { S2 = 0.35 }

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "ram"
mass = 45

[branch]
B = 1

[positions]
count = 12
start = "min"
working_stroke = "to_max"
accel = [2]
force_phi_deg = 150

[loads]
g = 9.81
mass_per_length = 25
inertia_factor = 0.1

[[force]]
point = "B"
magnitude = 6000
stroke = "working"
direction = "oppose"
profile = [[0, 0], [0.2, 0], [0.36, 1], [0.4, 0.3]]

[dynamics]
delta = 0.0667
efficiency = 0.85
synchronous_rpm = 1000
"""



# wedge62 (stop 62): review 62's wedge press (a): the wedge 3's inclined face (35°) runs through its own joint B and
# carries the block 4 pinned at C to the vertical ram 5 — drawn as the textbook's triangle on its guide, α3 in Table 4.
WEDGE62_PRESS = '''
# review62 (a): a six-bar WEDGE press: an offset crank-slider O-A-B drives the wedge 3 (the slider B on a
# horizontal guide) whose inclined face (35° to the guide) carries the block 4 at C, pinned to the vertical
# ram 5: I(0-1) -> II(2-3) ВВП -> II(4-5) ПВП; the crank CLOCKWISE at 120 rpm; 2500 N against the ram on its
# upward (working) stroke; masses by length, the wedge 8 kg, the block 1 kg, the ram 6 kg; [dynamics] to a
# 1000-rpm motor, δ = 0.05.
title = "Клиновий прес з кривошипно-повзунним приводом"
title_en = "Wedge press driven by a crank-slider"
designation = "ТММ.КП.62.810"

[sheet]
student = "Рецензент Р. Р."
teacher = "Викладач В. В."
group = "МБ-62"
organisation = "НУБіП України"

[frame.points]
O = [0, 0]

[frame.guides]
x = { through = [0, -0.02], angle_deg = 0, title_uk = "клина 3", title_en = "of the wedge 3" }
y = { through = [0.34, 0], angle_deg = 90, title_uk = "повзуна 5", title_en = "of the ram 5" }

[crank]
name = "OA"
pivot = "O"
pin = "A"
length = 0.05
rpm = 120
direction = "cw"
points = { S1 = 0.5 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.22
points = { S2 = 0.4 }

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "x"
guide = { through = [0.0, 0.0], angle_deg = 35 }
mass = 8

[[link]]
name = "C"
number = 4
joints = ["C"]
slides_on = "B"
mass = 1

[[link]]
name = "D"
number = 5
joints = ["C"]
slides_on = "y"
shape = { D = [0.06, 0] }
mass = 6

[branch]
B = 1

[positions]
count = 12
start = "working"
working_stroke = "to_max"
accel = [3, 8]
force_phi_deg = 90
output = "C"

[loads]
g = 9.81
mass_per_length = 20
inertia_factor = 0.1

[[force]]
point = "C"
magnitude = 2500
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.9
synchronous_rpm = 1000
'''



# frc62 (stop 62): a new force-sheet mechanism — a crank-slider whose triangular rod ABE drives a rocker O2C
# through EC (I(0-1) -> II(2-3) RRP -> II(4-5) RRR), a force on the slider and a moment on the rocker.
FRC62_TRIANGLE_ROD = '''
# frc62 (stop 62): a crank-slider whose triangular connecting rod ABE drives, from its third vertex E, a rod EC to a
# rocker O2C (a textbook six-bar of a feed drive): I(0-1) -> II(2-3) RRP -> II(4-5) RRR; the crank ccw at 150 rpm;
# 500 N against the slider over its working stroke and a 25 N·m resistance moment on the rocker; masses by length.
title = "Шестиланковий механізм з трикутним шатуном"
title_en = "Six-bar mechanism with a triangular connecting rod"
designation = "ТММ.КП.62.100"

[sheet]
student = "Помічник Ф. Ф."
teacher = "Викладач В. В."
group = "МБ-62"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O2 = [0.16, 0.22]

[frame.guides]
x = { through = [0, -0.02], angle_deg = 0, title_uk = "повзуна", title_en = "of the slider" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.05
rpm = 150
direction = "ccw"
points = { S1 = 0.0 }

[[link]]
name = "ABE"
number = 2
joints = ["A", "B"]
length = 0.20
shape = { E = [0.10, 0.06] }
points = { S2 = 0.5 }

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "x"
mass = 3

[[link]]
name = "EC"
number = 4
joints = ["E", "C"]
length = 0.14
points = { S4 = 0.5 }

[[link]]
name = "O2C"
number = 5
joints = ["O2", "C"]
length = 0.12
points = { S5 = 0.5 }

[branch]
B = 1
C = 1

[positions]
count = 12
start = "working"
accel = [3]
force_phi_deg = 60

[loads]
g = 9.81
mass_per_length = 20
inertia_factor = 0.1

[[force]]
point = "B"
magnitude = 500
stroke = "working"
direction = "oppose"

[[moment]]
link = 5
magnitude = 25
stroke = "working"
direction = "oppose"

[dynamics]
delta = 0.05
efficiency = 0.85
synchronous_rpm = 1500
'''



# gc62 (stop 62): a rocking roller follower turned clockwise, a cycloidal rise straight into a cosine return
# (no far dwell) — concave stretches on the rise and the return, said in the notes.
GC62_CAM = """\
# gc62's own: a ROCKING roller follower, the cam CLOCKWISE, a cycloidal rise of 120° straight into a cosine
# return of 90° (no far dwell), a near dwell of 150°; swing 20°, arm 100 mm, centre distance 120 mm, roller 9 mm.
title = "Кулачковий механізм з коромисловим роликовим штовхачем без дальнього вистою (gc62)"
title_en = "Cam with a rocking roller follower and no far dwell (gc62)"
designation = "ТММ.КМ.62.200"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-62"
organisation = "НУБіП України"

[cam]
follower = "rocking"
swing_deg = 20
arm = 0.1
centre_distance = 0.12
roller_radius = 0.009
phases_deg = { rise = 120, dwell_far = 0, return = 90, dwell_near = 150 }
laws = { rise = "cycloidal", return = "cosine" }
pressure_angle_deg = { rise = 40, return = 45 }
rpm = 150
direction = "cw"
divisions = 8
"""

# gc62 (stop 62): an equal-and-opposite shift pair 14/26 (x = ±0.3: αw = α, aw = a), m = 6 mm, and a type-A
# train synthesised for u1H = 8, K = 3 (17/49/115 chosen; 18/54/126 exact but 10 % larger).
GC62_GEARS = """\
# gc62's own: an equal-and-opposite shift pair 14/26 (x1 = 0.3, x2 = −0.3: αw = α, aw = a), m = 6 mm, and a
# type-A train synthesised for u1H = 8 with K = 3 planets, m = 3 mm, 960 rpm.
title = "Зубчаста передача 14/26 з рівнозміщеним зачепленням і планетарний редуктор (gc62)"
title_en = "A gear pair 14/26 with equal and opposite shifts and a planetary reducer (gc62)"
designation = "ТММ.ЗП.62.200"

[sheet]
student = "Перевірка Н. Н."
teacher = "Викладач В. В."
group = "МБ-62"
organisation = "НУБіП України"

[gears]
z = [14, 26]
module = 0.006
shifts = [0.3, -0.3]

[planetary]
type = "A"
ratio = 8
planets = 3
module = 0.003
rpm = 960
"""



# kin62 (stop 62): my own — a shaper's rocking coulisse driving the ram through a block pinned to it
# (I(0-1) -> II(2-3) RPR -> II(4-5) RPP): the ram 5 on its guide carries the block 4 of the coulisse's slot
KIN62_SHAPER_BLOCK = '''
# kin62 (stop 62): a shaper's rocking coulisse driving the ram through a block — the crank O1A turns
# clockwise at 60 rpm; the block 2 at A slides in the coulisse 3 (O3B) rocking about O3; the ram 5 on a
# horizontal guide carries on its pin C the block 4, which slides in the same coulisse
# (I(0-1) -> II(2-3) RPR -> II(4-5) RPP); a 1500 N cutting force on the ram over its working stroke.
title = "Кулісний механізм поперечно-стругального верстата з каменем на повзуні"
title_en = "Shaper's rocking-coulisse mechanism with a block on the ram"
designation = "ТММ.КП.62.100"

[sheet]
student = "Студент С. С."
teacher = "Викладач В. В."
group = "МБ-62"
organisation = "НУБіП України"

[frame.points]
O1 = [0, 0]
O3 = [0, -0.35]

[frame.guides]
x = { through = [0, 0.15], angle_deg = 0, title_uk = "повзуна", title_en = "of the ram" }

[crank]
name = "O1A"
pivot = "O1"
pin = "A"
length = 0.10
rpm = 60
direction = "cw"
points = { S1 = 0.0 }

[[link]]
name = "A2"
number = 2
joints = ["A"]
slides_on = "O3B"
mass = 2

[[link]]
name = "O3B"
number = 3
joints = ["O3"]
length = 0.56
points = { B = 1.0, S3 = 0.5 }

[[link]]
name = "C"
number = 5
joints = ["C"]
slides_on = "x"
mass = 30

[[link]]
name = "C4"
number = 4
joints = ["C"]
slides_on = "O3B"
mass = 2

[positions]
count = 12
start = "working"
accel = [2]
force_phi_deg = 60

[loads]
g = 9.81
mass_per_length = 20
inertia_factor = 0.1

[[force]]
point = "C"
magnitude = 1500
stroke = "working"
direction = "oppose"
'''



# diag62: review 62 F4 (b_pump_en), an English offset crank-slider of a plunger pump: e = 0.03 m, crank 0.06, rod
# 0.25 m, its 120.9-mm stroke drawn 60.5 mm high at μs 0,002 on the A1 (a_B 10.2 % off) where 0,001 reads 5.1 %
DIAG62_PUMP = """\
# review62 (b): in ENGLISH, an offset (eccentric) crank-slider of a single-acting plunger pump: crank OA 0.06 m
# CLOCKWISE at 150 rpm, rod AB 0.25 m, the plunger B on a horizontal guide 0.03 m below O; the discharge
# pressure on the plunger, 1500 N against it over its working (slow) stroke, building up over the first
# 40 mm (profile); masses by length 25 kg/m, the plunger 5 kg; [dynamics] to a 1500-rpm motor, δ = 0.03.
title = "Дезаксіальний кривошипно-повзунний механізм плунжерного насоса"
title_en = "Offset crank-slider of a plunger pump"
designation = "TMM.KP.62.820"
lang = "en"

[sheet]
student = "Reviewer R. R."
teacher = "Teacher T. T."
group = "MB-62"
organisation = "NULES of Ukraine"

[frame.points]
O = [0, 0]

[frame.guides]
x = { through = [0, -0.03], angle_deg = 0, title_uk = "плунжера 3", title_en = "of the plunger 3" }

[crank]
name = "OA"
pivot = "O"
pin = "A"
length = 0.06
rpm = 150
direction = "cw"
points = { S1 = 0.3 }

[[link]]
name = "AB"
number = 2
joints = ["A", "B"]
length = 0.25
points = { S2 = 0.35 }

[[link]]
name = "B"
number = 3
joints = ["B"]
slides_on = "x"
mass = 5

[branch]
B = 1

[positions]
count = 12
start = "working"
accel = [2, 9]
force_phi_deg = 120
output = "B"

[loads]
g = 9.81
mass_per_length = 25
inertia_factor = 0.1

[[force]]
point = "B"
magnitude = 1500
stroke = "working"
direction = "oppose"
profile = [[0, 0.2], [0.04, 1], [0.13, 1]]

[dynamics]
delta = 0.03
efficiency = 0.85
synchronous_rpm = 1500
"""
