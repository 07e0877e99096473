"""The texture: an image mapped onto surfaces by texture coordinates (u, v) (Hearn &
Baker, section 14-9, "Texture mapping": the texture space (s, t), here (u, v) in 0..1
across the image, u to the right and v up), filtered by nearest texel, bilinear
interpolation or trilinear mipmapping (Williams 1983), and wrapped (repeat, mirror)
or clamped outside 0..1.
"""

import functools
import os
from typing import TYPE_CHECKING, Dict, List, Optional, Tuple, Union, cast

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError

if TYPE_CHECKING:
    from PIL import Image

#: An image as textures take it: an array, a Pillow image or an image file's path.
ImageSource = Union[ArrayLike, "Image.Image", str, "os.PathLike[str]"]

#: Packed texels (3 N,) float32 and their levels' table (L, 3) int64.
Packed = Tuple[NDArray[np.float32], NDArray[np.int64]]

#: The filters: the nearest texel, bilinear interpolation between the four nearest
#: texel centers, and trilinear (bilinear in the two mipmap levels nearest the
#: pixel's footprint, then linear between them).
FILTERS = ("nearest", "bilinear", "trilinear")

#: Outside 0..1: the texture repeated, repeated mirrored, or its edge texels extended.
WRAPS = ("repeat", "clamp", "mirror")

#: Bytes per texel kept: the stored image (float64, 3 channels), its pyramid (4/3 of
#: it as float32) and the decoded copy for one gamma.
TEXEL_BYTES = 8 * 3 + 2 * 4 * 3 * 4 // 3 + 8


def _image_array(name: str, image: object) -> NDArray[np.float64]:
    """``image`` as stored values 0..1 (H, W, 3) float64 in image order (top row
    first): an (H, W), (H, W, 1|3|4) array of integers 0..255 or reals 0..1, a Pillow
    image, or an image file's path (alpha is not used)."""
    from PIL import Image

    if isinstance(image, (str, os.PathLike)):
        from ..imagefile import read

        image = read(image)
    if isinstance(image, Image.Image):
        image = np.asarray(image.convert("RGB"))
    if not isinstance(image, np.ndarray):
        if isinstance(image, (list, tuple)):
            image = np.asarray(image)
        else:
            raise ArgumentTypeError(
                f"{name} must be an image: an (H, W, 3|4) array, a Pillow Image or an image "
                f"file's path, got {v._show(image)}")
    a = image
    if a.dtype == bool or a.dtype.kind not in "uif":
        raise ArgumentTypeError(f"{name} must hold numbers (uint8 0..255 or reals 0..1), got "
                                f"an array of dtype {a.dtype}")
    if a.ndim == 2:
        a = a[..., None]
    if a.ndim != 3 or a.shape[2] not in (1, 3, 4) or a.shape[0] < 1 or a.shape[1] < 1:
        raise ArgumentValueError(f"{name} must have shape (H, W), (H, W, 3) or (H, W, 4), got "
                                 f"{a.shape}")
    from ..budget import check

    check(TEXEL_BYTES * a.shape[0] * a.shape[1], name,
          f"a {a.shape[1]} x {a.shape[0]} texture", "give a smaller image")
    if a.dtype.kind in "ui":
        if a.size and (a.min() < 0 or a.max() > 255):
            raise ArgumentValueError(f"{name}: integer texels must be in 0..255, got "
                                     f"{a.min()}..{a.max()}")
        out = a.astype(np.float64) / 255.0
    else:
        out = a.astype(np.float64)
        if not np.isfinite(out).all() or (out.size and (out.min() < 0 or out.max() > 1)):
            raise ArgumentValueError(f"{name}: real texels must be finite and in 0..1 "
                                     f"(integers 0..255 for uint8 images)")
    out = out[..., :3]
    if out.shape[2] == 1:
        out = np.repeat(out, 3, axis=2)
    return np.ascontiguousarray(out)


