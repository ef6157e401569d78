# Expansion range of incircle (d is the pivot, as in formulas.hpp): the absolute tree of
#   alift (bdx cdy - cdx bdy) + blift (cdx ady - adx cdy) + clift (adx bdy - bdx ady),
# homogeneous of degree 4. See range_orient.g for how K becomes incircle_max_log.
pa = |ax| + |dx|; qa = |ay| + |dy|;
pb = |bx| + |dx|; qb = |by| + |dy|;
pc = |cx| + |dx|; qc = |cy| + |dy|;
tree = (pa * pa + qa * qa) * (pb * qc + pc * qb) + (pb * pb + qb * qb) * (pc * qa + pa * qc)
     + (pc * pc + qc * qc) * (pa * qb + pb * qa);
{ |ax| in [0, 1] /\ |ay| in [0, 1] /\ |bx| in [0, 1] /\ |by| in [0, 1] /\ |cx| in [0, 1] /\ |cy| in [0, 1]
  /\ |dx| in [0, 1] /\ |dy| in [0, 1]
  -> tree in ? }
