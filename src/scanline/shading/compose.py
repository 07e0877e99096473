"""Stage three of the 3-D pipeline: what a visible-surface method found, colored and
stored -- the one way the renderer colors pixels.

:func:`shade` takes a :class:`~scanline.visible.visibility.Layer` (the triangle seen
at each pixel) and colors it: compiled (:mod:`scanline.shading.buffer`) where the
kernel covers the options, else in numpy (:func:`~scanline.shading.intensities`, with
depth cueing and shadow maps), and for ``model="none"`` by the surfaces' own pixel
values, in any frame-buffer mode.  :func:`composite` resolves layers of fragments
front to back over what the frame buffer holds (Hearn & Baker 14-5, transparency: I
= (1 - k_t) I_refl + k_t I_trans, applied layer after layer; 13-4, the A-buffer's
coverage), averaging the samples of each pixel.
"""

from typing import TYPE_CHECKING, Any, Iterable, Optional, Tuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..errors import ArgumentValueError
from ..lighting.model import depth_cue as cue_blend
from .buffer import drawable, shade_buffer, shade_textured, texturable
from .models import decode, encode, intensities
from .options import ShadingOptions
from .surface import any_maps, check_maps, texture_coordinates

if TYPE_CHECKING:
    from ..framebuffer import FrameBuffer
    from ..screen.scene import ScreenScene
    from ..visible.visibility import Layer


def triangle_functions(scene: "ScreenScene", triangles: NDArray[np.signedinteger[Any]],
                       perspective: bool = True) -> NDArray[np.float64]:
    """Per device triangle of ``triangles`` (U,): the screen-space linear functions
    (value at the origin, d/dx, d/dy) of 1/w, lambda_1/w and lambda_2/w, (U, 3, 3);
    NaN for a triangle with no area on the screen.  ``perspective=False``: of 1,
    lambda_1 and lambda_2 (affine interpolation in screen space)."""
    tri = scene.triangles[triangles]
    x, y = tri[:, :, 0], tri[:, :, 1]
    q = scene.inv_w[triangles] if perspective else np.ones(x.shape)
    b = scene.bary[triangles]
    vals = np.stack([q, b[:, :, 0] * q, b[:, :, 1] * q], 1)          # (U, fn, vertex)
    m = np.stack([np.ones_like(x), x, y], axis=2)                     # (U, vertex, c a b)
    out = np.full((len(triangles), 3, 3), np.nan)
    ok = np.abs(np.linalg.det(m)) > 1e-12 * (np.abs(m).max(axis=(1, 2), initial=0) ** 2 + 1.0)
    if ok.any():
        out[ok] = np.linalg.solve(m[ok], vals[ok].transpose(0, 2, 1)).transpose(0, 2, 1)
    return out


def surface_coordinates(scene: "ScreenScene", triangles: NDArray[np.signedinteger[Any]],
                        xs: NDArray[np.float64], ys: NDArray[np.float64],
                        perspective: bool = True
                        ) -> Tuple[NDArray[np.float64], NDArray[np.float64]]:
    """The barycentric coordinates (lambda_0, lambda_1, lambda_2) (M, 3) in their
    facets of the device points (``xs``, ``ys``) seen on ``triangles`` (M,), and their
    screen derivatives (M, 3, 2) (d/dx, d/dy): perspective-correct, lambda = (lambda /
    w) / (1 / w) with both linear in screen space (d lambda = (d(lambda/w) - lambda
    d(1/w)) / (1/w)), or with ``perspective=False`` affine in screen space."""
    u, inverse = np.unique(triangles, return_inverse=True)
    g = triangle_functions(scene, u, perspective)[inverse.reshape(-1)]
    vals = g[:, :, 0] + xs[:, None] * g[:, :, 1] + ys[:, None] * g[:, :, 2]
    lam = np.empty((len(triangles), 3))
    lam[:, 1:] = vals[:, 1:] / vals[:, :1]
    lam[:, 0] = 1.0 - lam[:, 1] - lam[:, 2]
    d = np.empty((len(triangles), 3, 2))
    d[:, 1:] = (g[:, 1:, 1:] - lam[:, 1:, None] * g[:, :1, 1:]) / vals[:, :1, None]
    d[:, 0] = -d[:, 1] - d[:, 2]
    return lam, d


