"""Step tables of the 3-D line clippers (Hearn & Baker, section 12-5).

The steps are logged by the very functions :func:`scanline.clip.lines3d` and
:func:`scanline.clip.homogeneous` compile (:mod:`scanline._kernels.clip3d`), run here
as plain Python (:func:`scanline._kernels._jit.python`), so the table and the
clipped segment come from the same code and no compilation is waited for.
"""

from typing import Optional, Sequence, Tuple, Union, cast

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from .._kernels import clip3d as k
from ..clip import three_d
from ..clip.volumes import UNIT_CUBE, Volume, volume as as_volume
from .clip import _KINDS
from .table import Table, _cell

DEFAULT_VOLUME = ((0.0, 0.0, 0.0), (10.0, 10.0, 10.0))
#: A 3-D point, and a clip volume: a Volume or a box given as its corners (lo, hi).
_Point3 = Sequence[float]
_VolumeArg = Union[Volume, Tuple[_Point3, _Point3]]


class Clip3DTable(Table):
    """The table of a 3-D line clipper's trace, with the clipped segment."""

    #: The visible part: its two end points (x, y, z, and w when homogeneous), or
    #: None when nothing is visible.
    result: Optional[Tuple[Tuple[float, ...], Tuple[float, ...]]]


def code_string(code: float, planes: int = 6) -> str:
    """A region code as Hearn & Baker write it: bit 6 first (back front above below
    right left for a box)."""
    return format(int(code), f"0{planes}b")


def _point(p: Union[Sequence[float], NDArray[np.float64]]) -> str:
    return "(" + ", ".join(_cell(float(c)) for c in p) + ")"


def _run(method: str, p0: _Point3, p1: _Point3, vol: Volume,
         w: Optional[Tuple[float, float]], rows: int, columns: int
         ) -> Tuple[NDArray[np.float64], bool, NDArray[np.float64], NDArray[np.float64]]:
    """The segment through ``method``; ``w`` = (w0, w1) makes it homogeneous."""
    coords = [v.number(n, c) for n, c in zip(("x0", "y0", "z0"), p0)]
    coords += [v.number(n, c) for n, c in zip(("x1", "y1", "z1"), p1)]
    start = np.ones((2, 4))
    start[0, :3], start[1, :3] = coords[:3], coords[3:]
    if w is not None:
        start[0, 3], start[1, 3] = v.number("w0", w[0]), v.number("w1", w[1])
    log = np.full((rows, columns), np.nan)
    ok, ends = k.trace_segment(three_d.method_token(method, vol), start, vol.planes, log)
    used = int(np.sum(~np.isnan(log[:, 0])))
    return start, bool(ok), cast("NDArray[np.float64]", ends), log[:used]


def _volume(volume: Optional[_VolumeArg], w: Optional[Tuple[float, float]]) -> Volume:
    if w is not None and volume is None:
        return UNIT_CUBE
    return as_volume(DEFAULT_VOLUME if volume is None else volume)


def _describe(vol: Volume, w: Optional[Tuple[float, float]]) -> str:
    if w is not None:
        what = "homogeneous unit cube: 0 <= x, y, z <= w"
    elif vol.kind == "box":
        (x0, y0, z0), (x1, y1, z1) = vol.bounds
        what = (f"box x {_cell(x0)}..{_cell(x1)}, y {_cell(y0)}..{_cell(y1)}, "
                f"z {_cell(z0)}..{_cell(z1)}")
    elif vol.kind == "frustum":
        what = f"canonical frustum z <= x, y <= -z, -1 <= z <= {_cell(vol.z_min)}"
    else:
        what = f"convex polyhedron of {len(vol.planes)} planes"
    return what


