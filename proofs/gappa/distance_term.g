# compare_distance term and the radial key's squares: S = fl(P), P = fl(ax - cx)^2, against
# the exact Sx = (ax - cx)^2, when nothing underflows: Gappa bounds the error of the
# rounded difference, squared (P -/ Sx), and of the square's rounding (S -/ P);
# ../derive_bounds.py checks that they compose to at most (1 + eps)^3 - 1, the per-square
# count the written combinations use (bounds.md#compare-distance, bounds.md#radial-key).
@rnd = float<ieee_64, ne>;
ax = rnd(ax_); cx = rnd(cx_);
x1 = rnd(ax - cx);
P = x1 * x1;
S = rnd(P);
Sx = (ax - cx) * (ax - cx);
{ |ax - cx| in [1b-1021, 1b511] /\ P in [1b-1021, 1b1022]
  -> P -/ Sx in ? /\ S -/ P in ? }
