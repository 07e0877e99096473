"""The depth buffer (z-buffer) of Hearn & Baker's depth-buffer method, section 13-3.

A :class:`DepthBuffer` holds one depth per pixel, float64, in the frame buffer's
device coordinates (``array[y, x]`` is pixel (x, y), y up).  It starts cleared to
infinity, as the notes' glossary says ("Before bringing in a new frame, the rendering
engine clears the buffer, setting all Z-values to 'infinity'"); Hearn & Baker clear to
the back plane's depth instead, which draws the same picture for everything inside
the view volume.  Depth grows away from the viewer (NDC depth 0 on the front plane,
1 on the back plane: docs/three-d.md), so a fragment is kept when its depth is
*smaller* than the stored one.
"""

from __future__ import annotations

import os
from typing import TYPE_CHECKING, BinaryIO, Union

import numpy as np
from numpy.typing import NDArray

from . import _validate as v
from .errors import ArgumentTypeError, ArgumentValueError

if TYPE_CHECKING:
    from ._typing import Color
    from .framebuffer import FrameBuffer


def _depth_value(name: str, value: object) -> float:
    """A clearing depth: a real number or +inf."""
    if isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(value, bool):
        x = float(value)
        if x == x and x != -np.inf:
            return x
    raise ArgumentValueError(f"{name} must be a depth (a number or inf), got {v._show(value)}")


