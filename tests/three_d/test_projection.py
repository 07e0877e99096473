"""Projections and the camera (scanline.projection): the textbook matrices written out
by hand from Hearn & Baker, section 12-3; the view-volume normalization against
OpenGL's matrices (gluPerspective, glFrustum, glOrtho, gluLookAt) built here;
vanishing points; bad cameras."""

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import scanline as sl
from scanline.projection import (axonometric, dimetric, foreshortening, frustum, isometric,
                                 oblique, orthographic, parallel, perspective)
from scanline.transform3d import apply
from tests.reference import HYPOTHESIS


def close(a, b, tol=1e-9):
    np.testing.assert_allclose(a, b, rtol=0, atol=tol)


# -- OpenGL's matrices, written here from the OpenGL reference pages ----------------------
def gl_perspective(fovy, aspect, near, far):
    f = 1 / math.tan(fovy / 2)
    return np.array([[f / aspect, 0, 0, 0], [0, f, 0, 0],
                     [0, 0, (far + near) / (near - far), 2 * far * near / (near - far)],
                     [0, 0, -1, 0]])


def gl_frustum(l, r, b, t, n, f):
    return np.array([[2 * n / (r - l), 0, (r + l) / (r - l), 0],
                     [0, 2 * n / (t - b), (t + b) / (t - b), 0],
                     [0, 0, -(f + n) / (f - n), -2 * f * n / (f - n)], [0, 0, -1, 0]])


def gl_ortho(l, r, b, t, n, f):
    return np.array([[2 / (r - l), 0, 0, -(r + l) / (r - l)], [0, 2 / (t - b), 0, -(t + b) / (t - b)],
                     [0, 0, -2 / (f - n), -(f + n) / (f - n)], [0, 0, 0, 1]])


def glu_look_at(eye, center, up):
    eye, center, up = (np.asarray(x, float) for x in (eye, center, up))
    f = (center - eye) / np.linalg.norm(center - eye)
    s = np.cross(f, up)
    s /= np.linalg.norm(s)
    u = np.cross(s, f)
    m = np.eye(4)
    m[0, :3], m[1, :3], m[2, :3] = s, u, -f
    t = np.eye(4)
    t[:3, 3] = -eye
    return m @ t


def gl_ndc(matrix, pts):
    h = np.hstack([pts, np.ones((len(pts), 1))]) @ matrix.T
    return h[:, :3] / h[:, 3:]


def our_ndc(matrix, pts):
    """Our NDC (0..1) of points through a clip matrix, mapped to OpenGL's -1..1."""
    h = np.hstack([pts, np.ones((len(pts), 1))]) @ matrix.T
    return 2 * h[:, :3] / h[:, 3:] - 1


rng = np.random.default_rng(12)
PTS = rng.uniform(-3, 3, (200, 3)) + [0, 0, -6]


# -- the textbook matrices ----------------------------------------------------------------
def test_perspective_is_hearn_and_bakers_m_pers():
    zprp, zvp = 7.0, 2.0
    dp = zprp - zvp
    m_pers = np.array([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, -zvp / dp, zvp * zprp / dp],
                       [0, 0, -1 / dp, zprp / dp]])
    p = perspective(z_prp=zprp, z_vp=zvp)
    close(p.matrix, m_pers)
    close(np.asarray(p), m_pers)
    # x_p = x (z_prp - z_vp) / (z_prp - z), y likewise, z_p = z_vp
    x, y, z = PTS.T
    out = apply(p, PTS)
    close(out[:, 0], x * dp / (zprp - z))
    close(out[:, 1], y * dp / (zprp - z))
    close(out[:, 2], zvp)


def test_oblique_projections_follow_the_formula():
    for kind, tan_alpha in (("cavalier", 1.0), ("cabinet", 2.0)):
        for phi in (math.radians(30), math.radians(45)):
            l1 = 1 / tan_alpha
            m = np.array([[1, 0, l1 * math.cos(phi), 0], [0, 1, l1 * math.sin(phi), 0],
                          [0, 0, 1, 0], [0, 0, 0, 1]])
            close(oblique(kind, phi=phi).matrix, m)
    a = 1.1
    close(oblique(alpha=a, phi=0.2).matrix[:2, 2],
          [math.cos(0.2) / math.tan(a), math.sin(0.2) / math.tan(a)])
    # cabinet: a unit edge along z is drawn half as long, cavalier full length
    q = apply(oblique("cabinet", phi=0.5), [(0, 0, 0), (0, 0, 1)])
    assert math.dist(q[0][:2], q[1][:2]) == pytest.approx(0.5)
    q = apply(oblique("cavalier", phi=0.5), [(0, 0, 0), (0, 0, 1)])
    assert math.dist(q[0][:2], q[1][:2]) == pytest.approx(1.0)


