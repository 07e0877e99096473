"""Environment maps (Hearn & Baker, section 14-8): the surroundings of a scene as a
cube map -- six square images on the faces of a cube around the viewer, looked up in
a direction by its major axis (OpenGL's convention: The OpenGL Graphics System 4.6,
section 8.13, "Cube Map Texture Selection", table 8.19) -- or as a
latitude-longitude map (one :class:`~scanline.texture.Texture`).  Both serve as
``Material(environment=...)``: the shading looks them up in the reflected view
direction, the ray tracer in the direction of each ray that leaves the scene.
"""

from typing import Dict, List, Sequence, Tuple, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError
from .texture import ImageSource, Packed, Texture, _image_array

#: The faces in OpenGL's order, and the order of ``CubeMap(faces)``.
FACES = ("+x", "-x", "+y", "-y", "+z", "-z")

#: Where each face sits in the horizontal cross layout (column, row of a 4 x 3 grid
#: of faces, top row 0): +y above +z, -y below it, and -x, +z, +x, -z across the
#: middle -- the arrangement in which OpenGL's faces meet edge to edge.
CROSS = {"+x": (2, 1), "-x": (0, 1), "+y": (1, 0), "-y": (1, 2), "+z": (1, 1), "-z": (3, 1)}

#: Per face, the direction (x, y, z) of the face point (s_c, t_c) (each -1..1, s_c to
#: the right, t_c down the image): the inverse of OpenGL's table 8.19, as the rows
#: that s_c, t_c and 1 multiply.
FACE_AXES = np.array([
    [[0, 0, -1], [0, -1, 0], [1, 0, 0]],     # +x: (1, -t_c, -s_c)
    [[0, 0, 1], [0, -1, 0], [-1, 0, 0]],     # -x: (-1, -t_c, s_c)
    [[1, 0, 0], [0, 0, 1], [0, 1, 0]],       # +y: (s_c, 1, t_c)
    [[1, 0, 0], [0, 0, -1], [0, -1, 0]],     # -y: (s_c, -1, -t_c)
    [[1, 0, 0], [0, -1, 0], [0, 0, 1]],      # +z: (s_c, -t_c, 1)
    [[-1, 0, 0], [0, -1, 0], [0, 0, -1]],    # -z: (-s_c, -t_c, -1)
], np.float64)

#: Filters of a cube map's faces (looked up at their finest level).
CUBE_FILTERS = ("nearest", "bilinear")


def _cross_faces(image: object) -> List[NDArray[np.float64]]:
    """The six faces (+x, -x, +y, -y, +z, -z) cut out of a horizontal cross image."""
    a = _image_array("faces", image)
    h, w = a.shape[:2]
    if w * 3 != h * 4:
        raise ArgumentValueError(
            f"faces: a single image must be a horizontal cross of 4 x 3 square faces (width "
            f"4 n, height 3 n), got {w} x {h}; or give the six faces +x, -x, +y, -y, +z, -z")
    n = h // 3
    return [a[r * n:(r + 1) * n, c * n:(c + 1) * n] for c, r in (CROSS[f] for f in FACES)]


