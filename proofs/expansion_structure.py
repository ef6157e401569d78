#!/usr/bin/env python3
"""The structure of the expansions that stage B estimates (bounds.md#expansion-estimate).

1. The counterexample to Shewchuk's Theorem 13 (Fast-Expansion-Sum keeps strongly
   nonoverlapping inputs strongly nonoverlapping), in binary64: expansion_sum of two
   nonadjacent expansions whose output is not strongly nonoverlapping, but is in class W.
2. Samples (not a proof) of conjecture W and of lemma E: near-degenerate inputs run through
   a transcription of the kernel's stage B code (predicates/src/expansion.hpp: two_sum,
   two_product, two_two_diff, two_two_sum, expansion_scale, expansion_sum; adaptive.cpp:
   incircle_row, incircle_of_rounded_differences, product_pair_adapt's B), in binary64
   (Python floats) and in a p-bit model (round to nearest even, unbounded exponent, integer
   values). Checked: orient2d's B is nonadjacent, incircle's fin is in W, and the estimate
   obeys lemma E with c = 7/3 (B, n = 4) and c = 40/7 (fin, its n), exactly (rationals).
   Also counted: fins that are not strongly nonoverlapping.

Exit code non-zero if the counterexample does not reproduce or a sample violates a check.
If the code transcribed here changes, change this file with it."""
import math
import random
import sys
from fractions import Fraction as Q

# ---- binary64 (Python floats: IEEE binary64, round to nearest even, no contraction) ----


def f_two_sum(a, b):
    x = a + b
    bv = x - a
    av = x - bv
    return x, (a - av) + (b - bv)


def f_split(a):
    c = 134217729.0 * a  # Dekker: 2^27 + 1
    hi = c - (c - a)
    return hi, a - hi


def f_two_product(a, b):
    """x + y == a * b exactly (Dekker's product; the kernel uses fma, with the same result)."""
    x = a * b
    ah, al = f_split(a)
    bh, bl = f_split(b)
    return x, al * bl - (((x - ah * bh) - al * bh) - ah * bl)


# ---- p-bit model: integers, rounded to P significant bits --------------------------------


def make_model(p):
    def rnd(x):
        a = abs(x)
        b = a.bit_length()
        if b <= p:
            return x
        sh = b - p
        m = a >> sh
        r = a - (m << sh)
        half = 1 << (sh - 1)
        if r > half or (r == half and (m & 1)):
            m += 1
        return (m << sh) if x >= 0 else -(m << sh)

    def two_sum(a, b):
        x = rnd(a + b)
        return x, a + b - x

    def two_product(a, b):
        x = rnd(a * b)
        return x, a * b - x

    return rnd, two_sum, two_product


# ---- the kernel's algorithms, on either arithmetic ----------------------------------------


class Kernel:
    def __init__(self, two_sum, two_product, add):
        self.two_sum, self.two_product, self.add = two_sum, two_product, add

    def two_two_diff(self, a1, a0, b1, b0):
        i, x0 = self.two_sum(a0, -b0)  # two_diff(a, b) == two_sum(a, -b): negation is exact
        j, k = self.two_sum(a1, i)
        i, x1 = self.two_sum(k, -b1)
        x3, x2 = self.two_sum(j, i)
        return [x0, x1, x2, x3]

    def two_two_sum(self, a1, a0, b1, b0):
        i, x0 = self.two_sum(a0, b0)
        j, k = self.two_sum(a1, i)
        i, x1 = self.two_sum(k, b1)
        x3, x2 = self.two_sum(j, i)
        return [x0, x1, x2, x3]

    def expansion_sum(self, e, f):
        h, i, j = [], 0, 0
        if not e and not f:
            return h
        def nxt():
            nonlocal i, j
            if j == len(f) or (i < len(e) and abs(e[i]) < abs(f[j])):
                i += 1
                return e[i - 1]
            j += 1
            return f[j - 1]
        q = nxt()
        while i + j < len(e) + len(f):
            q, hh = self.two_sum(q, nxt())
            if hh != 0:
                h.append(hh)
        if q != 0:
            h.append(q)
        return h

    def expansion_scale(self, e, b):
        if not e or b == 0:
            return []
        h = []
        q, hh = self.two_product(e[0], b)
        if hh != 0:
            h.append(hh)
        for c in e[1:]:
            p1, p0 = self.two_product(c, b)
            s, hh = self.two_sum(q, p0)
            if hh != 0:
                h.append(hh)
            q, hh = self.two_sum(p1, s)
            if hh != 0:
                h.append(hh)
        if q != 0:
            h.append(q)
        return h

    def estimate(self, e):
        s = 0
        for c in e:
            s = self.add(s, c)
        return s

    def incircle_row(self, x, y, p1, q1, p2, q2):
        a1, a0 = self.two_product(p1, q1)
        b1, b0 = self.two_product(p2, q2)
        cross = self.two_two_diff(a1, a0, b1, b0)
        xxc = self.expansion_scale(self.expansion_scale(cross, x), x)
        yyc = self.expansion_scale(self.expansion_scale(cross, y), y)
        return self.expansion_sum(xxc, yyc)

    def fin(self, adx, ady, bdx, bdy, cdx, cdy):
        a = self.incircle_row(adx, ady, bdx, cdy, cdx, bdy)
        b = self.incircle_row(bdx, bdy, cdx, ady, adx, cdy)
        c = self.incircle_row(cdx, cdy, adx, bdy, bdx, ady)
        return self.expansion_sum(self.expansion_sum(a, b), c)

    def orient_b(self, p, q, r, s, plus):
        first, first_tail = self.two_product(p, q)
        second, second_tail = self.two_product(r, s)
        make = self.two_two_sum if plus else self.two_two_diff
        return make(first, first_tail, second, second_tail)


