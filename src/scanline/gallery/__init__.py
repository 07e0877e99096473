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
    """Draw ``figures`` into ``out`` as ``NAME.png``, each written as soon as it is drawn
    and reported as ``(index, figure without its image)``, then ``animations`` as
    ``NAME.gif``, each reported as ``(None, name)``."""
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
    """Run one module of figures alone: ``-o DIR`` (default: the current folder) receives
    its PNG files and GIFs; each figure's title, caption and source are printed."""
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
