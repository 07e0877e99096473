"""The :class:`Scene`: checked scene data, its display file and its outputs."""

import copy
import os

from ..display import RasterDevice, SVGDevice, VectorDevice, interpret
from ..framebuffer import FrameBuffer
from . import files
from .files import SceneError
from .locate import line_of
from .schema import build

#: Output types by extension: raster images, SVG, and the vector listing.
OUTPUTS = {".png": "raster", ".gif": "raster", ".bmp": "raster", ".svg": "svg",
           ".txt": "listing", ".vec": "listing"}


class Scene:
    """A checked scene.

    Parameters
    ----------
    data : dict
        The scene's data as parsed from TOML or JSON.
    file : str, optional
        The file it came from, named in error messages.
    text, format : str, optional
        The text it was parsed from and its format (``"toml"`` or ``"json"``): error
        messages then give the line of the bad value.

    Attributes
    ----------
    data : dict
        A copy of the data.
    canvas
        ``width``, ``height``, ``background``, ``mode``, ``highlight``, ``antialias``.
    display_file : DisplayFile
    """

    def __init__(self, data, file=None, text=None, format="toml"):
        try:
            base = None if file is None else os.path.dirname(os.path.abspath(file))
            self.canvas, self.display_file = build(data, base)
        except SceneError as error:
            line = None
            if text is not None and error.path is not None:
                line = line_of(text, format, error.path)
            raise SceneError(error.message, file=file, line=line, path=error.path) from None
        except RecursionError:
            raise SceneError("the data is nested too deeply to be a scene", file=file) from None
        self.data = copy.deepcopy(data)
        self.file = file

    def raster(self):
        """The scene drawn on a new :class:`~scanline.FrameBuffer`."""
        c = self.canvas
        fb = FrameBuffer(c.width, c.height, mode=c.mode, background=c.background)
        if c.shading is not None:
            c.shading.draw(fb)
        interpret(self.display_file, RasterDevice(fb, c.antialias), highlight=c.highlight)
        return fb

    def _no_surfaces(self, what):
        if self.canvas.shading is not None and self.canvas.shading.surfaces:
            raise SceneError(f"a scene with shaded surfaces (meshes with a material) draws "
                             f"to raster files only (.png, .gif, .bmp), not {what}")

    def svg(self):
        """The scene as an SVG document (text)."""
        self._no_surfaces("SVG")
        c = self.canvas
        device = SVGDevice(c.width, c.height, background=c.background)
        interpret(self.display_file, device, highlight=c.highlight)
        return device.svg()

    def vector(self):
        """The scene on a random-scan display: a :class:`~scanline.display.VectorDevice`."""
        self._no_surfaces("a vector display")
        device = VectorDevice(self.canvas.width, self.canvas.height)
        interpret(self.display_file, device, highlight=self.canvas.highlight)
        return device

    def render(self, path):
        """Write the scene to ``path``: ``.png``, ``.gif``, ``.bmp`` (raster), ``.svg``,
        or ``.txt`` / ``.vec`` (the MOVE/LINE listing).  Atomic: on any error no file
        is left at ``path``."""
        from ..framebuffer import write_atomically

        kind = OUTPUTS.get(os.path.splitext(os.fspath(path))[1].lower())
        if kind is None:
            raise SceneError(f"cannot write {os.fspath(path)!r}: use one of "
                             + ", ".join(OUTPUTS))
        if os.path.isdir(path):
            raise SceneError(f"cannot write {os.fspath(path)!r}: it is a folder; give a "
                             "file name")
        if kind == "raster":
            self.raster().save(path)
            return
        text = self.svg() if kind == "svg" else self.vector().listing()
        write_atomically(path, lambda f: f.write(text.encode("utf-8")))

    def dumps(self, format="toml"):
        """The scene's data as TOML or JSON text."""
        return files.dumps(self.data, format)


def loads(text, format="toml", file=None):
    """A :class:`Scene` from TOML or JSON text."""
    return Scene(files.loads(text, format, file), file, text, format)


def load(path, format=None):
    """A :class:`Scene` from a ``.toml`` or ``.json`` file (or ``format``)."""
    name = os.fspath(path)
    fmt = files.format_of(name, format)
    return loads(files.read_text(name), fmt, name)
