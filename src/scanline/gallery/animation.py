"""
Computer animation
==================

Demo figures for computer animation (notes, chapter 6; Hearn & Baker, chapter 16):
in-between spacing, an eased motion path, morphing, kinematics, dynamics and
color-table animation; and two short GIFs (:data:`ANIMATIONS`)."""

import math

import numpy as np
from PIL import ImageDraw

import scanline as sl

from scanline.gallery._plot import INK, enlarge, font, side_by_side, stacked
from scanline.gallery.primitives import HIGHLIGHT, OCTANT_COLORS, PAPER, PIXEL, SECOND, Figure

PATH_COLOR = "#9aa3b5"


def _label(image, xy, text, size=13, anchor="la"):
    ImageDraw.Draw(image).text(xy, text, fill=INK, font=font(size), anchor=anchor)
    return image


def figure_spacing_laws():
    """The four in-between spacings of Hearn & Baker §16-5 on one time line."""
    n, width, left, row = 9, 520, 170, 34
    fb = sl.FrameBuffer(width, row * 4 + 20, background=PAPER)
    laws = sl.animation.SPACINGS
    for k, law in enumerate(laws):
        y = fb.height - 24 - k * row
        sl.draw.line(fb, left, y, width - 20, y, color=PATH_COLOR)
        times = sl.animation.inbetween_times(0.0, 1.0, n, spacing=law)
        for t, color in ((0.0, "black"), (1.0, "black")):
            x = left + t * (width - 20 - left)
            sl.draw.line(fb, x, y - 9, x, y + 9, color=color, width=3)
        for t in times:
            x = left + t * (width - 20 - left)
            sl.draw.line(fb, x, y - 6, x, y + 6, color=OCTANT_COLORS[k], width=2)
    image = fb.to_pil()
    for k, law in enumerate(laws):
        y_image = fb.height - 1 - (fb.height - 24 - k * row)       # device y up -> image row
        _label(image, (10, y_image), law, anchor="lm")
    return Figure(
        "spacing-laws", "Simulated accelerations: in-between spacing",
        "Nine in-betweens (colored ticks) between two key frames (black) at t = 0 and 1, "
        "spaced by Hearn & Baker's four laws: constant speed t_j = j/(n+1); speeding up "
        "1 - cos(jπ/2(n+1)) (the gaps grow); slowing down sin(jπ/2(n+1)); speeding up then "
        "slowing down (1 - cos(jπ/(n+1)))/2. The same laws are the sine easings "
        "(sl.animation.ease('ease-in-sine', t) ...).",
        "Notes, chapter 6, Q.1; Hearn & Baker §16-5", image,
        "\n".join(f"{law:>22}: " + " ".join(f"{t:.3f}" for t in
                                             sl.animation.inbetween_times(0, 1, n, law))
                  for law in laws))


def _arrow(fb, transform, color):
    """A small arrow shape drawn with a 3x3 transform (facing +x at the origin)."""
    shape = [(-9, -6), (11, 0), (-9, 6), (-4, 0)]
    sl.draw.polygon(fb, sl.transform.apply(transform, shape), color=color)


