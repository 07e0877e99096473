"""Sphinx configuration of scanline's documentation site.

Build: ``pip install -e '.[docs]'`` then ``sphinx-build -W --keep-going -b html docs OUT``.
The API reference (``api/``) is generated here from the public surface that
``tests/api_surface.py`` walks; the gallery (``gallery/``) runs ``src/scanline/gallery``.
"""

import re
import shutil
import sys
from pathlib import Path

DOCS = Path(__file__).resolve().parent
ROOT = DOCS.parent
sys.path[:0] = [str(DOCS), str(ROOT)]

import scanline  # noqa: E402
from tests.api_surface import _members, public_modules  # noqa: E402

project = "scanline"
author = "scanline developers"
copyright = "scanline developers"
release = version = scanline.__version__

extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "numpydoc",
    "sphinx_gallery.gen_gallery",
]
source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build", "gallery/*.ipynb", "gallery/*.py",
                    "gallery/*.zip", "gallery/*.json", "gallery/*.md5"]

myst_heading_anchors = 3
myst_enable_extensions = ["dollarmath"]

autosummary_generate = True
autodoc_typehints = "none"          # numpydoc shows the types in Parameters and Returns
autodoc_default_options = {"members": False}
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_xref_param_type = False

html_theme = "pydata_sphinx_theme"
html_title = f"scanline {release}"
html_static_path = []
html_theme_options = {
    "navigation_with_keys": False,
    "header_links_before_dropdown": 3,
    "show_toc_level": 2,
}

sphinx_gallery_conf = {
    "examples_dirs": str(ROOT / "src" / "scanline" / "gallery"),
    "gallery_dirs": "gallery",
    "filename_pattern": r"/[a-z][a-z_]*\.py$",     # every chapter's module runs
    "ignore_pattern": r"(^|/)_[^/]*\.py$",           # __init__.py, _plot.py
    "image_scrapers": ("_gallery.scraper",),
    "reset_argv": "_gallery.reset_argv",
    "within_subsection_order": "_gallery.ChapterOrder",
    "download_all_examples": False,
    "remove_config_comments": True,
    "show_memory": False,
    "plot_gallery": "True",
    "abort_on_example_error": True,
    "min_reported_time": 10**9,
}


def _api_pages():
    """One page per public module under ``api/``: an autosummary table whose entries
    get a page each (classes with their public methods and properties)."""
    folder = DOCS / "api"
    shutil.rmtree(folder, ignore_errors=True)   # no stale page of a name gone
    folder.mkdir()
    index = ["API reference", "=============", "",
             "Every public name of ``import scanline as sl``, module by module, from the "
             "docstrings.", "", ".. toctree::", "   :maxdepth: 1", ""]
    items = {module: [(name, obj) for name, obj, kind in _members(module)
                      if kind in ("function", "class")] for module in public_modules()}
    # an object exported by several modules has its page with the (deepest) one that
    # defines it
    documented = {id(obj): name for module, pairs in items.items()
                  for name, obj in pairs if obj.__module__.startswith(module)}
    for module, pairs in items.items():
        names, elsewhere = [], []
        for name, obj in pairs:
            if documented.setdefault(id(obj), name) != name:
                elsewhere.append(documented[id(obj)])
            else:
                names.append(name.removeprefix(module + "."))
        lines = [module, "=" * len(module), "", f".. automodule:: {module}", "   :no-members:",
                 "", f".. currentmodule:: {module}", "", ".. autosummary::",
                 "   :toctree: generated", "   :template: scanline-item.rst", "",
                 *(f"   {name}" for name in names), ""]
        if elsewhere:
            lines += ["Also exported here, documented with the module that defines them: " +
                      ", ".join(f":py:obj:`~{name}`" for name in elsewhere) + ".", ""]
        (folder / f"{module}.rst").write_text("\n".join(lines))
        index.append(f"   {module}")
    (folder / "index.rst").write_text("\n".join(index) + "\n")


_LITERAL = re.compile(r"(``.*?``|:math:`.*?`)")


def _absolute_values(app, what, name, obj, options, lines):
    """Docstrings write absolute values and norms as ``|x|``, which reStructuredText
    reads as a substitution: escape each ``|`` outside literals, doctests, line blocks
    and tables."""
    doctest = False
    for i, line in enumerate(lines):
        stripped = line.strip()
        doctest = stripped.startswith(">>>") or (doctest and bool(stripped))
        if doctest or "|" not in line or stripped == "|" or stripped.startswith(("| ", "+")):
            continue
        lines[i] = "".join(part if _LITERAL.fullmatch(part) else part.replace("|", "\\|")
                           for part in _LITERAL.split(line))


def setup(app):
    app.connect("autodoc-process-docstring", _absolute_values, priority=900)


templates_path = ["_templates"]
_api_pages()
