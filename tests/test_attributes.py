"""sl.FillStyle: solid, hollow, pattern and hatch fills painted through the area hook
``draw._area.fill_area``.

The areas here are drawn by callables written in this file (a numpy predicate per
pixel), so the styles are tested apart from the polygon and disk code; the expected
pixels come from slow per-pixel references written from the documented rules.
"""

import math
import pickle

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import scanline as sl
from scanline.draw._area import fill_area
from tests.reference import HYPOTHESIS, MODES, lit

FillStyle = sl.FillStyle


# -- areas given by a predicate ----------------------------------------------------------

class Area:
    """An area given by ``inside(x, y)`` (vectorized over device coordinates), with the
    ``draw`` and ``outline`` callables of the fill_area contract; records the calls."""

    def __init__(self, inside, bbox):
        self.inside = inside
        self.bbox = bbox
        self.rasters = []  # (width, height, ox, oy) of each draw call
        self.outlines = 0

    def draw(self, buf, packed, width, height, ox, oy, value):
        self.rasters.append((width, height, ox, oy))
        xs = np.arange(width)[None, :] + ox
        ys = np.arange(height)[:, None] + oy
        m = np.broadcast_to(self.inside(xs, ys), (height, width))
        if packed:
            bits = np.unpackbits(buf[:, :, 0], axis=1)
            bits[:, :width][m] = value[0]
            buf[:, :, 0] = np.packbits(bits, axis=1)
        else:
            buf[m] = value

    def outline(self):
        self.outlines += 1

    def paint(self, fb, style, color="white"):
        fill_area(fb, color, style, self.bbox, self.draw, self.outline)
        return fb


def box(x0, y0, x1, y1):
    return Area(lambda x, y: (x >= x0) & (x <= x1) & (y >= y0) & (y <= y1), (x0, y0, x1, y1))


def disk(xc, yc, r):
    return Area(lambda x, y: (x - xc) ** 2 + (y - yc) ** 2 <= r * r, (xc - r, yc - r, xc + r, yc + r))


def painted(style, area, width, height, mode="1", color="white"):
    return lit(area.paint(sl.FrameBuffer(width, height, mode=mode), style, color))


def rows_text(fb):
    return sl.text_image(fb).split("\n")


# -- slow references from the documented rules ----------------------------------------

def pattern_cell(tile, x, y, ax=0, ay=0):
    """tile[th - 1 - (y - ay) mod th][(x - ax) mod tw] (image-order tile)."""
    th, tw = len(tile), len(tile[0])
    return tile[th - 1 - (y - ay) % th][(x - ax) % tw]


def hatch_pixel(x, y, angle, spacing, width, cross=False, ax=0, ay=0):
    """(d + w'/2) mod spacing < w', d = c (y - ay) - s (x - ax), w' = width max(|c|, |s|)."""
    families = [angle, angle + math.pi / 2] if cross else [angle]
    for a in families:
        c, s = math.cos(a), math.sin(a)
        w = width * max(abs(c), abs(s))
        if (c * (y - ay) - s * (x - ax) + w / 2) % spacing < w:
            return True
    return False


def reference_image(fb, area, value_at):
    """Expected image-order array: fb's pixels, with area pixels replaced by
    ``value_at(x, y)`` (None: unchanged)."""
    out = fb.to_array()
    for x in range(fb.width):
        for y in range(fb.height):
            if area.inside(x, y):
                value = value_at(x, y)
                if value is not None:
                    out[fb.height - 1 - y, x] = value
    return out


# -- solid and hollow --------------------------------------------------------------------

@pytest.mark.parametrize("mode", MODES)
def test_solid_equals_no_style(mode):
    a = disk(5, 4, 3).paint(sl.FrameBuffer(12, 9, mode=mode), FillStyle.solid(), "white")
    b = disk(5, 4, 3).paint(sl.FrameBuffer(12, 9, mode=mode), None, "white")
    np.testing.assert_array_equal(a.to_array(), b.to_array())
    assert lit(a) == {(x, y) for x in range(12) for y in range(9) if (x - 5) ** 2 + (y - 4) ** 2 <= 9}


