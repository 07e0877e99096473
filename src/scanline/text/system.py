"""Installed fonts by family name: ``font="DejaVu Serif"``.

scanline depends on neither, but asks whichever is there:

1. **fontconfig** (Linux and most Unix systems; Homebrew and MSYS2 elsewhere): the
   ``fc-list`` program lists every installed face with its families, style and file.
2. **matplotlib**, when it is installed: ``matplotlib.font_manager.findfont`` with
   the fallback to its default font disabled, so that an unknown family is reported
   rather than replaced.

A family name is matched exactly, ignoring case and repeated spaces (``"dejavu
serif"`` is ``"DejaVu Serif"``); of its faces the upright regular one is taken
(style Regular, Book, Normal or Roman before Bold, Italic, Condensed ...; then the
shorter file name).  Only outline files scanline reads are taken: TrueType and
OpenType (``.ttf``, ``.otf``, ``.ttc``, ``.otc``; the first face of a collection).

The bundled families come first and keep their names: ``"DejaVu Sans"`` is the
built-in ``"sans"`` on every machine, whatever is installed.
"""

import difflib
import os
import re
import shutil
import subprocess
from typing import Dict, List, NamedTuple, Optional, Tuple

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError

#: Families shipped with scanline -> the built-in font's name.
BUNDLED = {"DejaVu Sans": "sans"}

#: Font files scanline reads (fontTools: TrueType and OpenType, collections too).
OUTLINE_SUFFIXES = (".ttf", ".otf", ".ttc", ".otc")

#: Style words of the upright regular face.
REGULAR = frozenset({"regular", "book", "normal", "roman", "plain", "standard"})

#: Seconds ``fc-list`` may take (a first run may build fontconfig's cache).
FC_TIMEOUT = 30.0

#: Families named in an error message before "... and N more".
SHOWN = 24


class Face(NamedTuple):
    """One installed font face: its family names, its style and its file."""

    families: Tuple[str, ...]
    style: str
    file: str


def key(name: str) -> str:
    """A family name as it is compared: case-folded, spaces collapsed."""
    return " ".join(name.casefold().split())


def _split(field: str) -> List[str]:
    """A fontconfig list value (``"DejaVu Sans,DejaVu Sans Condensed"``, commas in
    names escaped as ``\\,``) as its items."""
    return [item.replace("\\,", ",").strip() for item in re.split(r"(?<!\\),", field)
            if item.strip()]


def _fontconfig() -> Optional[List[Face]]:
    """Every outline face ``fc-list`` knows, or None when fontconfig is missing or
    fails."""
    program = shutil.which("fc-list")
    if program is None:
        return None
    try:
        done = subprocess.run([program, "--format", "%{family}\t%{style}\t%{file}\n"],
                              capture_output=True, text=True, timeout=FC_TIMEOUT,
                              errors="replace", check=False)
    except (OSError, subprocess.SubprocessError):
        return None
    if done.returncode != 0:
        return None
    faces = []
    for line in done.stdout.splitlines():
        parts = line.split("\t")
        if len(parts) != 3:
            continue
        families, style, file = _split(parts[0]), _split(parts[1]), parts[2].strip()
        if families and file.lower().endswith(OUTLINE_SUFFIXES):
            faces.append(Face(tuple(families), style[0] if style else "", file))
    return faces


def _matplotlib() -> Optional[List[Face]]:
    """Every outline face matplotlib's font manager knows, or None when matplotlib
    is not installed."""
    try:
        from matplotlib import font_manager
    except ImportError:
        return None
    faces = []
    for entry in font_manager.fontManager.ttflist:
        if entry.fname.lower().endswith(OUTLINE_SUFFIXES):
            style = " ".join(str(s) for s in (entry.style, entry.weight) if s not in ("normal", 400))
            faces.append(Face((entry.name,), style or "Regular", entry.fname))
    return faces


#: ``{"found": (finder, faces)}`` once looked up: fontconfig is asked once per process.
_CACHE: Dict[str, Tuple[str, Optional[List[Face]]]] = {}


def _faces() -> Tuple[str, Optional[List[Face]]]:
    """``(finder, faces)``: the installed faces by ``"fontconfig"``, else by
    ``"matplotlib"``, or ``("", None)`` when neither is available."""
    if "found" not in _CACHE:
        faces, finder = _fontconfig(), "fontconfig"
        if faces is None:
            faces, finder = _matplotlib(), "matplotlib"
        _CACHE["found"] = (finder if faces is not None else "", faces)
    return _CACHE["found"]


def _rank(face: Face, wanted: str) -> Tuple[int, int, int, str]:
    """Sort key of the faces of one family: upright regular first, the family
    named first in its list, then the shorter file name."""
    words = set(re.split(r"[\s\-_]+", face.style.casefold())) - {""}
    return (len(words - REGULAR), [key(f) for f in face.families].index(wanted),
            len(os.path.basename(face.file)), face.file)


