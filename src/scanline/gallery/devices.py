"""
Display devices
===============

Demo figures for display devices and three-dimensional display methods (Hearn &
Baker, sections 2-1 and 9-1; the notes' chapter 1): the shadow mask's phosphor
triads close up, delta and in-line, converged and not; the beam-penetration
screen's four colors; the direct-view storage tube's erase and redraw; the plasma
panel and the LCD refreshing; a cutaway view with its cuts capped.  The screens are
those of :mod:`scanline.display.color_crt`, :mod:`~scanline.display.storage_tube`
and :mod:`~scanline.display.flat_panel`; labels are Pillow text."""

import math

import numpy as np
from PIL import Image, ImageDraw

import scanline as sl
from scanline.display.color_crt import (PENETRATION_COLORS, PENETRATION_VOLTAGES,
                                        ShadowMask, penetration_colors)
from scanline.display.flat_panel import LCD, PlasmaPanel
from scanline.display.storage_tube import StorageTube

from scanline.gallery._plot import enlarge, font, side_by_side, stacked
from scanline.gallery.primitives import PAPER, Figure


def _bars(width=12, height=6):
    """Bars of white, yellow, cyan and magenta on black (image order)."""
    a = np.zeros((height, width, 3), np.uint8)
    for k, color in enumerate([(255, 255, 255), (255, 255, 0), (0, 255, 255), (255, 0, 255)]):
        a[1:height - 1, 1 + 3 * k:3 + 3 * k] = color
    return sl.FrameBuffer.from_array(a)


def figure_shadow_mask():
    """Phosphor triads of a shadow-mask tube, delta and in-line, converged and not."""
    fb = _bars()
    panels, titles, rows = [], [], []
    for arrangement in ("delta", "in-line"):
        for m in (0.0, 0.5):
            tube = ShadowMask(fb, arrangement=arrangement, dots=12, misconvergence=m,
                              persistence=1e3)
            panels.append(enlarge(Image.fromarray(tube.screen(tube.period * 0.999)), 2))
            titles.append(f"{arrangement}, " + ("converged" if m == 0 else f"red/blue off {m} px"))
        c = tube.triad_centers()
        rows.append(f"{arrangement:8s} dot centers in a 12 x 12 cell: " + ", ".join(
            f"{n} ({x:.1f}, {y:.1f})" for n, (x, y) in zip(("R", "G", "B"), c)))
    image = stacked([side_by_side(panels[:2], titles[:2]), side_by_side(panels[2:], titles[2:])])
    return Figure(
        "devices-shadow-mask", "Shadow-mask triads, delta and in-line",
        "Bars of white, yellow, cyan and magenta on a shadow-mask color CRT, each pixel a "
        "triad of red, green and blue phosphor dots (12 x 12 screen pixels), each dot lit "
        "by its own gun: white with all three, yellow with red and green, cyan with green "
        "and blue, magenta with red and blue. Top: the delta-delta arrangement (a dot "
        "triangle); bottom: in-line (the dots along the scan line). Right: the red beam "
        "lands half a pixel left and the blue half a pixel right (misconvergence): red "
        "fringes on the left edges, blue on the right.", "Hearn & Baker, section 2-1; "
        "notes chapter 1, Q.5", image, "\n".join(rows))


def _hues(width=240, height=60):
    """A strip of hues (left to right) and values (bright at the top)."""
    h = np.linspace(0, 1, width, endpoint=False)[None, :].repeat(height, axis=0)
    value = np.linspace(1, 0.15, height)[:, None].repeat(width, axis=1)
    hsv = np.stack([h, np.ones_like(h), value], axis=-1)
    rgb = sl.color.convert(hsv.reshape(-1, 3), "hsv", "rgb").reshape(height, width, 3)
    return sl.FrameBuffer.from_array(np.clip(np.rint(rgb * 255), 0, 255).astype(np.uint8))