def barycentrics(scene: "ScreenScene", triangles: NDArray[np.int64], xs: NDArray[np.float64],
                 ys: NDArray[np.float64]) -> NDArray[np.float64]:
    """The perspective-correct barycentric coordinates (lambda_1, lambda_2), (M, 2),
    in their facets of the device points (``xs``, ``ys``) seen on ``triangles`` (M,).

    Parameters
    ----------
    scene : ScreenScene
        The prepared scene.
    triangles : ndarray of int (M,)
        Device triangles of the scene (a visible-surface method's ``ids``).
    xs, ys : ndarray (M,)
        Device points.

    Returns
    -------
    ndarray (M, 2)
        (lambda_1, lambda_2); lambda_0 = 1 - lambda_1 - lambda_2.

    Notes
    -----
    lambda / w and 1 / w are linear in screen space; their ratio is the
    perspective-correct coordinate (Hearn & Baker 14-5, 14-9).

    Examples
    --------
    The coordinates found at pixel (2, 1) weight the triangle's device vertices back
    to that pixel:

    >>> import numpy as np, scanline as sl
    >>> from scanline.screen import prepare
    >>> from scanline.shading import ShadingOptions
    >>> from scanline.visible.zbuffer import nearest
    >>> cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0),
    ...                 projection=sl.projection.orthographic(window=(-2, -2, 2, 2)))
    >>> scene = prepare(sl.mesh.cube(2), cam, 4, 4)
    >>> layer = nearest(scene)                  # the z-buffer's triangle at each pixel
    >>> t = layer.ids[1, 2]                     # rows bottom-up: y = 1, x = 2
    >>> l1, l2 = sl.shading.barycentrics(scene, np.array([t]), np.array([2.0]), np.array([1.0]))[0]
    >>> v0, v1, v2 = scene.triangles[t][:, :2]
    >>> ((1 - l1 - l2) * v0 + l1 * v1 + l2 * v2).round(12).tolist()
    [2.0, 1.0]
    """
    lam: NDArray[np.float64] = surface_coordinates(scene, triangles, xs, ys)[0][:, 1:]
    return lam


def background_linear(fb: "FrameBuffer", gamma: float) -> NDArray[np.float64]:
    """The frame buffer's background as linear RGB."""
    value = np.asarray(fb._background, np.float64)
    c = np.repeat(value[:1], 3) if len(value) == 1 else value[:3]
    return decode(c / 255.0, gamma)


def _cue(scene: "ScreenScene", linear: NDArray[np.float64], depth: NDArray[np.float64],
         options: ShadingOptions,
         background: NDArray[np.float64]) -> NDArray[np.float64]:
    """Depth cueing of linear colors at device depths ``depth`` (M,), between the
    nearest and the farthest distance of the scene's device triangles (Hearn & Baker
    9-1: d_min and d_max of the scene), the same for every pixel, layer and band."""
    if options.depth_cue is None or not len(depth):
        return linear
    near, far = _depth_range(scene)
    return cue_blend(linear, scene.camera.linear_depth(depth), near, far, options.depth_cue,
                     background)


def _depth_range(scene: "ScreenScene") -> Tuple[float, float]:
    """The nearest and farthest distances of the scene's device triangles' vertices."""
    d = scene.camera.linear_depth(scene.triangles[..., 2].reshape(-1))
    d = d[np.isfinite(d)]
    return (float(d.min()), float(d.max())) if len(d) else (0.0, 0.0)


def _points(scene: "ScreenScene", ids: NDArray[np.signedinteger[Any]], depth: NDArray[np.float64],
            ys: NDArray[np.int64], xs: NDArray[np.int64], px: NDArray[np.float64],
            py: NDArray[np.float64], options: ShadingOptions,
            background: NDArray[np.float64]) -> Tuple[NDArray[np.int64], NDArray[np.float64]]:
    """Linear colors of the samples (``ys``, ``xs``) of a layer, at device points
    (``px``, ``py``): ``(facets, colors)``."""
    t = ids[ys, xs]
    facets = scene.facet[t]
    bary = barycentrics(scene, t, px, py) if options.model not in ("flat", "none") else \
        np.zeros((len(t), 2))
    at: Optional[Tuple[NDArray[np.float64], NDArray[np.float64]]] = None
    if any_maps(scene):
        check_maps(scene, options)
        if scene.uv is not None:
            lam, dlam = surface_coordinates(scene, t, px, py,
                                            options.texture_mapping == "perspective")
            at = texture_coordinates(scene, facets, lam, dlam)
    linear = intensities(scene, facets, bary, options, at)
    return facets, _cue(scene, linear, depth[ys, xs], options, background)


