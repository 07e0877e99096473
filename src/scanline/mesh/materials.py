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
from typing import Optional


@dataclass(frozen=True)
class MaterialRecord:
    """A material read from a mesh file.

    Attributes
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
    """
    name: str
    kd: tuple = (0.8, 0.8, 0.8)
    ks: Optional[tuple] = None
    ns: Optional[float] = None
    d: float = 1.0
    map_kd: Optional[str] = None

    @property
    def diffuse_rgb255(self):
        """``kd`` as an (r, g, b) of integers 0..255 (a face color)."""
        return tuple(int(round(255 * min(max(c, 0.0), 1.0))) for c in self.kd)


def _unit(x):
    return min(max(x, 0.0), 1.0)


def read_mtl(data, filename):
    """The materials of the ``.mtl`` bytes ``data`` as ``{name: MaterialRecord}``.

    Reflectances are clamped to 0..1; a statement this module does not use (``Ka``,
    ``Ke``, ``illum``, other maps) is skipped.  A malformed value is a
    :class:`~scanline.mesh.files.MeshFileError` naming the file and the line."""
    from .files import MeshFileError

    folder = os.path.dirname(os.path.abspath(filename))
    materials = {}
    current = None

    def fail(number, message):
        raise MeshFileError(f"line {number}: {message}", file=filename)

    def numbers(number, words, count):
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
            materials[current] = {"name": current}
            continue
        if current is None:
            continue
        fields = materials[current]
        if key in ("kd", "ks"):
            values = numbers(number, words, 3)
            rgb = tuple(_unit(values[k] if k < len(values) else values[0]) for k in range(3))
            fields[key] = rgb
        elif key == "ns":
            fields["ns"] = max(numbers(number, words, 1)[0], 0.0)
        elif key == "d":
            fields["d"] = _unit(numbers(number, words, 1)[-1])
        elif key == "tr":
            fields["d"] = 1.0 - _unit(numbers(number, words, 1)[-1])
        elif key == "map_kd" and len(words) > 1:
            # options (-s 1 1 1, -bm 2 ...) come before the file name: the last word
            fields["map_kd"] = os.path.join(folder, words[-1].replace("\\", "/"))
    return {name: MaterialRecord(**fields) for name, fields in materials.items()}
