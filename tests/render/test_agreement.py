"""The agreement harness of the one 3-D pipeline: random scenes of every hard kind --
intersecting triangles, cyclic overlap, a solid piercing another, triangles crossing
the near plane, one face covering the whole view -- on tall and wide devices, through
perspective, parallel and oblique projections, rendered by every method of
``sl.visible.METHODS`` and compared pixel by pixel with a ray caster written here.

The reference shares nothing with the package's pipeline but the camera's own matrix:
each pixel center is taken back through the inverse of the world -> device mapping to
the segment of its ray between the front and the back plane, and that segment is
intersected with every triangle of the meshes' faces in world coordinates
(Moller-Trumbore); the nearest hit gives the face.  Pixels whose center lies within a
hair of a triangle's edge, or whose two nearest hits are within a hair of each other,
could go either way by the fill's tie rule and are left out (and counted).  Every
method must give the reference's face at every other pixel, with no exception but the
painter's one-key sort on the scenes it cannot order (the counter-example)."""

import math

import numpy as np
import pytest

import scanline as sl

EDGE = 1e-7           # barycentric margin: the center is on an edge
DEPTH = 1e-9          # ray-parameter margin: two surfaces meet there


def rays(cam, width, height):
    """World points (H, W, 3) where each pixel center's ray meets the front plane (t =
    0) and the back plane (t = 1), from the inverse of the camera's mapping."""
    clip, scale, offset = cam.mapping((0.0, 0.0, float(width - 1), float(height - 1)))
    inv = np.linalg.inv(clip)
    y, x = np.mgrid[0:height, 0:width].astype(float)
    ends = []
    for depth in (offset[2], offset[2] + scale[2]):           # device depth of the planes
        ndc = np.stack([(x - offset[0]) / scale[0], (y - offset[1]) / scale[1],
                        np.full_like(x, (depth - offset[2]) / scale[2]), np.ones_like(x)], -1)
        h = ndc @ inv.T
        ends.append(h[..., :3] / h[..., 3:4])
    return ends


def triangles(meshes):
    """Every face's fan triangles in world coordinates (K, 3, 3) and the face (numbered
    mesh after mesh) of each."""
    tris, faces, base = [], [], 0
    for m in meshes:
        for f in range(m.face_count):
            idx = m.face(f)
            for k in range(1, len(idx) - 1):
                tris.append(m.vertices[[idx[0], idx[k], idx[k + 1]]])
                faces.append(base + f)
        base += m.face_count
    return np.array(tris, float).reshape(-1, 3, 3), np.array(faces)


def reference(meshes, cam, width, height):
    """``(face, ambiguous)``: the reference face at each pixel (-1 none) and the pixels
    left out."""
    p0, p1 = rays(cam, width, height)
    tris, faces = triangles(meshes)
    out = np.full((height, width), -1)
    unsure = np.zeros((height, width), bool)
    a, e1, e2 = tris[:, 0], tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0]
    for y in range(height):
        for x in range(width):
            o, d = p0[y, x], p1[y, x] - p0[y, x]
            pv = np.cross(d, e2)
            det = (e1 * pv).sum(axis=1)
            ok = np.abs(det) > 1e-300
            inv = np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)
            tv = o - a
            u = (tv * pv).sum(axis=1) * inv
            qv = np.cross(tv, e1)
            v = (d * qv).sum(axis=1) * inv
            t = (e2 * qv).sum(axis=1) * inv
            inside = ok & (u >= -EDGE) & (v >= -EDGE) & (u + v <= 1 + EDGE) & \
                (t >= -DEPTH) & (t <= 1 + DEPTH)
            if not inside.any():
                continue
            near = np.flatnonzero(inside)[np.argsort(t[inside], kind="stable")]
            first = near[0]
            out[y, x] = faces[first]
            margin = min(u[first], v[first], 1 - u[first] - v[first])
            rival = [k for k in near[1:] if faces[k] != faces[first]]
            unsure[y, x] = (margin < EDGE or t[first] < DEPTH or t[first] > 1 - DEPTH
                            or (rival and t[rival[0]] - t[first] < DEPTH))
    return out, unsure


def perspective(eye=(2.0, 1.5, 5.0), target=(0, 0, 0)):
    return sl.Camera(eye=eye, target=target,
                     projection=sl.projection.perspective(fov=math.radians(32), near=0.5,
                                                          far=30))


def parallel(eye=(2.0, 1.5, 5.0)):
    return sl.Camera(eye=eye, target=(0, 0, 0),
                     projection=sl.projection.orthographic(window=(-1.8, -1.4, 1.8, 1.4),
                                                           front=-1, back=-12))


def oblique(eye=(0.5, 0.5, 5.0)):
    return sl.Camera(eye=eye, target=(0, 0, 0),
                     projection=sl.projection.oblique("cabinet", phi=math.radians(30),
                                                      window=(-1.8, -1.4, 1.8, 1.4), front=-1,
                                                      back=-12, z_vp=-5.0))


