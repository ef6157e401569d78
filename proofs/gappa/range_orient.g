# Expansion range of orient2d (bounds.md#expansion-range). Every expansion component and
# every partial sum that the exact stages form is bounded by the "absolute tree": the same
# formula with every coordinate replaced by its magnitude and every - by +. With every
# |coordinate| <= 1 this script bounds the tree by K; the formula is homogeneous of degree 2,
# so with every |coordinate| < 2^(E+1) the tree is below K 2^(2(E+1)), which must stay at
# most 2^1023. ../derive_bounds.py turns K into the largest safe E (orient_max_log).
{ |ax| in [0, 1] /\ |ay| in [0, 1] /\ |bx| in [0, 1] /\ |by| in [0, 1] /\ |cx| in [0, 1] /\ |cy| in [0, 1]
  -> (|ax| + |cx|) * (|by| + |cy|) + (|ay| + |cy|) * (|bx| + |cx|) in ? }
