"""Wireframes (scanline.draw3d): the pixels are sl.draw.lines of the projected,
clipped edges, computed here independently (clipping in viewing coordinates, an
OpenGL-convention matrix); line attributes and antialiasing pass through; depth
cueing; and Mesa's GL_LINES (moderngl, llvmpipe) draws the same wireframe."""

import math

import numpy as np
import pytest

import scanline as sl
from tests.reference import gl_context
from tests.three_d.test_clip3d import reference_segments, viewing_frustum_planes
from tests.three_d.test_projection import gl_perspective, glu_look_at

W, H = 161, 121   # odd: the image center falls on a pixel center, not on a rounding tie
FOV, NEAR, FAR = 1.0, 0.5, 30.0


def camera(eye=(2.5, 1.5, 3.0), target=(0, 0, 0)):
    return sl.Camera(eye=eye, target=target, keep_aspect=False,
                     projection=sl.projection.perspective(fov=FOV, aspect=(W - 1) / (H - 1),
                                                          near=NEAR, far=FAR))


def reference_device_segments(mesh, eye, target):
    """The mesh's edges clipped in viewing coordinates (exactly, against the frustum's
    planes) and projected with gluLookAt / gluPerspective, in device coordinates; and
    which edges are seen (a mask)."""
    view = glu_look_at(eye, target, (0, 1, 0))
    v = np.hstack([mesh.vertices, np.ones((len(mesh.vertices), 1))]) @ view.T
    e = mesh.edges
    segs = np.hstack([v[e[:, 0], :3], v[e[:, 1], :3]])
    clipped, ok = reference_segments(segs, viewing_frustum_planes(FOV, (W - 1) / (H - 1), NEAR, FAR), 3)
    proj = gl_perspective(FOV, (W - 1) / (H - 1), NEAR, FAR)

    def device(p):
        h = np.hstack([p, np.ones((len(p), 1))]) @ proj.T
        ndc = h[:, :2] / h[:, 3:]
        return (ndc + 1) / 2 * [W - 1, H - 1]
    return np.hstack([device(clipped[ok, :3]), device(clipped[ok, 3:])]), ok


def rows(a):
    """The rows sorted (by their values rounded, so round-off cannot reorder them)."""
    return a[np.lexsort(np.round(a, 6).T[::-1])]


@pytest.mark.parametrize("eye", [(2.5, 1.5, 3.0), (0.6, 0.3, 1.2), (0.2, 0.1, 0.4)])
def test_wireframe_is_draw_lines_of_the_clipped_projected_edges(eye):
    # the nearer eyes are inside the sphere's bounding region: edges cross the front
    # plane and pass behind the eye
    mesh = sl.mesh.sphere(1.0, resolution=(16, 8))
    fb = sl.FrameBuffer(W, H)
    segs = sl.draw3d.wireframe(fb, mesh, camera(eye), color="white")
    ref, _ = reference_device_segments(mesh, eye, (0, 0, 0))
    assert len(segs) == len(ref) > 0
    np.testing.assert_allclose(rows(segs), rows(ref), atol=1e-7)
    fb_ref = sl.FrameBuffer(W, H)
    sl.draw.lines(fb_ref, ref, color="white")
    assert (fb.to_array() == fb_ref.to_array()).all()


def test_edges_projected_on_threads_keep_the_order_of_the_edges(monkeypatch):
    # enough edges for the projection to be split between threads (three chunks here):
    # the rows come back in the order of the edges, ``which`` naming each row's edge
    # in the whole list, equal to the independent clipping and projection
    from scanline._kernels import _threads
    monkeypatch.setattr(_threads, "threads", lambda: 3)
    chunks = []
    real = _threads.call
    monkeypatch.setattr(_threads, "call", lambda kernel, work, *a: chunks.append(len(a[4]))
                        or real(kernel, work, *a))
    mesh = sl.mesh.sphere(1.0, resolution=(160, 80))
    eye = (0.6, 0.3, 1.2)
    e = mesh.edges
    assert 20 * len(e) > sl._kernels._jit.TWIN_WORK
    ref, ok = reference_device_segments(mesh, eye, (0, 0, 0))
    segs, depth, which = sl.draw3d.project_edges(mesh.vertices, e, camera(eye), W, H)
    assert len(chunks) == 3 and sum(chunks) == len(e)
    assert 0 < ok.sum() < len(e)
    assert np.array_equal(which, np.flatnonzero(ok))
    np.testing.assert_allclose(segs, ref, atol=1e-7)
    assert depth.shape == (len(segs), 2) and ((0 <= depth) & (depth <= 1)).all()


