"""The display file: named segments of output primitives, in the style of GKS.

The notes (chapter 1, Q.3) describe the display file as the store of graphics
commands that the graphics package builds from the application program and that the
display processor reads to refresh the screen; the syllabus of chapter 2 lists the
display file, its structure, the display-file algorithm and the display-file
interpreter.  This module is the structure; :mod:`scanline.display.interpreter` walks
it.  As in GKS (ISO 7942), the file is a set of *segments*, each a named group of
primitives with its own visibility, highlighting, priority and segment
transformation, and the primitives are stored in normalized device coordinates.
"""

import math
import numbers
from typing import TYPE_CHECKING, Any, Optional

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from .. import transform as tf
from ..errors import ArgumentTypeError, ArgumentValueError
from . import primitives as p
from .viewing import ndc_rectangle, normalization

if TYPE_CHECKING:
    from .._typing import Angle, Color, Point, Points
    from ..framebuffer import FrameBuffer
    from ..projection import Camera
    from .pick import Pick

#: A rectangle (xmin, ymin, xmax, ymax).
Rect = tuple[float, float, float, float]

_UNIT = (0.0, 0.0, 1.0, 1.0)


class Segment:
    """A named group of primitives with its segment attributes.

    Attributes
    ----------
    name : str
    primitives : list of Primitive
        In NDC, in the order they were created.
    visible : bool
        Invisible segments are kept but not drawn.
    highlighted : bool
        Highlighted segments are drawn with a frame around them.
    priority : float
        Segments are drawn in increasing priority (higher ones on top); equal
        priorities keep the order of creation.
    transformation : ndarray, shape (3, 3)
        The segment transformation, applied to the NDC geometry when drawing.
    detectable : bool
        Only detectable segments can be picked (:meth:`DisplayFile.pick`).

    Parameters
    ----------
    name : str
        The segment's name.
    order : int
        Its rank of creation (breaks ties of priority).

    Examples
    --------
    >>> import scanline as sl
    >>> df = sl.DisplayFile()
    >>> df.create_segment("wheel")
    >>> df.close_segment()
    >>> df.segment("wheel")
    <Segment 'wheel': 0 primitives, priority 0>
    """

    __slots__ = ("name", "primitives", "visible", "highlighted", "priority",
                 "transformation", "detectable", "_order")

    def __init__(self, name: str, order: int) -> None:
        self.name = name
        self.primitives: list[p.Primitive] = []
        self.visible = True
        self.highlighted = False
        self.priority = 0.0
        self.transformation = np.eye(3)
        self.detectable = True
        self._order = order

    def __repr__(self) -> str:
        flags = [f for f, on in (("invisible", not self.visible),
                                 ("highlighted", self.highlighted)) if on]
        return (f"<Segment {self.name!r}: {len(self.primitives)} primitives, priority "
                f"{self.priority:g}{''.join(', ' + f for f in flags)}>")


def _name(value: object, what: str = "name") -> str:
    if not isinstance(value, str) or not value:
        raise ArgumentTypeError(f"{what} must be a non-empty string, got {v._show(value)}")
    return value


