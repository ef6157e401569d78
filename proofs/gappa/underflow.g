# Gradual underflow. For doubles a, b whose exact product (sum) is at most 2^-1021 in
# magnitude, the rounded product (sum) differs from it by at most eta = 2^-1075, half the
# smallest subnormal (lemma U). (A sum in this range is in fact exact, Hauser 1996; Gappa
# does not derive that, so the derivations use the weaker eta for sums too.)
# Read by ../derive_bounds.py as eta.
@rnd = float<ieee_64, ne>;
a = rnd(a_); b = rnd(b_);
p = rnd(a * b);
s = rnd(a + b);
{ |a * b| in [0, 1b-1021] /\ |a + b| in [0, 1b-1021]
  -> p - a * b in ? /\ s - (a + b) in ? }
