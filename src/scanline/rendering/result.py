"""What :func:`scanline.render` hands back: :class:`Rendering`."""

import functools

import numpy as np


class Rendering:
    """What :func:`scanline.render` drew.

    Attributes
    ----------
    method : str
    image : FrameBuffer
        The frame buffer drawn into.
    depth : DepthBuffer
        The depth of the visible surface at each pixel (inf where none; the front
        layer's at each pixel's central sample for the A-buffer).
    facets : ndarray of int64 (H, W)
        The facet (a triangle of a face's fan, numbered in ``scene``) seen at each
        pixel, -1 for the background; rows bottom-up like the depth buffer's array.
    scene : ScreenScene
        The prepared scene.
    pieces : ScreenPolygons or None
        For an object-order method, the pieces in drawing order (``face`` holds
        their facets).
    faces : ndarray of int64 (H, W)
        The face seen at each pixel (the meshes' faces numbered mesh after mesh;
        -1: none), ``faces[y, x]``.
    meshes : ndarray of int64 (H, W)
        The mesh (its index in the list given) seen at each pixel (-1: none).
    solids : ndarray of int64 (H, W)
        The solid (:mod:`scanline.solids`, its index among the solids given) seen at
        each pixel (-1: none; all -1 when no solid was given).
    """

    def __init__(self, method, image, depth, facets, scene, pieces=None, solids=None):
        if solids is not None:
            self.solids = solids       # else made when first read (a frame's worth of -1)
        self.method = method
        self.image = image
        self.depth = depth
        self.facets = facets
        self.scene = scene
        self.pieces = pieces

    @functools.cached_property
    def solids(self):
        return np.full(self.facets.shape, -1, np.int64)

    @functools.cached_property
    def faces(self):
        f = self.scene.facet_face
        if len(f) == self.scene.face_count:         # every face is one triangle
            return self.facets
        return np.where(self.facets >= 0, f[np.maximum(self.facets, 0)], -1)

    @functools.cached_property
    def meshes(self):
        m = self.scene.face_mesh
        return np.where(self.faces >= 0, m[np.maximum(self.faces, 0)], -1) if len(m) \
            else self.faces

    def face_image(self):
        """``faces`` in image order (top row first)."""
        return self.faces[::-1].copy()

    def __repr__(self):
        covered = int(((self.facets >= 0) | (self.solids >= 0)).sum())
        s = self.scene
        solids = len(np.unique(self.solids[self.solids >= 0]))
        return (f"<Rendering method={self.method!r} {s.width}x{s.height}: "
                f"{len(s.materials)} mesh(es), {s.face_count} faces, "
                f"{f'{solids} solid(s) seen, ' if solids else ''}{covered} of "
                f"{s.width * s.height} pixels covered>")

    def _repr_png_(self):
        """The frame buffer's image, so that a notebook shows a rendering as a picture."""
        return self.image._repr_png_()
