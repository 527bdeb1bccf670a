# Checks of `cgal-subdiv evaluate` and `cgal-subdiv tessellate`: values derived
# by hand (below, case by case) and values of another path through the tool,
# `cgal-subdiv surface --limit` (project_to_limit, the limit masks of the
# eigen-analysis). Used by test/cli_tests.cmake as
#   python3 limit_checks.py EXE DATA_DIR WORKDIR CASE
import json
import math
import os
import subprocess
import sys

EXE, DATA, WORK = sys.argv[1], sys.argv[2], sys.argv[3]
CUBE = os.path.join(DATA, "cube.off")
TETRA = os.path.join(DATA, "tetra.off")
GRID = os.path.join(DATA, "grid_4x4.off")


def run(*args):
    p = subprocess.run([EXE, *args], cwd=WORK, capture_output=True, text=True)
    assert p.returncode == 0, (args, p.returncode, p.stdout, p.stderr)
    return p.stdout


def evaluate(mesh, scheme, locations, *options):
    """the rows of `evaluate` (12 numbers each) or, with --json, the object"""
    path = os.path.join(WORK, "locations.txt")
    with open(path, "w") as f:
        f.write("".join(" ".join(str(x) for x in loc) + "\n" for loc in locations))
    out = run("evaluate", mesh, "--scheme", scheme, "--at", path, *options)
    if "--json" in options:
        return json.loads(out)
    return [[float(x) for x in line.split()] for line in out.splitlines()]


def read_off(path):
    """the vertices and faces of an OFF file (comments and NOFF normals skipped)"""
    with open(path) as f:
        lines = [l.split("#")[0].split() for l in f]
    lines = [l for l in lines if l]
    v, f = int(lines[1][0]), int(lines[1][1])
    points = [tuple(float(x) for x in l[:3]) for l in lines[2:2 + v]]
    faces = [[int(i) for i in l[1:1 + int(l[0])]] for l in lines[2 + v:2 + v + f]]
    return points, faces


def limit_points(mesh, scheme, levels):
    """the vertices of `surface --levels N --limit`"""
    out = os.path.join(WORK, "limit.off")
    run("surface", mesh, "-o", out, "--scheme", scheme, "--levels", str(levels), "--limit")
    return read_off(out)[0]


def near(p, q, tol=1e-14):
    return len(p) == len(q) and all(abs(a - b) <= tol for a, b in zip(p, q))


def expect(p, q, tol=1e-14, what=""):
    assert near(p, q, tol), (what, p, q)


def nearest(points, p):
    return min(points, key=lambda q: sum((a - b) ** 2 for a, b in zip(p, q)))


def unit(*v):
    n = math.sqrt(sum(x * x for x in v))
    return [x / n for x in v]


def position(row):
    return row[0:3]


def normal(row):
    return row[9:12]


def cc_cube_corners():
    # Catmull-Clark's limit mask at a vertex of valence 3: 9/24 on it, 4/24 on
    # each edge neighbour, 1/24 on each diagonal one; the corner (0,0,0) of the
    # unit cube goes to (1/4, 1/4, 1/4), with the normal -(1,1,1)/sqrt 3 (the
    # symmetry), and no derivative (the parameterisation has none there)
    rows = evaluate(CUBE, "catmull-clark", [(0, 0, 0)])
    expect(position(rows[0]), [0.25, 0.25, 0.25])
    expect(normal(rows[0]), unit(-1, -1, -1))
    expect(rows[0][3:9], [0] * 6)
    # corner k of face f at its (u, v) is the limit of the face's k-th vertex in
    # the file: the faces are numbered and their corners ordered as in the file
    points, faces = read_off(CUBE)
    limits = limit_points(CUBE, "catmull-clark", 0)
    corner_uv = [(0, 0), (1, 0), (1, 1), (0, 1)]
    locations = [(f, u, v) for f in range(len(faces)) for (u, v) in corner_uv]
    rows = evaluate(CUBE, "catmull-clark", locations)
    for (f, u, v), row in zip(locations, rows):
        vertex = faces[f][corner_uv.index((u, v))]
        expect(position(row), limits[vertex], what=(f, u, v))
        expect(position(row), [0.25 + 0.5 * x for x in points[vertex]], what=(f, u, v))


