"""``scanline explain``: the explorer page for one case as a single HTML file.

The explorer's own page, style and script (the studio's static assets) are inlined,
and the view of the case (:func:`scanline.studio.explorer.view_of`, built from the
step table) is embedded as JSON: the file needs no server, no network and no other
file.  Text from the table reaches the page only as JSON data, which the script
shows with ``textContent``.
"""

from __future__ import annotations

import argparse
import json
import os
import re
from importlib import resources
from typing import Any

from ..framebuffer import write_atomically
from .explorer import view_of
from .quiz import questions

STATIC = resources.files("scanline.studio") / "static"


def _json_for_script(data: Any) -> str:
    """JSON that cannot end the <script> element it sits in."""
    return (json.dumps(data, separators=(",", ":"))
            .replace("<", "\\u003c").replace(">", "\\u003e").replace("&", "\\u0026"))


def explain_html(ns: argparse.Namespace, quiz: bool = False) -> str:
    """The self-contained explorer page of parsed ``scanline trace`` arguments.

    Parameters
    ----------
    ns : argparse.Namespace
        The arguments, as :func:`scanline.studio.explorer.parse` returns them.
    quiz : bool
        Quiz mode: the page asks each step before showing it
        (:mod:`scanline.studio.quiz`) and keeps the score.

    Returns
    -------
    str
        One HTML page: the explorer's page, style and scripts (``quiz.js``,
        ``explorer.js``) inlined and the view embedded as JSON; it loads nothing.

    Raises
    ------
    ValueError
        A case the explorer refuses (too many rows, too much memory).

    Examples
    --------
    >>> from scanline.studio.explorer import parse
    >>> page = explain_html(parse("bresenham", ["0", "0", "3", "1"]), quiz=True)
    >>> '<script src=' in page, '"quiz":[' in page
    (False, True)
    """
    html = (STATIC / "explorer.html").read_text(encoding="utf-8")
    css = (STATIC / "studio.css").read_text(encoding="utf-8")
    js = "\n".join((STATIC / name).read_text(encoding="utf-8")
                   for name in ("quiz.js", "explorer.js"))
    view = view_of(ns)
    if quiz:
        view["quiz"] = questions(ns.algorithm, view)
    html = html.replace('<link rel="stylesheet" href="/static/studio.css">',
                        f"<style>\n{css}</style>")
    hint = ("answer each step before it is shown; the score is kept" if quiz else
            "step through the algorithm: the buttons, the arrow keys, or a click on a row")
    html = re.sub(r"<header>.*?</header>",
                  f'<header><h1>scanline explain</h1><span>{hint}</span></header>',
                  html, flags=re.S)
    html = html.replace('<script src="/static/quiz.js"></script>\n', "")
    html = html.replace('<script src="/static/explorer.js"></script>',
                        f'<script id="trace" type="application/json">{_json_for_script(view)}'
                        f"</script>\n<script>\n{js}</script>")
    return html


def explain(ns: argparse.Namespace, path: str | os.PathLike[str], quiz: bool = False) -> None:
    """Write :func:`explain_html` of ``ns`` to ``path``, atomically.

    Parameters
    ----------
    ns : argparse.Namespace
        Arguments parsed by ``scanline explain`` (or :func:`scanline.studio.explorer.parse`).
    path : str or os.PathLike
        The HTML file to write; a failure leaves no file there.
    quiz : bool
        Write the quiz page.

    Returns
    -------
    None

    Raises
    ------
    ValueError
        A case the explorer refuses.
    OSError
        ``path`` cannot be written.

    Examples
    --------
    >>> import os, tempfile
    >>> from scanline.studio.explorer import parse
    >>> path = os.path.join(tempfile.mkdtemp(), "dda.html")
    >>> explain(parse("dda", ["0", "0", "4", "2"]), path)
    >>> os.path.getsize(path) > 10_000
    True
    """
    page = explain_html(ns, quiz)
    write_atomically(path, lambda f: f.write(page.encode("utf-8")))
