"""Color models: conversions between RGB and HSV, HLS, CMY, CMYK and YIQ.

Every function works on a numpy array (or anything ``numpy.asarray`` takes) whose last
axis holds the components, with any leading shape: one color ``(3,)``, a list of
colors ``(n, 3)``, an image ``(h, w, 3)``.

Components are floats in [0, 1] or uint8 in 0..255:

* float input gives float64 output;
* uint8 input is read as ``value / 255`` and gives uint8 output (each component
  ``round(255 * c)``; a hue is a fraction of a turn, so 255 is almost 360 degrees, as
  in Pillow's ``"HSV"`` mode), except :func:`rgb_to_yiq`, whose I and Q are signed
  and always come back as float64.

Hues ``h`` are fractions of a turn in [0, 1): red 0, yellow 1/6, green 1/3, cyan 1/2,
blue 2/3, magenta 5/6.  Component orders follow Python's :mod:`colorsys`:
``(h, s, v)`` and ``(h, l, s)``.

Notes
-----
The notes (chapter 1, Q.5, the color CRT) describe additive RGB color: the red, green
and blue phosphors of a shadow-mask tube, yellow from red and green, white from all
three at equal intensity.  The other models are those of the standard texts: HSV and
HLS (Smith 1978), the subtractive CMY(K) of printers, and YIQ, the NTSC broadcast
encoding.

References
----------
.. [1] A. R. Smith, "Color gamut transform pairs", Computer Graphics (SIGGRAPH '78)
   12(3), 12-19, 1978.
.. [2] J. D. Foley, A. van Dam, S. K. Feiner, J. F. Hughes, *Computer Graphics:
   Principles and Practice*, 2nd ed., section 13.3, 1990.
.. [3] Federal Communications Commission, NTSC color television standard, 1953
   (the YIQ matrix; 47 CFR 73.682).
"""

import numpy as np

from ..errors import ArgumentTypeError, ArgumentValueError

#: RGB -> YIQ, the FCC NTSC matrix (column vectors: ``yiq = YIQ_FROM_RGB @ rgb``).
YIQ_FROM_RGB = np.array([
    [0.299, 0.587, 0.114],
    [0.5959, -0.2746, -0.3213],
    [0.2115, -0.5227, 0.3112],
])
#: YIQ -> RGB, the exact inverse of :data:`YIQ_FROM_RGB` (so round trips are exact).
RGB_FROM_YIQ = np.linalg.inv(YIQ_FROM_RGB)

#: ITU-R BT.601 luma weights of R, G and B (the Y row of YIQ).
LUMA_WEIGHTS = YIQ_FROM_RGB[0]


def _components(name, value, count):
    """``(float64 array in [0, 1] with last axis count, was_uint8)``."""
    a = np.asarray(value)
    if a.dtype == bool or a.dtype.kind not in "uif":
        raise ArgumentTypeError(
            f"{name} must be a numeric array (floats in [0, 1] or uint8), got dtype {a.dtype}")
    if a.ndim == 0 or a.shape[-1] != count:
        raise ArgumentValueError(
            f"{name} must have {count} components on its last axis, got shape {a.shape}")
    if a.dtype == np.uint8:
        return a / 255.0, True
    if a.dtype.kind in "iu":
        raise ArgumentTypeError(
            f"{name} has integer dtype {a.dtype}; use uint8 (0..255) or floats in [0, 1]")
    a = a.astype(np.float64)
    if not np.isfinite(a).all():
        raise ArgumentValueError(f"{name} must hold finite numbers")
    return a, False


def _unit(name, value, count):
    """Like :func:`_components`, and check that floats lie in [0, 1]."""
    a, was_uint8 = _components(name, value, count)
    if not was_uint8 and a.size and (a.min() < 0 or a.max() > 1):
        raise ArgumentValueError(
            f"{name} must hold floats in [0, 1] (or uint8 0..255); "
            f"got values from {a.min():g} to {a.max():g}")
    return a, was_uint8


def _out(a, as_uint8):
    if as_uint8:
        return np.floor(np.clip(a, 0.0, 1.0) * 255.0 + 0.5).astype(np.uint8)
    return a


# -- HSV and HLS ---------------------------------------------------------------------

def _hue(r, g, b, maxc, delta):
    """Hue in [0, 1) of RGB components with max ``maxc`` and range ``delta`` (> 0
    where the hue matters; elsewhere 0)."""
    safe = np.where(delta > 0, delta, 1.0)
    h = np.where(maxc == r, (g - b) / safe,
                 np.where(maxc == g, 2.0 + (b - r) / safe, 4.0 + (r - g) / safe))
    h = (h / 6.0) % 1.0    # a tiny negative h gives 1.0 here: that hue is 0
    return np.where((delta > 0) & (h < 1.0), h, 0.0)