def cc_cube_centres():
    # the centre of a face is the face point of the first level, a vertex of
    # valence 4 whose neighbours are 4 edge points ((1/2, 1/8, 1/8) for the
    # bottom face) and 4 vertex points ((2/9, 2/9, 2/9)): its limit
    # (16 v + 4 sum(edge) + sum(diagonal)) / 36 has z = (4 * 4/8 + 4 * 2/9) / 36
    # = 13/162 on the bottom face; the normal is the face's, by symmetry
    depth = 13 / 162
    rows = evaluate(CUBE, "catmull-clark", [(f, 0.5, 0.5) for f in range(6)])
    expect(position(rows[0]), [0.5, 0.5, depth])
    expect(normal(rows[0]), [0, 0, -1])
    expect(position(rows[1]), [0.5, 0.5, 1 - depth])
    expect(normal(rows[1]), [0, 0, 1])
    # every face's centre is the limit of its face point (surface --limit),
    # 13/162 inside the face's centroid in the file
    points, faces = read_off(CUBE)
    limits = limit_points(CUBE, "catmull-clark", 1)
    for f, row in enumerate(rows):
        expect(position(row), nearest(limits, position(row)), what=f)
        centroid = [sum(points[i][k] for i in faces[f]) / 4 for k in range(3)]
        expect(position(row), [0.5 + (c - 0.5) * (1 - 2 * depth) for c in centroid], what=f)


def cc_grid_plane():
    # a flat grid of quads: the bicubic B-spline of a uniform grid is linear
    # in (u, v), so face 5, from (1, 1) to (2, 2) with all its corners of
    # valence 4 inside (a regular patch), maps (u, v) to (1 + u, 1 + v, 0):
    # du = (1, 0, 0), dv = (0, 1, 0), no second derivative, normal (0, 0, 1)
    d = evaluate(GRID, "catmull-clark", [(5, 0.25, 0.5), (0, 0.5, 0.5), (15, 1, 1), (3, 0.75, 0.125)], "--json")
    first = d["locations"][0]
    expect(first["position"], [1.25, 1.5, 0])
    expect(first["du"], [1, 0, 0])
    expect(first["dv"], [0, 1, 0])
    for key in ("duu", "duv", "dvv"):
        expect(first[key], [0, 0, 0], what=key)
    # everywhere, at the border too: on the plane, the normal exactly (0, 0, 1)
    for loc in d["locations"]:
        assert loc["position"][2] == 0, loc
        assert loc["normal"] == [0, 0, 1], loc


def loop_tetra():
    # Loop's limit mask at valence 3 (beta = 3/16): 2/5 on the vertex, 1/5 on
    # each neighbour: (1,1,1) goes to (1/5, 1/5, 1/5), normal (1,1,1)/sqrt 3
    rows = evaluate(TETRA, "loop", [(0, 0, 0), (0, 1, 0), (0, 0, 1)])
    expect(position(rows[0]), [0.2, 0.2, 0.2])
    expect(normal(rows[0]), unit(1, 1, 1))
    # corners 1 and 2 of face 0 (3 0 1 2) are the file's vertices 1 and 2
    limits = limit_points(TETRA, "loop", 0)
    for row, vertex in zip(rows, [0, 1, 2]):
        expect(position(row), limits[vertex], what=vertex)
    # (1/2, 0), the middle of the edge from (1,1,1) to (1,-1,-1): the edge
    # point (1/2, 0, 0) of the first level, of valence 6, whose neighbours are
    # two vertex points (1/4)(1, +-1, +-1) and four edge points with x = 0;
    # its limit 1/2 v + 1/12 sum(neighbours) is (1/4 + 1/24, 0, 0) = (7/24, 0, 0)
    # the face centre (1/3, 1/3) is on the axis (1, 1, -1) of face 0, by symmetry
    rows = evaluate(TETRA, "loop", [(0, 0.5, 0), (0, "1/3", "1/3")])
    expect(position(rows[0]), [7 / 24, 0, 0])
    expect(normal(rows[0]), [1, 0, 0])
    expect(position(rows[0]), nearest(limit_points(TETRA, "loop", 1), position(rows[0])))
    x, y, z = position(rows[1])
    assert x > 0 and near([x, y, z], [x, x, -x]), rows[1]
    expect(normal(rows[1]), unit(1, 1, -1))


def cc_sub_quads():
    # Catmull-Clark on the tetrahedron: every face a triangle, so 3 sub-quads;
    # sub-quad c at (0, 0) is the limit of corner c, the file's vertex; at
    # (1, 1) the face's centre, the limit of its face point (first level)
    points, faces = read_off(TETRA)
    limits = limit_points(TETRA, "catmull-clark", 0)
    locations = [(f, c, 0, 0) for f in range(4) for c in range(3)]
    rows = evaluate(TETRA, "catmull-clark", locations)
    for (f, c, _, _), row in zip(locations, rows):
        expect(position(row), limits[faces[f][c]], what=(f, c))
    rows = evaluate(TETRA, "catmull-clark", [(f, c, 1, 1) for f in range(4) for c in range(3)])
    level_1 = limit_points(TETRA, "catmull-clark", 1)
    for f in range(4):
        centre = position(rows[3 * f])
        for c in range(3):  # the three sub-quads meet there
            expect(position(rows[3 * f + c]), centre, what=(f, c))
        expect(centre, nearest(level_1, centre), what=f)
        centroid = [sum(points[i][k] for i in faces[f]) / 3 for k in range(3)]
        assert sum(a * b for a, b in zip(centre, centroid)) > 0, (f, centre)  # on its own side


