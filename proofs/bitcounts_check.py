#!/usr/bin/env python3
"""Brute-force check of proofs/bitcounts.md on small integer grids.

Evaluates the formulas of predicates/src/formulas.hpp in exactly their order with every
+, -, * rounded to p significant bits (round to nearest even, unbounded exponent: what
MPFR does at precision p), for coordinates that are b-bit integers (|x| < 2^b), and checks:
  * at p = the derived bound, every intermediate is exact (so the sign is exact);
  * at smaller p, some configuration gives a wrong sign or an inexact intermediate
    (how far below the bound wrong signs start is printed: the bound is sufficient,
    not claimed tight).
Exit code non-zero if the bound fails anywhere.
"""
import itertools
import random
import sys


def round_to(x, p):
    """x rounded to p significant bits, ties to even (exact integers in, exact integers out)."""
    if x == 0:
        return 0
    n = abs(x).bit_length()
    if n <= p:
        return x
    shift = n - p
    q, r = divmod(abs(x), 1 << shift)
    half = 1 << (shift - 1)
    if r > half or (r == half and q & 1):
        q += 1
    return (q << shift) * (1 if x > 0 else -1)


class Eval:
    def __init__(self, p):
        self.p, self.inexact = p, False

    def op(self, exact):
        r = round_to(exact, self.p) if self.p else exact
        self.inexact |= r != exact
        return r

    def add(self, a, b): return self.op(a + b)
    def sub(self, a, b): return self.op(a - b)
    def mul(self, a, b): return self.op(a * b)


def sign(x): return (x > 0) - (x < 0)


def orient(ev, a, b, c):
    abx, aby = ev.sub(b[0], a[0]), ev.sub(b[1], a[1])
    acx, acy = ev.sub(c[0], a[0]), ev.sub(c[1], a[1])
    return sign(ev.sub(ev.mul(abx, acy), ev.mul(aby, acx)))


def incircle(ev, a, b, c, d):
    adx, ady, bdx, bdy = ev.sub(a[0], d[0]), ev.sub(a[1], d[1]), ev.sub(b[0], d[0]), ev.sub(b[1], d[1])
    cdx, cdy = ev.sub(c[0], d[0]), ev.sub(c[1], d[1])
    al = ev.add(ev.mul(adx, adx), ev.mul(ady, ady))
    bl = ev.add(ev.mul(bdx, bdx), ev.mul(bdy, bdy))
    cl = ev.add(ev.mul(cdx, cdx), ev.mul(cdy, cdy))
    t1 = ev.mul(al, ev.sub(ev.mul(bdx, cdy), ev.mul(cdx, bdy)))
    t2 = ev.mul(bl, ev.sub(ev.mul(cdx, ady), ev.mul(adx, cdy)))
    t3 = ev.mul(cl, ev.sub(ev.mul(adx, bdy), ev.mul(bdx, ady)))
    return sign(ev.add(ev.add(t1, t2), t3))


def cosine(ev, a, b, c, d):
    adx, ady, bdx, bdy = ev.sub(a[0], d[0]), ev.sub(a[1], d[1]), ev.sub(b[0], d[0]), ev.sub(b[1], d[1])
    acx, acy, bcx, bcy = ev.sub(a[0], c[0]), ev.sub(a[1], c[1]), ev.sub(b[0], c[0]), ev.sub(b[1], c[1])
    u = ev.add(ev.mul(adx, bdx), ev.mul(ady, bdy))
    v = ev.add(ev.mul(acx, bcx), ev.mul(acy, bcy))
    su, sv = sign(u), sign(v)
    if su == sv:
        return -su
    sq = lambda x, y: ev.add(ev.mul(x, x), ev.mul(y, y))
    left = ev.mul(ev.mul(sq(acx, acy), sq(bcx, bcy)), ev.mul(u, u))
    right = ev.mul(ev.mul(sq(adx, ady), sq(bdx, bdy)), ev.mul(v, v))
    e = su if left > right else (sv if right > left else 0)  # comparison: exact in MPFR
    return -e


def distance(ev, c, p, q):
    pcx, pcy = ev.sub(p[0], c[0]), ev.sub(p[1], c[1])
    qcx, qcy = ev.sub(q[0], c[0]), ev.sub(q[1], c[1])
    plen = ev.add(ev.mul(pcx, pcx), ev.mul(pcy, pcy))
    qlen = ev.add(ev.mul(qcx, qcx), ev.mul(qcy, qcy))
    return sign(ev.sub(plen, qlen))


