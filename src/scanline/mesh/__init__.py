"""Three-dimensional object representations (Hearn & Baker, chapter 10): polygon
meshes with their polygon tables and plane equations, quadric surfaces and
superquadrics, sweep representations, tensor-product surfaces and the Utah teapot,
blobby objects (:func:`blobby`, iso-surfaces of summed densities), and mesh files
(OBJ, PLY, STL, glTF).

>>> import scanline as sl
>>> cube = sl.mesh.cube()
>>> cube.plane_equations()[1].tolist()       # the face x = +1: outward normal +x
[8.0, 0.0, 0.0, -8.0]
>>> bool(cube.inside((0.5, 0, 0))), bool(cube.inside((2, 0, 0)))
(True, False)
"""

from .blobby import blobby
from .files import FORMATS, MeshFileError, MeshFileWarning, load, load_all, save
from .materials import MaterialRecord
from .mesh import Mesh, merge
from .shapes import (box, cube, ellipsoid, sphere, superellipsoid, superquadric, supertoroid,
                     torus)
from .sweeps import from_surface, rotational_sweep, sweep, teapot, translational_sweep
from .tables import PolygonTables

__all__ = ["FORMATS", "MaterialRecord", "Mesh", "MeshFileError", "MeshFileWarning",
           "PolygonTables", "blobby", "box", "cube", "ellipsoid",
           "from_surface", "load", "load_all", "merge", "rotational_sweep", "save", "sphere",
           "superellipsoid", "superquadric", "supertoroid", "sweep", "teapot", "torus",
           "translational_sweep"]
