"""sl.Context: the CTM and its composition order, save/restore, attributes and the
clip region, checked against the functional layer and explicit matrices."""

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import scanline as sl
from scanline import transform as tf
from tests.reference import HYPOTHESIS


def frame(width=40, height=30):
    return sl.FrameBuffer(width, height, mode="1")


def pixels(fb):
    return fb.to_array().astype(bool)


def test_ctm_composes_on_the_right():
    """translate then rotate then scale: CTM = T · R · S, so S acts first."""
    ctx = sl.Context(frame())
    ctx.translate(10, 5)
    ctx.rotate(0.3, pivot=(1, 2))
    ctx.scale(2, 3)
    expected = tf.translation(10, 5) @ tf.rotation(0.3, pivot=(1, 2)) @ tf.scaling(2, 3)
    assert np.allclose(ctx.matrix, expected, atol=1e-12)
    # the last-named transformation acts first on the geometry:
    p = np.array([1.0, 1.0, 1.0])
    by_hand = tf.translation(10, 5) @ (tf.rotation(0.3, pivot=(1, 2)) @ (tf.scaling(2, 3) @ p))
    assert np.allclose(ctx.matrix @ p, by_hand)


def test_order_matters():
    a, b = sl.Context(frame()), sl.Context(frame())
    a.translate(5, 0)
    a.rotate(math.pi / 2)
    b.rotate(math.pi / 2)
    b.translate(5, 0)
    assert np.allclose(tf.apply(a.matrix, (1, 0)), (5, 1))
    assert np.allclose(tf.apply(b.matrix, (1, 0)), (0, 6))


def test_drawing_equals_the_functional_layer_on_transformed_points():
    """A line and a polygon drawn through a CTM are the draw functions' pixels at the
    transformed coordinates (chosen to land on pixel centers)."""
    fb1, fb2 = frame(), frame()
    ctx = sl.Context(fb1)
    ctx.translate(20, 3)
    ctx.rotate(math.pi / 2)
    ctx.scale(2)
    ctx.line(0, 0, 5, 4)
    tri = [(1, 1), (6, 2), (3, 7)]
    ctx.polygon(tri)
    m = tf.compose(tf.translation(20, 3), tf.rotation(math.pi / 2), tf.scaling(2))
    ends = np.rint(tf.apply(m, [(0, 0), (5, 4)]))
    sl.draw.line(fb2, *ends[0], *ends[1])
    sl.draw.polygon(fb2, np.rint(tf.apply(m, tri)))
    assert (pixels(fb1) == pixels(fb2)).all() and pixels(fb1).sum() > 20


def test_save_restore_brings_back_everything():
    ctx = sl.Context(sl.FrameBuffer(20, 20))
    ctx.set_line(color="red", width=3)
    ctx.set_fill(color="blue", style="hatch:45:4", rule="nonzero")
    ctx.set_text(height=7, font="sans")
    before = (ctx.matrix, ctx.line_attributes, ctx.fill_attributes, ctx.text_attributes,
              ctx.clip_region)
    ctx.save()
    ctx.translate(3, 4)
    ctx.rotate(1.0)
    ctx.set_line(color="green", width=1, dash="dashed")
    ctx.set_fill(color="yellow", style="solid", rule="even-odd", edge="black")
    ctx.set_text(height=2)
    ctx.clip((2, 2, 10, 10))
    assert ctx.depth == 1
    ctx.restore()
    after = (ctx.matrix, ctx.line_attributes, ctx.fill_attributes, ctx.text_attributes,
             ctx.clip_region)
    assert np.array_equal(before[0], after[0])
    assert before[1:] == after[1:]
    assert ctx.depth == 0


def test_with_statement_restores_even_after_an_error():
    ctx = sl.Context(frame())
    with pytest.raises(sl.ArgumentValueError):
        with ctx:
            ctx.translate(5, 5)
            ctx.set_line(cap="pointy")
    assert np.array_equal(ctx.matrix, np.eye(3)) and ctx.depth == 0


