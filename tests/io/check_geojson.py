#!/usr/bin/python3
"""Checks GeoJSON against the structure RFC 7946 prescribes, with the standard library
only (ctest: exidel_geojson_rfc7946).

usage: check_geojson.py FILE...              check each file, print "ok: FILE (...)"
       check_geojson.py --exidel EXIDEL DIR  write exidel's GeoJSON outputs into DIR
                                             (triangulations, constrained ones, Voronoi
                                             diagrams, collinear, tiny and z input) and
                                             check every one

Checks: every object's "type" member; a FeatureCollection has a "features" array of
Features and nothing else as type; a Feature has "geometry" (a geometry object or null)
and "properties" (an object or null) members; geometries have the coordinates their type
needs (Point a position, MultiPoint and LineString arrays of positions, a LineString at
least two, Polygon an array of linear rings, Multi* arrays of those, a GeometryCollection
"geometries"); a position is 2 or 3 finite numbers (no booleans, no NaN or Infinity); a
linear ring has at least 4 positions and is closed (first == last); a Polygon's exterior
ring is counter-clockwise and its holes clockwise (exact signed areas, fractions); a
"bbox" has 2n numbers with min <= max. Exit status 0, or 1 with "FILE: where: what"."""
import json
import math
import os
import random
import subprocess
import sys
from fractions import Fraction

GEOMETRIES = {"Point", "MultiPoint", "LineString", "MultiLineString", "Polygon",
              "MultiPolygon", "GeometryCollection"}


class Invalid(Exception):
    pass


def fail(where, what):
    raise Invalid(f"{where}: {what}")


def reject_constant(name):
    raise Invalid(f"{name} is not a JSON number (RFC 8259)")