def store(fb: "FrameBuffer", ys: NDArray[np.int64], xs: NDArray[np.int64],
          linear: NDArray[np.float64], gamma: float) -> None:
    """Write linear RGB (M, 3) at pixels (xs, ys), encoded with ``gamma``."""
    buf = fb._raster()[0]
    if fb.mode == "L":
        buf[ys, xs, 0] = encode((linear * np.array([0.299, 0.587, 0.114])).sum(axis=1), gamma)
    else:
        buf[ys, xs, :3] = encode(linear, gamma)
        if fb.mode == "RGBA":
            buf[ys, xs, 3] = 255


def stored_linear(fb: "FrameBuffer", ys: NDArray[np.int64], xs: NDArray[np.int64],
                  gamma: float) -> NDArray[np.float64]:
    """The frame buffer's pixels (xs, ys) as linear RGB (M, 3)."""
    stored = fb._raster()[0][ys, xs].astype(np.float64) / 255.0
    if stored.shape[1] == 1:
        stored = np.repeat(stored, 3, axis=1)
    return decode(stored[:, :3], gamma)


def _paint(fb: "FrameBuffer", ids: NDArray[np.int32], values: ArrayLike,
           facets: Optional[NDArray[np.int64]] = None) -> None:
    """:func:`paint` without its checks (``ids`` int32, C order); ``facets``: each
    number's replacement in ``ids``."""
    from .._kernels._threads import call_in_bands
    from .._kernels.variants import layout
    from .._kernels.visible import color_ids

    buf, packed = fb._raster()
    call_in_bands(color_ids, fb.width * fb.height, buf, layout(packed), fb.width, fb.height,
                  np.ascontiguousarray(values, np.uint8), ids,
                  np.zeros(0, np.int64) if facets is None else facets)


def paint(fb: "FrameBuffer", ids: ArrayLike, values: ArrayLike) -> None:
    """Each pixel of ``fb`` whose number in ``ids`` (H, W integers, rows bottom-up as
    the frame buffer stores them; e.g. the piece numbers of
    :func:`scanline.visible.painted_depth_sort`) is p >= 0 takes the pixel value
    ``values[p]`` (rows of the frame buffer's channels, integers 0-255: ``fb.pixel(color)``
    gives one); the others keep theirs.  Any mode, on every core in bands.

    Parameters
    ----------
    fb : FrameBuffer
        Painted in place.
    ids : array_like of int (H, W)
        A number per pixel (-1: keep), rows bottom-up.
    values : array_like of int (n, channels)
        The pixel value of each number.

    Raises
    ------
    ArgumentValueError
        Values not (n, channels) integers 0..255, ids not the frame buffer's shape or
        not integers, or a number without a row.

    Examples
    --------
    >>> import numpy as np, scanline as sl
    >>> fb = sl.FrameBuffer(3, 2, mode="L")
    >>> ids = np.array([[0, -1, 1], [-1, -1, -1]])           # row y = 0 first
    >>> sl.shading.paint(fb, ids, [[200], [50]])
    >>> fb.to_array().tolist()                               # top row first
    [[0, 0, 0], [200, 0, 50]]
    """
    from .. import _validate as v
    from ..draw._common import target

    target(fb)
    channels = fb._raster()[0].shape[2]
    a = np.asarray(values)
    if (a.ndim != 2 or a.shape[1] != channels or not np.issubdtype(a.dtype, np.integer)
            or (a.size and (a.min() < 0 or a.max() > 255))):
        raise ArgumentValueError(
            f"values must hold one pixel value per number, integers 0-255 of shape (n, "
            f"{channels}) for a mode {fb.mode!r} frame buffer (fb.pixel(color) gives a row), "
            f"got dtype {a.dtype}, shape {a.shape}")
    n = np.asarray(ids)
    if n.shape != (fb.height, fb.width):
        raise ArgumentValueError(f"ids must have the frame buffer's shape ({fb.height}, "
                                 f"{fb.width}) (rows bottom-up), got {v._show(n.shape)}")
    if not np.issubdtype(n.dtype, np.integer):
        raise ArgumentValueError(f"ids must be integers, got dtype {n.dtype}")
    top = int(n.max()) if n.size else -1
    if top >= len(a):
        raise ArgumentValueError(f"values holds {len(a)} rows, but ids name number {top}: "
                                 "give one row per number")
    _paint(fb, np.ascontiguousarray(n, np.int32), np.ascontiguousarray(a, np.uint8))


