"""sl.render: every image-space method against a plain-Python per-pixel ray-casting
reference, Gouraud and Phong against their formulas on one triangle, back faces,
the eye plane, ordered pieces, bad input."""

import math
import warnings

import numpy as np
import pytest

import scanline as sl
from scanline.screen import prepare

W, H = 48, 36


def camera(eye=(0.5, 1.0, 6.0)):
    return sl.Camera(eye=eye, target=(0, 0, 0),
                     projection=sl.projection.perspective(fov=math.radians(50), near=0.5, far=20))


def random_scene(rng, n=14):
    verts = rng.uniform(-2, 2, size=(3 * n, 3))
    return sl.mesh.Mesh(verts, np.arange(3 * n).reshape(n, 3))


def reference_faces(scene):
    """Per pixel center, the mesh face of the nearest device triangle whose crossings
    (edges active for ylo < Y <= yhi) enclose it; depth from its plane; -1 none."""
    out = np.full((scene.height, scene.width), -1)
    best = np.full((scene.height, scene.width), np.inf)
    second = np.full((scene.height, scene.width), np.inf)
    for tri, face in zip(scene.triangles, scene.facet_face[scene.facet]):
        (x0, y0, z0), (x1, y1, z1), (x2, y2, z2) = tri
        area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
        if area == 0:
            continue
        for y in range(scene.height):
            xs = []
            for a, b in ((0, 1), (1, 2), (2, 0)):
                lo, hi = (a, b) if tri[a][1] < tri[b][1] else (b, a)
                if tri[lo][1] < y <= tri[hi][1]:
                    xl, yl = tri[lo][0], tri[lo][1]
                    xs.append(xl + ((y - yl) * (tri[hi][0] - xl)) / (tri[hi][1] - yl))
            if len(xs) != 2:
                continue
            for x in range(max(math.ceil(min(xs)), 0), min(math.ceil(max(xs)), scene.width)):
                l1 = ((x - x0) * (y2 - y0) - (x2 - x0) * (y - y0)) / area
                l2 = ((x1 - x0) * (y - y0) - (x - x0) * (y1 - y0)) / area
                z = (1 - l1 - l2) * z0 + l1 * z1 + l2 * z2
                if z < best[y, x]:
                    second[y, x] = best[y, x]
                    best[y, x], out[y, x] = z, face
                elif z < second[y, x]:
                    second[y, x] = z
    with np.errstate(invalid="ignore"):
        return out, second - best


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_image_space_methods_agree_with_the_reference(seed):
    rng = np.random.default_rng(seed)
    mesh = random_scene(rng)                      # random triangles: they intersect
    cam = camera()
    scene = prepare(mesh, cam, W, H)
    ref, gap = reference_faces(scene)
    clear = gap > 1e-9                            # ties (shared points) excluded
    for method in ("z-buffer", "ray-casting", "a-buffer"):
        fb = sl.FrameBuffer(W, H)
        r = sl.render(fb, mesh, cam, method=method, samples=1) if method == "a-buffer" \
            else sl.render(fb, mesh, cam, method=method)
        assert np.array_equal(r.faces[clear], ref[clear]), method
    assert (ref >= 0).sum() > 200