class DisplayFile:
    """A retained picture: named segments of primitives in normalized device
    coordinates, with a current normalization transformation and current attributes.

    Output functions (:meth:`polyline`, :meth:`polygon`, :meth:`circle`,
    :meth:`ellipse`, :meth:`text`, :meth:`markers`) take world coordinates, map them
    to NDC through the current window and viewport, and append the primitive to the
    open segment.  :func:`scanline.display.interpret` (or :meth:`draw`) draws the
    file on a device, mapping the NDC unit square onto the whole device
    (:func:`scanline.viewing.ndc_to_device`).

    Parameters
    ----------
    aspect : float
        The height / width ratio of the NDC unit square on the intended device,
        ``(height - 1) / (width - 1)`` pixels; only ``keep_aspect`` viewing uses it.

    Examples
    --------
    >>> import scanline as sl
    >>> df = sl.DisplayFile()
    >>> df.set_viewing(window=(0, 0, 7, 3))   # world units = pixels of an 8 x 4 frame
    >>> df.create_segment("base")
    >>> df.polyline([(0, 0), (7, 3)])
    >>> df.close_segment()
    >>> fb = sl.FrameBuffer(8, 4, mode="1")
    >>> df.draw(fb)
    >>> print(sl.text_image(fb))
    ------##
    ----##--
    --##----
    ##------

    Notes
    -----
    Notes, chapter 1, Q.3 (the refresh display file of a random-scan system) and the
    syllabus of chapter 2 (display-file structure, normalized device coordinates);
    segment operations after GKS: create, close, delete, rename (and reopen, to
    append), segment visibility, highlighting, priority and transformation.

    References
    ----------
    ISO 7942:1985, Graphical Kernel System (GKS), chapter 4.7 (segments).
    F. R. A. Hopgood, D. A. Duce, J. R. Gallop and D. C. Sutcliffe, *Introduction to
    the Graphical Kernel System (GKS)*, Academic Press, 1983.
    """

    def __init__(self, aspect: float = 1.0) -> None:
        self.aspect = v.number("aspect", aspect)
        if self.aspect <= 0:
            raise ArgumentValueError(f"aspect must be > 0, got {aspect!r}")
        self._segments: dict[str, Segment] = {}
        self._cameras: dict[str, "Camera"] = {}
        self._current_camera: Optional[str] = None
        self._open: Optional[Segment] = None
        self._created = 0
        self._pick_id = 0
        self.set_viewing()

    # -- viewing --------------------------------------------------------------------------
    def set_viewing(self, window: Rect = _UNIT, viewport: Rect = _UNIT,
                    view_up: tuple[float, float] = (0.0, 1.0), keep_aspect: bool = False,
                    clip: bool = True) -> None:
        """Set the current normalization transformation (world -> NDC).

        Parameters
        ----------
        window : (xmin, ymin, xmax, ymax)
            The world-coordinate window, in the viewing frame: with a ``view_up``
            other than (0, 1) the window is turned about its center so that
            ``view_up`` points up in the viewport.
        viewport : (xmin, ymin, xmax, ymax)
            The viewport in NDC, inside the unit square.
        view_up : (float, float)
            The world direction that points up in the viewport.
        keep_aspect : bool
            Keep the window's aspect ratio (the picture is centered in the viewport)
            on a device whose NDC square is :attr:`aspect` times as high as wide.
        clip : bool
            Clip later primitives to the viewport (GKS's clipping indicator).

        Raises
        ------
        ArgumentTypeError
            When ``clip`` is not a bool.
        ArgumentValueError
            For an empty window, a viewport outside the unit square or a zero view-up.

        Examples
        --------
        >>> import scanline as sl
        >>> df = sl.DisplayFile()
        >>> df.set_viewing(window=(0, 0, 10, 20), viewport=(0, 0, 0.5, 1))
        >>> df.normalization.tolist()           # x / 20, y / 20
        [[0.05, 0.0, 0.0], [0.0, 0.05, 0.0], [0.0, 0.0, 1.0]]
        """
        if not isinstance(clip, bool):
            raise ArgumentTypeError(f"clip must be True or False, got {v._show(clip)}")
        n = normalization(window, viewport, view_up, keep_aspect, self.aspect)
        self._normalization = n
        self._viewport_rect = ndc_rectangle("viewport", viewport)
        self._clip = self._viewport_rect if clip else None

    @property
    def normalization(self) -> NDArray[np.float64]:
        """The current world -> NDC matrix (3x3)."""
        return np.array(self._normalization)

    def world_transformation(self, m: Any) -> NDArray[np.float64]:
        """A transformation given in world coordinates, as the NDC segment
        transformation that has the same effect: N · m · N⁻¹.

        Parameters
        ----------
        m : array_like
            A 3 x 3 affine matrix in world coordinates (or what
            :func:`scanline.transform.compose` takes).

        Returns
        -------
        numpy.ndarray
            The NDC matrix N m N^-1.

        Examples
        --------
        >>> import scanline as sl
        >>> df = sl.DisplayFile()
        >>> df.set_viewing(window=(0, 0, 10, 10))
        >>> df.world_transformation(sl.transform.translation(5, 0))[0].round(12).tolist()   # 5 world = 0.5 NDC
        [1.0, 0.0, 0.5]
        """
        n = self._normalization
        return tf.compose(n, m, tf.inverse(n))

    # -- segments ---------------------------------------------------------------------------
    def create_segment(self, name: str, priority: float = 0.0, visible: bool = True,
                       highlighted: bool = False) -> None:
        """Open a new segment; later primitives go into it until :meth:`close_segment`.

        Parameters
        ----------
        name : str
            A new segment name.
        priority : float
            Its priority (higher drawn later).
        visible : bool
            Whether it is drawn.
        highlighted : bool
            Whether it is drawn with a frame.

        Raises
        ------
        ArgumentValueError
            When a segment is open, or ``name`` exists.
        ArgumentTypeError
            When ``name`` is not a non-empty str.

        Examples
        --------
        >>> import scanline as sl
        >>> df = sl.DisplayFile()
        >>> df.create_segment("house", priority=2)
        >>> df.open_segment, df.segment("house").priority
        ('house', 2.0)
        """
        _name(name)
        if self._open is not None:
            raise ArgumentValueError(
                f"cannot create segment {name!r}: segment {self._open.name!r} is still "
                "open; close it first (close_segment())"
            )
        if name in self._segments:
            raise ArgumentValueError(
                f"segment {name!r} already exists; reopen it to append "
                "(reopen_segment) or delete it first"
            )
        seg = Segment(name, self._created)
        self._created += 1
        self._segments[name] = seg
        self._open = seg
        self.set_priority(name, priority)
        self.set_visibility(name, visible)
        self.set_highlighting(name, highlighted)

    def close_segment(self) -> None:
        """Close the open segment.



        Raises
        ------
        ArgumentValueError
            When no segment is open.

        Examples
        --------
        >>> import scanline as sl
        >>> df = sl.DisplayFile()
        >>> df.create_segment("a"); df.close_segment()
        >>> df.open_segment is None
        True
        """
        if self._open is None:
            raise ArgumentValueError("no segment is open; create_segment(name) opens one")
        self._open = None

    def reopen_segment(self, name: str) -> None:
        """Open an existing segment again, to append primitives to it.

        Parameters
        ----------
        name : str
            The segment's name.

        Raises
        ------
        ArgumentValueError
            For an unknown name, or when a segment is open.

        Examples
        --------
        >>> import scanline as sl
        >>> df = sl.DisplayFile()
        >>> df.create_segment("a"); df.polyline([(0, 0), (1, 1)]); df.close_segment()
        >>> df.reopen_segment("a"); df.polyline([(1, 1), (0, 1)]); df.close_segment()
        >>> len(df.segment("a").primitives)
        2
        """
        seg = self.segment(name)
        if self._open is not None:
            raise ArgumentValueError(
                f"cannot reopen segment {name!r}: segment {self._open.name!r} is open; "
                "close it first"
            )
        self._open = seg

    def delete_segment(self, name: str) -> None:
        """Remove a closed segment and its primitives.

        Parameters
        ----------
        name : str
            The segment's name.

        Raises
        ------
        ArgumentValueError
            For an unknown name or the open segment.

        Examples
        --------
        >>> import scanline as sl
        >>> df = sl.DisplayFile()
        >>> df.create_segment("a"); df.close_segment(); df.delete_segment("a")
        >>> "a" in df, len(df)
        (False, 0)
        """
        seg = self.segment(name)
        if seg is self._open:
            raise ArgumentValueError(f"segment {name!r} is open; close it before deleting it")
        del self._segments[name]

    def rename_segment(self, old: str, new: str) -> None:
        """Give segment ``old`` the name ``new`` (which must be free).

        Parameters
        ----------
        old : str
            The segment's name.
        new : str
            Its new name, not taken.

        Raises
        ------
        ArgumentValueError
            For an unknown ``old`` or a taken ``new``.

        Examples
        --------
        >>> import scanline as sl
        >>> df = sl.DisplayFile()
        >>> df.create_segment("a"); df.close_segment(); df.rename_segment("a", "b")
        >>> [s.name for s in df.segments]
        ['b']
        """
        seg = self.segment(old)
        _name(new, "new")
        if new in self._segments:
            raise ArgumentValueError(f"cannot rename {old!r} to {new!r}: {new!r} already exists")
        self._segments = {(new if k == old else k): s for k, s in self._segments.items()}
        seg.name = new

    def segment(self, name: str) -> Segment:
        """The :class:`Segment` called ``name``.

        Parameters
        ----------
        name : str
            The segment's name.

        Returns
        -------
        Segment
            The segment (its attributes may be read; change them with the ``set_*`` methods).

        Raises
        ------
        ArgumentValueError
            For an unknown name.

        Examples
        --------
        >>> import scanline as sl
        >>> df = sl.DisplayFile()
        >>> df.create_segment("a"); df.close_segment()
        >>> df.segment("a").visible
        True
        """
        seg = self._segments.get(name) if isinstance(name, str) else None
        if seg is None:
            known = ", ".join(repr(k) for k in self._segments) or "none yet"
            raise ArgumentValueError(f"no segment named {v._show(name)}; segments: {known}")
        return seg

    @property
    def segments(self) -> list[Segment]:
        """The segments in order of creation."""
        return list(self._segments.values())

    @property
    def open_segment(self) -> Optional[str]:
        """The name of the open segment, or None."""
        return None if self._open is None else self._open.name

    def __contains__(self, name: object) -> bool:
        return name in self._segments

    def __len__(self) -> int:
        return len(self._segments)

    def set_visibility(self, name: str, visible: bool) -> None:
        """Show or hide a segment.

        Parameters
        ----------
        name : str
            The segment's name.
        visible : bool
            The new value.

        Raises
        ------
        ArgumentValueError
            For an unknown name or a bad value.

        Examples
        --------
        >>> import scanline as sl
        >>> df = sl.DisplayFile()
        >>> df.create_segment("a"); df.close_segment()
        >>> df.set_visibility("a", False)
        >>> df.segment("a").visible
        False
        """
        self.segment(name).visible = _flag("visible", visible)

    def set_highlighting(self, name: str, highlighted: bool) -> None:
        """Turn a segment's highlighting on or off.

        Parameters
        ----------
        name : str
            The segment's name.
        highlighted : bool
            The new value.

        Raises
        ------
        ArgumentValueError
            For an unknown name or a bad value.

        Examples
        --------
        >>> import scanline as sl
        >>> df = sl.DisplayFile()
        >>> df.create_segment("a"); df.close_segment()
        >>> df.set_highlighting("a", True)
        >>> df.segment("a").highlighted
        True
        """
        self.segment(name).highlighted = _flag("highlighted", highlighted)

    def set_priority(self, name: str, priority: float) -> None:
        """Set a segment's priority (higher is drawn later, on top).

        Parameters
        ----------
        name : str
            The segment's name.
        priority : float
            The new value.

        Raises
        ------
        ArgumentValueError
            For an unknown name or a bad value.

        Examples
        --------
        >>> import scanline as sl
        >>> df = sl.DisplayFile()
        >>> df.create_segment("a"); df.close_segment()
        >>> df.set_priority("a", 5)
        >>> df.segment("a").priority
        5.0
        """
        self.segment(name).priority = v.number("priority", priority)

    def set_detectability(self, name: str, detectable: bool) -> None:
        """Make a segment pickable or not (GKS's segment detectability).

        Parameters
        ----------
        name : str
            The segment's name.
        detectable : bool
            The new value.

        Raises
        ------
        ArgumentValueError
            For an unknown name or a bad value.

        Examples
        --------
        >>> import scanline as sl
        >>> df = sl.DisplayFile()
        >>> df.create_segment("a"); df.close_segment()
        >>> df.set_detectability("a", False)
        >>> df.segment("a").detectable
        False
        """
        self.segment(name).detectable = _flag("detectable", detectable)

    def set_pick_identifier(self, pick_id: int) -> None:
        """Set the pick identifier of later primitives (GKS's SET PICK IDENTIFIER):
        a pick reports it with the segment name, so parts of one segment can be told
        apart.  It starts at 0.

        Parameters
        ----------
        pick_id : int
            The identifier.

        Raises
        ------
        ArgumentTypeError
            When ``pick_id`` is not an integer.

        Examples
        --------
        >>> import scanline as sl
        >>> df = sl.DisplayFile()
        >>> df.create_segment("a"); df.set_pick_identifier(3); df.polyline([(0, 0), (1, 1)])
        >>> df.segment("a").primitives[0].pick_id
        3
        """
        if not isinstance(pick_id, numbers.Integral) or isinstance(pick_id, bool):
            raise ArgumentTypeError(f"pick_id must be an integer, got {v._show(pick_id)}")
        self._pick_id = int(pick_id)

    # -- input ------------------------------------------------------------------------------
    def pick(self, x: float, y: float, aperture: float, device: Any) -> Optional["Pick"]:
        """The segment (and pick identifier) under the device position (x, y): see
        :func:`scanline.display.pick.pick`.

        Parameters
        ----------
        x, y : float
            The pointer's device position.
        aperture : float
            Half the side of the pick window, device units, > 0.
        device : FrameBuffer, device or (width, height)
            The workstation the file is drawn on.

        Returns
        -------
        Pick or None
            The segment and pick identifier hit, or None.

        Examples
        --------
        >>> import scanline as sl
        >>> df = sl.DisplayFile()
        >>> df.set_viewing(window=(0, 0, 10, 10))
        >>> df.create_segment("bar"); df.polyline([(0, 5), (10, 5)]); df.close_segment()
        >>> df.pick(5, 50, 1, (101, 101))
        Pick(segment='bar', pick_id=0)
        """
        from .pick import pick

        return pick(self, x, y, aperture, device)

    def locate(self, x: float, y: float, device: Any) -> tuple[float, float]:
        """The world coordinates of the device position (x, y): see
        :func:`scanline.display.pick.locate`.

        Parameters
        ----------
        x, y : float
            The device position.
        device : FrameBuffer, device or (width, height)
            The workstation the file is drawn on.

        Returns
        -------
        tuple of float
            The world coordinates, through the current normalization.

        Examples
        --------
        >>> import scanline as sl
        >>> df = sl.DisplayFile()
        >>> df.set_viewing(window=(0, 0, 10, 10))
        >>> df.locate(50, 100, (101, 101))
        (5.0, 10.0)
        """
        from .pick import locate

        return locate(self, x, y, device)

    def set_transformation(self, name: str, matrix: Any) -> None:
        """Set a segment's transformation: an affine 3x3 matrix acting on NDC (use
        :meth:`world_transformation` to give one in world coordinates).

        Parameters
        ----------
        name : str
            The segment's name.
        matrix : array_like
            An affine 3 x 3 matrix acting on NDC.

        Raises
        ------
        ArgumentValueError
            For an unknown name or a matrix that is not affine.

        Examples
        --------
        >>> import scanline as sl
        >>> df = sl.DisplayFile()
        >>> df.create_segment("a"); df.close_segment()
        >>> df.set_transformation("a", sl.transform.translation(0.25, 0))
        >>> df.segment("a").transformation[0].tolist()
        [1.0, 0.0, 0.25]
        """
        m = tf.compose(matrix)
        tf.apply(m, (0.0, 0.0))  # refuses a non-affine matrix, saying why
        self.segment(name).transformation = m

    # -- output primitives ----------------------------------------------------------------
    def _add(self, kind: str, geometry: dict[str, Any], attributes: dict[str, Any]) -> None:
        if self._open is None:
            raise ArgumentValueError(
                f"no segment is open to hold the {kind}; call create_segment(name) first"
            )
        self._open.primitives.append(p.Primitive(kind, geometry, attributes, self._clip,
                                                 self._pick_id))

    def _ndc(self, pts: Any) -> NDArray[np.float64]:
        return tf.apply(self._normalization, pts)

    def polyline(self, points: "Points", color: Optional["Color"] = None, closed: bool = False,
                 **line: Any) -> None:
        """Append a polyline (``closed=True``: a polygon outline).

        ``line`` holds the line attributes of :func:`scanline.draw.polyline`:
        ``width`` (device units), ``cap``, ``join``, ``miter_limit``, ``dash``,
        ``dash_phase``.

        Parameters
        ----------
        points : (N, 2) array_like
            World coordinates.
        color : Color, optional
            The line color (None: the device's foreground).
        closed : bool
            Join the last point to the first.
        **line
            ``width``, ``cap``, ``join``, ``miter_limit``, ``dash``, ``dash_phase``.

        Raises
        ------
        ArgumentValueError
            When no segment is open, or for bad points or attributes.

        Examples
        --------
        >>> import scanline as sl
        >>> df = sl.DisplayFile()
        >>> df.set_viewing(window=(0, 0, 4, 2))
        >>> df.create_segment("a"); df.polyline([(0, 2), (4, 2)], color=1); df.close_segment()
        >>> fb = sl.FrameBuffer(5, 3, mode="1"); df.draw(fb)
        >>> print(sl.text_image(fb))
        #####
        -----
        -----
        """
        pts = p.points("points", points, 1)
        attrs = p.line_attributes(color, **line)
        attrs["closed"] = _flag("closed", closed)
        self._add("polyline", {"points": self._ndc(pts)}, attrs)

    def polygon(self, points: Any, color: Optional["Color"] = None, rule: str = "even-odd",
                style: Any = None, edge: Optional["Color"] = None, **line: Any) -> None:
        """Append a fill area: one contour or several (holes combine by ``rule``).

        ``style`` is a :class:`scanline.FillStyle` or its word (``"hollow"``,
        ``"hatch:45:8"``); ``edge`` an optional outline color drawn with the line
        attributes ``line``.

        Parameters
        ----------
        points : (N, 2) array_like or list of them
            One contour or several, world coordinates.
        color : Color, optional
            The fill color.
        rule : {"even-odd", "nonzero"}
            How contours combine.
        style : FillStyle or str, optional
            The fill style (None: solid).
        edge : Color, optional
            An outline color.
        **line
            The outline's line attributes.

        Raises
        ------
        ArgumentValueError
            When no segment is open, or for bad contours or attributes.

        Examples
        --------
        >>> import scanline as sl
        >>> df = sl.DisplayFile()
        >>> df.set_viewing(window=(0, 0, 4, 2))          # world units = pixels of 5 x 3
        >>> df.create_segment("a")
        >>> df.polygon([(0.5, -0.5), (2.5, -0.5), (2.5, 1.5), (0.5, 1.5)], color=1)
        >>> df.close_segment()
        >>> fb = sl.FrameBuffer(5, 3, mode="1"); df.draw(fb)
        >>> print(sl.text_image(fb))                  # centers x = 1, 2 and y = 0, 1
        -----
        -##--
        -##--
        """
        cs = p.contours("points", points)
        outline = p.line_attributes(edge, "edge", **line)
        attrs = {
            "color": p.color("color", color),
            "rule": v.choice("rule", rule, p.RULES),
            "style": p.fill_style("style", style),
            "edge": None,
        }
        if edge is not None:
            attrs["edge"] = outline
        self._add("polygon", {"contours": [self._ndc(c) for c in cs]}, attrs)

    def ellipse(self, center: "Point", rx: float, ry: float, angle: "Angle" = 0.0,
                color: Optional["Color"] = None, fill: bool = False, rule: str = "even-odd",
                style: Any = None, **line: Any) -> None:
        """Append an ellipse with semi-axes ``rx``, ``ry`` turned by ``angle`` radians;
        ``fill=True`` makes it a fill area (with ``style``), else an outline.

        Parameters
        ----------
        center : (x, y)
            World coordinates.
        rx, ry : float
            The semi-axes, world units, >= 0.
        angle : float or str
            The turn of the rx axis.
        color : Color, optional
            The color.
        fill : bool
            A fill area instead of an outline.
        rule : {"even-odd", "nonzero"}
            The fill rule.
        style : FillStyle or str, optional
            The fill style.
        **line
            The outline's line attributes.

        Raises
        ------
        ArgumentValueError
            When no segment is open, or for bad geometry or attributes.

        Examples
        --------
        >>> import scanline as sl
        >>> df = sl.DisplayFile()
        >>> df.create_segment("a"); df.ellipse((0.5, 0.5), 0.4, 0.2)
        >>> df.segment("a").primitives[0].kind
        'ellipse'
        """
        c = p.points("center", [center], 1)
        rx, ry = p._nonnegative("rx", rx), p._nonnegative("ry", ry)
        a = v.angle("angle", angle)
        axes = np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]]) @ np.diag([rx, ry])
        lin = self._normalization[:2, :2]
        attrs: dict[str, Any] = {"fill": _flag("fill", fill)}
        outline = p.line_attributes(color, **line)
        if attrs["fill"]:
            attrs.update(color=p.color("color", color), rule=v.choice("rule", rule, p.RULES),
                         style=p.fill_style("style", style), edge=None)
        else:
            attrs.update(outline, closed=True)
        self._add("ellipse", {"center": self._ndc(c)[0], "axes": lin @ axes}, attrs)

    def circle(self, center: "Point", radius: float, color: Optional["Color"] = None,
               fill: bool = False, **attributes: Any) -> None:
        """Append a circle (an ellipse with equal semi-axes).

        Parameters
        ----------
        center : (x, y)
            World coordinates.
        radius : float
            World units, >= 0.
        color : Color, optional
            The color.
        fill : bool
            A fill area instead of an outline.
        **attributes
            Those of :meth:`ellipse`.

        Raises
        ------
        ArgumentValueError
            When no segment is open or the radius is negative.

        Examples
        --------
        >>> import scanline as sl
        >>> df = sl.DisplayFile()
        >>> df.set_viewing(window=(0, 0, 10, 10))
        >>> df.create_segment("a"); df.circle((5, 5), 2)
        >>> df.segment("a").primitives[0].geometry["axes"].tolist()   # 2 world units = 0.2 NDC
        [[0.2, 0.0], [0.0, 0.2]]
        """
        radius = p._nonnegative("radius", radius)
        self.ellipse(center, radius, radius, 0.0, color, fill, **attributes)

    def text(self, position: "Point", string: str, height: float = 1.0, angle: "Angle" = 0.0,
             color: Optional["Color"] = None, font: Any = "stroke",
             align: tuple[str, str] = ("left", "base"), expansion: float = 1.0,
             spacing: float = 0.0, path: str = "right", clip: str = "character") -> None:
        """Append a text string at ``position`` (world coordinates).

        ``height`` is the character height in world units; ``angle`` turns the
        baseline (radians); ``font``, ``align``, ``expansion``, ``spacing`` and
        ``path`` are those of :func:`scanline.draw.text`.  ``clip`` says how the
        string is clipped: ``"string"`` (all or none), ``"character"`` (each
        character all or none) or ``"stroke"`` (strokes and pixels).

        Parameters
        ----------
        position : (x, y)
            World coordinates.
        string : str
            The text.
        height : float
            Character height, world units, > 0.
        angle : float or str
            The baseline's turn.
        color : Color, optional
            The color.
        font : str or font
            As :func:`scanline.draw.text` takes it.
        align : (str, str)
            Horizontal and vertical alignment.
        expansion : float
            Character width factor.
        spacing : float
            Extra space between characters, in heights.
        path : str
            The text path (``"right"``, ``"left"``, ``"up"``, ``"down"``).
        clip : {"string", "character", "stroke"}
            How the string is clipped.

        Raises
        ------
        ArgumentTypeError
            When ``string`` is not a str.
        ArgumentValueError
            When no segment is open, or for bad attributes.

        Examples
        --------
        >>> import scanline as sl
        >>> df = sl.DisplayFile()
        >>> df.create_segment("a"); df.text((0.1, 0.1), "Hi", height=0.2)
        >>> df.segment("a").primitives[0].geometry["string"]
        'Hi'
        """
        if not isinstance(string, str):
            raise ArgumentTypeError(f"string must be a str, got {v._show(string)}")
        pos = p.points("position", [position], 1)
        attrs = p.text_attributes(color, font, align, expansion, spacing, path, clip)
        frame = self._normalization[:2, :2] @ p.text_frame(p._positive("height", height),
                                                           v.angle("angle", angle))
        self._add("text", {"anchor": self._ndc(pos)[0], "frame": frame, "string": string},
                  attrs)

    def markers(self, points: "Points", kind: str = "plus", size: float = 7.0,
                color: Optional["Color"] = None) -> None:
        """Append polymarkers: ``kind`` one of dot, plus, asterisk, circle, cross
        (GKS types 1-5), ``size`` in device units (markers do not scale).

        Parameters
        ----------
        points : (N, 2) array_like
            World coordinates.
        kind : str
            dot, plus, asterisk, circle or cross.
        size : float
            Device units.
        color : Color, optional
            The color.

        Raises
        ------
        ArgumentValueError
            When no segment is open, or for a bad kind or size.

        Examples
        --------
        >>> import scanline as sl
        >>> df = sl.DisplayFile()
        >>> df.set_viewing(window=(0, 0, 4, 4))
        >>> df.create_segment("a"); df.markers([(2, 2)], size=5, color=1); df.close_segment()
        >>> fb = sl.FrameBuffer(5, 5, mode="1"); df.draw(fb)
        >>> print(sl.text_image(fb))
        --#--
        --#--
        #####
        --#--
        --#--
        """
        pts = p.points("points", points, 1)
        attrs = p.marker_attributes(kind, size, color)
        self._add("markers", {"points": self._ndc(pts)}, attrs)

    # -- 3-D primitives -----------------------------------------------------------------------
    def set_camera(self, camera: "Camera", name: str = "camera") -> None:
        """Define the camera ``name`` (or replace it) and make it the current one:
        the 3-D primitives created from now on are seen through it.  Cameras are
        looked up when the file is interpreted, so replacing one re-projects every
        primitive that uses it.

        Parameters
        ----------
        camera : Camera
            The camera.
        name : str
            Its name.

        Raises
        ------
        ArgumentTypeError
            When ``camera`` is not a Camera or ``name`` not a non-empty str.

        Examples
        --------
        >>> import scanline as sl
        >>> df = sl.DisplayFile()
        >>> cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0))
        >>> df.set_camera(cam, "front")
        >>> df.camera("front") is cam
        True
        """
        from ..projection import Camera

        if not isinstance(camera, Camera):
            raise ArgumentTypeError(f"camera must be a scanline.Camera, got {v._show(camera)}")
        _name(name)
        self._cameras[name] = camera
        self._current_camera = name

    def camera(self, name: str = "camera") -> "Camera":
        """The camera called ``name``.

        Parameters
        ----------
        name : str
            The camera's name.

        Returns
        -------
        Camera
            The camera.

        Raises
        ------
        ArgumentValueError
            For an unknown name.

        Examples
        --------
        >>> import scanline as sl
        >>> df = sl.DisplayFile()
        >>> df.set_camera(sl.Camera(eye=(0, 0, 5), target=(0, 0, 0)))
        >>> type(df.camera()).__name__
        'Camera'
        """
        cams = self._cameras
        if name not in cams:
            known = ", ".join(repr(k) for k in cams) or "none yet (set_camera)"
            raise ArgumentValueError(f"no camera named {v._show(name)}; cameras: {known}")
        return cams[name]

    def _add3d(self, kind: str, geometry: dict[str, Any], attributes: dict[str, Any]) -> None:
        name = self._current_camera
        if name is None:
            raise ArgumentValueError(
                f"a {kind} is seen through a camera: call set_camera(camera) first")
        geometry.update(camera=name, viewport=self._viewport_rect)
        self._add(kind, geometry, attributes)

    def polyline3d(self, points: Any, color: "Color" = "white", closed: bool = False,
                   **line: Any) -> None:
        """Append a 3-D polyline (world coordinates (N, 3)), seen through the current
        camera into the current viewport; ``line`` as :meth:`polyline`.

        Parameters
        ----------
        points : (N, 3) array_like
            World coordinates.
        color : Color
            The line color.
        closed : bool
            Join the last point to the first.
        **line
            The line attributes of :meth:`polyline`.

        Raises
        ------
        ArgumentValueError
            When no camera is set or no segment is open, or for bad points.

        Examples
        --------
        >>> import scanline as sl
        >>> df = sl.DisplayFile()
        >>> df.set_camera(sl.Camera(eye=(0, 0, 5), target=(0, 0, 0)))
        >>> df.create_segment("a"); df.polyline3d([(0, 0, 0), (1, 1, 1)])
        >>> df.segment("a").primitives[0].kind
        'polyline3d'
        """
        from ..transform3d.arrays import points as point_array

        pts, _ = point_array("points", points)
        if len(pts) < 1:
            raise ArgumentValueError("points needs at least 1 point")
        attrs = {"line": p.line_attributes(color, **line), "closed": _flag("closed", closed)}
        self._add3d("polyline3d", {"points": pts}, attrs)

    def mesh(self, mesh: Any, color: Optional["Color"] = None, depth_cue: Any = None,
             background: "Color" = "black", **line: Any) -> None:
        """Append the wireframe of a mesh -- a :class:`~scanline.mesh.Mesh` or any
        object :meth:`~scanline.mesh.Mesh.from_any` takes (trimesh, meshio, Open3D) --
        seen through the current camera into the current viewport: ``color`` (None:
        the mesh's own colors, else white), ``depth_cue`` as
        :func:`scanline.draw3d.wireframe` (fading toward ``background``), ``line`` as
        :meth:`polyline`.

        Parameters
        ----------
        mesh : Mesh or mesh-like
            The mesh.
        color : Color, optional
            The line color (None: the mesh's own colors, else white).
        depth_cue : optional
            As :func:`scanline.draw3d.wireframe` takes it.
        background : Color
            What depth cueing fades toward.
        **line
            The line attributes of :meth:`polyline`.

        Raises
        ------
        ArgumentTypeError
            For something that is not a mesh.
        ArgumentValueError
            When no camera is set or no segment is open.

        Examples
        --------
        >>> import scanline as sl
        >>> df = sl.DisplayFile()
        >>> df.set_camera(sl.Camera(eye=(3, 2, 4), target=(0, 0, 0)))
        >>> df.create_segment("cube"); df.mesh(sl.mesh.cube()); df.close_segment()
        >>> fb = sl.FrameBuffer(32, 32, mode="1"); df.draw(fb)
        >>> bool(fb.to_array().any())
        True
        """
        from ..draw3d.wireframe import depth_cue_intensities
        from ..mesh.convert import TAKES, from_any, kind

        if kind(mesh) is None:
            raise ArgumentTypeError(f"mesh must be {TAKES}, got {v._show(mesh)}")
        mesh = from_any(mesh)
        depth_cue_intensities(depth_cue)
        line_attrs = p.line_attributes("white" if color is None else color, **line)
        attrs = {"color": None if color is None else line_attrs["color"], "line": line_attrs,
                 "depth_cue": depth_cue, "background": p.color("background", background)}
        self._add3d("mesh", {"mesh": mesh}, attrs)

    # -- drawing ----------------------------------------------------------------------------
    def draw(self, fb: "FrameBuffer", antialias: bool = False,
             highlight: "Color" = "magenta") -> None:
        """Draw the file on a frame buffer (:func:`scanline.display.interpret` on a
        :class:`~scanline.display.RasterDevice`).

        Parameters
        ----------
        fb : FrameBuffer
            Drawn into as it is.
        antialias : bool
            Antialiased strokes and solid areas.
        highlight : Color
            The color of highlight frames.

        Examples
        --------
        >>> import scanline as sl
        >>> df = sl.DisplayFile()
        >>> df.set_viewing(window=(0, 0, 2, 2))
        >>> df.create_segment("a"); df.polyline([(0, 0), (2, 2)], color=1); df.close_segment()
        >>> fb = sl.FrameBuffer(3, 3, mode="1"); df.draw(fb)
        >>> print(sl.text_image(fb))
        --#
        -#-
        #--
        """
        from .devices import RasterDevice
        from .interpreter import interpret

        interpret(self, RasterDevice(fb, antialias), highlight=highlight)

    def __repr__(self) -> str:
        return f"<DisplayFile: {len(self._segments)} segments, open: {self.open_segment!r}>"


def _flag(name: str, value: object) -> bool:
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, numbers.Integral) and int(value) in (0, 1):
        return bool(value)
    raise ArgumentTypeError(f"{name} must be True or False, got {v._show(value)}")
