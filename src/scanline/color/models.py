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

from typing import Any, Callable

import numpy as np
from numpy.typing import ArrayLike, NDArray

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


def _components(name: str, value: ArrayLike, count: int) -> tuple[NDArray[np.float64], bool]:
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


def _unit(name: str, value: ArrayLike, count: int) -> tuple[NDArray[np.float64], bool]:
    """Like :func:`_components`, and check that floats lie in [0, 1]."""
    a, was_uint8 = _components(name, value, count)
    if not was_uint8 and a.size and (a.min() < 0 or a.max() > 1):
        raise ArgumentValueError(
            f"{name} must hold floats in [0, 1] (or uint8 0..255); "
            f"got values from {a.min():g} to {a.max():g}")
    return a, was_uint8


def _out(a: NDArray[np.float64], as_uint8: bool) -> NDArray[Any]:
    if as_uint8:
        return np.floor(np.clip(a, 0.0, 1.0) * 255.0 + 0.5).astype(np.uint8)
    return a


# -- HSV and HLS ---------------------------------------------------------------------

def _hue(r: NDArray[np.float64], g: NDArray[np.float64], b: NDArray[np.float64],
         maxc: NDArray[np.float64], delta: NDArray[np.float64]) -> NDArray[np.float64]:
    """Hue in [0, 1) of RGB components with max ``maxc`` and range ``delta`` (> 0
    where the hue matters; elsewhere 0)."""
    safe = np.where(delta > 0, delta, 1.0)
    h = np.where(maxc == r, (g - b) / safe,
                 np.where(maxc == g, 2.0 + (b - r) / safe, 4.0 + (r - g) / safe))
    h = (h / 6.0) % 1.0    # a tiny negative h gives 1.0 here: that hue is 0
    return np.where((delta > 0) & (h < 1.0), h, 0.0)


def rgb_to_hsv(rgb: ArrayLike) -> NDArray[Any]:
    """RGB to HSV (hexcone model): hue, saturation ``(max - min) / max``, value ``max``.

    Parameters
    ----------
    rgb : array_like
        RGB colors, components on the last axis (3): floats in [0, 1] or uint8.

    Returns
    -------
    numpy.ndarray
        The HSV (h, s, v) colors, the same leading shape, 3 components; float64 for float input, uint8 for uint8 input.

    Raises
    ------
    ArgumentTypeError
        When the array is not numeric, or of an integer dtype other than uint8.
    ArgumentValueError
        When its last axis is not 3 long, or floats lie outside [0, 1].

    Examples
    --------
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


def hsv_to_rgb(hsv: ArrayLike) -> NDArray[Any]:
    """HSV to RGB, the inverse of :func:`rgb_to_hsv` (hue taken modulo 1).

    Parameters
    ----------
    hsv : array_like
        HSV colors, components on the last axis (3): floats in [0, 1] or uint8.

    Returns
    -------
    numpy.ndarray
        The RGB colors, the same leading shape, 3 components; float64 for float input, uint8 for uint8 input.

    Raises
    ------
    ArgumentTypeError
        When the array is not numeric, or of an integer dtype other than uint8.
    ArgumentValueError
        When its last axis is not 3 long, or floats lie outside [0, 1].

    Examples
    --------
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


