#!/usr/bin/env python3
"""Run the Gappa scripts in proofs/gappa/, read the intervals Gappa proved, and combine them
into the smallest safe value of every constant of predicates/ (bounds.md writes out each
combination; this script is that text as exact rational arithmetic).

Usage: derive_bounds.py GAPPA OUTPUT
Writes OUTPUT with one line per claim:  name kind p/q [if=CONDITION]  (exact rational)
  kind `min`: the code's value must be >= p/q;  kind `max`: it must be <= p/q.
  if=CONDITION: the claim is proven only if the named unproven statement holds
  (bounds.md names it; no claim is conditional today).
Exit code non-zero when Gappa fails to prove a goal or prints something unexpected.
"""
import re
import subprocess
import sys
from fractions import Fraction as Q
from math import floor, log2
from pathlib import Path

HERE = Path(__file__).resolve().parent
NUMBER = r"-?\d+(?:b-?\d+)?"
RESULT = re.compile(r"^\s*(.+?) in \[(" + NUMBER + r")(?: \{[^}]*\})?, (" + NUMBER + r")(?: \{[^}]*\})?\]\s*$")


def gappa_number(text):
    """Gappa prints exact dyadic numbers as MbE (M * 2^E) or plain integers."""
    mantissa, _, exponent = text.partition("b")
    return Q(int(mantissa)) * (Q(2) ** int(exponent or 0))


def run_gappa(gappa, script):
    """The proven interval of every goal of `script`, keyed by Gappa's spelling of it."""
    proc = subprocess.run([gappa, str(HERE / "gappa" / script)], capture_output=True, text=True)
    out = proc.stdout + proc.stderr
    if proc.returncode != 0 or "not satisfied" in out:
        sys.exit(f"{script}: Gappa did not prove every goal:\n{out}")
    if "not trivially equal" in out:
        # A rewriting hint that is not an identity: Gappa would still answer, with the
        # difference as an extra error, but the script's reading of the goal assumes it is.
        sys.exit(f"{script}: a rewriting hint is not an identity:\n{out}")
    goals = {}
    for line in out.splitlines():
        m = RESULT.match(line)
        if m:
            goals[m.group(1)] = (gappa_number(m.group(2)), gappa_number(m.group(3)))
    if not goals:
        sys.exit(f"{script}: no result in Gappa's output:\n{out}")
    return goals


def magnitude(goals, key):
    lo, hi = goals[key]
    return max(abs(lo), abs(hi))


