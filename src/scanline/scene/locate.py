"""Finding the line of a key path (``segments[2].primitives[0].points``) in scene text.

Python's TOML and JSON readers report lines only for syntax errors; for an error in a
value, :func:`line_of` reads the (already valid) text again with a small tokenizer
that remembers where each value starts.  It understands what scene files use: TOML
tables, arrays of tables, dotted keys, inline tables and arrays, and JSON.  Anything
it cannot follow gives None (the message then has the key path only).
"""

import json
import re
from typing import Iterator, Union

#: A token: (kind, text, line).
_Token = tuple[str, str, int]
#: A parsed key path: names and indices.
_Path = tuple[Union[str, int], ...]

_TOKEN = re.compile(r"""
    (?P<newline>\n)
  | (?P<space>[ \t\r]+)
  | (?P<comment>\#[^\n]*)
  | (?P<string>"[^"\\\n]*(?:\\.[^"\\\n]*)*"|'[^'\n]*')
  | (?P<punct>[{}\[\],:=.])
  | (?P<bare>[A-Za-z0-9_+\-]+(?:[.:][0-9][A-Za-z0-9_+\-:.]*)?)
""", re.VERBOSE)
# (The string pattern is "unrolled": runs of plain characters between escapes, so a
# long string is matched by one character-class loop instead of one alternation per
# character, which made Python's matcher keep a backtracking frame per character:
# about 250 bytes of memory per byte of the string.)


class _Unknown(Exception):
    """The text holds something the tokenizer does not follow."""


def _tokens(text: str) -> Iterator[_Token]:
    """(kind, text, line) tuples, one at a time, then ("end", "", line); raises
    :class:`_Unknown` at anything else (such as a multi-line string)."""
    line, pos = 1, 0
    match = _TOKEN.match
    while pos < len(text):
        m = match(text, pos)
        if m is None:
            raise _Unknown()
        kind = m.lastgroup or ""
        if kind == "newline":
            yield ("newline", "\n", line)
            line += 1
        elif kind not in ("space", "comment"):
            yield (kind, m.group(), line)
        pos = m.end()
    yield ("end", "", line)


def _key(token: _Token) -> str:
    kind, value, _ = token
    if kind == "string":
        return str(json.loads(value)) if value.startswith('"') else value[1:-1]
    return value


class _Reader:
    """Reads the token stream once, with one token of lookahead, and records in
    ``lines`` where the values on the way to ``target`` (a key path tuple) start:
    memory stays proportional to the depth of the path, not to the size of the
    text."""

    def __init__(self, tokens: Iterator[_Token], target: _Path) -> None:
        self.tokens, self.target = tokens, target
        self.lines: dict[_Path, int] = {}
        self.ahead = next(self.tokens)

    def _next(self) -> _Token:
        token = self.ahead
        if token[0] != "end":
            self.ahead = next(self.tokens)
        return token

    def note(self, path: _Path, line: int) -> None:
        if path == self.target[:len(path)]:
            self.lines.setdefault(path, line)

    def peek(self, skip_newlines: bool = True) -> _Token:
        while skip_newlines and self.ahead[0] == "newline":
            self._next()
        return self.ahead

    def take(self, skip_newlines: bool = True) -> _Token:
        self.peek(skip_newlines)
        return self._next()

    def value(self, path: _Path) -> None:
        """Read one value, recording the line where it starts under ``path``."""
        kind, text, line = self.take()
        self.note(path, line)
        if text == "[":
            n = 0
            while self.peek()[1] != "]":
                if self.peek()[0] == "end":
                    raise _Unknown()
                self.value(path + (n,))
                n += 1
                if self.peek()[1] == ",":
                    self.take()
            self.take()
        elif text == "{":
            while self.peek()[1] != "}":
                if self.peek()[0] == "end":
                    raise _Unknown()
                self.value(self.keys(path))
                if self.peek()[1] == ",":
                    self.take()
            self.take()
        elif kind not in ("string", "bare"):
            raise _Unknown()

    def keys(self, path: _Path) -> _Path:
        """Read ``key.key = `` (TOML) or ``"key":`` (JSON); return the value's path."""
        while True:
            token = self.take()
            if token[0] == "end":
                raise _Unknown()
            path = path + (_key(token),)
            self.note(path, token[2])
            sep = self.take()[1]
            if sep != ".":
                if sep not in ("=", ":"):
                    raise _Unknown()
                return path


def _toml(r: _Reader) -> dict[_Path, int]:
    counts: dict[_Path, int] = {}
    table: _Path = ()
    while r.peek()[0] != "end":
        token = r.peek()
        if token[1] == "[":
            r.take()
            double = r.peek(False)[1] == "["
            if double:
                r.take()
            names: list[str] = []
            while r.peek(False)[1] != "]":
                tok = r.take(False)
                if tok[0] in ("end", "newline"):
                    raise _Unknown()
                if tok[1] != ".":
                    names.append(_key(tok))
            r.take(False)
            if double:
                r.take(False)
            table = _table_path(names, counts, double)
            for n in range(1, len(table) + 1):
                r.note(table[:n], token[2])
        else:
            r.value(r.keys(table))
    return r.lines


def _table_path(names: list[str], counts: dict[_Path, int], array: bool) -> _Path:
    """The path of a ``[a.b]`` or ``[[a.b]]`` header: each prefix that is an array
    of tables stands for its last element (counted per parent element)."""
    path: _Path = ()
    for k, name in enumerate(names):
        path = path + (name,)
        if array and k == len(names) - 1:
            counts[path] = counts.get(path, -1) + 1
        if path in counts:
            path = path + (counts[path],)
    return path


def parse_path(path: str) -> _Path:
    """``"segments[2].primitives[0].points"`` -> ``("segments", 2, "primitives", 0, "points")``.

    Parameters
    ----------
    path : str
        A key path as error messages give it.

    Returns
    -------
    tuple of str and int

    Examples
    --------
    >>> from scanline.scene.locate import parse_path
    >>> parse_path("segments[2].primitives[0].points")
    ('segments', 2, 'primitives', 0, 'points')
    """
    out: list[str | int] = []
    for name, index in re.findall(r"([^.\[\]]+)|\[(\d+)\]", path):
        out.append(int(index) if index else name)
    return tuple(out)


def line_of(text: str, format: str, path: str) -> int | None:
    """The line where the value at ``path`` (a key-path string) starts, or where its
    nearest enclosing value starts; None if unknown.  One pass over the text, in
    memory proportional to the path's depth.

    Parameters
    ----------
    text : str
        The scene file's text (already valid TOML or JSON).
    format : {"toml", "json"}
    path : str
        The key path.

    Returns
    -------
    int or None
        The line, from 1.

    Examples
    --------
    >>> from scanline.scene.locate import line_of
    >>> text = '''version = 1
    ... [[segments]]
    ... name = "a"
    ... primitives = [{type = "polygon", points = [[0, 0]]}]
    ... '''
    >>> line_of(text, "toml", "segments[0].primitives[0].points")
    4
    >>> line_of(text, "toml", "segments[0].name"), line_of(text, "toml", "canvas")
    (3, None)
    """
    keys = parse_path(path)
    reader = None
    try:
        reader = _Reader(_tokens(text), keys)
        lines = _toml(reader) if format == "toml" else _json(reader)
    except (_Unknown, ValueError, IndexError, RecursionError, StopIteration):
        lines = reader.lines if reader is not None else {}
    for n in range(len(keys), 0, -1):
        if keys[:n] in lines:
            return lines[keys[:n]]
    return None


def _json(r: _Reader) -> dict[_Path, int]:
    r.value(())
    return r.lines