def orient3d(ev, a, b, c, d):  # orient3d_of_differences, d as the pivot
    adx, ady, adz = (ev.sub(a[i], d[i]) for i in range(3))
    bdx, bdy, bdz = (ev.sub(b[i], d[i]) for i in range(3))
    cdx, cdy, cdz = (ev.sub(c[i], d[i]) for i in range(3))
    t1 = ev.mul(adz, ev.sub(ev.mul(bdx, cdy), ev.mul(cdx, bdy)))
    t2 = ev.mul(bdz, ev.sub(ev.mul(cdx, ady), ev.mul(adx, cdy)))
    t3 = ev.mul(cdz, ev.sub(ev.mul(adx, bdy), ev.mul(bdx, ady)))
    return sign(ev.add(ev.add(t1, t2), t3))


def insphere(ev, a, b, c, d, e):  # insphere_of_differences, e as the pivot
    (aex, aey, aez), (bex, bey, bez), (cex, cey, cez), (dex, dey, dez) = (
        [ev.sub(p[i], e[i]) for i in range(3)] for p in (a, b, c, d))
    minor = lambda p, q, r, s: ev.sub(ev.mul(p, q), ev.mul(r, s))
    ab, bc = minor(aex, bey, bex, aey), minor(bex, cey, cex, bey)
    cd, da = minor(cex, dey, dex, cey), minor(dex, aey, aex, dey)
    ac, bd = minor(aex, cey, cex, aey), minor(bex, dey, dex, bey)
    abc = ev.add(ev.sub(ev.mul(aez, bc), ev.mul(bez, ac)), ev.mul(cez, ab))
    bcd = ev.add(ev.sub(ev.mul(bez, cd), ev.mul(cez, bd)), ev.mul(dez, bc))
    cda = ev.add(ev.add(ev.mul(cez, da), ev.mul(dez, ac)), ev.mul(aez, cd))
    dab = ev.add(ev.add(ev.mul(dez, ab), ev.mul(aez, bd)), ev.mul(bez, da))
    lift = lambda x, y, z: ev.add(ev.add(ev.mul(x, x), ev.mul(y, y)), ev.mul(z, z))
    alift, blift = lift(aex, aey, aez), lift(bex, bey, bez)
    clift, dlift = lift(cex, cey, cez), lift(dex, dey, dez)
    return sign(ev.add(ev.sub(ev.mul(dlift, abc), ev.mul(clift, dab)),
                       ev.sub(ev.mul(blift, cda), ev.mul(alift, bcd))))


BOUNDS = {  # bits, derived per intermediate in bitcounts.md; points, coordinates per point
    "orient2d": (orient, 3, 2, lambda b: 2 * b + 3),
    "compare_distance": (distance, 3, 2, lambda b: 2 * b + 3),
    "incircle": (incircle, 4, 2, lambda b: 4 * b + 8),
    "incircle_cosine": (cosine, 4, 2, lambda b: 8 * b + 12),
    "orient3d": (orient3d, 4, 3, lambda b: 3 * b + 6),
    "insphere": (insphere, 5, 3, lambda b: 5 * b + 12),
}


def configurations(npts, dim, b, rng, count):
    hi = (1 << b) - 1
    extremes = [-hi, hi, 0, 1 - hi, hi - 1]
    for _ in range(count):
        if rng.random() < 0.5:  # extremes maximise the differences and the lifts
            yield [tuple(rng.choice(extremes) for _ in range(dim)) for _ in range(npts)]
        else:
            yield [tuple(rng.randint(-hi, hi) for _ in range(dim)) for _ in range(npts)]


def main():
    rng = random.Random(2025)
    failed = False
    for name, (fn, npts, dim, bound) in BOUNDS.items():
        for b in (2, 3, 4):
            p_ok = bound(b)
            configs = list(configurations(npts, dim, b, rng, 4000))
            if name in ("orient2d", "compare_distance") and b == 2:  # exhaustive, 7 x 7 grid
                grid = [(x, y) for x in range(-3, 4) for y in range(-3, 4)]
                configs = [list(t) for t in itertools.product(grid, repeat=3)]
            bad_at_bound = 0
            wrong_below = {}
            for pts in configs:
                exact = fn(Eval(0), *pts)
                ev = Eval(p_ok)
                if fn(ev, *pts) != exact or ev.inexact:
                    bad_at_bound += 1
                for p in range(p_ok - 1, 0, -1):
                    if p in wrong_below:
                        continue
                    if fn(Eval(p), *pts) != exact:
                        wrong_below[p] = pts
                        break
            first_wrong = max(wrong_below) if wrong_below else None
            ok = bad_at_bound == 0
            failed |= not ok
            print(f"{'ok  ' if ok else 'FAIL'} {name:16s} b={b}: exact at p={p_ok} in "
                  f"{len(configs)} configurations; wrong signs first at p={first_wrong}")
    if failed:
        sys.exit(1)


if __name__ == "__main__":
    main()
