"""Immediate-mode drawing with a current transformation, attributes and clip window.

A :class:`Context` keeps the *state* that the functional layer takes as arguments:
the current transformation matrix (CTM), the current line, fill and text attributes
and the clip window; each drawing call maps its geometry through the CTM, clips it
and draws it at once (nothing is retained: see :class:`scanline.DisplayFile` for a
retained picture).  ``save()`` / ``restore()`` (or ``with ctx:``) keep and bring back
the whole state.
"""

import numpy as np

from . import _validate as v
from . import transform as tf
from .display import pipeline
from .display import primitives as p
from .display.devices import RasterDevice
from .display.interpreter import draw_primitive
from .clip.window import rectangle
from .errors import ArgumentValueError
from .framebuffer import FrameBuffer

#: A clip window that the CTM maps to less device area than this (square pixels) is
#: an empty clip region: it holds no pixel center.
MIN_CLIP_AREA = 1e-9


class _State:
    """The current state; attribute values (LineStyle, FillStyle, colors, the clip
    region) are never changed in place, so a copy of the dicts is a full copy."""

    __slots__ = ("ctm", "line", "fill", "text", "clip")

    def copy(self):
        new = _State()
        new.ctm = self.ctm.copy()
        new.line, new.fill, new.text = dict(self.line), dict(self.fill), dict(self.text)
        new.clip = self.clip
        return new