def test_attributes_and_antialiasing_pass_through():
    mesh = sl.mesh.torus(1.0, 0.3, resolution=(12, 6))
    cam = camera()
    for attrs in ({"width": 3, "cap": "round"}, {"antialias": True}, {"dash": (4, 2)},
                  {"antialias": True, "width": 2.5}):
        fb = sl.FrameBuffer(W, H, background="white")
        segs = sl.draw3d.wireframe(fb, mesh, cam, color="navy", **attrs)
        ref = sl.FrameBuffer(W, H, background="white")
        sl.draw.lines(ref, segs, color="navy", **attrs)
        assert (fb.to_array() == ref.to_array()).all(), attrs


def test_several_meshes_and_mesh_colors():
    cam = camera()
    a = sl.mesh.cube(0.8, center=(-0.6, 0, 0), colors=["red"] * 6)
    b = sl.mesh.cube(0.8, center=(0.6, 0, 0))
    fb = sl.FrameBuffer(W, H)
    sl.draw3d.wireframe(fb, [a, b], cam)                 # a's own red, b white
    ra, rb = sl.FrameBuffer(W, H), sl.FrameBuffer(W, H)
    sl.draw3d.wireframe(ra, a, cam, color="red")
    sl.draw3d.wireframe(rb, b, cam, color="white")
    img, ia, ib = fb.to_array(), ra.to_array(), rb.to_array()
    lit_b = (ib != 0).any(axis=2)
    assert (img[lit_b] == 255).all()                     # b drawn after a, on top
    assert ((img == ia) | lit_b[..., None]).all()
    fb2 = sl.FrameBuffer(W, H)
    sl.draw3d.wireframe(fb2, [a, b], cam, color=["green", "blue"])
    assert {tuple(c) for c in fb2.to_array().reshape(-1, 3)} == {(0, 0, 0), (0, 128, 0), (0, 0, 255)}
    with pytest.raises(sl.ScanlineError, match="one per mesh"):
        sl.draw3d.wireframe(fb2, [a, b], cam, color=["green"])


def test_depth_cueing_fades_with_distance():
    # a quadrilateral tilted away from the viewer, in parallel projection: its near
    # edge (z = 0) and far edge (z = -5) are horizontal lines on the device
    cam = sl.Camera(eye=(0, 0, 10), target=(0, 0, 0),
                    projection=sl.projection.orthographic(window=(-2, -2, 2, 2), front=0, back=-20))
    quad = sl.mesh.Mesh([(-1.5, -1, 0), (1.5, -1, 0), (1.5, 0, -5), (-1.5, 0, -5)], [[0, 1, 2, 3]])
    segs, depth, _ = sl.draw3d.project_edges(quad.vertices, [[0, 1], [3, 2]], cam, 81, 81)
    assert depth[0, 0] < depth[1, 0]                     # the near edge first
    near_row, far_row = 80 - int(round(segs[0, 1])), 80 - int(round(segs[1, 1]))
    fb = sl.FrameBuffer(81, 81, mode="L", background=0)
    sl.draw3d.wireframe(fb, quad, cam, color=200, depth_cue=(1.0, 0.25))
    img = fb.to_array()
    assert img[near_row, 40] == 200                      # the nearest edge at full intensity
    assert img[far_row, 40] == 50                        # the farthest at a quarter
    # each edge has one intensity, from its midpoint's depth: the side edges (x = 10
    # on the device) are halfway, 0.25 + 0.75 / 2 of 200
    side = img[far_row + 1:near_row, 10]
    assert len(side) > 10 and (side == 125).all()
    fb = sl.FrameBuffer(81, 81, background="white")
    sl.draw3d.wireframe(fb, quad, cam, color="black", depth_cue=True)   # fades to white
    assert tuple(fb.to_array()[far_row, 40]) == (191, 191, 191)         # 255 - 0.25 * 255
    with pytest.raises(sl.ScanlineError, match="mode"):
        sl.draw3d.wireframe(sl.FrameBuffer(8, 8, mode="1"), quad, cam, depth_cue=True)
    with pytest.raises(sl.ScanlineError, match="depth_cue"):
        sl.draw3d.wireframe(fb, quad, cam, depth_cue=(2, 0))