def rgb_to_hsv(rgb):
    """RGB to HSV (hexcone model): hue, saturation ``(max - min) / max``, value ``max``.

    >>> rgb_to_hsv([1.0, 0.5, 0.0]).round(4).tolist()
    [0.0833, 1.0, 1.0]
    >>> rgb_to_hsv(np.array([255, 0, 255], np.uint8)).tolist()
    [213, 255, 255]
    """
    a, as_uint8 = _unit("rgb", rgb, 3)
    r, g, b = a[..., 0], a[..., 1], a[..., 2]
    maxc, minc = a.max(axis=-1), a.min(axis=-1)
    delta = maxc - minc
    s = np.where(maxc > 0, delta / np.where(maxc > 0, maxc, 1.0), 0.0)
    return _out(np.stack([_hue(r, g, b, maxc, delta), s, maxc], axis=-1), as_uint8)


def hsv_to_rgb(hsv):
    """HSV to RGB, the inverse of :func:`rgb_to_hsv` (hue taken modulo 1).

    >>> hsv_to_rgb([2 / 3, 1.0, 0.5]).tolist()
    [0.0, 0.0, 0.5]
    """
    a, as_uint8 = _unit("hsv", hsv, 3)
    h, s, v = a[..., 0] % 1.0, a[..., 1], a[..., 2]
    sector = np.floor(h * 6.0)
    f = h * 6.0 - sector
    p, q, t = v * (1 - s), v * (1 - s * f), v * (1 - s * (1 - f))
    i = sector.astype(np.int64) % 6
    choices = [(v, t, p), (q, v, p), (p, v, t), (p, q, v), (t, p, v), (v, p, q)]
    out = np.stack([np.choose(i, [c[k] for c in choices]) for k in range(3)], axis=-1)
    return _out(out, as_uint8)


def rgb_to_hls(rgb):
    """RGB to HLS (double hexcone): hue, lightness ``(max + min) / 2``, saturation.

    >>> rgb_to_hls([0.0, 0.5, 0.0]).round(4).tolist()
    [0.3333, 0.25, 1.0]
    """
    a, as_uint8 = _unit("rgb", rgb, 3)
    r, g, b = a[..., 0], a[..., 1], a[..., 2]
    maxc, minc = a.max(axis=-1), a.min(axis=-1)
    delta = maxc - minc
    lightness = (maxc + minc) / 2.0
    denominator = np.where(lightness <= 0.5, maxc + minc, 2.0 - maxc - minc)
    s = np.where(delta > 0, delta / np.where(delta > 0, denominator, 1.0), 0.0)
    return _out(np.stack([_hue(r, g, b, maxc, delta), lightness, s], axis=-1), as_uint8)


def hls_to_rgb(hls):
    """HLS to RGB, the inverse of :func:`rgb_to_hls` (hue taken modulo 1).

    >>> hls_to_rgb([0.0, 0.75, 1.0]).tolist()
    [1.0, 0.5, 0.5]
    """
    a, as_uint8 = _unit("hls", hls, 3)
    h, lightness, s = a[..., 0] % 1.0, a[..., 1], a[..., 2]
    m2 = np.where(lightness <= 0.5, lightness * (1.0 + s), lightness + s - lightness * s)
    m1 = 2.0 * lightness - m2

    def channel(hue):
        hue = hue % 1.0
        return np.where(hue < 1 / 6, m1 + (m2 - m1) * hue * 6.0,
                        np.where(hue < 0.5, m2,
                                 np.where(hue < 2 / 3, m1 + (m2 - m1) * (2 / 3 - hue) * 6.0, m1)))

    out = np.stack([channel(h + 1 / 3), channel(h), channel(h - 1 / 3)], axis=-1)
    return _out(out, as_uint8)


# -- CMY and CMYK --------------------------------------------------------------------

def rgb_to_cmy(rgb):
    """RGB to the subtractive CMY: ``(c, m, y) = (1, 1, 1) - (r, g, b)``.

    >>> rgb_to_cmy([1.0, 0.0, 0.25]).tolist()
    [0.0, 1.0, 0.75]
    """
    a, as_uint8 = _unit("rgb", rgb, 3)
    return _out(1.0 - a, as_uint8)


def cmy_to_rgb(cmy):
    """CMY to RGB: ``(r, g, b) = (1, 1, 1) - (c, m, y)``."""
    a, as_uint8 = _unit("cmy", cmy, 3)
    return _out(1.0 - a, as_uint8)


