(* Lemma R2 of ../gappa/rounding_result.g, proved by hand from Flocq.

   Gappa proves (rounding_result.g, the goal derive_bounds.py reads as eps_result):
     xp in [1b-1021, 1b1023] /\ xn in [-1b1023, -1b-1021] ->
     (xp - zp) / zp in [-1b-53, 1b-53] /\ (xn - zn) / zn in [-1b-53, 1b-53]
   with zp = float<ieee_64,ne>(xp), zn = float<ieee_64,ne>(xn). Its `gappa -Bcoq`
   certificate is 11 MB and takes coqc more than five minutes, so this file is R2's
   certificate instead: ../coq_check.py compiles it (and checks that its theorems use no
   axiom beyond those under Coq's reals) and does not run `gappa -Bcoq` on
   rounding_result.g. Theorem R2_gappa_goal is Gappa's goal, with the bound 1b-53 = 2^-53
   written as eps = /2 * bpow radix2 (-52) (lemma eps_is_two_to_minus_53); ../derive_bounds.py
   fails if Gappa's bound is below it. Below, [fl] is Flocq's rounding to binary64, round to
   nearest with ties to even (radix 2, FLT_exp (-1074) 53, Znearest with choice
   fun z => negb (Z.even z)); the last lemma checks that it is, by definition, the rounding a
   Gappa certificate writes for float<ieee_64,ne>. Flocq's FLT format has no largest
   exponent, so the upper limit 2^1023 of the range is a hypothesis that the proof does not
   need (as in Gappa, whose float<> does not model overflow either). *)

From Coq Require Import ZArith Reals Lra.
From Flocq Require Import Core Relative.

Open Scope R_scope.

(** The precision of binary64, 53 > 0 (Flocq's FLT format asks for it). *)
Local Instance prec_gt_0_53 : Prec_gt_0 53 := eq_refl.

(** One rounding of binary64, round to nearest, ties to even. *)
Definition fl (x : R) : R := round radix2 (FLT_exp (-1074) 53) ZnearestE x.

(** The bound 2^-53, written as Flocq's /2 * bpow (-prec + 1) with prec = 53. *)
Definition eps : R := / 2 * bpow radix2 (-52).

Lemma eps_is_two_to_minus_53 : eps = / 9007199254740992.
Proof.
  unfold eps; simpl bpow; simpl Z.pow_pos.
  rewrite <- Rinv_mult; f_equal; rewrite <- mult_IZR; reflexivity.
Qed.

(** R2, relative to the result: 2^-1021 <= |x| <= 2^1023 -> |fl(x) - x| <= 2^-53 |fl(x)|.
    Flocq's hypothesis is bpow (emin + prec - 1) = 2^-1022 <= |x|. *)
Theorem R2 :
  forall x : R,
  bpow radix2 (-1021) <= Rabs x <= bpow radix2 1023 ->
  Rabs (fl x - x) <= eps * Rabs (fl x).
Proof.
  intros x [Hlo _].
  apply (relative_error_N_FLT_round radix2 (-1074) 53 eq_refl).
  apply Rle_trans with (2 := Hlo).
  apply bpow_le; discriminate.
Qed.

(** In the range, fl(x) is not zero: |fl(x)| >= 2^-1021 (a double; rounding is monotone). *)
Lemma fl_large :
  forall x : R, bpow radix2 (-1021) <= Rabs x -> bpow radix2 (-1021) <= Rabs (fl x).
Proof.
  intros x Hx.
  apply (abs_round_ge_generic radix2 (FLT_exp (-1074) 53) ZnearestE); [| exact Hx].
  apply generic_format_bpow; discriminate.
Qed.

Lemma R2_quotient :
  forall x : R,
  bpow radix2 (-1021) <= Rabs x <= bpow radix2 1023 ->
  - eps <= (x - fl x) / fl x <= eps.
Proof.
  intros x Hx.
  assert (Hz : 0 < Rabs (fl x)).
  { apply Rlt_le_trans with (2 := fl_large x (proj1 Hx)); apply bpow_gt_0. }
  apply Rabs_le_inv.
  unfold Rdiv; rewrite Rabs_mult, Rabs_inv, Rabs_minus_sym.
  apply Rmult_le_reg_r with (1 := Hz).
  rewrite Rmult_assoc, Rinv_l by (apply Rgt_not_eq; exact Hz).
  rewrite Rmult_1_r.
  now apply R2.
Qed.

(** Gappa's goal, both signs, as rounding_result.g states it. *)
Theorem R2_gappa_goal :
  forall xp xn : R,
  bpow radix2 (-1021) <= xp <= bpow radix2 1023 ->
  - bpow radix2 1023 <= xn <= - bpow radix2 (-1021) ->
  - eps <= (xp - fl xp) / fl xp <= eps /\ - eps <= (xn - fl xn) / fl xn <= eps.
Proof.
  intros xp xn [Hp1 Hp2] [Hn1 Hn2].
  pose proof (bpow_ge_0 radix2 (-1021)) as H0.
  split; apply R2_quotient.
  - rewrite Rabs_pos_eq by lra; lra.
  - rewrite Rabs_left1 by lra; lra.
Qed.

(** fl is the rounding of Gappa's certificates for float<ieee_64,ne>: Gappa's Coq library
    writes rounding_float rndNE 53 (-1074), a notation for Flocq's round radix2
    (FLT_exp (-1074) 53) applied to Gappa_round_def.rndNE, which is defined as
    Znearest (fun z => negb (Z.even z)). *)
Require Gappa.Gappa_library.

Lemma fl_is_gappa_float_ieee_64_ne :
  forall x : R,
  Gappa.Gappa_float.rounding_float Gappa.Gappa_round_def.rndNE 53 (-1074) x = fl x.
Proof. reflexivity. Qed.
