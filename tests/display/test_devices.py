"""One display file, two devices: the raster device's pixels and the vector device's
MOVE/LINE commands (and the SVG) must show the same picture."""

import math
import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import scanline as sl
from scanline.display import DisplayFile, RasterDevice, SVGDevice, VectorDevice, interpret
from tests.reference import HYPOTHESIS, peer

W, H = 64, 48


def raster_of(df, width=W, height=H):
    fb = sl.FrameBuffer(width, height, mode="1")
    interpret(df, RasterDevice(fb), highlight="white")
    return fb.to_array().astype(bool)


def replay(segments, width=W, height=H):
    """Rasterize vector LINE commands with the plain line drawer."""
    fb = sl.FrameBuffer(width, height, mode="1")
    sl.draw.lines(fb, segments)
    return fb.to_array().astype(bool)


def world_to_device(points, window, viewport, width=W, height=H):
    """The viewing formulas written out (Hearn & Baker 6-4), then NDC -> pixel centers."""
    p = np.asarray(points, np.float64)
    wx0, wy0, wx1, wy1 = window
    vx0, vy0, vx1, vy1 = viewport
    nx = vx0 + (p[:, 0] - wx0) * (vx1 - vx0) / (wx1 - wx0)
    ny = vy0 + (p[:, 1] - wy0) * (vy1 - vy0) / (wy1 - wy0)
    return np.column_stack([nx * (width - 1), ny * (height - 1)])


coordinate = st.floats(-20, 120, allow_nan=False)
point = st.tuples(coordinate, coordinate)


@HYPOTHESIS
@given(st.lists(st.lists(point, min_size=2, max_size=6), min_size=1, max_size=5),
       st.sampled_from([(0, 0, 100, 100), (10, -5, 60, 80)]),
       st.sampled_from([(0, 0, 1, 1), (0.2, 0.1, 0.9, 0.7)]))
def test_thin_lines_raster_equals_vector_replay(lines, window, viewport):
    df = DisplayFile()
    df.set_viewing(window=window, viewport=viewport)
    df.create_segment("lines")
    for pts in lines:
        df.polyline(pts)
    df.close_segment()
    vector = VectorDevice(W, H)
    interpret(df, vector)
    assert (raster_of(df) == replay(vector.lines())).all()


@HYPOTHESIS
@given(st.lists(st.tuples(st.floats(0, 100), st.floats(0, 100)), min_size=2, max_size=8))
def test_vector_commands_are_the_viewing_formulas(points):
    """An unclipped polyline's commands are the world points through the window-to-
    viewport formulas, computed here independently."""
    window, viewport = (0, 0, 100, 100), (0.1, 0.2, 0.6, 0.9)
    df = DisplayFile()
    df.set_viewing(window=window, viewport=viewport)
    df.create_segment("s")
    df.polyline(points)
    df.close_segment()
    v = VectorDevice(W, H)
    interpret(df, v)
    expected = world_to_device(points, window, viewport)
    got = v.lines()
    assert np.allclose(got[:, :2], expected[:-1], atol=1e-9)
    assert np.allclose(got[:, 2:], expected[1:], atol=1e-9)


@HYPOTHESIS
@given(st.tuples(st.floats(-50, 150), st.floats(-50, 150), st.floats(-50, 150),
                 st.floats(-50, 150)))
