"""The Cornell box (Goral, Torrance, Greenberg and Battaile 1984), as measured and
published by the Cornell Program of Computer Graphics: "Cornell Box Data",
https://www.graphics.cornell.edu/online/box/data.html .

Geometry: the page's corner coordinates in millimetres (x to the left as the camera
sees it, y up, z into the box), here scaled by ``scale`` (default 1/1000: metres).
The page's light (130 x 105 mm) lies in the ceiling's plane; the ceiling here is the
page's ceiling with the light's rectangle cut out (four quadrilaterals around it), so
that the two never overlap.  Faces are turned to face the inside of the room, and
the blocks' faces outward.

Reflectance and emission: the page gives spectra (400-700 nm) for the white, red
and green paints and the light.  The RGB values here are the rendering of those
spectra in B. Bitterli's "Rendering resources" Cornell box scene (2016):
white (0.725, 0.71, 0.68), red (0.63, 0.065, 0.05), green (0.14, 0.45, 0.091), and
the light's emission (17, 12, 4) (warm: its spectrum rises from 400 to 700 nm).
The page's camera: eye (278, 273, -800) mm looking along
+z, a 25 mm film at 35 mm focal length (a field of view of 2 atan(12.5 / 35) =
39.3 degrees).
"""

import math
from typing import Any, Dict, List, Tuple

import numpy as np

from .. import _validate as v
from ..errors import ArgumentValueError

WHITE = (0.725, 0.71, 0.68)
RED = (0.63, 0.065, 0.05)
GREEN = (0.14, 0.45, 0.091)
LIGHT = (17.0, 12.0, 4.0)

#: The light's rectangle on the page (y = 548.8 mm).
_LIGHT = [(343.0, 548.8, 227.0), (343.0, 548.8, 332.0), (213.0, 548.8, 332.0),
          (213.0, 548.8, 227.0)]

#: The page's quadrilaterals (mm), by surface.
_SURFACES: Dict[str, List[List[Tuple[float, float, float]]]] = {
    "floor": [[(552.8, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, 559.2), (549.6, 0.0, 559.2)]],
    "back wall": [[(549.6, 0.0, 559.2), (0.0, 0.0, 559.2), (0.0, 548.8, 559.2),
                   (556.0, 548.8, 559.2)]],
    "right wall": [[(0.0, 0.0, 559.2), (0.0, 0.0, 0.0), (0.0, 548.8, 0.0),
                    (0.0, 548.8, 559.2)]],
    "left wall": [[(552.8, 0.0, 0.0), (549.6, 0.0, 559.2), (556.0, 548.8, 559.2),
                   (556.0, 548.8, 0.0)]],
    "short block": [
        [(130.0, 165.0, 65.0), (82.0, 165.0, 225.0), (240.0, 165.0, 272.0),
         (290.0, 165.0, 114.0)],
        [(290.0, 0.0, 114.0), (290.0, 165.0, 114.0), (240.0, 165.0, 272.0),
         (240.0, 0.0, 272.0)],
        [(130.0, 0.0, 65.0), (130.0, 165.0, 65.0), (290.0, 165.0, 114.0),
         (290.0, 0.0, 114.0)],
        [(82.0, 0.0, 225.0), (82.0, 165.0, 225.0), (130.0, 165.0, 65.0), (130.0, 0.0, 65.0)],
        [(240.0, 0.0, 272.0), (240.0, 165.0, 272.0), (82.0, 165.0, 225.0),
         (82.0, 0.0, 225.0)]],
    "tall block": [
        [(423.0, 330.0, 247.0), (265.0, 330.0, 296.0), (314.0, 330.0, 456.0),
         (472.0, 330.0, 406.0)],
        [(423.0, 0.0, 247.0), (423.0, 330.0, 247.0), (472.0, 330.0, 406.0),
         (472.0, 0.0, 406.0)],
        [(472.0, 0.0, 406.0), (472.0, 330.0, 406.0), (314.0, 330.0, 456.0),
         (314.0, 0.0, 456.0)],
        [(314.0, 0.0, 456.0), (314.0, 330.0, 456.0), (265.0, 330.0, 296.0),
         (265.0, 0.0, 296.0)],
        [(265.0, 0.0, 296.0), (265.0, 330.0, 296.0), (423.0, 330.0, 247.0),
         (423.0, 0.0, 247.0)]],
}

