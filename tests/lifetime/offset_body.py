"""The inner parallel body of the parametric knife (a prism of length L whose section is the
pentagon of a plate of thickness T and height H with a symmetric chisel of bevel height B),
offset by D on every face but the clamped top: the exact worn knife under uniform wear, in
closed form, for the lifetime checks (check_analytic.sh, check_reference_knife.sh)."""
import math


def section(D, H, T, B):
    """Area and worn perimeter of the pentagon offset by D (the top held)."""
    sin_a = (T / 2) / math.hypot(T / 2, B)
    tip, w = D / sin_a, T / 2 - D
    knee = tip + w * B / (T / 2)
    area = 2 * w * (H - knee) + w * (knee - tip)
    return area, 2 * math.hypot(w, knee - tip) + 2 * (H - knee)


def swept_over_archard(D, d, L, H, T, B):
    """The volume lost from depth D to D + d over d x the worn area at D (below 1 at convex
    edges, which the offset faces cut short)."""
    (a0, p0), (a1, _) = section(D, H, T, B), section(D + d, H, T, B)
    return ((L - 2 * D) * a0 - (L - 2 * D - 2 * d) * a1) / (d * (2 * a0 + (L - 2 * D) * p0))
