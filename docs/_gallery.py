"""sphinx-gallery's hooks for scanline's gallery (conf.py names them by their dotted names).

The gallery's scripts are ``src/scanline/gallery/*.py``; they draw with scanline, not
matplotlib, and write PNG files and GIFs into the folder of their ``-o`` option.
:func:`reset_argv` gives each script an empty folder of its own, and :func:`scraper`
hands what the script wrote there to sphinx-gallery, in the order it was written.
"""

import shutil
import tempfile
from pathlib import Path

from sphinx_gallery.scrapers import figure_rst

from scanline.gallery import MODULES

_OUT = Path(tempfile.gettempdir()) / "scanline-docs-gallery"


def _folder(src_file):
    return _OUT / Path(src_file).stem


def reset_argv(gallery_conf, script_vars):
    """``-o FOLDER``: an emptied folder for the script's pictures."""
    folder = _folder(script_vars["src_file"])
    shutil.rmtree(folder, ignore_errors=True)
    folder.mkdir(parents=True)
    return ["-o", str(folder)]


def scraper(block, block_vars, gallery_conf, **kwargs):
    """The PNG files and GIFs the script wrote, moved to sphinx-gallery's image paths."""
    folder = _folder(block_vars["src_file"])
    written = sorted((p for p in folder.glob("*") if p.suffix in (".png", ".gif")),
                     key=lambda p: (p.suffix == ".gif", p.stat().st_mtime_ns))
    paths = []
    for picture, target in zip(written, block_vars["image_path_iterator"]):
        target = Path(target).with_suffix(picture.suffix)
        shutil.move(picture, target)
        paths.append(target)
    return figure_rst(paths, gallery_conf["src_dir"])


class ChapterOrder:
    """The gallery's pages in the order of ``scanline demo`` (:data:`MODULES`)."""

    def __init__(self, src_dir):
        self.src_dir = src_dir

    def __call__(self, filename):
        stem = Path(filename).stem
        return MODULES.index(stem) if stem in MODULES else len(MODULES)

    def __repr__(self):
        return f"{type(self).__name__}()"
