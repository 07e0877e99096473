"""sl.Texture: mipmaps against Pillow's box-filtered reductions, the filters against
scipy's interpolation, the wraps, and coordinates no kernel may read outside its
arrays with."""

import numpy as np
import pytest
from PIL import Image
from scipy import ndimage

import scanline as sl
from scanline._kernels import texture as k
from scanline._kernels._jit import python
from scanline.errors import ArgumentTypeError, ArgumentValueError


def random_image(h, w, seed=0):
    return np.random.default_rng(seed).integers(0, 256, (h, w, 3), dtype=np.uint8)


@pytest.mark.parametrize("shape", [(16, 16), (13, 7), (1, 9), (10, 1), (6, 11)])
def test_each_mipmap_level_is_pillows_2x2_box_reduction_of_the_one_before(shape):
    image = random_image(*shape)
    levels = sl.Texture(image, filter="trilinear").levels
    assert levels[-1].shape[:2] == (1, 1)
    for i, level in enumerate(levels[1:], 1):
        before = np.rint(levels[i - 1] * 255).astype(np.uint8)
        expect = Image.fromarray(before).reduce(2)
        assert level.shape[:2] == (expect.height, expect.width)
        # one step on bytes: Pillow rounds its mean to a byte
        np.testing.assert_allclose(sl.texture.halved(before / 255.0) * 255,
                                   np.asarray(expect, np.float64), atol=0.51)
        # the pyramid keeps reals: the level before differs by up to half a byte
        np.testing.assert_allclose(level * 255, np.asarray(expect, np.float64), atol=1.01)


def test_a_power_of_two_pyramid_level_k_is_pillows_reduction_by_2_to_the_k():
    image = random_image(32, 64, seed=3)
    levels = sl.Texture(image, filter="trilinear").levels
    assert len(levels) == 7
    for i, level in enumerate(levels[1:6], 1):
        expect = np.asarray(Image.fromarray(image).reduce(2 ** i), np.float64)
        np.testing.assert_allclose(level * 255, expect, atol=0.51)


def flipped_rows(image):
    """The image's channels with row 0 at the bottom (v up), as reals."""
    return image[::-1].astype(np.float64) / 255.0


def uv_grid(n=400, lo=-1.7, hi=2.9, seed=1):
    return np.random.default_rng(seed).uniform(lo, hi, (n, 2))


SCIPY_MODE = {"repeat": "grid-wrap", "clamp": "nearest", "mirror": "reflect"}


@pytest.mark.parametrize("wrap", ["repeat", "clamp", "mirror"])
def test_bilinear_is_scipys_linear_interpolation_between_texel_centers(wrap):
    image = random_image(9, 14, seed=2)
    uv = uv_grid()
    got = sl.Texture(image, filter="bilinear", wrap=wrap).sample(uv)
    a = flipped_rows(image)
    # texel (i, j) is centered at ((i + 1/2) / w, (j + 1/2) / h)
    x = uv[:, 0] * 14 - 0.5
    y = uv[:, 1] * 9 - 0.5
    if wrap == "clamp":
        x, y = np.clip(x, -0.5, 13.5), np.clip(y, -0.5, 8.5)
    for c in range(3):
        expect = ndimage.map_coordinates(a[..., c], [y, x], order=1, mode=SCIPY_MODE[wrap])
        np.testing.assert_allclose(got[:, c], expect, atol=1e-6)


@pytest.mark.parametrize("wrap", ["repeat", "clamp", "mirror"])
def test_nearest_takes_the_texel_whose_square_holds_the_point(wrap):
    image = random_image(5, 8, seed=4)
    uv = uv_grid(seed=5)
    got = sl.Texture(image, filter="nearest", wrap=wrap).sample(uv)
    a = flipped_rows(image)
    i, j = np.floor(uv[:, 0] * 8).astype(int), np.floor(uv[:, 1] * 5).astype(int)
    if wrap == "repeat":
        i, j = i % 8, j % 5
    elif wrap == "clamp":
        i, j = np.clip(i, 0, 7), np.clip(j, 0, 4)
    else:
        i = np.where(i % 16 < 8, i % 16, 15 - i % 16)
        j = np.where(j % 10 < 5, j % 10, 9 - j % 10)
    np.testing.assert_allclose(got, a[j, i], atol=1e-6)


