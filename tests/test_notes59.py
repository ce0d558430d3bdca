"""Stop 59: a block of notes stays within the width it is wrapped to. Its lines start their ink flush
(``left_bearing``: a line opening on a letter with a wide side bearing, osifont's M or R, is set that much
left of the margin), and a block is placed by its box: a continued line filling the wrapped width then ran
that far past the column's right edge (the slow hypothesis test of the gear sheet: 150/150 teeth, the
English A1, the notes 0.15 mm out of their box)."""
from __future__ import annotations

import numpy as np

LINES = ["Meshing: the module drawn 4 mm, the whole depth 2.25·m = 9 mm, precision 0.5 mm",
         "ω_1 is given; the plan's segment 1 (400 mm at μ_ω = 0.25 (rad/s)/mm, that is 100 rad/s) checks the "
         "velocity picture's line 1; δ is the construction's error, in ω_2, ω_H too",
         "Rise: R_0 taken 56 mm, the least 55.881 mm read 55.8 mm off the phase diagram; 1 mm = 0.0004 m"]


def test_a_note_block_is_no_wider_than_its_width_whatever_the_width():
    """Every width from 100 to 190 mm by 0.1 mm: the block's box (the lines' boxes, the bearing-shifted
    ones included) no wider than the width it was given (before the fix 121 of 2600 widths in steps of
    0.05 mm over 60–190 mm ran over, by up to the first glyph's bearing, 0.41 mm at 3.5 mm)."""
    from graphplan.sheets.compose import note_block
    for w in np.arange(100.0, 190.0, 0.1):
        b = note_block(LINES, float(w)).bounds()
        assert b[2] - b[0] <= w + 1e-9, w
