"""exidel.research: the studies of `exidel study`, callable from Python.

    from exidel import research
    r = research.failure_map("fm", quick=True, kernel=["double", "adaptive"])
    r.tables["failure_map"]["wrong"]          # int64 column of failure_map.csv
    r.report                                  # Path of fm/report.md

    m = research.compute_failure_map(**research.failure_map_preset("kettner1"))
    m.wrong_count                             # 11972 cells where double is wrong

The studies run in the `exidel` command (the research library cannot be linked into the
extension module), as a subprocess: `run` writes the same report folder as the command,
report.md starting with the command that writes it again, and reads its CSV files back as
typed numpy arrays. The command is exidel._paths.cli (the build tree's or the install's),
or the environment variable EXIDEL_CLI when set.

`compute_failure_map` needs no command: it evaluates one predicate while one point moves
over a grid of ulp steps with the vectorised predicates of exidel, cell for cell what the
failure-map study computes.
"""

from __future__ import annotations

import csv
import dataclasses
import os
import re
import shutil
import subprocess
import tempfile
import time
from pathlib import Path

import numpy as np

from . import _ulp

__all__ = ["STUDIES", "StudyError", "StudyOptionError", "StudyResult", "Classification",
           "FailureMap", "cli_path", "run", "failure_map", "precision", "triangulation",
           "stages", "run_all", "replay", "read_fixture", "list_failure_map_presets", "read_table",
           "failure_map_preset", "failure_map_presets", "compute_failure_map", "nudge"]

DEFAULT_SEED = 20250704

#: The studies `run` takes (replay has its own function: it writes no folder).
STUDIES = ("failure-map", "precision", "triangulation", "stages", "all")

# Options of each study: Python keyword -> CLI flag. Values: a list or tuple becomes a
# comma-separated list, True a bare flag (False and None leave the flag out).
_FAILURE_MAP = {"preset": "--preset", "presets": "--preset", "kernel": "--kernel",
                "kernels": "--kernel", "width": "--width", "height": "--height",
                "predicate": "--predicate", "points": "--points", "move": "--move",
                "order": "--order", "step": "--step", "centered": "--centered",
                "corner": "--corner", "axes": "--axes"}
# The window of a custom failure map: centered=True or corner=False is --centered (the
# command's default), centered=False or corner=True is --corner.
_WINDOW = {"--centered": "--corner", "--corner": "--centered"}
_PRECISION = {"bits": "--bits", "families": "--families", "family": "--families",
              "samples": "--samples"}
_TRIANGULATION = {"kernel": "--kernel", "kernels": "--kernel", "families": "--families",
                  "family": "--families", "seeds": "--seeds", "sizes": "--sizes",
                  "shrink": "--shrink", "order": "--order", "orders": "--order",
                  "algorithm": "--algorithm", "algorithms": "--algorithm", "bits": "--bits"}
_STAGES = {"families": "--families", "family": "--families", "samples": "--samples",
           "seeds": "--seeds", "size": "--size"}
_OPTIONS = {"failure-map": _FAILURE_MAP, "precision": _PRECISION,
            "triangulation": _TRIANGULATION, "stages": _STAGES, "all": {}}


class StudyError(RuntimeError):
    """The exidel command failed (or is missing): .command, .returncode, .stderr."""

    def __init__(self, message, command=None, returncode=None, stderr=""):
        super().__init__(message)
        self.command = command
        self.returncode = returncode
        self.stderr = stderr


class StudyOptionError(StudyError, ValueError):
    """The exidel command refused its options (exit status 2)."""


@dataclasses.dataclass
class StudyResult:
    """What `run` returns: the tables of every CSV file the study wrote (name -> numpy
    structured array; the name is the file's path inside `out` without ".csv", e.g.
    "failure_map" or, for `run_all`, "failure-map/failure_map"), the report's path, the
    folder, the command run and what it printed (the main table)."""

    study: str
    out: Path
    report: Path
    tables: dict
    command: list
    stdout: str

    def __getitem__(self, name):
        return self.tables[name]

    def __repr__(self):
        return (f"<exidel.research.StudyResult {self.study}: {self.report}, tables "
                f"{', '.join(f'{k} ({len(v)} rows)' for k, v in self.tables.items())}>")


