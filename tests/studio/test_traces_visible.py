"""The BSP tree's step table against plan geometry worked here: which walls the root
plane y = 12 cuts, the pieces' lengths, every piece on the side of each node's plane
that the table says, and the drawing order checked by rays cast from the eye (along
any ray, a piece painted later is nearer); and its explorer view."""

import math

import numpy as np
import pytest

import scanline as sl
from scanline.errors import ArgumentValueError
from scanline.studio import explorer
from scanline.trace import bsp


def _hit(eye, direction, seg):
    """Distance along the ray eye + t direction to the plan segment, or None."""
    (x0, y0), (x1, y1) = seg
    a = np.array([[direction[0], x0 - x1], [direction[1], y0 - y1]])
    if abs(np.linalg.det(a)) < 1e-12:
        return None
    t, s = np.linalg.solve(a, [x0 - eye[0], y0 - eye[1]])
    return t if t > 1e-9 and 1e-6 < s < 1 - 1e-6 else None


def test_root_plane_is_wall_0_and_splits_walls_1_and_4():
    t = sl.trace.bsp_tree((6, 22))
    root = t.rows[0]
    a, b, c, d = t.planes[0]
    assert (abs(a), abs(b), abs(c)) == pytest.approx((0, 1, 0))
    assert -d / b == pytest.approx(12)          # the plane y = 12
    assert root["on"] == "0"
    # wall 1 spans y 4..20 at x = 10, wall 4 runs from y 16 to 7: both cross y = 12
    assert root["splits"] == "1 4"
    assert {p[0] for p in root["in front"].split() + root["behind"].split()} == set("1234")


@pytest.mark.parametrize("eye", [(6, 22), (30, 2), (16, 10), (1, 1), (12, 15)])
def test_pieces_cover_the_walls_and_sit_on_their_sides(eye):
    t = sl.trace.bsp_tree(eye)
    for w, (x0, y0, x1, y1) in enumerate(bsp.WALLS):
        mine = [seg for name, seg in t.pieces.items() if name.rstrip("abcdefgh") == str(w)]
        assert sum(math.dist(*seg) for seg in mine) == pytest.approx(math.dist((x0, y0),
                                                                               (x1, y1)))
    for r in (r for r in t.rows if r["phase"] == "build"):
        a, b, c, d = t.planes[r["node"]]
        for names, sign in ((r["in front"], 1), (r["behind"], -1)):
            for name in names.split() if names != "-" else []:
                mid = np.mean(t.pieces[name], axis=0)
                assert sign * (a * mid[0] + b * mid[1] + c * 0.5 + d) > 0


@pytest.mark.parametrize("eye", [(6, 22), (30, 2), (16, 10), (1, 1), (12, 15), (20, 13)])
def test_back_to_front_along_every_ray(eye):
    t = sl.trace.bsp_tree(eye)
    drawn = [r["piece"] for r in t.rows if r["phase"] == "draw"]
    assert sorted(drawn) == sorted(t.pieces)
    rays = 0
    for angle in np.linspace(0, 2 * np.pi, 721)[:-1]:
        d = (np.cos(angle), np.sin(angle))
        hits = [(k, _hit(eye, d, t.pieces[p])) for k, p in enumerate(drawn)]
        hits = [(k, h) for k, h in hits if h is not None]
        rays += len(hits) > 1
        by_order = [h for _, h in sorted(hits)]
        assert by_order == sorted(by_order, reverse=True), (angle, hits)
    assert rays > 50


def test_bsp_eye_is_two_numbers():
    with pytest.raises(ArgumentValueError, match="eye"):
        sl.trace.bsp_tree((1, 2, 3))


def test_bsp_explorer_view():
    view = explorer.explore("bsp-tree", ["--eye", "30", "2"])
    assert view["count"] == len(view["steps"]) == 18
    assert view["handles"][0]["x"] == 30 and view["handles"][0]["y"] == 2
    assert view["steps"][0]["plane"] == [[0, 12], [31, 12]]
    last = view["steps"][-1]
    assert len(last["areas"]) == 9 and last["areas"][-1][1] == "current"