class DepthBuffer:
    """A per-pixel depth store that drawing calls can share and keep.

    Parameters
    ----------
    width, height : int
        Its size: that of the frame buffer it goes with.
    clear : float
        The initial depth of every pixel (default infinity).

    Raises
    ------
    MemoryBudgetError
        When its 8 bytes a pixel pass the memory budget (:mod:`scanline.budget`),
        before anything is allocated.

    Examples
    --------
    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(6, 3, mode="L")
    >>> depth = sl.DepthBuffer(6, 3)
    >>> sl.draw.triangles(fb, [[(0, -1, 0.5), (6, -1, 0.5), (0, 3, 0.5)]], colors=255, depth=depth)
    >>> depth.to_array().tolist()[-1]
    [0.5, 0.5, 0.5, 0.5, 0.5, inf]
    """

    def __init__(self, width: int, height: int, clear: float = np.inf) -> None:
        from . import budget

        self.width = v.positive_int("width", width)
        self.height = v.positive_int("height", height)
        value = _depth_value("clear", clear)
        budget.check(8 * self.width * self.height, "width x height",
                     f"a {self.width} x {self.height} depth buffer (8 bytes a pixel)",
                     hint="use a smaller size")
        self.array: NDArray[np.float64] = np.full((self.height, self.width), value, np.float64)

    @classmethod
    def holding(cls, array: NDArray[np.float64]) -> DepthBuffer:
        """A depth buffer whose pixels are ``array`` (H, W) float64, C-contiguous (not
        copied: what a renderer hands back).

        Parameters
        ----------
        array : numpy.ndarray
            The depths, (H, W) float64, writable and C-contiguous, rows in device order
            (``array[y, x]`` is pixel (x, y), y up).

        Returns
        -------
        DepthBuffer
            A W x H depth buffer that shares ``array``.

        Raises
        ------
        ArgumentValueError
            When ``array`` is not a writable C-contiguous float64 2-D array.

        Examples
        --------
        >>> import numpy as np
        >>> import scanline as sl
        >>> a = np.zeros((2, 3))
        >>> depth = sl.DepthBuffer.holding(a)
        >>> depth.width, depth.height, depth.array is a
        (3, 2, True)
        """
        if not isinstance(array, np.ndarray) or array.ndim != 2:
            raise ArgumentValueError("a depth buffer's array must be a writable C-contiguous "
                                     f"float64 (H, W) array, got {v._show(array)}")
        height, width = array.shape
        out = cls.__new__(cls)
        out.width = v.positive_int("width", width)
        out.height = v.positive_int("height", height)
        out.array = depth_array_checked(array)
        return out

    @classmethod
    def like(cls, fb: FrameBuffer, clear: float = np.inf) -> DepthBuffer:
        """A depth buffer of the size of frame buffer ``fb``.

        Parameters
        ----------
        fb : FrameBuffer
            The frame buffer whose width and height it takes.
        clear : float
            The initial depth of every pixel (default infinity).

        Returns
        -------
        DepthBuffer
            A new depth buffer, every pixel at ``clear``.

        Raises
        ------
        ArgumentTypeError
            When ``fb`` is not a FrameBuffer.

        Examples
        --------
        >>> import scanline as sl
        >>> sl.DepthBuffer.like(sl.FrameBuffer(3, 2), clear=1.0).to_array().tolist()
        [[1.0, 1.0, 1.0], [1.0, 1.0, 1.0]]
        """
        from .framebuffer import FrameBuffer

        if not isinstance(fb, FrameBuffer):
            raise ArgumentTypeError(f"fb must be a scanline.FrameBuffer, got {v._show(fb)}")
        return cls(fb.width, fb.height, clear)

    def clear(self, value: float = np.inf) -> None:
        """Set every pixel's depth to ``value`` (a new frame).

        Parameters
        ----------
        value : float
            The depth, a real number or infinity (default).

        Raises
        ------
        ArgumentValueError
            When ``value`` is not a number, is NaN or is minus infinity.

        Examples
        --------
        >>> import scanline as sl
        >>> depth = sl.DepthBuffer(2, 1)
        >>> depth.clear(0.5)
        >>> depth.to_array().tolist()
        [[0.5, 0.5]]
        """
        self.array.fill(_depth_value("value", value))

    def to_array(self) -> NDArray[np.float64]:
        """A copy of the depths in image order (top row first), like
        :meth:`scanline.FrameBuffer.to_array`.

        Returns
        -------
        numpy.ndarray
            (H, W) float64: row 0 is the top row (y = H - 1).

        Examples
        --------
        >>> import scanline as sl
        >>> depth = sl.DepthBuffer(2, 2)
        >>> depth.array[0, 0] = 0.25             # pixel (0, 0): bottom left
        >>> depth.to_array().tolist()
        [[inf, inf], [0.25, inf]]
        """
        return np.array(self.array[::-1])        # a copy, C-contiguous

    def image(self, near: Color = "white", far: Color = "black",
              background: Color = "black") -> FrameBuffer:
        """The depths as a gray-level :class:`~scanline.FrameBuffer` (mode "L"): the
        nearest written depth ``near``, the farthest ``far`` (linearly between), the
        pixels still at infinity ``background``.

        Parameters
        ----------
        near : Color
            The gray of the smallest finite depth.
        far : Color
            The gray of the largest finite depth.
        background : Color
            The gray of the pixels at infinity (never written).

        Returns
        -------
        FrameBuffer
            A new W x H frame buffer in mode "L".

        Examples
        --------
        >>> import numpy as np
        >>> import scanline as sl
        >>> depth = sl.DepthBuffer(4, 1)
        >>> depth.array[0] = [0.0, 0.25, 1.0, np.inf]
        >>> depth.image().to_array().tolist()     # 255 + (0 - 255) * 0.25 = 191.25
        [[255, 191, 0, 0]]
        """
        from .framebuffer import FrameBuffer

        fb = FrameBuffer(self.width, self.height, mode="L", background=background)
        a = self.array
        seen = np.isfinite(a)
        if seen.any():
            lo, hi = float(a[seen].min()), float(a[seen].max())
            t = (a[seen] - lo) / (hi - lo) if hi > lo else np.zeros(int(seen.sum()))
            n = float(fb.pixel(near, "near")[0])
            f = float(fb.pixel(far, "far")[0])
            buf = fb._raster()[0]
            buf[seen, 0] = np.rint(n + (f - n) * t).astype(np.uint8)
        return fb

    def save(self, path: Union[str, os.PathLike[str], BinaryIO], **kw: Color) -> None:
        """Write :meth:`image` to ``path`` (atomically, as FrameBuffer.save does).

        Parameters
        ----------
        path : str, os.PathLike or binary file
            Where to write; the format follows the file name's extension.
        **kw : Color
            ``near``, ``far`` and ``background`` of :meth:`image`.

        Examples
        --------
        >>> import os, tempfile
        >>> import scanline as sl
        >>> depth = sl.DepthBuffer(4, 3)
        >>> with tempfile.TemporaryDirectory() as folder:
        ...     depth.save(os.path.join(folder, "depth.png"), background="gray")
        ...     sl.FrameBuffer.open(os.path.join(folder, "depth.png")).to_array()[0, 0].item()
        128
        """
        self.image(**kw).save(path)

    def _checked(self, fb: FrameBuffer, name: str = "depth") -> NDArray[np.float64]:
        """The float64 array for a kernel, after checking it fits ``fb``."""
        if not isinstance(self, DepthBuffer):
            raise ArgumentTypeError(f"{name} must be a scanline.DepthBuffer")
        if (self.width, self.height) != (fb.width, fb.height):
            raise ArgumentValueError(
                f"{name} is {self.width} x {self.height} but the frame buffer is "
                f"{fb.width} x {fb.height}; make it with sl.DepthBuffer.like(fb)")
        a = self.array
        if a.dtype != np.float64 or a.shape != (self.height, self.width) or \
                not a.flags.c_contiguous or not a.flags.writeable:
            raise ArgumentValueError(
                f"{name}.array must stay a writable C-contiguous float64 array of shape "
                f"({self.height}, {self.width}), got {a.dtype} {a.shape}")
        return a

    def __repr__(self) -> str:
        return f"<DepthBuffer {self.width} x {self.height}>"


