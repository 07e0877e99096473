"""3-D Cohen-Sutherland where a segment enters or leaves the volume exactly through an
edge or a corner (scanline.clip.lines3d, scanline.clip.homogeneous,
scanline.trace.cohen_sutherland_3d).

There the clipped point lies on two or three planes at once; round-off used to set the
region-code bit of a plane the endpoint had already been moved onto, so the endpoint
went back and forth between two planes until the step limit rejected a visible segment.
The cases below are checked against the exact visible parameter interval [u0, u1] of
each segment, computed here in rationals (fractions.Fraction) from the float inputs.

What is required of the clippers (decided here, and stated in the docstrings of
:func:`scanline.clip.lines3d` and :func:`scanline._kernels.clip3d.cohen_sutherland`):

- inputs exact in binary (coordinates, w and box bounds in short binary fractions, so
  that the lines pass exactly through the edges and corners): accepted exactly when
  the exact interval is non-empty -- also a segment that only touches an edge or a
  corner from outside, whose interval is one point -- and the clipped endpoints within
  1e-9 of the exact ones;
- other inputs (a box with bounds 0.1, 0.2 ...): an exact interval longer than 1e-9 is
  accepted, as above; a segment that misses even the volume grown by 1e-9 is rejected;
  one in between -- touching, or missing, by round-off -- may go either way (Hearn &
  Baker's algorithm decides it by region codes computed in floating point, as
  Liang-Barsky decides by u1 <= u2 on rounded quotients), and if accepted it is a piece
  of the segment within 1e-8 of the volume.

Cohen-Sutherland's accepted endpoints also lie in the closed box (homogeneous: the
closed cube 0 <= x, y, z <= w) exactly: a moved endpoint is put exactly on its plane.
"""

from fractions import Fraction

import numpy as np
import pytest

import scanline as sl
from scanline.clip import UNIT_CUBE, box, homogeneous, lines3d

METHODS = ("cohen-sutherland", "liang-barsky")
TOL = 1e-9


# -- the exact reference ----------------------------------------------------------------------
def exact_interval(p0, p1, planes, grow=0):
    """The exact parameter interval [u0, u1] of P0 + u (P1 - P0), 0 <= u <= 1, inside
    every plane a x + b y + c z + d w >= -grow w (homogeneous points; ``grow`` > 0
    widens the volume), in rationals; None when empty."""
    lo, hi = Fraction(0), Fraction(1)
    grow = Fraction(grow)
    q0 = [Fraction(float(c)) for c in p0]
    q1 = [Fraction(float(c)) for c in p1]
    for plane in planes:
        a = [Fraction(float(c)) for c in plane]
        a[3] += grow
        d0 = sum(x * c for x, c in zip(a, q0))
        d1 = sum(x * c for x, c in zip(a, q1))
        if d0 == d1:
            if d0 < 0:
                return None
        elif d1 > d0:
            lo = max(lo, d0 / (d0 - d1))
        else:
            hi = min(hi, d0 / (d0 - d1))
    return (lo, hi) if lo <= hi else None


def homogeneous_ends(seg, dim):
    p0, p1 = list(seg[:dim]), list(seg[dim:])
    if dim == 3:
        p0, p1 = p0 + [1.0], p1 + [1.0]
    return p0, p1


def expectations(segs, planes, dim, exact_inputs):
    """Per segment: 'accept', 'reject' or 'either', and the parameter interval the
    clipped segment must match: the exact one ('accept'), or that of the volume grown
    by 10 TOL ('either': the point of contact, or a stretch within 10 TOL of it)."""
    kinds, intervals = [], []
    for s in segs:
        p0, p1 = homogeneous_ends(s, dim)
        iv = exact_interval(p0, p1, planes)
        if iv is not None and (exact_inputs or iv[1] - iv[0] > TOL):
            kinds.append("accept")
        elif exact_inputs or exact_interval(p0, p1, planes, grow=TOL) is None:
            kinds.append("reject")
        else:
            kinds.append("either")
            iv = exact_interval(p0, p1, planes, grow=10 * TOL)
        intervals.append((0.0, 1.0) if iv is None else (float(iv[0]), float(iv[1])))
    return np.array(kinds), np.array(intervals)