# ---- structure ---------------------------------------------------------------------------


def bits(v):
    """(lsb, msb): exponents of the lowest and highest nonzero bit of a nonzero v."""
    v = abs(Q(v))
    n, d = v.numerator, v.denominator
    lsb = (n & -n).bit_length() - 1 - (d.bit_length() - 1)
    msb = n.bit_length() - d.bit_length()
    if Q(2) ** msb > v:
        msb -= 1
    return lsb, msb


def classify(e):
    """'nonadjacent', 'strong' (strongly nonoverlapping), 'W', or what breaks W."""
    nz = [c for c in e if c != 0]
    b = [bits(c) for c in nz]
    worst = "nonadjacent"
    prev_adjacent = False
    for k in range(len(nz) - 1):
        if abs(nz[k]) > abs(nz[k + 1]):
            return "not sorted"
        if b[k][1] >= b[k + 1][0]:
            return "overlapping"
        adjacent = b[k][1] + 1 >= b[k + 1][0]
        if adjacent:
            if prev_adjacent:
                return "adjacent to two"
            if b[k][0] != b[k][1]:
                return "adjacent, smaller not a power of two"
            if b[k + 1][0] != b[k + 1][1]:
                worst = "W"
            elif worst == "nonadjacent":
                worst = "strong"
        prev_adjacent = adjacent
    return worst


def lemma_e_holds(e, estimate, c, eps):
    nz = [Q(x) for x in e if x != 0]
    exact = sum(nz)
    if len(nz) < 2:
        return Q(estimate) == exact
    return abs(Q(estimate) - exact) <= c * eps * (1 + eps) ** (len(nz) - 2) * abs(exact)


# ---- the checks --------------------------------------------------------------------------


def counterexample():
    k = Kernel(f_two_sum, f_two_product, lambda a, b: a + b)
    e = [-(2.0**-4 + 2.0**-56), -(2.0**50)]
    f = [2.0**-6 + 2.0**-57, 2.0**-4, 2.0**60]
    h = k.expansion_sum(e, f)
    expected = [2.0**-57, 2.0**-6 - 2.0**-56, 2.0**60 - 2.0**50]
    ok = (classify(e) == "nonadjacent" and classify(f) == "nonadjacent" and h == expected
          and classify(h) == "W" and sum(map(Q, h)) == sum(map(Q, e)) + sum(map(Q, f)))
    print(("ok   " if ok else "FAIL ") + "counterexample to Theorem 13: expansion_sum of two "
          "nonadjacent expansions = " + ", ".join(x.hex() for x in h) + ": in W, not strongly "
          "nonoverlapping")
    return ok