def test_gouraud_and_phong_follow_their_formulas_on_one_triangle():
    # one triangle in the plane z = 0 with tilted vertex normals, orthographic view
    verts = np.array([(-1.0, -1.0, 0.0), (1.2, -0.8, 0.0), (-0.6, 1.1, 0.0)])
    normals = np.array([(0.5, 0.0, 1.0), (0.0, 0.6, 1.0), (-0.4, -0.4, 1.0)])
    mesh = sl.mesh.Mesh(verts, [[0, 1, 2]], normals=normals)
    cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0),
                    projection=sl.projection.orthographic(window=(-1.5, -1.5, 1.5, 1.5)))
    light = sl.lighting.PointLight((1.0, 2.0, 3.0))
    m = sl.lighting.Material(ka=0.1, kd=0.6, ks=0.3, shininess=5)
    lights = [sl.lighting.AmbientLight(0.3), light]

    def model(p, n):                      # Hearn & Baker 14-2 written out, eye at infinity +z
        n = n / np.linalg.norm(n)
        big_l = (light.position - p) / np.linalg.norm(light.position - p)
        nl = n @ big_l
        r = 2 * nl * n - big_l
        vr = max(r[2], 0.0)
        return 0.1 * 0.3 + (0.6 * nl + 0.3 * vr ** 5 if nl > 0 else 0.0)

    scale, offset = cam.device(W, H)
    dev = verts[:, :2] * 1.0                                 # device of world x, y
    clip, sc, of = cam.mapping((0, 0, W - 1, H - 1))
    h = verts @ clip[:3, :3].T + clip[:3, 3]
    dev = h[:, :2] / (verts @ clip[3, :3] + clip[3, 3])[:, None] * sc[:2] + of[:2]
    for shading in ("gouraud", "phong"):
        fb = sl.FrameBuffer(W, H, mode="L")
        r = sl.render(fb, mesh, cam, shading=shading, lights=lights, materials=m, gamma=1)
        ys, xs = np.nonzero(r.faces >= 0)
        assert len(xs) > 300
        buf = fb._raster()[0][..., 0]
        def cross(a, b):
            return a[0] * b[1] - a[1] * b[0]
        area = cross(dev[1] - dev[0], dev[2] - dev[0])
        for x, y in zip(xs, ys):
            l1 = cross(np.array([x, y]) - dev[0], dev[2] - dev[0]) / area
            l2 = cross(dev[1] - dev[0], np.array([x, y]) - dev[0]) / area
            lam = np.array([1 - l1 - l2, l1, l2])
            if shading == "gouraud":
                i = sum(lam[k] * model(verts[k], normals[k]) for k in range(3))
            else:
                i = model(lam @ verts, lam @ (normals / np.linalg.norm(normals, axis=1)[:, None]))
            # luminance of a gray: the same value
            assert abs(int(buf[y, x]) - round(255 * min(i, 1.0))) <= 1, (shading, x, y)


def test_back_face_test_and_culling():
    cube = sl.mesh.cube(2)
    cam = camera((3, 2, 4))
    scene = prepare(cube, cam, W, H)
    # a convex solid seen from outside: half of its faces are back faces, and the
    # front faces alone cover what the whole cube covers
    assert scene.front.sum() == 6                # 3 faces x 2 triangles
    fb1, fb2 = sl.FrameBuffer(W, H), sl.FrameBuffer(W, H)
    r1 = sl.render(fb1, cube, cam)
    r2 = sl.render(fb2, cube, cam, cull_back_faces=True)
    assert r2.scene.culled.sum() == 6
    assert np.array_equal(fb1.to_array(), fb2.to_array())
    assert np.array_equal(r1.faces, r2.faces)


def test_shared_vertices_projected_once_give_every_face_its_corners():
    # two meshes (their vertex numbers offset in the joined points), shared vertices:
    # each facet's device corners and 1/w as the camera's matrices give them per facet
    meshes = [sl.mesh.cube(2), sl.mesh.cube(1).transformed(sl.transform3d.translation(0, 1.5, 0))]
    cam = camera((3, 2, 4))
    scene = prepare(meshes, cam, W, H)
    clip, scale, offset = scene.mapping
    world = np.concatenate([m.vertices[m.triangulated().face_indices.reshape(-1, 3)]
                            for m in meshes])
    hom = np.concatenate([world, np.ones(world.shape[:2] + (1,))], axis=2) @ clip.T
    assert scene.whole.all() and np.array_equal(scene.facet, np.arange(len(world)))
    assert np.allclose(scene.triangles, hom[..., :3] / hom[..., 3:] * scale + offset,
                       rtol=1e-12, atol=1e-9)
    assert np.allclose(scene.inv_w, 1 / hom[..., 3], rtol=1e-12)


def test_a_face_whose_corner_is_not_a_vertex_is_not_drawn_nor_read_outside():
    from scanline._kernels.screen import project_faces

    points = 4
    corners = np.array([[0, 1, 2], [1, 2, points], [-1, 0, 1]], np.int64)
    eye = np.zeros((points, 3))
    dev = np.ones((points, 3))
    flags = np.ones(points, bool)
    out = (np.empty(3, bool), np.empty(3, bool), np.empty(3, bool), np.empty((3, 3, 3)),
           np.empty((3, 3)), np.empty((3, 4)))
    project_faces(0, 1, corners, eye, dev, np.ones(points), flags, flags,
                  np.array([0, 0, 1.0, 1.0]), *out)
    back, inside, good, tri, inv_w, plane = out
    assert good.tolist() == [True, False, False] and inside.tolist() == [True, False, False]
    assert np.isnan(tri[1:]).all() and np.isnan(inv_w[1:]).all() and np.isnan(plane[1:]).all()
    assert (tri[0] == 1).all()


