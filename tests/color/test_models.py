"""Color models: round trips, colorsys and Pillow cross-checks, the published YIQ
matrix, uint8 in/out, leading shapes and bad input."""

import colorsys

import numpy as np
import pytest
from PIL import Image

import scanline as sl
from scanline.color import models

RNG = np.random.default_rng(1978)
RGB = RNG.random((500, 3))
# corners of the RGB cube, grays and the primaries/secondaries: the hue's edge cases
SPECIAL = np.array([[r, g, b] for r in (0, 0.5, 1) for g in (0, 0.5, 1) for b in (0, 0.5, 1)])
SAMPLES = np.vstack([RGB, SPECIAL])


@pytest.mark.parametrize("ours, theirs", [
    (sl.color.rgb_to_hsv, colorsys.rgb_to_hsv),
    (sl.color.rgb_to_hls, colorsys.rgb_to_hls),
])
def test_forward_agrees_with_colorsys(ours, theirs):
    expected = np.array([theirs(*c) for c in SAMPLES])
    np.testing.assert_allclose(ours(SAMPLES), expected, atol=1e-12)


@pytest.mark.parametrize("ours, theirs, forward", [
    (sl.color.hsv_to_rgb, colorsys.hsv_to_rgb, colorsys.rgb_to_hsv),
    (sl.color.hls_to_rgb, colorsys.hls_to_rgb, colorsys.rgb_to_hls),
])
def test_inverse_agrees_with_colorsys(ours, theirs, forward):
    # random triples of the model, not only those that came from RGB
    triples = np.vstack([RNG.random((500, 3)), [forward(*c) for c in SPECIAL]])
    expected = np.array([theirs(*c) for c in triples])
    np.testing.assert_allclose(ours(triples), expected, atol=1e-12)


@pytest.mark.parametrize("forward, inverse", [
    (sl.color.rgb_to_hsv, sl.color.hsv_to_rgb),
    (sl.color.rgb_to_hls, sl.color.hls_to_rgb),
    (sl.color.rgb_to_cmy, sl.color.cmy_to_rgb),
    (sl.color.rgb_to_cmyk, sl.color.cmyk_to_rgb),
    (sl.color.rgb_to_yiq, sl.color.yiq_to_rgb),
])
def test_round_trip_floats(forward, inverse):
    np.testing.assert_allclose(inverse(forward(SAMPLES)), SAMPLES, atol=1e-12)


@pytest.mark.parametrize("forward, inverse, worst", [
    (sl.color.rgb_to_hsv, sl.color.hsv_to_rgb, 3),
    (sl.color.rgb_to_hls, sl.color.hls_to_rgb, 3),
    (sl.color.rgb_to_cmy, sl.color.cmy_to_rgb, 0),
    (sl.color.rgb_to_cmyk, sl.color.cmyk_to_rgb, 2),
])
def test_round_trip_uint8(forward, inverse, worst):
    rgb = RNG.integers(0, 256, (64, 64, 3), dtype=np.uint8)
    there = forward(rgb)
    assert there.dtype == np.uint8 and there.shape[:2] == (64, 64)
    back = inverse(there)
    assert back.dtype == np.uint8 and back.shape == rgb.shape
    # 8-bit hue and saturation lose a little: at most ``worst`` levels of 255
    assert np.abs(back.astype(int) - rgb).max() <= worst


def test_any_leading_shape():
    image = RNG.random((4, 5, 6, 3))
    hsv = sl.color.rgb_to_hsv(image)
    assert hsv.shape == image.shape
    np.testing.assert_allclose(hsv[2, 3, 4], colorsys.rgb_to_hsv(*image[2, 3, 4]))
    assert sl.color.rgb_to_cmyk(image).shape == (4, 5, 6, 4)
    assert sl.color.luminance(image).shape == (4, 5, 6)
    assert sl.color.rgb_to_hsv([0.25, 0.5, 1.0]).shape == (3,)


def test_hsv_by_hand():
    # hue as a fraction of a turn: red 0, yellow 1/6, green 1/3, ..., magenta 5/6
    hues = sl.color.rgb_to_hsv(np.array([[1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 1, 1],
                                         [0, 0, 1], [1, 0, 1]], float))[:, 0]
    np.testing.assert_allclose(hues, np.arange(6) / 6)
    assert sl.color.rgb_to_hsv([0.5, 0.5, 0.5]).tolist() == [0.0, 0.0, 0.5]
    assert sl.color.rgb_to_hsv([0.0, 0.0, 0.0]).tolist() == [0.0, 0.0, 0.0]
    assert sl.color.hsv_to_rgb([1.0, 1.0, 1.0]).tolist() == [1.0, 0.0, 0.0]  # h = 1 is red


