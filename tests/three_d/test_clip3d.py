"""3-D and homogeneous clipping (scanline.clip.lines3d, homogeneous, polygons3d):
the three line clippers agree with each other and with an exact rational reference
on thousands of random segments; homogeneous clipping agrees with clipping the same
segments in viewing coordinates against the frustum's planes (derived here from the
camera's geometry, not from its matrix), including segments through the eye's plane
and behind it; Sutherland-Hodgman against a sampling reference; the step tables
agree with the batch clippers."""

import math
from fractions import Fraction

import numpy as np
import pytest

import scanline as sl
from scanline.clip import UNIT_CUBE, box, frustum, homogeneous, lines3d, polygons3d
from tests.reference import HYPOTHESIS  # noqa: F401  (shared settings module)

BOX = ((0.0, -1.0, 2.0), (10.0, 4.0, 7.0))


def exact_interval(p0, p1, planes):
    """The exact visible parameter interval [t0, t1] of P0 + t (P1 - P0), t in [0, 1],
    against planes a.p >= 0 (p homogeneous), in rationals; None when empty."""
    lo, hi = Fraction(0), Fraction(1)
    for plane in planes:
        a = [Fraction(float(c)) for c in plane]
        d0 = sum(x * Fraction(float(c)) for x, c in zip(a, p0))
        d1 = sum(x * Fraction(float(c)) for x, c in zip(a, p1))
        b = d1 - d0
        if b == 0:
            if d0 < 0:
                return None
        elif b > 0:
            lo = max(lo, -d0 / b)
        else:
            hi = min(hi, -d0 / b)
    return (lo, hi) if lo <= hi else None


def reference_segments(segs, planes, dim):
    out, ok = [], []
    for s in segs:
        p0 = list(s[:dim]) + ([1.0] if dim == 3 else [])
        p1 = list(s[dim:]) + ([1.0] if dim == 3 else [])
        iv = exact_interval(p0, p1, planes)
        ok.append(iv is not None)
        if iv is None:
            out.append(s)
            continue
        t0, t1 = (float(t) for t in iv)
        a, b = np.array(s[:dim]), np.array(s[dim:])
        out.append(np.concatenate([a + t0 * (b - a), a + t1 * (b - a)]))
    return np.array(out), np.array(ok)


@pytest.mark.parametrize("method", ["liang-barsky", "cohen-sutherland", "cyrus-beck"])
def test_box_clippers_match_the_exact_reference(method):
    rng = np.random.default_rng(7)
    segs = rng.uniform(-6, 16, (3000, 6))
    vol = box(*BOX)
    ref, ref_ok = reference_segments(segs, vol.planes, 3)
    out, ok = lines3d(segs, BOX, method=method)
    assert (ok == ref_ok).all()
    assert 0.15 < ok.mean() < 0.85                       # both kinds well represented
    np.testing.assert_allclose(out[ok], ref[ok], rtol=0, atol=1e-9)
    np.testing.assert_array_equal(out[~ok], segs[~ok])   # rejected: as given


def test_the_three_clippers_agree_on_a_frustum_and_a_polyhedron():
    rng = np.random.default_rng(8)
    segs = rng.uniform(-1.5, 0.5, (2000, 6))
    for vol in (frustum(-0.2), sl.clip.polyhedron(sl.mesh.sphere(1.2, resolution=(10, 5)))):
        results = [lines3d(segs, vol, m) for m in ("liang-barsky", "cohen-sutherland", "cyrus-beck")]
        ref, ref_ok = reference_segments(segs, vol.planes, 3)
        for out, ok in results:
            assert (ok == ref_ok).all()
            np.testing.assert_allclose(out[ok], ref[ok], rtol=0, atol=1e-9)


def test_segments_on_the_boundary_and_degenerate_segments():
    out, ok = lines3d([(0, 0, 2, 10, 0, 2),       # along an edge of the box
                       (5, 1, 3, 5, 1, 3),         # a point inside
                       (5, 9, 3, 5, 9, 3),         # a point outside
                       (-1, 4, 7, 11, 4, 7)], BOX)  # on the top-back edge line
    assert ok.tolist() == [True, True, False, True]
    np.testing.assert_allclose(out[3], (0, 4, 7, 10, 4, 7))


def test_nan_and_infinite_segments_are_never_accepted():
    out, ok = lines3d([(np.nan, 0, 3, 1, 1, 3), (0, 0, 3, np.inf, 1, 3), (1, 0, 3, 2, 1, 3)], BOX)
    assert ok.tolist() == [False, False, True]
    out, ok = lines3d([(np.nan, 0, 3, 1, 1, 3)], BOX, method="cohen-sutherland")
    assert ok.tolist() == [False]


