"""The in-between spacing and morph equalization step tables against Hearn & Baker's
closed forms (section 16-5) worked here, and their explorer views."""

import math

import numpy as np
import pytest

import scanline as sl
from scanline.errors import ScanlineError
from scanline.studio import explorer


@pytest.mark.parametrize("spacing, law", [
    ("constant", lambda u: u),
    ("accelerate", lambda u: 1 - math.cos(u * math.pi / 2)),
    ("decelerate", lambda u: math.sin(u * math.pi / 2)),
    ("accelerate-decelerate", lambda u: (1 - math.cos(u * math.pi)) / 2)])
def test_inbetween_times_follow_the_laws(spacing, law):
    t1, t2, n = 2.0, 5.0, 5
    t = sl.trace.inbetweens(n, spacing, t1, t2)
    assert [r["j"] for r in t.rows] == [1, 2, 3, 4, 5]
    for r in t.rows:
        u = r["j"] / (n + 1)
        assert r["j/(n+1)"] == pytest.approx(u, abs=1e-6)
        assert r["eased"] == pytest.approx(law(u), abs=1e-6)
        assert r["t"] == pytest.approx(t1 + (t2 - t1) * law(u), abs=1e-6)
    gaps = [r["dt"] for r in t.rows]
    last = float(t.notes[-1].split(": ")[1])
    assert sum(gaps) + last == pytest.approx(t2 - t1, abs=1e-5)
    steps = np.diff(gaps + [last])
    if spacing == "constant":
        assert np.allclose(steps, 0, atol=1e-5)
    elif spacing == "accelerate":
        assert (steps > 0).all()
    elif spacing == "decelerate":
        assert (steps < 0).all()


def test_inbetweens_refuse_bad_counts_and_names():
    for bad in (0, 201, True, 2.5):
        with pytest.raises(ScanlineError, match="n must be"):
            sl.trace.inbetweens(bad)
    with pytest.raises(ScanlineError, match="not an easing"):
        sl.trace.inbetweens(3, "sideways")
    with pytest.raises(ScanlineError, match="t2 - t1 must be finite"):
        sl.trace.inbetweens(3, "constant", -1e308, 1e308)


def test_morph_adds_the_midpoints_of_the_triangles_two_longest_edges():
    t = sl.trace.morph_equalize(t=0.25)
    # triangle (2,2) (18,2) (10,16): the slanted edges are sqrt(8^2 + 14^2) = 16.12 long,
    # the base 16; 5 mod 3 = 2 edges get 2 sections: their midpoints are added
    a = [(r["ax"], r["ay"]) for r in t.rows]
    assert a == [(2, 2), (18, 2), (14, 9), (10, 16), (6, 9)]
    assert [r["added"] for r in t.rows] == ["-", "-", "A", "-", "A"]
    b = [(26.5, 2.5), (35.5, 2.5), (38, 11), (31, 16), (24, 11)]
    assert [(r["bx"], r["by"]) for r in t.rows] == b
    for r, p, q in zip(t.rows, a, b):
        assert (r["x"], r["y"]) == pytest.approx((0.75 * p[0] + 0.25 * q[0],
                                                  0.75 * p[1] + 0.25 * q[1]))


def test_morph_square_to_decagon_divides_two_edges_in_three():
    square = [0, 0, 4, 0, 4, 4, 0, 4]
    decagon = [c for k in range(10) for c in (10 + 3 * math.cos(k * math.pi / 5),
                                              3 * math.sin(k * math.pi / 5))]
    t = sl.trace.morph_equalize(square, decagon)
    # L_max = 10, L_min = 4: N_e = 2 edges into N_s + 1 = 3 sections, 2 edges into 2
    assert len(t.rows) == 10
    assert sum(r["added"] == "A" for r in t.rows) == 6
    corners = [k for k, r in enumerate(t.rows) if r["added"] == "-"]
    assert sorted(np.diff(corners + [10])) == [2, 2, 3, 3]
    with pytest.raises(ScanlineError, match="x,y pairs"):
        sl.trace.morph_equalize([0, 0, 1, 1])
    with pytest.raises(ScanlineError, match="x,y pairs"):
        sl.trace.morph_equalize([0, 0, 1, 1, math.nan, 2])
    with pytest.raises(ScanlineError, match="overflow"):
        sl.trace.morph_equalize([-1e308, 0, 1e308, 0, 0, 1])


def test_animation_explorer_views():
    view = explorer.explore("inbetween-spacing", ["--n", "3", "--spacing", "constant"])
    assert [s["pixels"] for s in view["steps"]] == [[[10, 0]], [[20, 0]], [[30, 0]]]
    assert view["bounds"] == [0, 0, 40, 4]
    view = explorer.explore("morph-equalize", ["--t", "0.5"])
    assert "added to A" in view["steps"][2]["rule"]
    assert view["steps"][-1]["areas"][-1][1] == "result"
