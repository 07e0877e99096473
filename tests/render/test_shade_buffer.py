"""The compiled visibility-buffer shading (scanline.shading.buffer) against the numpy
path (scanline.shading.intensities + encode): equal within one stored level,
for every shading model the kernel draws, both specular terms, every mode, several
kinds of lights, perspective and parallel views, back faces seen."""

import math

import numpy as np
import pytest

import scanline as sl
from scanline.screen import prepare
from scanline.shading import ShadingOptions, barycentrics, encode, intensities
from scanline.shading.buffer import gamma_tables, shade_buffer
from scanline.visible.zbuffer import nearest

W, H = 64, 48

LIGHTS = [sl.lighting.AmbientLight((0.2, 0.15, 0.1)),
          sl.lighting.DirectionalLight((0.4, -0.6, -1.0), (0.8, 0.7, 0.9)),
          sl.lighting.PointLight((2, 3, 4), 0.7, attenuation=(1, 0.05, 0.01)),
          sl.lighting.SpotLight((0, 0, 5), (0, 0, -1), 0.9, angle=0.4, exponent=3)]


def scene(parallel=False, mats=None):
    proj = (sl.projection.orthographic(window=(-2, -1.5, 2, 1.5)) if parallel else
            sl.projection.perspective(fov=math.radians(45), near=0.5, far=20))
    cam = sl.Camera(eye=(1.5, 1.0, 5.0), target=(0, 0, 0), projection=proj)
    torus = sl.mesh.torus(1.0, 0.35, resolution=(20, 10))
    box = sl.mesh.cube(0.8).transformed(sl.transform3d.translation(1.2, -0.6, 0.5))
    # a square whose outward normal points away from the viewer: a back face, seen
    back = sl.mesh.Mesh([(-2, -1, 0.3), (-2, 0.2, 0.3), (-1.1, 0.2, 0.3), (-1.1, -1, 0.3)],
                        [(0, 1, 2, 3)])
    if mats is None:
        mats = [sl.lighting.Material(ka=0.3, kd=0.6, ks=0.4, shininess=15,
                                     color=(200, 120, 60)),
                sl.lighting.Material(ka=0.2, kd=0.5, ks=0.6, shininess=80, color="teal",
                                     specular_color=(255, 220, 200))]
    sc = prepare([torus, box, back], cam, W, H, mats + [mats[0]])
    assert not sc.front[sc.facet_mesh == 2].any()
    return sc


def assert_like_the_numpy_path(sc, got, xs, ys, options, mode):
    """The kernel's pixels ``got`` (the stored bytes at columns ``xs``, rows ``ys``)
    within one stored level of the numpy path's, and equal at 99% of them."""
    tris = nearest(sc).ids[ys, xs]
    bary = barycentrics(sc, tris, xs.astype(float), ys.astype(float))
    linear = intensities(sc, sc.facet[tris], bary, options)
    if mode == "L":
        want = encode((linear * [0.299, 0.587, 0.114]).sum(axis=1), 2.2)[:, None]
    else:
        want = encode(linear, 2.2)
    assert np.abs(got[:, :want.shape[1]] - want).max() <= 1
    assert (got[:, :want.shape[1]] != want).mean() < 0.01


# Phong in every mode, view and specular term; the vertex path (none, flat, Gouraud)
# is one code for every mode and view
CASES = ([(parallel, "phong", specular, mode) for parallel in (False, True)
          for specular in ("phong", "blinn") for mode in ("L", "RGB", "RGBA")]
         + [(False, shading, specular, "RGB") for shading in ("flat", "gouraud")
            for specular in ("phong", "blinn")] + [(False, "none", "phong", "RGB")])


@pytest.mark.parametrize("parallel, shading, specular, mode", CASES)
def test_kernel_matches_the_numpy_path(parallel, shading, specular, mode):
    sc = scene(parallel)
    ids = nearest(sc).ids.copy()
    ys, xs = np.nonzero(ids >= 0)
    tris = ids[ys, xs]
    assert len(ys) > 500
    assert (sc.facet_mesh[sc.facet[tris]] == 2).sum() > 20        # the back face is seen
    fb = sl.FrameBuffer(W, H, mode=mode)
    opts = ShadingOptions(model=shading, lights=LIGHTS, specular=specular, gamma=2.2)
    shade_buffer(sc, fb, ids, opts)
    assert np.array_equal(ids[ys, xs], sc.facet[tris])          # the facets, in place
    got = fb._raster()[0][ys, xs].astype(int)
    assert_like_the_numpy_path(sc, got, xs, ys, opts, mode)
    if mode == "RGBA":
        assert (got[:, 3] == 255).all()


