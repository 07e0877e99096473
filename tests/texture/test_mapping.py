"""Texture, bump and environment maps in sl.render: the texture coordinates at each
pixel against the pixel's view ray intersected with the surface's plane (the
perspective-correct answer, computed here without the renderer's interpolation),
the texture as the diffuse color in every shading model and visible-surface method,
Blinn's bump mapping against the normal of the displaced surface in closed form, and
the environment map against the reflected view direction worked out by hand."""

import numpy as np
import pytest

import scanline as sl
from scanline.errors import ArgumentValueError
from scanline.screen import prepare

W = 64


def ramp_texture(**kw):
    """R = a ramp along u, G along v (stored values of texels at centers)."""
    i = np.arange(W) / (W - 1)
    img = np.zeros((W, W, 3))
    img[..., 0] = i[None, :]
    img[..., 1] = i[::-1, None]               # image rows top first: v up
    return sl.Texture(img, **{"filter": "bilinear", "wrap": "clamp", **kw})


def ramp_value(t):
    """The bilinear ramp's value at coordinate t (texel centers (i + 1/2) / W)."""
    return np.clip((t * W - 0.5) / (W - 1), 0, 1)


FLOOR = sl.mesh.Mesh([(-1, 0, 0), (1, 0, 0), (1, 0, -8), (-1, 0, -8)], [[0, 1, 2, 3]],
                     uv=[(0, 0), (1, 0), (1, 1), (0, 1)])
CAMERA = sl.Camera(eye=(0, 0.7, 1.2), target=(0, 0, -2), up=(0, 1, 0))


def pixel_rays(camera, width, height):
    """Each pixel center's view ray in world coordinates: (origin, direction), (H, W, 3)
    each, rows bottom up, from the inverse of the camera's clip matrix."""
    clip, scale, offset = prepare([FLOOR], camera, width, height).mapping
    inv = np.linalg.inv(clip)
    ys, xs = np.mgrid[0:height, 0:width]
    ends = []
    for depth in (0.0, 0.5):
        dev = np.stack([xs, ys, np.full(xs.shape, depth * scale[2] + offset[2])], -1)
        ndc = (dev - offset) / scale
        h = np.concatenate([ndc, np.ones(xs.shape + (1,))], -1) @ inv.T
        ends.append(h[..., :3] / h[..., 3:])
    return ends[0], ends[1] - ends[0]


def floor_uv(width, height):
    """(u, v) where each pixel's ray meets the floor's plane y = 0, by the floor's
    corners' barycentric coordinates; NaN off the floor."""
    o, d = pixel_rays(CAMERA, width, height)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = -o[..., 1] / d[..., 1]
    p = o + t[..., None] * d
    u, v = (p[..., 0] + 1) / 2, -p[..., 2] / 8
    off = (t <= 0) | (u < 0) | (u > 1) | (v < 0) | (v > 1)
    return np.where(off, np.nan, u), np.where(off, np.nan, v)


def render(material, shading="none", method="z-buffer", size=(80, 60), **kw):
    fb = sl.FrameBuffer(*size, mode="RGB", background="black")
    lights = kw.pop("lights", [sl.lighting.AmbientLight(1.0)])
    sl.render(fb, [kw.pop("mesh", FLOOR)], kw.pop("camera", CAMERA), materials=material,
              shading=shading, method=method, gamma=1, lights=lights, **kw)
    return fb.to_array()[::-1].astype(np.float64) / 255      # rows bottom up


def inner(u, v, margin=0.03):
    return (u > margin) & (u < 1 - margin) & (v > margin) & (v < 1 - margin)


def test_texture_coordinates_are_perspective_correct():
    img = render(sl.lighting.Material(texture=ramp_texture()))
    u, v = floor_uv(80, 60)
    ok = inner(u, v)
    assert ok.sum() > 800
    np.testing.assert_allclose(img[..., 0][ok], ramp_value(u[ok]), atol=1.01 / 255)
    np.testing.assert_allclose(img[..., 1][ok], ramp_value(v[ok]), atol=1.01 / 255)


def test_affine_mapping_is_not():
    img = render(sl.lighting.Material(texture=ramp_texture()), texture_mapping="affine")
    u, v = floor_uv(80, 60)
    ok = inner(u, v)
    assert np.abs(img[..., 1][ok] - ramp_value(v[ok])).max() > 0.15


METHODS = ["z-buffer", "scan-line", "ray-casting", "depth-sort", "bsp", "area-subdivision",
           "a-buffer", "painter"]


@pytest.mark.parametrize("method", METHODS)
def test_every_method_maps_the_texture(method):
    img = render(sl.lighting.Material(texture=ramp_texture()), method=method, size=(40, 30))
    u, v = floor_uv(40, 30)
    ok = inner(u, v, 0.08)
    np.testing.assert_allclose(img[..., 0][ok], ramp_value(u[ok]), atol=2.01 / 255)
    np.testing.assert_allclose(img[..., 1][ok], ramp_value(v[ok]), atol=2.01 / 255)