def rgb_to_cmyk(rgb, ucr=1.0):
    """RGB to CMYK with under-color removal.

    The gray component common to the three inks, ``min(c, m, y)``, is replaced by
    black ink: ``k = ucr * min(c, m, y)``, and each colored ink keeps what black does
    not print, ``c' = (c - k) / (1 - k)`` (0 when ``k = 1``).  ``ucr=1`` removes all
    of it (the usual "full" removal), ``ucr=0`` prints no black (Pillow's RGB ->
    CMYK).  :func:`cmyk_to_rgb` inverts this for every ``ucr``.

    >>> rgb_to_cmyk([0.2, 0.4, 0.6]).round(4).tolist()
    [0.6667, 0.3333, 0.0, 0.4]
    >>> rgb_to_cmyk([0.2, 0.4, 0.6], ucr=0).round(4).tolist()
    [0.8, 0.6, 0.4, 0.0]
    """
    a, as_uint8 = _unit("rgb", rgb, 3)
    if isinstance(ucr, bool) or not isinstance(ucr, (int, float)) or not 0 <= ucr <= 1:
        raise ArgumentValueError(f"ucr={ucr!r} must be a number in [0, 1] (1 = full removal)")
    cmy = 1.0 - a
    k = ucr * cmy.min(axis=-1, keepdims=True)
    rest = np.where(k < 1, 1.0 - k, 1.0)
    inks = np.where(k < 1, (cmy - k) / rest, 0.0)
    return _out(np.concatenate([inks, k], axis=-1), as_uint8)


def cmyk_to_rgb(cmyk):
    """CMYK to RGB: ``r = (1 - c)(1 - k)`` and so on, as Pillow decodes CMYK.

    >>> cmyk_to_rgb([0.0, 1.0, 1.0, 0.5]).tolist()
    [0.5, 0.0, 0.0]
    """
    a, as_uint8 = _unit("cmyk", cmyk, 4)
    return _out((1.0 - a[..., :3]) * (1.0 - a[..., 3:]), as_uint8)


# -- YIQ and luminance ---------------------------------------------------------------

def rgb_to_yiq(rgb):
    """RGB to NTSC YIQ: ``yiq = YIQ_FROM_RGB @ rgb`` with the FCC matrix

    ::

        Y = 0.299  R + 0.587  G + 0.114  B
        I = 0.5959 R - 0.2746 G - 0.3213 B
        Q = 0.2115 R - 0.5227 G + 0.3112 B

    Y is in [0, 1], I in [-0.5959, 0.5959], Q in [-0.5227, 0.5227]; the result is
    always float64 (I and Q are signed).

    >>> rgb_to_yiq([1.0, 0.0, 0.0]).tolist()
    [0.299, 0.5959, 0.2115]
    """
    a, _ = _unit("rgb", rgb, 3)
    return a @ YIQ_FROM_RGB.T


def yiq_to_rgb(yiq, clip=True):
    """NTSC YIQ to RGB with the inverse matrix.  Not every YIQ triple is an RGB color;
    with ``clip=True`` the result is clipped to [0, 1].  Float in, float out; uint8 is
    not accepted (I and Q are signed)."""
    a, as_uint8 = _components("yiq", yiq, 3)
    if as_uint8:
        raise ArgumentTypeError("yiq must be floats (I and Q are signed), not uint8")
    out = a @ RGB_FROM_YIQ.T
    return np.clip(out, 0.0, 1.0) if clip else out


def luminance(rgb):
    """The luminance Y (ITU-R BT.601 luma, the Y of YIQ) of RGB colors, shape
    ``rgb.shape[:-1]``; float in, float out; uint8 in, uint8 out (rounded).

    >>> luminance(np.array([[255, 0, 0], [255, 255, 255]], np.uint8)).tolist()
    [76, 255]
    """
    a, as_uint8 = _unit("rgb", rgb, 3)
    return _out(a @ LUMA_WEIGHTS, as_uint8)


#: ``(source, target) -> function`` for :func:`convert`.
_DIRECT = {
    ("rgb", "hsv"): rgb_to_hsv, ("hsv", "rgb"): hsv_to_rgb,
    ("rgb", "hls"): rgb_to_hls, ("hls", "rgb"): hls_to_rgb,
    ("rgb", "cmy"): rgb_to_cmy, ("cmy", "rgb"): cmy_to_rgb,
    ("rgb", "cmyk"): rgb_to_cmyk, ("cmyk", "rgb"): cmyk_to_rgb,
    ("rgb", "yiq"): rgb_to_yiq, ("yiq", "rgb"): yiq_to_rgb,
}
MODELS = ("rgb", "hsv", "hls", "cmy", "cmyk", "yiq")


def convert(colors, source, target):
    """Convert ``colors`` from model ``source`` to model ``target`` (each one of
    ``"rgb"``, ``"hsv"``, ``"hls"``, ``"cmy"``, ``"cmyk"``, ``"yiq"``), through RGB
    when neither is RGB.

    >>> convert([0.5, 1.0, 1.0], "hsv", "cmy").tolist()
    [1.0, 0.0, 0.0]
    """
    for name, model in (("source", source), ("target", target)):
        if model not in MODELS:
            listed = ", ".join(repr(m) for m in MODELS)
            raise ArgumentValueError(f"{name}={model!r} is not a color model; use one of {listed}")
    if source == target:
        a, as_uint8 = _components("colors", colors, 4 if source == "cmyk" else 3)
        return _out(a, as_uint8) if source != "yiq" else a
    rgb = colors if source == "rgb" else _DIRECT[(source, "rgb")](colors)
    return rgb if target == "rgb" else _DIRECT[("rgb", target)](rgb)
