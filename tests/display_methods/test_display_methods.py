"""Three-dimensional display methods (Hearn & Baker, section 9-1): exploded views,
cutaway views with capped cuts, stereo pairs and anaglyphs -- checked against
closed forms written here, trimesh's mass properties and shapely's areas."""

import math

import numpy as np
import pytest
import shapely
import trimesh

import scanline as sl
from scanline.errors import ScanlineError


def area_centroid(mesh):
    """The area-weighted surface centroid, by trimesh."""
    t = trimesh.Trimesh(mesh.vertices, mesh.triangulated().faces, process=False)
    return (t.area_faces[:, None] * t.triangles_center).sum(axis=0) / t.area


def solid(mesh):
    return trimesh.Trimesh(mesh.vertices, mesh.triangulated().faces, process=False)


def edge_uses(mesh):
    """How many faces use each undirected edge (counted here from the face lists)."""
    counts = {}
    for i in range(mesh.face_count):
        f = mesh.face(i).tolist()
        for a, b in zip(f, f[1:] + f[:1]):
            key = (min(a, b), max(a, b))
            counts[key] = counts.get(key, 0) + 1
    return set(counts.values())


# -- exploded views ------------------------------------------------------------------------
@pytest.mark.parametrize("factor", [0.0, 0.5, 1.0, 1.7, 3.0])
def test_exploded_scales_centroid_distances_by_the_factor(factor):
    parts = [sl.mesh.teapot(3, parts=[p]) for p in ("lid", "body", "handle", "spout")]
    cents = np.array([area_centroid(m) for m in parts])
    t = [solid(m) for m in parts]
    center = sum(x.area * c for x, c in zip(t, cents)) / sum(x.area for x in t)
    moved = sl.draw3d.exploded(parts, factor)
    for before, after, c in zip(parts, moved, cents):
        c2 = area_centroid(after)
        np.testing.assert_allclose(c2 - center, factor * (c - center), atol=1e-9)
        # a translation: the shape is unchanged
        d = after.vertices - before.vertices
        np.testing.assert_allclose(d, np.broadcast_to(d[0], d.shape), atol=1e-12)


def test_exploded_about_a_given_center():
    cubes = [sl.mesh.cube(1.0, center=(2, 0, 0)), sl.mesh.cube(1.0, center=(0, 3, 0))]
    out = sl.draw3d.exploded(cubes, 2.0, center=(0, 0, 0))
    np.testing.assert_allclose(out[0].vertices.mean(axis=0), (4, 0, 0), atol=1e-12)
    np.testing.assert_allclose(out[1].vertices.mean(axis=0), (0, 6, 0), atol=1e-12)


@pytest.mark.parametrize("args", [([], 2), ("cube", 2), ([sl.mesh.cube()], -1),
                                  ([sl.mesh.cube()], float("nan")),
                                  ([sl.mesh.cube()], 2, (0, 0)), ([sl.mesh.cube()], 1e300)])
def test_exploded_refuses_bad_input(args):
    with pytest.raises(ScanlineError):
        sl.draw3d.exploded(*args)


# -- cutaway views -------------------------------------------------------------------------
CUBE = sl.mesh.cube(2.0)          # [-1, 1]^3


@pytest.mark.parametrize("c", [-0.8, -0.25, 0.0, 0.3, 0.9])
def test_cube_cut_by_a_plane_x_equals_c(c):
    cut = sl.draw3d.cutaway(CUBE, (1, 0, 0, -c))          # keep x >= c
    closed = solid(cut.closed[0])
    assert closed.is_watertight and closed.is_winding_consistent
    assert closed.volume == pytest.approx(4 * (1 - c), rel=1e-12)
    cap = solid(cut.caps[0])
    assert cap.area == pytest.approx(4.0, rel=1e-12)              # the 2 x 2 square
    np.testing.assert_allclose(cut.caps[0].vertices[:, 0], c, atol=1e-12)
    np.testing.assert_allclose(cut.caps[0].normals, np.tile((-1, 0, 0), (len(cap.vertices), 1)),
                               atol=1e-12)
    assert cut.meshes[0].vertices[:, 0].min() == pytest.approx(c)
    assert edge_uses(cut.closed[0]) == {2}