class Classification:
    """What `replay` found: .outcome ("delaunay", "not_delaunay", "invalid", "failure",
    "guard") and .detail (the finding or failure kind; "" for delaunay)."""

    def __init__(self, outcome, detail=""):
        self.outcome, self.detail = outcome, detail

    def __eq__(self, other):
        if isinstance(other, str):
            return self.outcome == other
        return (isinstance(other, Classification)
                and (self.outcome, self.detail) == (other.outcome, other.detail))

    __hash__ = None

    def __repr__(self):
        return f"<Classification {self.outcome}{f' ({self.detail})' if self.detail else ''}>"


# ---------------------------------------------------------------------------------------
# The command

def cli_path():
    """The exidel command: $EXIDEL_CLI, else the one this package was built with. Raises
    StudyError when it does not exist or cannot be run."""
    path = os.environ.get("EXIDEL_CLI")
    origin = "EXIDEL_CLI"
    if not path:
        try:
            from . import _paths
            path, origin = _paths.cli, "exidel._paths.cli"
        except ImportError:
            path = None
    if not path:
        raise StudyError("the exidel command is unknown: set EXIDEL_CLI to its path")
    found = shutil.which(path)
    if found is None:
        raise StudyError(f"the exidel command {path!r} ({origin}) does not exist or is not "
                         "executable; set EXIDEL_CLI to the path of `exidel`")
    return found


def _call(args, timeout=None):
    cli = cli_path()
    command = [cli, *args]
    try:
        r = subprocess.run(command, capture_output=True, text=True, timeout=timeout)
    except OSError as error:
        raise StudyError(f"cannot run {cli}: {error}", command) from None
    if r.returncode != 0:
        detail = r.stderr.strip() or r.stdout.strip()
        cls = StudyOptionError if r.returncode == 2 else StudyError
        raise cls(f"`{' '.join(command[1:])}` failed with exit status {r.returncode}:\n{detail}",
                  command, r.returncode, r.stderr)
    return command, r.stdout


def _value(flag, v):
    if isinstance(v, (list, tuple, np.ndarray)) and flag == "--points":
        pts = np.asarray(v, dtype=np.float64)
        pts = pts if pts.ndim == 2 else pts.reshape(-1, 2)  # rows of 2 or 3 coordinates
        return ";".join(",".join(repr(c) for c in row) for row in pts.tolist())
    if isinstance(v, (list, tuple, np.ndarray)):
        return ",".join(str(x) for x in np.asarray(v).ravel().tolist())
    return str(v)


def _arguments(study, out, seed, jobs, quick, options):
    if study not in _OPTIONS:
        raise ValueError(f"unknown study {study!r}: expected one of {', '.join(STUDIES)} "
                         "(replay: exidel.research.replay)")
    known = _OPTIONS[study]
    args = ["study", study, "--out", os.fspath(out), "--seed", str(int(seed)),
            "--jobs", str(int(jobs)), "--no-progress"]
    if quick:
        args.append("--quick")
    given = set()
    for name, v in options.items():
        if name not in known:
            hint = f"; it takes {', '.join(sorted(known))}" if known else \
                ("; `all` takes only out, seed, jobs and quick" if study == "all" else "")
            raise TypeError(f"study {study!r} has no option {name!r}{hint}")
        flag = known[name]
        if flag in _WINDOW and v is not None:
            if not isinstance(v, (bool, np.bool_)):
                raise TypeError(f"option {name!r} is True or False, got {v!r}")
            flag = flag if v else _WINDOW[flag]
            if _WINDOW[flag] in given:
                raise TypeError("centered and corner choose different windows: give one")
            if flag not in given:
                given.add(flag)
                args.append(flag)
            continue
        if flag in given:
            raise TypeError(f"option {flag} given twice (keyword {name!r})")
        if v is None or v is False:
            continue
        given.add(flag)
        if v is True:
            raise TypeError(f"option {name!r} needs a value")
        else:
            args += [flag, _value(flag, v)]
    return args


