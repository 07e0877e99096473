"""DisplayFile.pick and DisplayFile.locate: the pick and locator input devices,
tested against what the raster device draws."""

import math

import numpy as np
import pytest

import scanline as sl
from scanline.errors import ArgumentTypeError, ArgumentValueError

COLORS = {"roof": (200, 0, 0), "wall": (0, 150, 0), "sun": (0, 0, 220), "label": (90, 90, 0)}


def scene():
    df = sl.DisplayFile()
    df.set_viewing(window=(0, 0, 200, 150))
    df.create_segment("wall")
    df.polygon([(20, 10), (90, 10), (90, 60), (20, 60)], color=COLORS["wall"])
    df.close_segment()
    df.create_segment("roof", priority=2)
    df.set_pick_identifier(1)
    df.polyline([(15, 65), (55, 100)], color=COLORS["roof"], width=3)
    df.set_pick_identifier(2)
    df.polyline([(55, 100), (95, 65)], color=COLORS["roof"])
    df.close_segment()
    df.create_segment("sun", priority=1)
    df.set_pick_identifier(0)
    df.circle((160, 120), 15, color=COLORS["sun"])
    df.close_segment()
    df.create_segment("label")
    df.text((120, 20), "GKS", height=20, font="stroke", color=COLORS["label"])
    df.close_segment()
    return df


def owners(df, size=(201, 151)):
    """pixel -> the segment whose color is there, drawing the file on white."""
    fb = sl.FrameBuffer(*size, mode="RGB", background="white")
    df.draw(fb)
    a = fb.to_array()[::-1]
    out = {}
    for name, rgb in COLORS.items():
        ys, xs = np.nonzero((a == rgb).all(axis=2))
        out.update({(int(x), int(y)): name for x, y in zip(xs, ys)})
    return out, a


def test_every_drawn_pixel_picks_its_segment():
    df = scene()
    drawn, _ = owners(df)
    assert set(drawn.values()) == set(COLORS)
    # every pixel of the thin primitives, a sample of the wall's area
    pixels = sorted(drawn.items())
    sample = [p for i, p in enumerate(pixels) if p[1] != "wall" or i % 7 == 0]
    for (x, y), name in sample:
        got = df.pick(x, y, 0.5, (201, 151))
        assert got is not None and got.segment == name, ((x, y), name, got)


def test_far_from_everything_picks_nothing():
    df = scene()
    drawn, a = owners(df)
    pts = np.array(list(drawn))
    rng = np.random.default_rng(3)
    tried = 0
    for x, y in rng.integers(0, [201, 151], (400, 2)).tolist():
        if np.abs(pts - (x, y)).max(axis=1).min() > 3:
            assert df.pick(x, y, 2, (201, 151)) is None, (x, y)
            tried += 1
    assert tried > 100


def test_pick_identifiers_tell_the_parts_of_a_segment_apart():
    df = scene()
    assert df.pick(35, 82.5, 1, (201, 151)) == ("roof", 1)
    assert df.pick(75, 82.5, 1, (201, 151)) == ("roof", 2)
    # the aperture: 3 px left of the thin right-hand rafter is a miss with 1, a hit with 4
    x = 75 - 3 * math.hypot(40, 35) / 35
    assert df.pick(x, 82.5, 1, (201, 151)) is None
    assert df.pick(x, 82.5, 4, (201, 151)) == ("roof", 2)


def test_topmost_detectable_visible_segment_wins():
    df = sl.DisplayFile()
    df.set_viewing(window=(0, 0, 100, 100))
    df.create_segment("under")
    df.polygon([(10, 10), (90, 10), (90, 90), (10, 90)], color="gray")
    df.close_segment()
    df.create_segment("over", priority=1)
    df.polygon([(40, 40), (60, 40), (60, 60), (40, 60)], color="red")
    df.close_segment()
    size = (101, 101)
    assert df.pick(50, 50, 0.5, size).segment == "over"
    assert df.pick(20, 20, 0.5, size).segment == "under"
    df.set_priority("over", -1)
    assert df.pick(50, 50, 0.5, size).segment == "under"
    df.set_priority("over", 1)
    df.set_detectability("over", False)
    assert df.pick(50, 50, 0.5, size).segment == "under"
    df.set_visibility("under", False)
    assert df.pick(50, 50, 0.5, size) is None
    df.set_detectability("over", True)
    df.set_visibility("over", False)
    assert df.pick(50, 50, 0.5, size) is None


