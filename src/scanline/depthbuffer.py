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

import numpy as np

from . import _validate as v
from .errors import ArgumentTypeError, ArgumentValueError


def _depth_value(name, value):
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

    def __init__(self, width, height, clear=np.inf):
        from . import budget

        self.width = v.positive_int("width", width)
        self.height = v.positive_int("height", height)
        value = _depth_value("clear", clear)
        budget.check(8 * self.width * self.height, "width x height",
                     f"a {self.width} x {self.height} depth buffer (8 bytes a pixel)",
                     hint="use a smaller size")
        self.array = np.full((self.height, self.width), value, np.float64)

    @classmethod
    def holding(cls, array):
        """A depth buffer whose pixels are ``array`` (H, W) float64, C-contiguous (not
        copied: what a renderer hands back)."""
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
    def like(cls, fb, clear=np.inf):
        """A depth buffer of the size of frame buffer ``fb``."""
        from .framebuffer import FrameBuffer

        if not isinstance(fb, FrameBuffer):
            raise ArgumentTypeError(f"fb must be a scanline.FrameBuffer, got {v._show(fb)}")
        return cls(fb.width, fb.height, clear)

    def clear(self, value=np.inf):
        """Set every pixel's depth to ``value`` (a new frame)."""
        self.array.fill(_depth_value("value", value))

    def to_array(self):
        """A copy of the depths in image order (top row first), like
        :meth:`scanline.FrameBuffer.to_array`."""
        return self.array[::-1].copy()

    def image(self, near="white", far="black", background="black"):
        """The depths as a gray-level :class:`~scanline.FrameBuffer` (mode "L"): the
        nearest written depth ``near``, the farthest ``far`` (linearly between), the
        pixels still at infinity ``background``."""
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

    def save(self, path, **kw):
        """Write :meth:`image` to ``path`` (atomically, as FrameBuffer.save does)."""
        self.image(**kw).save(path)

    def _checked(self, fb, name="depth"):
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

    def __repr__(self):
        return f"<DepthBuffer {self.width} x {self.height}>"


def depth_array_checked(array):
    """``array`` if it is a writable C-contiguous float64 (H, W) array, else an error."""
    if not (isinstance(array, np.ndarray) and array.dtype == np.float64 and array.ndim == 2
            and array.flags.c_contiguous and array.flags.writeable):
        raise ArgumentValueError("a depth buffer's array must be a writable C-contiguous "
                                 f"float64 (H, W) array, got {v._show(array)}")
    return array


def depth_argument(fb, depth, name="depth"):
    """The depth buffer array for ``depth`` (a DepthBuffer), or an error."""
    if not isinstance(depth, DepthBuffer):
        raise ArgumentTypeError(
            f"{name} must be a scanline.DepthBuffer (sl.DepthBuffer.like(fb)) or None, got "
            f"{v._show(depth)}")
    return depth._checked(fb, name)
