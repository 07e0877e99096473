"""Dithering: Bayer matrices, Floyd-Steinberg against a pure-Python reference and
Pillow, mean intensity kept, palettes, output modes and bad input."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp
from PIL import Image

import scanline as sl
from tests.reference import HYPOTHESIS

RNG = np.random.default_rng(1976)
ORDERED = ("bayer2", "bayer4", "bayer8")
METHODS = ("floyd-steinberg",) + ORDERED


# -- pure-Python references ----------------------------------------------------------

def floyd_steinberg_reference(image, values, serpentine=False):
    """Floyd & Steinberg (1976) written out plainly: ``image`` (h, w, c) floats,
    ``values`` (n, c) the colors allowed; returns the (h, w) index of the chosen
    color.  Error is diffused 7/16 right, 3/16 down-left, 5/16 down, 1/16
    down-right (mirrored on right-to-left rows); error leaving the image is lost."""
    work = [[list(map(float, px)) for px in row] for row in image]
    h, w = len(work), len(work[0])
    chosen = [[0] * w for _ in range(h)]
    for y in range(h):
        backwards = serpentine and y % 2 == 1
        step = -1 if backwards else 1
        for x in (range(w - 1, -1, -1) if backwards else range(w)):
            old = work[y][x]
            dist = [sum((o - v) ** 2 for o, v in zip(old, value)) for value in values]
            best = dist.index(min(dist))
            chosen[y][x] = best
            error = [o - v for o, v in zip(old, values[best])]
            for dx, dy, weight in ((step, 0, 7), (-step, 1, 3), (0, 1, 5), (step, 1, 1)):
                if 0 <= x + dx < w and y + dy < h:
                    for k, e in enumerate(error):
                        work[y + dy][x + dx][k] += e * weight / 16
    return np.array(chosen)


def pillow_floyd_steinberg(gray):
    """Pillow's integer Floyd-Steinberg for L -> 1 (libImaging/Convert.c,
    ``tobilevel``) re-expressed in Python: errors in sixteenths, the corrected value
    clipped to 0..255, integer division truncating toward zero, white when > 128."""
    h, w = gray.shape
    out = np.zeros((h, w), bool)
    errors = [0] * (w + 1)
    for y in range(h):
        ahead = below_left = below = 0          # l, l0, l1 in Pillow's code
        for x in range(w):
            total = ahead + errors[x + 1]
            value = min(255, max(0, int(gray[y, x]) + int(total / 16)))
            out[y, x] = value > 128
            e = value - (255 if out[y, x] else 0)
            errors[x] = 3 * e + below_left
            below_left = 5 * e + below
            below = e
            ahead = 7 * e
        errors[w] = below_left
    return out


def gray_values(levels):
    return [[k / (levels - 1)] for k in range(levels)]


def bits(fb):
    assert fb.mode == "1"
    return fb.to_array()


# -- Bayer matrices ------------------------------------------------------------------

def test_bayer_matrices_published_values():
    # Bayer (1973); the 4x4 and the first rows of the 8x8 as printed in the literature
    assert sl.color.bayer_matrix(2).tolist() == [[0, 2], [3, 1]]
    assert sl.color.bayer_matrix(4).tolist() == [[0, 8, 2, 10], [12, 4, 14, 6],
                                                 [3, 11, 1, 9], [15, 7, 13, 5]]
    m8 = sl.color.bayer_matrix(8)
    assert m8[0].tolist() == [0, 32, 8, 40, 2, 34, 10, 42]
    assert m8[1].tolist() == [48, 16, 56, 24, 50, 18, 58, 26]


@pytest.mark.parametrize("n", [1, 2, 4, 8, 16])
def test_bayer_matrix_is_a_permutation_with_the_recursive_structure(n):
    m = sl.color.bayer_matrix(n)
    assert sorted(m.ravel().tolist()) == list(range(n * n))
    if n > 1:
        half = sl.color.bayer_matrix(n // 2)
        # quadrants 4M, 4M + 2, 4M + 3, 4M + 1
        k = n // 2
        assert (m[:k, :k] == 4 * half).all() and (m[:k, k:] == 4 * half + 2).all()
        assert (m[k:, :k] == 4 * half + 3).all() and (m[k:, k:] == 4 * half + 1).all()


@pytest.mark.parametrize("n", [0, 3, 6, 512, 2.0, "4"])
def test_bayer_matrix_bad_sizes(n):
    with pytest.raises((ValueError, TypeError), match="n"):
        sl.color.bayer_matrix(n)


# -- Floyd-Steinberg against the reference --------------------------------------------

@pytest.mark.parametrize("seed", range(4))
@pytest.mark.parametrize("serpentine", [False, True])
def test_floyd_steinberg_bitmap_matches_reference(seed, serpentine):
    image = np.random.default_rng(seed).random((9, 11))
    ours = bits(sl.color.dither(image, serpentine=serpentine))
    expected = floyd_steinberg_reference(image[:, :, None], gray_values(2), serpentine)
    assert (ours == expected.astype(bool)).all()


@pytest.mark.parametrize("levels", [2, 5])
def test_floyd_steinberg_of_uint8_matches_reference(levels):
    # uint8 images go to the kernel as they are (read through a table of v / 255)
    gray = RNG.integers(0, 256, (9, 13), dtype=np.uint8)
    ours = sl.color.dither(gray, levels=levels, mode="L").to_array()
    index = floyd_steinberg_reference(gray[:, :, None] / 255, gray_values(levels))
    assert (ours == sl.color.gray_table(levels)[index, 0]).all()


@pytest.mark.parametrize("levels", [3, 4, 7])
def test_floyd_steinberg_levels_match_reference(levels):
    image = RNG.random((8, 10))
    ours = sl.color.dither(image, levels=levels, mode="L").to_array()
    index = floyd_steinberg_reference(image[:, :, None], gray_values(levels))
    assert (ours == sl.color.gray_table(levels)[index, 0]).all()


def test_floyd_steinberg_rgb_levels_match_reference():
    image = RNG.random((7, 9, 3))
    ours = sl.color.dither(image, levels=2, mode="RGB").to_array()
    for k in range(3):   # per channel, independently
        index = floyd_steinberg_reference(image[:, :, k:k + 1], gray_values(2))
        assert (ours[:, :, k] == 255 * index).all()


@pytest.mark.parametrize("serpentine", [False, True])
def test_floyd_steinberg_palette_matches_reference(serpentine):
    image = RNG.integers(0, 256, (8, 9, 3), dtype=np.uint8)
    palette = ["black", "white", "red", "#00c000", "blue", "yellow"]
    fb = sl.color.dither(image, palette=palette, serpentine=serpentine)
    assert fb.mode == "P"
    table = sl.color.color_table(palette)
    assert (fb.color_table == table).all()
    expected = floyd_steinberg_reference(image / 255, table / 255, serpentine)
    assert (fb.to_array() == expected).all()


def test_floyd_steinberg_by_hand():
    # one row of 0.25: errors carry 7/16 to the right only (there is no row below)
    # 0.25 -> 0 (e .25), .359 -> 0 (e .359), .407 -> 0, .428 -> 0, .437 -> 0, .441 ...
    # the running value v_k = .25 + 7/16 v_{k-1} stays below 1/2: all black
    assert not bits(sl.color.dither(np.full((1, 12), 0.25))).any()
    # a 2 x 2 of 0.5, by hand: (0, 0) rounds half up to 1, error -1/2;
    # (0, 1): .5 - 7/32 = .28125 -> 0, error .28125;
    # (1, 0): .5 - 5/32 + 3/16 * .28125 = .39648 -> 0, error .39648;
    # (1, 1): .5 - 1/32 + 5/16 * .28125 + 7/16 * .39648 = .73004 -> 1
    assert bits(sl.color.dither(np.full((2, 2), 0.5))).tolist() == [[True, False], [False, True]]


# -- Pillow's Floyd-Steinberg ---------------------------------------------------------

def test_pillow_reference_reproduces_pillow_exactly():
    gray = RNG.integers(0, 256, (23, 31), dtype=np.uint8)
    pillow = np.asarray(Image.fromarray(gray).convert("1"))
    assert (pillow_floyd_steinberg(gray) == pillow).all()


@pytest.mark.parametrize("kind", ["ramp", "random", "photo-like"])
def test_compare_with_pillow_convert_1(kind):
    """Pillow's convert("1") is Floyd-Steinberg too, in integers: it clips each
    corrected value to 0..255, truncates the sixteenths and sets white when > 128.
    scanline diffuses exact (float) errors without clipping and rounds 1/2 up, so
    the two agree on most pixels, not all; both keep the mean within 1%."""
    h, w = 96, 128
    if kind == "ramp":
        gray = np.tile(np.linspace(0, 255, w), (h, 1)).round().astype(np.uint8)
    elif kind == "random":
        gray = RNG.integers(0, 256, (h, w), dtype=np.uint8)
    else:
        y, x = np.mgrid[0:h, 0:w]
        gray = (127.5 + 127.5 * np.sin(x / 9.0) * np.cos(y / 13.0)).round().astype(np.uint8)
    pillow = np.asarray(Image.fromarray(gray).convert("1"))
    ours = bits(sl.color.dither(gray))
    mean = gray.mean() / 255
    assert abs(ours.mean() - mean) < 0.01 and abs(pillow.mean() - mean) < 0.01
    # not identical: the error arithmetic differs (see the docstring) ...
    assert (ours != pillow).any()
    # ... yet the same algorithm: both diffuse the same way on the first row until
    # the first pixel where the corrected values differ, and overall they agree on
    # most pixels (measured: 60-90% depending on the image)
    assert (ours == pillow).mean() > 0.5


# -- mean intensity is kept --------------------------------------------------------

def _ramp(h=64, w=256):
    return np.tile(np.linspace(0.0, 1.0, w), (h, 1))


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("levels", [2, 3, 4, 16])
def test_mean_kept_on_ramps_and_random_images(method, levels):
    for image in (_ramp(), RNG.random((64, 96)), _ramp().T.copy()):
        fb = sl.color.dither(image, method, levels=levels, mode="L")
        mean = fb.to_array().mean() / 255
        assert abs(mean - image.mean()) < 0.01, (method, levels, mean, image.mean())


@pytest.mark.parametrize("value", list(range(0, 256, 5)) + [1, 127, 128, 254])
def test_floyd_steinberg_keeps_any_constant_level(value):
    image = np.full((64, 64), value, np.uint8)
    assert abs(bits(sl.color.dither(image)).mean() - value / 255) < 0.01


@pytest.mark.parametrize("method, n", [("bayer2", 2), ("bayer4", 4), ("bayer8", 8)])
def test_ordered_dither_renders_its_n2_plus_1_levels_exactly(method, n):
    # an n x n matrix has n*n + 1 patterns: intensity k / n**2 sets exactly k of n**2
    for k in range(n * n + 1):
        image = np.full((4 * n, 4 * n), k / (n * n))
        assert bits(sl.color.dither(image, method)).sum() == 16 * k
    # between those, the error is at most half a pattern step: 1 / (2 n**2)
    for value in np.linspace(0, 1, 51):
        got = bits(sl.color.dither(np.full((8, 8), value), method)).mean()
        assert abs(got - value) <= 0.5 / (n * n) + 1e-9


@pytest.mark.parametrize("method", ORDERED)
@pytest.mark.parametrize("dtype", [np.float64, np.uint8])
def test_ordered_dither_matches_a_numpy_threshold_map(method, dtype):
    # (uint8 images take another path in the kernel: a table per threshold)
    n = int(method[5:])
    image = RNG.random((37, 45))
    if dtype == np.uint8:
        image = (image * 255).round().astype(np.uint8)
    unit = image.astype(np.float32) / np.float32(255) if dtype == np.uint8 else image.astype(np.float32)
    for levels in (2, 5, 256):
        thresholds = ((sl.color.bayer_matrix(n) + 0.5) / n ** 2).astype(np.float32)
        tiled = np.tile(thresholds, (37 // n + 1, 45 // n + 1))[:37, :45]
        scaled = unit * np.float32(levels - 1)
        expected = np.floor(scaled) + (scaled - np.floor(scaled) >= tiled)
        expected = np.minimum(expected, levels - 1).astype(int)
        got = sl.color.dither(image, method, levels=levels, mode="L").to_array()
        assert (got == sl.color.gray_table(levels)[expected, 0]).all()


@pytest.mark.parametrize("method", METHODS)
def test_palette_dither_keeps_mean_color(method):
    y, x = np.mgrid[0:96, 0:128]
    image = np.stack([x / 127, y / 95, 1 - x / 127 * 0.5], axis=2)
    fb = sl.color.dither(image, method, palette=sl.color.web_safe_table())
    shown = fb.color_table[fb.to_array()] / 255
    assert np.abs(shown.mean(axis=(0, 1)) - image.mean(axis=(0, 1))).max() < 0.01
    # and every pixel is within one palette step (51/255) per channel, or near it
    assert np.abs(shown - image).max() < 0.35


def test_gray_table_palette_equals_gray_levels():
    image = RNG.random((20, 30))
    for method in METHODS:
        as_palette = sl.color.dither(image, method, palette=sl.color.gray_table(4))
        as_levels = sl.color.dither(image, method, levels=4, mode="L")
        shown = as_palette.color_table[as_palette.to_array()][:, :, 0]
        if method == "floyd-steinberg":
            assert (shown == as_levels.to_array()).all()
        else:   # spread = one level step: same thresholds, up to float rounding
            assert (shown == as_levels.to_array()).mean() > 0.99


# -- sources and output modes ------------------------------------------------------

@pytest.mark.parametrize("method", ["floyd-steinberg", "bayer4"])
def test_sources_of_every_kind_give_the_same_bitmap(method):
    gray = RNG.integers(0, 256, (12, 17), dtype=np.uint8)
    rgb = np.repeat(gray[:, :, None], 3, axis=2)
    expected = bits(sl.color.dither(gray, method))
    sources = [gray, gray / 255.0, rgb, np.dstack([rgb, np.zeros_like(gray)]),
               sl.FrameBuffer.from_array(gray), sl.FrameBuffer.from_array(rgb),
               sl.FrameBuffer.from_array(np.dstack([rgb, gray]))]
    p = sl.FrameBuffer.from_array(gray, mode="P", color_table=sl.color.gray_table(256))
    sources.append(p)
    for source in sources:
        assert (bits(sl.color.dither(source, method)) == expected).all()


def test_color_source_uses_luminance():
    rgb = RNG.integers(0, 256, (10, 10, 3), dtype=np.uint8)
    luma = rgb.astype(float) @ [0.299, 0.587, 0.114] / 255
    assert (bits(sl.color.dither(rgb, "bayer4")) == bits(sl.color.dither(luma, "bayer4"))).all()


def test_bitmap_source_is_kept():
    on = RNG.random((9, 13)) > 0.5
    assert (bits(sl.color.dither(on)) == on).all()
    assert (bits(sl.color.dither(sl.FrameBuffer.from_array(on), "bayer8")) == on).all()


def test_output_modes():
    image = _ramp(8, 32)
    assert sl.color.dither(image).mode == "1"
    assert sl.color.dither(image, levels=4).mode == "L"
    assert sl.color.dither(image, levels=2, mode="L").to_array().max() == 255
    rgb = sl.color.dither(RNG.random((8, 8, 3)), levels=2, mode="RGB")
    assert rgb.mode == "RGB" and set(np.unique(rgb.to_array())) <= {0, 255}
    p = sl.color.dither(image, levels=4, mode="P")
    assert p.mode == "P" and p.color_table[:, 0].tolist() == [0, 85, 170, 255]
    # the frame buffer's image is bottom-up inside, but the array comes back in order
    assert sl.color.dither(image).to_array()[:, -1].all()
    assert sl.color.dither(image).get_pixel(31, 0) == 1


def test_palette_result_recolors_when_the_table_is_edited():
    image = _ramp(4, 16)
    fb = sl.color.dither(image, palette=["black", "white"])
    before = fb.to_array().copy()
    fb.set_table_entry(1, "red")
    assert (fb.to_array() == before).all()
    assert (fb.to_pil().convert("RGB").getpixel((15, 0))) == (255, 0, 0)


def test_method_none_rounds_to_the_nearest_level_halves_up():
    image = np.array([[0.0, 0.1, 0.2, 0.49, 0.5, 0.51, 0.8, 1.0]])
    assert sl.color.dither(image, "none").to_array().tolist() == [
        [False, False, False, False, True, True, True, True]]
    # as Floyd-Steinberg rounds its first pixel
    assert sl.color.dither(np.array([[0.5]])).to_array().tolist() == [[True]]
    # levels 0, 1/3, 2/3, 1: 1/6 and 1/2 are halfway
    image = np.array([[1 / 6, 0.5, 0.16, 0.49]])
    assert sl.color.dither(image, "none", levels=4, mode="L").to_array().tolist() == [
        [85, 170, 0, 85]]


# -- bad input -------------------------------------------------------------------------

@pytest.mark.parametrize("kwargs, words", [
    ({"levels": 1}, "levels=1"),
    ({"levels": 0}, "levels=0"),
    ({"levels": 257}, "levels=257"),
    ({"levels": 2.5}, "levels=2.5"),
    ({"levels": True}, "levels=True"),
    ({"method": "atkinson"}, "method"),
    ({"method": None}, "method"),
    ({"palette": []}, "palette must have 1 to 256"),
    ({"palette": np.zeros((0, 3), np.uint8)}, "palette must have 1 to 256"),
    ({"palette": ["black"] * 257}, "palette must have 1 to 256"),
    ({"palette": ["black", "nocolor"]}, "palette[1]"),
    ({"palette": "red"}, "palette"),
    ({"palette": ["black"], "levels": 4}, "not both"),
    ({"mode": "1", "levels": 4}, "mode='1'"),
    ({"mode": "RGBA"}, "mode"),
    ({"mode": "L", "palette": ["black"]}, "mode 'P'"),
    ({"serpentine": "yes"}, "serpentine"),
])
def test_bad_arguments(kwargs, words):
    with pytest.raises((sl.ArgumentValueError, sl.ArgumentTypeError)) as info:
        sl.color.dither(_ramp(4, 4), **kwargs)
    assert words in str(info.value)


@pytest.mark.parametrize("source, words", [
    (np.zeros((0, 4)), "non-empty"),
    (np.zeros(5), "shape"),
    (np.zeros((3, 3, 2)), "shape"),
    (np.full((3, 3), np.nan), "finite"),
    (np.full((3, 3), 1.5), "[0, 1]"),
    (np.full((3, 3), -0.1), "[0, 1]"),
    (np.zeros((3, 3), np.int32), "dtype int32"),
    ("image.png", "FrameBuffer"),
    (None, "FrameBuffer"),
])
def test_bad_sources(source, words):
    with pytest.raises((sl.ArgumentValueError, sl.ArgumentTypeError)) as info:
        sl.color.dither(source)
    assert words in str(info.value)


@HYPOTHESIS
@given(image=hnp.arrays(np.uint8, st.tuples(st.integers(1, 9), st.integers(1, 9), st.sampled_from([1, 3]))),
       method=st.sampled_from(METHODS + ("none",)),
       levels=st.integers(2, 256), palette_size=st.integers(0, 12),
       serpentine=st.booleans())
def test_fuzz_any_image_any_setting(image, method, levels, palette_size, serpentine):
    source = image[:, :, 0] if image.shape[2] == 1 else image
    if palette_size:
        palette = np.random.default_rng(palette_size).integers(0, 256, (palette_size, 3), dtype=np.uint8)
        fb = sl.color.dither(source, method, palette=palette, serpentine=serpentine)
        assert fb.mode == "P" and fb.to_array().max() < palette_size
    else:
        fb = sl.color.dither(source, method, levels=levels, mode="L", serpentine=serpentine)
        assert set(np.unique(fb.to_array())) <= set(sl.color.gray_table(levels)[:, 0].tolist())
    assert fb.size == (image.shape[1], image.shape[0])


# -- halftone patterns -----------------------------------------------------------------

@pytest.mark.parametrize("size", [2, 4, 8])
def test_halftone_cells_hold_round_intensity_times_size2_dots(size):
    values = np.linspace(0, 1, 23)[None]                 # one row of 23 pixels
    fb = sl.color.halftone(values, size)
    assert fb.mode == "1" and fb.size == (23 * size, size)
    cells = fb.to_array().reshape(size, 23, size).sum(axis=(0, 2))
    assert cells.tolist() == np.floor(values[0] * size * size + 0.5).astype(int).tolist()
    # dots are set in the order of the Bayer matrix: a cell with k dots has exactly
    # the entries M < k set
    m = sl.color.bayer_matrix(size)
    k = int(cells[11])
    assert (fb.to_array()[:, 11 * size:12 * size] == (m < k)).all()


def test_halftone_bad_size():
    for size in (3, 1, 16, True):
        with pytest.raises(sl.ArgumentValueError, match="size"):
            sl.color.halftone(np.zeros((2, 2)), size)