def test_solid_paint_called_directly():
    fb, area = sl.FrameBuffer(5, 4, mode="L"), box(1, 1, 3, 2)
    FillStyle.solid().paint(fb, 200, area.bbox, area.draw, area.outline)
    assert lit(fb) == {(x, y) for x in range(1, 4) for y in (1, 2)}


@pytest.mark.parametrize("mode", MODES)
def test_hollow_calls_outline_only(mode):
    fb, area = sl.FrameBuffer(8, 8, mode=mode), box(1, 1, 6, 6)
    area.paint(fb, FillStyle.hollow())
    assert area.outlines == 1 and area.rasters == []
    assert lit(fb) == set()


# -- pattern -----------------------------------------------------------------------------

def test_pattern_exact_image_and_tile_row_order():
    # row 0 of the tile is its top row: with the anchor at the origin, scan line 0
    # reads the tile's bottom row
    style = FillStyle.pattern([[True, True, False],
                               [True, False, False]])
    fb = box(0, 0, 6, 3).paint(sl.FrameBuffer(7, 4, mode="1"), style)
    assert rows_text(fb) == ["##-##-#",
                             "#--#--#",
                             "##-##-#",
                             "#--#--#"]


def test_pattern_origin_anchor_is_fixed_to_the_frame_buffer():
    tile = [[True, False, False], [False, False, True]]
    style = FillStyle.pattern(tile)
    first = painted(style, box(1, 1, 7, 6), 16, 12)
    moved = painted(style, box(5, 4, 11, 9), 16, 12)
    # the same device pixel gets the same tile cell, wherever the shape is
    expected = {(x, y) for x in range(16) for y in range(12) if pattern_cell(tile, x, y)}
    assert first == {(x, y) for (x, y) in expected if 1 <= x <= 7 and 1 <= y <= 6}
    assert moved == {(x, y) for (x, y) in expected if 5 <= x <= 11 and 4 <= y <= 9}
    assert moved != {(x + 4, y + 3) for x, y in first}


@pytest.mark.parametrize("dx, dy", [(4, 3), (1, 0), (-1, 2)])
def test_pattern_shape_anchor_moves_with_the_shape(dx, dy):
    tile = [[True, False, False], [False, False, True]]
    style = FillStyle.pattern(tile, anchor="shape")
    first = painted(style, disk(6, 6, 4), 20, 20)
    moved = painted(style, disk(6 + dx, 6 + dy, 4), 20, 20)
    assert moved == {(x + dx, y + dy) for x, y in first}
    # the tile's bottom-left cell sits on the bounding box's lower-left corner (2, 2)
    expected = {(x, y) for x in range(20) for y in range(20)
                if (x - 6) ** 2 + (y - 6) ** 2 <= 16 and pattern_cell(tile, x, y, 2, 2)}
    assert first == expected


def test_pattern_explicit_reference_point():
    tile = [[False, True], [True, False], [False, False]]
    style = FillStyle.pattern(tile, anchor="shape", reference=(3.4, -1.6))  # -> (3, -2)
    got = painted(style, box(0, 0, 9, 9), 10, 10)
    assert got == {(x, y) for x in range(10) for y in range(10) if pattern_cell(tile, x, y, 3, -2)}


@pytest.mark.parametrize("mode", MODES)
def test_transparent_pattern_keeps_the_pixels_underneath(mode):
    fb = sl.FrameBuffer(9, 7, mode=mode, background="white")
    fb.set_pixel(4, 3, "black")
    sl.draw.line(fb, 0, 0, 8, 6, color="black")
    before = fb.to_array()
    tile = sl.FillStyle.TILES["dots"]
    area = disk(4, 3, 3)
    area.paint(fb, FillStyle.pattern(tile), "red")
    red = value_of(fb, "red")
    expected = reference_image(sl.FrameBuffer.from_array(before, mode=mode, color_table=None if mode != "P"
                                                         else fb.color_table), area,
                               lambda x, y: red if pattern_cell(tile, x, y) else None)
    np.testing.assert_array_equal(fb.to_array(), expected)


