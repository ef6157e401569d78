"""Shared fixtures of the Python tests: an exact rational oracle, the exidel command."""

import os
import shutil
import subprocess
from fractions import Fraction

import numpy as np
import pytest


def F(p):
    return Fraction(float(p[0])), Fraction(float(p[1]))


def sign(x):
    return (x > 0) - (x < 0)


def orient2d_exact(a, b, c):
    (ax, ay), (bx, by), (cx, cy) = F(a), F(b), F(c)
    return sign((bx - ax) * (cy - ay) - (by - ay) * (cx - ax))


def incircle_exact(a, b, c, d):
    (ax, ay), (bx, by), (cx, cy), (dx, dy) = F(a), F(b), F(c), F(d)
    rows = [(px - dx, py - dy) for px, py in ((ax, ay), (bx, by), (cx, cy))]
    m = [(x, y, x * x + y * y) for x, y in rows]
    det = (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
           - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
           + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))
    return sign(det)


def compare_distance_exact(c, p, q):
    (cx, cy), (px, py), (qx, qy) = F(c), F(p), F(q)
    return sign((px - cx) ** 2 + (py - cy) ** 2 - (qx - cx) ** 2 - (qy - cy) ** 2)


@pytest.fixture(scope="session")
def exidel_cli():
    """The exidel command of this build (ctest sets EXIDEL_CLI), else the package's own."""
    path = os.environ.get("EXIDEL_CLI")
    if not path:
        from exidel import _paths
        path = _paths.cli
    if not path or not shutil.which(path):
        pytest.skip("the exidel command is not available")
    return path


def run_cli(cli, *args, stdin=""):
    r = subprocess.run([cli, *args], input=stdin, capture_output=True, text=True, check=True)
    return r.stdout


@pytest.fixture
def rng():
    return np.random.default_rng(20250704)
