"""The ``scanline`` command: ``scanline trace | draw | demo ...``.

This module parses arguments and turns errors into one line on stderr.  It imports
only the standard library (and ``scanline`` itself, which is lazy), so that
``scanline --help`` answers at once; each sub-command imports the drawing code, and
with it numba, when it runs.

Exit status: 0 on success, 2 on bad input (a usage error, or an error raised by
scanline or the operating system while the command runs).  ``--debug`` adds the
traceback.
"""

import argparse
import os
import re
import signal
import sys
import traceback

from .. import __version__
from ..errors import ScanlineError
from . import (animate, demo, dither, draw, examples, exercises, explain, fonts, render, simulate,
               studio, trace, warmup)

#: The sub-command modules; each has ``register(subparsers)``.
COMMANDS = (trace, draw, demo, render, dither, fonts, simulate, explain, exercises, studio, animate,
            warmup, examples)

#: Errors reported as bad input (exit status 2).
INPUT_ERRORS = (ScanlineError, ValueError, TypeError, OSError)


class UsageError(Exception):
    """A command line that argparse cannot parse; the message says why."""


class Parser(argparse.ArgumentParser):
    """An ArgumentParser that raises :class:`UsageError` instead of printing the
    usage and exiting, so that :func:`main` reports every error the same way, and
    that reads ``-1e3`` as a negative number, like ``-5`` and ``-2.5``."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        # Python < 3.13 takes "-1e3" for an option; 3.13 matches r"-\.?\d" instead.
        self._negative_number_matcher = re.compile(r"^-(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$")

    def error(self, message):
        raise UsageError(f"{message} (see '{self.prog} --help')")


def build_parser():
    """The argument parser of the ``scanline`` command and its sub-commands."""
    parser = Parser(
        prog="scanline",
        description="The classic computer-graphics pipeline: step tables of the notes' "
        "algorithms, drawing with attributes and text, scene files (2-D, 3-D views and shaded "
        "surfaces) through the display-file interpreter, animated scenes and storyboards, "
        "dithering, an interactive studio, and a gallery of the notes' examples.",
        epilog="'scanline COMMAND --help' describes each command.",
    )
    parser.add_argument("--version", action="version", version=f"scanline {__version__}")
    parser.add_argument("--debug", action="store_true",
                        help="on an error, print the traceback too")
    subparsers = parser.add_subparsers(title="commands", metavar="COMMAND", required=True)
    for command in COMMANDS:
        command.register(subparsers)
    return parser


def _report(message):
    """Print ``message`` as the one error line on stderr."""
    print(f"scanline: error: {' '.join(str(message).split())}", file=sys.stderr)


def main(argv=None):
    """Run the command line ``argv`` (default: ``sys.argv[1:]``); return the exit status.

    ``--help`` and ``--version`` print and return 0.  Bad input prints one line,
    ``scanline: error: ...``, on stderr and returns 2.
    """
    try:
        args = build_parser().parse_args(argv)
    except UsageError as exc:
        _report(exc)
        return 2
    except SystemExit as exc:  # --help, --version
        return exc.code
    try:
        from .progress import announce_compilation

        with announce_compilation():    # "compiling kernels for first use", if it lasts
            args.run(args)
    except BrokenPipeError:
        # The reader of our output went away (``scanline trace ... | head``): stop
        # quietly, and keep Python from complaining when it flushes stdout at exit.
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 1
    except INPUT_ERRORS as exc:
        if args.debug:
            traceback.print_exc()
        _report(exc)
        return 2
    except MemoryError:
        if args.debug:
            traceback.print_exc()
        _report("not enough memory for this command; give smaller sizes or fewer items")
        return 2
    except KeyboardInterrupt:
        return 130
    finally:
        if argv is None:
            _quiet_exit()
    return 0


def _quiet_exit():
    """Ignore Ctrl-C from now on: the command is done (its file written), and an
    interrupt during the interpreter's shutdown would only print "Exception ignored
    ... KeyboardInterrupt"."""
    import threading

    if threading.current_thread() is threading.main_thread():
        signal.signal(signal.SIGINT, signal.SIG_IGN)