class Context:
    """Draw on a frame buffer (or a display device) with a current state.

    Parameters
    ----------
    target : FrameBuffer or device
        A :class:`~scanline.FrameBuffer`, or a :class:`scanline.display.VectorDevice`
        / :class:`~scanline.display.SVGDevice` (anything with ``width``, ``height``,
        ``stroke`` and ``fill``).
    antialias : bool
        With a frame buffer: draw strokes and solid areas antialiased.

    Attributes
    ----------
    matrix : ndarray, shape (3, 3)
        The CTM, user coordinates -> device coordinates.  ``translate``, ``rotate``,
        ``scale``, ``reflect``, ``shear`` and ``transform`` compose a matrix onto it
        from the right (CTM := CTM · M), so the transformation named *last* is
        applied to the geometry *first*, as in PostScript and Cairo.

    Notes
    -----
    The notes' chapter 3 transforms each object by its own matrix (Q.1, Q.2); a
    current transformation that later calls inherit is the "transformation routines"
    of the syllabus, as in GKS's segment and normalization transformations and
    PostScript's CTM.  Clipping uses :mod:`scanline.clip`: Liang-Barsky (Cyrus-Beck
    when the CTM turns the clip window) for lines and Sutherland-Hodgman for areas.

    Examples
    --------
    >>> import math
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(9, 5, mode="1")
    >>> ctx = sl.Context(fb)
    >>> with ctx:
    ...     ctx.translate(4, 0)
    ...     ctx.rotate(math.pi / 2)        # applied first: (0, 0)-(4, 0) turns upright
    ...     ctx.line(0, 0, 4, 0)
    >>> ctx.line(0, 0, 2, 0)               # the CTM is the identity again
    >>> print(sl.text_image(fb))
    ----#----
    ----#----
    ----#----
    ----#----
    ###-#----
    """

    def __init__(self, target, antialias=False):
        if isinstance(target, FrameBuffer):
            target = RasterDevice(target, antialias)
        self._device = target
        for attr in ("width", "height", "stroke", "fill"):
            if not hasattr(self._device, attr):
                raise ArgumentValueError(
                    f"target must be a FrameBuffer or a display device, got "
                    f"{type(target).__name__}, which has no {attr!r}"
                )
        s = _State()
        s.ctm = np.eye(3)
        s.line = p.line_attributes()
        s.fill = {"color": None, "rule": "even-odd", "style": None, "edge": None}
        s.text = {"color": None, "font": "stroke", "height": 10.0, "angle": 0.0,
                  "align": ("left", "base"), "expansion": 1.0, "spacing": 0.0,
                  "path": "right", "clip": "stroke"}
        s.clip = (-0.5, -0.5, self._device.width - 0.5, self._device.height - 0.5)
        self._state = s
        self._stack = []

    # -- state stack ------------------------------------------------------------------------
    def save(self):
        """Push a copy of the whole state (CTM, attributes, clip window)."""
        self._stack.append(self._state.copy())

    def restore(self):
        """Pop the state pushed by the matching :meth:`save`."""
        if not self._stack:
            raise ArgumentValueError("restore() without a matching save(): the stack is empty")
        self._state = self._stack.pop()

    def __enter__(self):
        self.save()
        return self

    def __exit__(self, *exc):
        self.restore()
        return False

    @property
    def depth(self):
        """How many states :meth:`save` has pushed."""
        return len(self._stack)

    # -- current transformation -------------------------------------------------------------
    @property
    def matrix(self):
        return self._state.ctm.copy()

    @matrix.setter
    def matrix(self, m):
        m = tf.compose(m)
        tf.apply(m, (0.0, 0.0))  # refuses a non-affine matrix, saying why
        self._state.ctm = m

    def identity(self):
        """Reset the CTM to the identity (device coordinates)."""
        self._state.ctm = np.eye(3)

    def transform(self, m):
        """Compose ``m`` onto the CTM: CTM := CTM · m (``m`` acts first)."""
        t = tf.compose(m)
        tf.apply(t, (0.0, 0.0))
        with np.errstate(all="ignore"):
            ctm = self._state.ctm @ t
        if not np.isfinite(ctm).all():
            raise ArgumentValueError(
                f"the transformation overflows the CTM (CTM {self._state.ctm.tolist()} "
                f"times {t.tolist()}); use smaller factors or distances")
        self._state.ctm = ctm

    def translate(self, tx, ty):
        """CTM := CTM · T(tx, ty)."""
        self.transform(tf.translation(tx, ty))

    def rotate(self, angle, pivot=None):
        """CTM := CTM · R(angle) (about ``pivot``, in user coordinates)."""
        self.transform(tf.rotation(angle, pivot))

    def scale(self, sx, sy=None, fixed=None):
        """CTM := CTM · S(sx, sy) (about ``fixed``)."""
        self.transform(tf.scaling(sx, sy, fixed))

    def reflect(self, axis):
        """CTM := CTM · reflection(axis)."""
        self.transform(tf.reflection(axis))

    def shear(self, shx=0.0, shy=0.0, reference=None):
        """CTM := CTM · shear(shx, shy, reference)."""
        self.transform(tf.shear(shx, shy, reference))

    # -- attributes ---------------------------------------------------------------------------
    def set_line(self, **attributes):
        """Change line attributes: ``color``, ``width``, ``cap``, ``join``,
        ``miter_limit``, ``dash`` (``"solid"`` for none), ``dash_phase`` (those of
        ``sl.draw.polyline``)."""
        line = dict(self._state.line)
        if "color" in attributes:
            line["color"] = p.color("color", attributes.pop("color"))
        if "pen" in attributes:
            p.line_attributes(pen=attributes["pen"])  # refused, saying why
        line["style"] = line["style"].replace(**attributes)
        self._state.line = line

    def set_fill(self, color=None, style=None, rule=None, edge=None):
        """Change fill attributes: ``color``, ``style`` (FillStyle or its word),
        ``rule`` and ``edge`` (an outline color, drawn with the line attributes, or
        ``False`` for none)."""
        f = dict(self._state.fill)
        if color is not None:
            f["color"] = p.color("color", color)
        if style is not None:
            f["style"] = p.fill_style("style", style)
        if rule is not None:
            f["rule"] = v.choice("rule", rule, p.RULES)
        if edge is not None:
            f["edge"] = None if edge is False else p.color("edge", edge)
        self._state.fill = f

    def set_text(self, **attributes):
        """Change text attributes: ``color``, ``font``, ``height``, ``angle``,
        ``align``, ``expansion``, ``spacing``, ``path``, ``clip``."""
        t = dict(self._state.text)
        for name, value in attributes.items():
            if name not in t:
                raise ArgumentValueError(
                    f"unknown text attribute {name!r}; use one of {', '.join(t)}")
            t[name] = value
        height, angle = p._positive("height", t.pop("height")), v.angle("angle", t.pop("angle"))
        t["color_"] = t.pop("color")
        t = {**p.text_attributes(**t), "height": height, "angle": angle}
        self._state.text = t

    @property
    def line_attributes(self):
        return dict(self._state.line)

    @property
    def fill_attributes(self):
        return dict(self._state.fill)

    @property
    def text_attributes(self):
        return dict(self._state.text)

    # -- clipping --------------------------------------------------------------------------
    def clip(self, window):
        """Intersect the clip region with ``window`` = (xmin, ymin, xmax, ymax) in
        user coordinates (mapped by the CTM: a rotated CTM gives a turned window)."""
        r = rectangle(window, "window")
        with np.errstate(all="ignore"):
            corners = tf.apply(self._state.ctm, np.array(
                [(r[0], r[1]), (r[2], r[1]), (r[2], r[3]), (r[0], r[3])]))
        if not (np.abs(corners) <= v.COORD_LIMIT).all():
            raise ArgumentValueError(
                f"window={window!r} maps to device coordinates beyond +-{v.COORD_LIMIT} "
                "under the current transformation; use a smaller window")
        x, y = corners[:, 0], corners[:, 1]
        if not abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))) > 2 * MIN_CLIP_AREA:
            # a singular or vanishing CTM: the window covers no device area, so nothing
            # is visible (not a "non-convex window" error from the clippers later)
            self._state.clip = (0.0, 0.0, -1.0, -1.0)
            return
        if np.linalg.det(self._state.ctm[:2, :2]) < 0:
            corners = corners[::-1]  # keep the polygon counterclockwise
        old = self._state.clip
        if isinstance(old, tuple) and _upright(corners):
            new = pipeline.intersect(old, (corners[:, 0].min(), corners[:, 1].min(),
                                           corners[:, 0].max(), corners[:, 1].max()))
        else:
            pieces = pipeline.contours([corners], old)
            new = pieces[0] if pieces else None
        self._state.clip = new if new is not None else (0.0, 0.0, -1.0, -1.0)

    @property
    def clip_region(self):
        """The clip region in device coordinates: a rectangle tuple or a convex
        polygon (M, 2)."""
        c = self._state.clip
        return c if isinstance(c, tuple) else c.copy()

    # -- drawing ------------------------------------------------------------------------------
    def _draw(self, kind, geometry, attributes):
        clip = self._state.clip
        if isinstance(clip, tuple) and not (clip[0] <= clip[2] and clip[1] <= clip[3]):
            return  # empty clip region
        prim = p.Primitive(kind, geometry, attributes, None).transformed(self._state.ctm)
        draw_primitive(prim, clip, self._device)

    def line(self, x0, y0, x1, y1):
        """Stroke the segment (x0, y0)-(x1, y1) with the line attributes."""
        self.polyline([(x0, y0), (x1, y1)])

    def polyline(self, points, closed=False):
        """Stroke a polyline (``closed``: a polygon outline)."""
        pts = p.points("points", points, 1)
        self._draw("polyline", {"points": pts}, {**self._state.line, "closed": bool(closed)})

    def polygon(self, contours):
        """Fill an area (one contour or several) with the fill attributes."""
        cs = p.contours("points", contours)
        self._draw("polygon", {"contours": cs}, self._fill_attributes())

    def rectangle(self, x, y, width, height):
        """Fill the rectangle with corner (x, y) and the given size."""
        x, y = v.number("x", x), v.number("y", y)
        w, h = v.number("width", width), v.number("height", height)
        self.polygon([(x, y), (x + w, y), (x + w, y + h), (x, y + h)])

    def ellipse(self, xc, yc, rx, ry, angle=0.0, fill=False):
        """An ellipse: stroked with the line attributes, or filled (``fill=True``)."""
        c = p.points("center", [(xc, yc)])[0]
        axes = tf.rotation(v.angle("angle", angle))[:2, :2] @ np.diag(
            [p._nonnegative("rx", rx), p._nonnegative("ry", ry)])
        attrs = {**self._fill_attributes(), "fill": True} if fill else {
            **self._state.line, "fill": False, "closed": True}
        self._draw("ellipse", {"center": c, "axes": axes}, attrs)

    def circle(self, xc, yc, r, fill=False):
        """A circle: :meth:`ellipse` with equal semi-axes."""
        self.ellipse(xc, yc, r, r, 0.0, fill)

    def text(self, x, y, string):
        """Draw ``string`` at (x, y) with the text attributes (the CTM scales, turns
        and moves it)."""
        if not isinstance(string, str):
            raise ArgumentValueError(f"string must be a str, got {v._show(string)}")
        t = self._state.text
        geometry = {"anchor": p.points("position", [(x, y)])[0],
                    "frame": p.text_frame(t["height"], t["angle"]), "string": string}
        self._draw("text", geometry, t)

    def markers(self, points, kind="plus", size=7.0):
        """Polymarkers at ``points`` in the line color (``size`` in device units)."""
        pts = p.points("points", points, 1)
        attrs = p.marker_attributes(kind, size, self._state.line["color"])
        self._draw("markers", {"points": pts}, attrs)

    def _fill_attributes(self):
        f = dict(self._state.fill)
        if f["edge"] is not None:
            f["edge"] = {**self._state.line, "color": f["edge"]}
        return f


def _upright(corners):
    """Whether four corners form an axis-aligned rectangle."""
    xs, ys = corners[:, 0], corners[:, 1]
    return (np.isclose(xs[0], xs[3]) and np.isclose(xs[1], xs[2]) and np.isclose(ys[0], ys[1])
            and np.isclose(ys[2], ys[3])) or (np.isclose(ys[0], ys[3]) and np.isclose(
                ys[1], ys[2]) and np.isclose(xs[0], xs[1]) and np.isclose(xs[2], xs[3]))
