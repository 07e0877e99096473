"""``scanline exercises ALGORITHM --count N --seed S -o sheet.html``: a printable
exercise sheet of quiz cases, with an answer key on pages of its own."""

import argparse

from . import trace

#: Most cases on one sheet (:data:`scanline.studio.exercises.MAX_COUNT`; repeated
#: here so that parsing imports nothing heavy; a test checks they agree).
MAX_COUNT = 200
#: Largest case number (:data:`scanline.studio.quiz.MAX_SEED`).
MAX_SEED = 2**31 - 1


def register(subparsers):
    """Add the ``exercises`` command."""
    parser = subparsers.add_parser(
        "exercises", help="write a printable exercise sheet with an answer key (HTML)",
        description="Write N quiz cases of one algorithm as a printable HTML sheet: each "
        "case with its question and a blank step table, then the answer key (each case's "
        "table as 'scanline trace' prints it) on pages of its own. The cases are the "
        "studio's quiz cases SEED .. SEED + N - 1.",
        epilog="Example: scanline exercises bresenham --count 4 --seed 17 -o sheet.html",
    )
    parser.add_argument("algorithm", metavar="ALGORITHM", type=algorithm,
                        help="one of: " + ", ".join(trace.ALGORITHMS))
    parser.add_argument("--count", type=bounded("count", 1, MAX_COUNT), default=4,
                        help=f"the number of cases, 1..{MAX_COUNT} (default 4)")
    parser.add_argument("--seed", type=bounded("seed", 0, MAX_SEED), default=1,
                        help="the first case's number (default 1)")
    parser.add_argument("-o", "--output", metavar="SHEET.html", required=True,
                        help="the HTML file to write")
    parser.set_defaults(run=run)


def algorithm(text):
    """An algorithm name of ``scanline trace`` (argparse type)."""
    if text not in trace.ALGORITHMS:
        raise argparse.ArgumentTypeError(f"unknown algorithm {text!r}; choose one of "
                                         + ", ".join(trace.ALGORITHMS))
    return text


def bounded(name, lo, hi):
    """An argparse type: an integer lo..hi, refused in one line naming ``name``."""
    def parse(text):
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"invalid {name} {text!r}: give an integer "
                                             f"{lo}..{hi}") from None
        if not lo <= value <= hi:
            raise argparse.ArgumentTypeError(f"invalid {name} {value}: give {lo}..{hi}")
        return value
    return parse


def run(args):
    """Write the sheet."""
    from ..studio.exercises import write_sheet

    write_sheet(args.algorithm, args.count, args.seed, args.output)
    print(f"scanline exercises: wrote {args.output} (cases {args.seed}.."
          f"{args.seed + args.count - 1})")