@pytest.mark.parametrize("mode", MODES)
def test_color_tile_in_every_mode(mode):
    tile = [["red", None, (0, 0, 255)],
            [True, "#00ff00", "white"]]
    fb = sl.FrameBuffer(8, 6, mode=mode)
    area = box(1, 1, 6, 4)
    area.paint(fb, FillStyle.pattern(tile), "yellow")
    cell_value = {"red": "red", (0, 0, 255): (0, 0, 255), True: "yellow", "#00ff00": "#00ff00",
                  "white": "white"}

    def value(x, y):
        cell = pattern_cell(tile, x, y)
        if cell is None:
            return None
        p = fb.pixel(cell_value[cell])
        return p[0] if p.size == 1 else p

    blank = sl.FrameBuffer(8, 6, mode=mode)
    if mode == "P":
        blank.color_table = fb.color_table
    np.testing.assert_array_equal(fb.to_array(), reference_image(blank, area, value))


def test_rgb_array_tile_and_palette_mode():
    tile = np.zeros((2, 2, 3), np.uint8)
    tile[0, 0] = (255, 0, 0)
    tile[1, 1] = (0, 0, 255)  # bottom-right; the other two cells black
    fb = sl.FrameBuffer(4, 4, mode="P", background="white")
    box(0, 0, 3, 3).paint(fb, FillStyle.pattern(tile))
    table = fb.color_table
    colors = [[tuple(int(c) for c in table[i]) for i in row] for row in fb.to_array()]
    red, blue, black = (255, 0, 0), (0, 0, 255), (0, 0, 0)
    assert colors == [[red, black, red, black], [black, blue, black, blue]] * 2


def test_integer_tile_means_gray_levels_or_indices():
    fb = sl.FrameBuffer(4, 2, mode="L")
    box(0, 0, 3, 1).paint(fb, FillStyle.pattern(np.array([[10, 20], [30, 40]])))
    assert fb.to_array().tolist() == [[10, 20, 10, 20], [30, 40, 30, 40]]
    fb = sl.FrameBuffer(2, 1, mode="P", color_table=["black", "red", "lime"])
    box(0, 0, 1, 0).paint(fb, FillStyle.pattern([[2, 1]]))
    assert fb.to_array().tolist() == [[2, 1]]


@pytest.mark.parametrize("name", sorted(FillStyle.TILES))
def test_named_tiles(name):
    tile = FillStyle.TILES[name]
    assert tile.dtype == bool and tile.ndim == 2 and tile.any() and not tile.flags.writeable
    assert painted(FillStyle.pattern(name), box(0, 0, 15, 15), 16, 16) == {
        (x, y) for x in range(16) for y in range(16) if pattern_cell(tile.tolist(), x, y)}


def test_bricks_tile_looks_like_bricks():
    fb = box(0, 0, 15, 7).paint(sl.FrameBuffer(16, 8, mode="1"), FillStyle.pattern("bricks"))
    assert rows_text(fb) == ["################",
                             "#-------#-------",
                             "#-------#-------",
                             "#-------#-------",
                             "################",
                             "----#-------#---",
                             "----#-------#---",
                             "----#-------#---"]


# -- hatch -------------------------------------------------------------------------------

def test_hatch_horizontal_rows():
    fb = box(0, 0, 9, 9).paint(sl.FrameBuffer(10, 10, mode="1"), FillStyle.hatch(0.0, spacing=4))
    assert lit(fb) == {(x, y) for x in range(10) for y in (0, 4, 8)}


def test_hatch_vertical_columns():
    fb = box(0, 0, 9, 9).paint(sl.FrameBuffer(10, 10, mode="1"), FillStyle.hatch(math.pi / 2, spacing=3))
    assert lit(fb) == {(x, y) for x in (0, 3, 6, 9) for y in range(10)}


