"""Curve evaluation kernels: de Casteljau (Bezier) and de Boor (B-spline).

Arrays in, arrays out; the API layer (:mod:`scanline.curves`) checks shapes, that the
parameters lie in the curve's domain and that the knot vector is non-decreasing, so
every index computed here stays inside its array.
"""

import numpy as np

from ._jit import helper, inline, kernel


#: Parameters processed together by :func:`de_casteljau`: the innermost loop runs
#: over them, which the compiler vectorizes (measured 2x faster than point by point).
BLOCK = 8


@kernel
def de_casteljau(points, u, out):
    """out[i] = the Bezier curve with control ``points`` (n+1, dim) at ``u[i]``.

    de Casteljau's repeated linear interpolation
    Pᵢʳ = (1 − u) Pᵢʳ⁻¹ + u Pᵢ₊₁ʳ⁻¹, for BLOCK parameters at a time.
    """
    m, dim = points.shape
    n = u.shape[0]
    work = np.empty((m, BLOCK))
    t = np.empty(BLOCK)
    s = np.empty(BLOCK)
    for start in range(0, n, BLOCK):
        count = min(BLOCK, n - start)
        for b in range(BLOCK):
            t[b] = u[start + b] if b < count else 0.0
            s[b] = 1.0 - t[b]
        for c in range(dim):
            for j in range(m):
                for b in range(BLOCK):
                    work[j, b] = points[j, c]
            for r in range(m - 1, 0, -1):
                for j in range(r):
                    for b in range(BLOCK):
                        work[j, b] = s[b] * work[j, b] + t[b] * work[j + 1, b]
            for b in range(count):
                out[start + b, c] = work[0, b]


@helper
def last_at_most(values, lo, hi, t):
    """Binary search: the last index l in [lo, hi] with values[l] <= t (values
    non-decreasing, values[lo] <= t)."""
    a = lo
    b = hi
    while a < b:
        mid = (a + b + 1) // 2
        if values[mid] <= t:
            a = mid
        else:
            b = mid - 1
    return a


@inline
def clamped_index(f, top):
    """int(f) limited to [0, top]; NaN gives 0 (never an index outside the array)."""
    if not f >= 0.0:
        return 0
    if f >= top:
        return top
    return int(f)


@helper
def find_span(knots, lo, hi, t, guess, scale):
    """The index l in [lo, hi] with knots[l] <= t < knots[l + 1].

    ``t`` at or beyond ``knots[hi + 1]`` gives the last non-empty span (so the curve is
    closed at its right end).  Tries the estimate lo + (t - knots[lo]) * scale first,
    exact for (open) uniform knots, then ``guess`` (sorted parameters hit it), then a
    binary search.
    """
    est = lo + clamped_index((t - knots[lo]) * scale, hi - lo)
    if knots[est] <= t < knots[est + 1]:
        return est
    if knots[guess] <= t < knots[guess + 1]:
        return guess
    if t >= knots[hi + 1]:
        l = hi
        while l > lo and knots[l] >= knots[l + 1]:
            l -= 1
        return l
    return last_at_most(knots, lo, hi, t)


@kernel
def de_boor(points, knots, order, u, out):
    """out[i] = the B-spline of ``order`` d with control ``points`` at ``u[i]``.

    ``knots`` has len(points) + d values, non-decreasing, with
    knots[d-1] < knots[n+1]; every u[i] lies in [knots[d-1], knots[n+1]].
    de Boor's algorithm on the d control points that act on u's knot span.
    """
    m, dim = points.shape
    d = order
    work = np.empty((d, dim))
    lo = d - 1
    hi = m - 1
    scale = (hi + 1 - lo) / (knots[hi + 1] - knots[lo])
    span = lo
    for i in range(u.shape[0]):
        t = u[i]
        span = find_span(knots, lo, hi, t, span, scale)
        base = span - d + 1
        for j in range(d):
            for c in range(dim):
                work[j, c] = points[base + j, c]
        for r in range(1, d):
            for j in range(d - 1, r - 1, -1):
                k = base + j
                a = (t - knots[k]) / (knots[k + d - r] - knots[k])
                for c in range(dim):
                    work[j, c] = (1.0 - a) * work[j - 1, c] + a * work[j, c]
        for c in range(dim):
            out[i, c] = work[d - 1, c]


@helper
def find_section(breaks, t, guess):
    """The section s in [0, S-1] with breaks[s] <= t < breaks[s + 1] (the last
    section also takes t == breaks[S]).  Tries ``guess`` (the previous section: sorted
    parameters hit it), then a binary search."""
    last = breaks.shape[0] - 2
    if breaks[guess] <= t < breaks[guess + 1]:
        return guess
    if t >= breaks[last]:
        return last
    return last_at_most(breaks, np.int64(0), last, t)


@inline
def horner(coefficients, s, t, out, i):
    """out[i] = section s of the piecewise polynomial at local t, by Horner's rule."""
    m = coefficients.shape[1]
    for c in range(coefficients.shape[2]):
        acc = coefficients[s, 0, c]
        for j in range(1, m):
            acc = acc * t + coefficients[s, j, c]
        out[i, c] = acc


@kernel
def piecewise_horner(breaks, coefficients, u, out):
    """out[i] = the piecewise polynomial at ``u[i]``, by Horner's rule.

    Section s covers [breaks[s], breaks[s+1]] (increasing breaks); its polynomial in
    the local parameter t = (u - breaks[s]) / (breaks[s+1] - breaks[s]) in [0, 1] has
    the coefficient rows ``coefficients[s]`` (m, dim), highest power first.  The
    reciprocal of every section width must be finite.
    """
    sections = coefficients.shape[0]
    scale = sections / (breaks[sections] - breaks[0])
    if sections == 1:  # a single polynomial (a Bezier curve): no search
        for i in range(u.shape[0]):
            horner(coefficients, 0, (u[i] - breaks[0]) * scale, out, i)
        return
    s = np.int64(0)
    last = sections - 1
    for i in range(u.shape[0]):
        x = u[i]
        # the estimate is exact for equally spaced breaks; otherwise search
        est = clamped_index((x - breaks[0]) * scale, last)
        if breaks[est] <= x < breaks[est + 1]:
            s = est
        else:
            s = find_section(breaks, x, s)
        horner(coefficients, s, (x - breaks[s]) / (breaks[s + 1] - breaks[s]), out, i)
