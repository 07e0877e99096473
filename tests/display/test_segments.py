"""The display file's segments: operations, priority, visibility, highlighting and
segment transformations, and bad input."""

import math

import numpy as np
import pytest

import scanline as sl
from scanline.display import DisplayFile, VectorDevice, interpret


def pixel_file(width=40, height=30):
    """A display file whose world coordinates are the pixels of a width x height frame."""
    df = DisplayFile()
    df.set_viewing(window=(0, 0, width - 1, height - 1))
    return df


def raster(df, width=40, height=30, **options):
    fb = sl.FrameBuffer(width, height, background="black")
    df.draw(fb, **options)
    return fb


def colors_at(fb, points):
    return [fb.get_pixel(x, y) for x, y in points]


SQUARE_A = [(5, 5), (25, 5), (25, 20), (5, 20)]
SQUARE_B = [(15, 10), (35, 10), (35, 25), (15, 25)]
OVERLAP = (20, 15)  # inside both squares


def two_squares(priority_a, priority_b):
    df = pixel_file()
    df.create_segment("a", priority=priority_a)
    df.polygon(SQUARE_A, color="red")
    df.close_segment()
    df.create_segment("b", priority=priority_b)
    df.polygon(SQUARE_B, color="blue")
    df.close_segment()
    return df


# -- segment operations ---------------------------------------------------------------------
def test_create_close_reopen_append():
    df = pixel_file()
    df.create_segment("s")
    df.polyline([(0, 0), (5, 5)])
    assert df.open_segment == "s"
    df.close_segment()
    assert df.open_segment is None
    df.reopen_segment("s")
    df.markers([(3, 3)])
    df.close_segment()
    assert [p.kind for p in df.segment("s").primitives] == ["polyline", "markers"]


def test_rename_and_delete():
    df = pixel_file()
    df.create_segment("old")
    df.polygon(SQUARE_A)
    df.close_segment()
    df.create_segment("other")
    df.close_segment()
    df.rename_segment("old", "new")
    assert [s.name for s in df.segments] == ["new", "other"]  # order kept
    assert "old" not in df and "new" in df
    df.delete_segment("new")
    assert [s.name for s in df.segments] == ["other"]
    assert not sl.text_image(raster(df), on="#").count("#")


@pytest.mark.parametrize("action, message", [
    (lambda df: df.segment("nope"), "no segment named 'nope'"),
    (lambda df: df.delete_segment("nope"), "no segment named 'nope'"),
    (lambda df: df.rename_segment("nope", "x"), "no segment named 'nope'"),
    (lambda df: df.reopen_segment("nope"), "no segment named 'nope'"),
    (lambda df: df.set_priority("nope", 1), "no segment named 'nope'"),
    (lambda df: df.create_segment("a"), "already exists"),
    (lambda df: df.rename_segment("a", "b"), "'b' already exists"),
    (lambda df: df.close_segment(), "no segment is open"),
    (lambda df: df.polyline([(0, 0), (1, 1)]), "no segment is open"),
    (lambda df: df.create_segment(""), "non-empty string"),
    (lambda df: df.create_segment(3), "non-empty string"),
    (lambda df: df.set_visibility("a", "yes"), "visible must be True or False"),
    (lambda df: df.set_priority("a", float("nan")), "priority must be a finite number"),
    (lambda df: df.set_transformation("a", np.zeros((3, 3))), "bottom row"),
    (lambda df: df.set_transformation("a", [[1, 0], [0, 1]]), "3x3"),
])
def test_segment_errors(action, message):
    df = pixel_file()
    for name in ("a", "b"):
        df.create_segment(name)
        df.close_segment()
    with pytest.raises(sl.ScanlineError, match=message):
        action(df)


def test_open_segment_rules():
    df = pixel_file()
    df.create_segment("a")
    with pytest.raises(sl.ArgumentValueError, match="segment 'a' is still open"):
        df.create_segment("b")
    with pytest.raises(sl.ArgumentValueError, match="'a' is open"):
        df.delete_segment("a")
    df.close_segment()
    df.create_segment("b")
    with pytest.raises(sl.ArgumentValueError, match="segment 'b' is open"):
        df.reopen_segment("a")