@pytest.mark.parametrize("t", [0.3, 1.0, 1.9])
def test_cube_corner_cut_off_is_a_tetrahedron(t):
    # keep x + y + z <= -3 + t: the corner (-1, -1, -1) with legs t
    cut = sl.draw3d.cutaway(CUBE, (-1, -1, -1, -3 + t))
    closed = solid(cut.closed[0])
    assert closed.is_watertight and edge_uses(cut.closed[0]) == {2}
    assert closed.volume == pytest.approx(t ** 3 / 6, rel=1e-9)
    assert solid(cut.caps[0]).area == pytest.approx(math.sqrt(3) / 2 * t * t, rel=1e-9)
    loop = cut.loops[0]
    assert len(loop) == 1
    # the loop's three corners, at distance t along the edges from the corner
    corners = {tuple(np.round(p, 9)) for p in loop[0]}
    expected = {tuple(np.round(np.where(np.eye(3)[i] > 0, -1 + t, -1.0), 9)) for i in range(3)}
    assert expected <= corners


def test_three_planes_leave_an_octant():
    cut = sl.draw3d.cutaway(CUBE, [(1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0)])
    closed = solid(cut.closed[0])
    assert closed.is_watertight and closed.is_winding_consistent
    assert closed.volume == pytest.approx(1.0, rel=1e-12)
    assert solid(cut.caps[0]).area == pytest.approx(3.0, rel=1e-12)   # three unit squares
    np.testing.assert_allclose(closed.bounds, [[0, 0, 0], [1, 1, 1]], atol=1e-12)


def test_oblique_planes_keep_the_mesh_closed():
    rng = np.random.default_rng(4)
    for _ in range(10):
        planes = np.hstack([rng.normal(size=(2, 3)), rng.uniform(-0.3, 0.3, (2, 1))])
        cut = sl.draw3d.cutaway(CUBE, planes)
        closed = solid(cut.closed[0])
        assert closed.is_watertight and closed.is_winding_consistent
        assert edge_uses(cut.closed[0]) == {2}
        # the volume by a Monte Carlo count of the same half-spaces, independently
        p = rng.uniform(-1, 1, (200_000, 3))
        inside = ((p @ planes[:, :3].T + planes[:, 3]) >= 0).all(axis=1)
        assert closed.volume == pytest.approx(8 * inside.mean(), abs=0.03)


def test_torus_cut_through_its_hole_has_a_ring_cap():
    ring = sl.mesh.torus(1.0, 0.3, resolution=(48, 16))
    whole = solid(ring).volume
    cut = sl.draw3d.cutaway(ring, (0, 0, -1, 0.02))       # keep z <= 0.02
    closed = solid(cut.closed[0])
    assert closed.is_watertight and closed.is_winding_consistent
    assert len(cut.loops[0]) == 2                          # outer circle and hole
    polys = [shapely.Polygon(lp[:, :2]) for lp in cut.loops[0]]
    outer, hole = sorted(polys, key=lambda p: -p.area)
    assert solid(cut.caps[0]).area == pytest.approx(outer.area - hole.area, rel=1e-9)
    # the half below z = 0 plus the slab 0 < z < 0.02
    assert closed.volume == pytest.approx(whole / 2 + 0.02 * (outer.area - hole.area), rel=1e-3)


def test_vertical_cut_of_a_torus_halves_it():
    ring = sl.mesh.torus(1.0, 0.3, resolution=(48, 16))
    cut = sl.draw3d.cutaway(ring, (0, 1, 0, 0))
    assert len(cut.loops[0]) == 2                          # two separate discs
    assert solid(cut.closed[0]).volume == pytest.approx(solid(ring).volume / 2, rel=1e-9)