# -- homogeneous clipping ----------------------------------------------------------------------
def viewing_frustum_planes(fov, aspect, near, far):
    """The view volume of an eye at the origin looking along -z, as planes
    a x + b y + c z + d >= 0 in viewing coordinates, from the geometry: the four
    side planes through the eye and the window's edges at z = -near, and the front
    and back planes."""
    ty = math.tan(fov / 2)
    tx = ty * aspect
    return np.array([[1, 0, -tx, 0], [-1, 0, -tx, 0],      # z tx <= x <= -z tx
                     [0, 1, -ty, 0], [0, -1, -ty, 0],
                     [0, 0, -1, -near], [0, 0, 1, far]], float)


def test_homogeneous_clipping_matches_clipping_in_viewing_coordinates():
    fov, aspect, near, far = 1.1, 1.3, 0.7, 20.0
    cam = sl.Camera(projection=sl.projection.perspective(fov=fov, aspect=aspect, near=near, far=far),
                    keep_aspect=False)
    rng = np.random.default_rng(3)
    a = rng.uniform(-8, 8, (4000, 3))
    b = rng.uniform(-8, 8, (4000, 3))
    # many segments cross the eye's plane z = 0 or lie partly behind the eye (z > 0)
    assert ((a[:, 2] > 0) != (b[:, 2] > 0)).mean() > 0.3
    segs = np.hstack([a, b])
    ref, ref_ok = reference_segments(segs, viewing_frustum_planes(fov, aspect, near, far), 3)
    h = np.stack([cam.to_clip(a), cam.to_clip(b)], axis=1)
    assert (h[:, :, 3] < 0).any(axis=1).mean() > 0.3       # w < 0: behind the eye
    for method in ("liang-barsky", "cohen-sutherland"):
        out, ok = homogeneous(h, method=method)
        assert (ok == ref_ok).all()
        assert (out[ok, :, 3] > 0).all()
        ndc = out[ok, :, :3] / out[ok, :, 3:]
        expect = np.stack([cam.to_clip(ref[ok, :3]), cam.to_clip(ref[ok, 3:])], axis=1)
        np.testing.assert_allclose(ndc, expect[:, :, :3] / expect[:, :, 3:], rtol=0, atol=1e-8)
        assert (ndc >= -1e-9).all() and (ndc <= 1 + 1e-9).all()


def test_a_segment_through_the_eye_is_cut_at_the_front_plane_not_mirrored():
    cam = sl.Camera(eye=(0, 0, 0), target=(0, 0, -1),
                    projection=sl.projection.perspective(fov=1.0, near=1, far=10))
    # from 5 in front of the eye to 5 behind it, slightly off axis
    h = np.stack([cam.to_clip([(0.1, 0.1, -5)]), cam.to_clip([(0.1, 0.1, 5)])], axis=1)
    out, ok = homogeneous(h)
    assert ok[0]
    ndc = out[0, :, :3] / out[0, :, 3:]
    z_view = -(cam.linear_depth(ndc[:, 2]) + 1)             # back to viewing z
    np.testing.assert_allclose(sorted(z_view), [-5, -1], atol=1e-9)


# -- polygons -----------------------------------------------------------------------------------
def _inside_convex(poly, pts, normal):
    """Points (coplanar) inside a convex polygon: on the left of every edge."""
    ok = np.ones(len(pts), bool)
    for a, b in zip(poly, np.roll(poly, -1, axis=0)):
        ok &= np.cross(b - a, pts - a) @ normal >= -1e-9
    return ok


def test_sutherland_hodgman_matches_sampling_the_triangle():
    rng = np.random.default_rng(5)
    lo, hi = np.array(BOX[0]), np.array(BOX[1])
    tris = rng.uniform(-4, 14, (300, 3, 3))
    verts, counts = polygons3d(list(tris), BOX)
    starts = np.concatenate([[0], np.cumsum(counts)])
    nonempty = 0
    for tri, a, b in zip(tris, starts[:-1], starts[1:]):
        clipped = verts[a:b]
        w = rng.dirichlet([1, 1, 1], 400)
        samples = w @ tri
        inbox = ((samples >= lo) & (samples <= hi)).all(axis=1)
        if b - a == 0:
            assert inbox.sum() <= 2            # nothing (or a sliver a sample can hit)
            continue
        nonempty += 1
        assert ((clipped >= lo - 1e-9) & (clipped <= hi + 1e-9)).all()
        normal = np.cross(tri[1] - tri[0], tri[2] - tri[0])
        np.testing.assert_allclose((clipped - tri[0]) @ normal, 0, atol=1e-6 * np.linalg.norm(normal))
        margin = 1e-6
        strictly = ((samples > lo + margin) & (samples < hi - margin)).all(axis=1)
        outside = ((samples < lo - margin) | (samples > hi + margin)).any(axis=1)
        got = _inside_convex(clipped, samples, normal)
        assert got[strictly].all() and not got[outside].any()
    assert nonempty > 50