def test_general_parallel_projection_is_the_shear_a_b():
    p = parallel((1, 2, -4))          # a = -px/pz = 1/4, b = 1/2
    close(p.matrix, [[1, 0, 0.25, 0], [0, 1, 0.5, 0], [0, 0, 1, 0], [0, 0, 0, 1]])
    # every point moves along the projection vector onto z = 0
    q = np.array([3.0, -1.0, 2.0])
    t = -q[2] / -4
    close(apply(p, q)[:2], (q + t * np.array([1, 2, -4]))[:2])


def test_standard_views_by_hand():
    pt = (1, 2, 3)
    assert apply(orthographic(), pt).tolist() == [1, 2, 3]
    close(apply(orthographic("front"), pt), (1, 2, 3))
    close(apply(orthographic("side"), pt), (-3, 2, 1))      # from +x: z to the left
    close(apply(orthographic("rear"), pt), (-1, 2, -3))
    close(apply(orthographic("left"), pt), (3, 2, -1))
    close(apply(orthographic("top"), pt), (1, -3, 2))       # from +y, -z up: front at the bottom
    close(apply(orthographic("bottom"), pt), (1, 3, -2))


def test_axonometric_foreshortening():
    f = foreshortening(isometric())
    close(f, [math.sqrt(2 / 3)] * 3)
    m = isometric().matrix
    # the isometric view looks along (1, 1, 1): it maps onto the viewing z axis
    close(m[:3, :3] @ (np.ones(3) / math.sqrt(3)), (0, 0, 1))
    # the projected axes are 120 degrees apart
    ang = [math.atan2(m[1, k], m[0, k]) for k in range(3)]
    close([math.cos(a - b) for a, b in zip(ang, ang[1:] + ang[:1])], [-0.5] * 3)
    fx, fy, fz = foreshortening(dimetric(0.5))
    assert fx == pytest.approx(fy) and fz == pytest.approx(0.5)
    phi, theta = -0.4, 0.3
    fx, fy, fz = foreshortening(axonometric(phi, theta))
    assert fx == pytest.approx(math.sqrt(math.cos(phi) ** 2 + math.sin(phi) ** 2 * math.sin(theta) ** 2))
    assert fy == pytest.approx(math.cos(theta))
    assert fz == pytest.approx(math.sqrt(math.sin(phi) ** 2 + math.cos(phi) ** 2 * math.sin(theta) ** 2))


# -- normalization against OpenGL ------------------------------------------------------------
def test_field_of_view_normalization_matches_gluperspective():
    p = perspective(fov=0.9, aspect=1.5, near=0.5, far=40)
    close(our_ndc(p.normalization, PTS), gl_ndc(gl_perspective(0.9, 1.5, 0.5, 40), PTS), 1e-9)


def test_oblique_frustum_normalization_matches_glfrustum():
    p = frustum((0, 0, 0), window=(-1, -0.5, 3, 2), z_vp=-1.5, front=-1.5, back=-30)
    close(our_ndc(p.normalization, PTS), gl_ndc(gl_frustum(-1, 3, -0.5, 2, 1.5, 30), PTS), 1e-9)


def test_off_axis_center_of_projection_projects_through_the_prp():
    prp = np.array([1.0, -2.0, 5.0])
    p = frustum(prp, window=(-2, -1, 2, 3), z_vp=0, back=-20)
    out = apply(p, PTS)
    t = (0 - prp[2]) / (PTS[:, 2] - prp[2])   # where the line prp -> point meets z = 0
    close(out[:, :2], prp[:2] + t[:, None] * (PTS[:, :2] - prp[:2]), 1e-9)
    # and the normalization puts those projections at (x_p - xmin) / (xmax - xmin)
    h = np.hstack([PTS, np.ones((len(PTS), 1))]) @ p.normalization.T
    close(h[:, 0] / h[:, 3], (out[:, 0] + 2) / 4, 1e-9)
    close(h[:, 1] / h[:, 3], (out[:, 1] + 1) / 4, 1e-9)