@pytest.mark.parametrize("angle", [math.pi, -math.pi / 2, 3 * math.pi / 2, 2 * math.pi])
def test_hatch_right_angles_are_exact(angle):
    got = painted(FillStyle.hatch(angle, spacing=5), box(0, 0, 19, 19), 20, 20)
    horizontal = abs(math.cos(angle)) > 0.5
    assert got == {(x, y) for x in range(20) for y in range(20) if (y if horizontal else x) % 5 == 0}


def test_hatch_width_two_rows():
    got = painted(FillStyle.hatch(0.0, spacing=6, line_width=2), box(0, 0, 4, 13), 5, 14)
    assert {y for _, y in got} == {0, 5, 6, 11, 12}  # [-1, 1) about y = 0, 6, 12


def test_hatch_diagonal_is_single_pixel_diagonals():
    fb = box(0, 0, 11, 7).paint(sl.FrameBuffer(12, 8, mode="1"),
                              FillStyle.hatch(math.pi / 4, spacing=3 * math.sqrt(2)))
    assert rows_text(fb) == ["-#-----#----",
                             "#-----#-----",
                             "-----#-----#",
                             "----#-----#-",
                             "---#-----#--",
                             "--#-----#---",
                             "-#-----#----",
                             "#-----#-----"]


def test_cross_hatch():
    got = painted(FillStyle.hatch(0.0, spacing=4, cross=True), box(0, 0, 9, 9), 10, 10)
    assert got == {(x, y) for x in range(10) for y in range(10) if x % 4 == 0 or y % 4 == 0}
    fb = box(0, 0, 8, 8).paint(sl.FrameBuffer(9, 9, mode="1"),
                               FillStyle.hatch(math.pi / 4, spacing=3 * math.sqrt(2), cross=True))
    assert lit(fb) == {(x, y) for x in range(9) for y in range(9) if (x - y) % 6 == 0 or (x + y) % 6 == 0}


@pytest.mark.parametrize("angle, spacing, width", [
    (0.3, 7, 1), (1.1, 9, 2), (math.pi / 4, 6, 1.5), (2.0, 12.5, 3), (-0.7, 5, 1),
])
def test_hatch_share_of_pixels(angle, spacing, width):
    got = painted(FillStyle.hatch(angle, spacing=spacing, line_width=width), box(0, 0, 299, 299), 300, 300)
    expected = width * max(abs(math.cos(angle)), abs(math.sin(angle))) / spacing
    assert abs(len(got) / 300**2 - expected) < 0.01


@pytest.mark.parametrize("angle", [0.2, 0.6, 2.5, -0.4])
def test_hatch_width_one_has_one_pixel_per_column_or_row(angle):
    """Lines nearer horizontal: no two hatch pixels on top of each other in a column
    (one pixel per column per line); steeper lines likewise along rows."""
    got = painted(FillStyle.hatch(angle, spacing=5), box(0, 0, 59, 59), 60, 60)
    step = (0, 1) if abs(math.cos(angle)) >= abs(math.sin(angle)) else (1, 0)
    assert got and not any((x + step[0], y + step[1]) in got for x, y in got)


@pytest.mark.parametrize("seed", range(4))
def test_hatch_matches_reference_on_a_disk(seed):
    rng = np.random.default_rng(seed)
    angle, spacing, width = rng.uniform(-4, 4), rng.uniform(2, 9), rng.uniform(0.5, 3)
    cross = bool(seed % 2)
    area = disk(20, 17, 15)
    style = FillStyle.hatch(angle, spacing=spacing, line_width=width, cross=cross, anchor="shape")
    got = painted(style, area, 40, 36)
    expected = {(x, y) for x in range(40) for y in range(36) if area.inside(x, y)
                and hatch_pixel(x, y, angle, spacing, width, cross, ax=5, ay=2)}
    assert got == expected


def test_hatch_origin_anchor_continues_across_shapes():
    style = FillStyle.hatch(0.5, spacing=5)
    whole = painted(style, box(0, 0, 29, 19), 30, 20)
    fb = sl.FrameBuffer(30, 20, mode="1")
    box(0, 0, 14, 19).paint(fb, style)
    box(15, 0, 29, 19).paint(fb, style)
    assert lit(fb) == whole


