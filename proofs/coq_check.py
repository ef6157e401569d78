#!/usr/bin/env python3
"""Certificates: for every Gappa script in proofs/gappa/ (but rounding_result.g, see its
header), `gappa -Bcoq` writes a Coq proof of the proven intervals and `coqc` checks it
against Debian's Flocq and Gappa libraries (packages coq, libcoq-flocq, libcoq-gappa).
Usage: coq_check.py GAPPA COQC. Exit code non-zero if any certificate fails."""
import subprocess
import sys
import tempfile
from pathlib import Path

SKIP = {"rounding_result.g"}
gappa, coqc = sys.argv[1], sys.argv[2]
failed = 0
with tempfile.TemporaryDirectory() as tmp:
    for script in sorted((Path(__file__).resolve().parent / "gappa").glob("*.g")):
        if script.name in SKIP:
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
