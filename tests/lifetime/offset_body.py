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


def volume(D, L, H, T, B):
    """The inner parallel body's volume at depth D."""
    return (L - 2 * D) * section(D, H, T, B)[0]


def worn_area(D, L, H, T, B):
    """The wearable area at depth D: both ends and the worn perimeter along the length."""
    a, p = section(D, H, T, B)
    return 2 * a + (L - 2 * D) * p


def depth_after_volume(D, V, L, H, T, B):
    """The depth at which the body at depth D has lost volume V (bisection to 1e-15 m): where
    an update that removes Archard's volume V leaves uniform wear."""
    lo, hi = D, D + 2 * V / worn_area(D, L, H, T, B)
    target = volume(D, L, H, T, B) - V
    while hi - lo > 1e-15:
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if volume(mid, L, H, T, B) > target else (lo, mid)
    return 0.5 * (lo + hi)
