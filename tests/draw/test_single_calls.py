"""Single-primitive calls take the compiled entry point directly once their key is
known (scanline._kernels._jit.call_typed): the pixels must be those of the batch
kernels, which go through numba's dispatcher, in every storage layout and method,
and the Python twins must still run when compilation is switched off."""

import numpy as np
import pytest

import scanline as sl
from scanline._kernels import _jit


@pytest.mark.parametrize("mode", ["1", "L", "RGB", "RGBA", "P"])
def test_single_calls_match_the_batch_kernels(mode):
    rng = np.random.default_rng(7)
    segs = rng.integers(-20, 80, (60, 4))
    circles = np.c_[rng.integers(-10, 70, (40, 2)), rng.integers(0, 30, 40)]
    ellipses = np.c_[rng.integers(-10, 70, (40, 2)), rng.integers(0, 30, (40, 2))]
    one, many = sl.FrameBuffer(64, 48, mode=mode), sl.FrameBuffer(64, 48, mode=mode)
    # alternate the methods and the layouts so that a key standing for the wrong
    # specialization would show
    other = sl.FrameBuffer(64, 48, mode="1" if mode != "1" else "RGB")
    for method in ("bresenham", "dda"):
        for x0, y0, x1, y1 in segs.tolist():
            sl.draw.line(one, x0, y0, x1, y1, method=method)
            sl.draw.line(other, x0, y0, x1, y1, method=method)
        sl.draw.lines(many, segs, method=method)
    for xc, yc, r in circles.tolist():
        sl.draw.circle(one, xc, yc, r)
        sl.draw.circle(other, xc, yc, r)
    sl.draw.circles(many, circles)
    for xc, yc, rx, ry in ellipses.tolist():
        sl.draw.ellipse(one, xc, yc, rx, ry)
        sl.draw.ellipse(other, xc, yc, rx, ry)
    sl.draw.ellipses(many, ellipses)
    assert np.array_equal(one.to_array(), many.to_array())


def test_the_twins_still_run_when_compiling_is_off(monkeypatch):
    fb = sl.FrameBuffer(32, 32, mode="L")
    sl.draw.line(fb, 0, 0, 31, 9)              # compiled: the entry point is known now
    ran = []
    real = _jit._interpreted
    monkeypatch.setattr(_jit, "_interpreted", lambda kernel, args: ran.append(kernel) or real(kernel, args))
    monkeypatch.setattr(_jit, "COMPILE", "never")
    twin = sl.FrameBuffer(32, 32, mode="L")
    sl.draw.line(twin, 0, 0, 31, 9)
    sl.draw.circle(twin, 10, 10, 5)
    assert [k.__name__ for k in ran] == ["draw_line", "draw_circle"]
    sl.draw.circle(fb, 10, 10, 5)
    assert np.array_equal(fb.to_array(), twin.to_array())


@pytest.mark.parametrize("mode", ["1", "L", "RGB", "RGBA", "P"])
@pytest.mark.parametrize("rule", ["even-odd", "nonzero"])
def test_one_contour_matches_the_general_path(mode, rule):
    """One contour in an opaque color takes the single compiled call; the same
    vertices as one contour of a list of contours take the general path (contours,
    guard, blend)."""
    rng = np.random.default_rng(3)
    fast, general = sl.FrameBuffer(64, 48, mode=mode), sl.FrameBuffer(64, 48, mode=mode)
    for n in (3, 5, 9, 17):
        for dtype in (np.float64, np.int32, np.float32):
            verts = (rng.random((n, 2)) * 90 - 15).astype(dtype)
            sl.draw.polygon(fast, verts if dtype is np.int32 else verts.tolist(), rule=rule)
            sl.draw.polygon(general, [verts], rule=rule)
    # far and non-finite vertices: the fast call draws nothing and hands over
    far = np.array([[-1e12, -5.0], [40.0, 1e15], [50.0, 10.0]])
    sl.draw.polygon(fast, far, rule=rule)
    sl.draw.polygon(general, [far], rule=rule)
    assert np.array_equal(fast.to_array(), general.to_array())
    with pytest.raises(sl.ScanlineError, match=r"points must be finite; vertex 1 is \[nan"):
        sl.draw.polygon(fast, np.array([[0.0, 0.0], [np.nan, 3.0], [5.0, 5.0]]))
    with pytest.raises(sl.ScanlineError, match="must hold real numbers"):
        sl.draw.polygon(fast, [(True, False), (False, True), (True, True)])

