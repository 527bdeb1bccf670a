# Checks the JSON printed by `cgal-subdiv analyse --json`: used by
# test/cli_tests.cmake as   python3 analyse_checks.py CASE FILE
# (the file must also pass `python3 -m json.tool`, which the test runs first).
import json
import math
import sys

SURFACE_FIELDS = ["scheme", "valence", "boundary", "vertex", "sides", "eigenvalues", "subdominant", "subdominant_multiplicity",
                  "c1_necessary", "characteristic_map", "c1", "limit_mask", "exact"]
CURVE_FIELDS = ["scheme", "parameters", "window", "eigenvalues", "subdominant", "c1_necessary", "limit_mask",
                "converges", "c_infinity", "smoothness", "holder", "c1", "predicted_rate", "exact"]


def near(x, y, tol=1e-12):
    return abs(x - y) <= tol


def check_surface_shape(d):
    assert list(d.keys()) == SURFACE_FIELDS, list(d.keys())
    assert sorted(d["limit_mask"].keys()) == ["center", "weights"], d["limit_mask"]
    moduli = [math.hypot(re, im) for re, im in d["eigenvalues"]]
    assert all(a >= b - 1e-12 for a, b in zip(moduli, moduli[1:])), moduli
    assert near(d["eigenvalues"][0][0], 1) and near(d["eigenvalues"][0][1], 0), d["eigenvalues"][0]
    assert d["subdominant"] == d["eigenvalues"][1], (d["subdominant"], d["eigenvalues"][1])
    assert d["characteristic_map"] in ("regular_injective", "not_regular", "not_injective", "not_applicable")
    assert near(d["limit_mask"]["center"] + sum(d["limit_mask"]["weights"]), 1, 1e-12)
    assert d["vertex"] in ("interior", "border", "crease", "dart", "corner")
    assert (d["vertex"] == "border") == d["boundary"]
    assert (len(d["sides"]) == 2) == (d["vertex"] == "crease"), d["sides"]


def loop(d, n):
    check_surface_shape(d)
    assert d["scheme"] == "loop" and d["valence"] == n and d["boundary"] is False
    expected = 3 / 8 + math.cos(2 * math.pi / n) / 4
    assert near(d["subdominant"][0], expected) and d["subdominant"][1] == 0, d["subdominant"]
    assert d["subdominant_multiplicity"] == 2
    assert d["c1_necessary"] is True and d["c1"] is True
    assert d["characteristic_map"] == "regular_injective"
    assert d["exact"] is True  # Loop's beta is rational at 3, 4, 6
    # limit mask: centre 1 - n chi, neighbours chi = 1 / (3 / (8 beta) + n)
    beta = (5 / 8 - (3 / 8 + math.cos(2 * math.pi / n) / 4) ** 2) / n
    chi = 1 / (3 / (8 * beta) + n)
    assert near(d["limit_mask"]["center"], 1 - n * chi), d["limit_mask"]
    assert len(d["limit_mask"]["weights"]) == n
    assert all(near(w, chi) for w in d["limit_mask"]["weights"]), d["limit_mask"]


def loop3(d):
    loop(d, 3)
    assert d["subdominant"] == [0.25, 0]
    assert d["limit_mask"]["center"] == 0.4


def loop6(d):
    loop(d, 6)
    assert d["subdominant"] == [0.5, 0]
    assert d["eigenvalues"][1] == [0.5, 0] and d["eigenvalues"][2] == [0.5, 0]
    assert d["limit_mask"]["center"] == 0.5


def catmull_clark5(d):
    check_surface_shape(d)
    assert d["scheme"] == "catmull-clark" and d["valence"] == 5
    assert d["exact"] is True and d["c1"] is True and d["subdominant_multiplicity"] == 2
    # n^2 : 4 : 1 over n (n + 5) = 50; edge neighbours at odd labels, face neighbours at even labels
    assert d["limit_mask"]["center"] == 0.5
    assert d["limit_mask"]["weights"] == [0.08, 0.02] * 5, d["limit_mask"]["weights"]
    c = math.cos(2 * math.pi / 5)
    expected = (5 + c + math.cos(math.pi / 5) * math.sqrt(18 + 2 * c)) / 16
    assert near(d["subdominant"][0], expected)


def butterfly3(d):
    check_surface_shape(d)
    assert d["scheme"] == "butterfly" and d["valence"] == 3
    assert d["c1"] is False and d["c1_necessary"] is False
    assert d["subdominant"] == [0.25, 0] and d["subdominant_multiplicity"] == 7
    assert d["limit_mask"]["center"] == 1 and all(w == 0 for w in d["limit_mask"]["weights"])  # interpolating
    assert d["exact"] is True


def loop_border2(d):
    check_surface_shape(d)
    assert d["scheme"] == "loop" and d["valence"] == 2 and d["boundary"] is True
    assert d["c1"] is True and d["exact"] is True
    # the border is a cubic B-spline: 2/3 centre, 1/6 for each border neighbour (labels 1 and k + 1)
    w = d["limit_mask"]["weights"]
    assert near(d["limit_mask"]["center"], 2 / 3, 1e-16) and near(w[0], 1 / 6, 1e-16) and near(w[2], 1 / 6, 1e-16), w
    assert near(d["subdominant"][0], 0.5)


def catmull_clark_border5(d):
    check_surface_shape(d)
    assert d["boundary"] is True and d["valence"] == 5
    assert d["c1"] is False and d["characteristic_map"] == "not_regular"