@pytest.mark.parametrize("shading", ["flat", "gouraud", "phong", "fast-phong"])
def test_the_texel_scales_the_ambient_and_diffuse_terms_not_the_highlight(shading):
    # a directional light straight down on the floor: N . L = 1 everywhere; the
    # viewer's highlight varies; ka Ia + kd Il N.L = 0.2 + 0.5 scaled by the texel
    mat = sl.lighting.Material(ka=0.4, kd=0.5, ks=0.0, texture=ramp_texture())
    lights = [sl.lighting.AmbientLight(0.5), sl.lighting.DirectionalLight((0, -1, 0))]
    img = render(mat, shading, lights=lights)
    u, v = floor_uv(80, 60)
    ok = inner(u, v)
    np.testing.assert_allclose(img[..., 0][ok], 0.7 * ramp_value(u[ok]), atol=1.51 / 255)
    np.testing.assert_allclose(img[..., 2][ok], 0, atol=0.6 / 255)
    # with a highlight: I = T (ka Ia + kd N.L) + ks (V.R)^n, the specular part unscaled
    shiny = sl.lighting.Material(ka=0.4, kd=0.5, ks=0.3, shininess=1, texture=ramp_texture())
    plain = sl.lighting.Material(ka=0.4, kd=0.5, ks=0.3, shininess=1, color="black")
    spec = render(plain, shading, lights=lights)[..., 2]
    np.testing.assert_allclose(render(shiny, shading, lights=lights)[..., 0][ok],
                               0.7 * ramp_value(u[ok]) + spec[ok], atol=2.01 / 255)


def test_a_textured_mesh_needs_texture_coordinates():
    bare = sl.mesh.Mesh(FLOOR.vertices, [[0, 1, 2, 3]])
    with pytest.raises(ArgumentValueError, match="uv"):
        render(sl.lighting.Material(texture=ramp_texture()), mesh=bare)


def test_bump_and_environment_maps_need_phong_shading():
    with pytest.raises(ArgumentValueError, match="phong"):
        render(sl.lighting.Material(bump=ramp_texture()), "gouraud")


def test_bump_mapping_tilts_the_normal_by_the_ramps_slope():
    # the plane z = 0, u = (x + 1) / 2, v = (y + 1) / 2, seen from +z: P_u = (2, 0, 0);
    # height B(u) = k h(u) with h the bilinear ramp, dh/du = W / (W - 1); the displaced
    # surface z = B((x + 1) / 2) has the normal (-dz/dx, 0, 1) = (-k dh/du / 2, 0, 1)
    k = 0.8
    plane = sl.mesh.Mesh([(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0)], [[0, 1, 2, 3]],
                         uv=[(0, 0), (1, 0), (1, 1), (0, 1)])
    cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0), up=(0, 1, 0),
                    projection=sl.projection.orthographic(window=(-1.2, -1.2, 1.2, 1.2)))
    slope = k * W / (W - 1) / 2
    normal = np.array([-slope, 0, 1]) / np.hypot(slope, 1)
    to_light = np.array([-0.6, 0.3, 1.0]) / np.linalg.norm([-0.6, 0.3, 1.0])
    mat = sl.lighting.Material(ka=0, kd=1, ks=0, bump=ramp_texture(), bump_scale=k)
    img = render(mat, "phong", mesh=plane, camera=cam, size=(48, 48),
                 lights=[sl.lighting.DirectionalLight(-to_light)])
    flat = render(sl.lighting.Material(ka=0, kd=1, ks=0), "phong", mesh=plane, camera=cam,
                  size=(48, 48), lights=[sl.lighting.DirectionalLight(-to_light)])
    centre = img[12:36, 12:36, 0]
    np.testing.assert_allclose(centre, normal @ to_light, atol=1.01 / 255)
    np.testing.assert_allclose(flat[12:36, 12:36, 0], to_light[2], atol=1.01 / 255)
    assert abs(normal @ to_light - to_light[2]) > 0.1


def mirror_reflections(material, size=50):
    """A mirror on the plane z = 0 facing -z, seen from (0, 0, -1.5) with Phong
    shading: the image, the pixels well inside the mirror and each pixel's reflected
    view direction, at the point p, V = unit(eye - p), R = 2 (N . V) N - V."""
    mirror = sl.mesh.Mesh([(-1, -1, 0), (-1, 1, 0), (1, 1, 0), (1, -1, 0)], [[0, 1, 2, 3]])
    eye = np.array([0.0, 0.0, -1.5])
    cam = sl.Camera(eye=tuple(eye), target=(0, 0, 0), up=(0, 1, 0))
    img = render(material, "phong", mesh=mirror, camera=cam, size=(size, size))
    o, d = pixel_rays(cam, size, size)
    p = o + (-o[..., 2] / d[..., 2])[..., None] * d
    hit = (np.abs(p[..., 0]) < 0.97) & (np.abs(p[..., 1]) < 0.97)
    view = eye - p
    view /= np.linalg.norm(view, axis=-1, keepdims=True)
    n = np.array([0.0, 0.0, -1.0])
    return img, hit, 2 * (view @ n)[..., None] * n - view


def test_environment_map_is_looked_up_in_the_reflected_view_direction():
    # u = 1/2 + atan2(R_x, -R_z) / 2 pi, v = 1/2 + asin(R_y) / pi
    mat = sl.lighting.Material(ka=0, kd=0, ks=0, environment=ramp_texture(), reflectivity=0.9)
    img, hit, r = mirror_reflections(mat)
    u = 0.5 + np.arctan2(r[..., 0], -r[..., 2]) / (2 * np.pi)
    v = 0.5 + np.arcsin(r[..., 1]) / np.pi
    assert hit.sum() > 400 and np.ptp(u[hit]) > 0.1
    np.testing.assert_allclose(img[..., 0][hit], 0.9 * ramp_value(u[hit]), atol=1.01 / 255)
    np.testing.assert_allclose(img[..., 1][hit], 0.9 * ramp_value(v[hit]), atol=1.01 / 255)
