"""Materials as mesh files give them: a Wavefront ``.mtl`` material (``newmtl`` with
``Kd``, ``Ks``, ``Ns``, ``d``/``Tr``, ``map_Kd``) or a glTF material
(``pbrMetallicRoughness.baseColorFactor`` and ``baseColorTexture``), kept as a plain
record on the mesh (:attr:`Mesh.material`).

Geometry does not import the lighting (docs/architecture.md): the record holds the
file's values, and :func:`scanline.render` turns it into a
:class:`scanline.lighting.Material` when it prepares the scene.
"""

import math
import os
from dataclasses import dataclass
from typing import Dict, List, NoReturn, Optional, Tuple, TypedDict

#: An (r, g, b) reflectance, each in 0..1.
RGB = Tuple[float, float, float]


@dataclass(frozen=True)
class MaterialRecord:
    """A material read from a mesh file.

    Parameters
    ----------
    name : str
        The file's name for it (``newmtl NAME``; a glTF material's name or index).
    kd : (r, g, b) in 0..1
        The diffuse reflectance (MTL ``Kd``; glTF ``baseColorFactor``).
    ks : (r, g, b) in 0..1, or None
        The specular reflectance (MTL ``Ks``); None: the renderer's default.
    ns : float >= 0, or None
        The specular exponent (MTL ``Ns``); None: the renderer's default.
    d : float in 0..1
        Opacity ("dissolve": MTL ``d``, or 1 - ``Tr``; glTF's base color alpha).
    map_kd : str, or None
        The diffuse texture: a path (resolved against the material file's folder) or
        a glTF reference such as ``"image 0"``, kept for texturing.

    Examples
    --------
    >>> from scanline.mesh import MaterialRecord
    >>> brick = MaterialRecord("brick", kd=(0.6, 0.2, 0.1))
    >>> brick.d, brick.ks is None
    (1.0, True)
    """
    name: str
    kd: RGB = (0.8, 0.8, 0.8)
    ks: Optional[RGB] = None
    ns: Optional[float] = None
    d: float = 1.0
    map_kd: Optional[str] = None

    @property
    def diffuse_rgb255(self) -> Tuple[int, int, int]:
        """``kd`` as an (r, g, b) of integers 0..255 (a face color).

        Returns
        -------
        tuple of int
            ``round(255 * c)`` of each component, clamped to 0..1 first.

        Examples
        --------
        >>> from scanline.mesh import MaterialRecord
        >>> MaterialRecord("brick", kd=(0.6, 0.2, 1.5)).diffuse_rgb255
        (153, 51, 255)
        """
        r, g, b = (int(round(255 * min(max(c, 0.0), 1.0))) for c in self.kd)
        return r, g, b


def _unit(x: float) -> float:
    return min(max(x, 0.0), 1.0)


class _Fields(TypedDict, total=False):
    """The statements of one ``newmtl`` block read so far (MaterialRecord's fields)."""
    kd: RGB
    ks: RGB
    ns: float
    d: float
    map_kd: str


def read_mtl(data: bytes, filename: str) -> Dict[str, MaterialRecord]:
    """The materials of the ``.mtl`` bytes ``data`` as ``{name: MaterialRecord}``.

    Reflectances are clamped to 0..1; a statement this module does not use (``Ka``,
    ``Ke``, ``illum``, other maps) is skipped.  A malformed value is a
    :class:`~scanline.mesh.files.MeshFileError` naming the file and the line."""
    from .files import MeshFileError

    folder = os.path.dirname(os.path.abspath(filename))
    materials: Dict[str, _Fields] = {}
    current = None

    def fail(number: int, message: str) -> NoReturn:
        raise MeshFileError(f"line {number}: {message}", file=filename)

    def numbers(number: int, words: List[str], count: int) -> List[float]:
        try:
            values = [float(w) for w in words[1:1 + count]]
        except ValueError:
            fail(number, f"{words[0]} needs numbers, got {' '.join(words[1:])!r}")
        if not values or not all(math.isfinite(x) for x in values):
            fail(number, f"{words[0]} needs finite numbers, got {' '.join(words[1:])!r}")
        return values

    for number, raw in enumerate(data.split(b"\n"), 1):
        text = raw.split(b"#", 1)[0].decode("utf-8", errors="replace").strip()
        words = text.split()
        if not words:
            continue
        key = words[0].lower()
        if key == "newmtl":
            if len(words) < 2:
                fail(number, "newmtl needs a name")
            current = text.split(None, 1)[1]
            materials[current] = {}
            continue
        if current is None:
            continue
        fields = materials[current]
        if key in ("kd", "ks"):
            values = numbers(number, words, 3)
            r, g, b = (_unit(values[k] if k < len(values) else values[0]) for k in range(3))
            if key == "kd":
                fields["kd"] = (r, g, b)
            else:
                fields["ks"] = (r, g, b)
        elif key == "ns":
            fields["ns"] = max(numbers(number, words, 1)[0], 0.0)
        elif key == "d":
            fields["d"] = _unit(numbers(number, words, 1)[-1])
        elif key == "tr":
            fields["d"] = 1.0 - _unit(numbers(number, words, 1)[-1])
        elif key == "map_kd" and len(words) > 1:
            # options (-s 1 1 1, -bm 2 ...) come before the file name: the last word
            fields["map_kd"] = os.path.join(folder, words[-1].replace("\\", "/"))
    return {name: MaterialRecord(name, **fields) for name, fields in materials.items()}
