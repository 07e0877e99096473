"""Reading and writing scene files: TOML and JSON, one schema.

Parse errors carry the file name and the line (TOML's and JSON's decoders report
it); :class:`SceneError` keeps them apart from the message so that the command line
prints ``FILE:LINE: MESSAGE``.  TOML is written by :func:`dumps` (Python reads TOML
but does not write it; scene data need only tables, arrays of tables, strings,
numbers, booleans and arrays).
"""

import json
import math
import os
import re
import sys
from typing import Any

from ..errors import ArgumentValueError

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - Python 3.10
    import tomli as tomllib

#: Formats by file extension.
FORMATS = {".toml": "toml", ".json": "json"}

#: Largest scene file read (16 MiB): scenes are hand-written or generated listings of
#: primitives; a bigger file is refused before it is read.
MAX_FILE_BYTES = 16 << 20


class SceneError(ArgumentValueError):
    """A scene file that cannot be used.

    Attributes
    ----------
    file : str or None
        The file name.
    line : int or None
        The line, when known (parse errors).
    path : str or None
        The key path, e.g. ``segments[2].primitives[0].points``.

    Parameters
    ----------
    message : str
        What is wrong.
    file : str, optional
        The file name.
    line : int, optional
        The line, when known.
    path : str, optional
        The key path of the bad value.
    """

    def __init__(self, message: str, file: str | None = None, line: int | None = None,
                 path: str | None = None) -> None:
        self.file, self.line, self.path, self.message = file, line, path, message
        where = ":".join(str(x) for x in (file, line) if x is not None)
        if file is None and line is not None:
            where = f"line {line}"
        super().__init__(f"{where}: {message}" if where else message)


def format_of(path: "str | os.PathLike[str]", format: str | None = None) -> str:
    """The format of a file: ``format`` if given, else from the extension.

    Parameters
    ----------
    path : str or os.PathLike
        The file name.
    format : {"toml", "json"}, optional
        The format, when given.

    Returns
    -------
    str
        "toml" or "json".

    Raises
    ------
    ArgumentValueError
        If ``format`` is neither.
    SceneError
        If the extension is neither ``.toml`` nor ``.json`` (and no format is given).

    Examples
    --------
    >>> from scanline.scene.files import format_of
    >>> format_of("scene.JSON"), format_of("scene.txt", "toml")
    ('json', 'toml')
    >>> format_of("scene.txt")
    Traceback (most recent call last):
    ...
    scanline.scene.files.SceneError: scene.txt: unknown scene file type '.txt'; use .toml or .json
    """
    if format is not None:
        if format not in ("toml", "json"):
            raise ArgumentValueError(f"format must be 'toml' or 'json', got {format!r}")
        return format
    ext = os.path.splitext(os.fspath(path))[1].lower()
    if ext not in FORMATS:
        raise SceneError(f"unknown scene file type {ext!r}; use .toml or .json",
                         file=os.fspath(path))
    return FORMATS[ext]


def loads(text: str, format: str = "toml", file: str | None = None) -> dict[str, Any]:
    """Parse scene text into a dict; errors name ``file`` and the line.

    Parameters
    ----------
    text : str
        TOML or JSON text.
    format : {"toml", "json"}, default "toml"
    file : str, optional
        The file it came from, named in error messages.

    Returns
    -------
    dict
        The parsed data, not yet checked as a scene (:class:`~scanline.scene.Scene`
        checks it).

    Raises
    ------
    SceneError
        If the text does not parse (with the line) or is not a table at the top.

    Examples
    --------
    >>> import scanline as sl
    >>> sl.scene.parse('{"version": 1, "canvas": {"width": 7, "height": 5}}', "json")
    {'version': 1, 'canvas': {'width': 7, 'height': 5}}
    """
    try:
        data = _parse(text, format, file)
    except RecursionError:
        raise SceneError("the data is nested too deeply to be a scene", file=file) from None
    if not isinstance(data, dict):
        raise SceneError("a scene must be a table (a JSON object) at the top level",
                         file=file, line=1)
    return data


def _parse(text: str, format: str, file: str | None) -> Any:
    if format == "json":
        try:
            data = json.loads(text, parse_constant=_no_constant)
        except json.JSONDecodeError as error:
            raise SceneError(f"invalid JSON: {error.msg} (column {error.colno})",
                             file=file, line=error.lineno) from None
        except ValueError as error:  # NaN / Infinity, or an integer too long to convert
            if "digits" in str(error):
                raise _long_number(text, "JSON", error, file) from None
            raise SceneError(f"invalid JSON: {error}", file=file) from None
    else:
        try:
            data = tomllib.loads(text)
        except tomllib.TOMLDecodeError as error:
            message = str(error)
            found = re.search(r"\(at line (\d+), column (\d+)\)", message)
            line = int(found.group(1)) if found else None
            message = re.sub(r"\s*\(at line \d+, column \d+\)", "", message)
            if found:
                message += f" (column {found.group(2)})"
            raise SceneError(f"invalid TOML: {message}", file=file, line=line) from None
        except ValueError as error:   # an integer too long for Python's int conversion
            raise _long_number(text, "TOML", error, file) from None
    return data


