"""sl.trace step tables agree with what sl.draw draws (DESIGN.md, convention 5: one
algorithm, one truth), and with the notes' tables / the slow references.
"""

import csv
import io
import json
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import scanline as sl
from tests.reference import (
    HYPOTHESIS,
    bresenham,
    circle_pixels,
    dda,
    ellipse_pixels,
    ellipse_quadrant,
    lit,
    shift,
)

SIZE = 200


def draw(fn, *args, size=SIZE, **kw):
    fb = sl.FrameBuffer(size, size, mode="L")
    fn(fb, *args, color="white", **kw)
    return lit(fb)


def check_json(table, keys):
    rows = json.loads(table.to_json())
    assert rows == table.rows
    for row in rows:
        assert set(row) == set(keys)
    assert table.columns == list(keys)
    lines = list(csv.reader(io.StringIO(table.to_csv())))
    assert lines[0] == list(keys) and len(lines) == len(rows) + 1


# -- Bresenham -------------------------------------------------------------------------------------
def test_bresenham_notes_table():
    t = sl.trace.bresenham(20, 10, 30, 18)
    assert [r["k"] for r in t.rows] == list(range(10))
    assert [r["p"] for r in t.rows] == [6, 2, -2, 14, 10, 6, 2, -2, 14, 10]
    assert [(r["x"], r["y"]) for r in t.rows] == [
        (21, 11), (22, 12), (23, 12), (24, 13), (25, 14), (26, 15), (27, 16), (28, 16), (29, 17), (30, 18)]
    # increments: 2dy - 2dx = -4 when p >= 0, 2dy = 16 otherwise
    assert [r["increment"] for r in t.rows] == [-4, -4, 16, -4, -4, -4, -4, 16, -4, -4]
    assert t.pixels() == {(20, 10)} | {(r["x"], r["y"]) for r in t.rows}
    check_json(t, ["k", "p", "x", "y", "increment"])


def test_bresenham_trace_agrees_with_drawing_and_reference():
    rng = np.random.default_rng(30)
    for x0, y0, x1, y1 in rng.integers(0, SIZE, (3000, 4)).tolist():
        t = sl.trace.bresenham(x0, y0, x1, y1)
        pts, ps = bresenham(x0, y0, x1, y1)
        assert [r["p"] for r in t.rows] == ps
        assert [(r["x"], r["y"]) for r in t.rows] == pts[1:]
        assert [r["k"] for r in t.rows] == list(range(len(ps)))
        for a, b, r in zip(ps, ps[1:], t.rows):
            assert r["increment"] == b - a
        assert t.pixels() == set(pts)
        assert draw(sl.draw.line, x0, y0, x1, y1) == t.pixels()


@given(st.lists(st.integers(-150, 150), min_size=4, max_size=4), st.integers(0, 500), st.integers(0, 500))
@HYPOTHESIS
def test_bresenham_trace_equals_drawing_with_offset(seg, ox, oy):
    x0, y0, x1, y1 = seg
    t = sl.trace.bresenham(x0, y0, x1, y1)
    got = draw(sl.draw.line, x0 + 150 + ox, y0 + 150 + oy, x1 + 150 + ox, y1 + 150 + oy, size=801)
    assert got == shift(t.pixels(), 150 + ox, 150 + oy)


# -- DDA -------------------------------------------------------------------------------------------
def test_dda_trace_agrees_with_drawing_and_reference():
    rng = np.random.default_rng(31)
    for x0, y0, x1, y1 in rng.integers(0, SIZE, (3000, 4)).tolist():
        t = sl.trace.dda(x0, y0, x1, y1)
        pts = dda(x0, y0, x1, y1)
        assert [(r["x"], r["y"]) for r in t.rows] == pts
        assert [r["k"] for r in t.rows] == list(range(len(pts)))
        assert (t.rows[0]["x_real"], t.rows[0]["y_real"]) == (x0, y0)
        assert abs(t.rows[-1]["x_real"] - x1) < 1e-9 and abs(t.rows[-1]["y_real"] - y1) < 1e-9
        assert t.pixels() == set(pts)
        # drawn without offset: the DDA's float rounding depends on absolute coordinates
        assert draw(sl.draw.line, x0, y0, x1, y1, method="dda") == t.pixels()


def test_dda_trace_by_hand_and_json():
    t = sl.trace.dda(0, 0, 4, 2)
    assert [(r["x_real"], r["y_real"], r["x"], r["y"]) for r in t.rows] == [
        (0.0, 0.0, 0, 0), (1.0, 0.5, 1, 1), (2.0, 1.0, 2, 1), (3.0, 1.5, 3, 2), (4.0, 2.0, 4, 2)]
    check_json(t, ["k", "x_real", "y_real", "x", "y"])


# -- midpoint circle ----------------------------------------------------------------------------
def notes_circle_table(r):
    """The notes' table: k, p_k and (x_k+1, y_k+1), repeated until x >= y."""
    x, y, p = 0, r, 1 - r
    rows = []
    while x < y:
        pk = p
        x += 1
        if p < 0:
            p += 2 * x + 1
        else:
            y -= 1
            p += 2 * x + 1 - 2 * y
        rows.append((pk, x, y))
    return rows


