"""Octrees and quadtrees (Hearn & Baker, section 10-17): regions divided recursively
into octants (quadrants), each empty, full or split, stored as flat arrays; made from
solids, closed meshes, voxels, images and polygons; combined by set operations node by
node; measured, and turned back into voxels, images or boundary meshes.  The octree
visible-surface method (section 13-10) is ``sl.render(..., method="octree")``
(:mod:`scanline.visible.octree`).  See ``docs/octrees.md``.

>>> import scanline as sl
>>> ball = sl.octree.Octree.from_solid(sl.solids.Sphere(radius=1.0), depth=5)
>>> round(ball.volume(), 2), round(4 / 3 * 3.14159265, 2)     # exact: 4/3 pi r^3
(4.21, 4.19)
"""

from .octree import Octree
from .quadtree import Quadtree
from .tree import MAX_DEPTH

__all__ = ["MAX_DEPTH", "Octree", "Quadtree"]
