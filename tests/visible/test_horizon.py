"""The floating horizon against brute-force visibility on grids; hidden lines
against ray casting."""

import math

import numpy as np
import pytest

import scanline as sl
from scanline.draw3d.horizon import horizon_runs


def brute_force_states(points, curves="rows", width=80):
    """Visibility of every curve at every column, from scratch: a column of curve k
    is visible above when its y exceeds the y of every earlier curve and side edge
    there (np.interp of each, no horizon arrays), below when it is under all of
    them."""
    p = points if curves == "rows" else points.transpose(1, 0, 2)
    order = np.argsort(p[:, :, 2].mean(axis=1), kind="stable")
    drawn = []                 # earlier polylines, as (xs, ys) increasing in x
    out = np.full((len(order), width), 2, np.int8)
    prev = None
    for g, i in enumerate(order):
        xs, ys = p[i, :, 0], p[i, :, 1]
        if xs[0] > xs[-1]:
            xs, ys = xs[::-1], ys[::-1]
        cols = np.arange(math.ceil(xs[0]), math.floor(xs[-1]) + 1)
        for c in cols:
            if not 0 <= c < width:
                continue
            y = np.interp(c, xs, ys)
            others = [np.interp(c, a, b) for a, b in drawn if a[0] <= c <= a[-1]]
            if not others or y > max(others):
                out[g, c] = 1
            elif y < min(others):
                out[g, c] = -1
            else:
                out[g, c] = 0
        edges = []
        if prev is not None:
            for a, b in ((prev[0], (xs[0], ys[0])), (prev[1], (xs[-1], ys[-1]))):
                (xa, ya), (xb, yb) = sorted([a, b])
                if math.floor(xb) - math.ceil(xa) >= 1:
                    edges.append((np.array([xa, xb]), np.array([ya, yb])))
        drawn += edges + [(xs, ys)]
        prev = ((xs[0], ys[0]), (xs[-1], ys[-1]))
    return out


SURFACES = {
    "ripple": lambda x, y: np.sin(4 * np.hypot(x, y)) / (1 + 2 * np.hypot(x, y)),
    "saddle": lambda x, y: 0.6 * (x * x - y * y),
    "peaks": lambda x, y: (np.exp(-5 * ((x - 0.3) ** 2 + y ** 2))
                           - 0.7 * np.exp(-6 * ((x + 0.4) ** 2 + (y - 0.3) ** 2))),
}


@pytest.mark.parametrize("name", sorted(SURFACES))
@pytest.mark.parametrize("angles", [(0.5, 0.4), (-0.3, 0.7), (0.0, 0.2)])
def test_states_equal_brute_force(name, angles):
    h = sl.draw3d.horizon(SURFACES[name], x=np.linspace(-1, 1, 13),
                          y=np.linspace(-1, 1, 9), camera_or_angles=angles, width=80,
                          height=60)
    ref = brute_force_states(h.points, width=80)
    # columns where the curve meets an earlier one exactly are ties
    assert (h.states == ref).mean() > 0.99
    assert ((h.states == 2) == (ref == 2)).all()


def test_horizons_are_the_envelope():
    h = sl.draw3d.horizon(SURFACES["ripple"], x=np.linspace(-1, 1, 15),
                          y=np.linspace(-1, 1, 11), width=90, height=70)
    pts = h.points
    for c in range(90):
        ys = []
        for row in pts:
            xs, yv = row[:, 0], row[:, 1]
            if xs[0] > xs[-1]:
                xs, yv = xs[::-1], yv[::-1]
            if xs[0] <= c <= xs[-1]:
                ys.append(np.interp(c, xs, yv))
        if ys:
            assert h.upper[c] >= max(ys) - 1e-9 and h.lower[c] <= min(ys) + 1e-9


def test_first_curve_fully_visible_and_flat_plane():
    # a tilted plane seen from above: every curve shows above the previous ones
    h = sl.draw3d.horizon(lambda x, y: 0 * x, x=np.linspace(-1, 1, 5),
                          y=np.linspace(-1, 1, 5), camera_or_angles=(0.0, 0.5), width=60,
                          height=40)
    assert ((h.states == 1) | (h.states == 2)).all()
    assert (h.states[0] != 2).sum() > 30


def test_drawn_pixels_and_bad_input():
    fb = sl.FrameBuffer(80, 60, mode="1")
    sl.draw3d.floating_horizon(fb, SURFACES["peaks"], color=1)
    assert fb.to_array().any()
    with pytest.raises(sl.ArgumentValueError, match="not finite"):
        sl.draw3d.floating_horizon(fb, lambda x, y: np.log(x))
    grid = np.zeros((4, 5))
    grid[2, 3] = np.nan
    with pytest.raises(sl.ArgumentValueError, match="row 2, column 3"):
        sl.draw3d.floating_horizon(fb, grid)
    with pytest.raises(sl.ArgumentValueError, match="elevation"):
        sl.draw3d.floating_horizon(fb, np.zeros((3, 3)), camera_or_angles=(0, 2))
    with pytest.raises(sl.ArgumentValueError, match="folds back|increasing"):
        sl.draw3d.floating_horizon(fb, np.zeros((3, 3)), camera_or_angles=(math.pi / 2, 0.3))


def test_hidden_lines_against_ray_casting():
    cam = sl.Camera(eye=(3, 2, 4), target=(0, 0, 0),
                    projection=sl.projection.perspective(fov=0.8, near=1))
    cube = sl.mesh.cube()
    fb = sl.FrameBuffer(64, 48)
    seen, unseen = sl.visible.visible_lines(fb, cube, cam, hidden="dash")
    # a cube seen from a corner: 9 edges visible, 3 hidden (those at the far corner)
    assert len(seen) == 9 and len(unseen) == 3
    sp = sl.visible.screen_polygons(cube, cam, 64, 48)
    # every sample point of a visible part is in front of (or on) every face there
    for s in seen:
        for t in np.linspace(0.05, 0.95, 7):
            x, y = s[:2] + t * (s[2:] - s[:2])
            for p in range(len(sp)):
                poly = sp.polygon(p)
                inside = _strictly_inside(poly, x, y)
                if inside:
                    z_line = _line_depth(cam, s, t)
                    assert z_line <= sp.depth_at(p, x, y) + 1e-6


def _strictly_inside(poly, x, y):
    n = len(poly)
    area = sum(poly[i, 0] * poly[(i + 1) % n, 1] - poly[(i + 1) % n, 0] * poly[i, 1]
               for i in range(n))
    return all(np.sign(area) * ((poly[(i + 1) % n, 0] - poly[i, 0]) * (y - poly[i, 1])
                                - (poly[(i + 1) % n, 1] - poly[i, 1]) * (x - poly[i, 0])) > 1e-6
               for i in range(n))


def _line_depth(cam, seg, t):
    # the depth of the edge's 3-D point under (x, y): from the projected cube edges
    verts = sl.mesh.cube().vertices
    pts = cam.project(verts, 64, 48)
    x, y = seg[:2] + t * (seg[2:] - seg[:2])
    for i, j in sl.mesh.cube().edges:
        a, b = pts[i], pts[j]
        d = b[:2] - a[:2]
        u = np.dot([x, y] - a[:2], d) / np.dot(d, d)
        if 0 <= u <= 1 and np.linalg.norm(a[:2] + u * d - [x, y]) < 1e-6:
            # depth is linear along a device-space segment
            return a[2] + u * (b[2] - a[2])
    raise AssertionError("point on no edge")