def _result(ok: bool, ends: NDArray[np.float64], w: Optional[Tuple[float, float]]
            ) -> Tuple[Optional[Tuple[Tuple[float, ...], Tuple[float, ...]]], str]:
    if not ok:
        return None, "result: rejected, nothing is visible"
    n = 4 if w is not None else 3
    a, b = tuple(float(c) for c in ends[0, :n]), tuple(float(c) for c in ends[1, :n])
    line = f"result: visible from {_point(a)} to {_point(b)}"
    if w is not None:
        line += (f"; divided by w: {_point(np.array(a[:3]) / a[3])} to "
                 f"{_point(np.array(b[:3]) / b[3])}")
    return (a, b), line


def _title(name: str, start: NDArray[np.float64], w: Optional[Tuple[float, float]]) -> str:
    n = 4 if w is not None else 3
    return f"{name} clip {_point(start[0, :n])} -> {_point(start[1, :n])}"


def cohen_sutherland_3d(p0: _Point3, p1: _Point3, volume: Optional[_VolumeArg] = None,
                        w: Optional[Tuple[float, float]] = None) -> Clip3DTable:
    """3-D Cohen-Sutherland step by step: the six-bit region codes of both
    endpoints, their AND, and at each step the trivial accept or reject or the
    plane an outside endpoint is moved to.

    Codes are written bit 6 to bit 1: back, front, above, below, right, left (Hearn
    & Baker, section 12-5).  A moved endpoint lies exactly on its plane; its code is
    that of the crossing, computed from the boundary values at the original endpoints
    (not from the rounded point), and the bits of the planes it was moved onto stay
    0, so round-off where a segment enters through an edge or a corner cannot send it
    back and forth between two planes
    (:func:`scanline._kernels.clip3d.cohen_sutherland`).  ``w`` = (w0, w1)
    makes the endpoints homogeneous (x, y, z, w) and the volume the unit cube
    0 <= x, y, z <= w, clipped before the divide.  ``table.result`` is the clipped
    pair of points or None.

    Parameters
    ----------
    p0, p1 : (float, float, float)
        The segment's endpoints (x, y, z).
    volume : Volume or (lo, hi), optional
        The clip volume: a :class:`scanline.clip.volumes.Volume` or a box given by
        its corners ((xmin, ymin, zmin), (xmax, ymax, zmax)); default
        `DEFAULT_VOLUME` (0..10 on each axis), or the unit cube when `w` is given.
    w : (float, float), optional
        Homogeneous coordinates (w0, w1) of the endpoints; None (the default) clips
        the points as they are.

    Returns
    -------
    Table
        Columns step, code0, code1, and, decision, point, one row per step; ``table.result`` is the clipped pair of points (x, y, z, with w when `w`
        is given) or None when nothing is visible.

    Raises
    ------
    TypeError
        If a coordinate is not a real number or `volume` is neither a Volume nor a
        pair of corners.
    ValueError
        If the volume is degenerate.

    Examples
    --------
    >>> t = cohen_sutherland_3d((-5, 2, 5), (15, 22, 5))
    >>> for r in t.rows:
    ...     print(r["code0"], r["code1"], r["decision"], r["point"])
    000001 001010 clip P0 at left (bit 1) (0, 7, 5)
    000000 001010 clip P1 at right (bit 2) (10, 17, 5)
    000000 001000 clip P1 at above (bit 4) (3, 10, 5)
    000000 000000 accept: both codes 000000 None
    """
    vol = _volume(volume, w)
    start, ok, ends, log = _run("cohen-sutherland", p0, p1, vol, w,
                                k.cs_steps(len(vol.planes)), k.CS_COLUMNS)
    n = 4 if w is not None else 3
    rows = []
    for i, row in enumerate(log.tolist()):
        end, c0, c1, both, action, plane = row[:6]
        point = None
        if action == k.CS_CLIP:
            decision = f"clip P{int(end)} at {vol.names[int(plane) - 1]} (bit {int(plane)})"
            point = _point(row[6:6 + n])
        elif action == k.CS_ACCEPT:
            decision = f"accept: both codes {code_string(0, len(vol.planes))}"
        else:
            decision = f"reject: code0 AND code1 = {code_string(both, len(vol.planes))}"
        rows.append({"step": i, "code0": code_string(c0, len(vol.planes)),
                     "code1": code_string(c1, len(vol.planes)),
                     "and": code_string(both, len(vol.planes)), "decision": decision,
                     "point": point})
    result, line = _result(ok, ends, w)
    notes = [_describe(vol, w),
             "region code bits " + " ".join(str(b + 1) for b in reversed(range(len(vol.planes))))
             + " = " + " ".join(reversed(vol.names)) + "; point: the moved endpoint",
             "a moved endpoint is put exactly on its plane; its code is that of the exact "
             "crossing, and the bits of the planes it was moved onto stay 0 (at most one "
             "clip per plane and endpoint)",
             line]
    t = Clip3DTable(_title("Cohen-Sutherland 3-D", start, w),
              ["step", "code0", "code1", "and", "decision", "point"], rows, notes)
    t.result = result
    return t


