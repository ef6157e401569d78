# Granularity (bounds.md#stages-b-and-c, lemma G and the no-underflow argument of the
# adaptive stages):
#   a value x that is a multiple of 2^-1074 (FIX) and has at most 53 significant bits (FLT)
#   is a double, so rounding it is exact (every operation of stages B and C inside the
#   expansion range, whose results are multiples of 2^-1074, bounds.md#expansion-range);
#   a multiple of 2^-1074 below 2^-1021 in magnitude has at most 53 bits;
#   any real v below 2^-1021 rounds with an absolute error of at most eta = 2^-1075
#   (lemma G: a rounded error bound that lands in the subnormal range).
# Read by ../derive_bounds.py (it checks the exactness and reads eta).
@rnd = float<ieee_64, ne>;
z = rnd(x);
{ @FIX(y, -1074) /\ |y| in [0, 9007199254740991b-1074] /\ @FIX(x, -1074) /\ @FLT(x, 53)
  /\ |v| in [0, 1b-1021]
  -> @FLT(y, 53) /\ z - x in ? /\ rnd(v) - v in ? }