def check_against_exact(segs, planes, dim, out, ok, exact_inputs=True):
    """``out``, ``ok`` (N, 2 dim), (N,) from a clipper against the rules above; returns
    the kinds."""
    kinds, iv = expectations(segs, planes, dim, exact_inputs)
    wrong = np.nonzero((ok & (kinds == "reject")) | (~ok & (kinds == "accept")))[0]
    assert len(wrong) == 0, [(segs[i].tolist(), kinds[i]) for i in wrong[:5]]
    np.testing.assert_array_equal(out[~ok], segs[~ok])      # rejected: as given
    a, b = segs[:, :dim], segs[:, dim:]
    ref = np.hstack([a + iv[:, :1] * (b - a), a + iv[:, 1:] * (b - a)])
    exact = ok & (kinds == "accept")
    np.testing.assert_allclose(out[exact], ref[exact], rtol=0, atol=TOL)
    # touching: each end on the segment, at a parameter within the grown volume's
    for i in np.nonzero(ok & (kinds == "either"))[0]:
        d = b[i] - a[i]
        for e in range(2):
            p = out[i, e * dim:(e + 1) * dim]
            u = np.dot(p - a[i], d) / np.dot(d, d)
            assert np.abs(a[i] + u * d - p).max() <= TOL, (segs[i].tolist(), out[i].tolist())
            assert iv[i, 0] - TOL <= u <= iv[i, 1] + TOL, (segs[i].tolist(), out[i].tolist())
    return kinds


def inside_exactly(points, lo, hi):
    """(N, 3) points, or (N, 4) homogeneous ones against lo w <= x <= hi w."""
    if points.shape[1] == 4:
        w = points[:, 3:]
        xyz = points[:, :3]
        return ((xyz >= np.asarray(lo) * w) & (xyz <= np.asarray(hi) * w)).all(axis=1)
    return ((points >= lo) & (points <= hi)).all(axis=1)


# -- 1. segments through an edge or a corner, written out ---------------------------------------
CUBE = ((0.0, 0.0, 0.0), (1.0, 1.0, 1.0))

# (P0, P1, exact visible part): Cohen-Sutherland rejected each of these before the fix
# (the endpoint went back and forth between the edge's two planes)
PLAIN = [
    # enters through the edge x = y = 1 at (1, 1, 0.5625), ends inside
    ((4.8671875, 4.8671875, 0.6943359375), (0.44140625, 0.44140625, 0.54345703125),
     ((1, 1, 0.5625), (0.44140625, 0.44140625, 0.54345703125))),
    # enters through the edge y = z = 0 at (0.5, 0, 0)
    ((0.1875, -0.4375, -0.0625), (0.666015625, 0.232421875, 0.033203125),
     ((0.5, 0, 0), (0.666015625, 0.232421875, 0.033203125))),
    # enters through the corner (0, 0, 0)
    ((-0.484375, -1.9375, -1.6953125), (0.125, 0.5, 0.4375),
     ((0, 0, 0), (0.125, 0.5, 0.4375))),
]
# homogeneous (x, y, z, w) against the unit cube 0 <= x, y, z <= w, as (P0, P1,
# exact visible part divided by w)
HOMOGENEOUS = [
    # (4, 2, 1.5) w = 3 to (0.25, 0.75, 0.25) w = 2: enters through the edge x/w = y/w = 1
    ((12, 6, 4.5, 3), (0.5, 1.5, 0.5, 2), ((1, 1, 0.5), (0.25, 0.75, 0.25))),
    # (4, 2, 2) w = 3 to (0.25, 0.75, 0.75) w = 2: enters through the corner (1, 1, 1)
    ((12, 6, 6, 3), (0.5, 1.5, 1.5, 2), ((1, 1, 1), (0.25, 0.75, 0.75))),
    # (0.7, 0.7, 0.4) w = 5 to (7, 7, 2.5) w = 3: leaves through the edge x/w = y/w = 1
    ((3.5, 3.5, 2, 5), (21, 21, 7.5, 3), ((0.7, 0.7, 0.4), (1, 1, 0.5))),
]


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("p0, p1, visible", PLAIN)
def test_segments_entering_through_an_edge_or_a_corner(method, p0, p1, visible):
    out, ok = lines3d([p0 + p1], CUBE, method=method)
    assert ok.tolist() == [True]
    np.testing.assert_allclose(out[0], np.concatenate(visible), rtol=0, atol=1e-12)
    assert sl.clip.line3d(p0, p1, CUBE, method=method) is not None
    if method == "cohen-sutherland":
        assert inside_exactly(out[0].reshape(2, 3), *CUBE).all()
        # the two (or three) planes of the edge (corner): the point is on each exactly
        assert (out[0][:3] == np.asarray(visible[0], float)).all()


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("p0, p1, visible", HOMOGENEOUS)
def test_homogeneous_segments_through_an_edge_or_a_corner(method, p0, p1, visible):
    out, ok = homogeneous([(p0, p1)], method=method)
    assert ok.tolist() == [True]
    ndc = out[0, :, :3] / out[0, :, 3:]
    np.testing.assert_allclose(ndc, np.array(visible, float), rtol=0, atol=1e-12)
    if method == "cohen-sutherland":
        assert inside_exactly(out[0], *CUBE).all()