# -- Warnock's area subdivision ----------------------------------------------------------
def _side(poly, x, y):
    """+1 inside the convex polygon (strictly), -1 outside, 0 on its boundary."""
    p = np.asarray(poly, float)[:, :2]
    cross = [(b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0])
             for a, b in zip(p, np.roll(p, -1, axis=0))]
    if all(c > 1e-9 for c in cross) or all(c < -1e-9 for c in cross):
        return 1
    return 0 if all(c >= -1e-9 for c in cross) or all(c <= 1e-9 for c in cross) else -1


def _depth(poly, x, y):
    """The depth of the polygon's plane (through its first three vertices) at (x, y)."""
    a, b, c = np.asarray(poly, float)[:3]
    n = np.cross(b - a, c - a)
    return a[2] - (n[0] * (x - a[0]) + n[1] * (y - a[1])) / n[2]


def _check_nearest(face, polys):
    """Every pixel whose center is on no polygon's edge holds the nearest polygon
    covering it (-1: none)."""
    checked = 0
    for y, x in np.ndindex(face.shape):
        sides = [_side(p, x, y) for p in polys]
        if 0 in sides:
            continue                    # on an edge: the fill rule decides
        near = [(_depth(p, x, y), i) for i, p in enumerate(polys) if sides[i] > 0]
        assert face[y, x] == (min(near)[1] if near else -1), (x, y)
        checked += 1
    assert checked > 100


@pytest.mark.parametrize("scene", ["overlap", "surrounding"])
def test_warnock_areas_tile_the_screen_and_match_the_kernels_record(scene):
    from scanline.trace import subdivision as warnock
    from scanline.visible import ScreenPolygons, area_subdivision
    from scanline.visible.warnock import CASES

    t = sl.trace.warnock(scene)
    decided = [r for r in t.rows if r["decision"] != "subdivide"]
    count = np.zeros((warnock.HEIGHT, warnock.WIDTH), int)
    for r in decided:
        count[r["y0"]:r["y1"] + 1, r["x0"]:r["x1"] + 1] += 1
    assert (count == 1).all()
    sp = ScreenPolygons.from_device([np.array(p, float) for p in warnock.SCENES[scene]],
                                    warnock.WIDTH, warnock.HEIGHT)
    result = area_subdivision(sp, record=1000)
    assert result.areas == len(decided)
    assert result.regions.tolist() == [[r["x0"], r["y0"], r["x1"], r["y1"],
                                        CASES.index(r["decision"])] for r in decided]
    for r in t.rows:        # a subdivided area's quadrants are the rows one level down
        if r["decision"] == "subdivide":
            assert r["x0"] < r["x1"] or r["y0"] < r["y1"]


@pytest.mark.parametrize("scene", ["overlap", "surrounding"])
def test_warnock_classes_and_pixels_against_plane_geometry(scene):
    from scanline.trace import subdivision as warnock

    polys = warnock.SCENES[scene]
    t = sl.trace.warnock(scene)
    for r in t.rows:
        x0, y0, x1, y1 = r["x0"], r["y0"], r["x1"], r["y1"]
        for i, poly in enumerate(polys):
            c = r[f"P{i}"]
            if c == "surrounding":
                assert all(_side(poly, x, y) >= 0 for x in (x0, x1) for y in (y0, y1))
            elif c == "inside":
                xs, ys = [p[0] for p in poly], [p[1] for p in poly]
                assert x0 <= min(xs) and max(xs) <= x1 and y0 <= min(ys) and max(ys) <= y1
            elif c == "outside":
                assert all(_side(poly, x, y) <= 0 for x in range(x0, x1 + 1)
                           for y in range(y0, y1 + 1))
    _check_nearest(t.face, polys)
    painted = [p for w in t.written for p in w]
    assert len(painted) == len(set(painted)) == int((t.face >= 0).sum())


def test_warnock_explorer_view():
    view = explorer.explore("warnock", ["--scene", "overlap"])
    assert view["count"] == len(view["steps"])
    first = view["steps"][0]
    assert first["areas"][0][0] == [[-0.5, -0.5], [15.5, -0.5], [15.5, 11.5], [-0.5, 11.5]]
    assert "subdivide" in first["rule"]
    for step in view["steps"]:          # one polygon per decision, in its color
        assert len(step["colors"]) == len(step["pixels"]) and len(set(step["colors"])) <= 1


