"""The studio: a local web application to step through the algorithms, watch the
display devices of chapter 1 and use the logical input devices on a live display
file (``scanline studio``), and the single-file explorer pages of ``scanline
explain``.

Everything the pages show comes from the public API on the server
(:mod:`scanline.trace`, :mod:`scanline.display`); the pages' JavaScript draws and
sends input, it never runs an algorithm.
"""


def __getattr__(name: str) -> object:
    """``explore`` and ``Explorer``, the notebook widget (:mod:`.notebook`), loaded on
    first use: only they need anywidget (the ``notebook`` extra)."""
    if name in ("explore", "Explorer"):
        from . import notebook

        return getattr(notebook, name)
    raise AttributeError(f"module 'scanline.studio' has no attribute {name!r}")
