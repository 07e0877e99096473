"""Immediate-mode drawing with a current transformation, attributes and clip window.

A :class:`Context` keeps the *state* that the functional layer takes as arguments:
the current transformation matrix (CTM), the current line, fill and text attributes
and the clip window; each drawing call maps its geometry through the CTM, clips it
and draws it at once (nothing is retained: see :class:`scanline.DisplayFile` for a
retained picture).  ``save()`` / ``restore()`` (or ``with ctx:``) keep and bring back
the whole state.
"""

from typing import TYPE_CHECKING, Any, Literal, Optional, Protocol, Union

import numpy as np
from numpy.typing import NDArray

from . import _validate as v
from . import transform as tf
from .display import pipeline
from .display import primitives as p
from .display.devices import RasterDevice
from .display.interpreter import draw_primitive
from .clip.window import rectangle
from .errors import ArgumentValueError
from .framebuffer import FrameBuffer

if TYPE_CHECKING:
    from ._typing import Angle, Color, Point, Points
    from .attributes import FillStyle


class _Device(Protocol):
    """What a Context draws on besides a frame buffer: a display device (see
    :mod:`scanline.display`)."""

    width: int
    height: int

    def stroke(self, pieces: Any, closed: bool, attributes: dict[str, Any]) -> Any: ...

    def fill(self, contours: Any, attributes: dict[str, Any]) -> Any: ...


#: A clip region: a rectangle (xmin, ymin, xmax, ymax) or a convex polygon (M, 2).
Region = Union[tuple[float, float, float, float], NDArray[np.float64]]

__all__ = ["Context", "MIN_CLIP_AREA"]

#: A clip window that the CTM maps to less device area than this (square pixels) is
#: an empty clip region: it holds no pixel center.
MIN_CLIP_AREA = 1e-9