def value_of(fb, color):
    p = fb.pixel(color)
    return p[0] if p.size == 1 else p


@pytest.mark.parametrize("mode", MODES)
@pytest.mark.parametrize("background", ["white", None])
def test_hatch_background(mode, background):
    fb = sl.FrameBuffer(6, 6, mode=mode, background="blue")
    area = box(1, 1, 4, 4)
    area.paint(fb, FillStyle.hatch(0.0, spacing=2, background=background), "red")
    blank = sl.FrameBuffer(6, 6, mode=mode, background="blue")
    if mode == "P":
        blank.color_table = fb.color_table
    expected = reference_image(blank, area, lambda x, y: value_of(fb, "red") if y % 2 == 0 else
                               None if background is None else value_of(fb, background))
    np.testing.assert_array_equal(fb.to_array(), expected)


# -- every mode, packed bits, clipping ---------------------------------------------------

@pytest.mark.parametrize("mode", MODES)
@pytest.mark.parametrize("style", [
    FillStyle.pattern("bricks", anchor="shape"),
    FillStyle.hatch(0.9, spacing=4, cross=True),
])
def test_same_pixels_in_every_mode(mode, style):
    area = disk(13, 9, 8)
    assert painted(style, area, 27, 19, mode=mode) == painted(style, area, 27, 19, mode="L")


@pytest.mark.parametrize("x0, width", [(0, 16), (3, 20), (5, 9), (7, 1), (9, 2)])
def test_packed_bits_outside_the_area_are_kept(x0, width):
    rng = np.random.default_rng(x0)
    image = rng.random((6, width)) < 0.5
    fb = sl.FrameBuffer.from_array(image)
    area = box(x0, 1, x0 + 5, 4)
    area.paint(fb, FillStyle.pattern("checker"), 1)
    expected = reference_image(sl.FrameBuffer.from_array(image), area,
                               lambda x, y: True if pattern_cell(FillStyle.TILES["checker"], x, y) else None)
    np.testing.assert_array_equal(fb.to_array(), expected)
    # the padding bits of each row's last byte are untouched as well
    assert (fb._raster()[0] == sl.FrameBuffer.from_array(expected)._raster()[0]).all()


@pytest.mark.parametrize("bbox, raster", [
    ((-5, -7, 4, 3), (5, 4, 0, 0)),                           # partly outside
    ((6, 2, 40, 40), (4, 6, 6, 2)),
    ((-2**30, -2**30, 2**30, 2**30), (10, 8, 0, 0)),          # huge: clipped to the frame
    ((2.5, 1.2, 4.5, 3.7), (4, 4, 2, 1)),                     # fractions widen outward
])
@pytest.mark.parametrize("kind", ["pattern", "hatch"])
def test_mask_is_the_visible_part_of_the_bbox(bbox, raster, kind):
    style = FillStyle.pattern("dots") if kind == "pattern" else FillStyle.hatch(0.4, spacing=3)
    everything = Area(lambda x, y: np.ones(np.broadcast(x, y).shape, bool), bbox)
    fb = everything.paint(sl.FrameBuffer(10, 8, mode="L"), style)
    assert everything.rasters == [raster]
    w, h, ox, oy = raster
    assert all(ox <= x < ox + w and oy <= y < oy + h for x, y in lit(fb))


@pytest.mark.parametrize("bbox", [(10, 0, 20, 5), (-9, -9, -1, 30), (0, 8, 9, 2**30), (5, 5, 4, 6)])
def test_bbox_outside_draws_nothing(bbox):
    area = Area(lambda x, y: np.ones(np.broadcast(x, y).shape, bool), bbox)
    fb = area.paint(sl.FrameBuffer(10, 8, mode="RGB"), FillStyle.pattern("checker"))
    assert area.rasters == [] and lit(fb) == set()