def test_trilinear_reads_the_level_the_footprint_names_and_blends_two():
    image = random_image(64, 64, seed=6)
    t = sl.Texture(image, filter="trilinear", wrap="clamp")
    bil = [sl.Texture(np.rint(lv * 255).astype(np.uint8), filter="bilinear", wrap="clamp")
           for lv in t.levels]
    uv = uv_grid(50, 0.1, 0.9, seed=7)
    for level in (0, 2, 3):
        d = np.tile([2.0 ** level / 64, 0, 0, 2.0 ** level / 64], (50, 1))
        np.testing.assert_allclose(t.sample(uv, d), bil[level].sample(uv), atol=0.6 / 255)
    # a footprint of 2^2.5 texels: halfway between levels 2 and 3
    d = np.tile([2.0 ** 2.5 / 64, 0, 0, 0], (50, 1))
    np.testing.assert_allclose(t.sample(uv, d),
                               (bil[2].sample(uv) + bil[3].sample(uv)) / 2, atol=0.6 / 255)
    # magnified (a pixel smaller than a texel): the finest level
    np.testing.assert_allclose(t.sample(uv, d / 100), bil[0].sample(uv), atol=1e-6)


@pytest.mark.parametrize("compiled", [True, False])
@pytest.mark.parametrize("filter", [0, 1, 2])
@pytest.mark.parametrize("wrap", [0, 1, 2])
def test_no_coordinate_reads_outside_the_texels(compiled, filter, wrap):
    t = sl.Texture(random_image(3, 5, seed=8), filter="trilinear")
    texels, table = t.kernel_arrays()
    hostile = np.array([np.nan, np.inf, -np.inf, 1e308, -1e308, 2.0 ** 63, -2.0 ** 63, 1e-320,
                        -0.0, 0.9999999999999999, -1e-17, 3.5])
    uv = np.array(np.meshgrid(hostile, hostile)).reshape(2, -1).T.copy()
    d = np.tile(hostile[:4], (len(uv), 1))
    d[::3] = np.nan
    d[1::3] = 1e300
    out = np.full((len(uv), 3), -1.0)
    kernel = k.sample_points if compiled else python(k.sample_points)
    with np.errstate(all="ignore"):         # as the compiled kernel's error model
        kernel(np.array(texels), np.array(table), 0, len(table), filter, wrap, uv, d, out)
    assert np.isfinite(out).all() and out.min() >= 0 and out.max() <= 1


def test_nan_texture_coordinates_are_refused_by_name():
    t = sl.Texture(random_image(4, 4))
    with pytest.raises(ArgumentValueError, match="uv"):
        t.sample([[0.5, np.nan]])


@pytest.mark.parametrize("image, error", [
    (np.zeros((4, 4, 2), np.uint8), ArgumentValueError),
    (np.zeros((0, 4, 3), np.uint8), ArgumentValueError),
    (np.full((2, 2, 3), 1.5), ArgumentValueError),
    (np.full((2, 2, 3), np.nan), ArgumentValueError),
    (np.full((2, 2, 3), 300, np.int32), ArgumentValueError),
    (np.zeros((2, 2, 3), bool), ArgumentTypeError),
    (np.array([["a"]]), ArgumentTypeError),
    (42, ArgumentTypeError),
])
def test_bad_images_are_refused_by_name(image, error):
    with pytest.raises(error, match="image"):
        sl.Texture(image)


def test_filter_and_wrap_are_checked():
    with pytest.raises(ArgumentValueError, match="filter"):
        sl.Texture(random_image(2, 2), filter="cubic")
    with pytest.raises(ArgumentValueError, match="wrap"):
        sl.Texture(random_image(2, 2), wrap="border")


def test_images_come_from_arrays_pillow_and_files_alike(tmp_path):
    image = random_image(6, 5, seed=9)
    path = tmp_path / "t.png"
    Image.fromarray(image).save(path)
    rgba = np.concatenate([image, np.full((6, 5, 1), 7, np.uint8)], axis=2)
    gray = image[..., 0]
    for source in (Image.fromarray(image), path, str(path), rgba, image / 255.0):
        np.testing.assert_allclose(sl.Texture(source).image, image / 255.0, atol=1e-12)
    np.testing.assert_allclose(sl.Texture(gray).image, np.repeat(gray[..., None], 3, 2) / 255)
    with pytest.raises(sl.ImageFileError):
        sl.Texture(tmp_path / "missing.png")


def test_a_texture_too_large_for_the_memory_budget_is_refused(monkeypatch):
    monkeypatch.setenv("SCANLINE_MEMORY_LIMIT", "1M")
    with pytest.raises(sl.budget.MemoryBudgetError if hasattr(sl.budget, "MemoryBudgetError")
                       else ArgumentValueError, match="image"):
        sl.Texture(np.zeros((600, 600, 3), np.uint8))