@pytest.mark.parametrize("p0, p1, visible", PLAIN)
def test_step_table_of_an_edge_crossing(p0, p1, visible):
    """The step table runs the kernel's own code: each plane is clipped at most once
    per endpoint, and the table ends in the same accepted segment."""
    t = sl.trace.cohen_sutherland_3d(p0, p1, volume=CUBE)
    assert t.rows[-1]["decision"].startswith("accept")
    clips = [r["decision"] for r in t.rows if r["decision"].startswith("clip")]
    assert len(clips) == len(set(clips)) <= 6
    out, ok = lines3d([p0 + p1], CUBE, method="cohen-sutherland")
    np.testing.assert_array_equal(np.concatenate(t.result), out[0])


def test_homogeneous_step_table_of_an_edge_crossing():
    for p0, p1, visible in HOMOGENEOUS:
        t = sl.trace.cohen_sutherland_3d(p0[:3], p1[:3], w=(p0[3], p1[3]))
        assert t.rows[-1]["decision"].startswith("accept")
        clips = [r["decision"] for r in t.rows if r["decision"].startswith("clip")]
        assert len(clips) == len(set(clips))
        out, ok = homogeneous([(p0, p1)], method="cohen-sutherland")
        np.testing.assert_array_equal(np.array(t.result), out[0])


def test_a_segment_along_an_edge_and_one_touching_a_corner():
    # along the edge y = z = 1 of the cube, from outside to outside: the whole edge
    out, ok = lines3d([(-1, 1, 1, 3, 1, 1)], CUBE, method="cohen-sutherland")
    assert ok.tolist() == [True]
    np.testing.assert_array_equal(out[0], (0, 1, 1, 1, 1, 1))
    # through the corner (1, 1, 1) only, from outside to outside: that point
    for method in METHODS:
        out, ok = lines3d([(0.5, 1.5, 1, 1.5, 0.5, 1), (0.5, 1.5, 0.5, 1.5, 0.5, 1.5)],
                          CUBE, method=method)
        assert ok.tolist() == [True, True]
        np.testing.assert_allclose(out[0], (1, 1, 1, 1, 1, 1), atol=1e-12)
        np.testing.assert_allclose(out[1], (1, 1, 1, 1, 1, 1), atol=1e-12)
        # and just past it: nothing
        out, ok = lines3d([(0.5, 1.5 + 2**-20, 1, 1.5, 0.5 + 2**-20, 1)], CUBE, method=method)
        assert ok.tolist() == [False]


def test_cohen_sutherland_refuses_more_planes_than_its_code_has_bits():
    vol = sl.clip.polyhedron(sl.mesh.sphere(1.0, resolution=(16, 8)))
    assert len(vol.planes) > 64
    with pytest.raises(sl.ScanlineError, match="at most 64 planes"):
        lines3d([(0, 0, 0, 2, 0, 0)], vol, method="cohen-sutherland")
    with pytest.raises(sl.ScanlineError, match="at most 64 planes"):
        sl.trace.cohen_sutherland_3d((0, 0, 0), (2, 0, 0), volume=vol)
    out, ok = lines3d([(0, 0, 0, 2, 0, 0)], vol, method="liang-barsky")
    assert ok.tolist() == [True]