class CubeMap:
    """An environment map on the six faces of a cube (Hearn & Baker 14-8).

    Parameters
    ----------
    faces : six images, or one image
        The faces +x, -x, +y, -y, +z, -z in OpenGL's convention (each an (n, n) or (n,
        n, 3|4) array of uint8 0..255 or reals 0..1, a Pillow image or a file, top
        row first; all square and of one size), or one image holding them as a
        horizontal cross (4 n x 3 n: +y above +z, -y below, -x, +z, +x, -z across).
        Face (s_c, t_c) coordinates follow OpenGL's table 8.19: on +z, s_c = x to the
        right and t_c = -y down the image.
    filter : {"nearest", "bilinear"}
        Texel lookup in a face (at its finest level); bilinear clamps at the face's
        edges.

    Examples
    --------
    >>> import numpy as np, scanline as sl
    >>> faces = [np.full((2, 2, 3), 40 * k, np.uint8) for k in range(6)]
    >>> cube = sl.texture.CubeMap(faces, filter="nearest")
    >>> (cube.sample([[0, 0, -1], [0, 2, 0]]) * 255).round().tolist()
    [[200.0, 200.0, 200.0], [80.0, 80.0, 80.0]]
    """

    def __init__(self, faces: Union[Sequence[ImageSource], ImageSource],
                 filter: str = "bilinear") -> None:
        self.filter = v.choice("filter", filter, CUBE_FILTERS)
        if isinstance(faces, (list, tuple)):
            if len(faces) != 6:
                raise ArgumentValueError(f"faces must be six images (+x, -x, +y, -y, +z, -z) "
                                         f"or one cross image, got {len(faces)} items")
            arrays = [_image_array(f"faces[{i}] ({FACES[i]})", f) for i, f in enumerate(faces)]
        else:
            arrays = _cross_faces(faces)
        n = arrays[0].shape[0]
        for name, a in zip(FACES, arrays):
            if a.shape[0] != a.shape[1] or a.shape[0] != n:
                raise ArgumentValueError(
                    f"faces: every face must be square and of one size ({n} x {n} like "
                    f"+x), face {name} is {a.shape[1]} x {a.shape[0]}")
        self.faces = tuple(Texture(a, filter=self.filter, wrap="clamp") for a in arrays)
        self._kept: Dict[float, Packed] = {}

    @property
    def size(self) -> int:
        """The side of each face, in texels."""
        return self.faces[0].width

    @classmethod
    def from_latitude_longitude(cls, texture: Union[Texture, ImageSource], size: int = 256,
                                filter: str = "bilinear") -> "CubeMap":
        """The cube map of ``size`` x ``size`` faces whose texels are the
        latitude-longitude map ``texture`` (a :class:`Texture` or image) looked up in
        the directions of their centers.

        Parameters
        ----------
        texture : Texture or image
            The latitude-longitude map.
        size : int
            Texels a side of each face, 1..4096.
        filter : {"nearest", "bilinear"}
            The cube map's filter.

        Returns
        -------
        CubeMap
            The six faces.

        Raises
        ------
        ArgumentValueError
            ``size`` outside 1..4096.
        ArgumentTypeError
            ``texture`` neither a Texture nor an image.

        Notes
        -----
        Hearn & Baker 14-8, "Environment mapping".

        Examples
        --------
        >>> import numpy as np, scanline as sl
        >>> gray = sl.Texture(np.full((2, 4, 3), 128, np.uint8))
        >>> cube = sl.texture.CubeMap.from_latitude_longitude(gray, size=2)
        >>> cube.size, (cube.sample([[1, 0, 0]]) * 255).round().tolist()
        (2, [[128.0, 128.0, 128.0]])
        """
        from .texture import texture_of

        n = v.positive_int("size", size)
        if n > 4096:
            raise ArgumentValueError(f"size must be 1..4096 texels a side, got {n}")
        lat_long = texture_of("texture", texture)
        if not isinstance(lat_long, Texture):
            raise ArgumentTypeError(f"texture must be a latitude-longitude Texture or image, "
                                    f"got {v._show(texture)}")
        c = (np.arange(n) + 0.5) / n * 2 - 1
        sc, tc = np.meshgrid(c, c)
        st1 = np.stack([sc, tc, np.ones_like(sc)], axis=-1)               # (n, n, 3)
        directions = np.einsum("ijk,fkl->fijl", st1, FACE_AXES).reshape(-1, 3)
        colors = environment_colors(lat_long, directions).reshape(6, n, n, 3)
        return cls(list(np.clip(colors, 0.0, 1.0)), filter=filter)

    def kernel_arrays(self, gamma: float = 1.0) -> Packed:
        """``(texels, levels)`` of the six faces one after another (face k's level is
        row k), the texels decoded with ``gamma``.  Kept per gamma.

        Parameters
        ----------
        gamma : float
            Decodes the stored values (1: as stored).

        Returns
        -------
        texels : ndarray (3 N,) float32
            The faces' texels, as :meth:`Texture.kernel_arrays` packs them.
        levels : ndarray (6, 3) int64
            Each face's first texel, width and height.

        Examples
        --------
        >>> import numpy as np, scanline as sl
        >>> cube = sl.texture.CubeMap([np.zeros((1, 1, 3), np.uint8)] * 6)
        >>> texels, levels = cube.kernel_arrays()
        >>> len(texels), levels[:, 0].tolist()
        (18, [0, 1, 2, 3, 4, 5])
        """
        from .mipmap import joined

        gamma = float(gamma)
        if gamma not in self._kept:
            if len(self._kept) >= 4:
                self._kept.clear()
            texels, table, _ = joined([f.kernel_arrays(gamma) for f in self.faces])
            texels.flags.writeable = table.flags.writeable = False
            self._kept[gamma] = texels, table
        return self._kept[gamma]

    def sample(self, directions: ArrayLike, gamma: float = 1.0) -> NDArray[np.float64]:
        """The map's colors (M, 3) in ``directions`` (M, 3), stored values 0..1
        (``gamma``: decoded with it).

        Parameters
        ----------
        directions : array_like (M, 3) or (3,)
            Finite, non-zero directions (any length).
        gamma : float
            Decodes the stored values (1: as stored).

        Returns
        -------
        ndarray (M, 3) float64
            The colors, each from the face of its direction's major axis.

        Raises
        ------
        ArgumentValueError
            Directions not (M, 3), not finite, or zero.

        Examples
        --------
        >>> import numpy as np, scanline as sl
        >>> faces = [np.full((1, 1, 3), 50 * k, np.uint8) for k in range(6)]
        >>> cube = sl.texture.CubeMap(faces)
        >>> (cube.sample([[0, -3, 1], [0.5, 0, -2]])[:, 0] * 255).round().tolist()  # -y, -z
        [150.0, 250.0]
        """
        return environment_colors(self, checked_directions(directions), gamma)

    def __repr__(self) -> str:
        return f"<CubeMap 6 x {self.size}x{self.size} {self.filter}>"


