"""Adaptive flattening of Bezier segments by recursive subdivision (de Casteljau).

Arrays in, arrays out.  The API layer (:mod:`scanline.curves.flatten`) checks that
the control points are finite, the weights positive and the tolerance > 0.
"""

import numpy as np

from ._jit import helper, kernel


@helper
def _project(h, i, dim, out, k):
    """out[k] = the Cartesian point of homogeneous control point h[i] = [w x, w]."""
    w = h[i, dim]
    for c in range(dim):
        out[k, c] = h[i, c] / w


@helper
def _flat(h, dim, tol2):
    """True iff every control point lies within sqrt(tol2) of the chord *segment*
    from the first to the last (projected) control point.

    Distance to a segment is a convex function, so its maximum over the convex hull
    of the control points -- which holds the curve -- is attained at a control point:
    the test bounds the distance from every curve point to the chord.
    """
    m = h.shape[0]
    w0 = h[0, dim]
    w1 = h[m - 1, dim]
    len2 = 0.0
    for c in range(dim):
        d = h[m - 1, c] / w1 - h[0, c] / w0
        len2 += d * d
    for i in range(1, m - 1):
        wi = h[i, dim]
        t = 0.0
        if len2 > 0.0:
            for c in range(dim):
                t += (h[i, c] / wi - h[0, c] / w0) * (h[m - 1, c] / w1 - h[0, c] / w0)
            t /= len2
            if t < 0.0:
                t = 0.0
            elif t > 1.0:
                t = 1.0
        dist2 = 0.0
        for c in range(dim):
            a = h[0, c] / w0
            q = a + t * (h[m - 1, c] / w1 - a)
            e = h[i, c] / wi - q
            dist2 += e * e
        if not dist2 <= tol2:  # NaN counts as not flat (the depth limit stops it)
            return False
    return True


@helper
def _split(h, left, right, work):
    """de Casteljau at u = 1/2: ``left`` and ``right`` get the two halves of ``h``."""
    m, cols = h.shape
    for i in range(m):
        for c in range(cols):
            work[i, c] = h[i, c]
    for r in range(m):
        for c in range(cols):
            left[r, c] = work[0, c]
            right[m - 1 - r, c] = work[m - 1 - r, c]
        for i in range(m - 1 - r):
            for c in range(cols):
                work[i, c] = 0.5 * (work[i, c] + work[i + 1, c])


@helper
def _grow(out, count):
    if count < out.shape[0]:
        return out
    bigger = np.empty((2 * out.shape[0], out.shape[1]))
    bigger[:count] = out[:count]
    return bigger


@kernel
def subdivide(segments, tol2, max_depth, max_points):
    """Flatten Bezier segments given in homogeneous coordinates.

    Parameters
    ----------
    segments : float64 (S, n + 1, dim + 1)
        Control points [w x, w] of S segments of degree n >= 1, weights > 0.
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
    """
    S, m, cols = segments.shape
    dim = cols - 1
    out = np.empty((64, dim))
    firsts = np.empty(S, np.int64)
    count = 0
    truncated = False
    stack = np.empty((max_depth + 1, m, cols))
    depths = np.empty(max_depth + 1, np.int64)
    cur = np.empty((m, cols))
    left = np.empty((m, cols))
    work = np.empty((m, cols))
    for s in range(S):
        out = _grow(out, count)
        firsts[s] = count
        _project(segments[s], 0, dim, out, count)
        count += 1
        for i in range(m):
            for c in range(cols):
                cur[i, c] = segments[s, i, c]
        depth = 0
        top = 0
        while True:
            full = count + top >= max_points
            if full or depth >= max_depth or _flat(cur, dim, tol2):
                if full and not _flat(cur, dim, tol2):
                    truncated = True
                out = _grow(out, count)
                _project(cur, m - 1, dim, out, count)
                count += 1
                if top == 0:
                    break
                top -= 1
                for i in range(m):
                    for c in range(cols):
                        cur[i, c] = stack[top, i, c]
                depth = depths[top]
            else:
                _split(cur, left, stack[top], work)
                depth += 1
                depths[top] = depth
                top += 1
                for i in range(m):
                    for c in range(cols):
                        cur[i, c] = left[i, c]
    return out[:count].copy(), firsts, truncated