def test_area_drawing_outside_its_bbox_is_contained():
    """A draw callable that ignores the raster size cannot reach the frame buffer: it
    writes into the mask, which is clipped before anything is stored."""
    area = box(0, 0, 9, 7)
    area.bbox = (2, 2, 5, 5)  # too small on purpose
    got = painted(FillStyle.pattern([[True]]), area, 10, 8)
    assert got == {(x, y) for x in range(2, 6) for y in range(2, 6)}


# -- the style objects ---------------------------------------------------------------------

def test_repr_equality_hash_pickle_immutability():
    styles = [FillStyle.solid(), FillStyle.hollow(), FillStyle.pattern("bricks", anchor="shape"),
              FillStyle.pattern([["red", None]], anchor="shape", reference=(1, 2)),
              FillStyle.hatch(0.5, spacing=6, cross=True, line_width=2.5, background="white")]
    assert [repr(s) for s in styles] == [
        "FillStyle.solid()",
        "FillStyle.hollow()",
        "FillStyle.pattern(<8x8 tile, fill color>, anchor='shape')",
        "FillStyle.pattern(<1x2 tile, 1 colors>, anchor='shape', reference=(1, 2))",
        "FillStyle.hatch(angle=0.5, spacing=6, cross=True, line_width=2.5, background='white', "
        "anchor='origin')",
    ]
    for s in styles:
        assert pickle.loads(pickle.dumps(s)) == s
        with pytest.raises(AttributeError):
            s.kind = "solid"
    assert len(set(styles)) == 5
    assert FillStyle.pattern("bricks") == FillStyle.pattern(FillStyle.TILES["bricks"].tolist())
    assert FillStyle.pattern("bricks") != FillStyle.pattern("grid")
    assert FillStyle("hatch", angle=0.5) == FillStyle.hatch(0.5)
    assert FillStyle() == FillStyle.solid() and FillStyle().kind == "solid"


def test_attributes():
    h = FillStyle.hatch(1.0, spacing=3, line_width=2)
    assert (h.kind, h.angle, h.spacing, h.cross, h.line_width, h.background) == ("hatch", 1.0, 3, False, 2, None)
    p = FillStyle.pattern([[True, None], ["red", False]], anchor="shape")
    assert p.tile.tolist() == [[True, None], [(255, 0, 0, 255), None]]
    assert FillStyle.pattern("checker").tile.tolist() == [[True, False], [False, True]]
    with pytest.raises(AttributeError):
        FillStyle.solid().tile
    with pytest.raises(AttributeError):
        h.tile
    with pytest.raises(AttributeError):
        p.spacing
    with pytest.raises(ValueError):
        p.tile[0, 0] = False


@pytest.mark.parametrize("make, name", [
    (lambda: FillStyle.pattern([]), "tile"),
    (lambda: FillStyle.pattern([[]]), "tile"),
    (lambda: FillStyle.pattern(np.zeros((0, 3), bool)), "tile"),
    (lambda: FillStyle.pattern([True, False]), "tile"),
    (lambda: FillStyle.pattern(np.ones((2, 2, 2, 2), bool)), "tile"),
    (lambda: FillStyle.pattern(np.ones((2, 2, 5), np.uint8)), "tile"),
    (lambda: FillStyle.pattern([[True, False], [True]]), "tile"),
    (lambda: FillStyle.pattern([[False, None]]), "tile"),
    (lambda: FillStyle.pattern([["nocolor"]]), "tile[0][0]"),
    (lambda: FillStyle.pattern([[1, 300]]), "tile[0][1]"),
    (lambda: FillStyle.pattern(np.array([[0.5]])), "tile"),
    (lambda: FillStyle.pattern(np.array([[-1, 2]])), "tile"),
    (lambda: FillStyle.pattern("marble"), "tile"),
    (lambda: FillStyle.pattern(5), "tile"),
    (lambda: FillStyle.pattern("checker", anchor="center"), "anchor"),
    (lambda: FillStyle.pattern("checker", reference=(1, 2)), "reference"),
    (lambda: FillStyle.pattern("checker", anchor="shape", reference=(1,)), "reference"),
    (lambda: FillStyle.pattern("checker", anchor="shape", reference=(1, math.nan)), "reference"),
    (lambda: FillStyle.hatch(spacing=0), "spacing"),
    (lambda: FillStyle.hatch(spacing=-3), "spacing"),
    (lambda: FillStyle.hatch(spacing=math.inf), "spacing"),
    (lambda: FillStyle.hatch(line_width=0), "line_width"),
    (lambda: FillStyle.hatch(angle=math.nan), "angle"),
    (lambda: FillStyle.hatch(angle="45"), "angle"),
    (lambda: FillStyle.hatch(cross="yes"), "cross"),
    (lambda: FillStyle.hatch(background="nocolor"), "background"),
    (lambda: FillStyle.hatch(anchor="corner"), "anchor"),
    (lambda: FillStyle("dotted"), "kind"),
    (lambda: FillStyle("solid", color="red"), "argument"),
])
def test_bad_arguments_name_the_argument(make, name):
    with pytest.raises((sl.ArgumentValueError, sl.ArgumentTypeError), match=name.replace("[", r"\[")):
        make()


