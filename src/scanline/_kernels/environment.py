"""Environment maps (Hearn & Baker, section 14-8, "Environment mapping"): the color
of the surroundings in a direction, from a latitude-longitude map or a cube map.

* **Latitude-longitude**: the direction (x, y, z) (world y up) is at u = 1/2 +
  atan2(x, -z) / (2 pi), v = 1/2 + asin(y) / pi of one texture (u = 1/2 looks along
  -z, v = 1 straight up).
* **Cube map**: six square faces, +x, -x, +y, -y, +z, -z, the face chosen by the
  direction's major axis and the coordinates by OpenGL's table (The OpenGL
  Graphics System 4.6, section 8.13, "Cube Map Texture Selection", table 8.19):
  with m = |major component|, s = (s_c / m + 1) / 2, t = (t_c / m + 1) / 2, where
  (s_c, t_c) is (-z, -y) on +x, (z, -y) on -x, (x, z) on +y, (x, -z) on -y, (x, -y) on
  +z and (-x, -y) on -z.  t runs down the face image (its top row first, as images
  are stored), so the texture coordinate (v up) is v = 1 - t.  Ties go to x, then
  y.

The faces' texels are packed one after another in the sampling kernels' layout
(:mod:`scanline._kernels.texture`): face k's levels are ``first + k count`` ..
``first + (k + 1) count - 1`` of ``levels``.  The color comes from
:func:`scanline._kernels.texture.sample_run` (one compiled copy of the sampling),
at the finest level.
"""

import math

import numpy as np

from ._jit import helper, kernel
from .texture import sample_run

#: Kinds of environment map.
LATITUDE_LONGITUDE = 0
CUBE = 1


@helper
def map_coordinates(kind, x, y, z):
    """The face (0 for a latitude-longitude map) and texture coordinates (u, v) of
    the direction (x, y, z) (any length; a zero or NaN direction gives face 0 and
    coordinates that the sampling wraps or clamps into the texture)."""
    if kind == CUBE:
        ax = abs(x)
        ay = abs(y)
        az = abs(z)
        if ax >= ay and ax >= az:
            m = ax
            face = 0 if x > 0 else 1
            sc = -z if x > 0 else z
            tc = -y
        elif ay >= az:
            m = ay
            face = 2 if y > 0 else 3
            sc = x
            tc = z if y > 0 else -z
        else:
            m = az
            face = 4 if z > 0 else 5
            sc = x if z > 0 else -x
            tc = -y
        if not m > 0:
            return 0, 0.5, 0.5
        return face, 0.5 * (sc / m + 1.0), 0.5 * (1.0 - tc / m)
    length = math.sqrt(x * x + y * y + z * z)
    if not length > 0:
        return 0, 0.5, 0.5
    return (0, 0.5 + math.atan2(x, -z) / (2.0 * math.pi),
            0.5 + math.asin(min(max(y / length, -1.0), 1.0)) / math.pi)


@helper
def environment_color(texels, levels, first, count, filter, wrap, kind, x, y, z, s):
    """The color (r, g, b) of the environment map (packed at ``first``, ``count``
    levels a face) in the direction (x, y, z); ``s``: scratch of 6 reals."""
    face, u, v = map_coordinates(kind, x, y, z)
    s[0] = u
    s[1] = v
    for k in range(2, 6):
        s[k] = 0.0
    sample_run(texels, levels, first + face * count, count, filter, wrap, s, np.int64(0),
               np.int64(1), np.int64(0), np.int64(1))
    return s[2], s[3], s[4]


@kernel
def environment_points(texels, levels, first, count, filter, wrap, kind, directions, out):
    """``out[m]`` = the environment map's color in ``directions[m]`` (M, 3)."""
    s = np.empty(6)
    for m in range(min(directions.shape[0], out.shape[0])):
        out[m, 0], out[m, 1], out[m, 2] = environment_color(
            texels, levels, first, count, filter, wrap, kind, directions[m, 0],
            directions[m, 1], directions[m, 2], s)
