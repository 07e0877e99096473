"""Batch kernels on several threads (issue 31, item 1): the pixels of
``sl.draw.lines``, ``circles``, ``ellipses`` and ``polygons`` are the same on 1, 2, 3
and 5 threads, and the same as N single calls in order, in every mode, with
overlapping primitives in many colors (so the drawing order shows), primitives that
straddle the threads' strips, off-canvas and huge coordinates.

The reference is N calls of the single-primitive entry points (``sl.draw.line``,
``circle``, ``ellipse``, ``polygon``): other kernels (or the same kernel on the
whole raster), written before the batch paths were split across threads."""

import warnings

import numba
import numpy as np
import pytest

import scanline as sl
from scanline._kernels import _threads
from scanline._kernels._jit import check_thread_setting

MODES = ("1", "L", "RGB", "RGBA", "P")
W, H = 61, 97       # strips of 97 rows: 48/49 on 2 threads, 32/32/33 on 3, 19-20 on 5


def _values(mode, n, rng):
    """One integer color per primitive, as the batch calls and the single calls take
    them (an opaque RGBA alpha: translucent colors are blended one by one)."""
    if mode == "1":
        return rng.integers(0, 2, n)
    if mode in ("L", "P"):
        return rng.integers(0, 16 if mode == "P" else 256, n)
    rgb = rng.integers(0, 256, (n, 3))
    return rgb if mode == "RGB" else np.hstack([rgb, np.full((n, 1), 255)])


def _single(value):
    return tuple(int(c) for c in value) if np.ndim(value) else int(value)


def _frame(mode):
    if mode == "P":
        table = [(17 * i, 255 - 17 * i, 9 * i) for i in range(16)]
        return sl.FrameBuffer(W, H, mode="P", background=0, color_table=table)
    return sl.FrameBuffer(W, H, mode=mode, background=0 if mode in ("1", "L") else "black")


def _batch(draw, mode, threads, monkeypatch):
    """``draw(fb)`` with the batch kernels split over ``threads`` threads (however
    small the batch: the twin's threshold is lowered for it)."""
    fb = _frame(mode)
    with monkeypatch.context() as m:
        m.setattr(_threads, "threads", lambda: threads)
        m.setattr(_threads, "TWIN_WORK", -1)
        draw(fb)
    return fb.to_array()