def rgb_to_hls(rgb: ArrayLike) -> NDArray[Any]:
    """RGB to HLS (double hexcone): hue, lightness ``(max + min) / 2``, saturation.

    Parameters
    ----------
    rgb : array_like
        RGB colors, components on the last axis (3): floats in [0, 1] or uint8.

    Returns
    -------
    numpy.ndarray
        The HLS (h, l, s) colors, the same leading shape, 3 components; float64 for float input, uint8 for uint8 input.

    Raises
    ------
    ArgumentTypeError
        When the array is not numeric, or of an integer dtype other than uint8.
    ArgumentValueError
        When its last axis is not 3 long, or floats lie outside [0, 1].

    Examples
    --------
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


def hls_to_rgb(hls: ArrayLike) -> NDArray[Any]:
    """HLS to RGB, the inverse of :func:`rgb_to_hls` (hue taken modulo 1).

    Parameters
    ----------
    hls : array_like
        HLS colors, components on the last axis (3): floats in [0, 1] or uint8.

    Returns
    -------
    numpy.ndarray
        The RGB colors, the same leading shape, 3 components; float64 for float input, uint8 for uint8 input.

    Raises
    ------
    ArgumentTypeError
        When the array is not numeric, or of an integer dtype other than uint8.
    ArgumentValueError
        When its last axis is not 3 long, or floats lie outside [0, 1].

    Examples
    --------
    >>> hls_to_rgb([0.0, 0.75, 1.0]).tolist()
    [1.0, 0.5, 0.5]
    """
    a, as_uint8 = _unit("hls", hls, 3)
    h, lightness, s = a[..., 0] % 1.0, a[..., 1], a[..., 2]
    m2 = np.where(lightness <= 0.5, lightness * (1.0 + s), lightness + s - lightness * s)
    m1 = 2.0 * lightness - m2

    def channel(hue: NDArray[np.float64]) -> NDArray[np.float64]:
        hue = hue % 1.0
        return np.where(hue < 1 / 6, m1 + (m2 - m1) * hue * 6.0,
                        np.where(hue < 0.5, m2,
                                 np.where(hue < 2 / 3, m1 + (m2 - m1) * (2 / 3 - hue) * 6.0, m1)))

    out = np.stack([channel(h + 1 / 3), channel(h), channel(h - 1 / 3)], axis=-1)
    return _out(out, as_uint8)


# -- CMY and CMYK --------------------------------------------------------------------

def rgb_to_cmy(rgb: ArrayLike) -> NDArray[Any]:
    """RGB to the subtractive CMY: ``(c, m, y) = (1, 1, 1) - (r, g, b)``.

    Parameters
    ----------
    rgb : array_like
        RGB colors, components on the last axis (3): floats in [0, 1] or uint8.

    Returns
    -------
    numpy.ndarray
        The CMY colors, the same leading shape, 3 components; float64 for float input, uint8 for uint8 input.

    Raises
    ------
    ArgumentTypeError
        When the array is not numeric, or of an integer dtype other than uint8.
    ArgumentValueError
        When its last axis is not 3 long, or floats lie outside [0, 1].

    Examples
    --------
    >>> rgb_to_cmy([1.0, 0.0, 0.25]).tolist()
    [0.0, 1.0, 0.75]
    """
    a, as_uint8 = _unit("rgb", rgb, 3)
    return _out(1.0 - a, as_uint8)


def cmy_to_rgb(cmy: ArrayLike) -> NDArray[Any]:
    """CMY to RGB: ``(r, g, b) = (1, 1, 1) - (c, m, y)``.

    Parameters
    ----------
    cmy : array_like
        CMY colors, components on the last axis (3): floats in [0, 1] or uint8.

    Returns
    -------
    numpy.ndarray
        The RGB colors, the same leading shape, 3 components; float64 for float input, uint8 for uint8 input.

    Raises
    ------
    ArgumentTypeError
        When the array is not numeric, or of an integer dtype other than uint8.
    ArgumentValueError
        When its last axis is not 3 long, or floats lie outside [0, 1].

    Examples
    --------
    >>> cmy_to_rgb([0.0, 1.0, 0.75]).tolist()
    [1.0, 0.0, 0.25]
    >>> cmy_to_rgb(np.array([255, 0, 55], np.uint8)).tolist()
    [0, 255, 200]
    """
    a, as_uint8 = _unit("cmy", cmy, 3)
    return _out(1.0 - a, as_uint8)


def rgb_to_cmyk(rgb: ArrayLike, ucr: float = 1.0) -> NDArray[Any]:
    """RGB to CMYK with under-color removal.

    The gray component common to the three inks, ``min(c, m, y)``, is replaced by
    black ink: ``k = ucr * min(c, m, y)``, and each colored ink keeps what black does
    not print, ``c' = (c - k) / (1 - k)`` (0 when ``k = 1``).  ``ucr=1`` removes all
    of it (the usual "full" removal), ``ucr=0`` prints no black (Pillow's RGB ->
    CMYK).  :func:`cmyk_to_rgb` inverts this for every ``ucr``.

    Parameters
    ----------
    rgb : array_like
        RGB colors, components on the last axis (3): floats in [0, 1] or uint8.
    ucr : float
        The fraction of the gray component replaced by black, in [0, 1].

    Returns
    -------
    numpy.ndarray
        The CMYK colors, 4 components; float64 for float input, uint8 for uint8 input.

    Raises
    ------
    ArgumentTypeError
        When the array is not numeric, or of an integer dtype other than uint8.
    ArgumentValueError
        When its last axis is not 3 long, or floats lie outside [0, 1].
    ArgumentValueError
        When ``ucr`` is not a number in [0, 1].

    Examples
    --------
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