def test_polygon_attributes_are_interpolated_linearly_in_clip_space():
    rng = np.random.default_rng(9)
    coef = np.array([0.3, -1.2, 2.0, 0.7])
    polys = []
    for _ in range(200):
        p = rng.uniform(-2, 3, (4, 4))
        p[:, 3] = rng.uniform(-1, 2, 4)                    # some vertices behind the eye
        polys.append(np.hstack([p, (p @ coef)[:, None]]))  # an attribute linear in (x, y, z, w)
    verts, counts = polygons3d(polys, UNIT_CUBE, homogeneous=True)
    assert counts.sum() > 0
    np.testing.assert_allclose(verts[:, 4], verts[:, :4] @ coef, atol=1e-9)
    h = verts[:, :4]
    assert (h[:, 3] > 0).all()
    assert ((h[:, :3] >= -1e-9 * h[:, 3:]) & (h[:, :3] <= h[:, 3:] * (1 + 1e-9))).all()


def test_polygon3d_cases():
    sq = [(2, 2, 3), (8, 2, 3), (8, 3, 3), (2, 3, 3)]
    np.testing.assert_allclose(sl.clip.polygon3d(sq, BOX), sq)       # inside: unchanged
    assert sl.clip.polygon3d([(20, 0, 3), (30, 0, 3), (25, 2, 3)], BOX).shape == (0, 3)
    with pytest.raises(sl.ScanlineError, match="finite"):
        polygons3d([np.array([[0, 0, 0, np.nan], [1, 0, 0, 1], [0, 1, 0, 1]])], BOX)


# -- step tables ------------------------------------------------------------------------------------
def test_step_tables_agree_with_the_batch_clippers():
    rng = np.random.default_rng(11)
    segs = rng.uniform(-6, 16, (300, 6))
    for method, trace in (("cohen-sutherland", sl.trace.cohen_sutherland_3d),
                          ("liang-barsky", sl.trace.liang_barsky_3d)):
        out, ok = lines3d(segs, BOX, method=method)
        for s, o, k in zip(segs, out, ok):
            t = trace(s[:3], s[3:], volume=BOX)
            if not k:
                assert t.result is None
            else:
                np.testing.assert_allclose(np.concatenate(t.result), o, atol=1e-12)


def test_homogeneous_step_table_by_hand():
    # P0 = (1, 1, 1, 2) inside (NDC 0.5), P1 = (1, 1, -3, -2) behind the eye:
    # q = d(P0), p = d(P0) - d(P1); leaving x <= w, y <= w and z >= 0 at t = 1/4
    t = sl.trace.liang_barsky_3d((1, 1, 1), (1, 1, -3), w=(2, -2))
    rows = {r["plane"]: r for r in t.rows}
    assert (rows["right"]["p"], rows["right"]["q"], rows["right"]["t"]) == (4, 1, 0.25)
    assert (rows["front"]["p"], rows["front"]["q"], rows["front"]["t"]) == (4, 1, 0.25)
    assert rows["back"]["kind"] == "parallel, inside"
    assert t.result == ((1.0, 1.0, 1.0, 2.0), (1.0, 1.0, 0.0, 1.0))
    cs = sl.trace.cohen_sutherland_3d((1, 1, 1), (1, 1, -3), w=(2, -2))
    assert [r["code1"] for r in cs.rows][0] == "011010"    # front, above, right
    assert cs.result == t.result


@pytest.mark.parametrize("call, match", [
    (lambda: lines3d([(0, 0, 0, 1, 1)], BOX), "shape"),
    (lambda: lines3d([(0, 0, 0, 1, 1, 1)], ((0, 0, 0), (0, 1, 1))), "lo < hi"),
    (lambda: lines3d([(0, 0, 0, 1, 1, 1)], "box"), "box"),
    (lambda: lines3d([(0, 0, 0, 1, 1, 1)], BOX, method="sutherland"), "method"),
    (lambda: frustum(0.5), "z_min"),
    (lambda: homogeneous([(0, 0, 0, 1, 1, 1)]), "shape"),
    (lambda: sl.clip.polyhedron([[0, 0, 0, 1]]), "nonzero normal"),
])
def test_bad_input_is_a_clear_error(call, match):
    with pytest.raises(sl.ScanlineError, match=match):
        call()
