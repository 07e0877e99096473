"""The shadow-map pass of the renderer: shadows by shadow depth maps (Williams 1978),
the extra beyond the notes: the scene's depth buffer as seen from each light; a point is in shadow for that light
when something lies nearer the light along its line of sight than the point itself
(a depth farther than the map's, by more than a small bias)."""

import math
from typing import TYPE_CHECKING, Any, Iterable, List, Optional, Tuple

import numpy as np
from numpy.typing import NDArray

if TYPE_CHECKING:
    from ..lighting.lights import Light
    from ..projection import Camera
    from ..screen.scene import ScreenScene

#: Side of each shadow map, in texels.
SIZE = 1024
#: Depth bias (NDC units of the light's view) against self-shadowing "acne".
BIAS = 2e-3


class ShadowMaps:
    """The shadow maps of ``lights`` (those made with ``shadows=True``) over the
    meshes of a prepared ``scene``; :meth:`visibility` answers per point."""

    def __init__(self, meshes: Any, scene: "ScreenScene", lights: Iterable["Light"],
                 size: int = SIZE, bias: float = BIAS) -> None:
        from ..lighting import AmbientLight, DirectionalLight
        from ..projection import Camera, orthographic, perspective
        from ..screen import prepare
        from ..visible.zbuffer import nearest

        self.size, self.bias = size, bias
        world = scene.world.reshape(-1, 3)
        lo, hi = (world.min(axis=0), world.max(axis=0)) if len(world) else (np.zeros(3),) * 2
        center = (lo + hi) / 2
        radius = max(float(np.linalg.norm(hi - lo)) / 2, 1e-9)
        self.maps: List[Optional[Tuple["Camera", NDArray[np.float64]]]] = []
        for light in (x for x in lights if not isinstance(x, AmbientLight)):
            if not light.shadows:
                self.maps.append(None)
                continue
            if isinstance(light, DirectionalLight):
                d = light.direction
                up = (0, 1, 0) if abs(d[1]) < 0.9 else (1, 0, 0)
                cam = Camera(eye=center - 2 * radius * d, target=center, up=up,
                             projection=orthographic(window=(-radius, -radius, radius, radius),
                                                     front=-radius, back=-3 * radius))
            else:
                p = light.position
                dist = float(np.linalg.norm(center - p))
                d = (center - p) / dist if dist > 0 else np.array([0, 0, -1.0])
                up = (0, 1, 0) if abs(d[1]) < 0.9 else (1, 0, 0)
                half = math.asin(min(radius / dist, 0.999)) if dist > radius else 1.4
                cam = Camera(eye=p, target=p + d, up=up,
                             projection=perspective(fov=2 * half, near=max(dist - radius, 1e-3)
                                                    * 0.5, far=dist + radius))
            self.maps.append((cam, nearest(prepare(meshes, cam, size, size)).depth.copy()))

    def __call__(self, points: NDArray[np.float64]) -> List[NDArray[np.float64]]:
        """Per non-ambient light, 1.0 where ``points`` (M, 3) see it, 0.0 where they
        are in its shadow (1.0 everywhere for lights without shadows)."""
        out: List[NDArray[np.float64]] = []
        for entry in self.maps:
            if entry is None:
                out.append(np.ones(len(points)))
                continue
            cam, depth = entry
            p = cam.project(points, self.size, self.size)
            x = np.rint(p[:, 0])
            y = np.rint(p[:, 1])
            ok = np.isfinite(p).all(axis=1) & (x >= 0) & (x < self.size) & (y >= 0) & \
                (y < self.size)
            lit = np.ones(len(points))
            xi, yi = x[ok].astype(np.int64), y[ok].astype(np.int64)
            lit[ok] = (p[ok, 2] <= depth[yi, xi] + self.bias).astype(np.float64)
            out.append(lit)
        return out
