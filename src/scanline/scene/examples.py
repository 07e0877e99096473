"""The example scene files shipped inside the package (``scanline/data/scenes``), so
that they can be named from any folder: ``sl.scene.example("rotation")``,
``scanline render --example rotation -o out.png``, ``scanline examples``.

>>> import scanline as sl
>>> "rotation" in sl.scene.examples(), sl.scene.example("rotation").name
(True, 'rotation.toml')
"""

import itertools
import os
import shutil
from importlib import resources
from pathlib import Path
from typing import Dict, List, Union

from .. import _validate as v
from ..errors import ArgumentValueError


def _folder() -> Path:
    return Path(str(resources.files("scanline") / "data" / "scenes"))


def examples() -> Dict[str, str]:
    """{name: summary} of the bundled scene files, by name; the summary is the first
    sentence of the file's opening comment.

    Returns
    -------
    dict of str to str

    Examples
    --------
    >>> import scanline as sl
    >>> sl.scene.examples()["rotation"].split()[0]
    'Rotation'
    """
    out: Dict[str, str] = {}
    for path in sorted(_folder().glob("*.toml")):
        lines = path.read_text(encoding="utf-8").splitlines()
        comment = " ".join(line.lstrip("# ").strip() for line in
                           itertools.takewhile(lambda line: line.startswith("#"), lines))
        out[path.stem] = _first_clause(comment)
    return out


def _first_clause(text: str) -> str:
    """``text`` up to its first ``.`` or ``:`` outside parentheses that ends a clause."""
    depth = 0
    for i, c in enumerate(text):
        depth += (c == "(") - (c == ")")
        if depth == 0 and c in ".:" and (i + 1 == len(text) or text[i + 1] == " "):
            return text[:i]
    return text


def example(name: str) -> Path:
    """The path of the bundled scene file ``name`` (``"rotation"`` or
    ``"rotation.toml"``); a name that is none of them is refused, listing them.

    Parameters
    ----------
    name : str
        An example's name, with or without ``.toml``.

    Returns
    -------
    pathlib.Path

    Raises
    ------
    ArgumentValueError
        If ``name`` is not a bundled scene.

    Examples
    --------
    >>> import scanline as sl
    >>> sl.scene.example("rotation.toml").name
    'rotation.toml'
    """
    if not isinstance(name, str):
        raise ArgumentValueError(f"example must be a name such as 'rotation', got {v._show(name)}")
    stem = name[:-5] if name.endswith(".toml") else name
    path = _folder() / f"{stem}.toml"
    if stem not in examples():
        raise ArgumentValueError(
            f"example={name!r} is not a bundled scene; the examples are "
            f"{', '.join(examples())} ('scanline examples' lists them)")
    return path


def copy_examples(folder: Union[str, "os.PathLike[str]"]) -> List[Path]:
    """Copy every bundled scene file into ``folder`` (created if needed); files that
    exist there already are refused, and nothing is copied.  Returns the new paths.

    Parameters
    ----------
    folder : str or os.PathLike
        The destination folder (created if needed).

    Returns
    -------
    list of pathlib.Path
        The copied files.

    Raises
    ------
    ArgumentValueError
        If ``folder`` is a file, or already holds a file of the same name as an
        example.

    Examples
    --------
    >>> import tempfile, scanline as sl
    >>> copied = sl.scene.copy_examples(tempfile.mkdtemp())
    >>> sorted(p.stem for p in copied) == sorted(sl.scene.examples())
    True
    """
    folder = Path(folder)
    if folder.exists() and not folder.is_dir():
        raise ArgumentValueError(f"folder={str(folder)!r} exists and is not a folder")
    sources = [example(name) for name in examples()]
    clash = [p.name for p in sources if (folder / p.name).exists()]
    if clash:
        raise ArgumentValueError(
            f"folder={str(folder)!r} already has {', '.join(clash)}; copy into a new or "
            f"empty folder")
    folder.mkdir(parents=True, exist_ok=True)
    return [Path(shutil.copyfile(p, folder / p.name)) for p in sources]