def test_hsv_uint8_matches_pillow():
    # Pillow's "HSV" mode stores hue, saturation and value as 0..255 too
    rgb = RNG.integers(0, 256, (32, 32, 3), dtype=np.uint8)
    pillow = np.asarray(Image.fromarray(rgb).convert("HSV")).astype(int)
    ours = sl.color.rgb_to_hsv(rgb).astype(int)
    # value: exact; saturation and hue: Pillow truncates where we round, and its
    # hue is taken modulo 256 (red just below 360 degrees may wrap to 0)
    assert (ours[..., 2] == pillow[..., 2]).all()
    assert np.abs(ours[..., 1] - pillow[..., 1]).max() <= 1
    hue_gap = np.abs(ours[..., 0] - pillow[..., 0]) % 255
    assert np.minimum(hue_gap, 255 - hue_gap).max() <= 1


def test_yiq_matches_the_published_ntsc_matrix():
    # the FCC NTSC matrix (47 CFR 73.682 as usually quoted, 4 decimals) and the
    # 3-decimal inverse printed beside it
    fcc = np.array([[0.299, 0.587, 0.114],
                    [0.5959, -0.2746, -0.3213],
                    [0.2115, -0.5227, 0.3112]])
    fcc_inverse = np.array([[1.0, 0.956, 0.619],
                            [1.0, -0.272, -0.647],
                            [1.0, -1.106, 1.703]])
    # Foley, van Dam, Feiner & Hughes (2nd ed., eq. 13.31) print Q's green as -0.528
    foley = np.array([[0.299, 0.587, 0.114],
                      [0.596, -0.275, -0.321],
                      [0.212, -0.528, 0.311]])
    identity = np.eye(3)
    columns = sl.color.rgb_to_yiq(identity).T   # the images of R, G and B
    np.testing.assert_allclose(columns, fcc, atol=1e-12)
    np.testing.assert_allclose(columns, foley, atol=6e-3)
    inverse = sl.color.yiq_to_rgb(identity, clip=False).T
    np.testing.assert_allclose(inverse, fcc_inverse, atol=2e-3)
    # white has no chroma; Y is the luma of BT.601
    np.testing.assert_allclose(sl.color.rgb_to_yiq([1.0, 1.0, 1.0]), [1, 0, 0], atol=1e-12)


def test_yiq_agrees_with_colorsys():
    expected = np.array([colorsys.rgb_to_yiq(*c) for c in SAMPLES])
    # colorsys rounds the coefficients to two decimals (Y = 0.30 R + 0.59 G + 0.11 B,
    # I = 0.74 (R - Y) - 0.27 (B - Y) ...): Y differs by at most 0.004 (blue's
    # 0.11 vs 0.114), I and Q by a little more
    ours = sl.color.rgb_to_yiq(SAMPLES)
    np.testing.assert_allclose(ours[:, 0], expected[:, 0], atol=0.004 + 1e-12)
    np.testing.assert_allclose(ours, expected, atol=5e-3)
    # the inverses differ as little (colorsys clips to [0, 1] as yiq_to_rgb does)
    theirs = np.array([colorsys.yiq_to_rgb(*c) for c in ours])
    np.testing.assert_allclose(sl.color.yiq_to_rgb(ours), theirs, atol=6e-3)


def test_cmy_and_cmyk_by_hand():
    assert sl.color.rgb_to_cmy([1.0, 0.0, 0.25]).tolist() == [0.0, 1.0, 0.75]
    # full under-color removal: the gray component goes to black ink
    np.testing.assert_allclose(sl.color.rgb_to_cmyk([0.2, 0.4, 0.6]), [2 / 3, 1 / 3, 0, 0.4])
    np.testing.assert_allclose(sl.color.rgb_to_cmyk([0.2, 0.4, 0.6], ucr=0.5),
                               [0.6 / 0.8, 0.4 / 0.8, 0.2 / 0.8, 0.2])
    assert sl.color.rgb_to_cmyk([0.0, 0.0, 0.0]).tolist() == [0.0, 0.0, 0.0, 1.0]
    assert sl.color.rgb_to_cmyk([0.5, 0.5, 0.5]).tolist() == [0.0, 0.0, 0.0, 0.5]
    for ucr in (0.0, 0.3, 1.0):
        np.testing.assert_allclose(sl.color.cmyk_to_rgb(sl.color.rgb_to_cmyk(SAMPLES, ucr=ucr)),
                                   SAMPLES, atol=1e-12)


def test_cmyk_agrees_with_pillow():
    rgb = RNG.integers(0, 256, (16, 16, 3), dtype=np.uint8)
    # Pillow converts RGB -> CMYK without black ink: ucr=0
    pillow = np.asarray(Image.fromarray(rgb).convert("CMYK"))
    assert (sl.color.rgb_to_cmyk(rgb, ucr=0) == pillow).all()
    # and decodes CMYK multiplicatively, as cmyk_to_rgb does
    cmyk = RNG.integers(0, 256, (16, 16, 4), dtype=np.uint8)
    decoded = np.asarray(Image.fromarray(cmyk, "CMYK").convert("RGB")).astype(int)
    assert np.abs(sl.color.cmyk_to_rgb(cmyk).astype(int) - decoded).max() <= 1
    # so Pillow reads our full-removal CMYK back as the original colors
    ours = Image.fromarray(sl.color.rgb_to_cmyk(rgb), "CMYK").convert("RGB")
    assert np.abs(np.asarray(ours).astype(int) - rgb).max() <= 2


