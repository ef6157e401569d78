# Circumcentre, stage 2 (bounds.md#circumcenter, lemma DW): the error of the double-word
# product mul(x, y) of construct.cpp,
#   (ph, pl) = Two-Product(xh, yh)   (exact: ph + pl = xh yh)
#   c = fl(fl(xh yl) + fl(xl yh)),  w = fl(pl + c),  result ph + w (Fast-Two-Sum: exact),
# relative to |xh yh|, in the standard model of rounding (lemma R1, rounding.g): each of the
# five roundings is a factor (1 + e_i), |e_i| <= 2^-53 (ph = xh yh (1 + e0), so
# pl = -e0 xh yh). Dividing by xh yh (nonzero; a zero factor makes the product exactly 0):
# s = xl / xh, t = yl / yh with |s|, |t| <= 2^-53 (normalized double words), and
#   err = (ph + w - (xh + xl)(yh + yl)) / (xh yh).
# Gradual underflow in the two low products, and an inexact Two-Product, add absolute
# terms that bounds.md adds in writing. The rewriting hint is the algebra of the written
# derivation; Gappa checks that it is an identity and bounds it.
# Read by ../derive_bounds.py as the double-word product's coefficient (beta_h).
a1 = t * (1 + e1);
a2 = s * (1 + e2);
c = (a1 + a2) * (1 + e3);
w = (-e0 + c) * (1 + e4);
err = (1 + e0) + w - (1 + s) * (1 + t);
{ |s| <= 1b-53 /\ |t| <= 1b-53 /\ |e0| <= 1b-53 /\ |e1| <= 1b-53 /\ |e2| <= 1b-53
  /\ |e3| <= 1b-53 /\ |e4| <= 1b-53
  -> err in ? }
err -> -e0 * e4 + (s + t) * e4 + (t * (e1 + e3 + e1 * e3) + s * (e2 + e3 + e2 * e3)) * (1 + e4) - s * t;
