"""Random mechanisms of every dyad kind, as scene text, for the property tests.

Each builder takes plain numbers and returns (scene text, assemblable over the whole turn?)."""
from __future__ import annotations

import math


def _crank(r: float, omega: float, pivot=(0.0, 0.0), guide: str = "") -> str:
    return (f"[frame.points]\nO = [{pivot[0]}, {pivot[1]}]\n"
            f"[crank]\nname = \"OA\"\npivot = \"O\"\npin = \"A\"\nlength = {r}\nomega = {abs(omega)}\n"
            f"direction = \"{'ccw' if omega > 0 else 'cw'}\"\n{guide}")


def rrr(r, d, l2, l3, omega, branch):
    """Four-bar O(0,0)–A–B–O2(d,0)."""
    text = (_crank(r, omega) + f"[[link]]\nname = \"AB\"\njoints = [\"A\", \"B\"]\nlength = {l2}\n"
            "points = { S2 = [0.3, 0.05] }\n"
            f"[[link]]\nname = \"O2B\"\njoints = [\"O2\", \"B\"]\nlength = {l3}\n"
            f"[branch]\nB = {branch}\n[positions]\nstart = 0\n")
    text = text.replace("O = [0.0, 0.0]\n", f"O = [0.0, 0.0]\nO2 = [{d}, 0.0]\n")
    ok = (l2 + l3 > d + r) and (abs(l2 - l3) < d - r)
    return text, ok


def rrp(r, l, e, angle, omega, branch):
    """Crank-slider with an offset guide at any angle."""
    a = math.radians(angle)
    through = (-e * math.sin(a), e * math.cos(a))
    text = (_crank(r, omega) + f"[frame.guides]\ng = {{ through = [{through[0]}, {through[1]}], "
            f"angle_deg = {angle} }}\n"
            f"[[link]]\nname = \"AB\"\njoints = [\"A\", \"B\"]\nlength = {l}\npoints = {{ S2 = 0.4 }}\n"
            "[[link]]\nname = \"slider\"\njoints = [\"B\"]\nslides_on = \"g\"\n"
            f"[branch]\nB = {branch}\n[positions]\nstart = 0\n")
    return text, l > r + abs(e)


def rpr(r, c, e, omega, branch):
    """Slotted link: crank O(0,0), block at A on a rocker pivoted at P=(c,0), its slot offset e."""
    text = (_crank(r, omega) + "[[link]]\nname = \"2\"\njoints = [\"A\"]\nslides_on = \"PQ\"\n"
            f"[[link]]\nname = \"PQ\"\njoints = [\"P\"]\n"
            f"guide = {{ through = [0, {e}], angle_deg = 0 }}\npoints = {{ S3 = [0.05, 0.02] }}\n"
            f"[branch]\nA = {branch}\n[positions]\nstart = 0\n")
    text = text.replace("O = [0.0, 0.0]\n", f"O = [0.0, 0.0]\nP = [{c}, 0.0]\n")
    return text, abs(c - r) > abs(e)


def prp(r, d, l2, l3, alpha, beta, omega):
    """A four-bar whose rocker carries a guide (angle α to the rocker) for link 4; link 5 slides on
    a frame guide at angle β; 4 and 5 are pinned at C. The rocker's guide turns: Coriolis on 4."""
    text, ok = rrr(r, d, l2, l3, omega, 1)
    text = text.replace("[branch]", f"guide = {{ through = [0, 0], angle_deg = {alpha} }}\n"
                        "[[link]]\nname = \"4\"\njoints = [\"C\"]\nslides_on = \"O2B\"\n"
                        "[[link]]\nname = \"5\"\njoints = [\"C\"]\nslides_on = \"h\"\n[branch]")
    text = text.replace("[crank]", f"[frame.guides]\nh = {{ through = [0, 0.2], angle_deg = {beta} }}\n[crank]")
    return text, ok


def rpp(r, alpha, beta, omega):
    """Scotch yoke: block at A slides in the yoke's slot (angle α), the yoke on a frame guide (β)."""
    text = (_crank(r, omega) + f"[frame.guides]\ng = {{ through = [0, 0.3], angle_deg = {beta} }}\n"
            "[[link]]\nname = \"2\"\njoints = [\"A\"]\nslides_on = \"yoke\"\n"
            "[[link]]\nname = \"yoke\"\njoints = []\nref = \"Y\"\nslides_on = \"g\"\n"
            f"guide = {{ through = [0, 0], angle_deg = {alpha} }}\npoints = {{ S3 = [0.02, 0.01] }}\n"
            "[positions]\nstart = 0\n")
    return text, abs(math.sin(math.radians(alpha))) > 1e-3


def rrp_moving(r, d, l2, l3, l4, alpha, omega, branch):
    """A four-bar whose rocker carries a guide (angle α to the rocker); a rod A–C from the crank pin
    drives a slider C along that turning guide: II(4-5) RRP on a moving guide (Coriolis on 5)."""
    text, ok = rrr(r, d, l2, l3, omega, 1)
    text = text.replace("[branch]", f"guide = {{ through = [0, 0], angle_deg = {alpha} }}\n"
                        f"[[link]]\nname = \"AC\"\njoints = [\"A\", \"C\"]\nlength = {l4}\n"
                        "points = { S4 = [0.1, 0.02] }\n"
                        "[[link]]\nname = \"5\"\njoints = [\"C\"]\nslides_on = \"O2B\"\n[branch]")
    text = text.replace("[branch]\nB = 1\n", f"[branch]\nB = 1\nC = {branch}\n")
    return text, ok and l4 > d + r


def rpp_moving(r, d, l2, l3, alpha, beta, omega):
    """A four-bar whose rocker carries a guide (angle β to the rocker) on which a yoke slides; the
    block at the crank pin A slides in the yoke's slot (angle α to the yoke): II(4-5) RPP on a
    moving guide (Coriolis in both sliding pairs)."""
    text, ok = rrr(r, d, l2, l3, omega, 1)
    text = text.replace("[branch]", f"guide = {{ through = [0, 0], angle_deg = {beta} }}\n"
                        "[[link]]\nname = \"6\"\njoints = [\"A\"]\nslides_on = \"yoke\"\n"
                        "[[link]]\nname = \"yoke\"\njoints = []\nref = \"Y\"\nslides_on = \"O2B\"\n"
                        f"guide = {{ through = [0, 0], angle_deg = {alpha} }}\n"
                        "points = { S7 = [0.02, 0.01] }\n[branch]")
    return text, ok and abs(math.sin(math.radians(alpha))) > 1e-3