# -- the scan-line method ----------------------------------------------------------------
@pytest.mark.parametrize("scene", ["overlap", "surrounding"])
def test_scan_line_method_rows_against_the_polygons(scene):
    from scanline.trace import subdivision
    from scanline.visible import ScreenPolygons, scan_line

    polys = subdivision.SCENES[scene]
    t = sl.trace.scan_line_method(scene)
    sp = ScreenPolygons.from_device([np.array(p, float) for p in polys], subdivision.WIDTH,
                                    subdivision.HEIGHT)
    assert (t.face == scan_line(sp).face).all()
    assert (t.face == sl.trace.warnock(scene).face).all()
    _check_nearest(t.face, polys)
    shown = set()
    for y in range(subdivision.HEIGHT):
        line = [r for r in t.rows if r["y"] == y]
        xs = [r["x"] for r in line]
        assert xs == sorted(xs)
        for r in line:                  # the crossing lies on an edge of its polygon
            p = np.array(polys[int(r["edge"].split("P")[1].rstrip(")"))], float)
            hits = [a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
                    for a, b in zip(p, np.roll(p, -1, axis=0))
                    if min(a[1], b[1]) < y <= max(a[1], b[1])]
            assert r["x"] == pytest.approx(min(hits, key=lambda h: abs(h - r["x"])))
            if r["span"]:
                a, b = (int(c) for c in r["span"].split(".."))
                shown |= {(x, y) for x in range(a, b + 1)}
                assert set(r["visible"].split()) == {f"P{f}" for f in t.face[y, a:b + 1]}
            if r["depths"]:
                for item in r["depths"].split(", "):
                    name, z = item.split()
                    q = int(name[1:])
                    assert float(z) == pytest.approx(_depth(polys[q], a, y), abs=1e-4)
    assert shown == {(x, y) for y, x in zip(*np.nonzero(t.face >= 0))}


def test_scan_line_method_explorer_view():
    view = explorer.explore("scan-line-visible", ["--scene", "overlap"])
    assert view["count"] == len(view["steps"])
    assert view["steps"][0]["pixels"] == [[x, 2] for x in range(1, 14)]
    assert "depths P0 0.8, P1 0.3: P1 shown" in view["steps"][5]["rule"]
    assert view["steps"][5]["colors"] == [explorer.POLYGON_COLORS[1]] * 7     # P1's span


# -- ray casting -------------------------------------------------------------------------
@pytest.mark.parametrize("row", [1, 4, 7, 9])
def test_ray_casting_hits_against_barycentric_depths(row):
    from types import SimpleNamespace

    from scanline.trace import zbuffer
    from scanline.visible.raycast import raycast

    t = sl.trace.ray_casting(row)
    tris = zbuffer.SCENE
    scene = SimpleNamespace(triangles=tris, width=zbuffer.WIDTH, height=zbuffer.HEIGHT,
                            inv_w=np.ones((3, 3)), bary=np.zeros((3, 3, 0)))
    layer = raycast(scene)
    compared = 0
    for r in t.rows:
        x = r["x"]
        assert r["nearest"] == (f"T{layer.ids[row, x]}" if layer.ids[row, x] >= 0 else "none")
        hits = {} if r["hits"] == "none" else {
            int(h.split()[0][1:]): float(h.split()[1]) for h in r["hits"].split(", ")}
        for k, tri in enumerate(tris):
            side = _side(tri, x, row)
            if side == 0:
                continue                    # on an edge: the fill rule decides
            assert (k in hits) == (side > 0), (x, k)
            if k in hits:
                assert hits[k] == pytest.approx(_depth(tri, x, row), abs=1e-5)
                compared += 1
        if hits:
            k = min(hits, key=hits.get)
            assert r["nearest"] == f"T{k}" and r["depth"] == pytest.approx(hits[k], abs=1e-6)
    zb = sl.trace.z_buffer(row).notes[-1].split(": ")[1].split()
    assert zb == [r["nearest"][1:] if r["nearest"] != "none" else "." for r in t.rows]
    assert compared > 0


def test_ray_casting_refuses_a_row_off_the_device():
    with pytest.raises(ArgumentValueError, match="0..9"):
        sl.trace.ray_casting(10)


def test_ray_casting_explorer_view():
    view = explorer.explore("ray-casting", ["--row", "4"])
    assert view["count"] == len(view["steps"]) == 16
    assert view["steps"][6]["areas"][0][0] == [[4.0, 0.5], [15.0, 5.0], [8.0, 9.5]]
    assert view["steps"][0]["pixels"] == [] and "background" in view["steps"][0]["rule"]
