"""``scanline demo [--out DIR] [--jobs N]``: render the gallery of figures into DIR.

DIR receives one PNG per figure of the modules of :mod:`scanline.gallery`, each written as soon
as it is drawn, then ``gallery.png`` (all of them on one sheet) and ``index.html``, a
self-contained page that shows each figure with its caption and step table.  The
figure modules are drawn by N processes (default: one per core), each taking whole
modules, largest first: on a first run most of the time is numba compiling kernels,
and one process compiles one kernel at a time.
"""

import html
import os
import sys
import time

from .. import __version__
from ..gallery import MODULES as FIGURE_MODULES
from .progress import Progress, cpu_jobs, run_groups
from .warmup import jobs_argument

DEFAULT_DIR = "scanline-demo"

_STYLE = """
body { font-family: system-ui, sans-serif; max-width: 120rem; margin: 1.5rem auto;
       padding: 0 1rem; color: #222; }
.gallery { display: grid; gap: 1.25rem;
           grid-template-columns: repeat(auto-fill, minmax(min(100%, 24rem), 1fr)); }
.gallery section { border: 1px solid #ddd; border-radius: .4rem; padding: .75rem;
                   min-width: 0; background: #fff; }
figure { margin: 0; }
img { display: block; max-width: 100%; height: auto; margin: 0 auto; }
figcaption { margin-top: .5rem; line-height: 1.4; font-size: .92rem; }
.source { color: #666; font-style: italic; }
details { margin-top: .5rem; }
summary { cursor: pointer; color: #345; }
pre { font-size: .75rem; background: #f6f6f6; padding: .5rem; overflow-x: auto;
      margin: .25rem 0 0; max-height: 24rem; }
"""


def register(subparsers):
    """Add the ``demo`` command."""
    parser = subparsers.add_parser(
        "demo", help="render a gallery of the notes' examples (PNG files and index.html)",
        description="Render the gallery: the notes' worked examples with their step "
        "tables, and figures of every primitive and frame-buffer mode.",
    )
    parser.add_argument("--out", metavar="DIR", default=DEFAULT_DIR,
                        help=f"folder to write into, created if needed (default ./{DEFAULT_DIR})")
    parser.add_argument("--jobs", type=jobs_argument, default=None, metavar="N",
                        help="processes drawing figures (default: the number of cores)")
    parser.set_defaults(run=run)


def label(index):
    """The figure label of the 0-based ``index``: a ... z, then aa, ab, ...

    >>> [label(i) for i in (0, 25, 26, 27, 52)]
    ['a', 'z', 'aa', 'ab', 'ba']
    """
    letters = ""
    index += 1
    while index:
        index, rest = divmod(index - 1, 26)
        letters = chr(ord("a") + rest) + letters
    return letters


def page(figures, animated=()):
    """The HTML of the demo page for ``figures`` (each shown from ``NAME.png``; those
    named in ``animated`` also link ``NAME.gif``)."""
    sections = []
    for index, fig in enumerate(figures):
        letter = label(index)
        table = (f"\n<details><summary>step table</summary><pre>{html.escape(fig.table)}"
                 f"</pre></details>") if fig.table else ""
        if fig.name in animated:
            table += f'\n<p><a href="{fig.name}.gif">{fig.name}.gif</a> (animated)</p>'
        sections.append(
            f'<section id="{fig.name}">\n<figure>\n'
            f'<img src="{fig.name}.png" alt="{html.escape(fig.title)}">\n'
            f"<figcaption><b>({letter}) {html.escape(fig.title)}.</b> "
            f"{html.escape(fig.caption)} "
            f'<span class="source">{html.escape(fig.source)}.</span></figcaption>\n'
            f"</figure>{table}\n</section>"
        )
    return "\n".join([
        '<!DOCTYPE html>\n<html lang="en">\n<head>\n<meta charset="utf-8">',
        '<meta name="viewport" content="width=device-width, initial-scale=1">',
        "<title>scanline demo</title>",
        f"<style>{_STYLE}</style>\n</head>\n<body>",
        "<h1>scanline demo</h1>",
        f"<p>Scan conversion as the notes (<i>computer-graphics-notes.txt</i>) teach it, "
        f"drawn by scanline {html.escape(__version__)}. The scan-converted pixels come "
        "from <code>scanline.draw</code> (the soft-edged disk that the soft fill "
        "starts from is made with numpy, as its caption says); the grids, labels and "
        "red ideal curves are annotations. Each table is <code>scanline trace</code>'s output for the figure "
        "above it (\"step table\" unfolds it).</p>",
        _STUDIO,
        '<main class="gallery">',
        *sections,
        "</main>\n</body>\n</html>\n",
    ])


