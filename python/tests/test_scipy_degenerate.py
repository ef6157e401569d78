"""On degenerate sets exidel's triangulation certifies; what scipy.spatial.Delaunay does on
the same input is recorded (scipy_observations.md in the test's working directory, and
printed with pytest -s), not asserted: qhull's behaviour is its own and may change."""

import numpy as np
import pytest

import exidel
from degenerate_sets import markdown, scipy_outcome, sets

SETS = sets()


@pytest.mark.parametrize("name,points", SETS, ids=[name for name, _ in SETS])
def test_exidel_certifies_every_degenerate_set(name, points):
    for algorithm in ("external", "dwyer", "bowyer-watson"):
        tri = exidel.Delaunay(points, algorithm=algorithm)
        assert tri.certify().ok, (name, algorithm)
        # No distinct point is left out.
        used = set(tri.simplices.reshape(-1).tolist()) if not tri.collinear else set(tri.hull.tolist())
        assert len(used) == np.unique(points, axis=0).shape[0]


def test_record_what_scipy_does():
    rows = []
    for name, points in SETS:
        outcome, detail = scipy_outcome(points, exidel)
        rows.append((name, len(points), exidel.Delaunay(points).certify().ok, outcome, detail))
    table = markdown(rows)
    with open("scipy_observations.md", "w") as f:
        f.write(table + "\n")
    print("\n" + table)
    assert all(ok for _, _, ok, _, _ in rows)
    assert len(rows) == len(SETS)
