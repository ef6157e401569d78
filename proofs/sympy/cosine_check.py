#!/usr/bin/env python3
"""Symbolic checks of proofs/cosine.md, and of the degrees of every formula of
predicates/src/formulas.hpp that expansion_safe is given (bounds.md#expansion-range), with
orient3d and insphere against the determinants they name. Exit code non-zero on the first
failed claim.

Roles as in cosine.md: incircle_cosine(a, b, c, d) with B = a, C = b, D = c (opposite
vertex), A = d (new point); u = (a-d).(b-d), v = (a-c).(b-c).
"""
import itertools
import random
import sys

import sympy as sp

FAILED = []


def claim(ok, text):
    print(("ok   " if ok else "FAIL ") + text)
    if not ok:
        FAILED.append(text)


def cross(p, q):
    return p[0] * q[1] - p[1] * q[0]


def dot(p, q):
    return p[0] * q[0] + p[1] * q[1]


def sub(p, q):
    return (p[0] - q[0], p[1] - q[1])


# ---- the formulas of predicates/src/formulas.hpp, term for term -------------------------
def orient2d(a, b, c):
    return cross(sub(b, a), sub(c, a))


def incircle(a, b, c, d):  # incircle_of_differences with d as the pivot
    adx, ady = sub(a, d)
    bdx, bdy = sub(b, d)
    cdx, cdy = sub(c, d)
    alift, blift, clift = adx**2 + ady**2, bdx**2 + bdy**2, cdx**2 + cdy**2
    return (alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy)
            + clift * (adx * bdy - bdx * ady))


def cosine_parts(a, b, c, d):
    u = dot(sub(a, d), sub(b, d))
    v = dot(sub(a, c), sub(b, c))
    ac2, bc2 = dot(sub(a, c), sub(a, c)), dot(sub(b, c), sub(b, c))
    ad2, bd2 = dot(sub(a, d), sub(a, d)), dot(sub(b, d), sub(b, d))
    return u, v, ac2 * bc2 * u * u, ad2 * bd2 * v * v, (ac2, bc2, ad2, bd2)


def cosine_decision(u, v, left, right):  # returns sign(-E), as the C++ code
    su, sv = sp.sign(u), sp.sign(v)
    if su == sv:
        return -su
    e = su if left > right else (sv if right > left else 0)
    return -e


syms = sp.symbols("ax ay bx by cx cy dx dy")
a, b, c, d = (syms[0], syms[1]), (syms[2], syms[3]), (syms[4], syms[5]), (syms[6], syms[7])

# ---- 1. the sine-form identity ------------------------------------------------------------
# Paper's letters: A = new point, B, C = edge, D = opposite vertex.
for name, (A, B, C, D) in {"A=d B=a C=b D=c": (d, a, b, c)}.items():
    sine = cross(sub(B, A), sub(C, A)) * dot(sub(C, D), sub(B, D)) + \
        dot(sub(B, A), sub(C, A)) * cross(sub(C, D), sub(B, D))
    det = incircle(a, b, c, d)
    if sp.expand(sine - det) == 0:
        claim(True, f"sine form == +incircle(a, b, c, d) with {name}")
    else:
        claim(sp.expand(sine + det) == 0, f"sine form == -incircle(a, b, c, d) with {name}")
# Which argument order of the paper's determinant det[B-A, |B-A|^2; C-A, ...; D-A, ...]
paper_det = sp.Matrix([[*sub(P, d), dot(sub(P, d), sub(P, d))] for P in (a, b, c)]).det()
claim(sp.expand(paper_det - incircle(a, b, c, d)) == 0,
      "incircle(a, b, c, d) == det[B-A, |B-A|^2; C-A, ...; D-A, ...] with A = d")

# ---- 2. degrees (expansion_safe's degree argument) ---------------------------------------
u, v, left, right, _ = cosine_parts(a, b, c, d)
for name, poly, want in (("orient2d", orient2d(a, b, c), 2), ("incircle", incircle(a, b, c, d), 4),
                         ("cosine L", left, 8), ("cosine R", right, 8), ("u", u, 2),
                         # compare_distance(c = a, p = b, q = c)
                         ("compare_distance", dot(sub(b, a), sub(b, a)) - dot(sub(c, a), sub(c, a)), 2)):
    claim(sp.Poly(poly, *syms).total_degree() == want, f"{name} has total degree {want}")

# The predicates of space (formulas.hpp, term for term): each is the determinant it names
# (so its sign convention is Shewchuk's), of the degree adaptive3d.cpp passes to
# expansion_safe.
syms3 = sp.symbols("ax3 ay3 az3 bx3 by3 bz3 cx3 cy3 cz3 dx3 dy3 dz3 ex3 ey3 ez3")
pa3, pb3, pc3, pd3, pe3 = (syms3[3 * i:3 * i + 3] for i in range(5))


