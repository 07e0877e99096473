"""The algorithm explorer in a Jupyter notebook: an `anywidget
<https://anywidget.dev>`_ widget showing the page of ``scanline explain`` (the step
table's view, the explorer's own static JavaScript and style, inlined), so that it
works offline, with no server.

``pip install 'scanline-graphics[notebook]'`` installs anywidget; the rest of the package
does not need it.
"""

from __future__ import annotations

from importlib import resources
from typing import Any

import anywidget
import traitlets

from .explorer import parse
from .page import explain_html


class Explorer(anywidget.AnyWidget):
    """The explorer of one case of ``scanline trace ALGORITHM ARGS...`` as a widget.

    Setting ``algorithm``, ``args`` or ``quiz`` rebuilds the page (``html``);
    ``step`` is the step shown, kept in step with the page both ways.

    Parameters
    ----------
    algorithm : str
        An algorithm of ``scanline trace``.
    args : list of str
        Its arguments, as on the command line.
    quiz : bool
        Quiz mode: each step is asked before it is shown.

    Raises
    ------
    ValueError
        Arguments the command line refuses (its message).

    Examples
    --------
    >>> w = Explorer(algorithm="dda", args=["0", "0", "3", "1"])
    >>> w.step, "window.explorer" in w.html
    (0, True)
    """

    _esm = (resources.files("scanline.studio") / "static" / "widget.js").read_text(encoding="utf-8")
    algorithm = traitlets.Unicode("bresenham").tag(sync=True)
    args = traitlets.List(traitlets.Unicode(), default_value=["20", "10", "30", "18"]).tag(sync=True)
    quiz = traitlets.Bool(False).tag(sync=True)
    step = traitlets.Int(0).tag(sync=True)
    html = traitlets.Unicode("").tag(sync=True)

    def __init__(self, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self._build()

    @traitlets.observe("algorithm", "args", "quiz")
    def _rebuild(self, change: dict[str, Any]) -> None:
        self._build()

    def _build(self) -> None:
        self.html = explain_html(parse(self.algorithm, list(self.args)), self.quiz)
        self.step = 0


def explore(algorithm: str, *args: object, quiz: bool = False) -> Explorer:
    """The explorer widget of ``scanline trace ALGORITHM ARGS...`` (display it in a
    notebook cell).

    Parameters
    ----------
    algorithm : str
        An algorithm of ``scanline trace`` (``"bresenham"``, ``"z-buffer"`` ...).
    *args : object
        Its arguments as on the command line; numbers are written out
        (``explore("bresenham", 20, 10, 30, 18)``).
    quiz : bool
        Quiz mode: each step is asked before it is shown, and the score kept.

    Returns
    -------
    Explorer
        The widget; its ``step`` trait is the step shown.

    Raises
    ------
    ValueError
        Arguments the command line refuses (its message), an unknown algorithm.

    Examples
    --------
    >>> w = explore("bresenham", 20, 10, 30, 18)
    >>> w.algorithm, w.args
    ('bresenham', ['20', '10', '30', '18'])
    """
    return Explorer(algorithm=algorithm, args=[str(a) for a in args], quiz=quiz)