def checked_directions(directions: ArrayLike, name: str = "directions") -> NDArray[np.float64]:
    """``directions`` as a (M, 3) float64 array of finite, non-zero vectors."""
    d = v.real_array(name, directions, "(M, 3)")
    d = d.reshape(1, 3) if d.shape == (3,) else d
    if d.ndim != 2 or d.shape[1] != 3:
        raise ArgumentValueError(f"{name} must have shape (M, 3), got {d.shape}")
    if not np.isfinite(d).all():
        raise ArgumentValueError(f"{name} must be finite vectors; it holds NaN or infinite "
                                 f"values")
    if len(d) and not (np.abs(d).max(axis=1) > 0).all():
        raise ArgumentValueError(f"{name} must be non-zero vectors; it holds (0, 0, 0)")
    return np.ascontiguousarray(d)


def environment_of(name: str, value: object) -> Union["CubeMap", Texture, None]:
    """``value`` as an environment map: a :class:`CubeMap` kept, anything else a
    latitude-longitude :class:`Texture` (:func:`scanline.texture.texture.texture_of`)."""
    from .texture import texture_of

    return value if isinstance(value, CubeMap) else texture_of(name, value)


def environment_arrays(environment: Union[CubeMap, Texture], gamma: float
                       ) -> Tuple[NDArray[np.float32], NDArray[np.int64], int, int, int, int]:
    """The kernel's description of ``environment`` (a :class:`CubeMap` or a
    latitude-longitude :class:`Texture`): ``(texels, levels, count of levels a face,
    filter code, wrap code, kind)`` (:mod:`scanline._kernels.environment`)."""
    from .._kernels.environment import CUBE, LATITUDE_LONGITUDE
    from .texture import FILTER_CODES, WRAP_CODES

    texels, table = environment.kernel_arrays(gamma)
    if isinstance(environment, CubeMap):
        return (texels, table, len(table) // 6, FILTER_CODES[environment.filter],
                WRAP_CODES["clamp"], CUBE)
    return (texels, table, len(table), FILTER_CODES[environment.filter],
            WRAP_CODES[environment.wrap], LATITUDE_LONGITUDE)


def environment_colors(environment: Union[CubeMap, Texture], directions: ArrayLike,
                       gamma: float = 1.0) -> NDArray[np.float64]:
    """The colors (M, 3) of ``environment`` (cube or latitude-longitude) in
    ``directions`` (M, 3) (any length, not checked), decoded with ``gamma``."""
    from .._kernels import environment as k
    from .._kernels._jit import call

    texels, table, count, filter, wrap, kind = environment_arrays(environment, gamma)
    d = np.ascontiguousarray(directions, np.float64)
    out = np.empty((len(d), 3))
    call(k.environment_points, 8 * len(d), texels, table, 0, count, filter, wrap, kind, d, out)
    return out