def doo_sabin5(d):
    check_surface_shape(d)
    assert d["valence"] == 5 and d["c1"] is True and d["exact"] is False  # cos(2 pi / 5) is irrational
    assert near(d["subdominant"][0], 0.5) and d["subdominant_multiplicity"] == 2
    assert near(d["limit_mask"]["center"], 0.2, 1e-15)  # the centroid of the central face


def doo_sabin_border4(d):
    check_surface_shape(d)
    assert d["scheme"] == "doo-sabin" and d["valence"] == 4 and d["boundary"] is True
    assert d["c1"] is True and d["c1_necessary"] is True and d["exact"] is True
    assert d["characteristic_map"] == "regular_injective"
    # the interior corners of the border 4-gon give 3/4, the Chaikin border 1/2
    assert d["subdominant"] == [0.75, 0] and d["subdominant_multiplicity"] == 1
    assert d["eigenvalues"][2] == [0.5, 0], d["eigenvalues"]
    # the midpoint of the two border corners (labels 0 and 3) of the 4-gon, 14 vertices
    w = d["limit_mask"]["weights"]
    assert d["limit_mask"]["center"] == 0.5 and len(w) == 13 and w[2] == 0.5 and sum(w) == 0.5, w


def bspline3(d):
    assert list(d.keys()) == CURVE_FIELDS, list(d.keys())
    assert d["scheme"] == "bspline" and d["parameters"] == {"degree": 3} and d["window"] == [-1, 1]
    assert d["eigenvalues"] == [[1, 0], [0.5, 0], [0.25, 0]], d["eigenvalues"]
    assert d["subdominant"] == [0.5, 0]
    assert d["limit_mask"]["offsets"] == [-1, 0, 1]
    assert d["limit_mask"]["fractions"] == ["1/6", "2/3", "1/6"]
    assert d["limit_mask"]["weights"] == [1 / 6, 2 / 3, 1 / 6], d["limit_mask"]["weights"]
    assert d["smoothness"] == 2 and d["holder"] == 3 and d["c1"] is True and d["c_infinity"] is False
    assert d["predicted_rate"] == 0.25 and d["exact"] is True and d["converges"] is True


def four_point_tense(d):
    assert list(d.keys()) == CURVE_FIELDS
    assert d["parameters"] == {"w": 0.2}
    assert d["smoothness"] == 0 and d["c1"] is False and 0.8 < d["holder"] < 0.9
    assert d["limit_mask"]["fractions"] == ["0", "0", "1", "0", "0"]


def bezier(d):
    assert list(d.keys()) == CURVE_FIELDS
    assert d["c_infinity"] is True and d["smoothness"] is None and d["holder"] is None and d["c1"] is True
    assert d["eigenvalues"] == [[1, 0], [0.5, 0], [0.25, 0], [0.125, 0]]


def catmull_clark_crease_1_3(d):
    # a crease with 1 face on one side and 3 on the other: the crease curve is
    # the cubic B-spline (limit 1/6, 2/3, 1/6 on labels 1, 0, 3; eigenvalues
    # 1/2, 1/4); each side is refined as a border with as many faces, and the
    # border with 1 face is not C1 (1/4 ties with the next eigenvalue)
    check_surface_shape(d)
    assert d["scheme"] == "catmull-clark" and d["valence"] == 4 and d["vertex"] == "crease"
    assert d["exact"] is True
    w = d["limit_mask"]["weights"]
    assert near(d["limit_mask"]["center"], 2 / 3, 1e-16) and near(w[0], 1 / 6, 1e-16) and near(w[2], 1 / 6, 1e-16), w
    assert all(x == 0 for i, x in enumerate(w) if i not in (0, 2)), w
    assert [0.5, 0] in d["eigenvalues"] and [0.25, 0] in d["eigenvalues"], d["eigenvalues"]
    assert [s["faces"] for s in d["sides"]] == [1, 3], d["sides"]
    assert all(s["same_as_border"] for s in d["sides"]), d["sides"]
    assert [s["c1"] for s in d["sides"]] == [False, True], d["sides"]
    assert d["c1"] is False


def loop_dart5(d):
    # a dart of valence 5: the smooth valence-5 subdominant 3/8 + cos(2 pi/5)/4
    # stays (simple), a larger one comes with the crease; C1
    check_surface_shape(d)
    assert d["scheme"] == "loop" and d["valence"] == 5 and d["vertex"] == "dart" and d["sides"] == []
    smooth = 3 / 8 + math.cos(2 * math.pi / 5) / 4
    assert near(d["eigenvalues"][2][0], smooth), d["eigenvalues"]
    assert d["subdominant"][0] > smooth + 1e-3 and d["subdominant_multiplicity"] == 1
    assert d["c1_necessary"] is True and d["characteristic_map"] == "regular_injective" and d["c1"] is True


def loop_corner6(d):
    # a corner of valence 6 keeps its point; 5/8 then 1/2 twice: no C1
    check_surface_shape(d)
    assert d["vertex"] == "corner" and d["valence"] == 6
    assert d["limit_mask"]["center"] == 1 and all(w == 0 for w in d["limit_mask"]["weights"])
    assert d["subdominant"] == [0.625, 0] and d["eigenvalues"][2] == [0.5, 0] and d["eigenvalues"][3] == [0.5, 0]
    assert d["c1_necessary"] is False and d["c1"] is False


CASES = {name: f for name, f in globals().items() if callable(f) and name not in
         ("near", "check_surface_shape", "loop")}

if __name__ == "__main__":
    case, path = sys.argv[1], sys.argv[2]
    with open(path) as f:
        data = json.load(f)
    try:
        CASES[case](data)
    except AssertionError as e:
        print("check '%s' failed: %s\n%s" % (case, e, json.dumps(data)))
        sys.exit(1)
    print("check '%s' passed" % case)