@pytest.mark.parametrize("call, message", [
    (lambda df: df.polyline([(0, 0), (1, float("inf"))]), "points must be finite"),
    (lambda df: df.polyline("abc"), "points"),
    (lambda df: df.polyline([(0, 0, 0)]), r"shape \(N, 2\)"),
    (lambda df: df.polyline([(0, 0), (1, 1)], color="nocolor"), "not a known color"),
    (lambda df: df.polyline([(0, 0), (1, 1)], width=0), "width"),
    (lambda df: df.polyline([(0, 0), (1, 1)], cap="pointy"), "cap"),
    (lambda df: df.polyline([(0, 0), (1, 1)], dash="wiggly"), "dash"),
    (lambda df: df.polyline([(0, 0), (1, 1)], pen="square"), "pen is not"),
    (lambda df: df.polygon([(0, 0), (1, 1)]), "at least 3 points"),
    (lambda df: df.polygon(SQUARE_A, rule="odd"), "rule"),
    (lambda df: df.polygon(SQUARE_A, style="zigzag"), "style"),
    (lambda df: df.polygon(SQUARE_A, edge="nocolor"), "edge='nocolor'"),
    (lambda df: df.circle((0, 0), -1), "radius must be >= 0"),
    (lambda df: df.text((0, 0), 5), "string must be a str"),
    (lambda df: df.text((0, 0), "x", font="comic"), "font"),
    (lambda df: df.text((0, 0), "x", align="left"), "align"),
    (lambda df: df.text((0, 0), "x", clip="some"), "clip"),
    (lambda df: df.text((0, 0), "x", height=0), "height must be > 0"),
    (lambda df: df.markers([(0, 0)], kind="star"), "kind"),
    (lambda df: df.markers([(0, 0)], size=1e9), "size"),
])
def test_primitive_errors_name_the_argument(call, message):
    df = pixel_file()
    df.create_segment("s")
    with pytest.raises(sl.ScanlineError, match=message):
        call(df)
    assert df.segment("s").primitives == []  # nothing half-added


@pytest.mark.parametrize("kwargs, message", [
    ({"window": (0, 0, 0, 10)}, "degenerate"),
    ({"viewport": (0, 0, 2, 1)}, "unit square"),
    ({"viewport": (0.5, 0, 0.5, 1)}, "degenerate"),
    ({"view_up": (0, 0)}, "view_up"),
    ({"keep_aspect": "yes"}, "keep_aspect"),
    ({"clip": 2}, "clip"),
])
def test_viewing_errors(kwargs, message):
    df = DisplayFile()
    df.set_viewing(window=(0, 0, 10, 10), viewport=(0, 0, 0.5, 0.5))
    before = df.normalization
    with pytest.raises(sl.ScanlineError, match=message):
        df.set_viewing(**kwargs)
    assert np.array_equal(df.normalization, before)  # unchanged by the bad call


# -- priority, visibility, highlighting ------------------------------------------------------
def test_higher_priority_is_drawn_on_top():
    assert raster(two_squares(0, 1)).get_pixel(*OVERLAP) == (0, 0, 255)
    assert raster(two_squares(1, 0)).get_pixel(*OVERLAP) == (255, 0, 0)


def test_equal_priority_keeps_creation_order():
    assert raster(two_squares(0.5, 0.5)).get_pixel(*OVERLAP) == (0, 0, 255)


def test_changing_priority_redraws_in_the_new_order():
    df = two_squares(0, 1)
    df.set_priority("a", 2)
    assert raster(df).get_pixel(*OVERLAP) == (255, 0, 0)


def test_invisible_segments_are_kept_but_not_drawn():
    df = two_squares(0, 1)
    df.set_visibility("b", False)
    fb = raster(df)
    assert colors_at(fb, [OVERLAP, (30, 22)]) == [(255, 0, 0), (0, 0, 0)]
    df.set_visibility("b", True)
    assert raster(df).get_pixel(30, 22) == (0, 0, 255)


