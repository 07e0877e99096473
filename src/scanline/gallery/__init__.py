"""The demo figures, one module per chapter of the notes.

Each module has a ``FIGURES`` tuple of functions returning a
:class:`scanline.gallery.primitives.Figure` (and may have an ``ANIMATIONS`` tuple of
functions returning ``(name, Animation)``).  ``scanline demo`` draws them all; each
module also runs alone, ``python -m scanline.gallery.curves -o DIR``, and the
documentation's gallery runs them as scripts.
"""

from __future__ import annotations

import argparse
import os
import textwrap
from collections.abc import Callable, Sequence
from typing import Any

#: The modules of figures, in gallery order.
MODULES = ("primitives", "attributes", "antialias", "color", "text", "clip", "scene",
           "curves", "surfaces", "three_d", "visible", "shading", "surface_rendering",
           "animation", "octree", "devices", "csg", "fractals", "quaternions", "blobby")


def write(figures: Sequence[Callable[[], Any]], animations: Sequence[Callable[[], Any]],
          out: str, report: Callable[[int | None, Any], None]) -> None:
    """Draw figures into a folder, each PNG file written as soon as it is drawn.

    Parameters
    ----------
    figures : sequence of callables
        Each returns a :class:`scanline.gallery.primitives.Figure` (a module's
        ``FIGURES``).
    animations : sequence of callables
        Each returns ``(name, Animation)`` (a module's ``ANIMATIONS``), saved as
        ``NAME.gif`` after the figures.
    out : str
        An existing folder; ``NAME.png`` and ``NAME.gif`` are written into it atomically.
    report : callable
        Called as ``report(index, figure)`` after each figure (its image left out, so
        that it can cross a process boundary cheaply) and ``report(None, name)`` after
        each animation.

    Examples
    --------
    >>> import os, tempfile
    >>> from scanline.gallery import curves
    >>> out, seen = tempfile.mkdtemp(), []
    >>> write(curves.FIGURES[:1], (), out, lambda index, fig: seen.append((index, fig.name)))
    >>> seen, os.listdir(out)
    ([(0, 'de-casteljau')], ['de-casteljau.png'])
    """
    from ..framebuffer import write_atomically

    for index, make in enumerate(figures):
        fig = make()
        write_atomically(os.path.join(out, f"{fig.name}.png"),
                         lambda f, image=fig.image: image.save(f, format="PNG"))
        report(index, fig._replace(image=None))
    for make in animations:
        name, animation = make()
        animation.save(os.path.join(out, f"{name}.gif"), progress=False)
        report(None, name)


def main(figures: Sequence[Callable[[], Any]],
         animations: Sequence[Callable[[], Any]] = (), argv: list[str] | None = None) -> None:
    """Run one module of figures alone, as ``python -m scanline.gallery.NAME -o DIR``.

    Parameters
    ----------
    figures, animations : sequence of callables
        The module's ``FIGURES`` and ``ANIMATIONS``, as for :func:`write`.
    argv : list of str, optional
        The command line after the program's name (default: ``sys.argv[1:]``);
        ``-o DIR`` (default: the current folder) receives the PNG files and GIFs,
        created if needed.

    Notes
    -----
    Each figure's file name, title, caption and source in the notes are printed,
    wrapped to 88 columns: the documentation's gallery shows them under each page.

    Examples
    --------
    >>> import tempfile
    >>> from scanline.gallery import curves
    >>> main(curves.FIGURES[:1], argv=["-o", tempfile.mkdtemp()])  # doctest: +ELLIPSIS
    de-casteljau.png: de Casteljau's construction at u = 0.5. The control polygon P0..P3
    ...
    """
    parser = argparse.ArgumentParser(description="Draw one chapter's demo figures.")
    parser.add_argument("-o", "--out", metavar="DIR", default=".",
                        help="folder to write into, created if needed (default: .)")
    out = parser.parse_args(argv).out
    os.makedirs(out, exist_ok=True)

    def show(index: int | None, item: Any) -> None:
        if index is None:
            print(f"{item}.gif: an animation\n")
        else:
            print(textwrap.fill(f"{item.name}.png: {item.title}. {item.caption} "
                                f"({item.source}.)", 88) + "\n")

    write(figures, animations, out, show)