def test_pick_follows_the_segment_transformation_and_hollow_areas():
    df = sl.DisplayFile()
    df.set_viewing(window=(0, 0, 100, 100))
    df.create_segment("box")
    df.polygon([(10, 10), (30, 10), (30, 30), (10, 30)], style="hollow", edge="black")
    df.close_segment()
    size = (101, 101)
    assert df.pick(20, 20, 1, size) is None          # hollow: only its edge is drawn
    assert df.pick(20, 10, 1, size).segment == "box"
    df.set_transformation("box", df.world_transformation(sl.transform.translation(50, 40)))
    assert df.pick(20, 10, 1, size) is None
    assert df.pick(70, 50, 1, size).segment == "box"
    drawn, _ = owners_box(df, size)
    assert all(df.pick(x, y, 0.5, size) for x, y in drawn)


def owners_box(df, size):
    fb = sl.FrameBuffer(*size, mode="L", background=255)
    df.draw(fb)
    a = fb.to_array()[::-1]
    ys, xs = np.nonzero(a == 0)
    return list(zip(xs.tolist(), ys.tolist())), a


def test_locate_inverts_the_viewing_pipeline():
    rng = np.random.default_rng(11)
    for _ in range(50):
        x0, y0 = rng.uniform(-100, 100, 2)
        window = (x0, y0, x0 + rng.uniform(1, 300), y0 + rng.uniform(1, 300))
        a, b = np.sort(rng.uniform(0, 1, 2)), np.sort(rng.uniform(0, 1, 2))
        if a[1] - a[0] < 0.05 or b[1] - b[0] < 0.05:
            continue
        up = rng.normal(size=2)
        df = sl.DisplayFile()
        df.set_viewing(window=window, viewport=(a[0], b[0], a[1], b[1]), view_up=tuple(up))
        size = (int(rng.integers(2, 800)), int(rng.integers(2, 600)))
        px, py = rng.uniform(0, size[0]), rng.uniform(0, size[1])
        wx, wy = df.locate(px, py, size)
        # forward: world -> NDC (the normalization) -> device ((0,0)..(1,1) to the corner centers)
        nx, ny = sl.transform.apply(df.normalization, [(wx, wy)])[0]
        assert math.isclose(nx * (size[0] - 1), px, abs_tol=1e-6)
        assert math.isclose(ny * (size[1] - 1), py, abs_tol=1e-6)


def test_locate_by_hand():
    df = sl.DisplayFile()
    df.set_viewing(window=(0, 0, 100, 50), viewport=(0, 0, 1, 0.5))
    fb = sl.FrameBuffer(201, 101)
    assert df.locate(0, 0, fb) == (0.0, 0.0)
    assert df.locate(200, 50, fb) == (100.0, 50.0)
    assert df.locate(100, 100, fb) == (50.0, 100.0)   # above the viewport: outside the window


@pytest.mark.parametrize("args, error, text", [
    ((1, 1, 0, (10, 10)), ArgumentValueError, "aperture=0"),
    ((1, 1, float("nan"), (10, 10)), ArgumentValueError, "aperture"),
    ((float("nan"), 1, 1, (10, 10)), ArgumentValueError, "x must be a finite number, got nan"),
    ((1, 1e300, 1, (10, 10)), ArgumentValueError, "y="),
    ((1, 1, 1, "screen"), ArgumentTypeError, "device must be"),
    ((1, 1, 1, (0, 10)), ArgumentValueError, "device width"),
])
def test_bad_pick_arguments_are_named(args, error, text):
    with pytest.raises(error, match=text):
        scene().pick(*args)


def test_bad_pick_identifier_and_detectability():
    df = scene()
    with pytest.raises(ArgumentTypeError, match="pick_id"):
        df.set_pick_identifier(1.5)
    with pytest.raises(ArgumentTypeError, match="detectable"):
        df.set_detectability("sun", "yes")


def test_large_pictures_pick_with_the_compiled_clipper():
    from scanline.display import pick as pk

    df = sl.DisplayFile()
    df.set_viewing(window=(0, 0, 1000, 100))
    df.create_segment("zigzag")
    xs = np.arange(0, 1000, 1.0)
    df.polyline(np.stack([xs, 50 + 20 * (xs % 2)], axis=1))    # 999 segments, > PY_SEGMENTS
    df.close_segment()
    assert len(xs) - 1 > pk.PY_SEGMENTS
    size = (1001, 101)
    assert df.pick(500, 50, 0.5, size).segment == "zigzag"
    assert df.pick(500, 90, 5, size) is None
    assert df.pick(500.5, 60, 0.6, size).segment == "zigzag"