def main():
    gappa, output = sys.argv[1], Path(sys.argv[2])

    # ---- Lemmas (Gappa) -----------------------------------------------------------------
    rnd = run_gappa(gappa, "rounding.g")
    eps_exact = magnitude(rnd, "float<53,-1074,ne>(x) -/ x")
    res = run_gappa(gappa, "rounding_result.g")
    eps_result = max(magnitude(res, "(xp - zp) / zp"), magnitude(res, "(xn - zn) / zn"))
    # R2's certificate is coq/rounding_result.v, which proves the bound 2^-53: a tighter
    # value from Gappa would be used without a certificate.
    if eps_result < Q(1, 2**53):
        sys.exit(f"rounding_result.g: {eps_result} is below the 2^-53 of coq/rounding_result.v")
    e = max(eps_exact, eps_result)  # one rounding, either way round
    under = run_gappa(gappa, "underflow.g")
    eta = max(magnitude(under, "p - a * b"), magnitude(under, "s - (a + b)"))
    term = run_gappa(gappa, "orient_term.g")
    term_rel = (1 + magnitude(term, "P -/ Lx")) * (1 + magnitude(term, "L -/ P")) - 1

    def delta(k):
        """k roundings compose to a relative error of at most (1 + e)^k - 1."""
        return (1 + e) ** k - 1

    if term_rel > delta(3):
        sys.exit(f"orient_term.g: Gappa's term error {float(term_rel)} exceeds (1+e)^3-1")

    claims = []

    # ---- orient2d and the dot products, stage A (bounds.md#orient2d) ----------------------
    # |D - Dx| <= e|D| + d3 (|L|+|R|) + U,  |L|+|R| <= (1+e) T,  errbound >= (ccw_a T/(1+e) - eta
    # + underflow)/(1+e); the sign is right when d3 (1+e) T + U <= (1-e) errbound.
    claims.append(("ccw_a", "min", delta(3) * (1 + e) ** 3 / (1 - e)))
    u_orient = 2 * (1 + 2 * delta(3)) * eta + eta  # two products, the subtraction
    claims.append(("underflow_orient", "min", eta + u_orient * (1 + e) / (1 - e)))

    # ---- compare_distance, stage A (bounds.md#compare-distance) ---------------------------
    # One square: Gappa's rounded difference squared and the square's rounding; with the
    # length's sum, four roundings per squared length.
    square = run_gappa(gappa, "distance_term.g")
    square_rel = (1 + magnitude(square, "P -/ Sx")) * (1 + magnitude(square, "S -/ P")) - 1
    if square_rel > delta(3):
        sys.exit(f"distance_term.g: Gappa's square error {float(square_rel)} exceeds (1+e)^3-1")
    length_rel = max(delta(4), (1 + square_rel) * (1 + e) - 1)
    # |D - Dx| <= e|D| + length_rel (lp + lq) + U, lp + lq <= (1+e) T: as for orient2d.
    claims.append(("dist_a", "min", length_rel * (1 + e) ** 3 / (1 - e)))
    # U: four squares may underflow (eta each, through (1+e)^2), and Gappa's weaker eta for
    # the three sums (lp, lq, D), which are in fact exact when subnormal.
    u_dist = 4 * (1 + e) ** 2 * eta + 3 * eta
    claims.append(("underflow_dist", "min", eta + u_dist * (1 + e) / (1 - e)))

    # ---- the radial key (bounds.md#radial-key) ---------------------------------------------
    # Hypotheses of the derivation (checked against the code's limits): key in
    # [2^-1000, 2^1022].
    key_min, key_max = Q(2) ** -1000, Q(2) ** 1022
    claims.append(("radial_key_min", "min", key_min))
    claims.append(("radial_key_max", "max", key_max))
    # key = (1 + c) sum (X_i^2 (1 + a_i)^2 (1 + b_i) + h_i): relative to the exact K,
    # |key - K| <= length_rel K + h_key with h_key the two squares' and the sum's eta.
    h_key = 2 * eta * (1 + e) + eta
    k_low = (key_min - h_key) / (1 + e) ** 4  # the smallest K a key >= key_min allows
    rel_to_exact = length_rel + h_key / k_low
    # Relative to the key: K <= (key + h_key) / (1 - e)^4.
    grow = length_rel / (1 - e) ** 4
    rel_to_key = grow + h_key * (1 + grow) / key_min
    claims.append(("radial_key_rel", "min", max(rel_to_exact, rel_to_key)))

    # ---- incircle, stage A (bounds.md#incircle) -----------------------------------------
    # Error of one term alift * (P1 - P2), relative to alift * (|P1| + |P2|):
    c_term = ((1 + delta(4)) * (e * (1 + e) + delta(3))  # the cross difference, scaled by alift
              + delta(4) * (1 + e)                        # the lift's four roundings
              + e * (1 + e) ** 2                          # the product's rounding
              + e * (1 + e) ** 2)                         # the first sum's rounding
    # (1+e)^4: computed sa and permanent against the exact ones; (1+e)^2 the bound's roundings.
    claims.append(("icc_a", "min", c_term * (1 + e) ** 6 / (1 - e)))
    # Underflow: 2 eta per lift and per cross difference (scaled by the partner), 6 eta for
    # the three outer products, two sums and the bound's product; (1+e)^3 the sum X.
    k_under = max(2 * (1 + e) ** 4, 7 * (1 + e) ** 5)
    claims.append(("underflow_incircle", "min", k_under * eta * (1 + e) ** 4 / (1 - e)))

    # ---- incircle, semi-static filter (bounds.md#incircle-semi-static) ---------------------
    # M = max |x| over the six rounded differences x; hypotheses (checked against the code):
    # 2^-240 <= M <= 2^250. Everything below is a multiple of M^4.
    m_min, m_max = Q(2) ** -240, Q(2) ** 250
    claims.append(("icc_static_min", "min", m_min))
    claims.append(("icc_static_max", "max", m_max))
    # (1) D(x) against D(X): 12 monomials, each |m(x)| <= M^4, x = X (1 + d), |d| <= e.
    diffs = 12 * ((1 - e) ** -4 - 1)
    # (2) evaluating D(x): per term L P with L <= 2M^2, |P| <= 2M^2 (in units of M^4):
    #   |L~ - L| <= delta(2) 2,  |P~ - P| <= e (2 + e) 2,  |L~|, |P~| <= (1+e)^2 2,
    #   |T~ - L P| <= |L~ - L||P~| + L |P~ - P| + e |L~ P~|,  |T~| <= (1+e)^5 4.
    term = 4 * (delta(2) * (1 + e) ** 2 + e * (2 + e) + e * (1 + e) ** 4)
    sums = e * 8 * (1 + e) ** 5 + e * (8 * (1 + e) ** 6 + 4 * (1 + e) ** 5)
    # Underflow: 15 products, each at most eta, scaled by a partner <= (1+e)^2 2M^2; with
    # M >= 2^-240, eta M^2 <= eta 2^480 M^4.
    under = 15 * eta * 2 * (1 + e) ** 2 * Q(2) ** 480 + 3 * eta * Q(2) ** 960
    total = diffs + 3 * term + sums + under
    # The bound is computed as fl(icc_static * fl(fl(M M) fl(M M))): three roundings down.
    claims.append(("icc_static", "min", total / (1 - e) ** 3))

    # ---- stages B and C (bounds.md#expansion-estimate, bounds.md#stages-b-and-c) ----------
    # Per-step lemma of the estimate (estimate_step.g): R1 for a sum of two doubles above
    # 2^-1021, exact below (granular.g: a multiple of 2^-1074 of at most 53 bits is a double).
    step = run_gappa(gappa, "estimate_step.g")
    e_step = magnitude(step, "z -/ x")
    gran = run_gappa(gappa, "granular.g")
    if gran["z - x"] != (0, 0):
        sys.exit("granular.g: Gappa did not prove that a granular 53-bit value rounds exactly")
    if magnitude(gran, "float<53,-1074,ne>(v) - v") > eta:
        sys.exit("granular.g: the subnormal rounding error exceeds eta")
    if e_step > e:
        sys.exit(f"estimate_step.g: the step error {float(e_step)} exceeds one rounding")

    def estimate_rel(c, n):
        """Lemma E: an n-component expansion whose partial sums satisfy
        sum_{k>=2} |S_k| <= c |E| is estimated with |est - E| <= rho |E|, and then
        |est - E| <= rho / (1 - rho) |est| (the form the filters use)."""
        rho = e_step * c * (1 + e_step) ** (n - 2)
        return rho / (1 - rho)

    # c for the two classes of expansions the kernel estimates (bounds.md#expansion-estimate):
    # nonadjacent (orient2d's Two_Two_Diff, 4 components): 1 + 4/3;
    # class W (at most 96 components): 1 + 33/7. Incircle's fin is not in W by any theorem
    # (Shewchuk's Theorem 13, which would make it strongly nonoverlapping, is false); the
    # code checks it at run time (expansion.hpp, in_class_w) and goes to the exact stage
    # otherwise, so the claims below that use est_incircle are unconditional.
    est_orient = estimate_rel(Q(7, 3), 4)
    est_incircle = estimate_rel(Q(40, 7), 96)

    # Lemma G (bounds.md#lemma-g-deciding-against-a-rounded-bound): |d| > fl(fl(y1) + fl(y2))
    # implies |d| > (y1 + y2) / g2. Its case F >= 2^-1021 uses 2 eta <= eps F.
    g2 = (1 + e) ** 2 + e
    if 2 * eta > e * Q(2) ** -1021:
        sys.exit("lemma G: 2 eta exceeds eps 2^-1021")

    # orient2d stage B: |B - Dx| <= (2e + e^2)(|pq| + |rs|) <= (2e + e^2)(1+e)^2 T; the
    # estimate errs by est_orient |det|; lemma G: |det| > fl(ccw_b T) gives
    # |det| > ccw_b T / (1+e).
    claims.append(("ccw_b", "min", (2 * e + e * e) * (1 + e) ** 3 / (1 - est_orient)))
    # orient2d stage C: dropped tail products e^2 (|pq| + |rs|); the correction's first-order
    # terms sum to at most 2e (|pq| + |rs|) and carry two roundings each plus the
    # difference's e (|c1| + |c2|); (1+e)^2 to T; lemma G (g2), the final addition's
    # e |det_C| absorbed: g2 / (1-e).
    tail_terms = ((delta(2) + e * (1 + e) ** 2) * 2 * e + e * e) * (1 + e) ** 2
    claims.append(("ccw_c", "min", tail_terms * g2 / (1 - e)))
    # result_err covers the estimate of stage B in both predicates' stage C (incircle's
    # requirement is the larger).
    claims.append(("result_err", "min", est_orient * g2 / (1 - e)))
    claims.append(("result_err", "min", est_incircle * g2 / (1 - e)))
    # incircle stage B: each of the 12 monomials of four differences errs by d_4 relative to
    # its value in the rounded differences, whose sum of magnitudes is at most (1+e)^7
    # times the computed permanent; lemma G one rounding; the estimate est_incircle |det|.
    claims.append(("icc_b", "min", delta(4) * (1 + e) ** 8 / (1 - est_incircle)))
    # incircle stage C, per row in units of lift * (|p1| + |p2|): dropped terms
    # 6e^2 + 4e^3 + e^4; the correction's two products carry 2e and 2e of magnitude with
    # 9 and 8 roundings; (1+e)^7 to the permanent; lemma G g2, absorbed e: 1/(1-e).
    icc_tail = (6 * e ** 2 + 4 * e ** 3 + e ** 4) + 2 * e * delta(9) + 2 * e * delta(8)
    claims.append(("icc_c", "min", icc_tail * (1 + e) ** 7 * g2 / (1 - e)))

    # ---- the cosine squared comparison (bounds.md#cosine) -------------------------------
    # Hypotheses of the derivation, themselves checked against the code: the filter is tried
    # only for du, dv <= 1/4, and only when every guarded factor is >= 2^-1000.
    dmax, cmf = Q(1, 4), Q(2) ** -1000
    claims.append(("cos_max_dot_rel", "max", dmax))
    claims.append(("cos_min_factor", "min", cmf))

    def lam(du):
        """Relative error of L~ (relative to the result) when the computed du is `du`."""
        gamma = e + du * (1 + e) ** 2  # u~ against u: e|u~| + eu, du rounded twice
        squares = 4 * 2 * eta / cmf * (1 + e) ** 2  # underflowed squares in 4 lengths
        return (1 + e) ** 11 * (1 + gamma) ** 2 - 1 + squares

    factor = (1 + e) / (1 - e) ** 4  # the comparison's and the bound's own roundings
    cos_rel_min = lam(Q(0)) * factor
    claims.append(("cos_rel", "min", cos_rel_min))
    # lam is convex in du and the bound is linear: both end points suffice. With
    # cos_rel >= cos_rel_min, this cos_rel_dot makes the line pass above lam at du = dmax.
    claims.append(("cos_rel_dot", "min", (lam(dmax) * factor - cos_rel_min) / dmax))

    # ---- expansion range (bounds.md#expansion-range) -------------------------------------
    for script, name, degree, key in (("range_orient.g", "orient_max_log", 2, None),
                                      ("range_incircle.g", "incircle_max_log", 4, "tree"),
                                      ("range_distance.g", "distance_max_log", 2, None),
                                      # adaptive3d.cpp (bounds.md#expansion-range)
                                      ("range_orient3d.g", "orient3d_max_log", 3, "tree"),
                                      ("range_insphere.g", "insphere_max_log", 5, "tree")):
        # (incircle_cosine's exact stage uses cpp_int, which has no range limit; its dot
        # products run the orient2d-shaped stages under orient_max_log.)
        goals = run_gappa(gappa, script)
        k = magnitude(goals, key or next(iter(goals)))
        # K 2^(d (E + 1)) <= 2^1023
        max_log = floor((1023 - log2(k)) / degree) - 1
        if k * Q(2) ** (degree * (max_log + 1)) > Q(2) ** 1023:  # log2 in floating point
            sys.exit(f"{script}: {name} = {max_log} fails K 2^(d (E + 1)) <= 2^1023")
        claims.append((name, "max", Q(max_log)))
        # expansion_safe's granularity test needs at least the polynomial's degree
        # (sympy/cosine_check.py checks these degrees symbolically).
        claims.append((name.replace("max_log", "degree"), "min", Q(degree)))

    # ---- the circumcentre (bounds.md#circumcenter) ------------------------------------------
    # Hypotheses of the derivation (the range conditions of construct.cpp), claimed against
    # constants.hpp: M = max |rounded difference| in [min_scale, max_scale], every nonzero
    # rounded difference at least M min_part, |a|, |s| <= max_offset, w = a - s zero or at
    # least min_offset (stage 1: u zero or at least min_offset). Every range below is
    # derived from these five values.
    min_scale, max_scale, min_part = Q(2) ** -150, Q(2) ** 150, Q(2) ** -100
    min_off, max_off = Q(2) ** -400, Q(2) ** 400
    claims.append(("circumcenter_min_scale", "min", min_scale))
    claims.append(("circumcenter_max_scale", "max", max_scale))
    claims.append(("circumcenter_min_part", "min", min_part))
    claims.append(("circumcenter_min_offset", "min", min_off))
    claims.append(("circumcenter_max_offset", "max", max_off))
    eps = Q(1, 2 ** 53)       # bounds::epsilon, a factor in the code's formulas
    normal = Q(2) ** -1021    # R1 and R2 hold from here up (rounding.g, rounding_result.g)
    huge = Q(2) ** 1023

    def require(ok, what):
        if not ok:
            sys.exit(f"circumcenter: range condition fails: {what}")

    m_lo = min_scale * min_part   # smallest nonzero |rounded difference| (2^-250)
    m_hi = max_scale * (1 + e)    # largest |exact difference|
    x_lo = m_lo * (1 - e)         # smallest nonzero |exact difference|

    # Stage 1, F1: |d - D| <= circumcenter_float_rel * fl(|p1| + |p2|), the same for N.
    # Every product of two (three) nonzero differences is at least m_lo^2 (m_lo^3 (1-e)^2):
    # no product underflows, so R1 holds for every operation (sums: estimate_step.g).
    require(m_lo ** 3 * (1 - e) ** 2 >= normal, "stage 1 products are normal")
    require(8 * (1 + e) ** 5 * max_scale ** 3 < huge, "stage 1 products are finite")
    # D's monomial: two rounded differences and the product (orient_term.g), relative to
    # the exact monomial; relative to the computed one it is d3 / (1 - d3). The final
    # subtraction adds e |p1 - p2|, and |p1| + |p2| <= (1 + e) fl(|p1| + |p2|).
    d3 = max(delta(3), term_rel)
    c_d = (e + d3 / (1 - d3)) * (1 + e)
    # N's monomial cy (bx^2 + by^2): the difference cy, the square (distance_term.g: a
    # rounded difference squared, rounded), the sum of the two squares (nonnegative), the
    # product: six roundings; then the subtraction and the permanent's sum, as for D.
    d6 = max(delta(6), (1 + e) ** 3 * (1 + square_rel) - 1)
    c_n = (e + d6 / (1 - d6)) * (1 + e)
    claims.append(("circumcenter_float_rel", "min", max(c_d, c_n)))

    # Stage 1, F2: the offset's bound. The quotient u = fl(n fl(1 / (2d))) has the relative
    # error q_rel (circumcenter_quotient.g) against q = n / (2d), given the ranges below.
    quot = run_gappa(gappa, "circumcenter_quotient.g")
    q_rel = magnitude(quot, "u -/ q")
    # The ranges the Gappa script assumes (n, d > 0 by symmetry), against those derived:
    #   |d| > 2 ed >= 16 eps (1-e) (M part)^2 and |d| <= 2 (1+e)^2 M^2;
    #   n != 0: |n| >= Qmin 2^-53, Qmin = (1-e)^2 (M part)^3 the smallest nonzero computed
    #   product (both products are multiples of 2^(floor(log2 Qmin) - 52)); |n| <= 4(1+e)^4 M^3;
    #   q = n / (2d) in [|n|min / (4 (1+e)^2 M^2), 4 (1+e)^4 M^3 / (32 eps (1-e) (M part)^2)].
    d_lo = 16 * eps * (1 - e) * m_lo ** 2
    d_hi = 2 * (1 + e) ** 2 * max_scale ** 2
    n_lo = (1 - e) ** 2 * m_lo ** 3 * Q(2) ** -53
    n_hi = 4 * (1 + e) ** 4 * max_scale ** 3
    # |q| >= |n| / |2d| >= (1-e)^2 (M part)^3 2^-53 / (4 (1+e)^2 M^2): smallest at M = min_scale.
    q_lo = (1 - e) ** 2 * min_part ** 3 * min_scale * Q(2) ** -55 / (1 + e) ** 2
    q_hi = max_scale * (1 + e) ** 4 / (8 * eps * (1 - e) * min_part ** 2)
    require(Q(2) ** -560 <= d_lo and d_hi <= Q(2) ** 310, "d in circumcenter_quotient.g's range")
    require(Q(2) ** -810 <= n_lo and n_hi <= Q(2) ** 460, "n in circumcenter_quotient.g's range")
    require(Q(2) ** -510 <= q_lo and q_hi <= Q(2) ** 1000, "q in circumcenter_quotient.g's range")
    # The bound's own operations are normal: 2 |u| ed >= 2 min_offset ed (u != 0), 2 eps |u|,
    # and en slack >= 8 eps Qmin (1-e) / ((1+e)^3 2 M^2) (en != 0), smallest at M = min_scale.
    require(2 * min_off * 8 * eps * (1 - e) * m_lo ** 2 >= normal, "2 |u| ed is normal")
    require(2 * eps * min_off >= normal, "2 eps |u| is normal")
    en_slack_lo = (8 * eps * (1 - e) ** 3 * min_part ** 3 * min_scale
                   / (2 * (1 + e) ** 3))
    require(en_slack_lo / 2 >= normal, "en slack is normal")
    # |N/(2D) - u| <= (X/2 + q_rel |u|) / (1 - q_rel),  X = (en + 2|u| ed) / (|d| - ed);
    # computed e >= (1-e)^2 (1+f) [(1-e)^4 / (1+e) X/2 + 2 eps |u|]: f covers both terms when
    f_x = (1 + e) / ((1 - e) ** 6 * (1 - q_rel)) - 1
    f_u = q_rel / (2 * eps * (1 - e) ** 2 * (1 - q_rel)) - 1
    # (the checker compares the code's factor minus 1 with this excess)
    claims.append(("circumcenter_float_factor", "min", max(f_x, f_u)))
    # F3: fl(fl(|r| + e)(1 + m)) < h implies |r| + e < h when (1-e)^2 (1 + m) >= 1
    # (|r| + e is 0 or at least min(2 eps min_offset, en slack / 2): normal).
    margin_1 = 1 / (1 - e) ** 2 - 1

    # Stage 2, lemma DW: add errs by at most alpha (|x| + |y|), mul by beta |x||y| plus the
    # absolute underflow terms (bounds.md); alpha, beta relative to the double words' values
    # (|xh| <= |x| / (1 - e) for a normalized double word).
    if e > Q(1, 2 ** 53):
        sys.exit("dw_product.g assumes one rounding errs by at most 2^-53")
    dwp = run_gappa(gappa, "dw_product.g")
    beta_h = max(magnitude(dwp, "err"), e ** 2 * (8 + 6 * e + 2 * e ** 2))
    beta = beta_h / (1 - e) ** 2
    alpha = e ** 2 * (3 + e) / (1 - e)
    # Underflow: each of mul's two low products may add eta (P), carried through c's and w's
    # roundings; Two-Product is exact when |xh yh| >= 2^-969 (Boldo 2006, for Dekker's
    # algorithm; with a fused multiply-add as well), and otherwise (only 2D w can be that
    # small) errs by at most tp_err: Dekker's four products and four sums, each exact
    # result at most (1+e)^4 (((1 + 2^-25)^2 + 1) A + 4 eta) with A = |ab| < 2^-969.
    u_low = (1 + e) ** 2 * 2 * eta
    tp_a = Q(2) ** -969
    split = (1 + Q(2) ** -25) ** 2
    tp_err = e * split * tp_a + 4 * eta + 4 * e * (1 + e) ** 4 * ((split + 1) * tp_a + 4 * eta)
    u_tp = (1 + e) * tp_err
    # Smallest nonzero permanents of the products (the exact differences are 0 or >= x_lo):
    t1_min = x_lo ** 2                       # X Y (D's monomials, the squares)
    t3_min = x_lo ** 3                       # CY BB and the like (N's monomials)
    t4_min = 2 * x_lo ** 2 * (1 - e) * min_off   # 2 T_D |w|, w != 0
    require(m_lo ** 2 >= tp_a and (1 - e) ** 4 * m_lo ** 3 >= tp_a, "the differences' Two-Products are exact")
    # 2 D.hi w.hi: |D.hi| > 2 d_error >= 2 eps^2 m_lo^2 (circumcenter_rel >= eps^2, below), so
    # the product is normal and Dekker's split of 2 D.hi is exact (no operation underflows).
    a_lo = 4 * e ** 2 * m_lo ** 2
    require(a_lo * min_off >= normal and min(a_lo, min_off) * Q(2) ** -53 >= Q(2) ** -1022,
            "2 D w does not underflow")
    theta_1 = beta + u_low / t1_min
    theta_d = theta_1 * (1 + alpha) + alpha          # D = add(mul, -mul); also |b|^2, |c|^2
    theta_bb = theta_d
    theta_3 = (1 + beta) * (1 + theta_bb) - 1 + u_low / t3_min
    theta_n = theta_3 * (1 + alpha) + alpha
    theta_4 = (1 + beta) * (1 + theta_d) - 1 + (u_low + u_tp) / t4_min
    theta_f = max(theta_n, theta_4) * (1 + alpha) + alpha
    # The permanents the code computes from the high parts: T_N <= kappa_n tn,
    # 2 T_D |w| <= (1+e)^5 2 td |w.hi|, and tn + 2 td |w.hi| <= (1+e)^2 fl(...).
    kappa = max((1 + e) ** 4 / (1 - theta_bb), (1 + e) ** 5)
    # |D~ - D| <= d_error and |F~ - F| <= (1 + e) f_error:
    rel = max(theta_d * (1 + e) ** 4, theta_f * kappa * (1 + e))
    require(rel >= e ** 2, "circumcenter_rel >= eps^2 (used above)")
    claims.append(("circumcenter_rel", "min", rel))
    # f_error is 0 or normal (then lhs is normal too); everything stays finite:
    require(e ** 2 * min(t3_min, t4_min) * (1 - e) ** 4 >= normal, "f_error is normal")
    t_f_max = 4 * (1 + e) ** 3 * m_hi ** 3 + 2 * 2 * m_hi ** 2 * 2 * max_off * (1 + e)
    require(4 * t_f_max < huge, "stage 2 finite")
    # The acceptance test: (1-e)^2 (1+m) lhs-side against (1+e)^3 (1-m) rhs-side, and
    # |F| <= (1+e)(|F.hi| + f_error), |D| >= (1-e)(|D.hi| - d_error):
    g = (1 + e) ** 4 / (1 - e) ** 3
    claims.append(("circumcenter_margin", "min", max(margin_1, (g - 1) / (g + 1))))

    # ---- incircle, double-word stage (bounds.md#incircle-double-word) ---------------------
    # Hypotheses (adaptive.cpp's range test): every nonzero high part of a difference has
    # magnitude in [dw_lo, dw_hi]; a difference is exact (Two-Diff) and normalized, so its
    # exact value is 0 or in [(1 - e) dw_lo, (1 + e) dw_hi].
    dw_lo, dw_hi = Q(2) ** -220, Q(2) ** 220
    claims.append(("icc_dw_min", "min", dw_lo))
    claims.append(("icc_dw_max", "max", dw_hi))
    y_lo, y_hi = dw_lo * (1 - e), dw_hi * (1 + e)

    def require_dw(ok, what):
        if not ok:
            sys.exit(f"incircle double-word stage: range condition fails: {what}")

    # No overflow: lifts and crosses are at most 2 y_hi^2 (1 + theta), their products 4 y_hi^4,
    # the determinant three of those; Dekker's split (Boldo) needs operands <= 2^995 and
    # products <= 2^1021; the computed permanent is no larger than the determinant's bound.
    lift_hi = 2 * y_hi ** 2 * (1 + e) ** 4
    require_dw(lift_hi <= Q(2) ** 995 and 3 * lift_hi ** 2 * (1 + e) ** 6 <= Q(2) ** 1021,
               "no overflow, Dekker's split applies")
    # Underflow enters only through lemma DW's absolute terms u_low (low products) and u_tp
    # (an inexact Two-Product: applied to every product, although only a degree-4 product
    # can be small enough), against the least nonzero permanent of each product.
    t2_min = y_lo ** 2                       # X Y: the lifts' squares and the crosses' products
    t4_min = y_lo ** 4                       # lift x cross
    th_1 = beta + (u_low + u_tp) / t2_min
    th_2 = th_1 * (1 + alpha) + alpha        # lifts and crosses: add(mul, +-mul)
    th_4 = (1 + beta) * (1 + th_2) ** 2 - 1 + (u_low + u_tp) / t4_min
    th_s = th_4 * (1 + alpha) + alpha        # the first two terms
    th_det = th_s * (1 + alpha) + alpha      # all three
    # T <= kappa t: A <= (1 + e) lift.hi / (1 - th_2), |X| <= (1 + e) |X.hi|, and five
    # roundings (R2; every nonzero intermediate of t is at least (1 - e)^8 y_lo^4, normal).
    kappa_dw = (1 + e) ** 8 / (1 - th_2)
    require_dw((1 - e) ** 8 * y_lo ** 4 * e ** 2 >= normal, "t and the bound are normal")
    # Deciding: |det.hi| > fl(icc_dw t) >= icc_dw t / (1 + e) and |D~| >= (1 - e) |det.hi|.
    claims.append(("icc_dw", "min", th_det * kappa_dw * (1 + e) / (1 - e)))

    # ---- incircle_cosine, double-word stage (bounds.md#cosine-double-word) ---------------
    # The same rules for L - R = ac2 bc2 u^2 - ad2 bd2 v^2 (degree 8), every nonzero high part
    # of the eight differences in [cw_lo, cw_hi].
    cw_lo, cw_hi = Q(2) ** -110, Q(2) ** 110
    claims.append(("cos_dw_min", "min", cw_lo))
    claims.append(("cos_dw_max", "max", cw_hi))
    z_lo, z_hi = cw_lo * (1 - e), cw_hi * (1 + e)
    z2 = 2 * z_hi ** 2 * (1 + e) ** 4               # lifts and |u|, |v|
    require_dw(z2 ** 2 * (1 + e) ** 6 <= Q(2) ** 995 and z2 ** 4 * (1 + e) ** 12 <= Q(2) ** 1020,
               "cosine: no overflow, Dekker's split applies")
    c_2 = beta + (u_low + u_tp) / z_lo ** 2
    c_2 = c_2 * (1 + alpha) + alpha                  # u, v and the four squared lengths
    c_4 = (1 + beta) * (1 + c_2) ** 2 - 1 + (u_low + u_tp) / z_lo ** 4   # ac2 bc2, u u
    c_8 = (1 + beta) * (1 + c_4) ** 2 - 1 + (u_low + u_tp) / z_lo ** 8   # L, R
    c_diff = c_8 * (1 + alpha) + alpha
    # T <= kappa t: two lifts, (1 + e) / (1 - c_2) each; T_u <= (1 + e)^2 times the exact sum
    # of the high products, which is at most (1 + e)^2 tu, squared; and the roundings of
    # tu * tu, the lifts' product, their product and the final sum (R2; every nonzero
    # intermediate is at least (1 - e)^16 z_lo^8, normal): (1 + e)^(2 + 8 + 4).
    kappa_c = (1 + e) ** 14 / (1 - c_2) ** 2
    require_dw((1 - e) ** 16 * z_lo ** 8 * e ** 2 >= normal, "cosine: t and the bound are normal")
    claims.append(("cos_dw", "min", c_diff * kappa_c * (1 + e) / (1 - e)))

    # ==== The predicates of space (adaptive3d.cpp) ==========================================

    def require_3d(ok, what):
        if not ok:
            sys.exit(f"orient3d / insphere: range condition fails: {what}")

    # Every absolute (underflow) term below is carried by at most sixteen factors (1 + e) on
    # its way to the determinant: a partner's exact value against its computed one, and each
    # later rounding's relative error, which scales the absolute term it carries (bounds.md).
    carry = (1 + e) ** 16

    # ---- orient3d, stage A (bounds.md#orient3d) -------------------------------------------
    # One term z * fl(P1 - P2) against |z| sa, sa = |P1| + |P2| (computed z, products; by R2
    # each exact monomial is the computed product times three roundings): the minor errs by
    # e |m| + d3 sa with |m| <= (1+e) sa; z by d1; the product by z and the first sum one
    # rounding each (e (1+e)^2, as for incircle); the last sum e |D|, free.
    c_o3 = ((1 + delta(1)) * (e * (1 + e) + delta(3))  # the minor, scaled by |Z| <= (1+e)|z|
            + delta(1) * (1 + e)                        # z's own rounding, |m| <= (1+e) sa
            + e * (1 + e) ** 2                          # the product z * m
            + e * (1 + e) ** 2)                         # the first sum
    # (1+e)^4: sum |z| sa against the computed permanent (the pair's sum, the product by
    # |z|, the two sums); (1+e)^2 the bound's two roundings; 1/(1-e) the sign argument.
    claims.append(("o3d_a", "min", c_o3 * (1 + e) ** 6 / (1 - e)))
    # Underflow (bounds.md#underflow-3d), in units of eta against S = Z + 1 (Z = sum |z|):
    # per |z|, the minor's two products and its difference (Gappa's eta; in fact exact, (S));
    # constant: the three products by z and the two sums, and the permanent's three products
    # through c_o3 (sum |z| sa <= (1+e)^4 T + 3 (1+e) eta).
    o3_z = 3 * carry
    o3_1 = 5 * carry + 3 * (1 + e) * c_o3
    # The bound: fl(o3d_a T) and fl(u S~) may each lose eta, S~ >= (Z + 1) / (1+e)^2, the
    # bound's sum and the sign argument (1-e)/(1+e).
    claims.append(("underflow_orient3d", "min",
                   eta * max(o3_z, o3_1 + 2 * (1 - e) / (1 + e)) * (1 + e) ** 4 / (1 - e)))

    # ---- the skip rule of the underflow term (bounds.md#underflow-3d) ----------------------
    # filter_bound (adaptive3d.cpp) and incircle's stage A (adaptive.cpp) use `first` alone
    # when first >= skip_first and spread < skip_spread (hypotheses, read from the code by
    # the checker). Then u spread < u skip_spread <= skip_first 2^-54, so fl(u spread) <=
    # skip_first 2^-54 < ulp(first) / 2 and fl(first + fl(u spread)) == first: the bound the
    # derivations assume, the same double. That needs u <= skip_first 2^-54 / skip_spread.
    skip_first, skip_spread = Q(2) ** -960, Q(2) ** 46
    claims.append(("skip_first_min", "min", skip_first))
    claims.append(("skip_spread_max", "max", skip_spread))
    for name in ("underflow_incircle", "underflow_orient3d", "underflow_insphere"):
        claims.append((name, "max", skip_first * Q(2) ** -54 / skip_spread))

    # ---- orient3d, double-word stage (bounds.md#orient3d-double-word) ----------------------
    # The rules of bounds.md#incircle-double-word; every nonzero high part of a difference in
    # [o3_lo, o3_hi] (adaptive3d.cpp's range test).
    o3_lo, o3_hi = Q(2) ** -220, Q(2) ** 220
    claims.append(("o3d_dw_min", "min", o3_lo))
    claims.append(("o3d_dw_max", "max", o3_hi))
    w_lo, w_hi = o3_lo * (1 - e), o3_hi * (1 + e)
    minor_hi = 2 * w_hi ** 2 * (1 + e) ** 4
    require_3d(minor_hi <= Q(2) ** 995 and 3 * w_hi * minor_hi * (1 + e) ** 6 <= Q(2) ** 1021,
               "orient3d double words: no overflow, Dekker's split applies")
    u_dw = u_low + u_tp
    o_1 = beta + u_dw / w_lo ** 2                        # the minors' products
    o_2 = o_1 * (1 + alpha) + alpha                      # the minors
    o_3 = (1 + beta) * (1 + o_2) - 1 + u_dw / w_lo ** 3  # z * minor (z exact)
    o_det = (o_3 * (1 + alpha) + alpha) * (1 + alpha) + alpha
    # T <= kappa t: |X| <= (1+e) |X.hi| for the three factors, five roundings (R2: every
    # nonzero intermediate is at least (1 - e)^5 w_lo^3, normal).
    kappa_o3 = (1 + e) ** 8
    require_3d((1 - e) ** 5 * w_lo ** 3 * e ** 2 >= normal,
               "orient3d: t and the bound are normal")
    claims.append(("o3d_dw", "min", o_det * kappa_o3 * (1 + e) / (1 - e)))

    # ---- insphere, stage A (bounds.md#insphere) -------------------------------------------
    # One orientation o = fl(fl(t1 +- t2) + t3) against K = sum |z| sa: c_o3 and its last
    # sum, e |o| with |o| <= (1+e)^4 K.
    c_orient = c_o3 + e * (1 + e) ** 4
    # One term lift * o against l K (computed lift and orientation): the lift errs by d5
    # relative to the computed one (R2: the difference squared, the square, two sums of
    # nonnegative terms); the product and the inner sum one rounding each (e (1+e)^5, the
    # incircle pattern); the last sum free.
    c_isp = ((1 + delta(5)) * c_orient + delta(5) * (1 + e) ** 4
             + e * (1 + e) ** 5 + e * (1 + e) ** 5)
    # (1+e)^8: sum l K against the permanent (the pair's sum, the product by |z|, the
    # factor's two sums, the product by the lift, the three sums); (1+e)^2 the bound's two
    # roundings; 1/(1-e) the sign argument.
    claims.append(("isp_a", "min", c_isp * (1 + e) ** 10 / (1 - e)))
    # Underflow (bounds.md#underflow-3d), in units of eta against S = L Z + L + C + 1:
    #  L Z: each minor's two products and its difference, scaled by |z| and the lift
    #       (sum_p l_p Z_p <= L Z); the lift's absolute error g <= 5 (1+e)^2 eta times the
    #       orientation's relative error c_orient K_p, K_p <= 2 L Z_p, sum_p Z_p = 3 Z;
    #  L:   each orientation's three products by z and two sums, scaled by the lift; the
    #       permanent's twelve products by |z| through c_isp (bounds.md);
    #  C:   each lift's three squares and two sums, scaled by |o_p|;
    #  1:   the four products lift * o and the three sums; the permanent's four products
    #       through c_isp; g times the orientation's absolute terms (eta^2 Z_p, Z_p < 2^1026
    #       when every value is finite).
    g_lift = 5 * (1 + e) ** 2
    iu_lz = carry * (3 + g_lift * c_orient * 2 * 3)
    iu_l = carry * 5 + 3 * (1 + e) * c_isp
    iu_c = carry * 5
    iu_1 = (carry * (7 + 4 * g_lift * (3 * carry * Q(2) ** 1026 + 5) * eta)
           + 4 * (1 + e) ** 4 * c_isp)
    # The bound: S~ >= L Z/(1+e)^7 + (L + C)/(1+e)^4 + (1 - eta)/(1+e)^2, fl(u S~) >= u S~ /
    # (1+e) - eta, fl(isp_a T) loses at most eta, the bound's sum and the sign argument.
    need = max(iu_lz * (1 + e) ** 9, iu_l * (1 + e) ** 6, iu_c * (1 + e) ** 6,
               (iu_1 + 2 * (1 - e) / (1 + e)) * (1 + e) ** 4 / (1 - eta))
    claims.append(("underflow_insphere", "min", eta * need / (1 - e)))

    # ---- insphere, semi-static filter (bounds.md#insphere-semi-static) ---------------------
    # M = max |rounded difference|; hypotheses (checked against the code): M in [s5_lo, s5_hi].
    # A quantity of degree k is measured in units of M^k; an absolute eta in it is then at
    # most eta_k = eta / s5_lo^k (every bound below grows with the eta_k: M = s5_lo is the
    # worst case). Each step: |computed - exact (in the rounded differences)| <= e_*, and
    # |computed| <= b_*; a rounding adds e times the computed operands' bound plus eta_k
    # (Gappa's eta, charged to every operation, although (S) makes sums exact).
    s5_lo, s5_hi = Q(2) ** -190, Q(2) ** 200
    claims.append(("isp_static_min", "min", s5_lo))
    claims.append(("isp_static_max", "max", s5_hi))

    def semi_static_minor(eta_2, eta_3):
        """Error and magnitude bounds of z * (x y - x' y'), all |x| <= 1."""
        e_p, b_p = e + eta_2, (1 + e) + eta_2                     # a product, |x y| <= 1
        e_m = 2 * e_p + e * 2 * b_p + eta_2                        # the minor's difference
        b_m = (1 + e) * 2 * b_p + eta_2
        e_t = e_m + e * b_m + eta_3                                # |z| <= 1, the product
        b_t = (1 + e) * b_m + eta_3
        return e_t, b_t

    eta5 = [eta / s5_lo ** k for k in range(6)]         # eta in units of M^k
    e_t5, b_t5 = semi_static_minor(eta5[2], eta5[3])
    # The orientation (|z| <= 1): s = t1 +- t2, o = s + t3.
    e_s5, b_s5 = 2 * e_t5 + e * 2 * b_t5 + eta5[3], (1 + e) * 2 * b_t5 + eta5[3]
    e_o5 = e_s5 + e_t5 + e * (b_s5 + b_t5) + eta5[3]
    b_o5 = (1 + e) * (b_s5 + b_t5) + eta5[3]
    # The lift (squares of |x| <= 1): q1 + q2, then + q3.
    e_q, b_q = e + eta5[2], (1 + e) + eta5[2]
    e_12, b_12 = 2 * e_q + e * 2 * b_q + eta5[2], (1 + e) * 2 * b_q + eta5[2]
    e_l5 = e_12 + e_q + e * (b_12 + b_q) + eta5[2]
    b_l5 = (1 + e) * (b_12 + b_q) + eta5[2]
    # lift * o against lift(x) O(x), |lift(x)| <= 3, |O(x)| <= 6 (in the rounded differences).
    e_p5 = e_l5 * b_o5 + 3 * e_o5 + e * b_l5 * b_o5 + eta5[5]
    b_p5 = (1 + e) * b_l5 * b_o5 + eta5[5]
    # The two inner sums; the last sum free (charged Gappa's eta).
    e_det5 = 2 * (2 * e_p5 + e * 2 * b_p5 + eta5[5]) + eta5[5]
    # D(x) against D(X): 72 monomials, each at most M^5, five rounded differences each.
    total5 = 72 * ((1 - e) ** -5 - 1) + e_det5
    # The bound fl(isp_static fl(fl(m2 m2) M)), m2 = fl(M M): four roundings down, all normal
    # (isp_static >= 1024 eps, as claimed); the sign argument 1/(1-e). No overflow: every
    # intermediate is below 4 b_p5 M^5.
    require_3d(s5_lo ** 5 * Q(1024) * e * (1 - e) ** 4 >= normal,
               "insphere semi-static bound normal")
    require_3d(8 * b_p5 * s5_hi ** 5 < huge, "insphere semi-static: no overflow")
    claims.append(("isp_static", "min", total5 / (1 - e) ** 5))

    # ---- insphere, double-word stage (bounds.md#insphere-double-word) ----------------------
    i5_lo, i5_hi = Q(2) ** -160, Q(2) ** 160
    claims.append(("isp_dw_min", "min", i5_lo))
    claims.append(("isp_dw_max", "max", i5_hi))
    v_lo, v_hi = i5_lo * (1 - e), i5_hi * (1 + e)
    orient_hi = 3 * v_hi * 2 * v_hi ** 2 * (1 + e) ** 8   # |orientation~| (and 3 v_hi^2 lifts)
    lift_hi5 = 3 * v_hi ** 2 * (1 + e) ** 8
    require_3d(orient_hi <= Q(2) ** 995
               and 4 * lift_hi5 * orient_hi * (1 + e) ** 6 <= Q(2) ** 1021,
               "insphere double words: no overflow, Dekker's split applies")
    i_1 = beta + u_dw / v_lo ** 2                        # the minors' products, the squares
    i_2 = i_1 * (1 + alpha) + alpha                      # the minors
    i_3 = (1 + beta) * (1 + i_2) - 1 + u_dw / v_lo ** 3  # z * minor
    i_o = (i_3 * (1 + alpha) + alpha) * (1 + alpha) + alpha        # the orientations
    i_lift = (i_1 * (1 + alpha) + alpha) * (1 + alpha) + alpha     # the lifts
    i_5 = (1 + beta) * (1 + i_lift) * (1 + i_o) - 1 + u_dw / v_lo ** 5
    i_det = (i_5 * (1 + alpha) + alpha) * (1 + alpha) + alpha
    # T <= kappa t: each lift at most (1+e) lift.hi / (1 - i_lift), |X| <= (1+e) |X.hi| for
    # the three other factors, nine roundings (R2: every nonzero intermediate is at least
    # (1 - e)^12 v_lo^5, normal).
    kappa_i5 = (1 + e) ** 13 / (1 - i_lift)
    require_3d((1 - e) ** 12 * v_lo ** 5 * e ** 2 >= normal,
               "insphere: t and the bound are normal")
    claims.append(("isp_dw", "min", i_det * kappa_i5 * (1 + e) / (1 - e)))

    with open(output, "w") as f:
        f.write("# Proven bounds, written by proofs/derive_bounds.py from Gappa's output.\n")
        f.write("# A trailing if=CONDITION: proven only if that statement (bounds.md) holds.\n")
        for name, kind, value, *condition in claims:
            tail = "".join(f" if={c}" for c in condition)
            f.write(f"{name} {kind} {value.numerator}/{value.denominator}{tail}\n")
    for name, kind, value, *condition in claims:
        unit = "eps" if value < Q(1, 2**40) and value > Q(1, 2**70) else ""
        if value < Q(1, 2**90) and value > Q(1, 2**120) and value.numerator != 1:
            unit = "eps^2"  # (a power of two, a hypothesis, is shown as it is)
        shown = float(value / (Q(1, 2**53) if unit == "eps" else Q(1, 2**106))) if unit else float(value)
        tail = "".join(f" (if {c})" for c in condition)
        print(f"{name:20s} {kind} {shown!r} {unit}{tail}")


if __name__ == "__main__":
    main()