def test_nested_saves():
    ctx = sl.Context(frame())
    with ctx:
        ctx.translate(1, 0)
        with ctx:
            ctx.translate(0, 2)
            assert np.allclose(tf.apply(ctx.matrix, (0, 0)), (1, 2))
        assert np.allclose(tf.apply(ctx.matrix, (0, 0)), (1, 0))
    assert np.allclose(tf.apply(ctx.matrix, (0, 0)), (0, 0))


def test_restore_without_save():
    with pytest.raises(sl.ArgumentValueError, match="without a matching save"):
        sl.Context(frame()).restore()


def test_rectangular_clip_keeps_only_the_inside():
    fb = frame()
    ctx = sl.Context(fb)
    ctx.clip((5, 5, 20, 15))
    ctx.rectangle(0, 0, 40, 30)      # covers everything
    ctx.line(0, 10, 39, 10)
    on = np.argwhere(pixels(fb))
    ys, xs = 29 - on[:, 0], on[:, 1]
    assert xs.min() >= 5 and xs.max() <= 20 and ys.min() >= 5 and ys.max() <= 15
    # the covering rectangle clipped is the window itself (the scan-line fill of the
    # window's polygon: 15 x 10 centers by its edge rule), the line its part inside
    window = frame()
    sl.draw.polygon(window, [(5, 5), (20, 5), (20, 15), (5, 15)])
    sl.draw.line(window, 5, 10, 20, 10)
    assert (pixels(fb) == pixels(window)).all() and len(on) == 151


def test_clips_intersect():
    ctx = sl.Context(frame())
    ctx.clip((0, 0, 20, 20))
    ctx.clip((10, 5, 30, 25))
    assert ctx.clip_region == (10, 5, 20, 20)
    ctx.clip((25, 0, 30, 5))
    fb_before = ctx._device.fb.to_array().copy()
    ctx.rectangle(0, 0, 40, 30)      # empty clip region: nothing drawn
    assert (ctx._device.fb.to_array() == fb_before).all()


@pytest.mark.parametrize("factor", [0.0, 1e-300])
def test_clip_under_a_vanishing_ctm_is_empty(factor):
    """A window the CTM maps to no device area shows nothing; drawing is not an error
    (a filled circle raised "window must be a convex polygon for Sutherland-Hodgman")."""
    fb = frame()
    ctx = sl.Context(fb)
    ctx.scale(factor)
    ctx.clip((0, 0, 10, 10))
    assert ctx.clip_region == (0.0, 0.0, -1.0, -1.0)
    ctx.circle(0, 0, 3, fill=True)
    ctx.line(0, 0, 5, 5)
    assert not pixels(fb).any()


def test_rotated_clip_is_the_turned_window():
    """Under a rotated CTM the clip window is a turned square: filling everything
    fills exactly that square (the scan-line fill of the same polygon)."""
    fb1, fb2 = frame(60, 60), frame(60, 60)
    ctx = sl.Context(fb1)
    ctx.translate(30, 30)
    ctx.rotate(math.radians(30))
    ctx.clip((-12, -12, 12, 12))
    ctx.rectangle(-100, -100, 200, 200)
    assert isinstance(ctx.clip_region, np.ndarray)
    square = tf.apply(ctx.matrix, [(-12, -12), (12, -12), (12, 12), (-12, 12)])
    sl.draw.polygon(fb2, square)
    assert (pixels(fb1) == pixels(fb2)).all()


def test_reflect_and_shear_compose():
    ctx = sl.Context(frame())
    ctx.reflect("y=x")
    ctx.shear(shx=2)
    assert np.allclose(ctx.matrix, tf.reflection("y=x") @ tf.shear(2, 0))


def test_set_matrix_and_identity():
    ctx = sl.Context(frame())
    ctx.matrix = tf.translation(3, 4)
    ctx.transform(tf.scaling(2))
    assert np.allclose(ctx.matrix, tf.translation(3, 4) @ tf.scaling(2))
    ctx.identity()
    assert np.array_equal(ctx.matrix, np.eye(3))
    with pytest.raises(sl.ArgumentValueError, match="bottom row"):
        ctx.matrix = np.ones((3, 3))