def test_clipped_line_matches_shapely(segment):
    """A line clipped to its viewport: the vector device's segment is the shapely
    intersection of the device-space line with the viewport's device rectangle."""
    from shapely.geometry import LineString, box     # a test dependency: no skip

    window, viewport = (0, 0, 100, 100), (0.25, 0.25, 0.75, 0.75)
    df = DisplayFile()
    df.set_viewing(window=window, viewport=viewport)
    df.create_segment("s")
    df.polyline([segment[:2], segment[2:]])
    df.close_segment()
    v = VectorDevice(W, H)
    interpret(df, v)
    ends = world_to_device([segment[:2], segment[2:]], window, viewport)
    from scanline.display.interpreter import CLIP_TOLERANCE as e

    rect = (0.25 * (W - 1) - e, 0.25 * (H - 1) - e, 0.75 * (W - 1) + e, 0.75 * (H - 1) + e)
    if np.allclose(ends[0], ends[1]):
        return  # a point: shapely has no line to intersect
    inter = LineString(ends).intersection(box(*rect))
    got = v.lines()
    if inter.is_empty or inter.geom_type != "LineString":
        assert len(got) == 0 or np.allclose(got[0, :2], got[0, 2:], atol=1e-9)
        return
    assert len(got) == 1
    a = np.array(inter.coords)
    g = got[0].reshape(2, 2)
    assert np.allclose(g, a, atol=1e-9) or np.allclose(g, a[::-1], atol=1e-9)


polygon_point = st.tuples(st.floats(-10, 110), st.floats(-10, 110))


@HYPOTHESIS
@given(st.lists(st.lists(polygon_point, min_size=3, max_size=9), min_size=1, max_size=3),
       st.sampled_from(["even-odd", "nonzero"]),
       st.sampled_from([(0, 0, 1, 1), (0.1, 0.15, 0.8, 0.9)]))
def test_solid_fill_spans_cover_the_raster_fill(contours, rule, viewport):
    """A random-scan display fills an area with one stroke per scan line: replaying
    those strokes sets exactly the pixels of the raster scan-line fill, both rules,
    concave and self-intersecting contours, with holes, clipped to a viewport."""
    df = DisplayFile()
    df.set_viewing(window=(0, 0, 100, 100), viewport=viewport)
    df.create_segment("area")
    df.polygon(contours, rule=rule)
    df.close_segment()
    captured = Capture()
    interpret(df, captured)
    fill = raster_of(df)
    from scanline.display import spans

    runs = np.vstack([np.zeros((0, 4))] + [spans.spans(c, rule) for c in captured.areas])
    assert (replay(runs) == fill).all()
    # and the vector device lists those strokes (then the outline)
    vector = VectorDevice(W, H)
    interpret(df, vector)
    listed = vector.lines()
    assert np.array_equal(listed[:len(runs)], runs)


class Capture:
    """A device that keeps the clipped areas the interpreter sends."""

    width, height = W, H

    def __init__(self):
        self.areas = []

    def fill(self, contours, attributes):
        self.areas.append(contours)

    def stroke(self, pieces, closed, attributes):
        pass


def test_spans_match_the_polygon_fill_on_a_hand_example():
    """A pentagram (self-intersecting): the center is outside under even-odd and
    inside under nonzero, in the spans as in the fill."""
    star = [(16 + 14 * math.cos(math.pi / 2 + k * 4 * math.pi / 5),
             16 + 14 * math.sin(math.pi / 2 + k * 4 * math.pi / 5)) for k in range(5)]
    from scanline.display import spans

    for rule, center in (("even-odd", False), ("nonzero", True)):
        fb = sl.FrameBuffer(33, 33, mode="1")
        sl.draw.polygon(fb, star, rule=rule)
        runs = spans.spans([np.array(star)], rule)
        assert (replay(runs, 33, 33) == fb.to_array().astype(bool)).all()
        assert fb.get_pixel(16, 16) == int(center)


def test_hatch_strokes_lie_inside_and_are_parallel():
    from scanline.display import spans

    square = [np.array([(0, 0), (40, 0), (40, 40), (0, 40)], float)]
    strokes = spans.hatch(square, "even-odd", math.radians(30), 5.0)
    d = strokes[:, 2:] - strokes[:, :2]
    angles = np.degrees(np.arctan2(d[:, 1], d[:, 0])) % 180
    assert np.allclose(angles, 30)
    assert (strokes >= -1e-9).all() and (strokes <= 40 + 1e-9).all()
    # lines of the family x sin(a) - y cos(a) = -k * spacing, 5 apart
    offsets = -(strokes[:, 0] * math.sin(math.radians(30)) - strokes[:, 1] * math.cos(math.radians(30)))
    k = offsets / 5.0
    assert np.allclose(k, np.round(k))
    # the chords of a square hatched at 30 degrees: the total length is the area / spacing
    assert abs(np.hypot(d[:, 0], d[:, 1]).sum() - 1600 / 5) < 40