def test_a_vertex_far_out_renders_without_numpy_warnings():
    # finite but past what a product of two coordinates holds: the facets through it
    # are clipped, their normals are not finite, and no RuntimeWarning reaches the user
    cube = sl.mesh.cube(2)
    vertices = cube.vertices.copy()
    vertices[0] = (1e300, -1e300, 1e300)
    far = sl.mesh.Mesh(vertices, cube.face_indices.reshape(-1, 4))
    fb = sl.FrameBuffer(W, H)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        r = sl.render(fb, far, camera((3, 2, 4)))
    assert (r.faces >= 0).any() and np.isfinite(r.scene.triangles).all()


def test_triangles_crossing_the_eye_plane_are_clipped_before_the_divide():
    # a floor passing under and behind the eye: nothing mirrored, no giant triangle
    floor = sl.mesh.Mesh([(-50, -1, -50), (50, -1, -50), (50, -1, 50), (-50, -1, 50)],
                         [[0, 3, 2, 1]])
    cam = sl.Camera(eye=(0, 0, 0), target=(0, 0, -1),
                    projection=sl.projection.perspective(fov=math.radians(60), near=0.1, far=100))
    fb = sl.FrameBuffer(W, H)
    r = sl.render(fb, floor, cam)
    seen = r.faces >= 0
    assert seen[: H // 2 - 1].all() and not seen[H // 2:].any()     # floor below the horizon
    assert np.isfinite(r.scene.triangles).all()
    assert (np.abs(r.scene.triangles[..., :2]) < 1e5).all()
    d = r.depth.array[seen]
    assert (d >= 0).all() and (d <= 1).all()


def test_ordered_pieces_draw_in_order_with_the_faces_shading():
    from scanline.rendering import default_lights
    from scanline.shading import ShadingOptions, shade
    from scanline.visible.visibility import painted

    rng = np.random.default_rng(4)
    mesh = random_scene(rng, 8)
    cam = camera()
    fb = sl.FrameBuffer(W, H)
    r = sl.render(fb, mesh, cam, shading="phong")
    scene = r.scene
    # painter's order by the nearest-first z-buffer answer: paint every facet's polygon
    # farthest first; where the z-buffer saw facet f the last-painted covering piece is f
    sp = scene.screen_polygons
    far = np.maximum.reduceat(sp.vertices[:, 2], sp.offsets[:-1])
    layer = painted(scene, sp.subset(np.argsort(-far, kind="stable")))
    fb2 = sl.FrameBuffer(W, H)
    facets = shade(fb2, scene, layer, ShadingOptions(model="phong", lights=default_lights(cam)))
    same = facets == r.facets
    assert same.mean() > 0.6                      # the painter's order is often right ...
    # ... and wherever it picked the same face, the pixel is the same
    a, b = fb.to_array()[::-1], fb2.to_array()[::-1]
    assert (np.abs(a[same].astype(int) - b[same].astype(int)) <= 1).all()


def test_shading_models_differ_as_expected():
    sphere = sl.mesh.sphere(1.0, resolution=(10, 6))
    cam = camera((0, 0, 4))
    images = {}
    for s in ("flat", "gouraud", "phong", "fast-phong"):
        fb = sl.FrameBuffer(W, H, mode="L")
        sl.render(fb, sphere, cam, shading=s)
        images[s] = fb.to_array().astype(int)
    # flat: few distinct levels (one per face); the others smooth
    assert len(np.unique(images["flat"])) < len(np.unique(images["gouraud"]))
    # fast Phong approximates Phong more closely than Gouraud does
    assert (np.abs(images["fast-phong"] - images["phong"]).mean()
            < np.abs(images["gouraud"] - images["phong"]).mean())


def test_transparency_and_depth_cue():
    near = sl.mesh.cube(1, center=(0, 0, 1))
    far = sl.mesh.cube(3, center=(0, 0, -2))
    cam = camera((0, 0, 6))
    glass = sl.lighting.Material(color="white", transparency=0.5)
    solid = sl.lighting.Material(color="red")
    for method in ("z-buffer", "a-buffer"):
        fb = sl.FrameBuffer(W, H, background="black")
        sl.render(fb, [near, far], cam, method=method, materials=[glass, solid])
        r, g, b = fb.get_pixel(W // 2, H // 2)[:3]
        assert r > g > 0                           # red seen through the white glass
    fb1, fb2 = sl.FrameBuffer(W, H), sl.FrameBuffer(W, H)
    cam = camera((4, 3, 6))
    sl.render(fb1, far, cam, depth_cue=(1.0, 0.2))
    sl.render(fb2, far, cam)
    assert fb1.to_array().sum() < fb2.to_array().sum()


def test_shadow_map_darkens_the_floor_under_a_cube():
    floor = sl.mesh.Mesh([(-3, 0, -3), (3, 0, -3), (3, 0, 3), (-3, 0, 3)], [[0, 3, 2, 1]])
    cube = sl.mesh.cube(1, center=(0, 1, 0))
    sun = sl.lighting.DirectionalLight((0, -1, 0), shadows=True)
    cam = sl.Camera(eye=(0, 6, 6), target=(0, 0, 0))
    out = []
    for shadows in (False, True):
        fb = sl.FrameBuffer(64, 64)
        r = sl.render(fb, [floor, cube], cam, lights=[sun], shadows=shadows, shading="phong")
        out.append((fb.to_array()[::-1].astype(int).sum(axis=2), r.faces))
    on_floor = out[1][1] == 0                                # the floor is face 0
    dark = (out[1][0] < out[0][0]) & on_floor
    assert dark.sum() > 20                                   # the cube's shadow
    assert (out[1][0] <= out[0][0]).all()                    # shadows only darken
    assert not ((out[1][0] < out[0][0]) & ~on_floor).any()   # the sunlit cube top stays


@pytest.mark.parametrize("kw, match", [
    (dict(method="painters"), "method"),
    (dict(shading="smooth"), "shading"),
    (dict(cull_back_faces=1), "cull_back_faces"),
    (dict(depth_cue=(2, 0)), "depth_cue"),
    (dict(gamma=0), "gamma"),
    (dict(lights=["sun"]), "lights"),
    (dict(materials=[1, 2]), "materials"),
    (dict(method="a-buffer", samples=0), "samples"),
])
def test_bad_render_arguments(kw, match):
    with pytest.raises(sl.ScanlineError, match=match):
        sl.render(sl.FrameBuffer(8, 8), sl.mesh.cube(), camera(), **kw)


def test_bad_targets():
    with pytest.raises(sl.ScanlineError, match="mode"):
        sl.render(sl.FrameBuffer(8, 8, mode="1"), sl.mesh.cube(), camera())
    with pytest.raises(sl.ScanlineError, match="Camera"):
        sl.render(sl.FrameBuffer(8, 8), sl.mesh.cube(), "camera")
    with pytest.raises(sl.ScanlineError, match="Mesh"):
        sl.render(sl.FrameBuffer(8, 8), ["cube"], camera())


def test_z_buffer_trace_agrees_with_the_drawing():
    from scanline.trace import z_buffer
    from scanline.trace.zbuffer import HEIGHT, SCENE, WIDTH

    for row in range(HEIGHT):
        table = z_buffer(row)
        fb = sl.FrameBuffer(WIDTH, HEIGHT, mode="L")
        depth = sl.DepthBuffer.like(fb)
        sl.draw.triangles(fb, SCENE, colors=[50, 100, 150], depth=depth)
        written = {}
        for r in table.rows:
            if r["result"] == "write":
                written[r["x"]] = r["z"]
                assert r["depth"] == "inf" or r["z"] < r["depth"]
            else:
                assert r["depth"] != "inf" and r["z"] >= r["depth"]
        expect = {x: round(float(z), 6) for x, z in enumerate(depth.array[row]) if np.isfinite(z)}
        assert written == expect


def test_flat_shading_gives_a_polygon_one_intensity():
    # one planar quadrilateral under a point light: one level (its two fan triangles
    # used to be lit apart, at their own centroids: 74 and 151)
    quad = sl.mesh.Mesh([(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0)], [[0, 1, 2, 3]])
    cam = sl.Camera(eye=(0, 0, 4), target=(0, 0, 0),
                    projection=sl.projection.orthographic(window=(-1.5, -1.5, 1.5, 1.5)))
    light = sl.lighting.PointLight((1.2, -0.9, 0.6))
    for method in sorted(sl.visible.METHODS):
        fb = sl.FrameBuffer(40, 30, mode="L")
        r = sl.render(fb, quad, cam, method=method, shading="flat", lights=[light], gamma=1,
                      materials=sl.lighting.Material(ka=0, kd=1, ks=0))
        seen = r.faces >= 0
        if method == "a-buffer":            # its edges are blended: the inner pixels
            seen[[0, -1]] = seen[:, [0, -1]] = False
            seen = seen & np.roll(seen, 1, 0) & np.roll(seen, -1, 0) & np.roll(seen, 1, 1) \
                & np.roll(seen, -1, 1)
        assert seen.sum() > 300
        levels = np.unique(fb._raster()[0][..., 0][seen])
        # the model at the centroid (0, 0, 0) with the plane normal (0, 0, 1)
        to = np.array(light.position) / np.linalg.norm(light.position)
        assert levels.tolist() == [round(255 * to[2])], (method, levels)


def test_faces_are_mesh_faces_and_meshes_are_told_apart():
    # two quads of two meshes: faces 0 and 1 (not the fan triangles 0..3), meshes 0, 1
    a = sl.mesh.Mesh([(-1, -1, 0), (0, -1, 0), (0, 1, 0), (-1, 1, 0)], [[0, 1, 2, 3]])
    b = sl.mesh.Mesh([(0, -1, 0), (1, -1, 0), (1, 1, 0), (0, 1, 0)], [[0, 1, 2, 3]])
    cam = sl.Camera(eye=(0, 0, 4), target=(0, 0, 0),
                    projection=sl.projection.orthographic(window=(-1.5, -1.5, 1.5, 1.5)))
    for method in sorted(sl.visible.METHODS):
        r = sl.render(sl.FrameBuffer(30, 30), [a, b], cam, method=method)
        assert set(np.unique(r.faces).tolist()) == {-1, 0, 1}, method
        assert np.array_equal(r.meshes, r.faces), method       # one face per mesh
        assert set(np.unique(r.facets).tolist()) == {-1, 0, 1, 2, 3}, method
        assert (r.faces[15, 6:14] == 0).all() and (r.faces[15, 16:24] == 1).all(), method


def test_unknown_and_misplaced_keywords_are_clear_errors():
    fb, cube, cam = sl.FrameBuffer(8, 8), sl.mesh.cube(), camera()
    with pytest.raises(TypeError, match=r"material= is not an option of render; did you "
                                        r"mean materials=\?"):
        sl.render(fb, cube, cam, material=sl.lighting.Material())
    with pytest.raises(TypeError, match=r"colour=.*did you mean colors="):
        sl.render(fb, cube, cam, colour="red")
    with pytest.raises(sl.ScanlineError, match=r"samples= is an option of method='a-buffer', "
                                               r"not of method='z-buffer'"):
        sl.render(fb, cube, cam, samples=2)
    with pytest.raises(TypeError):
        sl.render(fb, cube, cam, "z-buffer")                 # options are keywords
    assert not fb.to_array().any()


def test_a_rendering_prints_in_one_line_and_shows_as_a_picture():
    from PIL import Image
    import io

    fb = sl.FrameBuffer(40, 30)
    r = sl.render(fb, sl.mesh.cube(), camera((3, 2, 4)))
    text = repr(r)
    assert "\n" not in text and len(text) < 160
    assert text.startswith("<Rendering method='z-buffer' 40x30: 1 mesh(es), 6 faces, ")
    image = Image.open(io.BytesIO(r._repr_png_()))
    assert image.size[0] >= 40 and image.format == "PNG"
    assert r.image is fb


def test_colors_per_mesh_and_per_face_and_any_mode():
    cam = sl.Camera(eye=(3, 2, 4), target=(0, 0, 0))
    for mode in ("1", "P", "L", "RGB", "RGBA"):
        fb = sl.FrameBuffer(40, 30, mode=mode)
        r = sl.render(fb, sl.mesh.cube(), cam, shading="none", colors="white")
        lit = sl.text_image(fb)
        assert lit.count("#") == int((r.faces >= 0).sum()) > 100, mode
    fb = sl.FrameBuffer(40, 30)
    colors = ["red", "lime", "blue", "yellow", "cyan", "magenta"]
    r = sl.render(fb, sl.mesh.cube(), cam, shading="none", colors=colors)
    a = fb._raster()[0]
    for f in np.unique(r.faces[r.faces >= 0]):
        assert (a[r.faces == f] == fb.pixel(colors[f])).all()
    with pytest.raises(sl.ScanlineError, match="colors holds 4 colors"):
        sl.render(fb, sl.mesh.cube(), cam, colors=colors[:4])
    with pytest.raises(sl.ScanlineError, match="mode"):
        sl.render(sl.FrameBuffer(8, 8, mode="1"), sl.mesh.cube(), cam, shading="phong")