def _segments(rng, n):
    rows = rng.integers(-20, [W + 20, H + 20, W + 20, H + 20], (n, 4))
    rows[: n // 8, 3] = rows[: n // 8, 1] + rng.integers(-200, 200, n // 8)   # steep, tall
    rows[-3:] = [[-10**9, -10**9, 10**9, 10**9], [5, -10**8, 40, 10**8], [-7, 48, 70, 49]]
    return rows


def _circles(rng, n, ellipse):
    centers = rng.integers(-30, [W + 30, H + 30], (n, 2))
    radii = rng.integers(0, 60, (n, 2 if ellipse else 1))
    rows = np.hstack([centers, radii])
    rows[-2:, :2] = [[30, 48], [30, 49]]       # on the 2-thread strip edge
    rows[-1, 2:] = 10**6 if not ellipse else [3, 10**5]   # huge, partly visible
    return rows


def _polygons(rng, n):
    polys = []
    for _ in range(n):
        k = rng.integers(3, 9)
        center = rng.uniform([-20, -20], [W + 20, H + 20])
        pts = center + rng.uniform(-40, 40, (k, 2))
        if rng.random() < 0.5:
            pts = np.round(pts)                 # integer edges, stepped exactly
        polys.append(pts)
    polys.append(np.array([[-1e7, 47.5], [1e7, 47.5], [30, 52.2]]))     # strip edge, far
    polys.append(np.array([[10.0, -50.0], [50.0, 200.0], [-20.0, 150.0], [40.0, 40.0]]))
    return polys


CASES = {
    "lines": (lambda rng: _segments(rng, 120),
              lambda fb, rows, c: sl.draw.lines(fb, rows, c),
              lambda fb, row, c: sl.draw.line(fb, *(int(v) for v in row), _single(c))),
    "circles": (lambda rng: _circles(rng, 60, False),
                lambda fb, rows, c: sl.draw.circles(fb, rows, c),
                lambda fb, row, c: sl.draw.circle(fb, *(int(v) for v in row), _single(c))),
    "ellipses": (lambda rng: _circles(rng, 60, True),
                 lambda fb, rows, c: sl.draw.ellipses(fb, rows, c),
                 lambda fb, row, c: sl.draw.ellipse(fb, *(int(v) for v in row), _single(c))),
    "polygons": (lambda rng: _polygons(rng, 40),
                 lambda fb, rows, c: sl.draw.polygons(fb, rows, c),
                 lambda fb, row, c: sl.draw.polygon(fb, row, _single(c))),
}


@pytest.mark.parametrize("mode", MODES)
@pytest.mark.parametrize("name", sorted(CASES))
def test_batch_pixels_do_not_depend_on_threads(name, mode, monkeypatch):
    make, batch, single = CASES[name]
    rng = np.random.default_rng(sum(map(ord, name + mode)))
    rows = make(rng)
    values = _values(mode, len(rows), rng)
    fb = _frame(mode)
    for row, value in zip(rows, values):
        single(fb, row, value)
    expected = fb.to_array()
    assert expected.any(), "the reference drew nothing"
    for threads in (1, 2, 3, 5):
        got = _batch(lambda f: batch(f, rows, values), mode, threads, monkeypatch)
        np.testing.assert_array_equal(got, expected, err_msg=f"{name} on {threads} threads")
    one_color = _batch(lambda f: batch(f, rows, 1), mode, 3, monkeypatch)
    fb = _frame(mode)
    for row in rows:
        single(fb, row, 1)
    np.testing.assert_array_equal(one_color, fb.to_array())


def test_more_threads_than_rows(monkeypatch):
    """A raster of 2 rows on 5 threads: three strips are empty, nothing is lost."""
    rows = np.array([[0, 0, 3, 1], [1, 1, 0, 0]])
    fb = sl.FrameBuffer(4, 2, mode="1")
    with monkeypatch.context() as m:
        m.setattr(_threads, "threads", lambda: 5)
        m.setattr(_threads, "TWIN_WORK", -1)
        sl.draw.lines(fb, rows)
        sl.draw.circles(fb, [[2, 0, 1]])
    # lines: (0,0) (1,0) (2,1) (3,1) and (0,0) (1,1); circle: (3,0) (1,0) (2,1) (2,-1)
    assert sl.text_image(fb) == "-###\n##-#"


def test_thread_count_beyond_the_machine_is_clamped_with_a_warning(monkeypatch):
    cores = _threads.cores()
    monkeypatch.setattr(numba, "get_num_threads", lambda: cores + 7)
    monkeypatch.setattr(_threads, "_warned", [])
    with pytest.warns(RuntimeWarning, match="NUMBA_NUM_THREADS"):
        assert _threads.threads() == cores
    with warnings.catch_warnings():
        warnings.simplefilter("error")          # said once
        assert _threads.threads() == cores


@pytest.mark.parametrize("value", ["0", "-3", "two", "1.5"])
def test_bad_numba_num_threads_is_a_clear_error(value):
    with pytest.raises(ValueError, match=r"NUMBA_NUM_THREADS must be a positive integer.*"
                                         + value.replace(".", r"\.")):
        check_thread_setting({"NUMBA_NUM_THREADS": value})


def test_good_numba_num_threads_passes():
    check_thread_setting({"NUMBA_NUM_THREADS": "2"})
    check_thread_setting({})


@pytest.mark.parametrize("count", [0, -1])
def test_bad_thread_argument_is_refused_by_numba(count):
    """``numba.set_num_threads``, the argument form, refuses 0 and negatives itself."""
    with pytest.raises(ValueError):
        numba.set_num_threads(count)


@pytest.mark.parametrize("dtype", [np.int64, np.int32, np.uint16])
def test_integer_batches_draw_what_their_float_values_draw(dtype):
    # integers in range skip the float round trip (_validate.integers_in_range): the
    # pixels must be those of the same values as floats, which the agreement tests
    # hold against scikit-image and OpenCV; the caller's array is not written
    rng = np.random.default_rng(11)
    segs = rng.integers(0, 60, (400, 4)).astype(dtype)
    rings = np.concatenate([rng.integers(5, 55, (300, 2)), rng.integers(0, 5, (300, 1))],
                           axis=1).astype(dtype)
    kept = segs.copy(), rings.copy()
    for draw, rows in ((sl.draw.lines, segs), (sl.draw.circles, rings)):
        ints, floats = sl.FrameBuffer(64, 64), sl.FrameBuffer(64, 64)
        draw(ints, rows, color="white")
        draw(floats, rows.astype(np.float64), color="white")
        assert np.array_equal(ints.to_array(), floats.to_array())
        assert ints.to_array().any()
    assert np.array_equal(segs, kept[0]) and np.array_equal(rings, kept[1])


@pytest.mark.parametrize("blocks", [False, True])
@pytest.mark.parametrize("threads", [1, 2, 3, 5])
def test_extremes_split_between_threads_are_numpy_s(threads, blocks, monkeypatch):
    from scanline import _validate as v

    monkeypatch.setattr(_threads, "threads", lambda: threads)
    monkeypatch.setattr(v, "SPLIT_VALUES", 10)
    if blocks:                      # each part reduced block by block (a large batch's)
        monkeypatch.setattr(v, "MIN_MAX_BLOCKED", 8)
        monkeypatch.setattr(v, "MIN_MAX_BLOCK", 3)
    rng = np.random.default_rng(threads)
    for n in (1, 9, 10, 11, 47, 1000):
        a = rng.normal(size=(n, 3)) * 1e3
        assert v.extremes(a) == (a.min(), a.max())
        assert v.extremes(a[:, ::2]) == (a[:, ::2].min(), a[:, ::2].max())   # strided
        for at in (0, n // 2, 3 * n - 1):                # a NaN in any part carries
            b = a.copy()
            b.flat[at] = np.nan
            lo, hi = v.extremes(b)
            assert np.isnan(lo) and np.isnan(hi)


def test_a_bad_value_in_any_part_of_a_large_batch_is_refused(monkeypatch):
    from scanline import _validate as v

    monkeypatch.setattr(_threads, "threads", lambda: 3)
    monkeypatch.setattr(v, "SPLIT_VALUES", 8)
    fb = sl.FrameBuffer(20, 10)
    tri = np.tile([[(1.0, 1.0, 0.5), (15.0, 2.0, 0.5), (5.0, 8.0, 0.5)]], (30, 1, 1))
    colors = np.full((30, 3, 3), 100.0)
    sl.draw.triangles(fb, tri, colors=colors)
    for at, value in ((0, 256.0), (44, -1.0), (269, np.nan)):
        bad = colors.copy()
        bad.flat[at] = value
        with pytest.raises(sl.ArgumentValueError, match="0..255"):
            sl.draw.triangles(fb, tri, colors=bad)
    bad = tri.copy()
    bad[29, 2, 1] = np.inf
    with pytest.raises(sl.ArgumentValueError, match=r"vertices\[29\].*not finite"):
        sl.draw.triangles(fb, bad, colors=colors)