def test_polylines_keep_joins_across_vertices_and_are_clipped():
    cam = camera(eye=(0, 0, 3))
    square = [(-0.5, -0.5, 0), (0.5, -0.5, 0), (0.5, 0.5, 0), (-0.5, 0.5, 0)]
    fb = sl.FrameBuffer(W, H)
    pieces = sl.draw3d.polylines(fb, [square], cam, closed=True, width=3, join="miter")
    assert len(pieces) == 1 and len(pieces[0]) == 5
    ref = sl.FrameBuffer(W, H)
    sl.draw.polylines(ref, pieces, width=3, join="miter")
    assert (fb.to_array() == ref.to_array()).all()
    # a polyline passing behind the eye is cut into the visible pieces
    through = [(-0.2, 0, 0), (0.2, 0, 6), (0.4, 0.1, 0)]
    got = sl.draw3d.polyline_pieces(through, cam, W, H)
    assert len(got) == 2


def test_wireframe_bad_input():
    fb = sl.FrameBuffer(8, 8)
    with pytest.raises(sl.ScanlineError, match="camera"):
        sl.draw3d.wireframe(fb, sl.mesh.cube(), "camera")
    with pytest.raises(sl.ScanlineError, match="Mesh"):
        sl.draw3d.wireframe(fb, [], camera())
    with pytest.raises(sl.ScanlineError, match="out of range"):
        sl.draw3d.project_edges([(0, 0, 0)], [[0, 1]], camera(), 8, 8)
    with pytest.raises(sl.ScanlineError):
        sl.draw3d.wireframe("fb", sl.mesh.cube(), camera())


# -- Mesa's GL_LINES as a peer ------------------------------------------------------------------
GL_VERTEX = """
#version 330
uniform mat4 clip;      // our world -> clip matrix (NDC 0..1)
uniform vec2 size;
in vec3 position;
void main() {
    vec4 h = clip * vec4(position, 1.0);
    // our device x = ndc (size - 1), pixel centers at integers; GL's window x =
    // (ndc_gl + 1) / 2 * size with centers at +0.5: put our centers on GL's
    vec2 dev = h.xy * (size - 1.0) + 0.5 * h.w;
    gl_Position = vec4(2.0 * dev / size - h.w, 2.0 * h.z - h.w, h.w);
}
"""
GL_FRAGMENT = "#version 330\nout vec4 color;\nvoid main() { color = vec4(1.0); }\n"


def test_mesa_gl_lines_draw_the_same_wireframe():
    ctx = gl_context()
    mesh = sl.mesh.sphere(1.0, resolution=(24, 12))
    eye = (0.5, 0.4, 1.1)                 # close: many edges cross the front plane
    cam = camera(eye)
    prog = ctx.program(vertex_shader=GL_VERTEX, fragment_shader=GL_FRAGMENT)
    prog["clip"].write(cam.matrix(W, H).T.astype("f4").tobytes())
    prog["size"].value = (W, H)
    vbo = ctx.buffer(mesh.vertices.astype("f4").tobytes())
    ibo = ctx.buffer(mesh.edges.astype("i4").tobytes())
    vao = ctx.vertex_array(prog, [(vbo, "3f", "position")], index_buffer=ibo)
    fbo = ctx.simple_framebuffer((W, H), components=1)
    fbo.use()
    fbo.clear(0.0)
    import moderngl

    vao.render(moderngl.LINES)
    gl = np.frombuffer(fbo.read(components=1), np.uint8).reshape(H, W) > 0   # row 0 = y 0
    fb = sl.FrameBuffer(W, H, mode="L")
    sl.draw3d.wireframe(fb, mesh, cam, color=255)
    ours = fb.to_array()[::-1] > 0                                           # row 0 = y 0

    def near(a, b):
        """The fraction of a's pixels within one pixel of one of b's."""
        grown = b.copy()
        for dy in (-1, 0, 1):
            for dx in (-1, 0, 1):
                grown |= np.roll(np.roll(b, dy, axis=0), dx, axis=1)
        return (a & grown).sum() / a.sum()
    assert gl.sum() > 500 and ours.sum() > 500
    assert near(ours, gl) > 0.99 and near(gl, ours) > 0.99
    assert 0.8 < ours.sum() / gl.sum() < 1.25
