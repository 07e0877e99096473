"""Quadtrees (Hearn & Baker, section 10-17, where they introduce octrees): a square of
pixels divided into quadrants recursively, each empty, full or split, made from a
binary image or a polygon filled by scanline's own scan-line fill, combined by set
operations node by node, and drawn with its cell boundaries."""

import numpy as np

from .. import _validate as v
from ..errors import ArgumentValueError
from .tree import FULL, Tree, check_depth


class Quadtree(Tree):
    """A quadtree of the pixels of a square image 2**depth a side.

    Pixel coordinates are the frame buffer's device coordinates: x to the right, y
    up, pixel (x, y) the unit square around its center (x, y); the tree's cell at
    (x, y) of size s covers pixels x .. x + s - 1, y .. y + s - 1.
    :meth:`from_image` and :meth:`to_image` take and give arrays in image order (top
    row first), as :meth:`scanline.FrameBuffer.to_array` does.

    Examples
    --------
    >>> import numpy as np, scanline as sl
    >>> image = np.zeros((4, 4), bool); image[2:, :2] = True    # bottom-left 2 x 2
    >>> q = sl.octree.Quadtree.from_image(image)
    >>> q, q.area()
    (<Quadtree depth 2: 5 nodes, 1 full leaves>, 4.0)
    """
    dims = 2
    noun = "quadtree"

    def __init__(self, kind, child, depth, origin, side, shape=None):
        super().__init__(kind, child, depth, origin, side)
        n = 1 << depth
        self.shape = (n, n) if shape is None else shape

    @classmethod
    def from_image(cls, image):
        """The quadtree of a 2-D array in image order (top row first; nonzero or True:
        inside), padded with empty pixels above and to the right to 2**depth a
        side."""
        a = np.asarray(image)
        if a.ndim != 2:
            raise ArgumentValueError(f"image must be a 2-D array (height, width), got "
                                     f"{v._show(image)}")
        grid, depth = cls._padded(a[::-1].T, "image")          # [x, y], y up
        tree = cls._grid_tree(grid, np.zeros(2), float(1 << depth))
        tree.shape = a.shape
        return tree

    @classmethod
    def from_polygon(cls, points, depth, rule="even-odd"):
        """The quadtree of a polygon (device coordinates, pixels) over the square of
        pixels 0 .. 2**depth - 1: the pixels whose centers the polygon fill
        (:func:`scanline.draw.polygon`, Hearn & Baker 3-11, with its fill ``rule``)
        sets."""
        from ..draw import polygon
        from ..framebuffer import FrameBuffer

        depth = check_depth(depth, 4, "a quadtree")
        n = 1 << depth
        fb = FrameBuffer(n, n, mode="L", background=0)
        polygon(fb, points, color=255, rule=rule)
        return cls.from_image(fb.to_array() > 0)

    def area(self):
        """The number of pixels in the full cells."""
        return self._measure()

    def to_image(self):
        """The full pixels, boolean, in image order, of the shape the tree was made
        from (padding cropped)."""
        grid = self._grid()                        # [x, y], y up
        h, w = self.shape
        return np.ascontiguousarray(grid[:w, :h].T[::-1]).astype(bool)

    def cells(self):
        """The leaves as rows (x, y, size, full): their lower-left pixel, side in
        pixels, and whether full; depth first."""
        rows = self._cells()
        return np.column_stack([rows[:, 0], rows[:, 1], rows[:, 3], rows[:, 4] == FULL])

    def draw(self, fb, color="black", boundary="gray", scale=1, at=(0, 0)):
        """Draw the tree on a frame buffer: the full pixels in ``color`` and, unless
        ``boundary`` is None, each leaf's boundary in that color, every pixel
        ``scale`` x ``scale`` frame-buffer pixels with the tree's pixel (0, 0) at
        device point ``at``."""
        from ..draw import lines, points

        s = v.positive_int("scale", scale)
        x0, y0 = (v.coordinate("at", c) for c in at)
        full = self._grid()                          # [x, y]
        fx, fy = np.nonzero(np.kron(full, np.ones((s, s), np.uint8)))
        if len(fx):
            points(fb, np.column_stack([fx + x0, fy + y0]), color)
        if boundary is not None:
            c = self._cells()
            x, y, size = (c[:, 0] * s + x0, c[:, 1] * s + y0, c[:, 3] * s)
            # each leaf's lower and left sides, and the region's top and right
            right, top = x + size, y + size
            segs = np.concatenate([
                np.column_stack([x, y, right - 1, y]), np.column_stack([x, y, x, top - 1]),
                np.column_stack([x, top - 1, right - 1, top - 1]),
                np.column_stack([right - 1, y, right - 1, top - 1])])
            lines(fb, segs.astype(np.float64), color=boundary)


__all__ = ["Quadtree"]
