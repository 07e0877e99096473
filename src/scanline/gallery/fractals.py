"""
Fractals
========

Demo figures for fractal-geometry methods (Hearn & Baker, sections 10-18 and
10-19): the Mandelbrot and a Julia set colored through a color table, self-similar
curves with their box-counting dimensions, Barnsley's fern and an L-system plant,
and midpoint-displacement terrain at two roughnesses."""

import math

import numpy as np

import scanline as sl

from scanline.gallery._plot import side_by_side
from scanline.gallery.primitives import PAPER, PIXEL, Figure

TERRAIN_COLORS = np.array([(40, 80, 160), (70, 130, 60), (120, 150, 70), (140, 110, 80),
                           (245, 245, 245)], np.float64)


def fit(points, width, height, margin=8):
    """``points`` (N, 2) scaled uniformly and centered into a width x height frame
    buffer's device coordinates, and the scale and offset used."""
    p = np.asarray(points, np.float64)
    lo, hi = p.min(axis=0), p.max(axis=0)
    scale = min((width - 2 * margin) / max(hi[0] - lo[0], 1e-12),
                (height - 2 * margin) / max(hi[1] - lo[1], 1e-12))
    offset = np.array([width, height]) / 2 - (lo + hi) / 2 * scale
    return p * scale + offset, scale, offset


def escape_time_panels(width=360, height=240):
    """The Mandelbrot set and the Julia set of c = -0.8 + 0.156i, each colored through
    the default color table (mode-"P" frame buffers)."""
    m = sl.fractals.mandelbrot(width, height, center=(-0.6, 0.0), span=3.2, max_iterations=128)
    j = sl.fractals.julia(width, height, c=complex(-0.8, 0.156), span=3.4, max_iterations=128)
    return [sl.fractals.colorize(m, 128).to_pil(), sl.fractals.colorize(j, 128, cycle=True).to_pil()]


def figure_escape_time():
    """The Mandelbrot set and a Julia set."""
    return Figure(
        "fractal-mandelbrot-julia", "Self-squaring fractals: Mandelbrot and Julia sets",
        "Left: z -> z² + c from z = 0 for the c at each pixel center; right: the same map from "
        "z = the pixel with c = -0.8 + 0.156i. A pixel's color is its iteration count until "
        "|z| > 2 through a 64-entry color table (black: no escape within 128 iterations; the "
        "Julia set's table cycles). Compiled kernel, rows in parallel.",
        "Hearn & Baker, section 10-18", side_by_side(escape_time_panels(),
                                                     ["Mandelbrot set", "Julia set"]), None)


def curve_panels(size=240):
    """Koch's snowflake, Heighway's dragon and Hilbert's curve drawn as polylines:
    [(title, Pillow image)]; Koch's with its box-counting dimension."""
    koch_dimension = sl.fractals.dimension(sl.fractals.koch(7))
    curves = [(f"Koch snowflake, D = {koch_dimension:.3f}", sl.fractals.koch(5, closed=True)),
              ("Heighway dragon, 12 steps", sl.fractals.dragon(12)),
              ("Hilbert curve, order 5", sl.fractals.hilbert(5))]
    out = []
    for title, points in curves:
        fb = sl.FrameBuffer(size, size, background=PAPER)
        xy, _, _ = fit(points, size, size)
        sl.draw.polyline(fb, xy, color=PIXEL)
        out.append((title, fb.to_pil()))
    return out


def figure_fractal_curves():
    """Self-similar curves and their dimensions."""
    panels = curve_panels()
    return Figure(
        "fractal-curves", "Self-similar curves from generators and grammars",
        "Koch's snowflake: each segment replaced by the four-segment generator, 5 steps; D "
        "is the box-counting dimension of the curve after 7 steps (log 4 / log 3 = 1.262). "
        "Heighway's dragon: a right-angled generator laid left and right alternately, 12 "
        "steps. Hilbert's curve from its L-system. The last two have similarity dimension 2 "
        "(two halves of scale 1 / sqrt 2; four quarters of scale 1 / 2): in the limit they "
        "fill regions of the plane.",
        "Hearn & Baker, sections 10-18 and 10-19",
        side_by_side([p for _, p in panels], [t for t, _ in panels], gap=16), None)


