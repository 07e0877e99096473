"""Adaptive flattening of Bezier segments by recursive subdivision (de Casteljau).

Arrays in, arrays out.  The API layer (:mod:`scanline.curves.flatten`) checks that
the control points are finite, the weights positive and the tolerance > 0.
"""

import numpy as np

from ._jit import helper, kernel

#: Control points with weights (homogeneous [w x, w]) or without: the token lengths
#: of ``weighted`` (:mod:`scanline._kernels.variants`), so a plain curve compiles no
#: weight code.
PLAIN = 1
WEIGHTED = 2


@helper
def _flat(stack, top, dim, tol2, proj, weighted):
    """True iff every control point of ``stack[top]`` ([w x, w] if ``weighted`` is the
    WEIGHTED token) lies
    within sqrt(tol2) of the chord *segment* from its first to its last point.

    Distance to a segment is a convex function, so its maximum over the convex hull
    of the control points -- which holds the curve -- is attained at a control point:
    the test bounds the distance from every curve point to the chord.  ``proj`` is
    work space for the projected points.
    """
    m = stack.shape[1]
    for i in range(m):
        r = 1.0 / stack[top, i, dim] if len(weighted) == WEIGHTED else 1.0
        for c in range(dim):
            proj[i, c] = stack[top, i, c] * r
    len2 = 0.0
    for c in range(dim):
        d = proj[m - 1, c] - proj[0, c]
        len2 += d * d
    inv = 1.0 / len2 if len2 > 0.0 else 0.0
    for i in range(1, m - 1):
        t = 0.0
        for c in range(dim):
            t += (proj[i, c] - proj[0, c]) * (proj[m - 1, c] - proj[0, c])
        t = min(max(t * inv, 0.0), 1.0)
        dist2 = 0.0
        for c in range(dim):
            e = proj[i, c] - (proj[0, c] + t * (proj[m - 1, c] - proj[0, c]))
            dist2 += e * e
        if not dist2 <= tol2:  # NaN counts as not flat (the depth limit stops it)
            return False
    return True


@helper
def _split(stack, top, work):
    """de Casteljau at u = 1/2 on ``stack[top]``: the right half stays in
    ``stack[top]``, the left half goes to ``stack[top + 1]`` (processed first)."""
    m, cols = stack.shape[1], stack.shape[2]
    for i in range(m):
        for c in range(cols):
            work[i, c] = stack[top, i, c]
    for r in range(m):
        for c in range(cols):
            stack[top + 1, r, c] = work[0, c]
            stack[top, m - 1 - r, c] = work[m - 1 - r, c]
        for i in range(m - 1 - r):
            for c in range(cols):
                work[i, c] = 0.5 * (work[i, c] + work[i + 1, c])


@helper
def _grow(out, count):
    bigger = np.empty((2 * out.shape[0] + count, out.shape[1]))
    for i in range(count):
        for c in range(out.shape[1]):
            bigger[i, c] = out[i, c]
    return bigger


@kernel
def subdivide(segments, weighted, tol2, max_depth, max_points):
    """Flatten Bezier segments.

    Parameters
    ----------
    segments : float64 (S, n + 1, dim + 1) or (S, n + 1, dim)
        Control points of S segments of degree n >= 1: homogeneous [w x, w] (weights
        > 0) if ``weighted``, else Cartesian.
    weighted : token
        WEIGHTED or PLAIN (a plain curve compiles no weight code).
    tol2 : float
        The squared tolerance.
    max_depth : int
        Subdivision stops at this depth whatever the flatness.
    max_points : int
        Once this many points are out, every remaining piece is taken as flat.

    Returns
    -------
    points : float64 (K, dim)
        For each segment its start point, then the end point of every piece of its
        subdivision, in order.
    firsts : int64 (S,)
        Index in ``points`` of each segment's start point.
    truncated : bool
        True if ``max_points`` cut the subdivision short.

    Notes
    -----
    The pieces waiting to be flattened are a stack in one array: the piece on top
    is tested; a flat piece is emitted and popped, any other is split in place (its
    right half stays, its left half is pushed), so pieces come out left to right.
    """
    S, m, cols = segments.shape
    dim = cols - 1 if len(weighted) == WEIGHTED else cols
    out = np.empty((max(64, 8 * S), dim))
    firsts = np.empty(S, np.int64)
    count = np.int64(0)     # (int64, not a literal 0: the helpers compile once)
    truncated = False
    stack = np.empty((max_depth + 1, m, cols))
    depths = np.empty(max_depth + 1, np.int64)
    work = np.empty((m, cols))
    proj = np.empty((m, dim))
    for s in range(S):
        if count + 1 > out.shape[0]:
            out = _grow(out, count)
        firsts[s] = count
        r = 1.0 / segments[s, 0, dim] if len(weighted) == WEIGHTED else 1.0
        for c in range(dim):
            out[count, c] = segments[s, 0, c] * r
        count += 1
        for i in range(m):
            for c in range(cols):
                stack[0, i, c] = segments[s, i, c]
        depths[0] = 0
        top = np.int64(0)
        while top >= 0:
            flat = _flat(stack, top, dim, tol2, proj, weighted)
            if flat or depths[top] >= max_depth or count + top >= max_points:
                if not flat and depths[top] < max_depth:
                    truncated = True
                if count + 1 > out.shape[0]:
                    out = _grow(out, count)
                r = 1.0 / stack[top, m - 1, dim] if len(weighted) == WEIGHTED else 1.0
                for c in range(dim):
                    out[count, c] = stack[top, m - 1, c] * r
                count += 1
                top -= 1
            else:
                _split(stack, top, work)
                depths[top] += 1
                depths[top + 1] = depths[top]
                top += 1
    return out[:count].copy(), firsts, truncated