class Texture:
    """An image to map onto surfaces (Hearn & Baker, section 14-9).

    Parameters
    ----------
    image : array, Pillow Image or path
        (H, W), (H, W, 3) or (H, W, 4) uint8 0..255 or reals 0..1, top row first (as
        Pillow and matplotlib hold images); a Pillow image; or an image file.  The
        values are stored colors, decoded with the rendering's gamma like every
        color; alpha is not used.
    filter : {"nearest", "bilinear", "trilinear"}
        How a texel color is found at (u, v): the texel whose square holds it,
        bilinear interpolation of the four nearest texel centers, or trilinear
        mipmapping -- bilinear in the two levels of the pyramid whose texels best
        match the pixel's footprint (from the screen derivatives of u and v), then
        linear between them (Williams 1983).
    wrap : {"repeat", "clamp", "mirror"}
        Coordinates outside 0..1: the image repeated, its edge texels extended, or
        the image repeated mirrored.

    Texture space: u runs 0..1 from the left edge to the right edge of the image and
    v 0..1 from the bottom edge to the top edge; texel (i, j) of a W x H image is
    centered at ((i + 1/2)/W, (j + 1/2)/H) counting rows from the bottom.

    Examples
    --------
    >>> import numpy as np, scanline as sl
    >>> t = sl.Texture(np.array([[[0, 0, 0], [255, 255, 255]]], np.uint8), filter="nearest")
    >>> t.sample([[0.25, 0.5], [0.75, 0.5]]).tolist()
    [[0.0, 0.0, 0.0], [1.0, 1.0, 1.0]]
    """

    def __init__(self, image: ImageSource, filter: str = "bilinear",
                 wrap: str = "repeat") -> None:
        self.filter = v.choice("filter", filter, FILTERS)
        self.wrap = v.choice("wrap", wrap, WRAPS)
        self.image = _image_array("image", image)
        self.image.flags.writeable = False
        self._kept: Dict[float, Packed] = {}

    @property
    def width(self) -> int:
        """The image's width W, in texels."""
        return int(self.image.shape[1])

    @property
    def height(self) -> int:
        """The image's height H, in texels."""
        return int(self.image.shape[0])

    @functools.cached_property
    def levels(self) -> List[NDArray[np.float64]]:
        """The mipmap pyramid (:func:`scanline.texture.mipmap.pyramid`): (h, w, 3)
        stored values 0..1, image order, from the image down to 1 x 1."""
        from .mipmap import pyramid

        return pyramid(self.image)

    def kernel_arrays(self, gamma: float = 1.0) -> Packed:
        """``(texels (3 N,) float32, levels (L, 3) int64)`` as
        :mod:`scanline._kernels.texture` takes them, the texels decoded with
        ``gamma`` (linear values; 1: the stored ones), only the first level unless
        the filter is trilinear.  Kept per gamma.

        Parameters
        ----------
        gamma : float
            The exponent that decodes the stored values (1: kept as stored).

        Returns
        -------
        texels : ndarray (3 N,) float32
            R, G, B of each texel, level after level, each level's rows bottom first
            (read-only).
        levels : ndarray (L, 3) int64
            Each level's first texel, width and height (read-only).

        Examples
        --------
        >>> import numpy as np, scanline as sl
        >>> t = sl.Texture(np.array([[[0, 0, 0]], [[255, 255, 255]]], np.uint8))
        >>> texels, levels = t.kernel_arrays()
        >>> texels.tolist(), levels.tolist()       # the bottom (white) row first
        ([1.0, 1.0, 1.0, 0.0, 0.0, 0.0], [[0, 1, 2]])
        """
        from .mipmap import packed

        gamma = float(gamma)
        kept = self._kept.get(gamma)
        if kept is not None:
            return kept
        levels = self.levels if self.filter == "trilinear" else [self.image]
        texels, table = packed(levels)
        if gamma != 1.0:
            texels = texels ** np.float32(gamma)
        texels.flags.writeable = table.flags.writeable = False
        if len(self._kept) >= 4:
            self._kept.clear()
        self._kept[gamma] = texels, table
        return texels, table

    def sample(self, uv: ArrayLike, derivatives: Optional[ArrayLike] = None,
               gamma: float = 1.0) -> NDArray[np.float64]:
        """The texture's color at texture coordinates ``uv`` (M, 2), filtered and
        wrapped as the texture says: (M, 3) reals 0..1 (stored values; ``gamma``:
        decoded with it).  ``derivatives`` (M, 4): du/dx, dv/dx, du/dy, dv/dy per
        pixel, which choose the mipmap levels of a trilinear texture (default 0:
        the finest level).

        Parameters
        ----------
        uv : array_like (M, 2) or (2,)
            Finite texture coordinates.
        derivatives : array_like (M, 4), optional
            The screen derivatives of u and v at each point.
        gamma : float
            Decodes the stored values (1: as stored).

        Returns
        -------
        ndarray (M, 3) float64
            The filtered colors.

        Raises
        ------
        ArgumentValueError
            ``uv`` or ``derivatives`` of the wrong shape, or not finite.

        Notes
        -----
        Hearn & Baker 14-9, "Texture mapping"; trilinear filtering after Williams
        (1983), "Pyramidal parametrics".

        Examples
        --------
        >>> import numpy as np, scanline as sl
        >>> t = sl.Texture(np.array([[[0, 0, 0], [255, 255, 255]]], np.uint8))
        >>> t.sample([[0.5, 0.5], [1.25, 0.5]]).tolist()   # halfway; 1.25 wraps to 0.25
        [[0.5, 0.5, 0.5], [0.0, 0.0, 0.0]]
        """
        from .._kernels import texture as k
        from .._kernels._jit import call

        a = v.real_array("uv", uv, "(M, 2)")
        a = a.reshape(1, 2) if a.shape == (2,) else a
        if a.ndim != 2 or a.shape[1] != 2:
            raise ArgumentValueError(f"uv must have shape (M, 2), got {a.shape}")
        if not np.isfinite(a).all():
            raise ArgumentValueError("uv must be finite texture coordinates; it holds NaN or "
                                     "infinite values")
        d = np.zeros((len(a), 4)) if derivatives is None else \
            v.real_array("derivatives", derivatives, "(M, 4)")
        if d.shape != (len(a), 4) or not np.isfinite(d).all():
            raise ArgumentValueError(f"derivatives must be finite, of shape ({len(a)}, 4), got "
                                     f"{d.shape}")
        texels, table = self.kernel_arrays(gamma)
        out = np.empty((len(a), 3))
        call(k.sample_points, 4 * len(a), texels, table, 0, len(table),
             FILTER_CODES[self.filter], WRAP_CODES[self.wrap], a, d, out)
        return out

    def __repr__(self) -> str:
        return f"<Texture {self.width}x{self.height} {self.filter} {self.wrap}>"


FILTER_CODES = {"nearest": 0, "bilinear": 1, "trilinear": 2}
WRAP_CODES = {"repeat": 0, "clamp": 1, "mirror": 2}


def texture_of(name: str, value: object) -> Optional[Texture]:
    """``value`` as a :class:`Texture` (an image becomes a bilinear, repeated one),
    ``None`` kept."""
    if value is None or isinstance(value, Texture):
        return value
    try:
        return Texture(cast(ImageSource, value))
    except (ArgumentTypeError, ArgumentValueError) as e:
        raise type(e)(f"{name}: {e}") from None
