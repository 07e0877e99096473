"""``python -m scanline``: the ``scanline`` command."""

from scanline.cli import main

if __name__ == "__main__":  # not when imported, e.g. by pytest --doctest-modules
    raise SystemExit(main())
