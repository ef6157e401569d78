# Circumcentre, stage 1 (bounds.md#circumcenter, claim F2): the offset's quotient
#   u = fl(n * fl(1 / (2 d)))  against  q = n / (2 d)   (n, d the computed doubles),
# two roundings: Gappa bounds u -/ q, the relative error ../derive_bounds.py uses as q_rel.
# By symmetry (rounding to nearest is odd) n, d > 0. The ranges are those the range
# conditions give (bounds.md#circumcenter: |d| > 2 ed, the granularity of n); the script
# checks that the ranges it derives from constants.hpp's limits lie inside these.
@rnd = float<ieee_64, ne>;
n = rnd(n_); d = rnd(d_);
r = 1 / (2 * d);
h = rnd(r);
p = n * h;
u = rnd(p);
q = n * r;
{ d in [1b-560, 1b310] /\ n in [1b-810, 1b460] /\ q in [1b-510, 1b1000]
  -> u -/ q in ? }
