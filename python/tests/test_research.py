"""exidel.research: the studies through the exidel command (typed tables equal to the CSV
files, the report's rerun line, errors, the EXIDEL_CLI override, replay), and the failure
map computed in Python against the C++ study: wrong counts per preset and kernel, and every
cell of the study's PNG."""

import csv
import math
import os
import shlex
import stat
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import exidel
from exidel import research

REPO = Path(__file__).resolve().parents[2]


@pytest.fixture(autouse=True)
def _cli_env(monkeypatch, request):
    """Every real run uses the command the suite was given (conftest's exidel_cli)."""
    if "exidel_cli" in request.fixturenames:
        monkeypatch.setenv("EXIDEL_CLI", request.getfixturevalue("exidel_cli"))


def check_tables_match_csv(result):
    """Every CSV file of the folder is a table, typed, with the same rows."""
    files = sorted(result.out.rglob("*.csv"))
    assert files and len(files) == len(result.tables)
    for f in files:
        name = f.relative_to(result.out).with_suffix("").as_posix()
        table = result.tables[name]
        with open(f, newline="") as fh:
            rows = list(csv.reader(fh))
        assert list(table.dtype.names) == rows[0]
        assert len(table) == len(rows) - 1
        for column, field in enumerate(rows[0]):
            kind = table.dtype[field]
            assert kind in (np.dtype(np.int64), np.dtype(np.float64)) or kind.kind == "U"
            for k, r in enumerate(rows[1:]):
                cell, value = r[column], table[field][k]
                if kind == np.int64:
                    assert int(cell) == value
                elif kind == np.float64:
                    assert float(cell) == value or (math.isnan(value) and cell.lower() == "nan")
                else:
                    assert cell == value


def check_report(result, study, *flags):
    text = result.report.read_text()
    lines = text.splitlines()
    assert lines[0].startswith("# ")
    rerun = next(line for line in lines[:4] if line.startswith("Rerun: `exidel study "))
    command = rerun[len("Rerun: `"):rerun.rindex("`")]
    assert command.startswith(f"exidel study {study} ")
    assert command.endswith(f"--out {shlex.quote(str(result.out))}")
    for flag in flags:
        assert flag in command, (flag, command)
    return command


# --- the studies through the command -------------------------------------------------------

FM_PRESETS = ["kettner1", "kettner1-pivot-q", "incircle-s2", "incircle-s12-move-a", "cosine-s2",
              "orient3d-tilted-move-a", "insphere-s2"]
FM_KERNELS = ["double", "long-double", "adaptive"]


@pytest.fixture(scope="module")
def fm_study(tmp_path_factory):
    out = tmp_path_factory.mktemp("fm") / "failure-map"
    return research.failure_map(out, preset=FM_PRESETS, kernel=FM_KERNELS, jobs=2)


def test_failure_map_study_tables_and_report(exidel_cli, fm_study):
    r = fm_study
    check_tables_match_csv(r)
    t = r.tables["failure_map"]
    assert t.dtype["cells"] == np.int64 and t.dtype["wrong"] == np.int64
    assert t.dtype["wrong rate"] == np.float64 and t.dtype["preset"].kind == "U"
    assert len(t) == len(FM_PRESETS) * len(FM_KERNELS)
    assert set(t["kernel"]) == set(FM_KERNELS)
    assert np.all(t["wrong"][t["kernel"] == "adaptive"] == 0)
    check_report(r, "failure-map", "--preset " + ",".join(FM_PRESETS), "--kernel " + ",".join(FM_KERNELS))
    assert "kettner1" in r.stdout and r["failure_map"] is t


def test_python_failure_map_equals_the_study(exidel_cli, fm_study):
    t = fm_study.tables["failure_map"]
    for row in t:
        m = research.compute_failure_map(**research.failure_map_preset(str(row["preset"])),
                                         kernel=str(row["kernel"]))
        assert m.signs.shape == (256, 256) and m.signs.dtype == np.int8
        assert m.wrong_count == row["wrong"], (row["preset"], row["kernel"])
        counts = " / ".join(map(str, m.counts()))
        exact = " / ".join(map(str, m.counts(exact=True)))
        assert (counts, exact) == (row["neg / zero / pos"], row["exact neg / zero / pos"])
    assert {"kettner1", "incircle-s2", "orient3d-tilted-move-a", "insphere-s2"} <= set(t["preset"][t["wrong"] > 0])