def json_layout():
    # one object: the scheme and a location per line of LOCATIONS, in order,
    # with the line number, the numbers as read and the same values as the lines
    locations = [(0, 0.5, 0.25), (3, "1/4", 1)]
    lines = evaluate(CUBE, "catmull-clark", locations)
    d = evaluate(CUBE, "catmull-clark", locations, "--json")
    assert list(d.keys()) == ["scheme", "locations"], d.keys()
    assert d["scheme"] == "catmull-clark"
    assert len(d["locations"]) == 2
    keys = ["line", "face", "corner", "u", "v", "position", "du", "dv", "duu", "duv", "dvv", "normal"]
    for i, (loc, row) in enumerate(zip(d["locations"], lines)):
        assert list(loc.keys()) == keys, loc.keys()
        assert loc["line"] == i + 1 and loc["face"] == locations[i][0] and loc["corner"] is None, loc
        for key in keys[5:]:
            assert len(loc[key]) == 3 and all(isinstance(x, (int, float)) for x in loc[key]), (key, loc)
        assert loc["position"] + loc["du"] + loc["dv"] + loc["normal"] == row, (loc, row)
    assert d["locations"][1]["u"] == 0.25 and d["locations"][1]["v"] == 1
    sub = evaluate(TETRA, "catmull-clark", [(2, 1, 0.5, 0.5)], "--json")["locations"][0]
    assert sub["face"] == 2 and sub["corner"] == 1, sub


def tessellate_matches_evaluate():
    # the output points are the evaluator's: bit for bit inside a face (rate
    # 2: the centre (1/2, 1/2); rate 3: (1/3, 2/3)); a point on a mesh edge or
    # vertex is evaluated once, from the first face that reaches it, and the
    # other face's evaluation there may differ in the last bits
    for rate, inner, shared in ((2, [(0.5, 0.5)], [(0.5, 0), (0, 0)]), (3, [("1/3", "2/3")], [("2/3", 0)])):
        out = os.path.join(WORK, "tess.off")
        run("tessellate", CUBE, "-o", out, "--scheme", "catmull-clark", "--rate", str(rate))
        points = read_off(out)[0]
        for f in range(6):
            for row in evaluate(CUBE, "catmull-clark", [(f, u, v) for u, v in inner]):
                assert tuple(position(row)) in points, (rate, f, row)
            for row in evaluate(CUBE, "catmull-clark", [(f, u, v) for u, v in shared]):
                expect(nearest(points, position(row)), position(row), what=(rate, f))
    # Loop on the tetrahedron at rate 3: the face points (1/3, 1/3), and the edge points
    out = os.path.join(WORK, "tess.off")
    run("tessellate", TETRA, "-o", out, "--scheme", "loop", "--rate", "3")
    points = read_off(out)[0]
    for f in range(4):
        for row in evaluate(TETRA, "loop", [(f, "1/3", "1/3")]):
            assert tuple(position(row)) in points, row
        for row in evaluate(TETRA, "loop", [(f, "1/3", 0), (f, "2/3", "1/3")]):
            expect(nearest(points, position(row)), position(row), what=f)


def tessellate_normals():
    # --normals to OBJ: one vn per v, the evaluator's normal at its point
    out = os.path.join(WORK, "tess.obj")
    run("tessellate", CUBE, "-o", out, "--scheme", "catmull-clark", "--rate", "2", "--normals")
    with open(out) as f:
        words = [l.split() for l in f]
    v = [tuple(float(x) for x in w[1:4]) for w in words if w and w[0] == "v"]
    vn = [[float(x) for x in w[1:4]] for w in words if w and w[0] == "vn"]
    assert len(v) == 26 and len(vn) == 26, (len(v), len(vn))
    for row in evaluate(CUBE, "catmull-clark", [(f, u, v) for f in range(6) for u, v in ((0, 0), (0.5, 0), (0.5, 0.5))]):
        point = nearest(v, position(row))
        expect(point, position(row), what=row)
        expect(vn[v.index(point)], normal(row), what=row)
    # every face f v//vn with the vertex's own normal
    for w in words:
        if w and w[0] == "f":
            assert all(c.split("//")[0] == c.split("//")[1] for c in w[1:]), w


CASES = {f.__name__: f for f in [cc_cube_corners, cc_cube_centres, cc_grid_plane, loop_tetra, cc_sub_quads,
                                 json_layout, tessellate_matches_evaluate, tessellate_normals]}

if __name__ == "__main__":
    os.makedirs(WORK, exist_ok=True)
    CASES[sys.argv[4]]()
