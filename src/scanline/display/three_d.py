"""3-D primitives in the display file: polylines and meshes kept in world
coordinates with the name of the camera they are seen through, projected by the
interpreter each time it draws the file (so moving a camera and interpreting again
shows the new view, as a display file regenerates its picture).

At interpretation, each 3-D primitive is clipped against its camera's view volume
in homogeneous coordinates and projected into its viewport (the NDC viewport that
was current when it was made, with the device's aspect ratio), giving ordinary
polyline primitives in NDC; the segment transformation, the viewport clip and the
device follow as for 2-D primitives.
"""

from typing import TYPE_CHECKING, Any, Sequence

import numpy as np
from numpy.typing import NDArray

from ..draw3d.wireframe import (cue_factor, depth_cue_intensities, edge_colors,
                                pieces_into, project_edges_into)
from ..color.spec import Channels
from .primitives import Primitive

if TYPE_CHECKING:
    from .file import DisplayFile

KINDS = ("polyline3d", "mesh")


def _aspect(rect: Sequence[float], width: int, height: int) -> float:
    """The displayed width / height of the NDC rectangle ``rect`` on the device."""
    return ((rect[2] - rect[0]) * (width - 1)) / ((rect[3] - rect[1]) * (height - 1))


def _blend(rgba: NDArray[np.uint8], background: Any, f: NDArray[np.float64]) -> NDArray[np.uint8]:
    """Colors faded toward ``background`` by the factors ``f`` (depth cueing)."""
    from ..color.spec import rgba as to_rgba

    bg = np.array(to_rgba(background, "background"), np.float64)
    out = np.rint(bg + f[:, None] * (rgba.astype(np.float64) - bg))
    return np.clip(out, 0, 255).astype(np.uint8)


def expand(primitives: Sequence[Primitive], display_file: "DisplayFile", width: int,
           height: int) -> list[Primitive]:
    """``primitives`` with each 3-D primitive replaced by the 2-D polylines (in NDC)
    of its visible parts for a ``width`` x ``height`` device."""
    out: list[Primitive] = []
    for prim in primitives:
        if prim.kind not in KINDS:
            out.append(prim)
            continue
        g, a = prim.geometry, prim.attributes
        camera = display_file.camera(g["camera"])
        rect = g["viewport"]
        aspect = _aspect(rect, width, height)
        if prim.kind == "polyline3d":
            for piece in pieces_into(g["points"], camera, rect, a["closed"], aspect):
                out.append(Primitive("polyline", {"points": piece},
                                     {**a["line"], "closed": False}, prim.clip))
            continue
        mesh = g["mesh"]
        segs, depth, which = project_edges_into(mesh.vertices, mesh.edges, camera, rect, aspect)
        if not len(segs):
            continue
        cue = depth_cue_intensities(a["depth_cue"])
        colors = None
        if a["color"] is None and mesh.colors is not None:
            colors = edge_colors(mesh, mesh.edges)[which]
        if cue is not None:
            from ..color.spec import rgba

            if colors is None:
                colors = np.repeat(np.array(rgba(a["color"] or "white"), np.uint8)[None],
                                   len(segs), axis=0)
            colors = _blend(colors, a["background"], cue_factor(camera, depth, cue))
        line = a["line"]
        for i, s in enumerate(segs):
            attrs = dict(line, closed=False)
            if colors is not None:
                attrs["color"] = Channels(int(c) for c in colors[i])
            out.append(Primitive("polyline", {"points": s.reshape(2, 2)}, attrs, prim.clip))
    return out