def panels(png, width, height):
    """The three panels of a failure-map PNG as (height, width, 3) RGB cell arrays, row j =
    offset j in y (lib/research failure_map_layout: 2 px per cell up to 256 x 256, panels
    from x = 96 with 24 px gaps, from y = 62)."""
    import matplotlib.image
    rgb = np.round(matplotlib.image.imread(png)[..., :3] * 255).astype(np.int64)
    cell = 2 if width <= 256 and height <= 256 else 1
    left = [96 + p * (width * cell + 24) for p in range(3)]
    return [rgb[62:62 + height * cell:cell, x:x + width * cell:cell][::-1] for x in left]


def colours(signs):
    from exidel.plot import SIGN_COLOURS
    out = np.empty(signs.shape + (3,), dtype=np.int64)
    for s, c in SIGN_COLOURS.items():
        out[signs == s] = c
    return out


def test_python_failure_map_equals_every_cell_of_the_pictures(exidel_cli, fm_study):
    for preset in ("kettner1", "incircle-s2", "orient3d-tilted-move-a"):
        m = research.compute_failure_map(**research.failure_map_preset(preset), kernel="double")
        signs, exact, _ = panels(fm_study.out / f"{preset}-double.png", 256, 256)
        assert np.array_equal(signs, colours(m.signs))
        assert np.array_equal(exact, colours(m.exact))


def test_custom_failure_map_conventions(exidel_cli, tmp_path):
    """Step, centred window, a non-square window, another moving point and order, and a
    window that crosses zero and the subnormals."""
    cases = [
        dict(predicate="orient2d", points=[(0.5, 0.5), (12.0, 12.0), (24.0, 24.0)], move=2,
             order=[2, 0, 1], step=1, centered=True, width=40, height=24),
        dict(predicate="orient2d", points=[(-2e-323, 1.5e-323), (1.0, 1.0), (-1.0, -1.0)], move=0,
             order=[0, 1, 2], step=2, centered=True, width=20, height=16),
        dict(predicate="incircle", points=[(0.75, 2.0), (3.0, 2.75), (1.25, 3.0), (2.75, 1.0)],
             move=3, order=[3, 0, 1, 2], step=2, centered=False, width=30, height=10),
        dict(predicate="incircle_cosine", points=[(0.75, 2.0), (3.0, 2.75), (1.25, 3.0), (2.75, 1.0)],
             move=1, step=5, centered=True, width=30, height=10),
        dict(predicate="orient3d", points=[(12.0, -4.5, -6.0), (-9.0, 20.5, -10.0), (-7.0, -8.0, 16.5),
                                           (0.75, 0.75, 0.0)],
             move=3, order=[3, 0, 1, 2], step=1, centered=True, width=36, height=20, axes="zx"),
        dict(predicate="insphere", points=research.failure_map_preset("insphere-s2")["points"],
             move=4, step=3, centered=True, width=28, height=30, axes="yz"),
    ]
    wrong = []
    for k, spec in enumerate(cases):
        r = research.failure_map(tmp_path / str(k), kernel=["double"], **spec)
        row = r.tables["failure_map"][0]
        m = research.compute_failure_map(**spec, kernel="double")
        assert m.signs.shape == (spec["height"], spec["width"])
        assert (m.wrong_count, row["cells"]) == (row["wrong"], m.signs.size)
        wrong.append(m.wrong_count)
        assert " / ".join(map(str, m.counts(exact=True))) == row["exact neg / zero / pos"]
        png = tmp_path / str(k) / "custom-double.png"
        if png.exists():  # drawn only when the kernel got a cell wrong
            signs, exact, _ = panels(png, spec["width"], spec["height"])
            assert np.array_equal(signs, colours(m.signs)) and np.array_equal(exact, colours(m.exact))
    assert all(wrong), wrong  # every case has cells the double kernel gets wrong
    # The second case crosses zero in x and y.
    m = research.compute_failure_map(**cases[1], kernel="double")
    assert m.x.min() < 0 < m.x.max() and m.y.min() < 0 < m.y.max()


