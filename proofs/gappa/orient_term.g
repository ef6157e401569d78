# orient2d (and dot product) term: L = fl(P), P = fl(ax - cx) * fl(by - cy), against the
# exact Lx = (ax - cx)(by - cy), when nothing underflows: Gappa bounds the error of the two
# rounded differences together (P -/ Lx) and of the product's rounding (L -/ P);
# ../derive_bounds.py checks that they compose to at most (1 + eps)^3 - 1, the per-term
# count the written combination uses (bounds.md#orient2d).
@rnd = float<ieee_64, ne>;
ax = rnd(ax_); cx = rnd(cx_); by = rnd(by_); cy = rnd(cy_);
x1 = rnd(ax - cx);
y1 = rnd(by - cy);
P = x1 * y1;
L = rnd(P);
Lx = (ax - cx) * (by - cy);
{ |ax - cx| in [1b-1021, 1b511] /\ |by - cy| in [1b-1021, 1b511] /\ |P| in [1b-1021, 1b1022]
  -> P -/ Lx in ? /\ L -/ P in ? }
