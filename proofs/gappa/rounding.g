# One rounding of binary64, round to nearest even, outside the subnormal range.
# Lemma R1 (relative to the exact value):  |fl(x) - x| <= eps |x|   for 2^-1021 <= |x| <= 2^1023.
# (Gappa's relative-error theorem for ieee_64 starts at 2^-1021, one binade above the
# smallest normal; underflow.g covers everything below.) Lemma R2, relative to the result,
# is in rounding_result.g. Read by ../derive_bounds.py as eps_exact.
@rnd = float<ieee_64, ne>;
{ |x| in [1b-1021, 1b1023] -> rnd(x) -/ x in ? }