def test_custom_failure_map_is_centred_unless_it_asks_for_the_corner(exidel_cli, tmp_path):
    """No window keyword: centred on the moving point (its unmoved, exactly collinear
    configuration at the centre cell), in Python and in the command alike; corner=True and
    centered=False: the point at cell (0, 0)."""
    spec = dict(predicate="orient2d", points=[(0.5, 0.5), (12.0, 12.0), (24.0, 24.0)], width=24,
                height=16)
    m = research.compute_failure_map(**spec)
    assert m.offsets_x[12] == 0 and m.offsets_y[8] == 0 and m.exact[8, 12] == 0
    assert m.exact[0, 0] != 0
    c = research.compute_failure_map(**spec, corner=True)
    assert np.array_equal(c.offsets_x, np.arange(24)) and np.array_equal(c.offsets_y, np.arange(16))
    assert c.exact[0, 0] == 0 and not np.array_equal(c.exact, m.exact)
    assert np.array_equal(research.compute_failure_map(**spec, centered=False).exact, c.exact)
    assert np.array_equal(research.compute_failure_map(**spec, centered=True).exact, m.exact)
    with pytest.raises(ValueError, match="give one"):
        research.compute_failure_map(**spec, centered=True, corner=True)
    windows = [({}, m, "--centered"), ({"centered": True}, m, "--centered"),
               ({"corner": True}, c, "--corner"), ({"centered": False}, c, "--corner"),
               ({"corner": False}, m, "--centered")]
    for k, (window, expected, flag) in enumerate(windows):
        r = research.failure_map(tmp_path / str(k), kernel=["adaptive"], **spec, **window)
        _, exact, _ = panels(tmp_path / str(k) / "custom-adaptive.png", 24, 16)
        assert np.array_equal(exact, colours(expected.exact)), window
        rerun = r.report.read_text().split("Rerun: `", 1)[1].split("`", 1)[0]
        assert f" {flag} " in rerun, (window, rerun)
    with pytest.raises(TypeError, match="give one"):
        research.failure_map(tmp_path / "x", **spec, centered=True, corner=True)


def test_exact_kernels_agree_and_presets_match_the_command(exidel_cli):
    for preset in ("kettner2", "incircle-s24", "cosine-s12"):
        spec = dict(research.failure_map_preset(preset), width=64, height=48)
        a = research.compute_failure_map(**spec, kernel="adaptive", reference="exact")
        b = research.compute_failure_map(**spec, kernel="exact-cpp", reference="adaptive")
        assert np.array_equal(a.exact, a.signs) and np.array_equal(a.exact, b.exact)
        assert a.wrong_count == 0 and b.wrong_count == 0
    names = [p["name"] for p in research.failure_map_presets()]
    assert names == list(research.list_failure_map_presets())


def test_nudge_steps_like_nextafter():
    for v in (0.0, -0.0, 1.0, -1.0, 5e-324, -5e-324, 2.2250738585072014e-308, 0.5, 1e300):
        for steps in (-3, -1, 0, 1, 2, 5):
            w = v
            for _ in range(abs(steps)):
                w = math.nextafter(w, math.inf if steps > 0 else -math.inf)
            assert research.nudge(v, steps) == w, (v, steps)
    top = sys.float_info.max
    assert research.nudge(top, 10) == top and research.nudge(-top, -10) == -top
    assert research.nudge(-5e-324, 2) == 5e-324
    # As the C++ testing::nudge: an infinity moves only toward the finite doubles.
    assert research.nudge(math.inf, 1) == math.inf and research.nudge(math.inf, -1) == top


def test_compute_failure_map_rejects_bad_specs():
    pts = [(0.5, 0.5), (12.0, 12.0), (24.0, 24.0)]
    with pytest.raises(ValueError, match="4 points"):
        research.compute_failure_map(pts, predicate="incircle")
    with pytest.raises(ValueError, match="permutation"):
        research.compute_failure_map(pts, order=[0, 0, 1])
    with pytest.raises(ValueError, match="moving point"):
        research.compute_failure_map(pts, move=3)
    with pytest.raises(ValueError, match="unknown predicate"):
        research.compute_failure_map(pts, predicate="orient4d")
    with pytest.raises(ValueError, match=r"shape \(4, 3\)"):
        research.compute_failure_map(pts + [(1.0, 2.0)], predicate="orient3d")
    with pytest.raises(ValueError, match="axes is for orient3d"):
        research.compute_failure_map(pts, axes="xz")
    space = research.failure_map_preset("orient3d-tilted")
    for bad in ("xx", "xw", "x", (0, 1)):
        with pytest.raises(ValueError, match="axes must be"):
            research.compute_failure_map(**dict(space, axes=bad))
    with pytest.raises(ValueError, match="unknown failure-map preset"):
        research.failure_map_preset("kettner9")


