"""Cube environment maps (Hearn & Baker 14-8) against OpenGL's face selection table
(The OpenGL Graphics System 4.6, table 8.19), written out here: the face and texel
of a direction, continuity across the seams, agreement with a latitude-longitude map,
the cross layout, the shading's and the tracer's use, and bad input named."""

import numpy as np
import pytest

import scanline as sl
from scanline.errors import ArgumentTypeError, ArgumentValueError

from .test_mapping import mirror_reflections, render

CubeMap = sl.texture.CubeMap

#: OpenGL table 8.19: major axis -> (face index, s_c, t_c, m) as functions of (x, y, z).
TABLE = {
    "+x": (0, lambda x, y, z: (-z, -y, x)),
    "-x": (1, lambda x, y, z: (z, -y, -x)),
    "+y": (2, lambda x, y, z: (x, z, y)),
    "-y": (3, lambda x, y, z: (x, -z, -y)),
    "+z": (4, lambda x, y, z: (x, -y, z)),
    "-z": (5, lambda x, y, z: (-x, -y, -z)),
}


def opengl_face(d):
    """Face name, s and t (0..1, t down the image) of direction d by table 8.19."""
    x, y, z = d
    axis = int(np.argmax(np.abs(d)))
    name = ("+" if d[axis] > 0 else "-") + "xyz"[axis]
    sc, tc, m = TABLE[name][1](x, y, z)
    return name, (sc / m + 1) / 2, (tc / m + 1) / 2


def smooth(d):
    """A smooth function of direction: 0.5 + 0.5 d / |d| per component."""
    d = np.asarray(d, np.float64)
    return 0.5 + 0.5 * d / np.linalg.norm(d, axis=-1, keepdims=True)


def faces_of(function, n):
    """Six n x n faces whose texels are ``function`` at the directions of their
    centers, by the inverse of table 8.19 (solved here face by face)."""
    c = (np.arange(n) + 0.5) / n * 2 - 1
    sc, tc = np.meshgrid(c, c)                  # rows: t_c down the image
    one = np.ones_like(sc)
    directions = {"+x": (one, -tc, -sc), "-x": (-one, -tc, sc), "+y": (sc, one, tc),
                  "-y": (sc, -one, -tc), "+z": (sc, -tc, one), "-z": (-sc, -tc, -one)}
    return [function(np.stack(directions[f], -1)) for f in ("+x", "-x", "+y", "-y", "+z", "-z")]


def numbered_faces(n):
    """Six n x n faces whose texels are all different: (face, row, column) coded in
    the three channels (values / 255)."""
    f, r, c = np.meshgrid(np.arange(6), np.arange(n), np.arange(n), indexing="ij")
    return [np.stack([f[k], r[k], c[k]], -1).astype(np.uint8) for k in range(6)]


def test_each_axis_meets_its_faces_center_texel():
    n = 5
    cube = CubeMap(numbered_faces(n), filter="nearest")
    axes = np.array([(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)])
    got = np.round(cube.sample(axes) * 255).astype(int)
    assert got.tolist() == [[k, 2, 2] for k in range(6)]


def test_any_direction_meets_the_texel_of_opengls_table():
    n = 8
    cube = CubeMap(numbered_faces(n), filter="nearest")
    rng = np.random.default_rng(3)
    d = rng.normal(size=(2000, 3)) * rng.uniform(0.1, 50, (2000, 1))
    got = np.round(cube.sample(d) * 255).astype(int)
    expected = []
    for row in d:
        name, s, t = opengl_face(row)
        expected.append([TABLE[name][0], min(int(t * n), n - 1), min(int(s * n), n - 1)])
    assert got.tolist() == expected


def test_the_seams_are_continuous():
    """Directions a hair either side of each of the 12 edges (and the 8 corners) of
    the cube, on a map of a smooth function: the two faces' bilinear colors agree
    within the function's change over a texel."""
    n = 32
    cube = CubeMap(faces_of(smooth, n))
    rng = np.random.default_rng(0)
    eps = 1e-9
    for a in range(3):
        for b in range(a + 1, 3):
            for sa in (-1, 1):
                for sb in (-1, 1):
                    t = rng.uniform(-0.95, 0.95, 50)
                    d = np.zeros((50, 3))
                    d[:, a], d[:, b] = sa, sb
                    d[:, 3 - a - b] = t
                    one, two = d.copy(), d.copy()
                    one[:, a] *= 1 + eps          # just on a's face
                    two[:, b] *= 1 + eps          # just on b's face
                    assert {opengl_face(one[0])[0], opengl_face(two[0])[0]} == {
                        ("+" if sa > 0 else "-") + "xyz"[a], ("+" if sb > 0 else "-") + "xyz"[b]}
                    np.testing.assert_allclose(cube.sample(one), cube.sample(two),
                                               atol=1.0 / n)
    # and everywhere, the map of the smooth function is the function within a texel
    d = rng.normal(size=(5000, 3))
    np.testing.assert_allclose(cube.sample(d), smooth(d), atol=1.0 / n)