def orient3d(a, b, c, d):  # orient3d_of_differences, d as the pivot
    adx, ady, adz = (a[i] - d[i] for i in range(3))
    bdx, bdy, bdz = (b[i] - d[i] for i in range(3))
    cdx, cdy, cdz = (c[i] - d[i] for i in range(3))
    return (adz * (bdx * cdy - cdx * bdy) + bdz * (cdx * ady - adx * cdy)
            + cdz * (adx * bdy - bdx * ady))


def insphere(a, b, c, d, e):  # insphere_of_differences, e as the pivot
    (aex, aey, aez), (bex, bey, bez), (cex, cey, cez), (dex, dey, dez) = (
        [p[i] - e[i] for i in range(3)] for p in (a, b, c, d))
    ab, bc = aex * bey - bex * aey, bex * cey - cex * bey
    cd, da = cex * dey - dex * cey, dex * aey - aex * dey
    ac, bd = aex * cey - cex * aey, bex * dey - dex * bey
    abc = aez * bc - bez * ac + cez * ab
    bcd = bez * cd - cez * bd + dez * bc
    cda = cez * da + dez * ac + aez * cd
    dab = dez * ab + aez * bd + bez * da
    alift, blift = aex**2 + aey**2 + aez**2, bex**2 + bey**2 + bez**2
    clift, dlift = cex**2 + cey**2 + cez**2, dex**2 + dey**2 + dez**2
    return (dlift * abc - clift * dab) + (blift * cda - alift * bcd)


def laplace(rows):  # cofactor expansion along the first row (fast on symbolic entries)
    if len(rows) == 1:
        return rows[0][0]
    return sum((-1) ** j * rows[0][j] * laplace([r[:j] + r[j + 1:] for r in rows[1:]])
               for j in range(len(rows)))


o3 = sp.expand(orient3d(pa3, pb3, pc3, pd3))
o3_rows = [[p[i] - pd3[i] for i in range(3)] for p in (pa3, pb3, pc3)]
claim(o3 == sp.expand(laplace(o3_rows)), "orient3d == det[a - d; b - d; c - d]")
i5 = sp.expand(insphere(pa3, pb3, pc3, pd3, pe3))
i5_rows = ([p[i] - pe3[i] for i in range(3)] for p in (pa3, pb3, pc3, pd3))
claim(i5 == sp.expand(laplace([[*r, sum(x**2 for x in r)] for r in i5_rows])),
      "insphere == det[p - e, |p - e|^2] over p = a, b, c, d")
for name, poly, want in (("orient3d", o3, 3), ("insphere", i5, 5)):
    claim(sp.Poly(poly, *syms3).total_degree() == want, f"{name} has total degree {want}")

# ---- 3. boundary cases ---------------------------------------------------------------------
t = sp.symbols("t0:4")


def on_unit_circle(s):  # rational parametrisation of the unit circle
    return ((1 - s**2) / (1 + s**2), 2 * s / (1 + s**2))


P = [on_unit_circle(s) for s in t]
u0, v0, l0, r0, _ = cosine_parts(P[0], P[1], P[2], P[3])
# Rational functions of t0..t3: cleared of denominators, the numerator must vanish.
def vanishes(expr):
    return sp.expand(sp.fraction(sp.together(expr))[0]) == 0


# L - R has degree 8 in the points: expanding it over four parameters is slow, so it is
# tested at 40 random rational parameter tuples instead (a nonzero rational function
# vanishes at random points with negligible probability: Schwartz-Zippel).
rng = random.Random(1)
lr = sp.lambdify(t, l0 - r0, modules=[{"sqrt": sp.sqrt}, "sympy"])
claim(all(lr(*[sp.Rational(rng.randint(-50, 50), rng.randint(1, 50)) for _ in t]) == 0
          for _ in range(40)), "all four on a circle: L == R, so |X| == |Y|")
claim(vanishes(incircle(*P)), "all four on a circle: incircle determinant == 0")
# With c, d on opposite arcs (opposite sides of ab), u and v have opposite signs (one
# cosine is -1 times the other): checked on the parametrisation, u v <= 0 for sample arcs.
uv_signs = set()
for ta, tb, tc, td in ((-2, 2, 0, 5), (-1, 3, 1, -3), (0, 1, sp.Rational(1, 2), 7)):
    sub_ = dict(zip(t, (ta, tb, tc, td)))
    uv_signs.add(sp.sign((u0 * v0).subs(sub_)))