def test_precision_study_and_its_rerun_line(exidel_cli, tmp_path):
    out = tmp_path / "precision"
    r = research.precision(out, quick=True, bits=[24, 53], families=["near_integer_grid", "near_dyadic_line"],
                           samples=100, seed=7)
    check_tables_match_csv(r)
    p = r.tables["precision"]
    assert set(p["bits"].tolist()) == {24, 53} and p.dtype["rate"] == np.float64
    assert np.all(p["total"] == 100)
    command = check_report(r, "precision", "--quick", "--seed 7", "--bits 24,53", "--samples 100")
    # The rerun line writes the same tables again.
    before = {f.name: f.read_bytes() for f in out.glob("*.csv")}
    for f in out.glob("*.csv"):
        f.unlink()
    subprocess.run([exidel_cli, *shlex.split(command)[1:]], check=True, capture_output=True)
    assert {f.name: f.read_bytes() for f in out.glob("*.csv")} == before


def test_precision_plot_is_one_line_per_family_as_svg_and_png(exidel_cli, tmp_path):
    """precision.svg parsed as XML: a panel per formulation, a series per family in each;
    precision.png decoded by Pillow (through matplotlib) at twice the SVG's size."""
    import xml.etree.ElementTree as ET
    import matplotlib.image
    families = ["near_integer_grid", "near_dyadic_line", "kettner"]
    research.precision(tmp_path, bits=[24, 53, 64], families=families, samples=40)
    ns = {"s": "http://www.w3.org/2000/svg"}
    svg = ET.parse(tmp_path / "precision.svg").getroot()
    panels = svg.findall("s:g[@class='panel']", ns)
    assert [p.find("s:title", ns).text for p in panels] == ["orient2d", "incircle", "incircle_cosine"]
    for p in panels:
        series = p.findall("s:g[@class='series']", ns)
        assert [g.find("s:title", ns).text for g in series] == families
        assert all(len(g.find("s:polyline", ns).get("points").split()) == 3 for g in series)
    rgb = matplotlib.image.imread(tmp_path / "precision.png")
    assert rgb.shape[:2] == (2 * int(float(svg.get("height"))), 2 * int(float(svg.get("width"))))
    assert len(np.unique((rgb[..., :3] * 255).round().reshape(-1, 3), axis=0)) > 5


def test_triangulation_study_and_replay_of_its_fixtures(exidel_cli, tmp_path):
    r = research.run("triangulation", tmp_path / "tri", quick=True, kernel=["double", "adaptive"],
                     families="uniform_scaled,kettner", seeds=2, sizes=[30], algorithm="external",
                     bits=[24], shrink=1)
    check_tables_match_csv(r)
    assert set(r.tables) == {"triangulation", "triangulation_summary", "triangulation_work",
                             "triangulation_precision"}
    s = r.tables["triangulation_summary"]
    assert np.all(s["runs"] == s["delaunay"] + s["not_delaunay"] + s["invalid"] + s["failure"] + s["guard"])
    assert np.all(s["delaunay"][s["kernel"] == "adaptive"] == s["runs"][s["kernel"] == "adaptive"])
    check_report(r, "triangulation", "--kernel double,adaptive", "--sizes 30", "--shrink 1")
    fixtures = sorted((tmp_path / "tri" / "fixtures").glob("*.xy"))
    assert fixtures
    for f in fixtures[:3]:
        fixture = research.read_fixture(f)
        assert fixture["points"].shape[1] == 2 and fixture["options"]["kernel"] == "double"
        c = research.replay(f)  # kernel and policy from the fixture's reproduce line
        assert (c.outcome, c.detail) == (fixture["outcome"], fixture["detail"]) and c == fixture["outcome"]
        policy = fixture["options"]["incircle"]
        assert research.replay(f, "adaptive", incircle=policy) == "delaunay"
        assert research.replay(fixture["points"], "double", incircle=policy) == fixture["outcome"]


def test_replay_of_a_repository_fixture_and_of_an_array(exidel_cli):
    f = REPO / "tests" / "research" / "fixtures" / "long_double_cosine_kettner_not_ccw.xy"
    if f.exists():
        c = research.replay(f, "long-double", incircle="cosine")
        assert (c.outcome, c.detail) == ("invalid", "not_ccw")
        assert research.replay(f, "exact", incircle="cosine", algorithm="dwyer") == "delaunay"
    pts = np.random.default_rng(3).random((40, 2))
    assert research.replay(pts, "adaptive", order="radial").outcome == "delaunay"
    with pytest.raises(research.StudyError, match="cannot open"):
        research.replay("/nonexistent/points.xy", "adaptive")
    with pytest.raises(ValueError):
        research.replay(pts, "bogus-kernel")
    with pytest.raises(TypeError, match="kernel"):
        research.replay(pts)