def soup(rng, n=14):
    """Random triangles: they intersect and overlap cyclically."""
    verts = rng.uniform(-1.8, 1.8, size=(3 * n, 3))
    return [sl.mesh.Mesh(verts, np.arange(3 * n).reshape(n, 3))]


def bars(rng):
    """Three bars each lying over the next (cyclic overlap), tilted at random."""
    out = []
    tilt = rng.uniform(0.25, 0.45)
    for k in range(3):
        a = 2 * np.pi * k / 3 + rng.uniform(-0.1, 0.1)
        c, s = np.cos(a), np.sin(a)
        turn = np.array([[c, -s, 0, 0], [s, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])
        shift = np.array([[1, 0, 0, 0], [0, 1, 0, 0.55], [0, 0, 1, 0], [0, 0, 0, 1]])
        bar = sl.mesh.Mesh([(-1.6, -0.22, -tilt), (1.6, -0.22, tilt), (1.6, 0.22, tilt),
                            (-1.6, 0.22, -tilt)], [[0, 1, 2, 3]])
        out.append(bar.transformed(turn @ shift))
    return out


def pierced(rng):
    """A cube pierced by a sphere and a torus."""
    c = rng.uniform(-0.3, 0.3, 3)
    return [sl.mesh.cube(1.4), sl.mesh.sphere(0.75, tuple(c + (0.6, 0.4, 0.5)), resolution=10),
            sl.mesh.torus(0.9, 0.2, tuple(c), resolution=(14, 6))]


def near_plane(rng):
    """A floor running under and behind the eye, and triangles crossing the near plane."""
    floor = sl.mesh.Mesh([(-40, -1, -40), (40, -1, -40), (40, -1, 40), (-40, -1, 40)],
                         [[0, 3, 2, 1]])
    verts = np.concatenate([rng.uniform([-1.5, -0.9, 2.0], [1.5, 1.2, 7.0], size=(18, 3))])
    return [floor, sl.mesh.Mesh(verts, np.arange(18).reshape(6, 3))]


def full_view(rng):
    """One tilted face far larger than the view, and a box in front of part of it."""
    z = rng.uniform(-2, -1)
    wall = sl.mesh.Mesh([(-60, -60, z - 3), (60, -60, z), (60, 60, z + 3), (-60, 60, z)],
                        [[0, 1, 2], [0, 2, 3]])
    return [wall, sl.mesh.box((-0.5, -0.4, 0), (0.7, 0.5, 0.6))]


SCENES = {"soup": soup, "bars": bars, "pierced": pierced, "near plane": near_plane,
          "full view": full_view}
CAMERAS = {"perspective": perspective, "parallel": parallel, "oblique": oblique}
#: (width, height): wide and tall devices
DEVICES = [(44, 20), (18, 40)]
#: The scenes the painter's one key per polygon cannot order.
PAINTER_FAILS = {"soup", "bars", "pierced"}


def cases():
    out = []
    for i, scene in enumerate(SCENES):
        for j, cam in enumerate(CAMERAS):
            if scene == "near plane" and cam != "perspective":
                continue        # nothing lies behind the eye of a parallel view
            for k in range(2):
                out.append((scene, cam, DEVICES[(i + j + k) % 2], 100 * i + 10 * j + k))
    return out


@pytest.mark.parametrize("scene, camera, device, seed", cases())
def test_every_method_agrees_with_the_reference_ray_caster(scene, camera, device, seed):
    meshes = SCENES[scene](np.random.default_rng(seed))
    cam = CAMERAS[camera]()
    w, h = device
    ref, unsure = reference(meshes, cam, w, h)
    sure = ~unsure
    assert unsure.mean() < 0.05, unsure.sum()                 # a few edge pixels at most
    assert (ref[sure] >= 0).sum() > 0.1 * w * h               # the scene is seen
    bad = {}
    for method in sorted(sl.visible.METHODS):
        extra = {"samples": 1} if method == "a-buffer" else {}
        r = sl.render(sl.FrameBuffer(w, h), meshes, cam, method=method, shading="none",
                      **extra)
        bad[method] = int((r.faces[sure] != ref[sure]).sum())
    painter = bad.pop("painter")
    assert bad == {m: 0 for m in bad}, bad
    if scene == "full view":
        assert (ref >= 0).all()                               # every pixel center covered
    if scene in PAINTER_FAILS and camera == "perspective":
        assert painter > 0                                    # the counter-example


def test_the_a_buffer_faces_are_its_central_samples():
    # at 3 x 3 samples the central sample of each pixel is its center: the faces agree
    # with the reference as the other methods' do (the colors are antialiased)
    meshes = pierced(np.random.default_rng(5))
    cam = perspective()
    ref, unsure = reference(meshes, cam, 30, 24)
    r = sl.render(sl.FrameBuffer(30, 24), meshes, cam, method="a-buffer", samples=3)
    assert (r.faces[~unsure] != ref[~unsure]).sum() == 0