def depth_array_checked(array: object) -> NDArray[np.float64]:
    """``array`` if it is a writable C-contiguous float64 (H, W) array, else an error.

    Parameters
    ----------
    array : object
        The array a depth buffer would hold.

    Returns
    -------
    numpy.ndarray
        ``array`` itself.

    Raises
    ------
    ArgumentValueError
        When ``array`` is not a writable C-contiguous float64 2-D array.

    Examples
    --------
    >>> import numpy as np
    >>> from scanline.depthbuffer import depth_array_checked
    >>> depth_array_checked(np.zeros((2, 2))).shape
    (2, 2)
    >>> depth_array_checked(np.zeros((2, 2), np.float32))
    Traceback (most recent call last):
      ...
    scanline.errors.ArgumentValueError: a depth buffer's array must be a writable C-contiguous float64 (H, W) array, got ...
    """
    if not (isinstance(array, np.ndarray) and array.dtype == np.float64 and array.ndim == 2
            and array.flags.c_contiguous and array.flags.writeable):
        raise ArgumentValueError("a depth buffer's array must be a writable C-contiguous "
                                 f"float64 (H, W) array, got {v._show(array)}")
    return array


def depth_argument(fb: FrameBuffer, depth: object, name: str = "depth") -> NDArray[np.float64]:
    """The depth buffer array for ``depth`` (a DepthBuffer), or an error.

    Parameters
    ----------
    fb : FrameBuffer
        The frame buffer the depths go with.
    depth : object
        The ``depth=`` argument of a drawing call.
    name : str
        Its name, for the error message.

    Returns
    -------
    numpy.ndarray
        The depth buffer's (H, W) float64 array, for a kernel.

    Raises
    ------
    ArgumentTypeError
        When ``depth`` is not a DepthBuffer.
    ArgumentValueError
        When its size is not the frame buffer's, or its array was replaced by one a
        kernel cannot take.

    Examples
    --------
    >>> import scanline as sl
    >>> from scanline.depthbuffer import depth_argument
    >>> fb = sl.FrameBuffer(3, 2)
    >>> depth_argument(fb, sl.DepthBuffer.like(fb)).shape
    (2, 3)
    >>> depth_argument(fb, sl.DepthBuffer(4, 4))
    Traceback (most recent call last):
      ...
    scanline.errors.ArgumentValueError: depth is 4 x 4 but the frame buffer is 3 x 2; make it with sl.DepthBuffer.like(fb)
    """
    if not isinstance(depth, DepthBuffer):
        raise ArgumentTypeError(
            f"{name} must be a scanline.DepthBuffer (sl.DepthBuffer.like(fb)) or None, got "
            f"{v._show(depth)}")
    return depth._checked(fb, name)
