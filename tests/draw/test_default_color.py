"""Defaults that do not hide drawings (issue 16, item 7): without a color, every
drawing function draws the frame buffer's foreground, which contrasts with the
background: white on a dark one, black on a light one."""

import numpy as np
import pytest

import scanline as sl

SQUARE = [(2, 2), (13, 2), (13, 9), (2, 9)]

DRAWINGS = {
    "line": lambda fb: sl.draw.line(fb, 1, 1, 14, 10),
    "lines": lambda fb: sl.draw.lines(fb, [[1, 1, 14, 10]]),
    "circle": lambda fb: sl.draw.circle(fb, 8, 6, 4),
    "ellipse": lambda fb: sl.draw.ellipse(fb, 8, 6, 6, 3),
    "polygon": lambda fb: sl.draw.polygon(fb, SQUARE),
    "polygons": lambda fb: sl.draw.polygons(fb, [SQUARE]),
    "polyline": lambda fb: sl.draw.polyline(fb, SQUARE, width=3),
    "fill_circle": lambda fb: sl.draw.fill_circle(fb, 8, 6, 4),
    "pie": lambda fb: sl.draw.pie(fb, 8, 6, 5, 5, 0.0, 2.0),
    "arc": lambda fb: sl.draw.arc(fb, 8, 6, 5, 5, 0.0, 2.0),
    "text": lambda fb: sl.draw.text(fb, 1, 2, "Hi", height=7),
    "antialiased line": lambda fb: sl.draw.line(fb, 1, 5, 14, 5, antialias=True),
    "curve": lambda fb: sl.draw.curve(fb, sl.curves.Bezier([(1, 1), (5, 11), (14, 1)])),
    "context": lambda fb: sl.Context(fb).rectangle(2, 2, 10, 6),
    "display file": lambda fb: _display_file().draw(fb),
}


def _display_file():
    df = sl.DisplayFile()
    df.set_viewing(window=(0, 0, 16, 12), viewport=(0, 0, 1, 1))
    df.create_segment("s")
    df.polyline([(1, 1), (14, 10)])
    df.close_segment()
    return df


@pytest.mark.parametrize("mode", ["1", "L", "RGB", "RGBA", "P"])
@pytest.mark.parametrize("background, drawn", [("black", "white"), ("white", "black"),
                                               ("#c0c0c0", "black"), ("navy", "white")])
@pytest.mark.parametrize("name", sorted(DRAWINGS))
def test_default_color_contrasts_with_the_background(name, mode, background, drawn):
    fb = sl.FrameBuffer(16, 12, mode=mode, background=background)
    assert fb.foreground == drawn
    DRAWINGS[name](fb)
    reference = sl.FrameBuffer(1, 1, mode=mode, background=drawn)
    want = np.asarray(reference)[0, 0]
    if mode == "P":
        got = fb.color_table[np.asarray(fb)]
        want = reference.color_table[want]
    else:
        got = np.asarray(fb)
    lit = (got == want).all(axis=-1) if got.ndim == 3 else got == want
    assert lit.sum() >= 3, f"{name} drew nothing visible on {background}"


def test_explicit_colors_are_unchanged():
    fb = sl.FrameBuffer(8, 2, background="white")
    sl.draw.line(fb, 0, 0, 7, 0, color="white")       # asked for: drawn, even if invisible
    assert (np.asarray(fb) == 255).all()


def test_boundary_fill_stops_at_the_default_outline():
    fb = sl.FrameBuffer(12, 12, mode="L", background=255)
    sl.draw.polygon(fb, [(1, 1), (10, 1), (10, 10), (1, 10)], style=sl.FillStyle.hollow())
    filled = sl.draw.boundary_fill(fb, 5, 5, color=100)      # boundary: the foreground
    assert filled == 8 * 8 and fb.get_pixel(0, 0) == 255


def test_vector_and_svg_devices_resolve_the_default():
    df = _display_file()
    vector = sl.display.VectorDevice(16, 12)
    sl.display.interpret(df, vector)
    svg = sl.display.SVGDevice(16, 12)
    sl.display.interpret(df, svg)
    assert 'stroke="rgb(0,0,0)"' in svg.svg()
    on_black = sl.display.SVGDevice(16, 12, background="black")
    sl.display.interpret(df, on_black)
    assert 'stroke="rgb(255,255,255)"' in on_black.svg()
