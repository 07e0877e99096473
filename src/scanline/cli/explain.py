"""``scanline explain ALGORITHM ARGS... -o page.html``: the explorer for one case as
a single self-contained HTML file (the trace embedded, no server, no network)."""

from . import trace


def register(subparsers):
    """Add the ``explain`` command: the algorithms and arguments of ``trace``."""
    parser = subparsers.add_parser(
        "explain", help="write the step-by-step explorer of one case as one HTML file",
        description="Write the algorithm explorer for one case as a single HTML file that "
        "works offline (open it from disk, share it): the pixel grid, the step table, "
        "step forward, back and play. The arguments are those of 'scanline trace'.",
        epilog="Example: scanline explain bresenham 20 10 30 18 -o bresenham.html",
    )
    for sub in trace.add_algorithms(parser, run).values():
        sub.add_argument("-o", "--output", metavar="PAGE.html", required=True,
                         help="the HTML file to write")
        sub.add_argument("--quiz", action="store_true",
                         help="a quiz: the page asks for each step (the next pixel, the "
                         "decision, ...) before showing it, and keeps the score")


def run(args):
    """Trace the case and write the page."""
    from ..studio.page import explain

    explain(args, args.output, args.quiz)
    print(f"scanline explain: wrote {args.output}")
