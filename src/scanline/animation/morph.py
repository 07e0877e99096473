"""Morphing: shapes changing from one key frame to the next (notes, chapter 6, Q4:
"transformation of one object into another"; Hearn & Baker §16-5, "Morphing"), and
Beier–Neely feature-based image morphing.

Two key frames of a shape may have different numbers of vertices.  Hearn & Baker
first *equalize* them: the key frame with fewer edges gets its edges divided so that
both have as many as the other.  With L_max and L_min edges,

    N_e = L_max mod L_min,   N_s = int(L_max / L_min),

N_e edges of the smaller key frame are divided into N_s + 1 sections and the other
L_min - N_e edges into N_s sections (N_e (N_s + 1) + (L_min - N_e) N_s = L_max).  In
terms of vertices, with V_max and V_min vertices of open polylines,

    N_ls = (V_max - 1) mod (V_min - 1),   N_p = int((V_max - 1) / (V_min - 1)),

N_p points are added to N_ls line sections and N_p - 1 points to the remaining ones.
Then corresponding vertices are interpolated.  :func:`equalize` does this (the longest
edges get the extra sections), :func:`morph` interpolates.

>>> import scanline as sl
>>> triangle = [(0, 0), (4, 0), (0, 3)]
>>> square = [(0, 0), (4, 0), (4, 4), (0, 4)]
>>> a, b = sl.animation.equalize(triangle, square)
>>> a.tolist()                       # the longest edge, (4, 0) -> (0, 3), is split
[[0.0, 0.0], [4.0, 0.0], [2.0, 1.5], [0.0, 3.0]]
>>> sl.animation.morph(triangle, square, 0.5).tolist()
[[0.0, 0.0], [4.0, 0.0], [3.0, 2.75], [0.0, 3.5]]
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Literal, NamedTuple, Union, overload

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentValueError
from ._checks import flag, floats
from .easing import fractions

if TYPE_CHECKING:
    from .._typing import Mode
    from ..framebuffer import FrameBuffer

#: An image to morph: a frame buffer of mode "L", "RGB" or "RGBA", or a uint8 array in
#: image order (h, w) or (h, w, 1|3|4).
MorphImage = Union["FrameBuffer", NDArray[np.uint8]]


class Equalization(NamedTuple):
    """Hearn & Baker's counts for equalizing two key frames (§16-5).

    ``edges_max``, ``edges_min``: L_max, L_min; ``n_e``, ``n_s``: N_e = L_max mod
    L_min edges are divided into N_s + 1 = int(L_max / L_min) + 1 sections, the rest
    into N_s.  ``vertices_max``, ``vertices_min``: V_max, V_min; ``n_ls``, ``n_p``:
    N_p points are added to N_ls = (V_max - 1) mod (V_min - 1) line sections and N_p - 1
    to the rest (the vertex form, which counts an open polyline's vertices).

    Examples
    --------
    A quadrilateral to a hexagon: 6 mod 4 = 2 of the quadrilateral's edges are divided
    into int(6 / 4) + 1 = 2 sections, the other 2 stay whole (2 · 2 + 2 · 1 = 6).

    >>> import scanline as sl
    >>> counts = sl.animation.equalization(4, 6)
    >>> counts.n_e, counts.n_s
    (2, 1)
    """

    edges_max: int
    edges_min: int
    n_e: int
    n_s: int
    vertices_max: int
    vertices_min: int
    n_ls: int
    n_p: int


def equalization(count_a: int, count_b: int, closed: bool = True) -> Equalization:
    """The counts of :class:`Equalization` for shapes of ``count_a`` and ``count_b``
    vertices (closed polygons: as many edges as vertices; open polylines: one fewer).

    Parameters
    ----------
    count_a, count_b : int
        Vertex counts: >= 3 for closed polygons, >= 2 for open polylines.
    closed : bool
        Closed polygons (default) or open polylines.

    Returns
    -------
    Equalization
        L_max, L_min, N_e, N_s, V_max, V_min, N_ls, N_p.

    Raises
    ------
    ArgumentTypeError
        For counts that are not integers, or a ``closed`` that is not a bool.
    ArgumentValueError
        For counts below the minimum.

    Examples
    --------
    Open polylines of 3 and 4 vertices (Hearn & Baker's triangle -> quadrilateral
    case): L_max = 3, L_min = 2, N_e = 3 mod 2 = 1, N_s = 1; N_ls = 3 mod 2 = 1, N_p = 1.

    >>> equalization(3, 4, closed=False)
    Equalization(edges_max=3, edges_min=2, n_e=1, n_s=1, vertices_max=4, vertices_min=3, n_ls=1, n_p=1)
    """
    closed = flag("closed", closed)
    minimum = 3 if closed else 2
    va = v.positive_int("count_a", count_a, minimum=minimum)
    vb = v.positive_int("count_b", count_b, minimum=minimum)
    vmax, vmin = max(va, vb), min(va, vb)
    lmax, lmin = (vmax, vmin) if closed else (vmax - 1, vmin - 1)
    return Equalization(lmax, lmin, lmax % lmin, lmax // lmin, vmax, vmin,
                        (vmax - 1) % (vmin - 1), (vmax - 1) // (vmin - 1))


def _shape(name: str, value: object, closed: bool) -> NDArray[np.float64]:
    a = floats(name, value, "an array of vertices")
    minimum = 3 if closed else 2
    if a.ndim != 2 or len(a) < minimum or a.shape[1] < 1:
        raise ArgumentValueError(
            f"{name} must have shape (V, dim) with V >= {minimum} "
            f"({'a closed polygon' if closed else 'an open polyline'}), got shape {a.shape}")
    if not np.isfinite(a).all():
        raise ArgumentValueError(f"{name} must be finite, got {v._show(a.tolist())}")
    return a


def _subdivide(points: NDArray[np.float64], edges: int,
               closed: bool) -> tuple[NDArray[np.float64], NDArray[np.bool_]]:
    """``points`` with its edges divided: edge i into ``sections[i]`` equal parts.
    Returns (vertices, added mask)."""
    lengths = np.linalg.norm(np.roll(points, -1, axis=0) - points, axis=1)
    if not closed:
        lengths = lengths[:-1]
    lmin = len(lengths)
    n_e, n_s = edges % lmin, edges // lmin
    sections = np.full(lmin, n_s)
    longest = np.argsort(-lengths, kind="stable")[:n_e]
    sections[longest] += 1
    out: list[NDArray[np.float64]] = []
    added: list[bool] = []
    for i in range(lmin):
        p, q = points[i], points[(i + 1) % len(points)]
        for k in range(sections[i]):
            out.append(p + (q - p) * (k / sections[i]))
            added.append(k > 0)
    if not closed:
        out.append(points[-1])
        added.append(False)
    return np.array(out), np.array(added)


def _align(reference: NDArray[np.float64], shape: NDArray[np.float64], added: NDArray[np.bool_]
           ) -> tuple[NDArray[np.float64], NDArray[np.bool_]]:
    """The cyclic shift (and direction) of closed ``shape`` closest to ``reference``."""
    best: tuple[float, NDArray[np.float64], NDArray[np.bool_]] | None = None
    for candidate, mask in ((shape, added), (shape[::-1], added[::-1])):
        for shift in range(len(shape)):
            rolled = np.roll(candidate, -shift, axis=0)
            cost = float(((rolled - reference) ** 2).sum())
            if best is None or cost < best[0] - 1e-12:
                best = (cost, rolled, np.roll(mask, -shift))
    assert best is not None                     # (a shape has vertices)
    return best[1], best[2]


@overload
def equalize(shape_a: ArrayLike, shape_b: ArrayLike, *more: ArrayLike, closed: bool = ...,
             align: bool = ..., return_added: Literal[False] = ...
             ) -> tuple[NDArray[np.float64], ...]: ...
@overload
def equalize(shape_a: ArrayLike, shape_b: ArrayLike, *more: ArrayLike, closed: bool = ...,
             align: bool = ..., return_added: bool
             ) -> tuple[NDArray[np.float64] | NDArray[np.bool_], ...]: ...
def equalize(shape_a: ArrayLike, shape_b: ArrayLike, *more: ArrayLike, closed: bool = True,
             align: bool = False, return_added: bool = False
             ) -> tuple[NDArray[np.float64] | NDArray[np.bool_], ...]:
    """Give key-frame shapes equal vertex counts (Hearn & Baker, §16-5).

    Parameters
    ----------
    shape_a, shape_b, *more : array_like (V, dim)
        Two or more key frames of one shape (polygons or polylines in 2-D or 3-D).
        Each shape with fewer edges than the largest gets its edges divided.
    closed : bool
        Closed polygons (V edges; default) or open polylines (V - 1 edges).
    align : bool
        Closed shapes: after equalizing, start each shape (and run it in the
        direction) that brings its vertices closest to the first shape's, so that
        the morph does not twist.  Default False: vertex 0 goes to vertex 0.
    return_added : bool
        Also return, per shape, a boolean mask of the vertices added.

    Returns
    -------
    tuple of numpy.ndarray
        The shapes with equal vertex counts, float (V, dim) (and, with
        ``return_added``, after them the masks, bool (V,)).

    Raises
    ------
    ArgumentTypeError
        For shapes that are not numbers, or flags that are not bools.
    ArgumentValueError
        For shapes that are not (V, dim) arrays of finite numbers with V >= 3 (closed)
        or V >= 2 (open), or shapes of different dimensions.

    Notes
    -----
    Of the smaller shape's L_min edges, the N_e = L_max mod L_min longest are divided
    into N_s + 1 sections and the others into N_s (N_s = int(L_max / L_min)); Hearn &
    Baker leave open which edges take the extra sections.

    Examples
    --------
    A segment against a two-segment tent: the segment's one edge is divided in two at
    its midpoint, the added vertex.

    >>> import scanline as sl
    >>> a, b, added_a, added_b = sl.animation.equalize(
    ...     [(0, 0), (2, 0)], [(0, 0), (1, 1), (2, 0)], closed=False, return_added=True)
    >>> a.tolist(), added_a.tolist(), added_b.tolist()
    ([[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]], [False, True, False], [False, False, False])
    """
    closed, align = flag("closed", closed), flag("align", align)
    return_added = flag("return_added", return_added)
    shapes = [_shape(name, s, closed) for name, s in
              zip(["shape_a", "shape_b"] + [f"more[{i}]" for i in range(len(more))],
                  (shape_a, shape_b) + more)]
    dims = {s.shape[1] for s in shapes}
    if len(dims) != 1:
        raise ArgumentValueError(f"the shapes must have one dimension, got {sorted(dims)}")
    edges = max(len(s) if closed else len(s) - 1 for s in shapes)
    out: list[NDArray[np.float64]] = []
    masks: list[NDArray[np.bool_]] = []
    for s in shapes:
        own = len(s) if closed else len(s) - 1
        if own == edges:
            out.append(s.copy())
            masks.append(np.zeros(len(s), bool))
        else:
            new, added = _subdivide(s, edges, closed)
            out.append(new)
            masks.append(added)
    if align and closed:
        for i in range(1, len(out)):
            out[i], masks[i] = _align(out[0], out[i], masks[i])
    return tuple(out) + tuple(masks) if return_added else tuple(out)


def morph(shape_a: ArrayLike, shape_b: ArrayLike, t: ArrayLike, closed: bool = True,
          align: bool = False) -> NDArray[np.float64]:
    """The in-between shape at fraction ``t`` of the way from ``shape_a`` to
    ``shape_b``: the two are equalized (:func:`equalize`), then each vertex moves
    linearly, P(t) = A + t (B - A).

    ``t`` may be an array: the result is then (len(t), V, dim).

    Parameters
    ----------
    shape_a, shape_b : array_like (V, dim)
        The key frames (polygons or polylines in 2-D or 3-D).
    t : float or array_like
        Fractions in [0, 1]: 0 gives ``shape_a``, 1 ``shape_b`` (equalized).
    closed, align : bool
        As :func:`equalize`.

    Returns
    -------
    numpy.ndarray
        (V, dim), or (len(t), V, dim) for an array ``t``.

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        As :func:`equalize`, and for fractions outside [0, 1].

    Examples
    --------
    Halfway from a segment to a tent, the segment's added midpoint (1, 0) has risen
    halfway to the apex (1, 1):

    >>> import scanline as sl
    >>> line, tent = [(0, 0), (2, 0)], [(0, 0), (1, 1), (2, 0)]
    >>> sl.animation.morph(line, tent, 0.5, closed=False).tolist()
    [[0.0, 0.0], [1.0, 0.5], [2.0, 0.0]]
    >>> sl.animation.morph(line, tent, [0, 0.25, 1], closed=False).shape
    (3, 3, 2)
    """
    a, b = equalize(shape_a, shape_b, closed=closed, align=align)
    ts = fractions(t)
    if ts.ndim == 0:
        return a + float(ts) * (b - a)
    return a[None] + ts.reshape(-1, 1, 1) * (b - a)[None]


# -- Beier–Neely ----------------------------------------------------------------------------
def _image(name: str, image: object) -> tuple[NDArray[np.uint8], Mode | int]:
    """(bottom-up uint8 storage (h, w, c), how to give the result back: the frame
    buffer's mode, or the array's number of dimensions)."""
    from ..framebuffer import FrameBuffer

    if isinstance(image, FrameBuffer):
        if image.mode not in ("L", "RGB", "RGBA"):
            raise ArgumentValueError(f"{name} is a mode {image.mode!r} frame buffer; morphing "
                                     "blends levels, so use mode 'L', 'RGB' or 'RGBA'")
        return image._raster()[0], image.mode
    try:
        a = np.asarray(image)
    except (TypeError, ValueError, OverflowError):
        a = np.asarray(None)
    if a.dtype != np.uint8 or a.ndim not in (2, 3) or (a.ndim == 3 and a.shape[2] not in (1, 3, 4)):
        raise ArgumentValueError(f"{name} must be a FrameBuffer or a uint8 image array (h, w) or "
                                 f"(h, w, 1|3|4), got dtype {a.dtype}, shape {a.shape}")
    storage = a[::-1] if a.ndim == 3 else a[::-1, :, None]
    return np.ascontiguousarray(storage), a.ndim


#: Feature lines: end points within +-COORD_LIMIT (as every device coordinate), and
#: lines at least MIN_LENGTH long (a shorter line has no direction to measure u and v
#: by: 1 / |d|^2 overflows or is lost to rounding).
MIN_LENGTH = 1e-6

#: The weights (|d|^p / (a + dist))^b must stay within 10**+-WEIGHT_EXPONENT over the
#: image, so that neither their sum nor the weighted displacements overflow, and the
#: best line's weight at the farthest pixel does not underflow to 0.
WEIGHT_EXPONENT = 250


def _lines(name: str, value: object, count: int | None = None) -> NDArray[np.float64]:
    a = floats(name, value, "an (n, 4) array of lines x0, y0, x1, y1")
    if a.ndim == 3 and a.shape[1:] == (2, 2):
        a = a.reshape(-1, 4)
    if a.ndim != 2 or a.shape[1] != 4 or len(a) < 1:
        raise ArgumentValueError(f"{name} must be an (n, 4) array of lines x0, y0, x1, y1 "
                                 f"with n >= 1, got shape {a.shape}")
    if count is not None and len(a) != count:
        raise ArgumentValueError(f"{name} must pair with the other line set: {count} lines, "
                                 f"got {len(a)}")
    if not np.isfinite(a).all():
        raise ArgumentValueError(f"{name} must be finite, got {v._show(a.tolist())}")
    far = np.abs(a) > v.COORD_LIMIT
    if far.any():
        k = int(np.flatnonzero(far.any(axis=1))[0])
        raise ArgumentValueError(
            f"{name}[{k}] = {v._show(a[k].tolist())} has an end point beyond the device "
            f"coordinate range +-{v.COORD_LIMIT}; give feature lines near the image")
    length = np.hypot(a[:, 2] - a[:, 0], a[:, 3] - a[:, 1])
    zero = length == 0
    if zero.any():
        raise ArgumentValueError(f"{name}[{int(np.flatnonzero(zero)[0])}] has zero length; a "
                                 "feature line needs two different end points")
    short = length < MIN_LENGTH
    if short.any():
        k = int(np.flatnonzero(short)[0])
        raise ArgumentValueError(
            f"{name}[{k}] has length {length[k]:.3g}, too short to give a direction; a "
            f"feature line needs end points at least {MIN_LENGTH:g} pixels apart")
    return np.ascontiguousarray(a)


def _between(lines: NDArray[np.float64], t: float) -> None:
    """Check that the interpolated lines L(t) keep a length (a pair of lines turning
    through a point, such as a line and its reverse, collapses halfway)."""
    length = np.hypot(lines[:, 2] - lines[:, 0], lines[:, 3] - lines[:, 1])
    short = length < MIN_LENGTH
    if short.any():
        k = int(np.flatnonzero(short)[0])
        raise ArgumentValueError(
            f"at t={t:g} feature line {k} (lines_a[{k}] -> lines_b[{k}]) shrinks to length "
            f"{length[k]:.3g}: its end points meet, and the warp is undefined there; give "
            "the pair end points that do not cross (not a line and its reverse), or "
            "another t")


def _weights(a: object, b: object, p: object) -> tuple[float, float, float]:
    fa, fb, fp = v.number("a", a), v.number("b", b), v.number("p", p)
    if fa <= 0 or fb < 0 or fp < 0:
        raise ArgumentValueError(f"need a > 0, b >= 0 and p >= 0 (the weight (length^p / "
                                 f"(a + dist))^b), got a={fa}, b={fb}, p={fp}")
    return fa, fb, fp


def _weight_range(lines: NDArray[np.float64], size: tuple[int, ...], a: float, b: float,
                  p: float) -> None:
    """Refuse weights (|d|^p / (a + dist))^b that overflow at a line or underflow far
    from every line, over an image of ``size`` (h, w) pixels: both would make the
    kernel's weighted mean 0 / 0 or inf / inf."""
    h, w = size
    if b == 0 or h == 0 or w == 0:
        return                                   # every weight is 1
    with np.errstate(all="ignore"):
        log_length = np.log(np.hypot(lines[:, 2] - lines[:, 0], lines[:, 3] - lines[:, 1]))
        log_lp = p * log_length if p else np.zeros(len(lines))
        # the farthest pixel of the image from each segment is a corner (the distance
        # to a segment is convex)
        corners = np.array([[0.0, 0.0], [w - 1.0, 0.0], [0.0, h - 1.0], [w - 1.0, h - 1.0]])
        far = np.zeros(len(lines))
        for cx, cy in corners:
            far = np.maximum(far, _segment_distance(lines, cx, cy))
        base_high = float(log_lp.max()) - math.log(a)          # log of |d|^p / a
        base_low = float((log_lp - np.log(a + far)).max())
        highest, lowest = b * base_high, b * base_low
    limit = WEIGHT_EXPONENT * math.log(10)
    bounds = (float(log_lp.max()), base_high, base_low, highest, lowest)
    if not (all(math.isfinite(x) and abs(x) <= limit for x in bounds[:2])
            and all(math.isfinite(x) and x >= -limit for x in bounds[2:3] + bounds[4:])
            and highest <= limit):
        def power(x: float) -> str:
            e = x / math.log(10)
            if not math.isfinite(e) or abs(e) > 1e6:
                return "0" if e < 0 else "infinity"
            return f"1e{e:+.0f}"
        raise ArgumentValueError(
            f"a={a:g}, b={b:g}, p={p:g}: the line weights (length^p / (a + dist))^b would "
            f"range from about {power(lowest)} (the farthest pixel) to {power(highest)} (on "
            f"a line), beyond 1e+-{WEIGHT_EXPONENT}, where floating point loses them; use a "
            "larger a, a smaller b or p (Beier and Neely suggest a small positive a, b in "
            "[0.5, 2] and p in [0, 1])")


def _segment_distance(lines: NDArray[np.float64], x: float, y: float) -> NDArray[np.float64]:
    """Distance from the point (x, y) to each segment of ``lines``."""
    px, py, qx, qy = lines.T
    dx, dy = qx - px, qy - py
    u = np.clip(((x - px) * dx + (y - py) * dy) / (dx * dx + dy * dy), 0.0, 1.0)
    out: NDArray[np.float64] = np.hypot(px + u * dx - x, py + u * dy - y)
    return out


def _result(storage: NDArray[np.uint8], how: Mode | int) -> MorphImage:
    from ..framebuffer import FrameBuffer

    if isinstance(how, str):
        fb = FrameBuffer(storage.shape[1], storage.shape[0], mode=how)
        fb._buf[...] = storage
        return fb
    image = storage[::-1]
    return np.ascontiguousarray(image if how == 3 else image[:, :, 0])


@overload
def beier_neely(image_a: FrameBuffer, image_b: MorphImage, lines_a: ArrayLike,
                lines_b: ArrayLike, t: float, a: float = ..., b: float = ...,
                p: float = ...) -> FrameBuffer: ...
@overload
def beier_neely(image_a: NDArray[np.uint8], image_b: MorphImage, lines_a: ArrayLike,
                lines_b: ArrayLike, t: float, a: float = ..., b: float = ...,
                p: float = ...) -> NDArray[np.uint8]: ...
def beier_neely(image_a: MorphImage, image_b: MorphImage, lines_a: ArrayLike,
                lines_b: ArrayLike, t: float, a: float = 1.0, b: float = 2.0,
                p: float = 0.5) -> MorphImage:
    """Beier–Neely feature-based morph of two images at fraction ``t``.

    The feature lines are interpolated, L(t) = L_A + t (L_B - L_A) (end points);
    image A is warped so that its lines L_A move to L(t), image B so that L_B move to
    L(t), and the two are cross-dissolved, (1 - t) A' + t B'.  With identical line
    sets the warps are the identity and the morph is a plain cross-dissolve.

    Parameters
    ----------
    image_a, image_b : FrameBuffer or numpy.ndarray
        Images of one size: frame buffers of mode "L", "RGB" or "RGBA", or uint8
        arrays in image order (top row first).
    lines_a, lines_b : array_like (n, 4)
        Corresponding feature lines (x0, y0, x1, y1) in device coordinates (x right,
        y up, pixel centers at integers, y = 0 the bottom row — also for arrays).
    t : float
        0 gives image A, 1 image B.
    a, b, p : float
        The weight of each line at a pixel, (length^p / (a + dist))^b: a > 0 (how
        closely pixels follow the lines), b (how fast influence falls off with
        distance), p (how much longer lines count).

    Returns
    -------
    FrameBuffer or numpy.ndarray
        Of image_a's kind, size and mode.

    Raises
    ------
    ArgumentTypeError
        For lines, ``t``, ``a``, ``b`` or ``p`` that are not numbers.
    ArgumentValueError
        For images of another kind, mode or size, line sets that are not (n, 4) of one
        n, lines of zero (or under 1e-6) length or beyond the device coordinate range,
        in-between lines that collapse, ``t`` outside [0, 1], or weights that would
        overflow or underflow over the image.

    Notes
    -----
    Compiled kernel :func:`scanline._kernels.morph.field_morph`; the source images
    are sampled bilinearly with edges clamped, and the result rounded half up.

    References
    ----------
    T. Beier and S. Neely, "Feature-based image metamorphosis", *SIGGRAPH '92*,
    Computer Graphics 26(2), 1992, pp. 35-42.

    Examples
    --------
    With one line set for both images the warps are the identity: a quarter of the
    way from black to 200 is a cross-dissolve, 0.75 · 0 + 0.25 · 200 = 50.

    >>> import numpy as np
    >>> import scanline as sl
    >>> black, gray = np.zeros((2, 3), np.uint8), np.full((2, 3), 200, np.uint8)
    >>> lines = [(0, 0, 2, 0)]
    >>> sl.animation.beier_neely(black, gray, lines, lines, 0.25).tolist()
    [[50, 50, 50], [50, 50, 50]]
    """
    sa, how = _image("image_a", image_a)
    sb, _ = _image("image_b", image_b)
    if sa.shape != sb.shape:
        raise ArgumentValueError(f"image_a and image_b must have one size and mode, got "
                                 f"storage {sa.shape} and {sb.shape}")
    la = _lines("lines_a", lines_a)
    lb = _lines("lines_b", lines_b, len(la))
    ts = fractions(t)
    if ts.ndim != 0:
        raise ArgumentValueError(f"t must be one fraction in [0, 1], got an array of shape "
                                 f"{ts.shape}")
    fraction = float(ts)
    lines = np.ascontiguousarray(la + fraction * (lb - la))
    _between(lines, fraction)
    weights = _weights(a, b, p)
    _weight_range(lines, sa.shape[:2], *weights)
    return _result(_morph(sa, sb, lines, la, lb, fraction, *weights), how)


@overload
def warp(image: FrameBuffer, lines_from: ArrayLike, lines_to: ArrayLike, a: float = ...,
         b: float = ..., p: float = ...) -> FrameBuffer: ...
@overload
def warp(image: NDArray[np.uint8], lines_from: ArrayLike, lines_to: ArrayLike,
         a: float = ..., b: float = ..., p: float = ...) -> NDArray[np.uint8]: ...
def warp(image: MorphImage, lines_from: ArrayLike, lines_to: ArrayLike, a: float = 1.0,
         b: float = 2.0, p: float = 0.5) -> MorphImage:
    """Beier–Neely's field warp of one image: the features on ``lines_from`` move to
    ``lines_to`` (same conventions as :func:`beier_neely`).

    Parameters
    ----------
    image : FrameBuffer or numpy.ndarray
        A frame buffer of mode "L", "RGB" or "RGBA", or a uint8 array in image order.
    lines_from, lines_to : array_like (n, 4)
        Corresponding feature lines (x0, y0, x1, y1) in device coordinates (y up).
    a, b, p : float
        The line weights, as :func:`beier_neely`.

    Returns
    -------
    FrameBuffer or numpy.ndarray
        Of the image's kind, size and mode.

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        As :func:`beier_neely`.

    Examples
    --------
    One line moved one pixel to the right moves the whole image with it (one line
    gives a rigid motion); the left column repeats the clamped edge.

    >>> import numpy as np
    >>> import scanline as sl
    >>> row = np.array([[10, 20, 30]], np.uint8)
    >>> sl.animation.warp(row, [(0, 0, 0, 1)], [(1, 0, 1, 1)]).tolist()
    [[10, 10, 20]]
    """
    storage, how = _image("image", image)
    src = _lines("lines_from", lines_from)
    dst = _lines("lines_to", lines_to, len(src))
    weights = _weights(a, b, p)
    _weight_range(dst, storage.shape[:2], *weights)
    return _result(_morph(storage, storage, dst, src, src, 0.0, *weights), how)


def _morph(sa: NDArray[np.uint8], sb: NDArray[np.uint8], lines: NDArray[np.float64],
           la: NDArray[np.float64], lb: NDArray[np.float64], t: float, a: float, b: float,
           p: float) -> NDArray[np.uint8]:
    from .._kernels._jit import call
    from .._kernels.morph import field_morph

    out = np.empty_like(sa)
    call(field_morph, 20 * sa.shape[0] * sa.shape[1] * len(lines), sa, sb,
         line_table(lines, la, lb, p), float(t), float(a), float(b), out)
    return out


def line_table(lines: NDArray[np.float64], lines_a: NDArray[np.float64],
               lines_b: NDArray[np.float64], p: float) -> NDArray[np.float64]:
    """The per-line constants that :func:`scanline._kernels.morph.field_morph` reads:
    the destination line, its direction, 1/|d|², 1/|d|, |d|^p and unit normal, and for
    each image the differences P' - P, d' - d, n' - n."""
    from .._kernels.morph import (A_OFFSET, COLUMNS, DX, DY, INV_LENGTH, INV_LENGTH2,
                                  LENGTH_P, NX, NY, PX, PY, QX, QY)

    n = len(lines)
    t = np.empty((n, COLUMNS))
    d = lines[:, 2:] - lines[:, :2]
    length = np.hypot(d[:, 0], d[:, 1])
    t[:, PX:PY + 1] = lines[:, :2]
    t[:, QX:QY + 1] = lines[:, 2:]
    t[:, DX:DY + 1] = d
    t[:, INV_LENGTH2] = 1.0 / (length * length)
    t[:, INV_LENGTH] = 1.0 / length
    t[:, LENGTH_P] = length ** p
    normal = np.stack([-d[:, 1], d[:, 0]], 1) / length[:, None]
    t[:, NX:NY + 1] = normal
    for k, src in enumerate((lines_a, lines_b)):
        ds = src[:, 2:] - src[:, :2]
        ls = np.hypot(ds[:, 0], ds[:, 1])
        base = A_OFFSET + 6 * k
        t[:, base:base + 2] = src[:, :2] - lines[:, :2]
        t[:, base + 2:base + 4] = ds - d
        t[:, base + 4:base + 6] = np.stack([-ds[:, 1], ds[:, 0]], 1) / ls[:, None] - normal
    return np.ascontiguousarray(t)