# -- SVG -----------------------------------------------------------------------------------------
def _svg_paths(text, height):
    """(d, attributes) of every path, coordinates back in device space."""
    root = ET.fromstring(text)
    out = []
    for el in root.iter("{http://www.w3.org/2000/svg}path"):
        rings = []
        for part in re.findall(r"M([^MZ]*)(Z?)", el.get("d")):
            nums = np.array([float(x) for x in re.split(r"[ L]+", part[0].strip())])
            xy = nums.reshape(-1, 2)
            rings.append(np.column_stack([xy[:, 0] - 0.5, height - 0.5 - xy[:, 1]]))
        out.append((rings, el.attrib))
    return out


def scene_file():
    df = DisplayFile()
    df.set_viewing(window=(0, 0, 100, 100))
    df.create_segment("back", priority=0)
    df.polygon([[(10, 10), (90, 15), (60, 90), (20, 70)], [(30, 30), (50, 30), (40, 50)]],
               color="#3060c0", rule="even-odd")
    df.close_segment()
    df.create_segment("front", priority=1)
    df.polygon([(50, 5), (95, 50), (50, 95), (5, 50)], color=(200, 40, 40), rule="nonzero")
    df.circle((50, 50), 20, color="yellow", fill=True)
    df.close_segment()
    return df


def test_svg_fills_rasterize_to_the_raster_device():
    """Parse the SVG back and fill its paths with the scan-line fill: the image equals
    the raster device's."""
    df = scene_file()
    svg = SVGDevice(W, H)
    interpret(df, svg)
    fb = sl.FrameBuffer(W, H)
    for rings, attrs in _svg_paths(svg.svg(), H):
        rule = "even-odd" if attrs.get("fill-rule") == "evenodd" else "nonzero"
        r, g, b = (int(c) for c in re.findall(r"\d+", attrs["fill"]))
        sl.draw.polygon(fb, rings, color=(r, g, b), rule=rule)
    direct = sl.FrameBuffer(W, H)
    df.draw(direct)
    assert (fb.to_array() == direct.to_array()).all()
    assert len({tuple(p) for p in direct.to_array().reshape(-1, 3)}) == 4


def test_svg_is_well_formed_and_escaped():
    df = DisplayFile()
    df.create_segment("s")
    df.polyline([(0, 0), (1, 1)], color="#ff000080", width=3, cap="round", dash=[6, 2])
    df.close_segment()
    svg = SVGDevice(20, 10, background="white")
    interpret(df, svg)
    root = ET.fromstring(svg.svg())
    assert root.get("width") == "20" and root.get("viewBox") == "0 0 20 10"
    path = next(root.iter("{http://www.w3.org/2000/svg}path"))
    assert path.get("stroke") == "rgb(255,0,0)"
    assert float(path.get("stroke-opacity")) == pytest.approx(128 / 255, abs=1e-3)
    assert path.get("stroke-width") == "3" and path.get("stroke-linecap") == "round"
    assert path.get("stroke-dasharray") == "6 2"
    # device (0, 0) is SVG (0.5, 9.5); (19, 9) is (19.5, 0.5)
    assert path.get("d") == "M0.5 9.5 L19.5 0.5"