def nature_panels(size=260):
    """Barnsley's fern by the chaos game and the bracketed L-system plant."""
    fb = sl.FrameBuffer(size, size, background=PAPER)
    points = sl.fractals.fern(60_000, seed=1)
    xy, _, _ = fit(points, size, size, margin=6)
    sl.draw.points(fb, xy, color="#2e7d32")
    plant = sl.FrameBuffer(size, size, background=PAPER)
    branches = sl.fractals.plant(5)
    xy, scale, offset = fit(np.vstack(branches), size, size, margin=6)
    sl.draw.polylines(plant, [b * scale + offset for b in branches], color="#5d4037")
    return [fb.to_pil(), plant.to_pil()]


def figure_fern_and_plant():
    """An IFS fern and an L-system plant."""
    return Figure(
        "fractal-fern-plant", "Affine fractals and shape grammars",
        "Left: Barnsley's fern, 60,000 points of the chaos game with four affine maps chosen "
        "with probabilities 0.01, 0.85, 0.07, 0.07 (seeded). Right: the bracketed L-system "
        "X -> F+[[X]-X]-F[-FX]+X, F -> FF after 5 rewriting steps, read by a turtle turning "
        "25 degrees ([ and ] start and end a branch).",
        "Hearn & Baker, sections 10-18 and 10-19; Barnsley 1988; Prusinkiewicz & "
        "Lindenmayer 1990", side_by_side(nature_panels(), ["IFS fern", "L-system plant"]),
        None)


def terrain_image(H, width=300, height=220, levels=6, seed=7):
    """A midpoint-displacement terrain of roughness ``H``, colored by elevation and
    Gouraud-shaded."""
    z = sl.fractals.midpoint_displacement(levels, H, seed=seed)
    z = (z - z.mean()) / z.std()
    mesh = sl.fractals.height_field(np.maximum(z, -0.6), size=2.0, height=0.22)
    heights = mesh.vertices[:, 2] / 0.22
    t = np.clip((heights + 0.6) / 2.6, 0, 1) * (len(TERRAIN_COLORS) - 1)
    k = np.minimum(t.astype(int), len(TERRAIN_COLORS) - 2)
    f = (t - k)[:, None]
    colors = TERRAIN_COLORS[k] * (1 - f) + TERRAIN_COLORS[k + 1] * f
    colors[heights <= -0.6 + 1e-9] = TERRAIN_COLORS[0]
    mesh = sl.mesh.Mesh(mesh.vertices - (1, 1, 0), mesh.faces,
                        colors=np.floor(colors + 0.5).astype(np.uint8), color_on="vertex")
    fb = sl.FrameBuffer(width, height, background="#dfe8f2")
    cam = sl.Camera(eye=(2.1, -2.0, 1.5), target=(0, 0, 0.05), up=(0, 0, 1),
                    projection=sl.projection.perspective(fov=math.radians(40), near=0.5))
    sl.render(fb, mesh, cam, lights=[sl.lighting.AmbientLight(0.35),
                                     sl.lighting.DirectionalLight((-0.6, 0.5, -0.7), 0.8)])
    return fb.to_pil()


def figure_terrain():
    """Fractal terrain at two roughnesses."""
    return Figure(
        "fractal-terrain", "Random midpoint displacement: terrain and the roughness H",
        "A 65 x 65 height field by random midpoint displacement (diamond-square steps, the "
        "displacement's standard deviation shrinking by 2^(-H/2) per step; same seed), "
        "colored by elevation with the low ground flooded. H = 0.35: jagged; H = 0.85: smooth "
        "hills. The increments have variance proportional to d^(2H), as fractional Brownian "
        "motion does.", "Hearn & Baker, section 10-18; Fournier, Fussell & Carpenter 1982",
        side_by_side([terrain_image(0.35), terrain_image(0.85)], ["H = 0.35", "H = 0.85"]),
        None)


FIGURES = (figure_escape_time, figure_fractal_curves, figure_fern_and_plant, figure_terrain)


if __name__ == "__main__":
    from scanline.gallery import main

    main(FIGURES)