def _by_matplotlib(family: str) -> Optional[str]:
    """The file matplotlib's ``findfont`` picks for ``family`` (no fallback),
    checked to be a face of that very family."""
    try:
        from matplotlib import font_manager
    except ImportError:
        return None
    try:
        file = font_manager.findfont(font_manager.FontProperties(family=[family]),
                                     fallback_to_default=False)
    except ValueError:
        return None
    names = {key(e.name) for e in font_manager.fontManager.ttflist
             if os.path.abspath(e.fname) == os.path.abspath(file)}
    if key(family) in names and file.lower().endswith(OUTLINE_SUFFIXES):
        return file
    return None


def families() -> Dict[str, str]:
    """The installed font families scanline can use, ``{family: file}``, sorted by
    name, with the file :func:`find_font` picks for each; empty when neither
    fontconfig nor matplotlib is available.  A bundled family is listed only if it
    is installed too, and ``font=`` still takes the bundled one
    (:func:`scanline.text.fonts` lists those).

    Returns
    -------
    dict of str to str
        Family name -> font file.

    Examples
    --------
    >>> import scanline as sl
    >>> all(f.lower().endswith((".ttf", ".otf", ".ttc", ".otc"))
    ...     for f in sl.text.families().values())
    True
    """
    _, faces = _faces()
    out: Dict[str, str] = {}
    best: Dict[str, Tuple[Tuple[int, int, int, str], str]] = {}
    for face in faces or []:
        for name in face.families:
            rank = _rank(face, key(name))
            if key(name) not in best or rank < best[key(name)][0]:
                best[key(name)] = (rank, name)
                out[key(name)] = face.file
    return {best[k][1]: out[k] for k in sorted(best, key=lambda k: best[k][1].casefold())}


def find_font(family: str) -> str:
    """The font file of the family named ``family``: the bundled DejaVu Sans for
    ``"DejaVu Sans"``, else the installed face that fontconfig (``fc-list``) or
    matplotlib finds (see the module docstring).

    Parameters
    ----------
    family : str
        A family name, compared case-insensitively.

    Returns
    -------
    str
        The font file's path.

    Raises
    ------
    ArgumentValueError
        The family is not installed: the message lists the families that are (or
        says that neither fontconfig nor matplotlib is there to ask).

    Examples
    --------
    >>> import os, scanline as sl
    >>> os.path.basename(sl.text.find_font("dejavu sans"))
    'DejaVuSans.ttf'
    """
    if not isinstance(family, str):
        raise ArgumentTypeError(f"family must be a font family name (str), got {v._show(family)}")
    found = _find(family)
    if found is None:
        raise ArgumentValueError(not_found("family", family))
    if found in BUNDLED.values():
        from .catalog import DATA
        return str(DATA / "DejaVuSans.ttf")
    return found


def _find(family: str) -> Optional[str]:
    """A bundled font's name or an installed font's file for ``family``, or None."""
    wanted = key(family)
    if not wanted:
        return None
    for name, builtin in BUNDLED.items():
        if key(name) == wanted:
            return builtin
    finder, faces = _faces()
    if finder == "fontconfig" and faces is not None:
        mine = [f for f in faces if wanted in (key(n) for n in f.families)]
        return min(mine, key=lambda f: _rank(f, wanted)).file if mine else None
    if finder == "matplotlib":
        return _by_matplotlib(family)
    return None


def not_found(name: str, family: str, builtin: Tuple[str, ...] = ()) -> str:
    """The message of a family that is not found: what is available instead."""
    finder, _ = _faces()
    installed = list(families())
    what = "an installed font family" if finder else "a font family scanline can find"
    head = (f"{name}={family!r} is neither a built-in font ({', '.join(map(repr, builtin))}), "
            f"{what}, nor an existing .ttf/.otf file" if builtin
            else f"{name}={family!r} is not {what}")
    if not finder:
        return (head + ": looking fonts up by family name needs fontconfig's fc-list or "
                "matplotlib, and neither is installed; give the path of a .ttf/.otf file, "
                "or 'DejaVu Sans' (bundled)")
    close = difflib.get_close_matches(family, installed + list(BUNDLED), n=3, cutoff=0.6)
    hint = f" (did you mean {' or '.join(map(repr, close))}?)" if close else ""
    shown = ", ".join(installed[:SHOWN]) + (
        f" ... and {len(installed) - SHOWN} more" if len(installed) > SHOWN else "")
    return (f"{head}{hint}; installed families (by {finder}): {shown or 'none'}; bundled: "
            f"{', '.join(BUNDLED)} (`scanline fonts --system` lists the installed ones)")