def face_values(fb: "FrameBuffer", scene: "ScreenScene") -> NDArray[np.uint8]:
    """The pixel value of each face's color in ``fb``'s mode, (F, channels) uint8."""
    channels = fb._raster()[0].shape[2]
    rgb = np.rint(scene.face_colors * 255.0).astype(np.uint8)
    if not len(rgb):
        return np.zeros((0, channels), np.uint8)
    unique, inverse = np.unique(rgb, axis=0, return_inverse=True)
    values = np.array([fb.pixel((int(r), int(g), int(b))) for r, g, b in unique], np.uint8)
    return values.reshape(len(unique), channels)[inverse.reshape(-1)]


def facets_of(scene: "ScreenScene", ids: NDArray[np.signedinteger[Any]]) -> NDArray[np.int32]:
    """The facet of each entry of a buffer of device triangles ``ids`` (-1 stays -1)."""
    if not len(scene.facet):
        return np.full(ids.shape, -1, np.int32)
    return np.where(ids >= 0, scene.facet[np.maximum(ids, 0)], -1).astype(np.int32)


def shade(fb: "FrameBuffer", scene: "ScreenScene", layer: "Layer",
          options: ShadingOptions) -> NDArray[np.int32]:
    """Color the pixels of ``layer`` (a :class:`~scanline.visible.visibility.Layer`)
    into ``fb`` with ``options`` (:class:`~scanline.shading.ShadingOptions`); the
    others keep their values.  Returns the facet seen at each pixel (H, W; -1 none):
    ``layer.ids`` itself, overwritten, where a compiled path shades.

    Parameters
    ----------
    fb : FrameBuffer
        Drawn into.
    scene : ScreenScene
        The prepared scene.
    layer : Layer
        The device triangle and depth at each pixel.
    options : ShadingOptions
        How to color.

    Returns
    -------
    ndarray of int32 (H, W)
        The facet at each pixel, rows bottom-up.

    Raises
    ------
    ArgumentValueError
        A lit model into a mode other than L, RGB, RGBA.

    Examples
    --------
    Flat shading under ambient light 1: ka Ia = 0.2, stored round(255 x 0.2) = 51.

    >>> import numpy as np, scanline as sl
    >>> from scanline.screen import prepare
    >>> from scanline.shading import ShadingOptions
    >>> from scanline.visible.zbuffer import nearest
    >>> cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0),
    ...                 projection=sl.projection.orthographic(window=(-2, -2, 2, 2)))
    >>> scene = prepare(sl.mesh.cube(2), cam, 4, 4)
    >>> layer = nearest(scene)                  # the z-buffer's triangle at each pixel
    >>> ambient = ShadingOptions(model="flat", lights=sl.lighting.AmbientLight(1.0), gamma=1)
    >>> fb = sl.FrameBuffer(4, 4, mode="L")
    >>> facets = sl.shading.shade(fb, scene, layer, ambient)
    >>> fb.to_array().tolist()
    [[0, 0, 0, 0], [0, 51, 51, 0], [0, 51, 51, 0], [0, 0, 0, 0]]
    """
    ids = layer.ids
    maps = any_maps(scene)
    if options.model == "none" and options.depth_cue is None and not maps:
        values = face_values(fb, scene)[scene.facet_face[scene.facet]]
        _paint(fb, ids, values, np.ascontiguousarray(scene.facet, np.int64))
        return ids
    if fb.mode not in ("L", "RGB", "RGBA"):
        raise ArgumentValueError(f"shading={options.model!r} draws into modes L, RGB and "
                                 f"RGBA; the frame buffer is mode {fb.mode!r} (use "
                                 f"shading='none' for face colors)")
    if drawable(fb, options) and not maps:
        shade_buffer(scene, fb, ids, options)
        return ids
    if maps:
        check_maps(scene, options)
        if texturable(fb, scene, options):
            shade_textured(scene, fb, ids, options)
            return ids
    ys, xs = np.nonzero(ids >= 0)
    background = background_linear(fb, options.gamma)
    facets, linear = _points(scene, ids, layer.depth, ys, xs, xs.astype(np.float64),
                             ys.astype(np.float64), options, background)
    store(fb, ys, xs, linear, options.gamma)
    out = np.full(ids.shape, -1, np.int32)
    out[ys, xs] = facets
    return out