def test_svg_matches_a_skia_rendering():
    """An independent renderer (Skia's SVG module) draws our SVG; its picture agrees
    with the raster device except along antialiased edges."""
    skia = peer("skia")
    df = scene_file()
    svg = SVGDevice(W, H, background="black")
    interpret(df, svg)
    stream = skia.MemoryStream(svg.svg().encode())
    dom = skia.SVGDOM.MakeFromStream(stream)
    surface = skia.Surface(W, H)
    with surface as canvas:
        dom.render(canvas)
    theirs = surface.makeImageSnapshot().toarray()[:, :, [2, 1, 0]].astype(int)  # BGRA
    fb = sl.FrameBuffer(W, H, background="black")
    df.draw(fb)
    ours = fb.to_array().astype(int)
    close = np.abs(theirs - ours).max(axis=2) <= 8
    # interior pixels: all 8 neighbors have the pixel's color in our image
    padded = np.pad(ours, ((1, 1), (1, 1), (0, 0)), mode="edge")
    interior = np.ones((H, W), bool)
    for dy in (0, 1, 2):
        for dx in (0, 1, 2):
            interior &= (padded[dy:dy + H, dx:dx + W] == ours).all(axis=2)
    assert interior.mean() > 0.7
    assert close[interior].all()
    assert close.mean() > 0.9


def test_listing_text():
    df = DisplayFile()
    df.set_viewing(window=(0, 0, 10, 10))
    df.create_segment("s")
    df.polyline([(0, 0), (10, 0), (10, 10)], color="red")
    df.markers([(5, 5)], kind="plus", size=2, color="blue")
    df.close_segment()
    v = VectorDevice(11, 11)
    interpret(df, v)
    assert v.listing().splitlines() == [
        "; random-scan display file, 11 x 11 device units",
        "COLOR 255 0 0 255", "MOVE 0 0", "LINE 10 0", "LINE 10 10",
        "COLOR 0 0 255 255", "MOVE 4 5", "LINE 6 5", "MOVE 5 4", "LINE 5 6",
    ]


def test_text_vector_strokes_replay_to_the_raster():
    """Stroke-font text: the raster device draws the glyph strokes the vector device
    lists (clipped per stroke at the frame's edge)."""
    df = DisplayFile()
    df.set_viewing(window=(0, 0, W - 1, H - 1))
    df.create_segment("t")
    df.text((3, 20), "Display 42", height=12, clip="stroke")
    df.text((40, 5), "edge", height=10, angle=0.4, clip="stroke")
    df.close_segment()
    v = VectorDevice(W, H)
    interpret(df, v)
    raster = raster_of(df)
    assert raster.sum() > 100
    assert (raster == replay(v.lines())).all()


@pytest.mark.parametrize("mode, expected", [("string", ""), ("character", "Cli"),
                                            ("stroke", "Clip")])
def test_text_clipping_modes(mode, expected):
    """The string straddles the viewport's right edge at its last character."""
    from scanline.display import text as display_text

    df = DisplayFile()
    df.set_viewing(window=(0, 0, 100, 100), viewport=(0, 0, 0.5, 1))
    df.create_segment("t")
    df.text((46, 50), "Clip", height=10, clip=mode)
    df.close_segment()
    prim = df.segment("t").primitives[0]
    from scanline.display.viewing import workstation

    placed = display_text.glyphs(prim.transformed(workstation(W, H)))
    edge = 0.5 * (W - 1)
    assert placed[-2].cell[2] < edge < placed[-1].cell[2]  # the setup: 'p' straddles
    v = VectorDevice(W, H)
    interpret(df, v)
    drawn = v.lines()
    if expected == "":
        assert len(drawn) == 0
        return
    assert drawn[:, [0, 2]].max() <= edge + 1e-9
    # 'character' keeps 'C', 'l', 'i' whole; 'stroke' also keeps the left part of 'p'
    beyond_i = drawn[:, [0, 2]].max() > placed[-1].cell[0] + 1e-9
    assert beyond_i == (mode == "stroke")