def run(study, out, *, seed=DEFAULT_SEED, jobs=1, quick=False, timeout=None, **options):
    """Runs `exidel study <study> --out <out> ...` and reads what it wrote.

    study    "failure-map", "precision", "triangulation", "stages" or "all"
    out      the report folder (created; files of an earlier run are overwritten, others
             left as they are)
    seed, jobs, quick   the common options (jobs changes no result)
    options  the study's own options, named as the command's flags without "--"
             (kernel=["double", "adaptive"] -> --kernel double,adaptive; points=[[x, y],
             ...] -> --points "x,y;..."; a custom map's window: centered=False or
             corner=True -> --corner, centered=True -> --centered, the default). See
             `exidel study --help`.
    Returns a StudyResult (.tables, .report, ...). Raises ValueError for an unknown study,
    TypeError for an option the study does not take, StudyOptionError (a ValueError) when
    the command refuses a value, StudyError when it fails or cannot be found.
    """
    args = _arguments(study, out, seed, jobs, quick, options)
    start = time.time_ns() - 1_000_000_000  # file times may lag the clock by a tick
    command, stdout = _call(args, timeout)
    out = Path(out)
    tables = {}
    # The CSV files this run wrote: out/*.csv, or out/<study>/*.csv for `all` (files an
    # earlier run left there under other names are not this run's and are skipped).
    for f in sorted(out.glob("*/*.csv" if study == "all" else "*.csv")):
        if f.stat().st_mtime_ns >= start:
            tables[f.relative_to(out).with_suffix("").as_posix()] = read_table(f)
    return StudyResult(study, out, out / "report.md", tables, command, stdout)


def failure_map(out, **kwargs):
    """The failure-map study (`run("failure-map", out, ...)`): preset, kernel, width,
    height, or a custom predicate, points, move, order, step, axes and its window (centred
    by default; centered=False or corner=True: the moving point at the corner). For the map itself
    without the command, see compute_failure_map."""
    return run("failure-map", out, **kwargs)


def precision(out, **kwargs):
    """The precision study: bits, families, samples."""
    return run("precision", out, **kwargs)


def triangulation(out, **kwargs):
    """The triangulation study: kernel, families, seeds, sizes, shrink, order, algorithm,
    bits."""
    return run("triangulation", out, **kwargs)


def stages(out, **kwargs):
    """The stages study: families, samples, seeds, size."""
    return run("stages", out, **kwargs)


def run_all(out, **kwargs):
    """All four studies into out/<study>/ and out/report.md (only seed, jobs, quick)."""
    return run("all", out, **kwargs)


def read_fixture(path):
    """A point file as the triangulation study writes its fixtures: a dict with "points"
    ((n, 2) float64, hex or decimal numbers), "header" (the '#' lines), and from the header
    when present "outcome" and "detail" (what the study saw) and "options" (the keywords
    of `replay` that reproduce it: kernel, incircle, algorithm, order)."""
    header, rows = [], []
    with open(path, encoding="utf-8") as f:
        for line in f:
            line = line.strip()
            if line.startswith("#"):
                header.append(line)
            elif line:
                rows.append([float.fromhex(v) if "0x" in v.lower() else float(v)
                             for v in re.split(r"[\s,]+", line)[:2]])
    d = {"points": np.array(rows, dtype=np.float64).reshape(-1, 2), "header": header}
    for line in header:
        m = re.match(r"# exidel study triangulation fixture: (\w+)(?: \((.*)\))?", line)
        if m:
            d["outcome"], d["detail"] = m.group(1), m.group(2) or ""
        m = re.match(r"# reproduce: exidel study replay -i FILE (.*)", line)
        if m:
            words = m.group(1).split()
            d["options"] = {w[2:]: v for w, v in zip(words[::2], words[1::2]) if w.startswith("--")}
    return d