def test_bad_colors_at_paint_time_name_the_cell():
    fb = sl.FrameBuffer(4, 4, mode="1")
    with pytest.raises(sl.ArgumentValueError, match=r"tile\[0\]\[1\]"):
        box(0, 0, 3, 3).paint(fb, FillStyle.pattern([[True, 7]]))
    fb = sl.FrameBuffer(4, 4, mode="P")
    with pytest.raises(sl.ArgumentValueError, match="background"):
        box(0, 0, 3, 3).paint(fb, FillStyle.hatch(background=9))


@HYPOTHESIS
@given(angle=st.floats(allow_nan=True, allow_infinity=True),
       spacing=st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.integers(-5, 50)),
       line_width=st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.integers(-2, 9)))
def test_fuzz_hatch_arguments(angle, spacing, line_width):
    try:
        style = FillStyle.hatch(angle, spacing=spacing, line_width=line_width, cross=True)
    except (sl.ArgumentValueError, sl.ArgumentTypeError):
        assert not (math.isfinite(angle) and math.isfinite(spacing) and spacing > 0
                    and math.isfinite(line_width) and line_width > 0)
        return
    fb = box(-3, -3, 12, 12).paint(sl.FrameBuffer(10, 10, mode="1"), style)
    assert lit(fb) <= {(x, y) for x in range(10) for y in range(10)}


@HYPOTHESIS
@given(x0=st.integers(-2**30, 2**30), y0=st.integers(-2**30, 2**30),
       w=st.integers(0, 2**30), h=st.integers(0, 2**30),
       tile=st.lists(st.lists(st.booleans(), min_size=3, max_size=3), min_size=1, max_size=4))
def test_fuzz_pattern_bbox(x0, y0, w, h, tile):
    if not any(map(any, tile)):
        tile[0][0] = True
    area = Area(lambda x, y: np.ones(np.broadcast(x, y).shape, bool), (x0, y0, x0 + w, y0 + h))
    fb = area.paint(sl.FrameBuffer(13, 11, mode="1"), FillStyle.pattern(tile, anchor="shape"))
    assert all(rw * rh <= 13 * 11 for rw, rh, _, _ in area.rasters)
    expected = {(x, y) for x in range(max(x0, 0), min(x0 + w, 12) + 1)
                for y in range(max(y0, 0), min(y0 + h, 10) + 1) if pattern_cell(tile, x, y, x0, y0)}
    assert lit(fb) == expected


@pytest.mark.parametrize("text, style", [
    ("solid", FillStyle.solid()),
    (" hollow ", FillStyle.hollow()),
    ("pattern:dots", FillStyle.pattern("dots")),
    ("pattern:bricks:shape", FillStyle.pattern("bricks", anchor="shape")),
    ("hatch:90", FillStyle.hatch(math.pi / 2)),
    ("hatch:30:5", FillStyle.hatch(math.radians(30), spacing=5)),
    ("crosshatch:-45:6.5:2", FillStyle.hatch(-math.pi / 4, spacing=6.5, line_width=2, cross=True)),
])
def test_parse(text, style):
    assert FillStyle.parse(text) == style