def test_cut_keeps_face_colors_and_interpolates_normals():
    sphere = sl.mesh.sphere(1.0, resolution=(24, 12)).colored("orange")
    cut = sl.draw3d.cutaway(sphere, (0, 0, 1, -0.2), cap_color="gray")
    body = cut.meshes[0]
    assert body.color_on == "face" and (body.colors[:, :3] == (255, 165, 0)).all()
    np.testing.assert_allclose(np.linalg.norm(body.normals, axis=1), 1, atol=1e-12)
    assert (cut.caps[0].colors[:, :3] == (128, 128, 128)).all()
    assert body.vertices[:, 2].min() == pytest.approx(0.2)


def test_open_mesh_is_cut_without_a_cap():
    square = sl.mesh.Mesh([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], [[0, 1, 2, 3]])
    cut = sl.draw3d.cutaway(square, (1, 0, 0, -0.5))
    assert cut.caps[0] is None and cut.loops[0] == []
    assert solid(cut.meshes[0]).area == pytest.approx(0.5)


def test_plane_missing_the_mesh():
    assert len(sl.draw3d.cutaway(CUBE, (1, 0, 0, 5)).meshes[0].vertices) == 8
    gone = sl.draw3d.cutaway(CUBE, (1, 0, 0, -5))
    assert gone.meshes[0] is None and gone.caps[0] is None and gone.drawable() == []


@pytest.mark.parametrize("planes", [(0, 0, 0, 1), (1, 0, 0), [(1, 0, float("nan"), 0)],
                                    "x", np.zeros((0, 4)), np.ones((65, 4))])
def test_cutaway_refuses_bad_planes(planes):
    with pytest.raises(ScanlineError):
        sl.draw3d.cutaway(CUBE, planes)


# -- stereo pairs --------------------------------------------------------------------------
@pytest.mark.parametrize("eye, target, up", [((0, 1, 5), (0, 0, 0), (0, 1, 0)),
                                              ((3, -2, 4), (0.5, 0, 1), (0, 0, 1)),
                                              ((-6, 2, -1), (1, 1, 1), (0, 1, 0))])
def test_stereo_cameras_are_symmetric_about_the_mono_camera(eye, target, up):
    cam = sl.Camera(eye=eye, target=target, up=up)
    sep = 0.4
    left, right = cam.stereo(sep)
    n = np.subtract(eye, target) / np.linalg.norm(np.subtract(eye, target))
    u = np.cross(up, n) / np.linalg.norm(np.cross(up, n))   # Hearn & Baker 12-2: u = V x N
    np.testing.assert_allclose(left.eye, np.add(eye, -sep / 2 * u), atol=1e-12)
    np.testing.assert_allclose(right.eye, np.add(eye, sep / 2 * u), atol=1e-12)
    assert left.target == right.target == cam.target
    # the mirror image of the left eye in the mono camera's y_v z_v plane is the right eye
    mirror = left.eye - 2 * np.dot(np.subtract(left.eye, eye), u) * u
    np.testing.assert_allclose(mirror, right.eye, atol=1e-12)
    # a point on the mono camera's axis projects symmetrically about the image center
    p = np.add(target, 0.0)
    xl = left.project([p], 101, 101)[0, 0]
    xr = right.project([p], 101, 101)[0, 0]
    assert xl == pytest.approx(50) and xr == pytest.approx(50)
    q = np.add(target, 0.5 * n)                                 # nearer the eyes than the target
    assert left.project([q], 101, 101)[0, 0] - 50 == pytest.approx(
        50 - right.project([q], 101, 101)[0, 0], abs=1e-9)


@pytest.mark.parametrize("sep", [-1, float("nan"), "a"])
def test_stereo_refuses_bad_separation(sep):
    with pytest.raises(ScanlineError):
        sl.Camera(eye=(0, 0, 5), target=(0, 0, 0)).stereo(sep)


def test_stereo_needs_an_eye_and_a_target():
    with pytest.raises(ScanlineError, match="eye= and target="):
        sl.Camera(target=(0, 0, 0), projection=sl.projection.isometric()).stereo(0.1)