#: The interactive half: the explain page written beside the figures, and the studio.
EXPLAIN = ("bresenham", "20", "10", "30", "18")
_STUDIO = (
    '<p>Step through an algorithm: <a href="explain-bresenham.html">Bresenham (20, 10) to '
    "(30, 18)</a> (<code>scanline explain bresenham 20 10 30 18 -o page.html</code> writes "
    "such a page for any case). Run <code>scanline studio</code> for the "
    '<a href="http://127.0.0.1:8765/explorer">algorithm explorer</a>, the '
    '<a href="http://127.0.0.1:8765/devices">display devices</a> and the '
    '<a href="http://127.0.0.1:8765/workstation">workstation with its input devices</a>.</p>')


def all_figures():
    """Every figure function of the gallery, in order."""
    import importlib

    return [make for name in FIGURE_MODULES
            for make in importlib.import_module(f"scanline.gallery.{name}").FIGURES]


def all_animations():
    """The names of the short animations of the gallery, by module (a figure module's
    optional ``ANIMATIONS`` tuple of functions returning ``(name, Animation)``)."""
    import importlib

    return {m: len(getattr(importlib.import_module(f"scanline.gallery.{m}"), "ANIMATIONS", ()))
            for m in FIGURE_MODULES}


def _warm():
    """Whether the kernels of the gallery seem to be in numba's cache already."""
    from .._kernels import antialias, conics, lines, polygon, strokes, text
    from .progress import kernels_cached

    return kernels_cached([lines.draw_line, conics.draw_circle, polygon.fill_polygons,
                           strokes.stroke_outlines, antialias.draw_lines, text.stamp_line])


def draw_module(group, report):
    """Draw the figures of one module, ``group = (module, out)``, writing each PNG as
    soon as it is drawn and reporting ``(module, index, figure without its image)``,
    then its animations as GIFs, reporting ``(module, None, name)``."""
    import importlib

    from ..gallery import write

    module, out = group
    figures = importlib.import_module(f"scanline.gallery.{module}")
    write(figures.FIGURES, getattr(figures, "ANIMATIONS", ()), out,
          lambda index, item: report((module, index, item)))


def run(args):
    """Draw every figure and animation (in parallel processes), then gallery.png and
    index.html."""
    import importlib

    from PIL import Image

    from ..framebuffer import write_atomically
    from ..studio.page import explain
    from . import build_parser
    from ..gallery._plot import grid_of

    os.makedirs(args.out, exist_ok=True)
    sizes = {m: len(importlib.import_module(f"scanline.gallery.{m}").FIGURES)
             for m in FIGURE_MODULES}
    animated = all_animations()
    total = sum(sizes.values()) + sum(animated.values())
    groups = [(m, args.out) for m in sorted(FIGURE_MODULES,
                                            key=lambda m: -sizes[m] - animated[m])]
    jobs = args.jobs or (1 if _warm() else cpu_jobs())
    print(f"scanline demo: drawing {sum(sizes.values())} figures and {sum(animated.values())} "
          f"animations with {jobs} process{'es' if jobs > 1 else ''} (a first run compiles "
          "the kernels they use)", file=sys.stderr, flush=True)
    progress = Progress(total, "scanline demo")
    done, gifs = {}, set()
    t0 = time.perf_counter()

    def finished(message):
        module, index, item = message
        if index is None:
            gifs.add(item)
            progress.update(f"{item}.gif")
        else:
            done[module, index] = item
            progress.update(item.name)

    try:
        run_groups(draw_module, groups, jobs, finished)
    finally:
        progress.close()
    figures = [done[m, i] for m in FIGURE_MODULES for i in range(sizes[m])]
    images = []
    for fig in figures:
        with Image.open(os.path.join(args.out, f"{fig.name}.png")) as im:
            images.append(im.convert("RGB"))
    write_atomically(os.path.join(args.out, "gallery.png"),
                     lambda f: grid_of(images, [f.title for f in figures]).save(f, format="PNG"))
    explain(build_parser().parse_args(["explain", *EXPLAIN, "-o", "-"]),
            os.path.join(args.out, "explain-bresenham.html"))
    index = os.path.join(args.out, "index.html")
    write_atomically(index, lambda f: f.write(page(figures, gifs).encode("utf-8")))
    print(f"scanline demo: wrote {len(figures)} figures, {len(gifs)} GIFs, gallery.png and "
          f"index.html to {os.path.abspath(args.out)} in {time.perf_counter() - t0:.1f} s")
    print(f"open {os.path.abspath(index)}")
