"""Bounded time and memory (issue 11, item 3): a hostile or just large input is
refused before the work, or finishes in time proportional to what is visible."""

import numpy as np
import pytest

import scanline as sl
from scanline.curves.flatten import MAX_WORK, point_budget
from scanline.display import text as display_text
from scanline.text.layout import MAX_CHARACTERS, MAX_LAYOUT


def test_open_uniform_knots_refuses_a_billion_control_points():
    with pytest.raises(sl.ArgumentValueError, match=r"count=1,000,000,000.*4,194,304"):
        sl.curves.open_uniform_knots(10**9, 4)
    with pytest.raises(sl.ArgumentTypeError, match="count"):
        sl.curves.open_uniform_knots(4.0, 2)
    # the notes' vector is unchanged
    assert sl.curves.open_uniform_knots(4, 2).tolist() == [0, 0, 1, 2, 3, 3]


def test_de_casteljau_trace_is_bounded_like_the_other_traces():
    pts = np.random.default_rng(1).random((5000, 2)) * 50
    with pytest.raises(sl.ArgumentValueError, match=r"12,502,500 rows.*at most 100,000.*446"):
        sl.trace.de_casteljau(pts, 0.5)
    # the largest triangle that fits is still traced: 446 points -> 99,681 rows
    assert len(sl.trace.de_casteljau(pts[:446], 0.5).rows) == 446 * 447 // 2


def test_bezier_tolerance_1e_300_is_refused_up_front():
    curve = sl.curves.Bezier(np.random.default_rng(2).random((200, 2)) * 50)
    with pytest.raises(sl.ArgumentValueError, match="tolerance=1e-300 is too small"):
        curve.flatten(tolerance=1e-300)
    # a high degree lowers the point budget so that the work stays bounded
    assert point_budget(199) * 200 ** 2 <= MAX_WORK
    assert len(curve.flatten(tolerance=0.25)) > 2


def test_a_bezier_of_enormous_degree_is_refused_by_its_cost():
    curve = sl.curves.Bezier(np.random.default_rng(3).random((10**5, 2)))
    with pytest.raises(sl.ArgumentValueError, match="degree 99999.*split the curve"):
        curve.flatten()


def test_bspline_of_1e5_control_points_flattens_without_the_dense_basis():
    rng = np.random.default_rng(4)
    pts = np.cumsum(rng.random((10**5, 2)) - 0.5, axis=0)
    curve = sl.curves.BSpline(pts, order=4)
    poly = curve.flatten(tolerance=0.25)
    # the polyline passes through the curve's points at the knots (de Boor reference)
    u = np.linspace(*curve.domain, 7)
    on = curve.evaluate(u)
    d = np.min(np.linalg.norm(poly[None, :, :] - on[:, None, :], axis=2), axis=1)
    assert d.max() < 0.26


def test_clip_arcs_with_a_tiny_tolerance_is_refused_by_its_point_count():
    with pytest.raises(sl.ArgumentValueError, match="tolerance=1e-09.*use a larger tolerance"):
        sl.clip.arcs(5, 5, 8e6, 3e6, [(0, 6.28)], tolerance=1e-9)


def test_text_longer_than_the_limit_is_refused_before_any_work():
    fb = sl.FrameBuffer(16, 12)
    big = "x" * (MAX_CHARACTERS + 1)
    for kw in ({}, {"font": "stroke"}, {"antialias": True}):
        with pytest.raises(sl.ArgumentValueError, match="1,048,577 characters"):
            sl.draw.text(fb, 0, 5, big, **kw)
    with pytest.raises(sl.ArgumentValueError, match="laid out has at most 100,000"):
        sl.text.layout("x" * (MAX_LAYOUT + 1))
    assert not fb.to_array().any()


@pytest.mark.parametrize("mode", ["string", "character", "stroke"])
def test_display_text_makes_glyphs_for_the_visible_characters_only(mode):
    from scanline.display import DisplayFile, interpret
    from scanline.display.devices import VectorDevice
    from scanline.display.viewing import workstation

    def drawn(string):
        df = DisplayFile()
        df.set_viewing(window=(0, 0, 100, 100), viewport=(0, 0, 1, 1))
        df.create_segment("t")
        df.text((5, 50), string, height=10, clip=mode)
        df.close_segment()
        dev = VectorDevice(64, 48)
        interpret(df, dev)
        return df, dev.lines()

    long = "ab" * 50_000
    df, lines = drawn(long)
    prim = df.segment("t").primitives[0].transformed(workstation(64, 48))
    placed = display_text.visible(prim, (0, 0, 63, 47))
    assert len(placed) < 40                   # objects for what can show, not 100,000
    assert len(display_text.glyphs(prim)) == len(long)
    # the strokes drawn are those of the first characters: the rest lie outside
    _, short = drawn(long[:40])
    if mode == "string":                      # all or nothing: the string is cut
        assert len(lines) == 0 and len(short) == 0
    else:
        assert len(lines) > 0 and np.array_equal(lines, short)
