"""Stop 58: a reaction flagged past the lab's 5 % for being short says by how much a ruler's half
division misses it and that, closing the plan, it carries the rounded knowns — as the kinematics
sheet says it (FRC56_PUMP's R03, 45 N read against 40.2 N, +12 %, was flagged "a short vector" alone)."""
from conftest import group_of, scene_force_plans


def test_a_short_reactions_flag_says_what_it_misses_by():
    from graphplan.drawing.forces import reaction_why
    from review_scenes import FRC56_PUMP
    fp = scene_force_plans(FRC56_PUMP, group_mu_F={"II(4-5)": 5.0})
    gp = group_of(fp, "II(2-3)")
    m = gp.reactions["R03"]
    assert abs(m.value - m.analytic) / m.analytic > 0.05          # flagged: past the lab's 5 %
    share = round(100 * fp.precision / 2 / m.mm)                  # 0.25 mm of 4.5 mm: 6 %
    known = len([s for s in gp.sides if s.role == "known"])
    for lang, words in (("uk", (f"({m.mm:g} мм)".replace(".", ","), f"{share} %", f"{known} сил")),
                        ("en", (f"({m.mm:g} mm)", f"{share} %", f"{known} forces"))):
        said = reaction_why(fp, "R03", lang)
        assert all(w in said for w in words), said
