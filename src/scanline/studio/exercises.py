"""Printable exercise sheets: quiz cases of one algorithm, each with its question and
a blank step table to fill in, and an answer key -- the cases' step tables exactly
as ``scanline trace`` prints them -- on pages of its own.

The cases are :func:`scanline.studio.quiz.case` of the seeds ``seed, seed + 1, ...``,
so "case 17" on the sheet is the studio's quiz case 17 (``/explorer?algorithm=...&case=17``).
"""

from __future__ import annotations

import html
import os
import shlex

from ..framebuffer import write_atomically
from .explorer import parse, table_of
from .quiz import MAX_SEED, QUESTIONS, case

#: Most cases one sheet takes.
MAX_COUNT = 200

_STYLE = """
body { font: 12pt/1.4 Georgia, serif; color: #111; max-width: 48em; margin: 1.5em auto; }
h1 { font-size: 1.5em; margin-bottom: .2em; } h2 { font-size: 1.1em; margin: 1.2em 0 .3em; }
.exercise { break-inside: avoid; page-break-inside: avoid; margin-bottom: 1.2em; }
code, pre { font: 10pt ui-monospace, monospace; }
table.blank { border-collapse: collapse; margin-top: .4em; }
table.blank th, table.blank td { border: 1px solid #555; padding: .15em .6em; min-width: 3.2em; height: 1.4em; }
table.blank th { background: #eee; font: 10pt ui-monospace, monospace; }
.key { break-before: page; page-break-before: always; }
.key pre { break-inside: avoid; page-break-inside: avoid; border-left: 3px solid #999; padding-left: .6em; }
.meta { color: #555; font-size: .9em; }
@media print { body { margin: 0; max-width: none; } .noprint { display: none; } }
"""


def _integer(name: str, value: object) -> int:
    if isinstance(value, bool) or not isinstance(value, int):
        raise TypeError(f"{name} must be an integer, not {type(value).__name__}")
    return value


def _check(algorithm: object, count: object, seed: object) -> tuple[str, int, int]:
    if not isinstance(algorithm, str) or algorithm not in QUESTIONS:
        raise ValueError(f"unknown algorithm {algorithm!r}; choose one of " + ", ".join(QUESTIONS))
    n, first = _integer("count", count), _integer("seed", seed)
    if not 1 <= n <= MAX_COUNT:
        raise ValueError(f"count must be 1..{MAX_COUNT} cases, not {n}")
    if not 0 <= first <= MAX_SEED - n:
        raise ValueError(f"seed must be 0..{MAX_SEED - n} (the cases are seed .. seed + "
                         f"count - 1), not {first}")
    return algorithm, n, first


def trace_text(algorithm: str, args: list[str]) -> str:
    """The step table of a case as ``scanline trace ALGORITHM ARGS...`` prints it.

    Parameters
    ----------
    algorithm : str
        An algorithm of the catalog.
    args : list of str
        Its arguments, as on the command line.

    Returns
    -------
    str
        The table's text (title, notes, columns and rows), without a final newline.

    Examples
    --------
    >>> print(trace_text("bresenham", ["0", "0", "2", "1"]).splitlines()[0])
    Bresenham line (0, 0) -> (2, 1)
    """
    return str(table_of(parse(algorithm, args)))


def sheet_html(algorithm: str, count: int, seed: int) -> str:
    """A printable exercise sheet of ``count`` quiz cases of ``algorithm``.

    Parameters
    ----------
    algorithm : str
        An algorithm of the catalog (``scanline trace`` names).
    count : int
        The number of cases, 1 to :data:`MAX_COUNT`.
    seed : int
        The first case's number; the cases are ``seed`` .. ``seed + count - 1``.

    Returns
    -------
    str
        One HTML page: the exercises (each: its case, the question, a blank table
        with the trace's columns and one line per step), then the answer key on
        new pages (each case's :func:`trace_text`).

    Raises
    ------
    ValueError
        An unknown algorithm, a count or seed out of range.
    TypeError
        A count or seed that is not an integer.

    Examples
    --------
    >>> page = sheet_html("bresenham", 2, 17)
    >>> page.count('class="exercise"'), "Answer key" in page
    (2, True)
    """
    algorithm, count, seed = _check(algorithm, count, seed)
    esc = html.escape
    prompt = QUESTIONS[algorithm].prompt
    ask = prompt[0].lower() + prompt[1:]
    parts, key = [], []
    for s in range(seed, seed + count):
        args = case(algorithm, s)
        text = trace_text(algorithm, args)
        table = table_of(parse(algorithm, args))
        command = shlex.join(["scanline", "trace", algorithm, *args])
        head = "".join(f"<th>{esc(c)}</th>" for c in table.columns)
        blank = "".join("<tr>" + "<td></td>" * len(table.columns) + "</tr>"
                        for _ in table.rows)
        parts.append(f'<section class="exercise"><h2>Case {s}: {esc(table.title)}</h2>'
                     f"<p>Run the algorithm by hand on <code>{esc(command)}</code> and fill in "
                     f"its step table, one line per step. At each step: {esc(ask)}"
                     f'</p><table class="blank"><tr>{head}</tr>{blank}</table></section>')
        key.append(f"<h2>Case {s}</h2><pre>{esc(text)}</pre>")
    title = f"scanline exercises: {algorithm}, cases {seed}..{seed + count - 1}"
    return (f'<!doctype html>\n<html lang="en"><head><meta charset="utf-8"><title>{esc(title)}'
            f"</title><style>{_STYLE}</style></head><body><h1>{esc(title)}</h1>"
            '<p class="meta">Name: ____________________ &nbsp; Date: __________</p>'
            + "".join(parts)
            + '<section class="key"><h1>Answer key</h1><p class="meta">Each table as '
            "<code>scanline trace</code> prints it.</p>" + "".join(key)
            + "</section></body></html>\n")


def write_sheet(algorithm: str, count: int, seed: int,
                path: str | os.PathLike[str]) -> None:
    """Write :func:`sheet_html` to ``path`` atomically (a failure leaves no file).

    Parameters
    ----------
    algorithm, count, seed
        As for :func:`sheet_html`.
    path : str or os.PathLike
        The HTML file to write.

    Returns
    -------
    None

    Raises
    ------
    ValueError, TypeError
        As :func:`sheet_html`; OSError where ``path`` cannot be written.

    Examples
    --------
    >>> import os, tempfile
    >>> path = os.path.join(tempfile.mkdtemp(), "sheet.html")
    >>> write_sheet("dda", 1, 0, path)
    >>> open(path).read().startswith("<!doctype html>")
    True
    """
    page = sheet_html(algorithm, count, seed)
    write_atomically(path, lambda f: f.write(page.encode("utf-8")))