def test_circle_under_scaling_is_an_ellipse():
    fb1, fb2 = sl.FrameBuffer(60, 40, mode="1"), sl.FrameBuffer(60, 40, mode="1")
    ctx = sl.Context(fb1)
    ctx.translate(30, 20)
    ctx.scale(2, 1)
    ctx.circle(0, 0, 10, fill=True)
    ctx2 = sl.Context(fb2)
    ctx2.ellipse(30, 20, 20, 10, fill=True)
    assert (pixels(fb1) == pixels(fb2)).all() and pixels(fb1).sum() > 500


def test_context_on_a_vector_device():
    dev = sl.display.VectorDevice(11, 11)
    ctx = sl.Context(dev)
    ctx.translate(5, 5)
    ctx.rotate(math.pi / 2)
    ctx.line(0, 0, 3, 0)
    got = dev.lines()
    assert np.allclose(got, [[5, 5, 5, 8]], atol=1e-12)


@pytest.mark.parametrize("call, message", [
    (lambda c: c.set_line(width=-1), "width"),
    (lambda c: c.set_line(pen="circle"), "pen"),
    (lambda c: c.set_fill(rule="odd"), "rule"),
    (lambda c: c.set_text(size=3), "unknown text attribute"),
    (lambda c: c.set_text(height=-1), "height"),
    (lambda c: c.clip((0, 0, 0, 5)), "degenerate"),
    (lambda c: c.rotate("a lot"), "angle"),
    (lambda c: c.polygon([(0, 0)]), "at least 3"),
    (lambda c: c.text(0, 0, 12), "string"),
    (lambda c: c.markers([(0, 0)], kind="star"), "kind"),
])
def test_bad_input(call, message):
    with pytest.raises(sl.ScanlineError, match=message):
        call(sl.Context(frame()))


def test_target_must_be_a_frame_buffer_or_device():
    with pytest.raises(sl.ArgumentValueError, match="FrameBuffer or a display device"):
        sl.Context("picture.png")


_num = st.one_of(st.sampled_from([0.0, 1e-300, 1e300, -1e300, 2.0**31, float("nan"),
                                  float("inf")]), st.floats(-1e4, 1e4))


@HYPOTHESIS
@given(st.lists(st.tuples(st.sampled_from(["translate", "rotate", "scale", "shear", "clip"]),
                          _num, _num), max_size=4),
       st.lists(st.tuples(st.sampled_from(["line", "polygon", "circle", "ellipse", "text",
                                           "markers"]), _num, _num, _num), max_size=4))
def test_fuzzed_states_and_drawings_never_crash(ops, draws):
    """Any CTM (huge, tiny, degenerate) and any geometry: drawing works or raises a
    ScanlineError, on a raster and on a vector device."""
    for target in (sl.FrameBuffer(20, 15, mode="1"), sl.display.VectorDevice(20, 15)):
        ctx = sl.Context(target)
        for op, a, b in ops:
            try:
                if op == "translate":
                    ctx.translate(a, b)
                elif op == "rotate":
                    ctx.rotate(a, pivot=(b, a))
                elif op == "scale":
                    ctx.scale(a, b)
                elif op == "shear":
                    ctx.shear(a, b)
                else:
                    ctx.clip((a, b, a + abs(b) + 1, b + 5))
            except sl.ScanlineError:
                pass
        for kind, a, b, c in draws:
            try:
                if kind == "line":
                    ctx.line(a, b, c, a)
                elif kind == "polygon":
                    ctx.polygon([(a, b), (c, a), (b, c)])
                elif kind == "circle":
                    ctx.circle(a, b, abs(c), fill=c > 0)
                elif kind == "ellipse":
                    ctx.ellipse(a, b, abs(c), abs(a), angle=b, fill=True)
                elif kind == "text":
                    ctx.text(a, b, "Ab")
                else:
                    ctx.markers([(a, b)], kind="asterisk")
            except sl.ScanlineError:
                pass


def test_a_bad_attribute_changes_nothing():
    ctx = sl.Context(frame())
    before = (ctx.line_attributes, ctx.fill_attributes, ctx.text_attributes)
    for call in (lambda: ctx.set_fill(color="red", rule="odd"),
                 lambda: ctx.set_line(color="red", cap="pointy"),
                 lambda: ctx.set_text(color="red", font="comic")):
        with pytest.raises(sl.ArgumentValueError):
            call()
    assert (ctx.line_attributes, ctx.fill_attributes, ctx.text_attributes) == before