class _State:
    """The current state; attribute values (LineStyle, FillStyle, colors, the clip
    region) are never changed in place, so a copy of the dicts is a full copy."""

    __slots__ = ("ctm", "line", "fill", "text", "clip")

    ctm: NDArray[np.float64]
    line: dict[str, Any]
    fill: dict[str, Any]
    text: dict[str, Any]
    clip: Region

    def copy(self) -> "_State":
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

    def __init__(self, target: Union[FrameBuffer, _Device], antialias: bool = False) -> None:
        self._device: _Device = (RasterDevice(target, antialias) if isinstance(target, FrameBuffer)
                                else target)
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
        self._stack: list[_State] = []

    # -- state stack ------------------------------------------------------------------------
    def save(self) -> None:
        """Push a copy of the whole state (CTM, attributes, clip window).

        Examples
        --------
        >>> import scanline as sl
        >>> ctx = sl.Context(sl.FrameBuffer(4, 4))
        >>> ctx.save(); ctx.translate(1, 2)
        >>> ctx.depth, ctx.matrix[:2, 2].tolist()
        (1, [1.0, 2.0])
        >>> ctx.restore(); ctx.depth, ctx.matrix[:2, 2].tolist()
        (0, [0.0, 0.0])
        """
        self._stack.append(self._state.copy())

    def restore(self) -> None:
        """Pop the state pushed by the matching :meth:`save`.

        Raises
        ------
        ArgumentValueError
            When nothing was saved.

        Examples
        --------
        >>> import scanline as sl
        >>> ctx = sl.Context(sl.FrameBuffer(4, 4))
        >>> ctx.save(); ctx.set_line(color="red"); ctx.restore()
        >>> ctx.line_attributes["color"] is None
        True
        """
        if not self._stack:
            raise ArgumentValueError("restore() without a matching save(): the stack is empty")
        self._state = self._stack.pop()

    def __enter__(self) -> "Context":
        self.save()
        return self

    def __exit__(self, *exc: object) -> Literal[False]:
        self.restore()
        return False

    @property
    def depth(self) -> int:
        """How many states :meth:`save` has pushed."""
        return len(self._stack)

    # -- current transformation -------------------------------------------------------------
    @property
    def matrix(self) -> NDArray[np.float64]:
        """A copy of the CTM (3, 3), user -> device coordinates; assigning a matrix (or
        anything :func:`scanline.transform.compose` takes) replaces it."""
        return np.array(self._state.ctm)

    @matrix.setter
    def matrix(self, m: Any) -> None:
        m = tf.compose(m)
        tf.apply(m, (0.0, 0.0))  # refuses a non-affine matrix, saying why
        self._state.ctm = m

    def identity(self) -> None:
        """Reset the CTM to the identity (device coordinates).

        Examples
        --------
        >>> import scanline as sl
        >>> ctx = sl.Context(sl.FrameBuffer(4, 4))
        >>> ctx.scale(2); ctx.identity()
        >>> ctx.matrix.tolist()
        [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
        """
        self._state.ctm = np.eye(3)

    def transform(self, m: Any) -> None:
        """Compose ``m`` onto the CTM: CTM := CTM · m (``m`` acts first).

        Parameters
        ----------
        m : array_like or sequence of matrices
            A 3 x 3 affine matrix, or what :func:`scanline.transform.compose` takes.

        Raises
        ------
        ArgumentValueError
            For a matrix that is not affine, or a CTM that would overflow.

        Examples
        --------
        >>> import scanline as sl
        >>> ctx = sl.Context(sl.FrameBuffer(4, 4))
        >>> ctx.transform(sl.transform.translation(2, 0)); ctx.transform(sl.transform.scaling(3))
        >>> ctx.matrix[:2].tolist()                 # T(2, 0) S(3): x' = 3 x + 2
        [[3.0, 0.0, 2.0], [0.0, 3.0, 0.0]]
        """
        t = tf.compose(m)
        tf.apply(t, (0.0, 0.0))
        with np.errstate(all="ignore"):
            ctm = self._state.ctm @ t
        if not np.isfinite(ctm).all():
            raise ArgumentValueError(
                f"the transformation overflows the CTM (CTM {self._state.ctm.tolist()} "
                f"times {t.tolist()}); use smaller factors or distances")
        self._state.ctm = ctm

    def translate(self, tx: float, ty: float) -> None:
        """CTM := CTM · T(tx, ty).

        Parameters
        ----------
        tx, ty : float
            The translation.

        Examples
        --------
        >>> import scanline as sl
        >>> fb = sl.FrameBuffer(4, 2, mode="1")
        >>> ctx = sl.Context(fb)
        >>> ctx.translate(2, 1); ctx.line(0, 0, 1, 0)
        >>> print(sl.text_image(fb))
        --##
        ----
        """
        self.transform(tf.translation(tx, ty))

    def rotate(self, angle: "Angle", pivot: Optional["Point"] = None) -> None:
        """CTM := CTM · R(angle) (about ``pivot``, in user coordinates).

        Parameters
        ----------
        angle : float or str
            Radians counterclockwise (or a string with its unit, "90deg").
        pivot : (x, y), optional
            The fixed point, in user coordinates (default the origin).

        Examples
        --------
        >>> import scanline as sl
        >>> ctx = sl.Context(sl.FrameBuffer(4, 4))
        >>> ctx.rotate("90deg")
        >>> ctx.matrix[:2, :2].round(12).tolist()
        [[0.0, -1.0], [1.0, 0.0]]
        """
        self.transform(tf.rotation(angle, pivot))

    def scale(self, sx: float, sy: Optional[float] = None,
              fixed: Optional["Point"] = None) -> None:
        """CTM := CTM · S(sx, sy) (about ``fixed``).

        Parameters
        ----------
        sx : float
            The x factor.
        sy : float, optional
            The y factor (default ``sx``).
        fixed : (x, y), optional
            The fixed point, in user coordinates (default the origin).

        Examples
        --------
        >>> import scanline as sl
        >>> fb = sl.FrameBuffer(5, 1, mode="1")
        >>> ctx = sl.Context(fb)
        >>> ctx.scale(2); ctx.line(0, 0, 2, 0)       # drawn from x = 0 to 4
        >>> print(sl.text_image(fb))
        #####
        """
        self.transform(tf.scaling(sx, sy, fixed))

    def reflect(self, axis: Any) -> None:
        """CTM := CTM · reflection(axis).

        Parameters
        ----------
        axis : str or line
            The axis of :func:`scanline.transform.reflection` (``"x"``, ``"y"``, ...).

        Examples
        --------
        >>> import scanline as sl
        >>> ctx = sl.Context(sl.FrameBuffer(4, 4))
        >>> ctx.reflect("x")                        # about the x axis: y -> -y
        >>> ctx.matrix[:2, :2].tolist()
        [[1.0, 0.0], [0.0, -1.0]]
        """
        self.transform(tf.reflection(axis))

    def shear(self, shx: float = 0.0, shy: float = 0.0,
              reference: Optional[float] = None) -> None:
        """CTM := CTM · shear(shx, shy, reference).

        Parameters
        ----------
        shx, shy : float
            The x and y shear factors.
        reference : float, optional
            The reference line of :func:`scanline.transform.shear`.

        Examples
        --------
        >>> import scanline as sl
        >>> ctx = sl.Context(sl.FrameBuffer(4, 4))
        >>> ctx.shear(shx=0.5)                      # x' = x + 0.5 y
        >>> ctx.matrix[0].tolist()
        [1.0, 0.5, 0.0]
        """
        self.transform(tf.shear(shx, shy, reference))

    # -- attributes ---------------------------------------------------------------------------
    def set_line(self, **attributes: Any) -> None:
        """Change line attributes: ``color``, ``width``, ``cap``, ``join``,
        ``miter_limit``, ``dash`` (``"solid"`` for none), ``dash_phase`` (those of
        ``sl.draw.polyline``).

        Parameters
        ----------
        **attributes
            ``color`` and the :class:`~scanline.LineStyle` attributes.

        Raises
        ------
        ArgumentTypeError
            For an attribute a LineStyle does not have.
        ArgumentValueError
            For a bad value, or a pen (not drawn through a Context).

        Examples
        --------
        >>> import scanline as sl
        >>> ctx = sl.Context(sl.FrameBuffer(4, 4))
        >>> ctx.set_line(width=3, cap="round")
        >>> ctx.line_attributes["style"]
        LineStyle(width=3, cap='round')
        """
        line = dict(self._state.line)
        if "color" in attributes:
            line["color"] = p.color("color", attributes.pop("color"))
        if "pen" in attributes:
            p.line_attributes(pen=attributes["pen"])  # refused, saying why
        line["style"] = line["style"].replace(**attributes)
        self._state.line = line

    def set_fill(self, color: Optional["Color"] = None,
                 style: Union["FillStyle", str, None] = None, rule: Optional[str] = None,
                 edge: Union["Color", Literal[False], None] = None) -> None:
        """Change fill attributes: ``color``, ``style`` (FillStyle or its word),
        ``rule`` and ``edge`` (an outline color, drawn with the line attributes, or
        ``False`` for none).

        Parameters
        ----------
        color : Color, optional
            The fill color.
        style : FillStyle or str, optional
            The fill style, or its word (``"hatch:45:4"``).
        rule : {"even-odd", "nonzero"}, optional
            The inside rule.
        edge : Color or False, optional
            An outline color, or False for none.

        Raises
        ------
        ArgumentValueError
            For a bad color, style or rule.

        Examples
        --------
        >>> import scanline as sl
        >>> fb = sl.FrameBuffer(4, 3, mode="1")
        >>> ctx = sl.Context(fb)
        >>> ctx.set_fill(color=1, style="hollow")
        >>> ctx.rectangle(0, 0, 3, 2)
        >>> print(sl.text_image(fb))
        ####
        #--#
        ####
        """
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

    def set_text(self, **attributes: Any) -> None:
        """Change text attributes: ``color``, ``font``, ``height``, ``angle``,
        ``align``, ``expansion``, ``spacing``, ``path``, ``clip``.

        Parameters
        ----------
        **attributes
            ``color``, ``font``, ``height``, ``angle``, ``align``, ``expansion``,
            ``spacing``, ``path`` or ``clip``, as :func:`scanline.draw.text` takes them.

        Raises
        ------
        ArgumentValueError
            For an unknown attribute or a bad value.

        Examples
        --------
        >>> import scanline as sl
        >>> ctx = sl.Context(sl.FrameBuffer(4, 4))
        >>> ctx.set_text(height=14, angle="90deg")
        >>> ctx.text_attributes["height"], round(ctx.text_attributes["angle"], 6)
        (14.0, 1.570796)
        """
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
    def line_attributes(self) -> dict[str, Any]:
        """A copy of the current line attributes: ``color`` and ``style`` (a
        :class:`~scanline.LineStyle`)."""
        return dict(self._state.line)

    @property
    def fill_attributes(self) -> dict[str, Any]:
        """A copy of the current fill attributes: ``color``, ``rule``, ``style``,
        ``edge``."""
        return dict(self._state.fill)

    @property
    def text_attributes(self) -> dict[str, Any]:
        """A copy of the current text attributes."""
        return dict(self._state.text)

    # -- clipping --------------------------------------------------------------------------
    def clip(self, window: tuple[float, float, float, float]) -> None:
        """Intersect the clip region with ``window`` = (xmin, ymin, xmax, ymax) in
        user coordinates (mapped by the CTM: a rotated CTM gives a turned window).

        Parameters
        ----------
        window : (xmin, ymin, xmax, ymax)
            The window in user coordinates.

        Raises
        ------
        ArgumentValueError
            For a window that is not one, or one mapped beyond the coordinate range.

        Examples
        --------
        >>> import scanline as sl
        >>> fb = sl.FrameBuffer(6, 1, mode="1")
        >>> ctx = sl.Context(fb)
        >>> ctx.clip((1.6, -1, 3.4, 1))             # pixel centers 2 and 3
        >>> ctx.line(0, 0, 5, 0)
        >>> print(sl.text_image(fb))
        --##--
        """
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
        new: Optional[Region]
        if isinstance(old, tuple) and _upright(corners):
            new = pipeline.intersect(old, (corners[:, 0].min(), corners[:, 1].min(),
                                           corners[:, 0].max(), corners[:, 1].max()))
        else:
            pieces = pipeline.contours([corners], old)
            new = pieces[0] if pieces else None
        self._state.clip = new if new is not None else (0.0, 0.0, -1.0, -1.0)

    @property
    def clip_region(self) -> Region:
        """The clip region in device coordinates: a rectangle tuple or a convex
        polygon (M, 2)."""
        c = self._state.clip
        return c if isinstance(c, tuple) else c.copy()

    # -- drawing ------------------------------------------------------------------------------
    def _draw(self, kind: str, geometry: dict[str, Any], attributes: dict[str, Any]) -> None:
        clip = self._state.clip
        if isinstance(clip, tuple) and not (clip[0] <= clip[2] and clip[1] <= clip[3]):
            return  # empty clip region
        prim = p.Primitive(kind, geometry, attributes, None).transformed(self._state.ctm)
        draw_primitive(prim, clip, self._device)

    def line(self, x0: float, y0: float, x1: float, y1: float) -> None:
        """Stroke the segment (x0, y0)-(x1, y1) with the line attributes.

        Parameters
        ----------
        x0, y0, x1, y1 : float
            The endpoints, in user coordinates.

        Examples
        --------
        >>> import scanline as sl
        >>> fb = sl.FrameBuffer(4, 2, mode="1")
        >>> sl.Context(fb).line(0, 0, 3, 1)
        >>> print(sl.text_image(fb))
        --##
        ##--
        """
        self.polyline([(x0, y0), (x1, y1)])

    def polyline(self, points: "Points", closed: bool = False) -> None:
        """Stroke a polyline (``closed``: a polygon outline).

        Parameters
        ----------
        points : (N, 2) array_like
            The vertices, in user coordinates.
        closed : bool
            Join the last vertex to the first.

        Examples
        --------
        >>> import scanline as sl
        >>> fb = sl.FrameBuffer(3, 3, mode="1")
        >>> sl.Context(fb).polyline([(0, 0), (2, 0), (2, 2)])
        >>> print(sl.text_image(fb))
        --#
        --#
        ###
        """
        pts = p.points("points", points, 1)
        self._draw("polyline", {"points": pts}, {**self._state.line, "closed": bool(closed)})

    def polygon(self, contours: Any) -> None:
        """Fill an area (one contour or several) with the fill attributes.

        Parameters
        ----------
        contours : (N, 2) array_like or list of them
            One contour or several, in user coordinates.

        Examples
        --------
        >>> import scanline as sl
        >>> fb = sl.FrameBuffer(4, 4, mode="1")
        >>> ctx = sl.Context(fb)
        >>> ctx.set_fill(color=1)
        >>> ctx.polygon([(-0.5, -0.5), (3.5, -0.5), (-0.5, 3.5)])   # centers with x + y < 3
        >>> print(sl.text_image(fb))
        ----
        #---
        ##--
        ###-
        """
        cs = p.contours("points", contours)
        self._draw("polygon", {"contours": cs}, self._fill_attributes())

    def rectangle(self, x: float, y: float, width: float, height: float) -> None:
        """Fill the rectangle with corner (x, y) and the given size.

        Parameters
        ----------
        x, y : float
            A corner, in user coordinates.
        width, height : float
            The size (negative: the other way).

        Examples
        --------
        >>> import scanline as sl
        >>> fb = sl.FrameBuffer(4, 3, mode="1")
        >>> ctx = sl.Context(fb)
        >>> ctx.set_fill(color=1)
        >>> ctx.rectangle(0.5, -0.5, 2, 2)          # centers x = 1, 2 and y = 0, 1
        >>> print(sl.text_image(fb))
        ----
        -##-
        -##-
        """
        x, y = v.number("x", x), v.number("y", y)
        w, h = v.number("width", width), v.number("height", height)
        self.polygon([(x, y), (x + w, y), (x + w, y + h), (x, y + h)])

    def ellipse(self, xc: float, yc: float, rx: float, ry: float, angle: "Angle" = 0.0,
                fill: bool = False) -> None:
        """An ellipse: stroked with the line attributes, or filled (``fill=True``).

        Parameters
        ----------
        xc, yc : float
            The center, in user coordinates.
        rx, ry : float
            The semi-axes, >= 0.
        angle : float or str
            The turn of the rx axis from +x.
        fill : bool
            Fill with the fill attributes instead of stroking.

        Examples
        --------
        >>> import scanline as sl
        >>> fb = sl.FrameBuffer(7, 3, mode="1")
        >>> ctx = sl.Context(fb)
        >>> ctx.set_fill(color=1)
        >>> ctx.ellipse(3, 1, 3.2, 1.2, fill=True)    # rows y = 0, 2: |x - 3| < 1.77
        >>> print(sl.text_image(fb))
        --###--
        #######
        --###--
        """
        c = p.points("center", [(xc, yc)])[0]
        axes = tf.rotation(v.angle("angle", angle))[:2, :2] @ np.diag(
            [p._nonnegative("rx", rx), p._nonnegative("ry", ry)])
        attrs = {**self._fill_attributes(), "fill": True} if fill else {
            **self._state.line, "fill": False, "closed": True}
        self._draw("ellipse", {"center": c, "axes": axes}, attrs)

    def circle(self, xc: float, yc: float, r: float, fill: bool = False) -> None:
        """A circle: :meth:`ellipse` with equal semi-axes.

        Parameters
        ----------
        xc, yc : float
            The center, in user coordinates.
        r : float
            The radius, >= 0.
        fill : bool
            Fill with the fill attributes instead of stroking.

        Examples
        --------
        >>> import scanline as sl
        >>> fb = sl.FrameBuffer(3, 3, mode="1")
        >>> ctx = sl.Context(fb)
        >>> ctx.set_fill(color=1)
        >>> ctx.circle(1, 1, 1.2, fill=True)         # centers within 1.2 of (1, 1)
        >>> print(sl.text_image(fb))
        -#-
        ###
        -#-
        """
        self.ellipse(xc, yc, r, r, 0.0, fill)

    def text(self, x: float, y: float, string: str) -> None:
        """Draw ``string`` at (x, y) with the text attributes (the CTM scales, turns
        and moves it).

        Parameters
        ----------
        x, y : float
            The anchor point, in user coordinates.
        string : str
            The text.

        Raises
        ------
        ArgumentValueError
            When ``string`` is not a str.

        Examples
        --------
        >>> import scanline as sl
        >>> fb = sl.FrameBuffer(20, 12, mode="1")
        >>> ctx = sl.Context(fb)
        >>> ctx.text(1, 1, "T")
        >>> fb.to_array().any()
        np.True_
        """
        if not isinstance(string, str):
            raise ArgumentValueError(f"string must be a str, got {v._show(string)}")
        t = self._state.text
        geometry = {"anchor": p.points("position", [(x, y)])[0],
                    "frame": p.text_frame(t["height"], t["angle"]), "string": string}
        self._draw("text", geometry, t)

    def markers(self, points: "Points", kind: str = "plus", size: float = 7.0) -> None:
        """Polymarkers at ``points`` in the line color (``size`` in device units).

        Parameters
        ----------
        points : (N, 2) array_like
            The marker positions, in user coordinates.
        kind : str
            The marker shape (``"plus"``, ``"cross"``, ...).
        size : float
            Its size in device units.

        Examples
        --------
        >>> import scanline as sl
        >>> fb = sl.FrameBuffer(5, 5, mode="1")
        >>> sl.Context(fb).markers([(2, 2)], size=5)
        >>> print(sl.text_image(fb))
        --#--
        --#--
        #####
        --#--
        --#--
        """
        pts = p.points("points", points, 1)
        attrs = p.marker_attributes(kind, size, self._state.line["color"])
        self._draw("markers", {"points": pts}, attrs)

    def _fill_attributes(self) -> dict[str, Any]:
        f = dict(self._state.fill)
        if f["edge"] is not None:
            f["edge"] = {**self._state.line, "color": f["edge"]}
        return f


def _upright(corners: NDArray[np.float64]) -> bool:
    """Whether four corners form an axis-aligned rectangle."""
    xs, ys = corners[:, 0], corners[:, 1]
    return bool((np.isclose(xs[0], xs[3]) and np.isclose(xs[1], xs[2])
                 and np.isclose(ys[0], ys[1]) and np.isclose(ys[2], ys[3]))
                or (np.isclose(ys[0], ys[3]) and np.isclose(ys[1], ys[2])
                    and np.isclose(xs[0], xs[1]) and np.isclose(xs[2], xs[3])))
