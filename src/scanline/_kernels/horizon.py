"""The floating-horizon kernel (Wright 1973; Rogers, *Procedural Elements for
Computer Graphics*, section 4-2): curves tested against an upper and a lower
horizon kept per screen column.

A *run* is one curve (or one of the side edges joining a curve to the previous one)
sampled at consecutive integer columns ``c0, c0 + 1, ...``: its screen y there.  A
run of one column is a vertical stroke from ``ylo`` to ``yhi``.  The runs of one
*group* (a curve and its side edges) are all tested against the horizon left by the
groups before it, then merged into it, so a curve never hides itself.
"""

import numpy as np

from ._jit import helper, kernel


@helper
def emit(segs, n, x0, y0, x1, y1):
    """Append segment (x0, y0)-(x1, y1) to ``segs`` while there is room; the new count."""
    if n < len(segs):
        segs[n, 0] = x0
        segs[n, 1] = y0
        segs[n, 2] = x1
        segs[n, 3] = y1
    return n + 1


@helper
def above(y, h):
    """y - h, +inf where the horizon ``h`` is not yet defined (-inf)."""
    return np.inf if h == -np.inf else y - h


@helper
def below(y, h):
    """h - y, +inf where the lower horizon ``h`` is not yet defined (+inf)."""
    return np.inf if h == np.inf else h - y


@helper
def visible_part(f0, f1, t):
    """The part of [0, 1] where the linear function from ``f0`` to ``f1`` is > 0:
    written to ``t[0], t[1]``; returns whether it is not empty."""
    if f0 > 0.0 and f1 > 0.0:
        t[0] = 0.0
        t[1] = 1.0
        return True
    if f0 <= 0.0 and f1 <= 0.0:
        return False
    if f0 == np.inf or f1 == np.inf:         # entering or leaving undefined horizon
        t[0] = 0.0 if f0 > 0.0 else 1.0
        t[1] = 1.0 if f1 > 0.0 else 0.0
        return t[0] < t[1]
    c = f0 / (f0 - f1)                       # the crossing, by interpolation
    if f0 > 0.0:
        t[0] = 0.0
        t[1] = c
    else:
        t[0] = c
        t[1] = 1.0
    return t[1] > t[0]


@helper
def run_visibility(c0, count, ylo, yhi, upper, lower, row):
    """Test one run against the horizon: ``row[c]`` = 1 above the upper horizon, -1
    below the lower one, 0 hidden, for its columns c inside the raster."""
    width = len(upper)
    for k in range(count):
        c = c0 + k
        if c < 0 or c >= width:
            continue
        if above(yhi[k], upper[c]) > 0.0:
            row[c] = 1
        elif below(ylo[k], lower[c]) > 0.0:
            row[c] = -1
        else:
            row[c] = 0


@helper
def draw_run(c0, count, ylo, yhi, upper, lower, segs, n, t):
    """The visible pieces of one run against the horizon (not updated here):
    between columns c and c + 1 the run and both horizons are interpolated linearly
    and the parts above the upper and below the lower horizon are drawn, cut where
    they cross it (Rogers' intersection of the curve with the horizon).  A
    one-column run is a vertical stroke.  Returns the new segment count."""
    width = len(upper)
    if count == 1:
        c = np.float64(c0)
        if 0 <= c0 < width:
            top = yhi[0]
            bot = ylo[0]
            u = upper[c0]
            lo = lower[c0]
            if top > u:
                n = emit(segs, n, c, max(bot, u), c, top)
            if bot < lo:
                n = emit(segs, n, c, bot, c, min(top, lo))
        return n
    for k in range(count - 1):
        c = c0 + k
        if c < 0 or c + 1 >= width:
            continue
        ya = yhi[k]
        yb = yhi[k + 1]
        dy = yb - ya
        if visible_part(above(ya, upper[c]), above(yb, upper[c + 1]), t):
            n = emit(segs, n, c + t[0], ya + t[0] * dy, c + t[1], ya + t[1] * dy)
        if visible_part(below(ya, lower[c]), below(yb, lower[c + 1]), t):
            if not (upper[c] == -np.inf or upper[c + 1] == -np.inf):
                n = emit(segs, n, c + t[0], ya + t[0] * dy, c + t[1], ya + t[1] * dy)
    return n


@helper
def merge_run(c0, count, ylo, yhi, upper, lower):
    """Raise the upper and lower horizons to the run."""
    width = len(upper)
    for k in range(count):
        c = c0 + k
        if 0 <= c < width:
            if yhi[k] > upper[c]:
                upper[c] = yhi[k]
            if ylo[k] < lower[c]:
                lower[c] = ylo[k]


@helper
def horizon_group(g, groups, runs, ylo, yhi, upper, lower, newup, newlo, segs, n, t):
    """Process group ``g``: draw its runs against the horizon, then merge them (into
    ``newup``/``newlo``, copied back).  Returns the segment count."""
    width = len(upper)
    for c in range(width):
        newup[c] = upper[c]
        newlo[c] = lower[c]
    for r in range(groups[g], groups[g + 1]):
        s = runs[r, 2]
        n = draw_run(runs[r, 0], runs[r, 1], ylo[s:], yhi[s:], upper, lower, segs, n, t)
        merge_run(runs[r, 0], runs[r, 1], ylo[s:], yhi[s:], newup, newlo)
    for c in range(width):
        upper[c] = newup[c]
        lower[c] = newlo[c]
    return n


@kernel
def floating_horizon(groups, runs, ylo, yhi, upper, lower, newup, newlo, segs, states):
    """Every group in order (nearest curve first).  ``runs`` rows: first column,
    column count, start in ``ylo``/``yhi``; the last run of each group is its curve,
    whose visibility per column goes to ``states`` (rows: groups; 2 where the curve
    has no sample).  Returns the number of visible segments (written to ``segs``
    while there is room)."""
    n = np.int64(0)
    t = np.empty(2)
    width = len(upper)
    for g in range(len(groups) - 1):
        r = groups[g + 1] - 1
        s = runs[r, 2]
        c0 = runs[r, 0]
        count = runs[r, 1]
        for c in range(width):
            states[g, c] = 2
        run_visibility(c0, count, ylo[s:], yhi[s:], upper, lower, states[g])
        n = horizon_group(g, groups, runs, ylo, yhi, upper, lower, newup, newlo, segs, n, t)
    return n