def liang_barsky_3d(p0: _Point3, p1: _Point3, volume: Optional[_VolumeArg] = None,
                    w: Optional[Tuple[float, float]] = None) -> Clip3DTable:
    """3-D Liang-Barsky step by step: for each plane k the p_k and q_k (for a box
    p1 = -dx, q1 = x0 - xmin, p2 = dx, q2 = xmax - x0, ..., p5 = -dz,
    q5 = z0 - zmin, p6 = dz, q6 = zmax - z0), t = q_k / p_k, entering (p_k < 0)
    or leaving (p_k > 0), and u1, u2 so far.  ``w`` as in
    :func:`cohen_sutherland_3d` (then p_k and q_k are those of the homogeneous
    planes, e.g. q = w0 - x0 for x <= w).

    Parameters
    ----------
    p0, p1 : (float, float, float)
        The segment's endpoints (x, y, z).
    volume : Volume or (lo, hi), optional
        The clip volume: a :class:`scanline.clip.volumes.Volume` or a box given by
        its corners ((xmin, ymin, zmin), (xmax, ymax, zmax)); default
        `DEFAULT_VOLUME` (0..10 on each axis), or the unit cube when `w` is given.
    w : (float, float), optional
        Homogeneous coordinates (w0, w1) of the endpoints; None (the default) clips
        the points as they are.

    Returns
    -------
    Table
        Columns k, plane, p, q, t, kind, u1, u2, one row per plane; ``table.result`` is the clipped pair of points (x, y, z, with w when `w`
        is given) or None when nothing is visible.

    Raises
    ------
    TypeError
        If a coordinate is not a real number or `volume` is neither a Volume nor a
        pair of corners.
    ValueError
        If the volume is degenerate.

    Examples
    --------
    >>> t = liang_barsky_3d((-5, 2, 5), (15, 12, 5))
    >>> [(r["k"], r["p"], r["q"], r["u1"], r["u2"]) for r in t.rows][:2]
    [(1, -20.0, -5.0, 0.25, 1.0), (2, 20.0, 15.0, 0.25, 0.75)]
    >>> t.result
    ((0.0, 4.5, 5.0), (10.0, 9.5, 5.0))
    """
    vol = _volume(volume, w)
    start, ok, ends, log = _run("liang-barsky", p0, p1, vol, w, len(vol.planes),
                                k.PARAM_COLUMNS)
    rows = []
    for kk, p, q, r, kind, u1, u2 in log.tolist():
        rows.append({"k": int(kk), "plane": vol.names[int(kk) - 1], "p": p, "q": q,
                     "t": None if np.isnan(r) else r, "kind": _KINDS[int(kind)],
                     "u1": u1, "u2": u2})
    result, line = _result(ok, ends, w)
    notes = [_describe(vol, w),
             "p_k = d_k(P0) - d_k(P1), q_k = d_k(P0) (d_k: the boundary value, >= 0 "
             "inside); p_k < 0: entering, u1 = max(u1, q/p); p_k > 0: leaving, "
             "u2 = min(u2, q/p)",
             line]
    t = Clip3DTable(_title("Liang-Barsky 3-D", start, w),
              ["k", "plane", "p", "q", "t", "kind", "u1", "u2"], rows, notes)
    t.result = result
    return t