def sample(name, k, eps, draw, near, n_samples, seed, orient_near=None):
    """near(x, rng) returns x[5] (possibly changing x) so that incircle's determinant nearly
    vanishes; orient_near(x, rng), if given, x[3] so that x[0] x[1] - x[2] x[3] does."""
    rng = random.Random(seed)
    counts, bad = {}, 0
    for _ in range(n_samples):
        x = [draw(rng) for _ in range(6)]
        x[5] = near(x, rng)
        fin = k.fin(*x)
        if orient_near is not None:
            x[3] = orient_near(x, rng)
        cls = classify(fin)
        counts[cls] = counts.get(cls, 0) + 1
        if cls not in ("nonadjacent", "strong", "W"):
            bad += 1
            print(f"FAIL {name}: fin {cls}: {x}")
        elif fin and not lemma_e_holds(fin, k.estimate(fin), Q(40, 7), eps):
            bad += 1
            print(f"FAIL {name}: lemma E (40/7) for fin: {x}")
        p, q, r = x[0], x[1], x[2]
        s = x[3]
        for plus in (False, True):
            b = k.orient_b(p, q, r, s, plus)
            if classify(b) != "nonadjacent":
                bad += 1
                print(f"FAIL {name}: orient2d B {classify(b)}: {p, q, r, s}")
            elif not lemma_e_holds(b, k.estimate(b), Q(7, 3), eps):
                bad += 1
                print(f"FAIL {name}: lemma E (7/3) for B: {p, q, r, s}")
    shown = ", ".join(f"{v} {c}" for c, v in sorted(counts.items()))
    print(("ok   " if bad == 0 else "FAIL ") + f"{name}: {n_samples} fins: {shown}; "
          "orient2d B nonadjacent; lemma E held")
    return bad == 0


def binary64_draw(rng):
    return math.ldexp(rng.uniform(-1, 1), rng.randint(-20, 20))


def binary64_near(x, rng):
    """The six differences of four points on a circle of random radius (coordinates rounded),
    the last point moved by one ulp half of the time: replaces x in place, returns cdy."""
    radius = math.ldexp(1.0, rng.randint(-20, 20))
    t = [rng.uniform(-math.pi, math.pi) for _ in range(4)]
    px = [radius * math.cos(a) for a in t]
    py = [radius * math.sin(a) for a in t]
    if rng.random() < 0.5:
        px[3] = math.nextafter(px[3], math.inf)
    x[:] = [px[0] - px[3], py[0] - py[3], px[1] - px[3], py[1] - py[3], px[2] - px[3],
            py[2] - py[3]]
    return x[5]


def binary64_orient_near(x, rng):
    if x[2] == 0:
        return x[3]
    s = x[0] * x[1] / x[2]
    return s + rng.randint(-2, 2) * math.ulp(s)


def model_check(p, n_samples, seed):
    rnd, two_sum, two_product = make_model(p)
    k = Kernel(two_sum, two_product, lambda a, b: rnd(a + b))

    def draw(rng):
        b = rng.randint(1, 3 * p)
        if rng.random() < 0.3:
            m = rng.choice([1, 3, (1 << p) - 1, (1 << (p - 1)) + 1, 1 << (p - 1)])
            v = m << max(0, b - m.bit_length())
        else:
            v = rng.getrandbits(b) | (1 << (b - 1))
        return rnd(v) * rng.choice([-1, 1])

    def near(x, rng):
        if x[2] != 0:
            x[3] = rnd(x[0] * x[1] // x[2] + rng.randint(-2, 2)) or 1
        adx, ady, bdx, bdy, cdx, _ = x
        la, lb, kk = adx * adx + ady * ady, bdx * bdx + bdy * bdy, adx * bdy - bdx * ady
        a_, b_, c_ = kk, la * bdx - lb * adx, kk * cdx * cdx - la * cdx * bdy + lb * cdx * ady
        disc = b_ * b_ - 4 * a_ * c_
        if kk == 0 or disc < 0:
            return draw(rng)
        root = (-b_ + rng.choice([-1, 1]) * math.isqrt(disc)) // (2 * a_)
        return rnd(root + rng.randint(-2, 2))

    return sample(f"{p}-bit model", k, Q(1, 2**p), draw, near, n_samples, seed)


def main():
    ok = counterexample()
    k64 = Kernel(f_two_sum, f_two_product, lambda a, b: a + b)
    ok &= sample("binary64", k64, Q(1, 2**53), binary64_draw, binary64_near, 20000, 1,
                 binary64_orient_near)
    for p, n in ((4, 4000), (6, 4000)):
        ok &= model_check(p, n, p)
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