def figure_beam_penetration():
    """The four colors of a beam-penetration screen, and a picture quantized to them."""
    strip = _hues()
    swatches = Image.new("RGB", (360, 76), PAPER)
    draw = ImageDraw.Draw(swatches)
    for k, (name, rgb) in enumerate(PENETRATION_COLORS.items()):
        draw.rectangle((k * 90 + 8, 4, k * 90 + 82, 36), fill=rgb)
        draw.text((k * 90 + 45, 48), name, fill="black", font=font(12), anchor="mm")
        draw.text((k * 90 + 45, 66), f"{PENETRATION_VOLTAGES[name]:.0f} kV", fill="black",
                  font=font(12), anchor="mm")
    image = stacked([side_by_side([enlarge(strip.to_pil(), 1),
                                   enlarge(penetration_colors(strip).to_pil(), 1)],
                                  ["any color", "as the beam-penetration screen shows it"]),
                     swatches])
    return Figure(
        "devices-beam-penetration", "Beam penetration: four colors",
        "A red outer and a green inner phosphor layer: slow electrons excite only the red "
        "layer, very fast ones reach only the green, intermediate speeds light both "
        "(orange, yellow). The accelerating voltage picks one of the four colors (the "
        "voltages are illustrative); every other color goes to the nearest of them, or "
        "the beam stays off (sl.display.color_crt.penetration_colors): blues and purples "
        "are lost.", "Hearn & Baker, section 2-1; notes chapter 1, Q.5", image,
        "\n".join(f"{n:7s} {PENETRATION_VOLTAGES[n]:4.1f} kV  RGB {c}"
                  for n, c in PENETRATION_COLORS.items()))


def _scene():
    df = sl.DisplayFile()
    df.set_viewing(window=(0, 0, 100, 100))
    df.create_segment("house")
    df.polyline([(15, 10), (55, 10), (55, 45), (35, 65), (15, 45), (15, 10)])
    df.polyline([(30, 10), (30, 30), (40, 30), (40, 10)])
    df.close_segment()
    df.create_segment("sun")
    df.circle((78, 75), 12)
    df.close_segment()
    return df


def figure_storage_tube():
    """A storage tube removing a segment: write, hold, erase all, write again."""
    tube = StorageTube(_scene(), 120, 120, writing_speed=2e4, settle_time=0.0, hold=0.1,
                       remove="sun", erase_time=0.1)
    moments = [("writing", 0.5), ("holding", 0.5), ("erasing", 0.3), ("holding", 0.5)]
    panels, titles = [], []
    seen = {}
    for name, f in moments:
        k = [i for i, p in enumerate(tube.phases) if p[0] == name][seen.get(name, 0)]
        seen[name] = seen.get(name, 0) + 1
        _, a, b = tube.phases[k]
        panels.append(enlarge(Image.fromarray(tube.screen(a + f * (b - a))), 2))
        titles.append(f"{name} ({1e3 * (a + f * (b - a)):.0f} ms)")
    return Figure(
        "devices-storage-tube", "A direct-view storage tube",
        "The primary gun writes the picture once; the flood gun keeps the stored pattern "
        "glowing, with no refresh and no fading. To take the sun away the tube cannot "
        "erase it alone (StorageTube.erase_segment raises SelectiveEraseError): it erases "
        "the whole screen, a bright flash, and writes the house again.",
        "Hearn & Baker, section 2-1; notes chapter 1 (quiz 5)", side_by_side(panels, titles),
        "\n".join(f"{n:10s} {1e3 * a:7.1f} - {1e3 * b:7.1f} ms" for n, a, b in tube.phases))