def test_vector_device_keeps_what_the_raster_rounds():
    """Erratum E1: the random-scan display follows the line path (its commands keep
    the exact end points), the raster display plots the nearest pixel centers."""
    df = DisplayFile()
    df.set_viewing(window=(0, 0, 10, 10))
    df.create_segment("s")
    df.polyline([(1, 1), (8, 3)])
    df.close_segment()
    v = VectorDevice(W, H)
    interpret(df, v)
    (x0, y0, x1, y1), = v.lines().tolist()
    assert (x0, y0) == pytest.approx((6.3, 4.7)) and (x1, y1) == pytest.approx((50.4, 14.1))
    fb = sl.FrameBuffer(W, H, mode="1")
    df.draw(fb)
    lit = np.argwhere(fb.to_array())
    xs, ys = lit[:, 1], H - 1 - lit[:, 0]
    assert (xs.min(), xs.max()) == (6, 50)       # rounded end points
    assert {(6, 5), (50, 14)} <= set(zip(xs.tolist(), ys.tolist()))


def test_antialiased_raster_device():
    """antialias=True: the same picture with soft edges: intermediate gray levels, and
    about the same amount of ink as the aliased drawing."""
    df = scene_file()
    hard, soft = sl.FrameBuffer(W, H, mode="L"), sl.FrameBuffer(W, H, mode="L")
    df.draw(hard)
    df.draw(soft, antialias=True)
    a, b = hard.to_array().astype(float), soft.to_array().astype(float)
    assert len(np.unique(b)) > len(np.unique(a)) + 10
    assert abs(a.sum() - b.sum()) < 0.03 * a.sum()
    with pytest.raises(sl.ArgumentTypeError, match="antialias"):
        RasterDevice(hard, antialias="yes")


def test_svg_groups_segments_and_escapes_their_names():
    name = 'a <b> & "c" \'d\''
    df = DisplayFile()
    df.create_segment(name)
    df.polyline([(0, 0), (1, 1)])
    df.close_segment()
    df.create_segment("hidden")
    df.polyline([(0, 0), (1, 1)])
    df.close_segment()
    df.set_visibility("hidden", False)
    svg = SVGDevice(10, 10)
    interpret(df, svg)
    root = ET.fromstring(svg.svg())
    groups = root.findall("{http://www.w3.org/2000/svg}g")
    assert [g.get("data-segment") for g in groups] == [name]
    assert groups[0].find("{http://www.w3.org/2000/svg}title").text == name


class OneByOne:
    """A device with only stroke and fill: the interpreter draws every primitive on
    its own through it (no batches)."""

    def __init__(self, device):
        self.device, self.width, self.height = device, device.width, device.height

    def stroke(self, pieces, closed, attributes):
        self.device.stroke(pieces, closed, attributes)

    def fill(self, contours, attributes):
        self.device.fill(contours, attributes)


@HYPOTHESIS
@given(st.lists(st.tuples(st.sampled_from(["line", "closed", "area", "hatched"]),
                          st.lists(polygon_point, min_size=1, max_size=6),
                          st.sampled_from(["white", "red"])), min_size=1, max_size=12),
       st.sampled_from([(0, 0, 1, 1), (0.2, 0.1, 0.7, 0.8)]),
       st.floats(-1, 1))
def test_batches_draw_what_one_by_one_draws(items, viewport, turn):
    """Runs of thin lines and solid areas are drawn in batches; the pixels and the
    vector commands are those of drawing each primitive alone."""
    df = DisplayFile()
    df.set_viewing(window=(0, 0, 100, 100), viewport=viewport)
    df.create_segment("s")
    for kind, pts, color in items:
        if kind in ("line", "closed"):
            df.polyline(pts, color=color, closed=kind == "closed")
        elif len(pts) >= 3:
            df.polygon(pts, color=color, style="hatch:30:3" if kind == "hatched" else None)
    df.close_segment()
    df.set_transformation("s", sl.transform.rotation(turn, pivot=(0.5, 0.5)))
    fb1, fb2 = sl.FrameBuffer(W, H), sl.FrameBuffer(W, H)
    interpret(df, RasterDevice(fb1))
    interpret(df, OneByOne(RasterDevice(fb2)))
    assert (fb1.to_array() == fb2.to_array()).all()
    v1, v2 = VectorDevice(W, H), VectorDevice(W, H)
    interpret(df, v1)
    interpret(df, OneByOne(v2))
    assert np.array_equal(v1.lines(), v2.lines())
