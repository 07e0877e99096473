"""What :func:`scanline.render` hands back: :class:`Rendering`."""

import functools
from typing import TYPE_CHECKING, Any, Optional

import numpy as np
from numpy.typing import NDArray

if TYPE_CHECKING:
    from ..depthbuffer import DepthBuffer
    from ..framebuffer import FrameBuffer
    from ..screen.polygons import ScreenPolygons
    from ..screen.scene import ScreenScene


class Rendering:
    """What :func:`scanline.render` drew.

    Parameters
    ----------
    method : str
        The visible-surface method that drew it.
    image : FrameBuffer
        The frame buffer drawn into.
    depth : DepthBuffer
        The depth at each pixel.
    facets : ndarray of int32 (H, W)
        The facet seen at each pixel (-1: none), rows bottom-up.
    scene : ScreenScene
        The prepared scene.
    pieces : ScreenPolygons, optional
        An object-order method's pieces in drawing order.
    solids : ndarray of int64 (H, W), optional
        The solid seen at each pixel (default: none anywhere).

    Attributes
    ----------
    method : str
        The method's name.
    image : FrameBuffer
        The frame buffer drawn into.
    depth : DepthBuffer
        The depth of the visible surface at each pixel (inf where none; the front
        layer's at each pixel's central sample for the A-buffer).
    facets : ndarray of int32 (H, W)
        The facet (a triangle of a face's fan, numbered in ``scene``) seen at each
        pixel, -1 for the background; rows bottom-up like the depth buffer's array.
    scene : ScreenScene
        The prepared scene.
    pieces : ScreenPolygons or None
        For an object-order method, the pieces in drawing order (``face`` holds
        their facets).
    faces : ndarray of int (H, W)
        The face seen at each pixel (the meshes' faces numbered mesh after mesh;
        -1: none), ``faces[y, x]``.
    meshes : ndarray of int (H, W)
        The mesh (its index in the list given) seen at each pixel (-1: none).
    solids : ndarray of int64 (H, W)
        The solid (:mod:`scanline.solids`, its index among the solids given) seen at
        each pixel (-1: none; all -1 when no solid was given).

    Examples
    --------
    A 2 x 2 cube seen head on through a 4 x 4 window: its front face (face 5, z = 1)
    covers the pixel centers at x, y = -0.5 and 0.5.

    >>> import scanline as sl
    >>> fb = sl.FrameBuffer(4, 4, mode="L")
    >>> cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0),
    ...                 projection=sl.projection.orthographic(window=(-2, -2, 2, 2)))
    >>> r = sl.render(fb, sl.mesh.cube(2), cam, shading="none")
    >>> r
    <Rendering method='z-buffer' 4x4: 1 mesh(es), 6 faces, 4 of 16 pixels covered>
    >>> r.meshes.tolist()[1]
    [-1, 0, 0, -1]
    """

    def __init__(self, method: str, image: "FrameBuffer", depth: "DepthBuffer",
                 facets: NDArray[np.int32], scene: "ScreenScene",
                 pieces: Optional["ScreenPolygons"] = None,
                 solids: Optional[NDArray[np.int64]] = None) -> None:
        if solids is not None:
            self.solids = solids       # else made when first read (a frame's worth of -1)
        self.method = method
        self.image = image
        self.depth = depth
        self.facets = facets
        self.scene = scene
        self.pieces = pieces

    @functools.cached_property
    def solids(self) -> NDArray[np.int64]:
        return np.full(self.facets.shape, -1, np.int64)

    @functools.cached_property
    def faces(self) -> NDArray[np.signedinteger[Any]]:
        f = self.scene.facet_face
        if len(f) == self.scene.face_count:         # every face is one triangle
            return self.facets
        return np.where(self.facets >= 0, f[np.maximum(self.facets, 0)], -1)

    @functools.cached_property
    def meshes(self) -> NDArray[np.signedinteger[Any]]:
        m = self.scene.face_mesh
        return np.where(self.faces >= 0, m[np.maximum(self.faces, 0)], -1) if len(m) \
            else self.faces

    def face_image(self) -> NDArray[np.signedinteger[Any]]:
        """``faces`` in image order (top row first).

        Returns
        -------
        ndarray of int (H, W)
            The face seen at each pixel (-1: none), a copy, top row first.

        Examples
        --------
        The cube of :class:`Rendering`'s example: its front face is face 5 (the
        vertices 4, 5, 7, 6 of ``sl.mesh.cube``, all at z = 1).

        >>> import scanline as sl
        >>> fb = sl.FrameBuffer(4, 4, mode="L")
        >>> cam = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0),
        ...                 projection=sl.projection.orthographic(window=(-2, -2, 2, 2)))
        >>> sl.render(fb, sl.mesh.cube(2), cam, shading="none").face_image().tolist()
        [[-1, -1, -1, -1], [-1, 5, 5, -1], [-1, 5, 5, -1], [-1, -1, -1, -1]]
        """
        image: NDArray[np.signedinteger[Any]] = self.faces[::-1].copy()
        return image

    def __repr__(self) -> str:
        covered = int(((self.facets >= 0) | (self.solids >= 0)).sum())
        s = self.scene
        solids = len(np.unique(self.solids[self.solids >= 0]))
        return (f"<Rendering method={self.method!r} {s.width}x{s.height}: "
                f"{len(s.materials)} mesh(es), {s.face_count} faces, "
                f"{f'{solids} solid(s) seen, ' if solids else ''}{covered} of "
                f"{s.width * s.height} pixels covered>")

    def _repr_png_(self) -> bytes:
        """The frame buffer's image, so that a notebook shows a rendering as a picture."""
        return self.image._repr_png_()
