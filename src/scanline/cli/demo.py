"""``scanline demo [--out DIR]``: render the gallery of figures into DIR.

DIR receives one PNG per figure of :mod:`scanline.cli.figures`, ``gallery.png`` (all
of them on one sheet) and ``index.html``, a self-contained page that shows each figure
with its caption and step table.
"""

import html
import os

from .. import __version__

DEFAULT_DIR = "scanline-demo"

_STYLE = """
body { font-family: system-ui, sans-serif; max-width: 75rem; margin: 2rem auto;
       padding: 0 1rem; color: #222; }
section { display: flex; flex-wrap: wrap; gap: 1.5rem; align-items: flex-start;
          border-top: 1px solid #ddd; padding: 1.5rem 0; }
figure { margin: 0; max-width: 42rem; }
img { max-width: 100%; }
figcaption { margin-top: .5rem; line-height: 1.4; }
.source { color: #666; font-style: italic; }
pre { font-size: .8rem; background: #f6f6f6; padding: .75rem; overflow-x: auto;
      margin: 0; max-width: 100%; }
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


def page(figures):
    """The HTML of the demo page for ``figures`` (each shown from ``NAME.png``)."""
    sections = []
    for index, fig in enumerate(figures):
        letter = label(index)
        table = f"\n<pre>{html.escape(fig.table)}</pre>" if fig.table else ""
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
        "<title>scanline demo</title>",
        f"<style>{_STYLE}</style>\n</head>\n<body>",
        "<h1>scanline demo</h1>",
        f"<p>Scan conversion as the notes (<i>computer-graphics-notes.txt</i>) teach it, "
        f"drawn by scanline {html.escape(__version__)}. The scan-converted pixels come "
        "from <code>scanline.draw</code> (the soft-edged disk that the soft fill "
        "starts from is made with numpy, as its caption says); the grids, labels and "
        "red ideal curves are annotations. Each table is <code>scanline trace</code>'s output for the figure "
        "next to it.</p>",
        *sections,
        "</body>\n</html>\n",
    ])


#: The modules of figures, in gallery order; each has a ``FIGURES`` tuple of
#: functions that return a :class:`scanline.cli.figures.Figure`.
FIGURE_MODULES = ("figures", "figures_attributes", "figures_antialias", "figures_color",
                  "figures_text", "figures_clip", "figures_scene", "figures_curves",
                  "figures_surfaces", "figures_three_d")


def all_figures():
    """Every figure function of the gallery, in order."""
    import importlib

    return [make for name in FIGURE_MODULES
            for make in importlib.import_module(f"{__package__}.{name}").FIGURES]


def run(args):
    """Render every figure, then write the PNGs, gallery.png and index.html."""
    from ..framebuffer import write_atomically
    from ._plot import grid_of

    def save_png(image, name):
        write_atomically(os.path.join(args.out, name), lambda f: image.save(f, format="PNG"))

    os.makedirs(args.out, exist_ok=True)
    figures = [make() for make in all_figures()]
    for fig in figures:
        save_png(fig.image, f"{fig.name}.png")
    save_png(grid_of([f.image for f in figures], [f.title for f in figures]), "gallery.png")
    index = os.path.join(args.out, "index.html")
    write_atomically(index, lambda f: f.write(page(figures).encode("utf-8")))
    print(f"scanline demo: wrote {len(figures)} figures, gallery.png and index.html "
          f"to {os.path.abspath(args.out)}")
    print(f"open {os.path.abspath(index)}")