def cmyk_to_rgb(cmyk: ArrayLike) -> NDArray[Any]:
    """CMYK to RGB: ``r = (1 - c)(1 - k)`` and so on, as Pillow decodes CMYK.

    Parameters
    ----------
    cmyk : array_like
        CMYK colors, components on the last axis (4): floats in [0, 1] or uint8.

    Returns
    -------
    numpy.ndarray
        The RGB colors, the same leading shape, 3 components; float64 for float input, uint8 for uint8 input.

    Raises
    ------
    ArgumentTypeError
        When the array is not numeric, or of an integer dtype other than uint8.
    ArgumentValueError
        When its last axis is not 4 long, or floats lie outside [0, 1].

    Examples
    --------
    >>> cmyk_to_rgb([0.0, 1.0, 1.0, 0.5]).tolist()
    [0.5, 0.0, 0.0]
    """
    a, as_uint8 = _unit("cmyk", cmyk, 4)
    return _out((1.0 - a[..., :3]) * (1.0 - a[..., 3:]), as_uint8)


# -- YIQ and luminance ---------------------------------------------------------------

def rgb_to_yiq(rgb: ArrayLike) -> NDArray[np.float64]:
    """RGB to NTSC YIQ: ``yiq = YIQ_FROM_RGB @ rgb`` with the FCC matrix

    ::

        Y = 0.299  R + 0.587  G + 0.114  B
        I = 0.5959 R - 0.2746 G - 0.3213 B
        Q = 0.2115 R - 0.5227 G + 0.3112 B

    Y is in [0, 1], I in [-0.5959, 0.5959], Q in [-0.5227, 0.5227]; the result is
    always float64 (I and Q are signed).

    Parameters
    ----------
    rgb : array_like
        RGB colors, components on the last axis (3): floats in [0, 1] or uint8.

    Returns
    -------
    numpy.ndarray
        float64 (y, i, q) colors, the same leading shape.

    Raises
    ------
    ArgumentTypeError
        When the array is not numeric, or of an integer dtype other than uint8.
    ArgumentValueError
        When its last axis is not 3 long, or floats lie outside [0, 1].

    Examples
    --------
    >>> rgb_to_yiq([1.0, 0.0, 0.0]).tolist()
    [0.299, 0.5959, 0.2115]
    """
    a, _ = _unit("rgb", rgb, 3)
    yiq: NDArray[np.float64] = a @ YIQ_FROM_RGB.T
    return yiq