def figure_flat_panels():
    """A plasma panel and an LCD in the middle of a refresh."""
    a = np.zeros((24, 32, 3), np.uint8)
    a[4:20, 4:14] = 255
    a[8:16, 18:28] = (255, 200, 60)
    fb = sl.FrameBuffer.from_array(a)
    plasma = PlasmaPanel(fb, persistence=0.006, dots=6)
    t = plasma.hits[13, 20] + 1e-7
    p_img = Image.fromarray(plasma.image(t, beam=False))
    row, col = plasma.conductors(t)
    draw = ImageDraw.Draw(p_img)
    d = plasma.dots
    draw.line((0, row * d + d // 2, p_img.width, row * d + d // 2), fill="white")
    draw.line((col * d + d // 2, 0, col * d + d // 2, p_img.height), fill="white")
    lcd = LCD(fb, refresh_rate=60, response_time=0.0015, dots=6)
    t2 = 14.5 * lcd.line_time
    l_img = Image.fromarray(lcd.image(t2, beam=False))
    ImageDraw.Draw(l_img).rectangle((0, 14 * d, 3, 15 * d - 2), fill="white")
    image = side_by_side([p_img, l_img], [f"plasma: conductors {row}, {col} fired",
                                          "active-matrix LCD: row 14 selected"])
    return Figure(
        "devices-flat-panels", "Plasma panel and LCD",
        "Left: a plasma panel fires the cell at the intersection of one horizontal and "
        "one vertical conductor at a time (white lines), row by row; fired cells glow "
        "neon orange and fade until their next refresh. Right: an active-matrix LCD "
        "selects one row at a time (white mark) and every column writes that row at once; "
        "the rows above hold their new values (a transistor per cell), the rows selected "
        "last are still turning (the liquid crystal's response time, 1.5 ms), the rows "
        "below still show the previous picture (black).", "Hearn & Baker, section 2-1", image,
        f"plasma: {plasma.cell_time * 1e6:.2f} us per intersection, {plasma.on.sum()} cells on; "
        f"LCD: {lcd.line_time * 1e3:.3f} ms per row")


def _shell():
    """A hollow box: the outer cube and the inner one facing inward, one closed mesh."""
    outer = sl.mesh.cube(3.0)
    inner = sl.mesh.cube(2.5)
    inward = sl.mesh.Mesh(inner.vertices, inner.faces[:, ::-1])
    return sl.mesh.merge([outer, inward])


def figure_cutaway():
    """A hollow box holding a sphere and a ring, cut open with the cuts capped."""
    shell = _shell().colored("lightsteelblue")
    ball = sl.mesh.sphere(0.6, center=(0.4, -0.35, 0.0), resolution=(24, 12)).colored("tomato")
    ring = sl.mesh.torus(0.45, 0.15, center=(-0.55, 0.55, 0.2),
                         resolution=(24, 10)).colored("gold")
    cam = sl.Camera(eye=(3.5, 3.0, 6.5), target=(0, 0, 0),
                    projection=sl.projection.perspective(fov=math.radians(36), near=1))
    lights = [sl.lighting.AmbientLight(0.35), sl.lighting.DirectionalLight((-0.4, -0.6, -0.7), 0.8)]
    size = (260, 240)
    whole = sl.FrameBuffer(*size, background=PAPER)
    sl.render(whole, [shell, ball, ring], cam, shading="flat", lights=lights)
    plane = (0, 0, -1, 0.25)                                # keep z <= 0.25
    cuts = [sl.draw3d.cutaway(m, plane, cap_color=c) for m, c in
            ((shell, "slategray"), (ball, "darkred"), (ring, "darkgoldenrod"))]
    opened = sl.FrameBuffer(*size, background=PAPER)
    sl.render(opened, [m for cut in cuts for m in cut.drawable()], cam, shading="flat",
              lights=lights)
    closed = all(set(cut.closed[0].edge_faces()[1].tolist()) == {2} for cut in cuts)
    return Figure(
        "devices-cutaway", "A cutaway view",
        "A hollow box holding a ball and a ring (left), cut by the plane z = 0.25 with "
        "sl.draw3d.cutaway (right): the part in front of the plane is removed and each "
        "cut is capped (in a darker color) with a polygon computed from the plane's intersection loops; "
        "the box's cap is a square ring (an outer loop and a hole). Rendered by the "
        "z-buffer with flat shading.", "Hearn & Baker, section 9-1 (cutaway views)",
        side_by_side([whole.to_pil(), opened.to_pil()], ["whole", "cut away"]),
        "\n".join(f"{name:6s} {len(cut.loops[0])} intersection loop(s)" for name, cut in
                  zip(("box", "ball", "ring"), cuts)) +
        f"\nclipped and capped meshes closed (every edge on two faces): {closed}")


FIGURES = (figure_shadow_mask, figure_beam_penetration, figure_storage_tube, figure_flat_panels,
           figure_cutaway)


if __name__ == "__main__":
    from scanline.gallery import main

    main(FIGURES)