def replay(file, kernel=None, *, incircle=None, algorithm=None, order=None, timeout=None):
    """Classifies one point file as the triangulation study would (`exidel study replay`):
    a fixture the study wrote, any xy file, or an (n, 2) array (written to a temporary
    file in hex floats). kernel, incircle, algorithm and order default to the fixture's
    "reproduce" line, else to the command's defaults (incircle determinant, the external
    algorithm in lexicographic order). Returns a Classification (equal to its outcome
    string)."""
    tmp = None
    if not isinstance(file, (str, os.PathLike)):
        pts = np.asarray(file, dtype=np.float64)
        if pts.ndim != 2 or pts.shape[1] != 2:
            raise ValueError("replay: expected a file or an array of shape (n, 2)")
        tmp = tempfile.NamedTemporaryFile("w", suffix=".xy", delete=False)
        with tmp:
            tmp.write("".join(f"{x.hex()} {y.hex()}\n" for x, y in pts.tolist()))
        file = tmp.name
        given = {}
    else:
        try:
            given = read_fixture(file).get("options", {})
        except (OSError, ValueError):
            given = {}  # the command says what is wrong with the file
    options = {**given, **{k: v for k, v in dict(kernel=kernel, incircle=incircle, algorithm=algorithm,
                                                  order=order).items() if v is not None}}
    if "kernel" not in options:
        raise TypeError("replay: give a kernel (the file has no 'reproduce' line naming one)")
    args = ["study", "replay", "-i", os.fspath(file)]
    for name in ("kernel", "incircle", "algorithm", "order"):
        if name in options:
            args += [f"--{name}", str(options[name])]
    try:
        _, stdout = _call(args, timeout)
    finally:
        if tmp is not None:
            os.unlink(tmp.name)
    m = re.fullmatch(r"(\w+)(?: \((.*)\))?", stdout.strip())
    if not m:
        raise StudyError(f"replay printed something unexpected: {stdout!r}")
    return Classification(m.group(1), m.group(2) or "")


def list_failure_map_presets():
    """The command's failure-map presets: {name: description}."""
    _, stdout = _call(["study", "failure-map", "--list-presets"])
    return dict(line.split("  ", 1) for line in stdout.splitlines() if line.strip())


# ---------------------------------------------------------------------------------------
# Tables

_INT = re.compile(r"[-+]?\d+")


def _column(name, values):
    if values and all(_INT.fullmatch(v) for v in values) and "rate" not in name:
        return np.array([int(v) for v in values], dtype=np.int64)
    try:
        if values:
            return np.array([float(v) for v in values], dtype=np.float64)
    except ValueError:
        pass
    return np.array(values, dtype=f"U{max([1, *map(len, values)])}")


def read_table(path):
    """One CSV file of a study as a numpy structured array, a field per column (the
    header's names as written): int64 where every cell is an integer, float64 where every
    cell is a number (and in every numeric column named "... rate"), str otherwise."""
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    if not rows:
        return np.zeros(0, dtype=[])
    header, body = rows[0], rows[1:]
    for i, r in enumerate(body):
        if len(r) != len(header):
            raise ValueError(f"{path}: row {i + 2} has {len(r)} cells, the header {len(header)}")
    columns = [_column(name, [r[k] for r in body]) for k, name in enumerate(header)]
    table = np.zeros(len(body), dtype=[(name, c.dtype) for name, c in zip(header, columns)])
    for name, c in zip(header, columns):
        table[name] = c
    return table


# ---------------------------------------------------------------------------------------
# Failure maps in Python

def nudge(v, steps):
    """v moved by |steps| representable doubles (exidel.testing.nudge: the C++ testing::nudge)."""
    return _ulp.nudge(v, steps)


_ARITY = {"orient2d": 3, "incircle": 4, "incircle_cosine": 4, "compare_distance": 3,
          "orient3d": 4, "insphere": 5}
_SPACE = ("orient3d", "insphere")  # predicates of points (x, y, z)


def _lattice_circle(s):
    r = 2.0 ** -s
    return [(2 + x * r, 2 + y * r) for x, y in ((-5, 0), (4, 3), (-3, 4), (3, -4))]


_KETTNER = [list(c) for c in _ulp.KETTNER_CONFIGURATIONS]

# The coplanar and cospherical configurations of the study's maps of space (their
# construction is explained in lib/research/src/failure_map.cpp).
_PLANE_DIAGONAL = [(12.0, 12.0, 1.0), (24.0, 24.0, 3.0), (1.0, 1.0, 12.0), (0.5, 0.5, 0.5)]
_PLANE_TILTED = [(12.0, -4.5, -6.0), (-9.0, 20.5, -10.0), (-7.0, -8.0, 16.5), (0.75, 0.75, 0.0)]