def yiq_to_rgb(yiq: ArrayLike, clip: bool = True) -> NDArray[np.float64]:
    """NTSC YIQ to RGB with the inverse matrix.  Not every YIQ triple is an RGB color;
    with ``clip=True`` the result is clipped to [0, 1].  Float in, float out; uint8 is
    not accepted (I and Q are signed).

    Parameters
    ----------
    yiq : array_like
        Float YIQ colors, components on the last axis (3).
    clip : bool
        Clip the result to [0, 1].

    Returns
    -------
    numpy.ndarray
        float64 RGB colors, the same leading shape.

    Raises
    ------
    ArgumentTypeError
        For uint8 or non-numeric input.
    ArgumentValueError
        When the last axis is not 3 long or a value is not finite.

    Examples
    --------
    >>> yiq_to_rgb([0.299, 0.5959, 0.2115]).round(12).tolist()     # red's YIQ
    [1.0, 0.0, 0.0]
    >>> yiq_to_rgb([0.5, 0.5, 0.0]).round(4).tolist()   # B = 0.5 - 1.106 * 0.5 < 0: clipped
    [0.978, 0.364, 0.0]
    """
    a, as_uint8 = _components("yiq", yiq, 3)
    if as_uint8:
        raise ArgumentTypeError("yiq must be floats (I and Q are signed), not uint8")
    out: NDArray[np.float64] = a @ RGB_FROM_YIQ.T
    return np.clip(out, 0.0, 1.0) if clip else out


def luminance(rgb: ArrayLike) -> NDArray[Any]:
    """The luminance Y (ITU-R BT.601 luma, the Y of YIQ) of RGB colors, shape
    ``rgb.shape[:-1]``; float in, float out; uint8 in, uint8 out (rounded).

    Parameters
    ----------
    rgb : array_like
        RGB colors, components on the last axis (3): floats in [0, 1] or uint8.

    Returns
    -------
    numpy.ndarray
        Y per color, shape ``rgb.shape[:-1]``; float64, or uint8 for uint8 input.

    Raises
    ------
    ArgumentTypeError
        When the array is not numeric, or of an integer dtype other than uint8.
    ArgumentValueError
        When its last axis is not 3 long, or floats lie outside [0, 1].

    Examples
    --------
    >>> luminance(np.array([[255, 0, 0], [255, 255, 255]], np.uint8)).tolist()
    [76, 255]
    """
    a, as_uint8 = _unit("rgb", rgb, 3)
    return _out(a @ LUMA_WEIGHTS, as_uint8)


#: ``(source, target) -> function`` for :func:`convert`.
_DIRECT: dict[tuple[str, str], Callable[[ArrayLike], NDArray[Any]]] = {
    ("rgb", "hsv"): rgb_to_hsv, ("hsv", "rgb"): hsv_to_rgb,
    ("rgb", "hls"): rgb_to_hls, ("hls", "rgb"): hls_to_rgb,
    ("rgb", "cmy"): rgb_to_cmy, ("cmy", "rgb"): cmy_to_rgb,
    ("rgb", "cmyk"): rgb_to_cmyk, ("cmyk", "rgb"): cmyk_to_rgb,
    ("rgb", "yiq"): rgb_to_yiq, ("yiq", "rgb"): yiq_to_rgb,
}
MODELS = ("rgb", "hsv", "hls", "cmy", "cmyk", "yiq")


def convert(colors: ArrayLike, source: str, target: str) -> NDArray[Any]:
    """Convert ``colors`` from model ``source`` to model ``target`` (each one of
    ``"rgb"``, ``"hsv"``, ``"hls"``, ``"cmy"``, ``"cmyk"``, ``"yiq"``), through RGB
    when neither is RGB.

    Parameters
    ----------
    colors : array_like
        Colors of model ``source``, components on the last axis.
    source, target : {"rgb", "hsv", "hls", "cmy", "cmyk", "yiq"}
        The models converted from and to.

    Returns
    -------
    numpy.ndarray
        The colors in model ``target`` (float64, or uint8 where both ends take it).

    Raises
    ------
    ArgumentValueError
        For an unknown model, or colors the source model's function refuses.
    ArgumentTypeError
        For colors that are not a numeric array.

    Examples
    --------
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
    if target == "rgb":
        return _DIRECT[(source, "rgb")](colors)
    rgb = colors if source == "rgb" else _DIRECT[(source, "rgb")](colors)
    return _DIRECT[("rgb", target)](rgb)