# -- 2. and 3. randomized, against the exact interval, and the clippers against each other ------
def feature_segments(rng, lo, hi, n, dyadic=True):
    """``n`` segments through a point F on an edge or at a corner of the box (lo, hi)
    (two or three coordinates on the box's faces), along directions that enter there,
    only touch there (inward on one face, outward on another), run along the edge, or
    are random; F shifted off the box by 1/1024 in a sixth of them; half reversed, so
    that the endpoint moved there is P1.  With ``dyadic`` (and a box of dyadic bounds)
    every coordinate is exact, so the lines pass exactly through the edges and
    corners."""
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    segs = []
    for _ in range(n):
        on = rng.choice(3, rng.integers(2, 4), replace=False)
        side = rng.integers(0, 2, 3)                    # 0: lo face, 1: hi face
        inward = np.where(side == 1, -1.0, 1.0)
        f = lo + (hi - lo) * rng.integers(1, 16, 3) / 16
        f[on] = np.where(side[on] == 1, hi[on], lo[on])
        d = rng.integers(-8, 9, 3) / 8
        size = rng.integers(1, 9, 3) / 8
        kind = rng.integers(0, 4)
        if kind == 0:                                   # enters through the edge / corner
            d[on] = inward[on] * size[on]
        elif kind == 1:                                 # touches it only
            d[on] = inward[on] * size[on]
            d[on[0]] = -d[on[0]]
        elif kind == 2:                                 # along the edge (from a corner: in)
            d[on] = 0.0
            if len(on) == 3:
                d[on[0]] = inward[on[0]] * size[on[0]]
        if not d.any():
            d[0] = 0.5
        if rng.integers(0, 6) == 0:                     # just off the box
            f[on[0]] -= inward[on[0]] / 1024
        if not dyadic:
            d = d * 0.9 + rng.uniform(-1e-3, 1e-3, 3) * (kind == 3)
        s = rng.integers(1, 65) / 16
        r = rng.integers(1, 65) / 32
        seg = np.concatenate([f - s * d, f + r * d])
        segs.append(seg if rng.integers(0, 2) else np.concatenate([seg[3:], seg[:3]]))
    return np.array(segs)


def axis_segments(rng, lo, hi, n):
    """Segments parallel to an axis, their other two coordinates on a face, on an
    edge's line, inside or outside."""
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    size = hi - lo
    segs = np.empty((n, 6))
    for i in range(n):
        axis = rng.integers(0, 3)
        choices = np.stack([lo, hi, lo + size / 2, lo - size / 4, hi + size / 4])
        p = choices[rng.integers(0, 5, 3), [0, 1, 2]]
        q = p.copy()
        p[axis], q[axis] = lo[axis] + size[axis] * rng.integers(-8, 25, 2) / 16
        segs[i] = np.concatenate([p, q])
    return segs


def random_segments(rng, lo, hi, n, dyadic=True):
    """Segments with random endpoints around the box (on a grid of 1/64 with
    ``dyadic``)."""
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    span = hi - lo
    segs = np.hstack([rng.uniform(lo - span, hi + span, (n, 3)),
                      rng.uniform(lo - span, hi + span, (n, 3))])
    return np.round(segs * 64) / 64 if dyadic else segs


def plain_cases(seed):
    rng = np.random.default_rng(seed)
    cases = []
    for lo, hi, dyadic in (((0.0, -1.0, 2.0), (10.0, 4.0, 7.0), True),
                           ((0.0, 0.0, 0.0), (1.0, 1.0, 1.0), True),
                           ((0.1, 0.2, 0.3), (0.7, 0.9, 1.3), False)):
        segs = np.vstack([feature_segments(rng, lo, hi, 900, dyadic),
                          axis_segments(rng, lo, hi, 200),
                          random_segments(rng, lo, hi, 300, dyadic)])
        cases.append((lo, hi, dyadic, segs))
    return cases


def test_random_edge_and_corner_segments_match_the_exact_interval():
    counts = {"accept": 0, "reject": 0, "either": 0, "touch": 0}
    for lo, hi, dyadic, segs in plain_cases(20):
        vol = box(lo, hi)
        results = {}
        for method in METHODS:
            out, ok = lines3d(segs, vol, method=method)
            kinds = check_against_exact(segs, vol.planes, 3, out, ok, exact_inputs=dyadic)
            results[method] = out, ok
        cs_out, cs_ok = results["cohen-sutherland"]
        lb_out, lb_ok = results["liang-barsky"]
        # accepted by Cohen-Sutherland: inside the closed box exactly
        assert inside_exactly(cs_out[cs_ok].reshape(-1, 3), lo, hi).all()
        # the two clippers agree (on segments touching by round-off they may not)
        decided = kinds != "either"
        assert (cs_ok[decided] == lb_ok[decided]).all()
        both = cs_ok & lb_ok
        np.testing.assert_allclose(cs_out[both], lb_out[both], rtol=0, atol=2 * TOL)
        for kind in ("accept", "reject", "either"):
            counts[kind] += int((kinds == kind).sum())
        if dyadic:                                  # accepted as a single point
            point = np.abs(cs_out[:, :3] - cs_out[:, 3:]).max(axis=1) == 0
            counts["touch"] += int((cs_ok & point).sum())
    # the mix the cases were built for: both answers, many segments touching at one point
    assert counts["accept"] > 1500 and counts["reject"] > 800 and counts["either"] > 100
    assert counts["touch"] > 300


