# Expansion range of insphere (e is the pivot, as in formulas.hpp): the absolute tree of
#   (dlift abc - clift dab) + (blift cda - alift bcd),
#   abc = aez bc - bez ac + cez ab (bcd, cda, dab alike), ab = aex bey - bex aey (...),
#   alift = aex^2 + aey^2 + aez^2 (...),
# homogeneous of degree 5. See range_orient.g for how K becomes insphere_max_log.
pa = |ax| + |ex|; qa = |ay| + |ey|; ra = |az| + |ez|;
pb = |bx| + |ex|; qb = |by| + |ey|; rb = |bz| + |ez|;
pc = |cx| + |ex|; qc = |cy| + |ey|; rc = |cz| + |ez|;
pd = |dx| + |ex|; qd = |dy| + |ey|; rd = |dz| + |ez|;
ab = pa * qb + pb * qa; bc = pb * qc + pc * qb; cd = pc * qd + pd * qc;
da = pd * qa + pa * qd; ac = pa * qc + pc * qa; bd = pb * qd + pd * qb;
abc = ra * bc + rb * ac + rc * ab;
bcd = rb * cd + rc * bd + rd * bc;
cda = rc * da + rd * ac + ra * cd;
dab = rd * ab + ra * bd + rb * da;
la = pa * pa + qa * qa + ra * ra; lb = pb * pb + qb * qb + rb * rb;
lc = pc * pc + qc * qc + rc * rc; ld = pd * pd + qd * qd + rd * rd;
tree = (ld * abc + lc * dab) + (lb * cda + la * bcd);
{ |ax| in [0, 1] /\ |ay| in [0, 1] /\ |az| in [0, 1] /\ |bx| in [0, 1] /\ |by| in [0, 1]
  /\ |bz| in [0, 1] /\ |cx| in [0, 1] /\ |cy| in [0, 1] /\ |cz| in [0, 1]
  /\ |dx| in [0, 1] /\ |dy| in [0, 1] /\ |dz| in [0, 1]
  /\ |ex| in [0, 1] /\ |ey| in [0, 1] /\ |ez| in [0, 1]
  -> tree in ? }