@pytest.mark.parametrize("shininess", [20, 2.5, 300])
def test_one_exponent_for_every_material(shininess):
    """One material for every facet: a small whole exponent is raised by squaring inside
    the lighting loop, a fraction or a whole one of 256 or more by the power in a pass
    of its own; each is the numpy path's highlight within a stored level."""
    mat = sl.lighting.Material(ka=0.2, kd=0.5, ks=0.8, shininess=shininess, color="white")
    sc = scene(mats=[mat, mat])
    ids = nearest(sc).ids.copy()
    ys, xs = np.nonzero(ids >= 0)
    tris = ids[ys, xs]
    fb = sl.FrameBuffer(W, H)
    opts = ShadingOptions(model="phong", lights=LIGHTS, specular="phong", gamma=2.2)
    shade_buffer(sc, fb, ids, opts)
    got = fb._raster()[0][ys, xs].astype(int)
    bary = barycentrics(sc, tris, xs.astype(float), ys.astype(float))
    want = encode(intensities(sc, sc.facet[tris], bary, opts), 2.2)
    matte = sl.lighting.Material(ka=0.2, kd=0.5, ks=0.0, color="white")
    plain = scene(mats=[matte, matte])                            # the same triangles
    dull = encode(intensities(plain, plain.facet[tris], bary, opts), 2.2)
    assert (want > dull + 2).any(axis=1).sum() >= 3             # a highlight is drawn
    assert np.abs(got - want).max() <= 1
    assert (got != want).mean() < 0.01


def test_pixels_without_a_face_are_left_alone():
    sc = scene()
    faces = nearest(sc).ids.copy()
    fb = sl.FrameBuffer(W, H, background="orange")
    before = fb._raster()[0].copy()
    shade_buffer(sc, fb, faces.copy(), ShadingOptions(model="phong", lights=LIGHTS))
    after = fb._raster()[0]
    assert np.array_equal(after[faces < 0], before[faces < 0])
    assert (after[faces >= 0] != before[faces >= 0]).any(axis=1).mean() > 0.9


@pytest.mark.parametrize("gamma", [1.0, 2.2, 0.45])
def test_gamma_tables_encode_like_the_power(gamma):
    from scanline._kernels._jit import python
    from scanline._kernels.shade import encode as kernel_encode

    table, thresholds = gamma_tables(gamma)
    rng = np.random.default_rng(3)
    values = np.concatenate([rng.uniform(-0.1, 1.1, 3000), rng.uniform(0, 1e-3, 1000),
                             [0.0, 1.0, np.nan, np.inf, -np.inf]])
    twin = python(kernel_encode)
    got = np.array([twin(x, table, thresholds) for x in values], int)
    want = encode(np.nan_to_num(values, nan=0.0), gamma).astype(int)
    assert np.abs(got - want).max() <= 1
    assert (got == want).mean() > 0.999


@pytest.mark.parametrize("gamma", [1.0, 2.2, 0.45, 3.0])
def test_the_stores_encode_every_intensity_as_the_climb_does(gamma):
    # the kernel's store takes the table step's value and one up past the step's own
    # copy of the next threshold; the full climb (encode) is the rule: the same byte
    # for intensities on every threshold, one unit in the last place either side of
    # it, near black, out of range and not a number
    from scanline._kernels import shade as ks
    from scanline._kernels._jit import python
    from scanline._kernels.variants import MODE

    table, thresholds = gamma_tables(gamma)
    edges = thresholds[1:256]
    rng = np.random.default_rng(5)
    values = np.concatenate([edges, np.nextafter(edges, -1), np.nextafter(edges, 2),
                             rng.uniform(-0.05, 1.05, 3000), rng.uniform(0, 1e-3, 500),
                             [0.0, 1.0, np.nan, np.inf, -np.inf]])
    n = ks.CHUNK
    values = np.concatenate([values, np.zeros(-len(values) % (3 * n))]).reshape(-1, 3, n)
    climb = python(ks.encode)
    for chunk in values:
        s = np.zeros(ks.FIELDS * n)
        s[ks.IR * n:(ks.IR + 3) * n] = chunk.ravel()
        raster = np.zeros((1, n, 3), np.uint8)
        ks.store_chunk(0, n, s, np.arange(n), table, thresholds, raster, ks.SHADING["phong"],
                       MODE["RGB"], False)
        want = np.array([[climb(v, table, thresholds) for v in channel] for channel in chunk],
                        np.uint8)
        assert np.array_equal(raster[0].T, want)
        # a gray light's one intensity (the red field) into every channel
        ks.store_chunk(0, n, s, np.arange(n), table, thresholds, raster, ks.SHADING["phong"],
                       MODE["RGB"], True)
        assert np.array_equal(raster[0].T, want[[0, 0, 0]])