def test_random_homogeneous_edge_and_corner_segments_match_the_exact_interval():
    rng = np.random.default_rng(21)
    lo, hi = (0.0, 0.0, 0.0), (1.0, 1.0, 1.0)
    p = np.vstack([feature_segments(rng, lo, hi, 2000),
                   axis_segments(rng, lo, hi, 400),
                   random_segments(rng, lo, hi, 600)])              # all exact in binary
    n = len(p)
    w = rng.integers(1, 33, (n, 2)) / 8                 # exact products: w = 1/8 .. 4
    h = np.empty((n, 2, 4))
    h[:, 0, :3], h[:, 1, :3] = p[:, :3] * w[:, :1], p[:, 3:] * w[:, 1:]
    h[:, :, 3] = w
    flat = h.reshape(n, 8)
    kinds = None
    results = {}
    for method in METHODS:
        out, ok = homogeneous(h, method=method)
        kinds = check_against_exact(flat, UNIT_CUBE.planes, 4, out.reshape(n, 8), ok)
        results[method] = out, ok
    cs_out, cs_ok = results["cohen-sutherland"]
    lb_out, lb_ok = results["liang-barsky"]
    assert inside_exactly(cs_out[cs_ok].reshape(-1, 4), lo, hi).all()
    assert (cs_ok == lb_ok).all()
    both = cs_ok & lb_ok
    np.testing.assert_allclose(cs_out[both], lb_out[both], rtol=0, atol=2 * TOL)
    assert (kinds == "accept").sum() > 1000 and (kinds == "reject").sum() > 300
    ndc = cs_out[cs_ok, :, :3] / cs_out[cs_ok, :, 3:]
    assert (np.abs(ndc[:, 0] - ndc[:, 1]).max(axis=1) < 1e-12).sum() > 300   # touching


def test_step_table_agrees_with_the_kernel_on_edge_and_corner_segments():
    """Convention 5: the table (the kernel's code run as Python) and the compiled
    clipper give the same answer on the segments through edges and corners."""
    rng = np.random.default_rng(22)
    lo, hi = (0.0, -1.0, 2.0), (10.0, 4.0, 7.0)
    segs = feature_segments(rng, lo, hi, 200)
    out, ok = lines3d(segs, (lo, hi), method="cohen-sutherland")
    for s, o, k in zip(segs, out, ok):
        t = sl.trace.cohen_sutherland_3d(s[:3], s[3:], volume=(lo, hi))
        assert (t.result is not None) == k
        if k:
            np.testing.assert_array_equal(np.concatenate(t.result), o)
    w = rng.integers(1, 33, (200, 2)) / 8
    segs = feature_segments(rng, (0, 0, 0), (1, 1, 1), 200)
    h = np.stack([np.hstack([segs[:, :3] * w[:, :1], w[:, :1]]),
                  np.hstack([segs[:, 3:] * w[:, 1:], w[:, 1:]])], axis=1)
    out, ok = homogeneous(h, method="cohen-sutherland")
    for s, o, k in zip(h, out, ok):
        t = sl.trace.cohen_sutherland_3d(s[0, :3], s[1, :3], w=(s[0, 3], s[1, 3]))
        assert (t.result is not None) == k
        if k:
            np.testing.assert_array_equal(np.array(t.result), o)


def test_each_plane_is_clipped_at_most_once_per_endpoint():
    """The loop is bounded by the planes, not by a step limit: at most one clip per
    plane and endpoint, on a frustum and a 50-plane polyhedron too."""
    rng = np.random.default_rng(23)
    vols = [box((0, 0, 0), (1, 1, 1)), sl.clip.frustum(-0.25),
            sl.clip.polyhedron(sl.mesh.sphere(1.0, resolution=(10, 5)))]
    segs = np.vstack([feature_segments(rng, (0, 0, 0), (1, 1, 1), 100),
                      rng.uniform(-1.5, 1.5, (100, 6))])
    for vol in vols:
        out, ok = lines3d(segs, vol, method="liang-barsky")
        cs_out, cs_ok = lines3d(segs, vol, method="cohen-sutherland")
        kinds = check_against_exact(segs, vol.planes, 3, cs_out, cs_ok, exact_inputs=False)
        assert (cs_ok == ok)[kinds != "either"].all()
        for s in segs[:60]:
            t = sl.trace.cohen_sutherland_3d(s[:3], s[3:], volume=vol)
            clips = [(r["decision"]) for r in t.rows if r["decision"].startswith("clip")]
            assert len(clips) == len(set(clips)) <= 2 * len(vol.planes)
            assert not t.rows[-1]["decision"].startswith("clip")