def composite(fb: "FrameBuffer", scene: "ScreenScene",
              bands: Iterable[Tuple[int, int, Iterable["Layer"]]], samples: int,
              options: ShadingOptions) -> Tuple[NDArray[np.int32], NDArray[np.float64]]:
    """Resolve layers of fragments over the frame buffer's pixels, band of rows after
    band of rows: ``bands`` yields ``(y0, rows, layers)``, ``layers`` the Layers of
    the band's rows at ``samples`` x ``samples`` points per pixel, front to back.  At
    each sample, I = sum_k T_k (1 - k_t,k) I_k + T I_behind, T_k the product of the
    transparencies k_t in front of fragment k and I_behind the pixel's present color;
    each pixel averages its samples, and is written where any sample met a surface.
    Returns the facet and the depth of the first layer at each pixel's central
    sample, (H, W) each.

    Parameters
    ----------
    fb : FrameBuffer
        Blended into (modes L, RGB, RGBA).
    scene : ScreenScene
        The prepared scene.
    bands : iterable of (y0, rows, layers)
        The layers of fragments of each band of rows, front to back.
    samples : int
        Samples per pixel side.
    options : ShadingOptions
        How to color.

    Returns
    -------
    facets : ndarray of int32 (H, W)
        The first layer's facet at each pixel (-1: none).
    depth : ndarray (H, W)
        Its depth (inf: none).

    Raises
    ------
    ArgumentValueError
        A mode other than L, RGB, RGBA.

    Notes
    -----
    Hearn & Baker 14-5 (transparency) and 13-4 (the A-buffer's coverage).

    Examples
    --------
    One opaque layer, one sample a pixel: the same pixels as :func:`shade`.

    >>> import numpy as np, scanline as sl
    >>> from scanline.screen import prepare
    >>> from scanline.shading import ShadingOptions
    >>> from scanline.visible.zbuffer import nearest
    >>> cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0),
    ...                 projection=sl.projection.orthographic(window=(-2, -2, 2, 2)))
    >>> scene = prepare(sl.mesh.cube(2), cam, 4, 4)
    >>> layer = nearest(scene)                  # the z-buffer's triangle at each pixel
    >>> ambient = ShadingOptions(model="flat", lights=sl.lighting.AmbientLight(1.0), gamma=1)
    >>> fb = sl.FrameBuffer(4, 4, mode="L")
    >>> facets, depth = sl.shading.composite(fb, scene, [(0, 4, [layer])], 1, ambient)
    >>> fb.to_array().tolist(), int((facets >= 0).sum())
    ([[0, 0, 0, 0], [0, 51, 51, 0], [0, 51, 51, 0], [0, 0, 0, 0]], 4)
    """
    if fb.mode not in ("L", "RGB", "RGBA"):
        raise ArgumentValueError(f"layers of fragments are blended in modes L, RGB and RGBA; "
                                 f"the frame buffer is mode {fb.mode!r}")
    s = samples
    h, w = scene.height, scene.width
    gamma = options.gamma
    background = background_linear(fb, gamma)
    kt = np.array([m.transparency for m in scene.materials], np.float64)[scene.facet_mesh] \
        if scene.facet_count else np.zeros(0)
    facets = np.full((h, w), -1, np.int32)
    depth = np.full((h, w), np.inf)
    c = s // 2
    for y0, rows, layers in bands:
        color = np.zeros((rows * s, w * s, 3))
        through = np.ones((rows * s, w * s))
        first = None
        for layer in layers:
            if first is None:
                first = layer
            ys, xs = np.nonzero(layer.ids >= 0)
            # sample (i, j) of pixel (x, y) lies at device (x - 1/2 + (i + 1/2) / s, ...)
            seen, linear = _points(scene, layer.ids, layer.depth, ys, xs,
                                   (xs - (s - 1) / 2.0) / s, y0 + (ys - (s - 1) / 2.0) / s,
                                   options, background)
            t = kt[seen]
            color[ys, xs] += (through[ys, xs] * (1 - t))[:, None] * linear
            through[ys, xs] *= t
        if first is None:
            continue
        covered = (first.ids >= 0).reshape(rows, s, w, s).any(axis=(1, 3))
        py, px = np.nonzero(covered)
        behind = stored_linear(fb, py + y0, px, gamma)
        pixel = color.reshape(rows, s, w, s, 3)[py, :, px] + \
            through.reshape(rows, s, w, s)[py, :, px][..., None] * behind[:, None, None, :]
        store(fb, py + y0, px, pixel.mean(axis=(1, 2)), gamma)
        facets[y0:y0 + rows] = facets_of(scene, first.ids[c::s, c::s])
        depth[y0:y0 + rows] = first.depth[c::s, c::s]
    return facets, depth