def is_number(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def check_position(p, where):
    if not isinstance(p, list) or len(p) not in (2, 3):
        fail(where, f"a position is an array of 2 or 3 numbers, got {json.dumps(p)[:60]}")
    for v in p:
        if not is_number(v) or not math.isfinite(v):
            fail(where, f"a coordinate is not a finite number: {v!r}")


def check_positions(ps, where, minimum):
    if not isinstance(ps, list):
        fail(where, "expected an array of positions")
    if len(ps) < minimum:
        fail(where, f"at least {minimum} positions needed, got {len(ps)}")
    for k, p in enumerate(ps):
        check_position(p, f"{where}[{k}]")


def signed_area2(ring):
    # Twice the exact signed area of the closed ring (shoelace, in fractions).
    s = Fraction(0)
    for a, b in zip(ring, ring[1:]):
        s += Fraction(a[0]) * Fraction(b[1]) - Fraction(b[0]) * Fraction(a[1])
    return s


def check_polygon(rings, where):
    if not isinstance(rings, list) or not rings:
        fail(where, "a Polygon's coordinates are a non-empty array of linear rings")
    for k, ring in enumerate(rings):
        w = f"{where}[{k}]"
        check_positions(ring, w, 4)
        if ring[0] != ring[-1]:
            fail(w, "a linear ring is closed: its last position equals its first")
        area = signed_area2(ring)
        if k == 0 and area <= 0:
            fail(w, "the exterior ring is not counter-clockwise (RFC 7946 section 3.1.6)")
        if k > 0 and area >= 0:
            fail(w, "a hole is not clockwise (RFC 7946 section 3.1.6)")


def check_bbox(obj, where):
    if "bbox" not in obj:
        return
    b = obj["bbox"]
    if not isinstance(b, list) or len(b) not in (4, 6) or not all(is_number(v) for v in b):
        fail(where, "bbox is an array of 2n numbers")
    n = len(b) // 2
    if any(b[k] > b[k + n] for k in range(n)):
        fail(where, "bbox: a minimum above its maximum")


def check_geometry(g, where):
    if not isinstance(g, dict):
        fail(where, "a geometry is an object")
    t = g.get("type")
    if t not in GEOMETRIES:
        fail(where, f"unknown geometry type {t!r}")
    check_bbox(g, where)
    if t == "GeometryCollection":
        if not isinstance(g.get("geometries"), list):
            fail(where, "a GeometryCollection has a \"geometries\" array")
        for k, m in enumerate(g["geometries"]):
            check_geometry(m, f"{where}.geometries[{k}]")
        return
    if "coordinates" not in g:
        fail(where, f"a {t} has \"coordinates\"")
    c = g["coordinates"]
    w = f"{where}.coordinates"
    if t == "Point":
        check_position(c, w)
    elif t == "MultiPoint":
        check_positions(c, w, 0)
    elif t == "LineString":
        check_positions(c, w, 2)
    elif t == "MultiLineString":
        if not isinstance(c, list):
            fail(w, "expected an array of LineStrings")
        for k, line in enumerate(c):
            check_positions(line, f"{w}[{k}]", 2)
    elif t == "Polygon":
        check_polygon(c, w)
    else:
        if not isinstance(c, list):
            fail(w, "expected an array of Polygons")
        for k, p in enumerate(c):
            check_polygon(p, f"{w}[{k}]")


def check_feature(f, where):
    if not isinstance(f, dict) or f.get("type") != "Feature":
        fail(where, "expected a Feature object")
    if "geometry" not in f:
        fail(where, "a Feature has a \"geometry\" member (null allowed)")
    if "properties" not in f:
        fail(where, "a Feature has a \"properties\" member (null allowed)")
    if f["properties"] is not None and not isinstance(f["properties"], dict):
        fail(where, "properties is an object or null")
    check_bbox(f, where)
    if f["geometry"] is not None:
        check_geometry(f["geometry"], f"{where}.geometry")


def check_document(doc):
    if not isinstance(doc, dict) or "type" not in doc:
        fail("$", "a GeoJSON text is an object with a \"type\"")
    t = doc["type"]
    if t == "FeatureCollection":
        check_bbox(doc, "$")
        if not isinstance(doc.get("features"), list):
            fail("$", "a FeatureCollection has a \"features\" array")
        for k, f in enumerate(doc["features"]):
            check_feature(f, f"$.features[{k}]")
    elif t == "Feature":
        check_feature(doc, "$")
    else:
        check_geometry(doc, "$")


def check_text(text):
    doc = json.loads(text, parse_constant=reject_constant)
    check_document(doc)
    return doc


def check_file(path):
    with open(path, encoding="utf-8") as f:
        return check_text(f.read())


# ---- exidel's outputs ----------------------------------------------------------------

def run(exidel, args, stdin=""):
    r = subprocess.run([exidel] + args, input=stdin, capture_output=True, text=True)
    if r.returncode != 0:
        raise Invalid(f"exidel {' '.join(args)} exited {r.returncode}: {r.stderr.strip()}")
    return r.stdout


def expect(condition, what):
    if not condition:
        raise Invalid(what)


def exidel_outputs(exidel, work):
    os.makedirs(work, exist_ok=True)
    rng = random.Random(20261205)
    # UTM-like coordinates: a 600 m square far from the origin, and a duplicate.
    pts = [(500000 + rng.uniform(0, 600), 4000000 + rng.uniform(0, 600)) for _ in range(200)]
    pts.append(pts[7])
    xy = "".join(f"{x!r} {y!r}\n" for x, y in pts)
    lon_lat = "".join(f"{rng.uniform(-10, 10)!r},{rng.uniform(40, 50)!r},{rng.uniform(0, 900)!r}\n"
                      for _ in range(50))
    collinear = "0 0\n1 1\n3 3\n1 1\n-2 -2\n"
    checked = []

    def check(name, text, features=None, triangles=None):
        path = os.path.join(work, name)
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)
        doc = check_text(text)
        if features is not None:
            expect(len(doc["features"]) == features,
                   f"{name}: {len(doc['features'])} features, expected {features}")
        checked.append(name)
        return doc

    # Triangulations: one Feature per triangle, then the hull.
    tri_json = json.loads(run(exidel, ["triangulate", "-q"], xy))
    n = len(tri_json["triangles"]) // 3
    doc = check("tri.geojson", run(exidel, ["triangulate", "-q", "-f", "geojson"], xy), n + 1)
    for t, f in enumerate(doc["features"][:n]):
        expect(f["properties"] == {"triangle": t, "vertices": tri_json["triangles"][3 * t:3 * t + 3]},
               f"tri.geojson: feature {t}'s properties {f['properties']}")
        ring = f["geometry"]["coordinates"][0]
        expect([tuple(p) for p in ring] ==
               [pts[v] for v in f["properties"]["vertices"] + f["properties"]["vertices"][:1]],
               f"tri.geojson: feature {t}'s ring is not its vertices' exact coordinates")
    hull = doc["features"][n]
    expect(hull["properties"] == {"hull": True, "vertices": tri_json["hull"]}, "tri.geojson: hull")
    expect(hull["geometry"]["type"] == "Polygon", "tri.geojson: the hull is a Polygon")
    doc = check("tri-z.geojson",
                run(exidel, ["triangulate", "-q", "-f", "geojson", "--columns", "1,2,3"], lon_lat))
    expect(all(len(p) == 3 for f in doc["features"] for p in f["geometry"]["coordinates"][0]),
           "tri-z.geojson: positions without z")
    # Collinear, one point, none.
    doc = check("collinear.geojson",
                run(exidel, ["triangulate", "-q", "-f", "geojson"], collinear), 1)
    expect(doc["features"][0]["geometry"]["type"] == "LineString", "collinear: a LineString")
    expect(doc["features"][0]["geometry"]["coordinates"] == [[-2, -2], [0, 0], [1, 1], [3, 3]],
           f"collinear: {doc['features'][0]['geometry']}")
    doc = check("point.geojson", run(exidel, ["triangulate", "-q", "-f", "geojson"], "3 4\n3 4\n"), 1)
    expect(doc["features"][0]["geometry"] == {"type": "Point", "coordinates": [3, 4]}, "one point")
    check("empty.geojson", run(exidel, ["triangulate", "-q", "-f", "geojson"], ""), 0)
    # Constrained (--constraints): a UTM-sized square with a square hole and an island in
    # it (rings), and a breakline with z crossing everything: the domain's triangles with
    # their region, then each segment's chain as a LineString; the domain's area is exactly
    # the polygons' (even-odd), the rings' crossings with the breakline included.
    def ring(x0, y0, side, clockwise, z):
        corners = [(x0, y0), (x0 + side, y0), (x0 + side, y0 + side), (x0, y0 + side)]
        if clockwise:
            corners.reverse()
        return [[x, y, z] for x, y in corners + corners[:1]]
    polygons = [[ring(500000, 4000000, 600, False, 10), ring(500100, 4000100, 400, True, 20)],
                [ring(500200, 4000200, 200, False, 30)]]
    constraints = {"type": "FeatureCollection", "features": [
        {"type": "Feature", "properties": {"name": "parcel"},
         "geometry": {"type": "MultiPolygon", "coordinates": polygons}},
        {"type": "Feature", "properties": None,
         "geometry": {"type": "LineString",
                      "coordinates": [[499990, 4000301.5, 0], [500610, 4000301.25, 5]]}}]}
    text = run(exidel, ["triangulate", "-q", "--constraints", "--input-format", "geojson",
                        "-f", "geojson", "--certify"], json.dumps(constraints))
    doc = check("constrained.geojson", text)
    triangles = [f for f in doc["features"] if f["geometry"]["type"] == "Polygon"]
    chains = [f for f in doc["features"] if f["geometry"]["type"] == "LineString"]
    expect(len(chains) == 4 + 4 + 4 + 1, f"constrained: {len(chains)} chains, expected 13")
    expect(all("region" in f["properties"] and len(p) == 3
               for f in triangles for p in f["geometry"]["coordinates"][0]),
           "constrained: a triangle without its region or z")
    expect(len(chains[-1]["geometry"]["coordinates"]) == 2 + 6,
           "constrained: the breakline does not pass its 6 crossings")

    def twice_area(r):
        return sum(Fraction(a[0]) * Fraction(b[1]) - Fraction(b[0]) * Fraction(a[1])
                   for a, b in zip(r, r[1:]))
    domain = sum(twice_area(f["geometry"]["coordinates"][0]) for f in triangles)
    expect(domain == 2 * (600 * 600 - 400 * 400 + 200 * 200),
           f"constrained: the domain's area is {domain / 2}, not the polygons'")
    checked.append("constrained area")
    # Voronoi diagrams, clipped by default and to a box: one Feature per site.
    doc = check("vor.geojson", run(exidel, ["voronoi", "-q", "-f", "geojson"], xy), len(pts))
    for i, f in enumerate(doc["features"]):
        expect(f["properties"] == {"site": i}, f"vor.geojson: feature {i}'s properties")
        expect(f["geometry"] is not None, f"vor.geojson: site {i} (inside the box) has no cell")
    expect(doc["features"][len(pts) - 1]["geometry"] == doc["features"][7]["geometry"],
           "vor.geojson: the duplicate's cell is not its twin's")
    doc = check("vor-clip.geojson",
                run(exidel, ["voronoi", "-q", "-f", "geojson", "--clip", "500100", "4000100",
                             "500300", "4000250"], xy), len(pts))
    expect(any(f["geometry"] is None for f in doc["features"]), "vor-clip: every cell in the box")
    expect(doc["bbox"] == [500100, 4000100, 500300, 4000250], f"vor-clip: bbox {doc['bbox']}")
    check("vor-collinear.geojson", run(exidel, ["voronoi", "-q", "-f", "geojson"], collinear), 5)
    check("vor-point.geojson", run(exidel, ["voronoi", "-q", "-f", "geojson"], "1 2\n"), 1)
    check("vor-empty.geojson", run(exidel, ["voronoi", "-q", "-f", "geojson"], ""), 0)
    return checked


def main(argv):
    if len(argv) == 4 and argv[1] == "--exidel":
        try:
            checked = exidel_outputs(argv[2], argv[3])
        except (Invalid, ValueError, KeyError, TypeError, IndexError) as e:
            print(f"check_geojson: {e}", file=sys.stderr)
            return 1
        print(f"ok: {len(checked)} GeoJSON outputs of exidel ({', '.join(checked)})")
        return 0
    if len(argv) < 2 or argv[1].startswith("-"):
        print(__doc__, file=sys.stderr)
        return 2
    status = 0
    for path in argv[1:]:
        try:
            doc = check_file(path)
            count = len(doc.get("features", [])) if isinstance(doc, dict) else 0
            print(f"ok: {path} ({doc['type']}, {count} features)")
        except (Invalid, ValueError) as e:
            print(f"{path}: {e}", file=sys.stderr)
            status = 1
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv))