@pytest.mark.parametrize("text", ["", "dotted", "solid:1", "pattern", "pattern:marble", "pattern:dots:center",
                                  "hatch", "hatch:x", "hatch:45:0", "hatch:nan", "hatch:1:2:3:4",
                                  "crosshatch:45:8:-1"])
def test_parse_bad_text_names_style(text):
    with pytest.raises(sl.ArgumentValueError, match="style="):
        FillStyle.parse(text)
    with pytest.raises(sl.ArgumentTypeError, match="style"):
        FillStyle.parse(45)


# -- with the real area primitives ----------------------------------------------------------

def _primitive(name):
    return getattr(sl.draw, name)


def styled_pixels(draw_shape, style, size=(40, 30), mode="L"):
    fb = sl.FrameBuffer(*size, mode=mode)
    draw_shape(fb, style)
    return lit(fb)


SHAPES = {
    "polygon": lambda fb, style: _primitive("polygon")(
        fb, [(2.3, 1.7), (37.5, 5.2), (20.1, 28.4), (18.0, 12.5), (4.0, 26.0)], color="white",
        style=style),
    "fill_circle": lambda fb, style: _primitive("fill_circle")(fb, 19, 14, 12, color="white", style=style),
    "fill_ellipse": lambda fb, style: _primitive("fill_ellipse")(fb, 19, 14, 17, 9, color="white",
                                                                 style=style),
    "pie": lambda fb, style: _primitive("pie")(fb, 19, 14, 15, 11, 0.3, 4.0, color="white", style=style),
}


@pytest.mark.parametrize("shape", sorted(SHAPES))
@pytest.mark.parametrize("mode", MODES)
def test_primitives_styled_pixels_are_the_solid_pixels_that_the_style_selects(shape, mode):
    tile = FillStyle.TILES["bricks"].tolist()
    solid = styled_pixels(SHAPES[shape], None, mode=mode)
    assert solid
    assert styled_pixels(SHAPES[shape], FillStyle.pattern("bricks"), mode=mode) == {
        (x, y) for x, y in solid if pattern_cell(tile, x, y)}
    assert styled_pixels(SHAPES[shape], FillStyle.hatch(0.7, spacing=4, cross=True), mode=mode) == {
        (x, y) for x, y in solid if hatch_pixel(x, y, 0.7, 4, 1, cross=True)}
    assert styled_pixels(SHAPES[shape], FillStyle.solid(), mode=mode) == solid


def test_polygon_pattern_moves_with_the_polygon_only_when_anchored_to_the_shape():
    polygon = _primitive("polygon")
    ring = np.array([(3.5, 2.5), (30.5, 4.5), (16.5, 25.5)])
    for anchor, moves in (("shape", True), ("origin", False)):
        style = FillStyle.pattern([[True, False, False], [False, True, False]], anchor=anchor)
        first, moved = sl.FrameBuffer(48, 40, mode="1"), sl.FrameBuffer(48, 40, mode="1")
        polygon(first, ring, color=1, style=style)
        polygon(moved, ring + (7, 5), color=1, style=style)
        assert (lit(moved) == {(x + 7, y + 5) for x, y in lit(first)}) == moves


def test_polygon_hollow_draws_only_the_boundary():
    polygon = _primitive("polygon")
    ring = [(2, 2), (25, 3), (12, 20)]
    hollow, lines = sl.FrameBuffer(30, 25, mode="1"), sl.FrameBuffer(30, 25, mode="1")
    polygon(hollow, ring, color=1, style=FillStyle.hollow())
    sl.draw.lines(lines, [(2, 2, 25, 3), (25, 3, 12, 20), (12, 20, 2, 2)], color=1)
    assert lit(hollow) == lit(lines)