def test_a_cube_map_made_from_a_latitude_longitude_map_agrees_with_it():
    h = 128
    theta = (np.arange(h) + 0.5) / h * np.pi                       # from the top: v = 1 - theta/pi
    phi = (np.arange(2 * h) + 0.5) / (2 * h) * 2 * np.pi - np.pi   # u = 1/2 + phi / 2 pi
    th, ph = np.meshgrid(theta, phi, indexing="ij")
    # u = 1/2 + atan2(x, -z) / 2 pi, v = 1/2 + asin(y) / pi
    d = np.stack([np.sin(th) * np.sin(ph), np.cos(th), -np.sin(th) * np.cos(ph)], -1)
    latlong = sl.Texture(smooth(d))
    cube = CubeMap.from_latitude_longitude(latlong, size=64)
    rng = np.random.default_rng(1)
    dirs = rng.normal(size=(3000, 3))
    from scanline.texture.cubemap import environment_colors

    np.testing.assert_allclose(cube.sample(dirs), environment_colors(latlong, dirs),
                               atol=0.03)
    np.testing.assert_allclose(cube.sample(dirs), smooth(dirs), atol=0.03)


def test_the_cross_layout_is_the_six_faces():
    n = 3
    faces = numbered_faces(n)
    cross = np.zeros((3 * n, 4 * n, 3), np.uint8)
    # +y above +z, -y below it; -x, +z, +x, -z across the middle
    for k, (col, row) in enumerate([(2, 1), (0, 1), (1, 0), (1, 2), (1, 1), (3, 1)]):
        cross[row * n:(row + 1) * n, col * n:(col + 1) * n] = faces[k]
    a, b = CubeMap(cross, filter="nearest"), CubeMap(faces, filter="nearest")
    d = np.random.default_rng(2).normal(size=(500, 3))
    assert np.array_equal(a.sample(d), b.sample(d))


def test_the_shading_reflects_a_cube_map_tinted_by_the_specular_color():
    """A mirror seen with Phong shading: each pixel is k_r S_s times the map of the
    smooth function in the reflected view direction R = 2 (N . V) N - V."""
    tint = np.array([1.0, 0.5, 0.25])
    mat = sl.lighting.Material(ka=0, kd=0, ks=0, reflectivity=0.9, specular_color=tint,
                               environment=CubeMap(faces_of(smooth, 64)))
    img, hit, r = mirror_reflections(mat)
    assert hit.sum() > 400
    np.testing.assert_allclose(img[hit], 0.9 * tint * smooth(r[hit]), atol=0.02)


def test_the_tracer_and_the_shading_agree_on_a_mirror_with_a_cube_map():
    mirror = sl.mesh.Mesh([(-1, -1, 0), (-1, 1, 0), (1, 1, 0), (1, -1, 0)], [[0, 1, 2, 3]])
    cam = sl.Camera(eye=(0.3, 0.2, -1.5), target=(0, 0, 0), up=(0, 1, 0))
    mat = sl.lighting.Material(ka=0, kd=0, ks=0, reflectivity=0.8,
                               environment=CubeMap(faces_of(smooth, 16)))
    shaded = render(mat, "phong", mesh=mirror, camera=cam, size=(40, 40))
    traced = render(mat, "phong", method="ray-tracing", mesh=mirror, camera=cam, size=(40, 40))
    seen = shaded.sum(axis=-1) > 0
    assert seen.sum() > 300
    np.testing.assert_allclose(traced[seen], shaded[seen], atol=1.01 / 255)


@pytest.mark.parametrize("faces, error, words", [
    ([np.zeros((4, 4, 3))] * 5, ArgumentValueError, "six images"),
    ([np.zeros((4, 4, 3))] * 5 + [np.zeros((2, 2, 3))], ArgumentValueError, "-z"),
    ([np.zeros((4, 3, 3))] * 6, ArgumentValueError, "square"),
    ([np.zeros((4, 4, 3))] * 5 + [np.zeros((4, 4, 3), "U1")], ArgumentTypeError,
     r"faces\[5\]"),
    ([np.zeros((4, 4, 3))] * 5 + [np.full((4, 4, 3), np.nan)], ArgumentValueError,
     r"faces\[5\]"),
    (np.zeros((8, 8, 3)), ArgumentValueError, "horizontal cross"),
    ("no-such-file.png", Exception, "no-such-file"),
])
def test_bad_faces_name_the_argument(faces, error, words):
    with pytest.raises(error, match=words):
        CubeMap(faces)


def test_bad_filter_size_and_directions():
    faces = [np.zeros((2, 2, 3))] * 6
    with pytest.raises(ArgumentValueError, match="filter"):
        CubeMap(faces, filter="trilinear")
    cube = CubeMap(faces)
    with pytest.raises(ArgumentValueError, match="directions"):
        cube.sample([[np.nan, 0, 1]])
    with pytest.raises(ArgumentValueError, match="directions"):
        cube.sample([[0, 0, 0]])
    with pytest.raises(ArgumentValueError, match="directions"):
        cube.sample([[1, 2]])
    with pytest.raises(ArgumentValueError, match="size"):
        CubeMap.from_latitude_longitude(np.zeros((4, 8, 3)), size=0)
    with pytest.raises(ArgumentTypeError, match="texture"):
        CubeMap.from_latitude_longitude(cube)
    with pytest.raises(ArgumentValueError, match="environment"):
        sl.lighting.Material(environment=np.zeros((2, 2, 5)))