claim(uv_signs == {-1}, "cocircular, opposite arcs: u and v have opposite signs, so E == 0")
# Right angle at A (d on the circle with diameter ab, Thales): u == 0.
s = sp.symbols("s")
mid = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
half = sub(b, mid)
rot = ((1 - s**2) / (1 + s**2), 2 * s / (1 + s**2))
d_thales = (mid[0] + rot[0] * half[0] - rot[1] * half[1], mid[1] + rot[1] * half[0] + rot[0] * half[1])
u_thales = dot(sub(a, d_thales), sub(b, d_thales))
claim(vanishes(u_thales), "d on the circle with diameter ab: u == 0 (right angle at A)")
# Then E = |a-d||b-d| v, and the circle through a, b, c contains d iff the angle at c is
# obtuse (v < 0): the determinant has the sign of -v times orient (checked below by sampling).

# ---- 4. the case analysis of cosine_decision -----------------------------------------------
# sign(E) with E = sqrt(W1) u + sqrt(W2) v, exhaustively over small integers, W1, W2 >= 0.
# Geometry ties the weights to the dot products: W1 = |a-c|^2 |b-c|^2 is 0 only when c == a
# or c == b, and then v = (a-c).(b-c) = 0; likewise W2 = 0 forces u = 0. Without that tie
# the same-sign shortcut would be wrong (u, v > 0 with both weights 0 gives E = 0).
bad = 0
for uu, vv, w1, w2 in itertools.product(range(-3, 4), range(-3, 4), range(0, 7), range(0, 7)):
    if (w1 == 0 and vv != 0) or (w2 == 0 and uu != 0):
        continue
    exact = sp.sign(sp.sqrt(w1) * uu + sp.sqrt(w2) * vv)
    if cosine_decision(uu, vv, w1 * uu * uu, w2 * vv * vv) != -exact:
        bad += 1
claim(bad == 0, "cosine_decision == sign(-E) for all u, v in [-3, 3], weights^2 in [0, 6]")

# ---- 5. the chain: opposite sides => sign(-E) == orient(a, b, c) * incircle(a, b, c, d) ----
random.seed(5)
mismatch = 0
cases = 0
for _ in range(300):
    pts = [(sp.Rational(random.randint(-9, 9)), sp.Rational(random.randint(-9, 9))) for _ in range(3)]
    # d: random, or exactly on the circle through a, b, c (rational point via the centre)
    pa, pb, pc = pts
    det_abc = orient2d(pa, pb, pc)
    if det_abc == 0:
        continue
    if random.random() < 0.5:
        pd = (sp.Rational(random.randint(-9, 9)), sp.Rational(random.randint(-9, 9)))
    else:  # reflect c across the line through the centre perpendicular to ab: on the circle
        ba, ca = sub(pb, pa), sub(pc, pa)  # circumcentre, by the textbook formula
        den = 2 * cross(ba, ca)
        o = (pa[0] + (ca[1] * dot(ba, ba) - ba[1] * dot(ca, ca)) / den,
             pa[1] + (ba[0] * dot(ca, ca) - ca[0] * dot(ba, ba)) / den)
        k = random.choice([sp.Rational(1, 3), sp.Rational(2, 5), 2, -3])
        # a point of the circle: the second intersection of the line through a with slope k
        dirv = (1, k)
        tt = -2 * dot(sub(pa, o), dirv) / dot(dirv, dirv)
        pd = (pa[0] + tt * dirv[0], pa[1] + tt * dirv[1])
    if sp.sign(orient2d(pa, pb, pc)) * sp.sign(orient2d(pa, pb, pd)) >= 0:
        continue  # precondition: c and d strictly on opposite sides of ab
    cases += 1
    uu, vv, ll, rr, lens = cosine_parts(pa, pb, pc, pd)
    E = sp.sqrt(lens[0] * lens[1]) * uu + sp.sqrt(lens[2] * lens[3]) * vv
    want = sp.sign(det_abc) * sp.sign(incircle(pa, pb, pc, pd))
    if sp.sign(-E) != want or cosine_decision(uu, vv, ll, rr) != want:
        mismatch += 1
claim(cases > 50 and mismatch == 0,
      f"opposite sides: sign(-E) == cosine_decision == orient * incircle ({cases} cases)")

# ---- 6. the precondition matters: same side, both on the circle -> not "on" --------------
# circle x^2 + y^2 = 25, chord ab below the centre, c and d on the same (major) arc
pa, pb = (sp.Integer(-3), sp.Integer(-4)), (sp.Integer(3), sp.Integer(-4))
pc, pd = (sp.Integer(4), sp.Integer(3)), (sp.Integer(-4), sp.Integer(3))
uu, vv, ll, rr, _ = cosine_parts(pa, pb, pc, pd)
claim(incircle(pa, pb, pc, pd) == 0 and cosine_decision(uu, vv, ll, rr) != 0,
      "same side, cocircular: the cosine test does not answer 'on the circle' (cosine.md 3)")

if FAILED:
    print(f"{len(FAILED)} claim(s) failed")
    sys.exit(1)
print("all cosine claims hold")
