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


def det3(m):
    return (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))


def orient3d_exact(a, b, c, d):
    """Shewchuk's orient3d in rationals: the sign of det(a - d, b - d, c - d)."""
    dd = [Fraction(float(v)) for v in d]
    return sign(det3([[Fraction(float(v)) - w for v, w in zip(p, dd)] for p in (a, b, c)]))


def insphere_exact(a, b, c, d, e):
    """Shewchuk's insphere in rationals: the 4 x 4 determinant of the rows
    (p - e, |p - e|^2), p = a, b, c, d, expanded along the last column."""
    ee = [Fraction(float(v)) for v in e]
    rows = [[Fraction(float(v)) - w for v, w in zip(p, ee)] for p in (a, b, c, d)]
    lift = [x * x + y * y + z * z for x, y, z in rows]
    det = 0
    for k in range(4):
        minor = [rows[i] for i in range(4) if i != k]
        det += (-1) ** (k + 3) * lift[k] * det3(minor)
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