def _lattice_sphere(s):
    r = 2.0 ** -s
    return [(2 + x * r, 2 + y * r, 2 + z * r)
            for x, y, z in ((3, 0, 0), (0, 3, 0), (0, 0, 3), (-1, -2, -2), (-2, 2, -1))]


def failure_map_presets():
    """The failure-map presets of the study (lib/research failure_map_presets()), each a
    dict of compute_failure_map's arguments plus "name": kettner1..3 (p moved over
    [0, 256)^2, orient2d(p, q, r)), kettner1-pivot-q/-r (the same p moved, passed as
    orient2d(q, r, p) / orient2d(r, p, q)), and four exactly cocircular points a, b, c, d
    (radius 5 * 2^-s around (2, 2)) with d (or a) moved over the centred window
    [-128, 128)^2 for incircle and incircle_cosine; in space, orient3d of four exactly
    coplanar points (on x = y and on x + y + z = 3/2) with d (or a) moved in x and y, and
    insphere of five exactly cospherical points (radius 3 * 2^-s around (2, 2, 2)) with e
    (or a) moved, over the centred window."""
    def kettner(i, order, name):
        return dict(name=name, predicate="orient2d", points=_KETTNER[i], move=0, order=order,
                    centered=False)

    def circle(predicate, s, move, name):
        return dict(name=name, predicate=predicate, points=_lattice_circle(s), move=move,
                    order=[0, 1, 2, 3], centered=True)

    v = [kettner(0, [0, 1, 2], "kettner1"), kettner(1, [0, 1, 2], "kettner2"),
         kettner(2, [0, 1, 2], "kettner3"), kettner(0, [1, 2, 0], "kettner1-pivot-q"),
         kettner(0, [2, 0, 1], "kettner1-pivot-r")]
    v += [circle("incircle", s, 3, f"incircle-s{s}") for s in (2, 12, 24)]
    v.append(circle("incircle", 12, 0, "incircle-s12-move-a"))
    v += [circle("incircle_cosine", s, 3, f"cosine-s{s}") for s in (2, 12, 24)]

    def space(predicate, points, move, name):
        return dict(name=name, predicate=predicate, points=points, move=move,
                    order=list(range(len(points))), centered=True, axes="xy")

    v += [space("orient3d", _PLANE_DIAGONAL, 3, "orient3d-diagonal"),
          space("orient3d", _PLANE_TILTED, 3, "orient3d-tilted"),
          space("orient3d", _PLANE_TILTED, 0, "orient3d-tilted-move-a")]
    v += [space("insphere", _lattice_sphere(s), 4, f"insphere-s{s}") for s in (2, 12, 24)]
    v.append(space("insphere", _lattice_sphere(12), 0, "insphere-s12-move-a"))
    for p in v:
        p.update(width=256, height=256, step=1)
    return v


def failure_map_preset(name):
    """One preset as keyword arguments of compute_failure_map (without "name")."""
    for p in failure_map_presets():
        if p["name"] == name:
            del p["name"]
            return p
    names = ", ".join(p["name"] for p in failure_map_presets())
    raise ValueError(f"unknown failure-map preset {name!r} (presets: {names})")


@dataclasses.dataclass
class FailureMap:
    """A failure map: signs and exact are (height, width) int8 arrays, row j the offset
    offsets_y[j] in y, column i the offset offsets_x[i] in x (in steps of one ulp of the
    moving coordinate); x and y the moving point's coordinates per column and row."""

    signs: np.ndarray
    exact: np.ndarray
    offsets_x: np.ndarray
    offsets_y: np.ndarray
    x: np.ndarray
    y: np.ndarray
    predicate: str
    kernel: str

    @property
    def wrong_cells(self):
        """(height, width) bool array: the cells where the kernel's sign is wrong."""
        return self.signs != self.exact

    @property
    def wrong_count(self):
        """How many cells are wrong (an int)."""
        return int(np.count_nonzero(self.signs != self.exact))

    def counts(self, exact=False):
        """(negative, zero, positive) cell counts of the kernel's (or the exact) signs."""
        s = self.exact if exact else self.signs
        return tuple(int(np.count_nonzero(s == v)) for v in (-1, 0, 1))