def test_highlighting_frames_the_segment():
    df = two_squares(0, 1)
    plain = raster(df, width=40, height=30)
    df.set_highlighting("a", True)
    lit = raster(df, highlight="lime")
    a = np.argwhere((lit.to_array() != plain.to_array()).any(axis=2))
    ys = 29 - a[:, 0]
    xs = a[:, 1]
    # the frame: the bounding box of square a (5..25 x 5..20) grown by 2 device units
    assert (xs.min(), xs.max(), ys.min(), ys.max()) == (3, 27, 3, 22)
    assert {lit.get_pixel(int(x), int(y)) for x, y in zip(xs, ys)} == {(0, 255, 0)}
    on_frame = (np.isin(xs, (3, 27))) | (np.isin(ys, (3, 22)))
    assert on_frame.all()


# -- segment transformations -------------------------------------------------------------------
def test_world_transformation_equals_moved_coordinates():
    """A segment translated and turned by a quarter turn (exact in world pixels) draws
    the same pixels as the primitive given at its new place."""
    m = sl.transform.compose(sl.transform.translation(3, -2),
                             sl.transform.rotation(math.pi / 2, pivot=(15, 12)))
    moved = np.rint(sl.transform.apply(m, SQUARE_A))
    df1 = pixel_file()
    df1.create_segment("s")
    df1.polygon(SQUARE_A, color="white", edge="red")
    df1.close_segment()
    df1.set_transformation("s", df1.world_transformation(m))
    df2 = pixel_file()
    df2.create_segment("s")
    df2.polygon(moved, color="white", edge="red")
    df2.close_segment()
    a, b = raster(df1).to_array(), raster(df2).to_array()
    assert (a == b).all() and (a != 0).any()


def test_segment_transformation_acts_in_ndc():
    """set_transformation takes an NDC matrix: scaling about the NDC center by 1/2
    halves the picture about the frame's center."""
    df = DisplayFile()
    df.create_segment("s")
    df.polyline([(0, 0), (1, 1)])
    df.close_segment()
    df.set_transformation("s", sl.transform.scaling(0.5, fixed=(0.5, 0.5)))
    v = VectorDevice(101, 101)
    interpret(df, v)
    assert v.lines().tolist() == [[25.0, 25.0, 75.0, 75.0]]


def test_coordinates_beyond_the_device_range_are_drawn_and_overflow_is_refused():
    # any finite device coordinate is drawn (issue 11; refused before): a segment
    # scaled to 1e12 is clipped through the guard as sl.draw clips it, in order with
    # its neighbours; a mapping that overflows to inf is refused by name
    df = pixel_file()
    df.create_segment("s")
    df.polyline([(0, 0), (10, 10)])
    df.polyline([(0, 0), (0, 5)])                 # a run of two: the batch path
    df.polygon([(0, 0), (3, 0), (0, 3)])
    df.polyline([(1, 0), (1, 5)])
    df.close_segment()
    df.set_transformation("s", sl.transform.scaling(1e12))
    fb = raster(df)
    ref = sl.FrameBuffer(fb.width, fb.height, mode=fb.mode)
    sl.draw.polyline(ref, [(0, 0), (1e13, 1e13)], color="white")
    sl.draw.polyline(ref, [(0, 0), (0, 5e12)], color="white")
    sl.draw.polygon(ref, [(0, 0), (3e12, 0), (0, 3e12)], color="white")
    sl.draw.polyline(ref, [(1e12, 0), (1e12, 5e12)], color="white")
    assert np.array_equal(fb.to_array(), ref.to_array()) and fb.to_array().any()
    df = pixel_file()
    df.create_segment("t")
    df.polyline([(0, 0), (1e9, 1e9)])
    df.close_segment()
    df.set_transformation("t", sl.transform.scaling(1e300))       # 1e309: inf
    with pytest.raises(sl.ArgumentValueError, match="segment 't', primitive 0.*overflow"):
        raster(df)


def test_colors_as_lists_and_arrays():
    df = pixel_file()
    df.create_segment("s")
    df.polyline([(0, 0), (10, 0)], color=np.array([255, 0, 0]))
    df.polyline([(0, 2), (10, 2)], color=[0, 255, 0])
    df.close_segment()
    fb = raster(df)
    assert colors_at(fb, [(5, 0), (5, 2)]) == [(255, 0, 0), (0, 255, 0)]
