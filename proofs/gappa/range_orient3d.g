# Expansion range of orient3d (d is the pivot, as in formulas.hpp): the absolute tree of
#   adz (bdx cdy - cdx bdy) + bdz (cdx ady - adx cdy) + cdz (adx bdy - bdx ady),
# homogeneous of degree 3. See range_orient.g for how K becomes orient3d_max_log.
pa = |ax| + |dx|; qa = |ay| + |dy|; ra = |az| + |dz|;
pb = |bx| + |dx|; qb = |by| + |dy|; rb = |bz| + |dz|;
pc = |cx| + |dx|; qc = |cy| + |dy|; rc = |cz| + |dz|;
tree = ra * (pb * qc + pc * qb) + rb * (pc * qa + pa * qc) + rc * (pa * qb + pb * qa);
{ |ax| in [0, 1] /\ |ay| in [0, 1] /\ |az| in [0, 1] /\ |bx| in [0, 1] /\ |by| in [0, 1]
  /\ |bz| in [0, 1] /\ |cx| in [0, 1] /\ |cy| in [0, 1] /\ |cz| in [0, 1]
  /\ |dx| in [0, 1] /\ |dy| in [0, 1] /\ |dz| in [0, 1]
  -> tree in ? }