def figure_motion_path():
    """An eased trip along a Bezier path by arc length, onion-skinned."""
    curve = sl.curves.Bezier([(30, 30), (60, 260), (300, -60), (390, 200)])
    path = sl.animation.MotionPath(curve)
    fb = sl.FrameBuffer(420, 240, background=PAPER)
    sl.draw.polyline(fb, curve.evaluate(np.linspace(0, 1, 300)), color=PATH_COLOR, width=2)
    frames = 13
    times = np.linspace(0, 1, frames)
    s = path.progress(times, 0, 1, "ease-in-out-cubic")
    for k, sk in enumerate(s):
        shade = int(225 - 190 * k / (frames - 1))
        _arrow(fb, path.transform(float(sk)), (shade, shade, 255 if k < frames - 1 else 120))
    plain = sl.FrameBuffer(420, 240, background=PAPER)
    sl.draw.polyline(plain, curve.evaluate(np.linspace(0, 1, 300)), color=PATH_COLOR, width=2)
    for k, u in enumerate(np.linspace(0, 1, frames)):
        x, y = curve.evaluate(u)
        sl.draw.fill_circle(plain, x, y, 4, color=SECOND)
    return Figure(
        "motion-path", "Motion along a path: arc length and easing",
        "Left: the curve's parameter u in 13 equal steps bunches the frames where the "
        "control points pull (green). Right: the same curve as a MotionPath, parameterized by "
        "arc length and eased in and out (ease-in-out-cubic): 13 onion-skinned frames of an "
        "arrow that faces along the tangent; it starts slowly, covers the middle fast and "
        "stops gently.",
        "Notes, chapter 6, Q.4; Hearn & Baker §16-5, §16-6",
        side_by_side([plain.to_pil(), fb.to_pil()], ["equal steps of u", "arc length, eased"]),
        f"path length {path.length:.2f} px; s at the 13 frames: "
        + " ".join(f"{x:.3f}" for x in s))


def figure_morph():
    """Hearn & Baker's triangle to quadrilateral, equalized, with in-betweens."""
    triangle = np.array([(40, 30), (150, 30), (60, 150)], float)
    square = np.array([(40, 30), (150, 30), (150, 140), (40, 140)], float)
    a, b, added, _ = sl.animation.equalize(triangle, square, return_added=True)
    e = sl.animation.equalization(3, 4)
    panels, titles = [], []
    for t in (0.0, 0.25, 0.5, 0.75, 1.0):
        fb = sl.FrameBuffer(190, 180, background=PAPER)
        shape = a + t * (b - a)
        sl.draw.polygon(fb, shape, color="#cfe3f5")
        sl.draw.polyline(fb, np.vstack([shape, shape[:1]]), color=PIXEL, width=2)
        for point, extra in zip(shape, added):
            sl.draw.fill_circle(fb, *point, 5 if extra else 3, color="red" if extra else "black")
        panels.append(fb.to_pil())
        titles.append(f"t = {t:g}")
    return Figure(
        "morph", "Morphing a triangle into a quadrilateral",
        f"The key frames have L_min = 3 and L_max = 4 edges: N_e = 4 mod 3 = {e.n_e} edge of "
        f"the triangle is divided into N_s + 1 = {e.n_s + 1} sections (the longest; the red "
        "vertex is the one added), the others into N_s = 1, so both have four vertices; "
        "then each vertex moves linearly. The vertex form gives the same: N_p = 1 point on "
        "N_ls = 1 section.",
        "Notes, chapter 6, Q.4; Hearn & Baker §16-5 (Fig. 16-9, 16-10)",
        side_by_side(panels, titles, gap=10),
        "triangle equalized: " + "  ".join(f"({x:g}, {y:g})" for x, y in a))


