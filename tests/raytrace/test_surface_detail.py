"""The ray tracer's reflections tinted by the specular color (Whitted's k_s I_reflected,
here k_r S_s), and texture, bump and environment maps honored after the first bounce:
values worked out here from the geometry (mirrors at 45 degrees, gamma 1)."""

import math

import numpy as np
import pytest

import scanline as sl

L = sl.lighting


def quad(corners, uv=None):
    return sl.mesh.Mesh(corners, [(0, 1, 2, 3)], uv=uv)


def ortho(size=2.0):
    return sl.Camera(eye=(0, 0, 5), target=(0, 0, 0),
                     projection=sl.projection.orthographic(window=(-size, -size, size, size)))


#: A mirror tilted 45 degrees about y: the view rays (-z) leave it along +x.
MIRROR = [(-1, -1, 1), (1, -1, -1), (1, 1, -1), (-1, 1, 1)]
#: A wall at x = 3 facing the mirror (-x), u = (y + 5) / 10 and v = (z + 5) / 10.
WALL = [(3, -5, -5), (3, -5, 5), (3, 5, 5), (3, 5, -5)]
WALL_UV = [(0, 0), (0, 1), (1, 1), (1, 0)]


def traced(meshes, mats, lights, **options):
    fb = sl.FrameBuffer(21, 21, background="black")
    sl.render(fb, meshes, ortho(), method="ray-tracing", materials=mats, lights=lights,
              shading="phong", gamma=1, **options)
    return fb.to_array()


# pixel rows (image order) whose world y is +0.57 and -0.57 (21 rows over y -2..2)
UP, DOWN = 7, 13


def test_reflection_is_tinted_by_the_specular_color():
    """I = k_r S_s I_wall: the wall's (200, 40, 40) times S_s = (1, 0.5, 0), times
    k_r = 1 and then 0.5."""
    wall = L.Material(ka=1.0, kd=0, ks=0, color=(200, 40, 40))
    for kr, expected in ((1.0, [200, 20, 0]), (0.5, [100, 10, 0])):
        mirror = L.Material(ka=0, kd=0, ks=0, reflectivity=kr,
                            specular_color=np.array([1.0, 0.5, 0.0]))
        a = traced([quad(MIRROR), quad(WALL)], [mirror, wall], [L.AmbientLight(1.0)])
        assert a[10, 10].tolist() == expected


def test_a_reflected_texture():
    """The wall's texture is red for u < 1/2 and blue beyond; the 45-degree mirror
    keeps y, so it shows blue above the middle (u = (y + 5) / 10 > 1/2) and red below,
    ambient light 1 on ka = 1: the texels themselves; a yellow specular color leaves
    the red and takes the blue away."""
    image = np.array([[[255, 0, 0], [0, 0, 255]]], np.uint8)
    wall = L.Material(ka=1.0, kd=0, ks=0, texture=sl.Texture(image, filter="nearest"))
    mirror = L.Material(ka=0, kd=0, ks=0, reflectivity=1.0)
    meshes = [quad(MIRROR), quad(WALL, WALL_UV)]
    a = traced(meshes, [mirror, wall], [L.AmbientLight(1.0)])
    assert a[UP, 10].tolist() == [0, 0, 255]
    assert a[DOWN, 10].tolist() == [255, 0, 0]
    yellow = L.Material(ka=0, kd=0, ks=0, reflectivity=1.0,
                        specular_color=np.array([1.0, 1.0, 0.0]))
    a = traced(meshes, [yellow, wall], [L.AmbientLight(1.0)])
    assert a[UP, 10].tolist() == [0, 0, 0]
    assert a[DOWN, 10].tolist() == [255, 0, 0]


def test_a_reflected_bump_map_tilts_the_walls_normal():
    """A height ramp B = s u (a clamped 64-texel ramp whose texel centers hold u) on the
    wall: the displaced surface P + B n has the tangents P_u + s n = (-s, 10, 0) and
    P_v = (0, 0, 10), so the normal (-100, -10 s, 0) / |.| (toward the mirror), lit by
    a directional light from L = (-1, -1, 0) / sqrt 2 with kd = 1: seen in the mirror,
    the wall's intensity is N' . L."""
    s = 5.0
    ramp = ((np.arange(64) + 0.5) / 64)[None, :].repeat(4, axis=0)
    bump = sl.Texture(ramp, filter="bilinear", wrap="clamp")
    light = [L.DirectionalLight(direction=(1, 1, 0))]
    mirror = L.Material(ka=0, kd=0, ks=0, reflectivity=1.0)
    meshes = [quad(MIRROR), quad(WALL, WALL_UV)]
    for scale, normal in ((s, (-100.0, -10.0 * s, 0.0)), (0.0, (-1.0, 0.0, 0.0))):
        wall = L.Material(ka=0, kd=1.0, ks=0, bump=bump, bump_scale=scale)
        a = traced(meshes, [mirror, wall], light)
        n = np.array(normal) / np.linalg.norm(normal)
        expected = 255 * float(n @ (np.array([-1.0, -1.0, 0.0]) / math.sqrt(2)))
        for row in (UP, 10, DOWN):
            assert a[row, 10].tolist() == pytest.approx([expected] * 3, abs=1.0)


