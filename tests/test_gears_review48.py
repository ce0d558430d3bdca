"""Stop 48's gear-sheet review (helper gear48): the lead's pair 12/31 "auto" + type B u = 16 (GEARS48),
GEARS_B47's primed z′₂ and the plan of angular velocities' scale — checked against the glyphs' ink and
the closed forms, not the code's own numbers."""
from __future__ import annotations

from graphplan.graphic.record import ink_boxes


def test_an_index_after_a_prime_stands_under_the_prime_by_its_letter():
    """z'_2 typeset as z′₂ (the prime high, the 2 low, both right after the z): the 2's ink begins
    within the prime's advance — not past it, hanging apart from its z (GEARS_B47's notes: the 2 a
    word of its own beside z′, overprinted) — and stays clear of the prime's ink below it."""
    for size in (2.5, 3.5, 5.0):
        z, prime, two = ink_boxes("z'_2", size)
        assert two[0] < prime[2]                           # under the prime, not after it
        assert two[0] - z[2] < 0.25 * size                 # beside its letter (as z_2 sets it)
        assert two[3] < prime[1] - 0.2 * size              # clear of the prime's ink
        z_, two_ = ink_boxes("z_2", size)
        assert abs(two[0] - two_[0]) < 1e-9                # where the unprimed z₂ sets it