def test_parallel_normalization_matches_glortho_and_the_oblique_volume():
    p = orthographic(window=(-2, -1, 4, 3), front=-1, back=-10)
    close(our_ndc(p.normalization, PTS), gl_ndc(gl_ortho(-2, 4, -1, 3, 1, 10), PTS), 1e-9)
    q = oblique("cabinet", phi=0.6, window=(-2, -1, 4, 3), front=-1, back=-10)
    h = np.hstack([PTS, np.ones((len(PTS), 1))]) @ q.normalization.T
    xp = apply(q, PTS)
    close(h[:, 0], (xp[:, 0] + 2) / 6)
    close(h[:, 2], (-1 - PTS[:, 2]) / 9)


def test_camera_matches_glulookat_and_gluperspective():
    eye, target, up = (4, 3, 6), (0.5, 0, -1), (0, 1, 0.2)
    cam = sl.Camera(eye=eye, target=target, up=up, keep_aspect=False,
                    projection=perspective(fov=0.8, aspect=640 / 480, near=1, far=50))
    close(cam.view_matrix, glu_look_at(eye, target, up))
    pts = rng.uniform(-2, 2, (300, 3))
    ndc = gl_ndc(gl_perspective(0.8, 640 / 480, 1, 50) @ glu_look_at(eye, target, up), pts)
    got = cam.project(pts, 641, 481)
    close(got[:, 0], (ndc[:, 0] + 1) / 2 * 640, 1e-7)
    close(got[:, 1], (ndc[:, 1] + 1) / 2 * 480, 1e-7)
    close(got[:, 2], (ndc[:, 2] + 1) / 2, 1e-9)


def test_hearn_and_baker_camera_form_is_the_eye_form():
    # VRP at the target, N toward the eye, prp at distance d: the same picture as eye/target
    d = 8.0
    n = np.array([1.0, 2.0, 2.0]) / 3
    a = sl.Camera(view_reference_point=(0, 0, 0), view_plane_normal=n, view_up=(0, 1, 0),
                  projection=perspective(z_prp=d, z_vp=d - 1, window=(-0.5, -0.5, 0.5, 0.5),
                                         back=-30))
    b = sl.Camera(eye=d * n, target=(0, 0, 0), up=(0, 1, 0),
                  projection=perspective(fov=2 * math.atan(0.5), near=1, far=d + 30))
    pts = rng.uniform(-2, 2, (50, 3))
    close(a.project(pts, 200, 200)[:, :2], b.project(pts, 200, 200)[:, :2], 1e-7)
    close(a.eye, d * n)


def test_keep_aspect_widens_the_window_and_keeps_squares_square():
    cam = sl.Camera(projection=orthographic(window=(-1, -1, 1, 1)))
    sq = cam.project([(-1, -1, 0), (1, 1, 0)], 401, 201)
    close(sq, [[100, 0, 0.5], [300, 200, 0.5]])
    flat = cam.replace(keep_aspect=False).project([(-1, -1, 0), (1, 1, 0)], 401, 201)
    close(flat[:, :2], [[0, 0], [400, 200]])


def test_viewport_maps_the_unit_cube_to_part_of_the_device():
    cam = sl.Camera(projection=orthographic(front=1, back=-1), viewport=(0.5, 0, 0.2, 1, 0.5, 0.4),
                    keep_aspect=False)
    close(cam.project((-1, -1, 1), 101, 101), (50, 0, 0.2))
    close(cam.project((1, 1, -1), 101, 101), (100, 50, 0.4))


def test_points_behind_the_eye_are_nan_not_mirrored():
    cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0), projection=perspective(fov=1, near=1))
    out = cam.project([(0, 0, 0), (0, 0, 10), (1, 1, 5)], 100, 100)
    assert np.isfinite(out[0]).all()
    assert np.isnan(out[1:]).all()
    assert cam.visible([(0, 0, 0), (0, 0, 10), (0, 0, 4.5)]).tolist() == [True, False, False]


@given(st.floats(-3, 3), st.floats(-3, 3), st.floats(-3, 3))
@HYPOTHESIS
def test_linear_depth_is_the_distance_beyond_the_front_plane(x, y, z):
    cam = sl.Camera(eye=(0, 0, 10), target=(0, 0, 0), projection=perspective(fov=1, near=2, far=30))
    d = cam.project((x, y, z), 64, 64)[2]
    assert cam.linear_depth(d) == pytest.approx((10 - z) - 2, abs=1e-8)


