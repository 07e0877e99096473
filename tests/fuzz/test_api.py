"""Every public drawing, clipping, curve and 3-D entry point on generated hostile
arguments: arrays of every dtype, shape and memory layout, extreme values and
counts.  Each call runs in :func:`tests.fuzz.harness.bounded` (time and memory
limits; only ScanlineError may escape) on a frame buffer with guard memory (no byte
outside it may change).  Marked ``boundscheck``: .ci/run runs this module again with
NUMBA_BOUNDSCHECK=1, where any out-of-bounds access in a kernel is an IndexError."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import scanline as sl
from scanline.shading import paint
from scanline.visible.visibility import piece_numbers
from tests.fuzz.harness import arrays, bounded, guard_intact, guarded, index_arrays, values

pytestmark = pytest.mark.boundscheck

MODES = st.sampled_from(["1", "L", "RGB", "RGBA", "P"])
COLORS = st.sampled_from(["white", (255, 0, 0, 128), 1, "red"])
size = st.integers(1, 24)


def frame(mode, w, h):
    return guarded(w, h, mode)


@given(segs=arrays(4), mode=MODES, w=size, h=size, color=COLORS,
       kind=st.sampled_from(["lines", "aa", "wide", "dda", "dash"]))
def test_lines(segs, mode, w, h, color, kind):
    fb, big = frame(mode, w, h)
    with bounded():
        if kind == "lines":
            sl.draw.lines(fb, segs, color)
        elif kind == "aa":
            sl.draw.antialias.lines(fb, segs, color)
        elif kind == "wide":
            sl.draw.lines(fb, segs, color, width=3)
        elif kind == "dda":
            sl.draw.lines(fb, segs, color, method="dda")
        else:
            sl.draw.lines(fb, segs, color, dash=(2, 1))
    assert guard_intact(big)


@given(x0=values, y0=values, x1=values, y1=values, mode=MODES, w=size, h=size,
       width=st.sampled_from([None, 1, 2.5, 7, 1e9, -1, np.nan]))
def test_line(x0, y0, x1, y1, mode, w, h, width):
    fb, big = frame(mode, w, h)
    with bounded():
        sl.draw.line(fb, x0, y0, x1, y1, width=width)
    assert guard_intact(big)


@given(pts=arrays(2, max_rows=16), counts=index_arrays(), mode=MODES, w=size, h=size,
       kind=st.sampled_from(["polygon", "aa-polygon", "polygons", "polyline", "wide",
                             "aa-wide", "polylines", "closed"]),
       rule=st.sampled_from(["even-odd", "nonzero"]))
def test_areas_and_paths(pts, counts, mode, w, h, kind, rule):
    fb, big = frame(mode, w, h)
    with bounded():
        if kind == "polygon":
            sl.draw.polygon(fb, pts, rule=rule)
        elif kind == "aa-polygon":
            sl.draw.polygon(fb, pts, rule=rule, antialias=True)
        elif kind == "polygons":
            sl.draw.polygons(fb, pts, counts=counts, rule=rule)
        elif kind == "polyline":
            sl.draw.polyline(fb, pts)
        elif kind == "wide":
            sl.draw.polyline(fb, pts, width=4, join="miter")
        elif kind == "aa-wide":
            sl.draw.polyline(fb, pts, width=2.5, antialias=True)
        elif kind == "polylines":
            sl.draw.polylines(fb, pts, counts=counts, width=2)
        else:
            sl.draw.polyline(fb, pts, closed=True, dash=(3, 1))
    assert guard_intact(big)


@given(pts=arrays(2, max_rows=16), contours=index_arrays(), shapes=index_arrays(),
       mode=MODES, w=size, h=size)
def test_fills_flat(pts, contours, shapes, mode, w, h):
    fb, big = frame(mode, w, h)
    with bounded():
        sl.draw.antialias.fills_flat(fb, pts, contours, shapes)
    assert guard_intact(big)


def _finite(*vals):
    """Whether every value is a finite real number (as scanline reads it)."""
    for c in vals:
        try:
            if isinstance(c, (bool, np.bool_)) or not np.isfinite(float(c)):
                return False
        except (TypeError, ValueError, OverflowError):
            return False
    return True


#: Conic kinds that take any finite center and radius (issue 11): for those a
#: ScanlineError on finite arguments is a failure ("wide-dash" draws ellipses,
#: degenerate ones included, "aa-dash" circles).
DRAWN = {"circle", "ellipse", "fill_circle", "fill_ellipse", "wide", "aa", "dash", "arc",
         "pie", "chord", "wide-dash", "aa-dash"}


@given(xc=values, yc=values, rx=values, ry=values, mode=MODES, w=size, h=size,
       kind=st.sampled_from(["circle", "ellipse", "fill_circle", "fill_ellipse", "wide",
                             "aa", "dash", "arc", "pie", "chord", "wide-dash", "aa-dash"]))
def test_conics(xc, yc, rx, ry, mode, w, h, kind):
    fb, big = frame(mode, w, h)
    radii = (rx,) if kind in ("circle", "fill_circle", "aa-dash") else (rx, ry)
    drawn = kind in DRAWN and _finite(xc, yc, *radii) and min(float(r) for r in radii) >= -0.5
    with bounded(refusals=not drawn):
        if kind == "circle":
            sl.draw.circle(fb, xc, yc, rx)
        elif kind == "ellipse":
            sl.draw.ellipse(fb, xc, yc, rx, ry)
        elif kind == "fill_circle":
            sl.draw.fill_circle(fb, xc, yc, rx)
        elif kind == "fill_ellipse":
            sl.draw.fill_ellipse(fb, xc, yc, rx, ry)
        elif kind == "wide":
            sl.draw.ellipse(fb, xc, yc, rx, ry, width=3)
        elif kind == "aa":
            sl.draw.ellipse(fb, xc, yc, rx, ry, antialias=True)
        elif kind == "dash":
            sl.draw.circle(fb, xc, yc, rx, dash=(2, 1))
        elif kind == "arc":
            sl.draw.arc(fb, xc, yc, rx, ry, 0.5, 4.0)
        elif kind == "wide-dash":
            sl.draw.ellipse(fb, xc, yc, rx, ry, width=3, dash=(2, 1))
        elif kind == "aa-dash":
            sl.draw.circle(fb, xc, yc, rx, width=3, dash=(2, 1), antialias=True)
        elif kind == "chord":
            sl.draw.chord(fb, xc, yc, rx, ry, 4.0, 0.5, style=sl.FillStyle.hollow())
        else:
            sl.draw.pie(fb, xc, yc, rx, ry, -1.0, 2.0)
    assert guard_intact(big)


def _drawable(rows, columns):
    """Whether a batch is a valid (N, columns) array: real, finite, radii >= 0 --
    then it must be drawn, wherever its conics are."""
    if not isinstance(rows, np.ndarray) or rows.dtype.kind not in "fiuO" or rows.ndim != 2 \
            or rows.shape[1] != columns:
        return False
    try:
        a = rows.astype(np.float64)
    except (TypeError, ValueError, OverflowError):
        return False
    return bool(np.isfinite(a).all() and (a[:, 2:] >= 0).all())


@given(rows=arrays(4), mode=MODES, w=size, h=size,
       kind=st.sampled_from(["circles", "ellipses", "fill_ellipses", "aa", "wide-circles",
                             "aa-fill"]))
def test_conic_batches(rows, mode, w, h, kind):
    fb, big = frame(mode, w, h)
    if kind in ("circles", "wide-circles") and rows.ndim == 2:
        rows = rows[..., :3]
    drawn = _drawable(rows, 3 if kind in ("circles", "wide-circles") else 4)
    with bounded(refusals=not drawn):
        if kind == "circles":
            sl.draw.circles(fb, rows)
        elif kind == "wide-circles":
            sl.draw.circles(fb, rows, width=2.5)
        elif kind == "ellipses":
            sl.draw.ellipses(fb, rows)
        elif kind == "fill_ellipses":
            sl.draw.fill_ellipses(fb, rows)
        elif kind == "aa-fill":
            sl.draw.antialias.filled_ellipses(fb, rows)
        else:
            sl.draw.antialias.ellipses(fb, rows)
    assert guard_intact(big)


@given(x=values, y=values, text=st.text(max_size=30), mode=MODES, w=size, h=size,
       kw=st.sampled_from([{}, {"font": "stroke"}, {"antialias": True}, {"height": 1e9},
                           {"angle": 1e300}, {"height": 0.01}]))
def test_text(x, y, text, mode, w, h, kw):
    fb, big = frame(mode, w, h)
    with bounded():
        sl.draw.text(fb, x, y, text, **kw)
    assert guard_intact(big)


@given(segs=arrays(4), pts=arrays(2, max_rows=10), counts=index_arrays(),
       window=st.tuples(values, values, values, values))
def test_clipping(segs, pts, counts, window):
    with bounded():
        sl.clip.lines(segs, window)
    with bounded():
        sl.clip.lines(segs, window, method="cohen-sutherland")
    with bounded():
        sl.clip.polygon(pts, window)
    with bounded():
        sl.clip.polygons(pts, window, counts=counts)
    with bounded():
        sl.clip.polygon(pts, pts[::-1], method="weiler-atherton")


@given(pts=arrays(2, max_rows=10, flavour=False), tol=values, order=values)
def test_curves(pts, tol, order):
    with bounded():
        sl.curves.Bezier(pts).flatten(tolerance=tol)
    with bounded():
        sl.curves.BSpline(pts, order=order).flatten(tolerance=tol)
    with bounded():
        sl.curves.open_uniform_knots(order, 3)


@given(segs=arrays(6), verts=arrays(3, max_rows=8), faces=arrays(3, max_rows=5),
       edges=index_arrays(), counts=index_arrays(), mode=MODES)
def test_three_d(segs, verts, faces, edges, counts, mode):
    cam = sl.Camera(eye=(3, 2, 4), target=(0, 0, 0),
                    projection=sl.projection.perspective(fov=1.0, aspect=1.0, near=0.5, far=20))
    fb, big = frame(mode, 16, 12)
    with bounded():
        sl.draw3d.lines(fb, segs, cam)
    with bounded():
        sl.clip.lines3d(segs, sl.clip.box((-1, -1, -1), (1, 1, 1)))
    with bounded():
        sl.clip.polygons3d(verts, sl.clip.box((-1, -1, -1), (1, 1, 1)), counts=counts)
    with bounded():
        sl.draw3d.project_edges(verts, np.asarray(edges).reshape(-1, 2) if np.asarray(edges).size % 2 == 0 else edges, cam, 16, 12)
    with bounded():
        sl.draw3d.wireframe(fb, sl.mesh.Mesh(verts, faces), cam)
    assert guard_intact(big)


@given(verts=arrays(3, max_rows=15), mode=MODES,
       method=st.sampled_from(["painter", "depth-sort", "scan-line", "area-subdivision",
                               "depth-sort beside"]))
def test_visible_surface_methods(verts, mode, method):
    # hostile device triangles (every one planar and convex, so most pass validation
    # with their extreme values): sorted, split, painted into a guarded frame buffer
    # (afterwards, or beside the sort: painted_depth_sort)
    fb, big = frame(mode, 16, 12)
    with bounded():
        tris = [verts[i:i + 3] for i in range(0, len(verts) - 2, 3)] if np.ndim(verts) == 2 \
            else verts
        sp = sl.visible.ScreenPolygons.from_device(tris, 16, 12)
        values = np.full((max(len(tris), 1), len(fb.pixel("white"))), 255, np.uint8)
        if method == "depth-sort beside":
            pieces, numbers = sl.visible.painted_depth_sort(sp)
            paint(fb, numbers, values[pieces.face])
        elif method in ("scan-line", "area-subdivision"):
            seen = getattr(sl.visible, method.replace("-", "_"))(sp).face
            paint(fb, seen, values)
        else:
            pieces = {"painter": sl.visible.painter, "depth-sort": sl.visible.depth_sort}[
                method](sp)
            paint(fb, piece_numbers(pieces), values[pieces.face])
    assert guard_intact(big)


@given(verts=arrays(3, max_rows=9, flavour=False), mode=MODES)
def test_bsp_trees(verts, mode):
    fb, big = frame(mode, 16, 12)
    n = len(verts) // 3
    cam = sl.Camera(eye=(3, 2, 4), target=(0, 0, 0))
    with bounded():
        mesh = sl.mesh.Mesh(verts[:3 * n], np.arange(3 * n).reshape(n, 3))
        sl.render(fb, mesh, cam, method="bsp", shading="none")
    assert guard_intact(big)