def test_luminance_matches_pillow_l():
    rgb = RNG.integers(0, 256, (32, 32, 3), dtype=np.uint8)
    pillow = np.asarray(Image.fromarray(rgb).convert("L")).astype(int)
    assert np.abs(sl.color.luminance(rgb).astype(int) - pillow).max() <= 1


def test_convert_through_rgb():
    hsv = sl.color.rgb_to_hsv(SAMPLES)
    np.testing.assert_allclose(sl.color.convert(hsv, "hsv", "hls"), sl.color.rgb_to_hls(SAMPLES),
                               atol=1e-12)
    np.testing.assert_allclose(sl.color.convert(SAMPLES, "rgb", "rgb"), SAMPLES)
    assert sl.color.convert([0.5, 1.0, 1.0], "hsv", "cmy").tolist() == [1.0, 0.0, 0.0]


@pytest.mark.parametrize("call, error, words", [
    (lambda: sl.color.rgb_to_hsv([0.1, 0.2]), ValueError, "3 components"),
    (lambda: sl.color.rgb_to_hsv([0.1, 0.2, 1.5]), ValueError, "[0, 1]"),
    (lambda: sl.color.rgb_to_hsv([0.1, np.nan, 0.5]), ValueError, "finite"),
    (lambda: sl.color.rgb_to_hsv(np.array([1, 2, 3], np.int64)), TypeError, "uint8"),
    (lambda: sl.color.rgb_to_hsv(["a", "b", "c"]), TypeError, "numeric"),
    (lambda: sl.color.rgb_to_hsv(5.0), ValueError, "components"),
    (lambda: sl.color.cmyk_to_rgb([0.1, 0.2, 0.3]), ValueError, "4 components"),
    (lambda: sl.color.rgb_to_cmyk([0.1, 0.2, 0.3], ucr=2), ValueError, "ucr"),
    (lambda: sl.color.yiq_to_rgb(np.zeros(3, np.uint8)), TypeError, "signed"),
    (lambda: sl.color.convert([0, 0, 0], "rgb", "lab"), ValueError, "target='lab'"),
])
def test_bad_input(call, error, words):
    with pytest.raises(error, match=None) as info:
        call()
    assert isinstance(info.value, sl.ScanlineError)
    assert words in str(info.value)


def test_module_constants_are_inverse():
    np.testing.assert_allclose(models.RGB_FROM_YIQ @ models.YIQ_FROM_RGB, np.eye(3), atol=1e-12)


# -- properties on arbitrary colors ------------------------------------------------------

from hypothesis import given  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from tests.reference import HYPOTHESIS  # noqa: E402

UNIT = st.floats(0.0, 1.0, allow_nan=False)
TRIPLE = st.tuples(UNIT, UNIT, UNIT)


@HYPOTHESIS
@given(rgb=TRIPLE, ucr=UNIT)
def test_round_trips_hold_for_any_color(rgb, ucr):
    a = np.array(rgb)
    for forward, inverse in ((sl.color.rgb_to_hsv, sl.color.hsv_to_rgb),
                             (sl.color.rgb_to_hls, sl.color.hls_to_rgb),
                             (sl.color.rgb_to_yiq, sl.color.yiq_to_rgb)):
        np.testing.assert_allclose(inverse(forward(a)), a, atol=1e-9)
    cmyk = sl.color.rgb_to_cmyk(a, ucr=ucr)
    assert ((cmyk >= 0) & (cmyk <= 1 + 1e-12)).all()
    np.testing.assert_allclose(sl.color.cmyk_to_rgb(np.clip(cmyk, 0, 1)), a, atol=1e-9)
    # HSV and HLS components stay in [0, 1], hue in [0, 1)
    for model in (sl.color.rgb_to_hsv(a), sl.color.rgb_to_hls(a)):
        assert 0 <= model[0] < 1 and 0 <= model[1] <= 1 and 0 <= model[2] <= 1


@HYPOTHESIS
@given(hsv=TRIPLE)
def test_hsv_to_rgb_agrees_with_colorsys_everywhere(hsv):
    np.testing.assert_allclose(sl.color.hsv_to_rgb(np.array(hsv)), colorsys.hsv_to_rgb(*hsv),
                               atol=1e-12)
    np.testing.assert_allclose(sl.color.hls_to_rgb(np.array(hsv)), colorsys.hls_to_rgb(*hsv),
                               atol=1e-12)
