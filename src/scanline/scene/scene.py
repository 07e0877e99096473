"""The :class:`Scene`: checked scene data, its display file and its outputs."""

import copy
import os
from typing import Any

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

    Raises
    ------
    SceneError
        If the data is not a valid scene; the message names the key path (and the
        file and line when ``file`` and ``text`` are given).

    Notes
    -----
    The scene's segments become display-file segments (Hearn & Baker, chapter 7);
    docs/scene-format.md describes the schema.

    Examples
    --------
    >>> import scanline as sl
    >>> scene = sl.scene.Scene({"version": 1, "canvas": {"width": 7, "height": 5,
    ...     "background": "black"}, "segments": [{"name": "triangle", "primitives": [
    ...     {"type": "polygon", "points": [[0, 0], [6, 0], [3, 4]]}]}]})
    >>> scene.canvas.width, scene.display_file.segment("triangle").name
    (7, 'triangle')
    """

    def __init__(self, data: dict[str, Any], file: str | None = None,
                 text: str | None = None, format: str = "toml") -> None:
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

    def raster(self) -> FrameBuffer:
        """The scene drawn on a new :class:`~scanline.FrameBuffer`.

        Returns
        -------
        FrameBuffer
            The canvas's size, mode and background, with the segments drawn.

        Examples
        --------
        Pixel centers on the base (y = 0) are outside by the fill rule's top-left
        convention (DESIGN.md, convention 2):

        >>> import scanline as sl
        >>> scene = sl.scene.Scene({"version": 1, "canvas": {"width": 7, "height": 5,
        ...     "background": "black"}, "segments": [{"name": "triangle", "primitives": [
        ...     {"type": "polygon", "points": [[0, 0], [6, 0], [3, 4]]}]}]})
        >>> print(sl.text_image(scene.raster()))
        -------
        ---#---
        --###--
        -#####-
        -------
        """
        c = self.canvas
        fb = FrameBuffer(c.width, c.height, mode=c.mode, background=c.background)
        if c.shading is not None:
            c.shading.draw(fb)
        interpret(self.display_file, RasterDevice(fb, c.antialias), highlight=c.highlight)
        return fb

    def _no_surfaces(self, what: str) -> None:
        if self.canvas.shading is not None and self.canvas.shading.surfaces:
            raise SceneError(f"a scene with shaded surfaces (meshes with a material) draws "
                             f"to raster files only (.png, .gif, .bmp), not {what}")

    def svg(self) -> str:
        """The scene as an SVG document (text).

        Returns
        -------
        str

        Raises
        ------
        SceneError
            If the scene has shaded surfaces (raster only).

        Examples
        --------
        >>> import scanline as sl
        >>> scene = sl.scene.Scene({"version": 1, "canvas": {"width": 7, "height": 5,
        ...     "background": "black"}, "segments": [{"name": "triangle", "primitives": [
        ...     {"type": "polygon", "points": [[0, 0], [6, 0], [3, 4]]}]}]})
        >>> print(scene.svg().splitlines()[3])
        <path d="M0.5 4.5 L6.5 4.5 L3.5 0.5 Z" fill-rule="evenodd" fill="rgb(255,255,255)"/>
        """
        self._no_surfaces("SVG")
        c = self.canvas
        device = SVGDevice(c.width, c.height, background=c.background)
        interpret(self.display_file, device, highlight=c.highlight)
        return device.svg()

    def vector(self) -> VectorDevice:
        """The scene on a random-scan display: a :class:`~scanline.display.VectorDevice`.

        Returns
        -------
        VectorDevice
            Its ``listing()`` is the MOVE/LINE display file.

        Raises
        ------
        SceneError
            If the scene has shaded surfaces (raster only).

        Examples
        --------
        The filled triangle becomes horizontal strokes, then its outline:

        >>> import scanline as sl
        >>> scene = sl.scene.Scene({"version": 1, "canvas": {"width": 7, "height": 5,
        ...     "background": "black"}, "segments": [{"name": "triangle", "primitives": [
        ...     {"type": "polygon", "points": [[0, 0], [6, 0], [3, 4]]}]}]})
        >>> print(scene.vector().listing().splitlines()[-4:])
        ['MOVE 0 0', 'LINE 6 0', 'LINE 3 4', 'LINE 0 0']
        """
        self._no_surfaces("a vector display")
        device = VectorDevice(self.canvas.width, self.canvas.height)
        interpret(self.display_file, device, highlight=self.canvas.highlight)
        return device

    def render(self, path: "str | os.PathLike[str]") -> None:
        """Write the scene to ``path``: ``.png``, ``.gif``, ``.bmp`` (raster), ``.svg``,
        or ``.txt`` / ``.vec`` (the MOVE/LINE listing).  Atomic: on any error no file
        is left at ``path``.

        Parameters
        ----------
        path : str or os.PathLike
            The output file; its extension picks the output.

        Raises
        ------
        SceneError
            If the extension is unknown or ``path`` is a folder.

        Examples
        --------
        >>> import os, tempfile
        >>> import scanline as sl
        >>> scene = sl.scene.Scene({"version": 1, "canvas": {"width": 7, "height": 5,
        ...     "background": "black"}, "segments": [{"name": "triangle", "primitives": [
        ...     {"type": "polygon", "points": [[0, 0], [6, 0], [3, 4]]}]}]})
        >>> out = os.path.join(tempfile.mkdtemp(), "triangle.svg")
        >>> scene.render(out)
        >>> open(out).read() == scene.svg()
        True
        """
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

    def dumps(self, format: str = "toml") -> str:
        """The scene's data as TOML or JSON text.

        Parameters
        ----------
        format : {"toml", "json"}, default "toml"

        Returns
        -------
        str

        Raises
        ------
        ArgumentValueError
            If ``format`` is neither.

        Examples
        --------
        >>> import scanline as sl
        >>> scene = sl.scene.Scene({"version": 1, "canvas": {"width": 7, "height": 5,
        ...     "background": "black"}, "segments": [{"name": "triangle", "primitives": [
        ...     {"type": "polygon", "points": [[0, 0], [6, 0], [3, 4]]}]}]})
        >>> print(scene.dumps().splitlines()[:3])
        ['version = 1', '', '[canvas]']
        """
        return files.dumps(self.data, format)


def loads(text: str, format: str = "toml", file: str | None = None) -> Scene:
    """A :class:`Scene` from TOML or JSON text.

    Parameters
    ----------
    text : str
        The scene file's text.
    format : {"toml", "json"}, default "toml"
    file : str, optional
        The file it came from, named in error messages.

    Returns
    -------
    Scene

    Raises
    ------
    SceneError
        If the text does not parse or is not a valid scene (with the line).

    Examples
    --------
    >>> import scanline as sl
    >>> scene = sl.scene.loads('{"version": 1, "canvas": {"width": 3, "height": 2}}', "json")
    >>> scene.canvas.width, scene.canvas.height
    (3, 2)
    """
    return Scene(files.loads(text, format, file), file, text, format)


def load(path: "str | os.PathLike[str]", format: str | None = None) -> Scene:
    """A :class:`Scene` from a ``.toml`` or ``.json`` file (or ``format``).

    Parameters
    ----------
    path : str or os.PathLike
        The scene file.
    format : {"toml", "json"}, optional
        The format; by default from the extension.

    Returns
    -------
    Scene

    Raises
    ------
    SceneError
        If the file cannot be read or is not a valid scene (with the file and line).

    Examples
    --------
    >>> import scanline as sl
    >>> sl.scene.load(sl.scene.example("rotation")).canvas.width > 0
    True
    """
    name = os.fspath(path)
    fmt = files.format_of(name, format)
    return loads(files.read_text(name), fmt, name)