def _centred(centered, corner):
    """The window of a failure map from the keywords centered and corner (None: not given):
    centred unless centered=False or corner=True."""
    if centered is not None and corner is not None and bool(centered) == bool(corner):
        raise ValueError(f"centered={centered!r} and corner={corner!r} choose different "
                         "windows: give one")
    if corner is not None:
        return not corner
    return True if centered is None else bool(centered)


def compute_failure_map(points, move=0, predicate="orient2d", kernel="double", width=256,
                        height=256, step=1, centered=None, order=None, reference="exact",
                        axes="xy", corner=None):
    """One predicate evaluated while points[move] moves over a width x height grid: cell
    (j, i) moves its x by offset(i) * step and its y by offset(j) * step representable
    doubles, as the failure-map study: offset(i) = i - width // 2 by default (the window
    centred on the point, as `exidel study failure-map` draws a custom map), or
    offset(i) = i with centered=False or corner=True (the point at the window's corner).

    points     3 (orient2d, compare_distance) or 4 (incircle, incircle_cosine) points
               (x, y); 4 (orient3d) or 5 (insphere) points (x, y, z)
    order      argument k of the predicate is points[order[k]] (default 0, 1, 2, ...):
               the floating formulas subtract their first argument (orient2d) or their
               last (the others)
    axes       in space: the moving point's coordinates on the map's x and y, two letters
               of "xyz" ("xy": x and y move, z stays)
    kernel     the kernel mapped; reference the exact kernel the map is compared with
    Returns a FailureMap (.signs, .exact, .wrong_cells, .wrong_count, ...); its .x and .y
    are the values of the moving coordinates per column and row.
    """
    from . import _core

    if predicate not in _ARITY:
        raise ValueError(f"unknown predicate {predicate!r}: expected one of {', '.join(_ARITY)}")
    n = _ARITY[predicate]
    dim = 3 if predicate in _SPACE else 2
    pts = np.asarray(points, dtype=np.float64)
    if pts.shape != (n, dim):
        raise ValueError(f"{predicate} needs {n} points (an array of shape ({n}, {dim})), got shape {pts.shape}")
    if not np.all(np.isfinite(pts)):
        raise ValueError("failure map points must be finite")
    move = int(move)
    if not 0 <= move < n:
        raise ValueError(f"the moving point index must be in [0, {n})")
    order = list(range(n)) if order is None else [int(k) for k in order]
    if sorted(order) != list(range(n)):
        raise ValueError(f"order must be a permutation of 0..{n - 1}, got {order}")
    width, height, step = int(width), int(height), int(step)
    if width < 1 or height < 1:
        raise ValueError("width and height must be at least 1")
    if step < 1:
        raise ValueError("step must be at least 1 ulp")
    if dim == 2 and axes != "xy":
        raise ValueError("axes is for orient3d and insphere maps")
    if not (isinstance(axes, str) and len(axes) == 2 and set(axes) <= set("xyz"[:dim])
            and axes[0] != axes[1]):
        raise ValueError(f"axes must be two different letters of x, y, z (e.g. 'xz'), got {axes!r}")
    ax, ay = "xyz".index(axes[0]), "xyz".index(axes[1])

    centered = _centred(centered, corner)
    offsets_x = np.arange(width, dtype=np.int64) - (width // 2 if centered else 0)
    offsets_y = np.arange(height, dtype=np.int64) - (height // 2 if centered else 0)
    bx, by = float(pts[move, ax]), float(pts[move, ay])
    xs = np.array([nudge(bx, int(k) * step) for k in offsets_x])
    ys = np.array([nudge(by, int(k) * step) for k in offsets_y])
    moving = np.tile(pts[move], (height * width, 1))
    moving[:, ax] = np.tile(xs, height)
    moving[:, ay] = np.repeat(ys, width)  # row j = offset j in y
    args = [moving if order[a] == move else pts[order[a]] for a in range(n)]
    f = getattr(_core, predicate)
    signs = np.asarray(f(*args, kernel=kernel), dtype=np.int8).reshape(height, width)
    exact = np.asarray(f(*args, kernel=reference), dtype=np.int8).reshape(height, width)
    return FailureMap(signs, exact, offsets_x, offsets_y, xs, ys, predicate, kernel)
