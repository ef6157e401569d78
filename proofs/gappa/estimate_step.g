# One step of the expansion estimate s_k = fl(s_{k-1} + e_k) (expansion.hpp,
# expansion_estimate; bounds.md#expansion-estimate), s and e doubles:
#   above 2^-1021 the step errs by at most eps |s + e| (R1 for a sum of two doubles);
#   below 2^-1021 the sum of two doubles is a multiple of 2^-1074 (FIX) of at most 53 bits
#   (FLT), so granular.g makes the step exact.
# Read by ../derive_bounds.py as the per-step error of the estimate lemma.
@rnd = float<ieee_64, ne>;
s = rnd(s_); e = rnd(e_);
x = s + e;
z = rnd(x);
t = rnd(t_); f = rnd(f_);
y = t + f;
{ |x| in [1b-1021, 1b1023] /\ |y| in [0, 9007199254740991b-1074]
  -> z -/ x in ? /\ @FIX(y, -1074) /\ @FLT(y, 53) }
