#!/usr/bin/env python3
"""Coq checks of the Gappa lemmas, with Debian's Flocq and Gappa libraries (packages coq,
libcoq-flocq, libcoq-gappa).

- Every Coq file in proofs/coq/ (hand-written proofs) is compiled by `coqc`, and every
  Theorem/Lemma in it may use no axiom but the ones Coq's real numbers and Flocq rest on
  (classical Dedekind reals, excluded middle, functional extensionality), checked with
  `Print Assumptions` (coqc alone accepts `Admitted`).
- Every Gappa script in proofs/gappa/ without a hand-written file of the same name is
  certified by `gappa -Bcoq`, whose output `coqc` checks. rounding_result.g (lemma R2) is
  certified by coq/rounding_result.v instead: its `gappa -Bcoq` certificate is 11 MB and
  takes coqc more than five minutes, so `gappa -Bcoq` is not run on it.

Usage: coq_check.py GAPPA COQC. Exit code non-zero if any file or certificate fails.
Nothing is written into the source tree (the hand-written files are compiled in a copy)."""
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
# What the statements over R may rest on: the axioms under Coq's reals and Flocq (the names
# Coq 8.16 prints; another version may name them differently, and then this check fails).
ALLOWED_AXIOMS = {
    "ClassicalDedekindReals.sig_not_dec",
    "ClassicalDedekindReals.sig_forall_dec",
    "FunctionalExtensionality.functional_extensionality_dep",
    "Classical_Prop.classic",
}
THEOREM = re.compile(
    r"^\s*(?:Theorem|Lemma|Corollary|Proposition|Fact|Remark)\s+([A-Za-z_][\w']*)", re.MULTILINE)


def axioms_used(printed):
    """The axiom names in `Print Assumptions` output: each axiom starts a line at column 0
    with its name (its type follows, after " : " or on indented lines)."""
    names = set()
    for line in printed.splitlines():
        if line and not line[0].isspace() and line != "Axioms:" \
                and not line.startswith("Closed under the global context"):
            names.add(line.split()[0])
    return names


def check_hand_written(coqc, source, work):
    """Compile one hand-written file in `work`; return an error text, or None."""
    copy = work / source.name
    shutil.copyfile(source, copy)
    built = subprocess.run([coqc, "-Q", ".", "", copy.name], capture_output=True, text=True,
                           cwd=work)
    if built.returncode != 0:
        return built.stdout + built.stderr
    names = THEOREM.findall(source.read_text())
    if not names:
        return "no Theorem or Lemma found"
    module = source.stem
    driver = work / f"assumptions_{module}.v"
    driver.write_text(f"Require {module}.\n"
                      + "".join(f"Print Assumptions {module}.{n}.\n" for n in names))
    printed = subprocess.run([coqc, "-Q", ".", "", driver.name], capture_output=True, text=True,
                             cwd=work)
    if printed.returncode != 0:
        return printed.stdout + printed.stderr
    extra = axioms_used(printed.stdout) - ALLOWED_AXIOMS
    if extra:
        return "uses axioms beyond those under Coq's reals: " + ", ".join(sorted(extra))
    return None


def main():
    gappa, coqc = sys.argv[1], sys.argv[2]
    hand_written = sorted((HERE / "coq").glob("*.v"))
    by_hand = {v.stem for v in hand_written}
    failed = 0
    hand_ok = {}
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp) / "coq"
        work.mkdir()
        for source in hand_written:
            error = check_hand_written(coqc, source, work)
            hand_ok[source.stem] = error is None
            print(("ok   " if error is None else "FAIL ") + "coq/" + source.name)
            if error is not None:
                print(error)
                failed += 1
        for script in sorted((HERE / "gappa").glob("*.g")):
            if script.stem in by_hand:
                # Counted once, above, if it failed.
                print(("ok   " if hand_ok[script.stem] else "FAIL ")
                      + f"{script.name} (certified by coq/{script.stem}.v)")
                continue
            cert = Path(tmp) / (script.stem + ".v")
            made = subprocess.run([gappa, "-Bcoq", str(script)], capture_output=True, text=True)
            cert.write_text(made.stdout)
            checked = subprocess.run([coqc, str(cert)], capture_output=True, text=True, cwd=tmp)
            ok = made.returncode == 0 and checked.returncode == 0 and "Lemma" in made.stdout
            print(("ok   " if ok else "FAIL ") + script.name)
            if not ok:
                print(made.stderr + checked.stdout + checked.stderr)
                failed += 1
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
