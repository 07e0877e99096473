"""Projections and the camera: the 3-D viewing pipeline of Hearn & Baker, chapter 12.

Parallel projections -- :func:`orthographic` (front, side, top ... views),
:func:`axonometric` (:func:`isometric`, :func:`dimetric`, :func:`trimetric`),
:func:`oblique` (cavalier, cabinet, any α and φ), :func:`parallel` (any projection
vector) -- and perspective ones -- :func:`perspective` (Hearn & Baker's z_prp / z_vp
form, or a field of view) and :func:`frustum` (any center of projection) -- are
:class:`Projection` objects: a 4x4 matrix (``numpy.asarray(p)``) and a view volume.
A :class:`~scanline.Camera` puts one behind a viewing transformation
(:func:`viewing_matrix`, :func:`look_at`) and maps the normalized view volume onto
a device through a 3-D viewport.

>>> import math, scanline as sl
>>> p = sl.projection.oblique("cavalier", phi=math.radians(45))
>>> sl.transform3d.apply(p, (0, 0, 1)).round(6).tolist()
[0.707107, 0.707107, 1.0]
"""

from .camera import Camera, look_at, viewing_matrix
from .projections import (
    OBLIQUE,
    VIEW_NAMES,
    VIEWS,
    Projection,
    axonometric,
    dimetric,
    foreshortening,
    frustum,
    isometric,
    oblique,
    orthographic,
    parallel,
    perspective,
    trimetric,
)

__all__ = ["Camera", "OBLIQUE", "Projection", "VIEWS", "VIEW_NAMES", "axonometric", "dimetric",
           "foreshortening", "frustum", "isometric", "look_at", "oblique", "orthographic",
           "parallel", "perspective", "trimetric", "viewing_matrix"]
