"""Quadtrees (Hearn & Baker, section 10-17, where they introduce octrees): a square of
pixels divided into quadrants recursively, each empty, full or split, made from a
binary image or a polygon filled by scanline's own scan-line fill, combined by set
operations node by node, and drawn with its cell boundaries."""

from typing import TYPE_CHECKING, Optional, Sequence, Tuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from .._typing import Color, Points, Rule
from ..errors import ArgumentValueError
from .tree import FULL, Tree, check_depth

if TYPE_CHECKING:
    from ..framebuffer import FrameBuffer


class Quadtree(Tree):
    """A quadtree of the pixels of a square image 2**depth a side.

    Pixel coordinates are the frame buffer's device coordinates: x to the right, y
    up, pixel (x, y) the unit square around its center (x, y); the tree's cell at
    (x, y) of size s covers pixels x .. x + s - 1, y .. y + s - 1.
    :meth:`from_image` and :meth:`to_image` take and give arrays in image order (top
    row first), as :meth:`scanline.FrameBuffer.to_array` does.

    Parameters
    ----------
    kind : array_like of int8 (nodes,)
        Per node: 0 empty, 1 full, 2 split, the root first.
    child : array_like of int64 (nodes,)
        Per node: the first of its 4 consecutive children, -1 for a leaf.
    depth : int
        Levels below the root.
    origin : ndarray (2,)
        The region's lower-left corner.
    side : float
        The region's side.
    shape : (int, int), optional
        The (height, width) of the image it was made from (default: the square).

    Raises
    ------
    ArgumentValueError
        ``kind`` and ``child`` not 1-D arrays of one length.

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

    def __init__(self, kind: ArrayLike, child: ArrayLike, depth: int,
                 origin: NDArray[np.float64], side: float,
                 shape: Optional[Tuple[int, int]] = None) -> None:
        super().__init__(kind, child, depth, origin, side)
        n = 1 << depth
        self.shape = (n, n) if shape is None else shape

    @classmethod
    def from_image(cls, image: ArrayLike) -> "Quadtree":
        """The quadtree of a 2-D array in image order (top row first; nonzero or True:
        inside), padded with empty pixels above and to the right to 2**depth a
        side.

        Parameters
        ----------
        image : array_like (H, W)
            Nonzero or True: inside.

        Returns
        -------
        Quadtree
            Its tree (Hearn & Baker 10-17).

        Raises
        ------
        ArgumentValueError
            An array that is not 2-D, or one too large.

        Examples
        --------
        The top-left pixel of a 2 x 2 image: one full leaf of the four quadrants.

        >>> import scanline as sl
        >>> sl.octree.Quadtree.from_image([[True, False], [False, False]])
        <Quadtree depth 1: 5 nodes, 1 full leaves>
        """
        a = np.asarray(image)
        if a.ndim != 2:
            raise ArgumentValueError(f"image must be a 2-D array (height, width), got "
                                     f"{v._show(image)}")
        grid, depth = cls._padded(a[::-1].T, "image")          # [x, y], y up
        tree = cls._grid_tree(grid, np.zeros(2), float(1 << depth))
        tree.shape = a.shape
        return tree

    @classmethod
    def from_polygon(cls, points: Points, depth: int, rule: Rule = "even-odd") -> "Quadtree":
        """The quadtree of a polygon (device coordinates, pixels) over the square of
        pixels 0 .. 2**depth - 1: the pixels whose centers the polygon fill
        (:func:`scanline.draw.polygon`, Hearn & Baker 3-11, with its fill ``rule``)
        sets.

        Parameters
        ----------
        points : (N, 2) points
            The polygon's vertices.
        depth : int
            Levels: the square is 2**depth pixels a side.
        rule : {"even-odd", "nonzero"}
            The fill's inside-outside rule.

        Returns
        -------
        Quadtree
            The tree of the filled pixels.

        Raises
        ------
        ArgumentValueError
            A depth whose tree would be too large, or a bad polygon.

        Examples
        --------
        A square around the pixel centers 0..1 x 0..1 fills the lower-left quadrant:

        >>> import scanline as sl
        >>> q = sl.octree.Quadtree.from_polygon([(-0.5, -0.5), (1.5, -0.5), (1.5, 1.5), (-0.5, 1.5)], 2)
        >>> q
        <Quadtree depth 2: 5 nodes, 1 full leaves>
        """
        from ..draw import polygon
        from ..framebuffer import FrameBuffer

        depth = check_depth(depth, 4, "a quadtree")
        n = 1 << depth
        fb = FrameBuffer(n, n, mode="L", background=0)
        polygon(fb, points, color=255, rule=rule)
        return cls.from_image(fb.to_array() > 0)

    def area(self) -> float:
        """The number of pixels in the full cells.

        Returns
        -------
        float
            The full cells' area, in pixels.

        Examples
        --------
        >>> import scanline as sl
        >>> q = sl.octree.Quadtree.from_polygon([(-0.5, -0.5), (1.5, -0.5), (1.5, 1.5), (-0.5, 1.5)], 2)
        >>> q.area()
        4.0
        """
        return self._measure()

    def to_image(self) -> NDArray[np.bool_]:
        """The full pixels, boolean, in image order, of the shape the tree was made
        from (padding cropped).

        Returns
        -------
        ndarray of bool (H, W)
            Top row first.

        Examples
        --------
        >>> import scanline as sl
        >>> q = sl.octree.Quadtree.from_polygon([(-0.5, -0.5), (1.5, -0.5), (1.5, 1.5), (-0.5, 1.5)], 2)
        >>> q.to_image().astype(int).tolist()
        [[0, 0, 0, 0], [0, 0, 0, 0], [1, 1, 0, 0], [1, 1, 0, 0]]
        """
        grid = self._grid()                        # [x, y], y up
        h, w = self.shape
        return np.ascontiguousarray(grid[:w, :h].T[::-1]).astype(bool)

    def cells(self) -> NDArray[np.int64]:
        """The leaves as rows (x, y, size, full): their lower-left pixel, side in
        pixels, and whether full; depth first.

        Returns
        -------
        ndarray (leaves, 4)
            x, y, size, full (1 or 0).

        Examples
        --------
        The quadrants in order: x's upper half is bit 0 of a child's number, y's bit 1.

        >>> import scanline as sl
        >>> q = sl.octree.Quadtree.from_polygon([(-0.5, -0.5), (1.5, -0.5), (1.5, 1.5), (-0.5, 1.5)], 2)
        >>> q.cells().tolist()
        [[0, 0, 2, 1], [2, 0, 2, 0], [0, 2, 2, 0], [2, 2, 2, 0]]
        """
        rows = self._cells()
        return np.column_stack([rows[:, 0], rows[:, 1], rows[:, 3], rows[:, 4] == FULL])

    def draw(self, fb: "FrameBuffer", color: Color = "black", boundary: Optional[Color] = "gray",
             scale: int = 1, at: Sequence[int] = (0, 0)) -> None:
        """Draw the tree on a frame buffer: the full pixels in ``color`` and, unless
        ``boundary`` is None, each leaf's boundary in that color, every pixel
        ``scale`` x ``scale`` frame-buffer pixels with the tree's pixel (0, 0) at
        device point ``at``.

        Parameters
        ----------
        fb : FrameBuffer
            Drawn into.
        color : color
            Of the full pixels.
        boundary : color or None
            Of the leaves' boundaries (None: not drawn).
        scale : int
            Frame-buffer pixels per tree pixel, per side.
        at : (int, int)
            Where the tree's pixel (0, 0) goes.

        Examples
        --------
        >>> import scanline as sl
        >>> q = sl.octree.Quadtree.from_polygon([(-0.5, -0.5), (1.5, -0.5), (1.5, 1.5), (-0.5, 1.5)], 2)
        >>> fb = sl.FrameBuffer(4, 4, mode="L")
        >>> q.draw(fb, color=255, boundary=None)
        >>> fb.to_array().tolist()
        [[0, 0, 0, 0], [0, 0, 0, 0], [255, 255, 0, 0], [255, 255, 0, 0]]
        """
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