def _face(w, h, mouth, eyes, color):
    fb = sl.FrameBuffer(w, h, background=(235, 240, 250))
    sl.draw.fill_ellipse(fb, w // 2, h // 2, 40, 52, color=color)
    for ex in eyes:
        sl.draw.fill_circle(fb, ex, h // 2 + 16, 6, color="black")
    sl.draw.polyline(fb, mouth, color="black", width=4)
    return fb


def figure_beier_neely():
    """A Beier–Neely morph strip between two drawn faces."""
    w, h = 120, 130
    a = _face(w, h, [(40, 40), (60, 32), (80, 40)], (42, 78), "#f2c08a")
    b = _face(w, h, [(36, 36), (60, 46), (84, 36)], (48, 72), "#a5d6a7")
    lines_a = [[42, 81, 78, 81], [40, 40, 60, 32], [60, 32, 80, 40], [60, 13, 60, 117],
               [20, 65, 100, 65]]
    lines_b = [[48, 81, 72, 81], [36, 36, 60, 46], [60, 46, 84, 36], [60, 13, 60, 117],
               [20, 65, 100, 65]]
    panels = []
    for t in (0.0, 0.25, 0.5, 0.75, 1.0):
        panels.append(enlarge(sl.animation.beier_neely(a, b, lines_a, lines_b, t).to_pil(), 2))
    return Figure(
        "beier-neely", "Beier–Neely feature-based morph",
        "Two faces and five pairs of feature lines (the eyes, the two halves of the mouth, "
        "the vertical and horizontal axes). Each in-between warps both images so their lines meet at the interpolated "
        "lines, then cross-dissolves: the eyes move apart and the mouth turns while the color "
        "fades from one face to the other.",
        "Hearn & Baker §16-5 (morphing); Beier & Neely 1992",
        side_by_side(panels, [f"t = {t:g}" for t in (0, 0.25, 0.5, 0.75, 1)], gap=10), None)


def figure_two_link_arm():
    """A planar two-link arm reaching four targets (one out of reach)."""
    arm = sl.animation.Chain([90.0, 60.0], base=(170, 40))
    targets = [(260, 120), (120, 170), (60, 60), (330, 200)]
    fb = sl.FrameBuffer(360, 230, background=PAPER)
    sl.draw.circle(fb, 170, 40, 150, color="#e4e4e4")
    sl.draw.circle(fb, 170, 40, 30, color="#e4e4e4")
    lines = []
    for k, target in enumerate(targets):
        reach = arm.inverse(target)
        joints = arm.forward(reach)
        color = OCTANT_COLORS[k]
        sl.draw.polyline(fb, joints, color=color, width=5, cap="round", join="round")
        sl.draw.fill_circle(fb, *target, 5, color=color if reach.reached else "red")
        if not reach.reached:
            sl.draw.circle(fb, *target, 9, color="red")
        lines.append(f"target {target}: {'reached' if reach.reached else 'NOT reached'}, "
                     f"angles ({math.degrees(reach.angles[0]):.1f}°, "
                     f"{math.degrees(reach.angles[1]):.1f}°), error {reach.error:.3g}")
    sl.draw.fill_circle(fb, 170, 40, 6, color="black")
    return Figure(
        "two-link-arm", "Inverse kinematics: a two-link arm reaching",
        "Links of 90 and 60 pixels; the gray circles bound what the hand can reach "
        "(radii 150 and 30). For each target the law of cosines gives the elbow-up angles; "
        "the fourth target is out of reach: the arm stretches toward it and the solver reports "
        "it (reached = False) instead of failing.",
        "Hearn & Baker §16-6 (kinematics, goal-directed motion)", fb.to_pil(),
        "\n".join(lines))


def figure_bouncing_ball():
    """Direct motion y = A|sin(ωx + θ0)|e^(−kx) beside a simulated bounce."""
    fb = sl.FrameBuffer(420, 170, background=PAPER)
    sl.draw.line(fb, 10, 20, 410, 20, color="gray", width=2)
    x = np.linspace(0, 400, 600)
    y = sl.animation.bouncing_ball(x, amplitude=130, omega=math.pi / 110, damping=0.006)
    sl.draw.polyline(fb, np.column_stack([x + 10, y + 26]), color=PATH_COLOR, width=2)
    for xk in np.arange(0, 400, 22):
        yk = sl.animation.bouncing_ball(xk, amplitude=130, omega=math.pi / 110, damping=0.006)
        sl.draw.fill_circle(fb, xk + 10, yk + 26, 6, color=HIGHLIGHT)
    sim = sl.FrameBuffer(420, 170, background=PAPER)
    sl.draw.line(sim, 10, 20, 410, 20, color="gray", width=2)
    ball = sl.animation.Particles([(16.0, 150.0)], velocities=[(60.0, 0.0)],
                                  forces=[sl.animation.Gravity((0, -400))],
                                  obstacles=[sl.animation.Plane((0, 26), (0, 1), restitution=0.8)])
    trail = ball.run(6.0, dt=1 / 240)
    sl.draw.polyline(sim, trail[:, 0], color=PATH_COLOR, width=2)
    for p in trail[::36, 0]:
        sl.draw.fill_circle(sim, p[0], p[1], 6, color=PIXEL)
    e = ball.energy()
    return Figure(
        "bouncing-ball", "A bouncing ball: direct motion and dynamics",
        "Left: direct motion specification, y = A |sin(ωx + θ0)| e^(-kx), the arches "
        "shrinking by e^(-kπ/ω). Right: a particle under gravity (F = ma, velocity Verlet) "
        "bouncing on a plane with restitution e = 0.8: each bounce rises to e² = 0.64 of "
        "the one before.",
        "Hearn & Baker §16-6 (eq. 16-6; kinematics and dynamics)",
        stacked([fb.to_pil(), sim.to_pil()], gap=8),
        f"simulated: {ball.steps} steps, {ball.contacts} contacts, energy now "
        f"{e['total']:.1f} (kinetic {e['kinetic']:.1f}, potential {e['potential']:.1f})")


def color_table_demo(steps=8):
    """The ColorTableAnimation of a ball along an arc (shared with the GIF)."""
    cta = sl.raster.ColorTableAnimation(260, 90, steps=steps, color="gold", background="#203040",
                                        method="bit-planes")
    for k in range(steps):
        x = 22 + k * 30
        y = 20 + 50 * math.sin(math.pi * k / (steps - 1))
        cta.draw(k, lambda fb, color, x=x, y=y: sl.draw.fill_circle(fb, x, y, 16, color=color))
    return cta


def figure_color_table_animation():
    """Color-table animation: one drawing, a frame per table."""
    cta = color_table_demo()
    frames = [cta.frame(k).to_pil() for k in (0, 2, 4, 7)]
    tables = "\n".join(f"frame {k}: entries lit " + ", ".join(
        str(i) for i in range(len(cta.table(k))) if tuple(cta.table(k)[i]) == cta.color)
        for k in (0, 1))
    return Figure(
        "color-table-animation", "Color-table animation",
        "The ball was drawn once at each of 8 positions along its path into a mode 'P' frame "
        "buffer, position k in bit k of the index (so overlapping positions keep both). "
        "Frame k changes only the color table: the entries with bit k set are gold, all others "
        "the background. No pixel is rewritten; the table is cycled.",
        "Notes, chapter 6, Q.3; Hearn & Baker §16-3 (Fig. 16-5)",
        side_by_side(frames, ["frame 0", "frame 2", "frame 4", "frame 7"], gap=10), tables)


FIGURES = (figure_spacing_laws, figure_motion_path, figure_morph, figure_beier_neely,
           figure_two_link_arm, figure_bouncing_ball, figure_color_table_animation)


def animation_motion_path():
    """A GIF: the eased arrow along its path."""
    curve = sl.curves.Bezier([(30, 30), (60, 260), (300, -60), (390, 200)])
    path = sl.animation.MotionPath(curve)
    polyline = curve.evaluate(np.linspace(0, 1, 200))
    count = 36

    def frame(i):
        fb = sl.FrameBuffer(420, 240, background=PAPER)
        sl.draw.polyline(fb, polyline, color=PATH_COLOR, width=2)
        s = path.progress(i / (count - 1), 0, 1, "ease-in-out-cubic")
        _arrow(fb, path.transform(s), PIXEL)
        return fb
    return "motion-path", sl.animation.Animation(frame, frames=count, fps=18)


def animation_color_table():
    """A GIF: the color-table animation, cycled."""
    return "color-table-animation", color_table_demo().animation(fps=10)


#: Short GIFs the demo writes beside the figures: functions returning (name, Animation).
ANIMATIONS = (animation_motion_path, animation_color_table)


if __name__ == "__main__":
    from scanline.gallery import main

    main(FIGURES, ANIMATIONS)