#: Surface colors (reflectance) and the light's emission.
COLORS = {"floor": WHITE, "ceiling": WHITE, "back wall": WHITE, "right wall": GREEN,
          "left wall": RED, "short block": WHITE, "tall block": WHITE, "light": WHITE}


def _ceiling() -> List[List[Tuple[float, float, float]]]:
    """The page's ceiling (556 x 559.2 mm at y = 548.8) less the light: four
    quadrilaterals around the light's rectangle (x 213-343, z 227-332)."""
    y = 548.8
    x0, x1, z0, z1 = 213.0, 343.0, 227.0, 332.0
    return [[(556.0, y, 0.0), (556.0, y, z0), (0.0, y, z0), (0.0, y, 0.0)],
            [(556.0, y, z1), (556.0, y, 559.2), (0.0, y, 559.2), (0.0, y, z1)],
            [(556.0, y, z0), (556.0, y, z1), (x1, y, z1), (x1, y, z0)],
            [(x0, y, z0), (x0, y, z1), (0.0, y, z1), (0.0, y, z0)]]


def _oriented(quads: Any, inside: bool) -> Any:
    """``quads`` (mm) turned so that each normal points toward ``inside`` (True: the
    room's centre) or away from its block's centre (False)."""
    from ..mesh import Mesh

    q = np.asarray(quads, np.float64)
    centre = np.array([278.0, 274.4, 279.6]) if inside else q.reshape(-1, 3).mean(axis=0)
    out = []
    for quad in q:
        normal = np.cross(quad[2] - quad[0], quad[3] - quad[1])
        toward = (centre - quad.mean(axis=0)) @ normal
        out.append(quad if (toward > 0) == inside else quad[::-1])
    verts = np.concatenate(out)
    return Mesh(verts, np.arange(len(verts)).reshape(-1, 4))


def cornell_box(scale: float = 1e-3) -> Dict[str, Any]:
    """The Cornell box as meshes, its reflectances, emission and camera.

    Parameters
    ----------
    scale : float
        The factor of the published millimetre coordinates (default: metres).

    Returns
    -------
    dict
        ``meshes`` (list of Mesh: floor, ceiling, back wall, right wall (green),
        left wall (red), short block, tall block, light), ``names``, ``reflectance``
        and ``emission`` (one (r, g, b) per mesh, for :func:`scanline.radiosity.solve`)
        and ``camera`` (a :class:`scanline.Camera`: the page's viewpoint).

    Raises
    ------
    ArgumentTypeError
        ``scale`` not a number.
    ArgumentValueError
        ``scale`` not positive and finite.

    Examples
    --------
    >>> import scanline as sl
    >>> box = sl.radiosity.cornell_box()
    >>> box["names"][:5]
    ['floor', 'ceiling', 'back wall', 'right wall', 'left wall']
    >>> box["names"][5:]
    ['short block', 'tall block', 'light']
    >>> [m.face_count for m in box["meshes"]]
    [1, 4, 1, 1, 1, 5, 5, 1]
    """
    from .. import projection, transform3d
    from ..projection import Camera

    s = v.number("scale", scale)
    if not 0 < s < math.inf:
        raise ArgumentValueError(f"scale must be a positive finite number, got {scale!r}")
    names = ["floor", "ceiling", "back wall", "right wall", "left wall", "short block",
             "tall block", "light"]
    quads = dict(_SURFACES, ceiling=_ceiling(), light=[_LIGHT])
    # the light faces down into the room; the blocks' faces outward
    meshes = [_oriented(quads[n], inside=not n.endswith("block")) for n in names]
    meshes = [m.transformed(transform3d.scaling(s, s, s)) for m in meshes]
    emission = [LIGHT if n == "light" else (0.0, 0.0, 0.0) for n in names]
    camera = Camera(eye=(278.0 * s, 273.0 * s, -800.0 * s),
                    target=(278.0 * s, 273.0 * s, 0.0), up=(0.0, 1.0, 0.0),
                    projection=projection.perspective(fov=2 * math.atan(12.5 / 35.0),
                                                      near=100.0 * s, far=2000.0 * s))
    return {"meshes": meshes, "names": names,
            "reflectance": [COLORS[n] for n in names], "emission": emission,
            "camera": camera}