def test_vanishing_points_one_two_and_three_point_perspective():
    proj = perspective(fov=1.0, near=0.5)
    axes = np.eye(3)
    one = sl.Camera(eye=(0.3, 0.4, 6), target=(0.3, 0.4, 0), projection=proj)
    two = sl.Camera(eye=(5, 0.5, 5), target=(0, 0.5, 0), projection=proj)
    three = sl.Camera(eye=(5, 4, 5), target=(0, 0, 0), projection=proj)
    for cam, count in ((one, 1), (two, 2), (three, 3)):
        vps = [cam.vanishing_point(a, 400, 300) for a in axes]
        assert sum(vp is not None for vp in vps) == count
        for a, vp in zip(axes, vps):
            if vp is None:
                continue
            far = cam.project([(0.2, 0.1, -0.3) + 1e7 * a], 400, 300)[0]
            back = cam.project([(0.2, 0.1, -0.3) - 1e7 * a], 400, 300)[0]
            ok = [p for p in (far, back) if np.isfinite(p).all()]
            assert ok and np.allclose(ok[0][:2], vp, atol=1e-3)


def test_view_volume_corners_map_to_the_unit_cube():
    cam = sl.Camera(eye=(1, 2, 3), target=(0, 0, 0),
                    projection=perspective(fov=0.7, aspect=2, near=1, far=9))
    corners = cam.volume_corners()
    h = np.hstack([corners, np.ones((8, 1))]) @ cam.matrix().T
    close(h[:, :3] / h[:, 3:], [[x, y, z] for z in (0, 1) for x, y in
                                ((0, 0), (1, 0), (1, 1), (0, 1))], 1e-9)


@pytest.mark.parametrize("make, match", [
    (lambda: sl.Camera(eye=(1, 1, 1), target=(1, 1, 1)), "same point"),
    (lambda: sl.Camera(eye=(0, 5, 0), target=(0, 0, 0), up=(0, 1, 0)), "parallel"),
    (lambda: sl.Camera(eye=(0, 5, 0), target=(0, 0, 0), up=(0, 0, 0)), "zero vector"),
    (lambda: sl.Camera(eye=(0, 5, 0)), "both eye and target"),
    (lambda: sl.Camera(eye=(0, 5, 0), target=(0, 0, 0), view_up=(0, 1, 0)), "not both"),
    (lambda: sl.Camera(eye=(float("nan"), 0, 1), target=(0, 0, 0)), "finite"),
    (lambda: sl.Camera(projection="perspective"), "Projection"),
    (lambda: perspective(fov=1, near=2, far=2), "far must be greater"),
    (lambda: perspective(fov=1, near=3, far=2), "far must be greater"),
    (lambda: perspective(fov=0, near=1), "fov"),
    (lambda: perspective(fov=math.pi, near=1), "fov"),
    (lambda: perspective(fov=1, near=0), "near must be > 0"),
    (lambda: perspective(fov=1), "needs near"),
    (lambda: perspective(z_prp=0, z_vp=1), "z_prp > z_vp"),
    (lambda: perspective(z_prp=5, z_vp=0, front=6), "front"),
    (lambda: perspective(z_prp=5, z_vp=0, front=-1, back=0), "back < front"),
    (lambda: orthographic(front=0, back=1), "back < front"),
    (lambda: orthographic(window=(0, 0, 0, 1)), "degenerate"),
    (lambda: orthographic("diagonal"), "view"),
    (lambda: oblique(), "either kind"),
    (lambda: oblique("cavalier", alpha=1), "either kind"),
    (lambda: oblique(alpha=math.pi / 2), "alpha"),
    (lambda: parallel((1, 1, 0)), "parallel"),
    (lambda: dimetric(1.5), "fz"),
    (lambda: sl.Camera(viewport=(0, 0, 0, 1, 1, 2)), "viewport"),
    (lambda: sl.Camera().project([(0, 0, 0)], 0, 10), "width"),   # 1 is a device (1 x N)
])
def test_degenerate_cameras_and_projections_are_clear_errors(make, match):
    with pytest.raises(sl.ScanlineError, match=match):
        make()