def test_stages_study(exidel_cli, tmp_path):
    r = research.stages(tmp_path / "stages", families=["uniform", "near_lattice_circle"], samples=200,
                        seeds=1, size=60)
    check_tables_match_csv(r)
    t = r.tables["stages"]
    assert t.dtype["calls"] == np.int64 and t.dtype["filter"] == np.float64
    assert set(t["family"]) == {"uniform", "near_lattice_circle"}
    check_report(r, "stages", "--families uniform,near_lattice_circle", "--samples 200", "--size 60")


def test_unknown_study_and_options(exidel_cli, tmp_path):
    with pytest.raises(ValueError, match="unknown study 'delaunay'"):
        research.run("delaunay", tmp_path)
    with pytest.raises(TypeError, match="has no option 'samples'"):
        research.failure_map(tmp_path, samples=10)
    with pytest.raises(TypeError, match="all"):
        research.run_all(tmp_path, kernel="double")
    with pytest.raises(research.StudyOptionError, match="preset") as e:
        research.failure_map(tmp_path / "x", preset="kettner9")
    assert isinstance(e.value, ValueError) and e.value.returncode == 2 and "kettner9" in e.value.stderr


def test_a_bad_command_path_is_a_clear_error(monkeypatch, tmp_path):
    monkeypatch.setenv("EXIDEL_CLI", str(tmp_path / "no-such-exidel"))
    with pytest.raises(research.StudyError, match="EXIDEL_CLI"):
        research.precision(tmp_path / "p", quick=True)


def fake_cli(tmp_path, body):
    path = tmp_path / "fake-exidel"
    path.write_text("#!/bin/sh\n" + body)
    path.chmod(path.stat().st_mode | stat.S_IXUSR)
    return path


def test_exidel_cli_overrides_the_package_path(monkeypatch, tmp_path):
    """EXIDEL_CLI names the command: here a stand-in that records its arguments and writes
    `all`'s layout (the real `study all --quick` takes minutes)."""
    log = tmp_path / "args"
    cli = fake_cli(tmp_path, f"""echo "$@" > {log}
while [ $# -gt 0 ]; do [ "$1" = --out ] && out=$2; shift; done
for s in failure-map precision; do
  mkdir -p "$out/$s"; printf 'a,b,c\\n1,2.5,x\\n-3,4,"y,z"\\n' > "$out/$s/$s.csv"
done
echo '# all' > "$out/report.md"
echo done
""")
    monkeypatch.setenv("EXIDEL_CLI", str(cli))
    assert research.cli_path() == str(cli)
    r = research.run_all(tmp_path / "all", seed=5, jobs=2, quick=True)
    assert log.read_text().split() == ["study", "all", "--out", str(tmp_path / "all"), "--seed", "5",
                                       "--jobs", "2", "--no-progress", "--quick"]
    assert sorted(r.tables) == ["failure-map/failure-map", "precision/precision"]
    t = r.tables["precision/precision"]
    assert t.dtype.names == ("a", "b", "c")
    assert [t.dtype[k] for k in "ab"] == [np.dtype(np.int64), np.dtype(np.float64)]
    assert t["c"].tolist() == ["x", "y,z"] and t["a"].tolist() == [1, -3]
    assert r.report == tmp_path / "all" / "report.md" and r.stdout == "done\n"


def test_a_failing_command_raises_with_its_stderr(monkeypatch, tmp_path):
    monkeypatch.setenv("EXIDEL_CLI", str(fake_cli(tmp_path, "echo 'exidel study: disk full' >&2; exit 1\n")))
    with pytest.raises(research.StudyError, match="disk full") as e:
        research.stages(tmp_path / "s")
    assert e.value.returncode == 1 and not isinstance(e.value, ValueError)


def test_importing_exidel_imports_no_matplotlib():
    code = "import sys, exidel, exidel.research, exidel.plot; print('matplotlib' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True,
                         env={**os.environ, "MPLBACKEND": "Agg"})
    assert out.stdout.strip() == "False"
    assert exidel.research is research