def test_anaglyph_channels_are_the_eyes_luminances():
    rng = np.random.default_rng(2)
    a = rng.integers(0, 256, (30, 40, 3), dtype=np.uint8)
    b = rng.integers(0, 256, (30, 40, 3), dtype=np.uint8)
    out = sl.draw3d.anaglyph(sl.FrameBuffer.from_array(a), sl.FrameBuffer.from_array(b))
    img = out.to_array().astype(float)

    def luma(x):                          # ITU-R BT.601
        return x[..., 0] * 0.299 + x[..., 1] * 0.587 + x[..., 2] * 0.114

    assert np.abs(img[..., 0] - luma(a.astype(float))).max() <= 0.5 + 1e-9
    assert np.abs(img[..., 1] - luma(b.astype(float))).max() <= 0.5 + 1e-9
    assert (img[..., 1] == img[..., 2]).all()


def test_anaglyph_of_gray_views_and_side_by_side():
    left = sl.FrameBuffer(8, 4, mode="L", background=200)
    right = sl.FrameBuffer(8, 4, mode="L", background=50)
    assert sl.draw3d.anaglyph(left, right).to_array()[0, 0].tolist() == [200, 50, 50]
    pair = sl.draw3d.side_by_side(left, right, gap=3).to_array()
    assert pair.shape == (4, 19, 3)
    assert pair[0, 0].tolist() == [200] * 3 and pair[0, -1].tolist() == [50] * 3
    assert pair[0, 9].tolist() == [255] * 3
    crossed = sl.draw3d.side_by_side(left, right, crossed=True).to_array()
    assert crossed[0, 0].tolist() == [50] * 3


def test_anaglyph_refuses_mismatched_views():
    with pytest.raises(ScanlineError, match="same size"):
        sl.draw3d.anaglyph(sl.FrameBuffer(4, 4), sl.FrameBuffer(5, 4))
    with pytest.raises(ScanlineError):
        sl.draw3d.anaglyph(np.zeros((4, 4)), sl.FrameBuffer(4, 4))


def test_planes_through_vertices_and_faces_keep_the_mesh_closed():
    # planes through mesh vertices, some containing whole faces (the torus's flat
    # bottom band at z = -0.3 sin 72 degrees, the box's faces)
    rng = np.random.default_rng(11)
    meshes = [CUBE, sl.mesh.box((0, 0, 0), (1, 2, 3)), sl.mesh.torus(1, 0.3, resolution=(24, 10)),
              sl.mesh.sphere(1, resolution=(16, 8))]
    z = -0.3 * math.sin(math.radians(72))
    cases = [(meshes[2], [(0, 0, -1, z)]), (meshes[2], [(0, 0, 1, -z)]),
             (meshes[1], [(0, 0, -1, 0.0)]), (meshes[1], [(0, 0, 1, 0.0), (-1, -2, -1, 3)])]
    for _ in range(60):
        m = meshes[rng.integers(4)]
        k = rng.integers(1, 4)
        v = m.vertices[rng.integers(0, len(m.vertices), k)]
        n = np.round(rng.normal(size=(k, 3)))
        n[np.all(n == 0, axis=1)] = (1, 0, 0)
        cases.append((m, np.hstack([n, -(n * v).sum(axis=1)[:, None]])))
    for m, planes in cases:
        cut = sl.draw3d.cutaway(m, planes)
        if cut.closed[0] is None:
            continue
        assert edge_uses(cut.closed[0]) == {2}, planes
        assert solid(cut.closed[0]).is_winding_consistent
    flat = sl.draw3d.cutaway(meshes[2], (0, 0, -1, z))       # only the band in the plane
    assert flat.meshes[0] is None or solid(flat.closed[0]).volume == pytest.approx(0, abs=1e-12)
    whole = sl.draw3d.cutaway(meshes[2], (0, 0, 1, -z))       # keep z >= z: the band stays
    assert solid(whole.closed[0]).volume == pytest.approx(solid(meshes[2]).volume, rel=1e-12)