#: Six 1 x 1 faces of distinct colors, +x, -x, +y, -y, +z, -z.
FACE_COLORS = [(255, 0, 0), (0, 255, 255), (0, 255, 0), (255, 0, 255), (0, 0, 255),
               (255, 255, 0)]


def cube_map():
    return sl.texture.CubeMap([np.array([[c]], np.uint8) for c in FACE_COLORS],
                              filter="nearest")


def test_a_ray_leaving_the_scene_samples_the_environment_map_of_the_surface_it_left():
    """Mirror A sends the view rays along +x; mirror B at x = 3 (the plane y = x - 3)
    turns them to +y.  The ray that leaves the scene brings the cube map of the
    surface it left: A's alone, the ray leaves A along +x (the +x face, red); B's, it
    leaves B along +y (the +y face, green); A's only but B in the way, the ray leaves
    B, which has none: the background."""
    b = quad([(2, -1, -2), (4, 1, -2), (4, 1, 2), (2, -1, 2)])
    plain = L.Material(ka=0, kd=0, ks=0, reflectivity=1.0)
    mapped = L.Material(ka=0, kd=0, ks=0, reflectivity=1.0, environment=cube_map())
    ambient = [L.AmbientLight(1.0)]
    assert traced([quad(MIRROR)], [mapped], ambient)[10, 10].tolist() == [255, 0, 0]
    assert traced([quad(MIRROR), b], [plain, mapped], ambient)[10, 10].tolist() == [0, 255, 0]
    assert traced([quad(MIRROR), b], [mapped, plain], ambient)[10, 10].tolist() == [0, 0, 0]
    # the tint applies to the map too: S_s = (0, 1, 1) on the green face
    cyan = L.Material(ka=0, kd=0, ks=0, reflectivity=1.0, environment=cube_map(),
                      specular_color=np.array([0.0, 1.0, 1.0]))
    assert traced([quad(MIRROR), b], [plain, cyan], ambient)[10, 10].tolist() == [0, 255, 0]
    cyan_a = L.Material(ka=0, kd=0, ks=0, reflectivity=1.0, environment=cube_map(),
                        specular_color=np.array([0.0, 1.0, 1.0]))
    assert traced([quad(MIRROR)], [cyan_a], ambient)[10, 10].tolist() == [0, 0, 0]


def test_a_latitude_longitude_map_after_the_bounce():
    """A latitude-longitude map (u = 1/2 + atan2(x, -z) / 2 pi): the +x direction is at
    u = 3/4, the right half of a 2-texel map (blue)."""
    image = np.array([[[255, 0, 0], [0, 0, 255]]], np.uint8)
    mapped = L.Material(ka=0, kd=0, ks=0, reflectivity=1.0,
                        environment=sl.Texture(image, filter="nearest"))
    a = traced([quad(MIRROR)], [mapped], [L.AmbientLight(1.0)])
    assert a[10, 10].tolist() == [0, 0, 255]


def test_the_ray_tree_lists_per_component_weights_when_tinted():
    mirror = L.Material(ka=0, kd=0, ks=0, reflectivity=0.5,
                        specular_color=np.array([1.0, 0.5, 0.0]))
    wall = L.Material(ka=1.0, kd=0, ks=0, color=(200, 40, 40))
    t = sl.trace.ray_tracing(10, 10, meshes=[quad(MIRROR), quad(WALL)], camera=ortho(),
                             materials=[mirror, wall], lights=[L.AmbientLight(1.0)],
                             width=21, height=21, gamma=1)
    reflected = [r for r in t.rows if r["kind"] == "reflected"]
    assert reflected[0]["weight"] == [0.5, 0.25, 0.0]
    last = t.rows[-1]
    assert [last["sum_r"], last["sum_g"], last["sum_b"]] == pytest.approx(
        [0.5 * 200 / 255, 0.25 * 40 / 255, 0.0])