GRAY_LIGHTS = [sl.lighting.AmbientLight(0.25),
               sl.lighting.DirectionalLight((0.4, -0.6, -1.0), 0.8),
               sl.lighting.PointLight((2, 3, 4), 0.7, attenuation=(1, 0.05, 0.01)),
               sl.lighting.SpotLight((0, 0, 5), (0, 0, -1), 0.9, angle=0.4, exponent=3)]

#: A colored light too faint to change any sum: 1e-300 times a term added to an
#: intensity of at least the ambient term's (about 0.01) is far below half a unit in
#: its last place, and the red and green sums gain exact zeros.
FAINT = sl.lighting.DirectionalLight((0.1, 0.2, -1.0), (0.0, 0.0, 1e-300))


@pytest.mark.parametrize("mode", ["L", "RGB", "RGBA"])
@pytest.mark.parametrize("materials", ["one", "two"])
def test_a_gray_light_is_summed_once_with_the_same_pixels(mode, materials):
    """Gray materials under gray lights: the kernel sums one intensity a pixel instead
    of three and stores its encoding into every channel.  The pixels are exactly
    those of the three sums (the same lights and FAINT, which makes the light
    colored without changing a value) and the numpy path's within a stored level."""
    from scanline._kernels.shade import light_setup
    from scanline.shading.buffer import material_rows, source_rows

    light = sl.lighting.Material(ka=0.3, kd=0.6, ks=0.4, shininess=15, color=(180, 180, 180))
    dark = sl.lighting.Material(ka=0.2, kd=0.5, ks=0.6, shininess=40, color=(90, 90, 90),
                                specular_color=(200, 200, 200))
    if materials == "one":          # one mesh, one material: the material's terms constant
        cam = sl.Camera(eye=(1.5, 1.0, 5.0), target=(0, 0, 0),
                        projection=sl.projection.perspective(fov=math.radians(45), near=0.5,
                                                             far=20))
        sc = prepare(sl.mesh.torus(1.0, 0.35, resolution=(20, 10)), cam, W, H, light)
        assert len(sc.materials) == 1
    else:
        sc = scene(mats=[light, dark])
    ids = nearest(sc).ids
    ys, xs = np.nonzero(ids >= 0)
    rows = material_rows(sc.materials)
    shaded = {}
    for name, lights in (("gray", GRAY_LIGHTS), ("colored", GRAY_LIGHTS + [FAINT])):
        sources, ambient = source_rows(lights)
        assert light_setup(sources, rows, ambient)[2] == (name == "gray")     # the path
        fb = sl.FrameBuffer(W, H, mode=mode)
        opts = ShadingOptions(model="phong", lights=lights, specular="phong", gamma=2.2)
        shade_buffer(sc, fb, ids.copy(), opts)
        shaded[name] = fb._raster()[0][ys, xs].astype(int)
    got = shaded["gray"]
    assert np.array_equal(got, shaded["colored"])
    if mode != "L":
        assert (got[:, 0] == got[:, 1]).all() and (got[:, 1] == got[:, 2]).all()
    assert len(np.unique(got[:, 0])) > 50                      # shaded, not one flat value
    assert_like_the_numpy_path(sc, got, xs, ys, ShadingOptions(model="phong", lights=GRAY_LIGHTS,
                                                               specular="phong", gamma=2.2), mode)