def _long_number(text: str, format: str, error: ValueError, file: str | None) -> SceneError:
    """The error for a number too long to convert (Python refuses integer strings of
    more than ``sys.get_int_max_str_digits()`` digits), with the line it is on."""
    limit = sys.get_int_max_str_digits() if hasattr(sys, "get_int_max_str_digits") else 4300
    found = re.search(r"[0-9_]{%d,}" % (limit + 1), text) if limit else None
    line = text.count("\n", 0, found.start()) + 1 if found else None
    digits = re.search(r"value has (\d+) digits", str(error))
    count = f"{digits.group(1)} digits" if digits else f"more than {limit} digits"
    return SceneError(f"invalid {format}: a number has {count}, more than the {limit} "
                      "Python converts", file=file, line=line)


def _no_constant(name: str) -> None:
    raise ValueError(f"{name} is not a number a scene can use")


def read_text(path: "str | os.PathLike[str]") -> str:
    """The text of a scene file (UTF-8, a byte-order mark allowed), errors naming
    the file.  Only regular files of at most :data:`MAX_FILE_BYTES` are read (a
    FIFO or a device such as /dev/zero is refused before reading).

    Parameters
    ----------
    path : str or os.PathLike
        The scene file.

    Returns
    -------
    str

    Raises
    ------
    SceneError
        If the file cannot be read, is not a regular file, is too big, or is not
        UTF-8 (with the line of the first bad byte).

    Examples
    --------
    >>> import scanline as sl
    >>> from scanline.scene.files import read_text
    >>> read_text(sl.scene.example("rotation")).splitlines()[0]
    '# Rotation of an object about a pivot point (xr, yr) (notes, chapter 3, Q.2):'
    """
    from .._files import read_limited

    name = os.fspath(path)
    raw = read_limited(path, "scene file", MAX_FILE_BYTES, SceneError)
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError as error:
        line = raw[:error.start].count(b"\n") + 1
        raise SceneError("the file is not UTF-8 text", file=name, line=line) from None


def read(path: "str | os.PathLike[str]", format: str | None = None) -> dict[str, Any]:
    """Read and parse a scene file into a dict.

    Parameters
    ----------
    path : str or os.PathLike
        A ``.toml`` or ``.json`` file.
    format : {"toml", "json"}, optional
        The format; by default from the extension.

    Returns
    -------
    dict
        The parsed data, not yet checked as a scene.

    Raises
    ------
    SceneError
        If the file cannot be read or does not parse (with the file and line).

    Examples
    --------
    >>> import scanline as sl
    >>> sl.scene.read(sl.scene.example("rotation"))["version"]
    1
    """
    name = os.fspath(path)
    fmt = format_of(name, format)
    return loads(read_text(name), fmt, name)


# -- writing ---------------------------------------------------------------------------------
def dumps(data: dict[str, Any], format: str = "toml") -> str:
    """Scene data (a dict) as TOML or JSON text.

    Parameters
    ----------
    data : dict
        Scene data: tables, arrays of tables, strings, finite numbers, booleans and
        arrays.
    format : {"toml", "json"}, default "toml"

    Returns
    -------
    str

    Raises
    ------
    ArgumentValueError
        If ``format`` is neither, or a value cannot be written (a non-finite number,
        another type).

    Examples
    --------
    >>> import scanline as sl
    >>> print(sl.scene.dumps({"version": 1, "canvas": {"width": 7, "height": 5}}))
    version = 1
    <BLANKLINE>
    [canvas]
    width = 7
    height = 5
    <BLANKLINE>
    """
    if format == "json":
        return json.dumps(data, indent=2, allow_nan=False) + "\n"
    if format != "toml":
        raise ArgumentValueError(f"format must be 'toml' or 'json', got {format!r}")
    lines: list[str] = []
    _table(data, [], lines)
    return "\n".join(lines).strip("\n") + "\n"


_BARE = re.compile(r"^[A-Za-z0-9_-]+$")


def _key(k: str) -> str:
    return k if _BARE.match(k) else json.dumps(k)


def _value(x: object) -> str:
    if isinstance(x, bool):
        return "true" if x else "false"
    if isinstance(x, int):
        return str(x)
    if isinstance(x, float):
        if not math.isfinite(x):
            raise ArgumentValueError(f"cannot write the number {x!r} in a scene")
        return repr(x)
    if isinstance(x, str):
        return json.dumps(x, ensure_ascii=False)
    if isinstance(x, (list, tuple)):
        return "[" + ", ".join(_value(i) for i in x) + "]"
    if isinstance(x, dict):
        return "{" + ", ".join(f"{_key(k)} = {_value(v)}" for k, v in x.items()) + "}"
    raise ArgumentValueError(f"cannot write a {type(x).__name__} in a scene")


def _is_tables(x: object) -> bool:
    return isinstance(x, list) and bool(x) and all(isinstance(i, dict) for i in x)


def _table(d: dict[str, Any], path: list[str], lines: list[str]) -> None:
    """Key/value lines of table ``d``, then its sub-tables and arrays of tables."""
    for k, x in d.items():
        if not isinstance(x, dict) and not _is_tables(x):
            lines.append(f"{_key(k)} = {_value(x)}")
    for k, x in d.items():
        here = path + [_key(k)]
        if isinstance(x, dict):
            lines += ["", f"[{'.'.join(here)}]"]
            _table(x, here, lines)
        elif _is_tables(x):
            for item in x:
                lines += ["", f"[[{'.'.join(here)}]]"]
                _table(item, here, lines)