def test_circle_notes_table_r10():
    t = sl.trace.midpoint_circle(10)
    assert [(r["k"], r["p"], r["x"], r["y"], r["2x"], r["2y"]) for r in t.rows] == [
        (0, -9, 1, 10, 2, 20), (1, -6, 2, 10, 4, 20), (2, -1, 3, 10, 6, 20), (3, 6, 4, 9, 8, 18),
        (4, -3, 5, 9, 10, 18), (5, 8, 6, 8, 12, 16), (6, 5, 7, 7, 14, 14)]
    check_json(t, ["k", "p", "x", "y", "2x", "2y"])
    tc = sl.trace.midpoint_circle(10, center=(3, -4))
    check_json(tc, ["k", "p", "x", "y", "2x", "2y", "xc+x", "yc+y"])
    assert [(r["xc+x"], r["yc+y"]) for r in tc.rows][-1] == (10, 3)


def test_circle_trace_agrees_with_drawing_and_reference():
    rng = np.random.default_rng(32)
    radii = list(range(0, 120)) + rng.integers(0, 300, 400).tolist()
    for r in radii:
        c = r + 3
        xc, yc = c + int(rng.integers(0, 5)), c + int(rng.integers(0, 5))
        t = sl.trace.midpoint_circle(r, center=(xc, yc))
        assert [(row["p"], row["x"], row["y"]) for row in t.rows] == notes_circle_table(r)
        assert all(row["2x"] == 2 * row["x"] and row["2y"] == 2 * row["y"] for row in t.rows)
        assert t.pixels() == circle_pixels(xc, yc, r)
        assert draw(sl.draw.circle, xc, yc, r, size=2 * c + 6) == t.pixels()
        # without a center, the pixels are about the origin
        assert sl.trace.midpoint_circle(r).pixels() == shift(t.pixels(), -xc, -yc)


# -- midpoint ellipse ----------------------------------------------------------------------------
def test_ellipse_notes_table_8_6():
    t = sl.trace.midpoint_ellipse(8, 6)
    got = [(r["region"], r["k"], r["p"], r["x"], r["y"], r["2ry2x"], r["2rx2y"]) for r in t.rows]
    assert got == [
        ("1", 0, -332, 1, 6, 72, 768), ("1", 1, -224, 2, 6, 144, 768), ("1", 2, -44, 3, 6, 216, 768),
        ("1", 3, 208, 4, 5, 288, 640), ("1", 4, -108, 5, 5, 360, 640), ("1", 5, 288, 6, 4, 432, 512),
        ("1", 6, 244, 7, 3, 504, 384),
        # region 2: p2_0 = 36 * 7.5^2 + 64 * 2^2 - 64 * 36 = -23 (as the notes); then
        # -23 <= 0: x + 1, p += 2*36*8 - 2*64*2 + 64 = 384 -> 361 (the notes print -215),
        # 361 > 0: p += 64 - 2*64*1 = -64 -> 297 (the notes print -279)
        ("2", 0, -23, 8, 2, 576, 256), ("2", 1, 361, 8, 1, 576, 128), ("2", 2, 297, 8, 0, 576, 0)]
    check_json(t, ["region", "k", "p", "x", "y", "2ry2x", "2rx2y"])


def test_ellipse_trace_quarter_values_and_tip():
    # rx = 1, ry = 1: p1_0 = 1 - 1 + 1/4 = 1/4 (not an integer)
    t = sl.trace.midpoint_ellipse(1, 1)
    assert t.rows[0]["p"] == 0.25
    # a flat ellipse ends with a "tip" row whose p is None
    t = sl.trace.midpoint_ellipse(10, 1)
    assert t.rows[-1]["region"] == "tip" and t.rows[-1]["p"] is None and (t.rows[-1]["x"], t.rows[-1]["y"]) == (10, 0)
    json.loads(t.to_json())


def test_ellipse_trace_agrees_with_drawing_and_reference():
    rng = np.random.default_rng(33)
    cases = [(rx, ry) for rx in range(0, 25) for ry in range(0, 25)]
    cases += [tuple(v) for v in rng.integers(0, 120, (400, 2)).tolist()]
    for rx, ry in cases:
        xc, yc = rx + 2, ry + 2
        t = sl.trace.midpoint_ellipse(rx, ry, center=(xc, yc))
        ref = ellipse_quadrant(rx, ry)
        assert [r["region"] for r in t.rows] == [r[0] for r in ref]
        for row, (region, pk, x, y, px, py) in zip(t.rows, ref):
            if region == "tip":
                assert row["p"] is None
            else:
                assert Fraction(row["p"]) == pk
            assert (row["x"], row["y"], row["2ry2x"], row["2rx2y"]) == (x, y, px, py)
            assert (row["xc+x"], row["yc+y"]) == (xc + x, yc + y)
        # k restarts in each region
        for name in ("1", "2", "tip"):
            ks = [r["k"] for r in t.rows if r["region"] == name]
            assert ks == list(range(len(ks)))
        assert t.pixels() == ellipse_pixels(xc, yc, rx, ry)
        assert draw(sl.draw.ellipse, xc, yc, rx, ry, size=2 * max(xc, yc) + 2) == t.pixels()


# -- limits ----------------------------------------------------------------------------------------
def test_trace_limits_raise_package_errors():
    for call, name in [(lambda: sl.trace.bresenham(0, 0, 10**6, 0), "steps"),
                       (lambda: sl.trace.dda(0, 0, 0, 10**6), "steps"),
                       (lambda: sl.trace.midpoint_circle(10**6), "r"),
                       (lambda: sl.trace.midpoint_circle(-1), "r"),
                       (lambda: sl.trace.midpoint_ellipse(10, -2), "ry"),
                       (lambda: sl.trace.bresenham(float("nan"), 0, 1, 1), "x0"),
                       (lambda: sl.trace.midpoint_circle(3, center=(1,)), "center")]:
        with pytest.raises((ValueError, TypeError)) as e:
            call()
        assert isinstance(e.value, sl.ScanlineError)
        assert name in str(e.value)
