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

import numpy as np

from .. import _validate as v
from .. import transform as tf
from ..errors import ArgumentTypeError, ArgumentValueError
from . import primitives as p
from .viewing import ndc_rectangle, normalization

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


def _name(value, what="name"):
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

    def __init__(self, aspect=1.0):
        self.aspect = v.number("aspect", aspect)
        if self.aspect <= 0:
            raise ArgumentValueError(f"aspect must be > 0, got {aspect!r}")
        self._segments = {}
        self._cameras = {}
        self._current_camera = None
        self._open = None
        self._created = 0
        self._pick_id = 0
        self.set_viewing()

    # -- viewing --------------------------------------------------------------------------
    def set_viewing(self, window=_UNIT, viewport=_UNIT, view_up=(0.0, 1.0),
                    keep_aspect=False, clip=True):
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
        keep_aspect : bool
            Keep the window's aspect ratio (the picture is centered in the viewport)
            on a device whose NDC square is :attr:`aspect` times as high as wide.
        clip : bool
            Clip later primitives to the viewport (GKS's clipping indicator).
        """
        if not isinstance(clip, bool):
            raise ArgumentTypeError(f"clip must be True or False, got {v._show(clip)}")
        n = normalization(window, viewport, view_up, keep_aspect, self.aspect)
        self._normalization = n
        self._viewport_rect = ndc_rectangle("viewport", viewport)
        self._clip = self._viewport_rect if clip else None

    @property
    def normalization(self):
        """The current world -> NDC matrix (3x3)."""
        return self._normalization.copy()

    def world_transformation(self, m):
        """A transformation given in world coordinates, as the NDC segment
        transformation that has the same effect: N · m · N⁻¹."""
        n = self._normalization
        return tf.compose(n, m, tf.inverse(n))

    # -- segments ---------------------------------------------------------------------------
    def create_segment(self, name, priority=0.0, visible=True, highlighted=False):
        """Open a new segment; later primitives go into it until :meth:`close_segment`."""
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

    def close_segment(self):
        """Close the open segment."""
        if self._open is None:
            raise ArgumentValueError("no segment is open; create_segment(name) opens one")
        self._open = None

    def reopen_segment(self, name):
        """Open an existing segment again, to append primitives to it."""
        seg = self.segment(name)
        if self._open is not None:
            raise ArgumentValueError(
                f"cannot reopen segment {name!r}: segment {self._open.name!r} is open; "
                "close it first"
            )
        self._open = seg

    def delete_segment(self, name):
        """Remove a closed segment and its primitives."""
        seg = self.segment(name)
        if seg is self._open:
            raise ArgumentValueError(f"segment {name!r} is open; close it before deleting it")
        del self._segments[name]

    def rename_segment(self, old, new):
        """Give segment ``old`` the name ``new`` (which must be free)."""
        seg = self.segment(old)
        _name(new, "new")
        if new in self._segments:
            raise ArgumentValueError(f"cannot rename {old!r} to {new!r}: {new!r} already exists")
        self._segments = {(new if k == old else k): s for k, s in self._segments.items()}
        seg.name = new

    def segment(self, name):
        """The :class:`Segment` called ``name``."""
        seg = self._segments.get(name) if isinstance(name, str) else None
        if seg is None:
            known = ", ".join(repr(k) for k in self._segments) or "none yet"
            raise ArgumentValueError(f"no segment named {v._show(name)}; segments: {known}")
        return seg

    @property
    def segments(self):
        """The segments in order of creation."""
        return list(self._segments.values())

    @property
    def open_segment(self):
        """The name of the open segment, or None."""
        return None if self._open is None else self._open.name

    def __contains__(self, name):
        return name in self._segments

    def __len__(self):
        return len(self._segments)

    def set_visibility(self, name, visible):
        """Show or hide a segment."""
        self.segment(name).visible = _flag("visible", visible)

    def set_highlighting(self, name, highlighted):
        """Turn a segment's highlighting on or off."""
        self.segment(name).highlighted = _flag("highlighted", highlighted)

    def set_priority(self, name, priority):
        """Set a segment's priority (higher is drawn later, on top)."""
        self.segment(name).priority = v.number("priority", priority)

    def set_detectability(self, name, detectable):
        """Make a segment pickable or not (GKS's segment detectability)."""
        self.segment(name).detectable = _flag("detectable", detectable)

    def set_pick_identifier(self, pick_id):
        """Set the pick identifier of later primitives (GKS's SET PICK IDENTIFIER):
        a pick reports it with the segment name, so parts of one segment can be told
        apart.  It starts at 0."""
        if not isinstance(pick_id, numbers.Integral) or isinstance(pick_id, bool):
            raise ArgumentTypeError(f"pick_id must be an integer, got {v._show(pick_id)}")
        self._pick_id = int(pick_id)

    # -- input ------------------------------------------------------------------------------
    def pick(self, x, y, aperture, device):
        """The segment (and pick identifier) under the device position (x, y): see
        :func:`scanline.display.pick.pick`."""
        from .pick import pick

        return pick(self, x, y, aperture, device)

    def locate(self, x, y, device):
        """The world coordinates of the device position (x, y): see
        :func:`scanline.display.pick.locate`."""
        from .pick import locate

        return locate(self, x, y, device)

    def set_transformation(self, name, matrix):
        """Set a segment's transformation: an affine 3x3 matrix acting on NDC (use
        :meth:`world_transformation` to give one in world coordinates)."""
        m = tf.compose(matrix)
        tf.apply(m, (0.0, 0.0))  # refuses a non-affine matrix, saying why
        self.segment(name).transformation = m

    # -- output primitives ----------------------------------------------------------------
    def _add(self, kind, geometry, attributes):
        if self._open is None:
            raise ArgumentValueError(
                f"no segment is open to hold the {kind}; call create_segment(name) first"
            )
        self._open.primitives.append(p.Primitive(kind, geometry, attributes, self._clip,
                                                 self._pick_id))

    def _ndc(self, pts):
        return tf.apply(self._normalization, pts)

    def polyline(self, points, color=None, closed=False, **line):
        """Append a polyline (``closed=True``: a polygon outline).

        ``line`` holds the line attributes of :func:`scanline.draw.polyline`:
        ``width`` (device units), ``cap``, ``join``, ``miter_limit``, ``dash``,
        ``dash_phase``.
        """
        pts = p.points("points", points, 1)
        attrs = p.line_attributes(color, **line)
        attrs["closed"] = _flag("closed", closed)
        self._add("polyline", {"points": self._ndc(pts)}, attrs)

    def polygon(self, points, color=None, rule="even-odd", style=None, edge=None,
                **line):
        """Append a fill area: one contour or several (holes combine by ``rule``).

        ``style`` is a :class:`scanline.FillStyle` or its word (``"hollow"``,
        ``"hatch:45:8"``); ``edge`` an optional outline color drawn with the line
        attributes ``line``.
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

    def ellipse(self, center, rx, ry, angle=0.0, color=None, fill=False, rule="even-odd",
                style=None, **line):
        """Append an ellipse with semi-axes ``rx``, ``ry`` turned by ``angle`` radians;
        ``fill=True`` makes it a fill area (with ``style``), else an outline."""
        c = p.points("center", [center], 1)
        rx, ry = p._nonnegative("rx", rx), p._nonnegative("ry", ry)
        a = v.angle("angle", angle)
        axes = np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]]) @ np.diag([rx, ry])
        lin = self._normalization[:2, :2]
        attrs = {"fill": _flag("fill", fill)}
        outline = p.line_attributes(color, **line)
        if attrs["fill"]:
            attrs.update(color=p.color("color", color), rule=v.choice("rule", rule, p.RULES),
                         style=p.fill_style("style", style), edge=None)
        else:
            attrs.update(outline, closed=True)
        self._add("ellipse", {"center": self._ndc(c)[0], "axes": lin @ axes}, attrs)

    def circle(self, center, radius, color=None, fill=False, **attributes):
        """Append a circle (an ellipse with equal semi-axes)."""
        radius = p._nonnegative("radius", radius)
        self.ellipse(center, radius, radius, 0.0, color, fill, **attributes)

    def text(self, position, string, height=1.0, angle=0.0, color=None, font="stroke",
             align=("left", "base"), expansion=1.0, spacing=0.0, path="right",
             clip="character"):
        """Append a text string at ``position`` (world coordinates).

        ``height`` is the character height in world units; ``angle`` turns the
        baseline (radians); ``font``, ``align``, ``expansion``, ``spacing`` and
        ``path`` are those of :func:`scanline.draw.text`.  ``clip`` says how the
        string is clipped: ``"string"`` (all or none), ``"character"`` (each
        character all or none) or ``"stroke"`` (strokes and pixels).
        """
        if not isinstance(string, str):
            raise ArgumentTypeError(f"string must be a str, got {v._show(string)}")
        pos = p.points("position", [position], 1)
        attrs = p.text_attributes(color, font, align, expansion, spacing, path, clip)
        frame = self._normalization[:2, :2] @ p.text_frame(p._positive("height", height),
                                                           v.angle("angle", angle))
        self._add("text", {"anchor": self._ndc(pos)[0], "frame": frame, "string": string},
                  attrs)

    def markers(self, points, kind="plus", size=7.0, color=None):
        """Append polymarkers: ``kind`` one of dot, plus, asterisk, circle, cross
        (GKS types 1-5), ``size`` in device units (markers do not scale)."""
        pts = p.points("points", points, 1)
        attrs = p.marker_attributes(kind, size, color)
        self._add("markers", {"points": self._ndc(pts)}, attrs)

    # -- 3-D primitives -----------------------------------------------------------------------
    def set_camera(self, camera, name="camera"):
        """Define the camera ``name`` (or replace it) and make it the current one:
        the 3-D primitives created from now on are seen through it.  Cameras are
        looked up when the file is interpreted, so replacing one re-projects every
        primitive that uses it."""
        from ..projection import Camera

        if not isinstance(camera, Camera):
            raise ArgumentTypeError(f"camera must be a scanline.Camera, got {v._show(camera)}")
        _name(name)
        self._cameras[name] = camera
        self._current_camera = name

    def camera(self, name="camera"):
        """The camera called ``name``."""
        cams = self._cameras
        if name not in cams:
            known = ", ".join(repr(k) for k in cams) or "none yet (set_camera)"
            raise ArgumentValueError(f"no camera named {v._show(name)}; cameras: {known}")
        return cams[name]

    def _add3d(self, kind, geometry, attributes):
        name = self._current_camera
        if name is None:
            raise ArgumentValueError(
                f"a {kind} is seen through a camera: call set_camera(camera) first")
        geometry.update(camera=name, viewport=self._viewport_rect)
        self._add(kind, geometry, attributes)

    def polyline3d(self, points, color="white", closed=False, **line):
        """Append a 3-D polyline (world coordinates (N, 3)), seen through the current
        camera into the current viewport; ``line`` as :meth:`polyline`."""
        from ..transform3d.arrays import points as point_array

        pts, _ = point_array("points", points)
        if len(pts) < 1:
            raise ArgumentValueError("points needs at least 1 point")
        attrs = {"line": p.line_attributes(color, **line), "closed": _flag("closed", closed)}
        self._add3d("polyline3d", {"points": pts}, attrs)

    def mesh(self, mesh, color=None, depth_cue=None, background="black", **line):
        """Append the wireframe of a mesh -- a :class:`~scanline.mesh.Mesh` or any
        object :meth:`~scanline.mesh.Mesh.from_any` takes (trimesh, meshio, Open3D) --
        seen through the current camera into the current viewport: ``color`` (None:
        the mesh's own colors, else white), ``depth_cue`` as
        :func:`scanline.draw3d.wireframe` (fading toward ``background``), ``line`` as
        :meth:`polyline`."""
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
    def draw(self, fb, antialias=False, highlight="magenta"):
        """Draw the file on a frame buffer (:func:`scanline.display.interpret` on a
        :class:`~scanline.display.RasterDevice`)."""
        from .devices import RasterDevice
        from .interpreter import interpret

        interpret(self, RasterDevice(fb, antialias), highlight=highlight)

    def __repr__(self):
        return f"<DisplayFile: {len(self._segments)} segments, open: {self.open_segment!r}>"


def _flag(name, value):
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, numbers.Integral) and value in (0, 1):
        return bool(value)
    raise ArgumentTypeError(f"{name} must be True or False, got {v._show(value)}")
