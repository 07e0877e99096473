"""Finding the line of a key path (``segments[2].primitives[0].points``) in scene text.

Python's TOML and JSON readers report lines only for syntax errors; for an error in a
value, :func:`line_of` reads the (already valid) text again with a small tokenizer
that remembers where each value starts.  It understands what scene files use: TOML
tables, arrays of tables, dotted keys, inline tables and arrays, and JSON.  Anything
it cannot follow gives None (the message then has the key path only).
"""

import json
import re

_TOKEN = re.compile(r'''
    (?P<newline>\n)
  | (?P<space>[ \t\r]+)
  | (?P<comment>\#[^\n]*)
  | (?P<string>"(?:[^"\\\n]|\\.)*"|'[^'\n]*')
  | (?P<punct>[{}\[\],:=.])
  | (?P<bare>[A-Za-z0-9_+\-]+(?:[.:][0-9][A-Za-z0-9_+\-:.]*)?)
''', re.VERBOSE)


def _tokens(text):
    """(kind, text, line) tuples; None when the text holds something else (such as a
    multi-line string)."""
    out, line, pos = [], 1, 0
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if m is None:
            return None
        kind = m.lastgroup
        if kind == "newline":
            out.append(("newline", "\n", line))
            line += 1
        elif kind not in ("space", "comment"):
            out.append((kind, m.group(), line))
        pos = m.end()
    out.append(("end", "", line))
    return out


def _key(token):
    kind, value, _ = token
    if kind == "string":
        return json.loads(value) if value.startswith('"') else value[1:-1]
    return value


class _Reader:
    def __init__(self, tokens, lines):
        self.t, self.i, self.lines = tokens, 0, lines

    def peek(self, skip_newlines=True):
        while skip_newlines and self.t[self.i][0] == "newline":
            self.i += 1
        return self.t[self.i]

    def take(self, skip_newlines=True):
        token = self.peek(skip_newlines)
        self.i += 1
        return token

    def value(self, path):
        """Read one value, recording the line where it starts under ``path``."""
        kind, text, line = self.take()
        self.lines.setdefault(path, line)
        if text == "[":
            n = 0
            while self.peek()[1] != "]":
                self.value(path + (n,))
                n += 1
                if self.peek()[1] == ",":
                    self.take()
            self.take()
        elif text == "{":
            while self.peek()[1] != "}":
                self.value(self.keys(path))
                if self.peek()[1] == ",":
                    self.take()
            self.take()
        elif kind not in ("string", "bare"):
            raise ValueError(f"unexpected {text!r} on line {line}")

    def keys(self, path):
        """Read ``key.key = `` (TOML) or ``"key":`` (JSON); return the value's path."""
        while True:
            token = self.take()
            path = path + (_key(token),)
            self.lines.setdefault(path, token[2])
            sep = self.take()[1]
            if sep != ".":
                if sep not in ("=", ":"):
                    raise ValueError(f"expected '=' or ':' on line {token[2]}")
                return path


def _toml(tokens):
    lines, counts = {}, {}
    r = _Reader(tokens, lines)
    table = ()
    while r.peek()[0] != "end":
        token = r.peek()
        if token[1] == "[":
            r.take()
            double = r.peek(False)[1] == "["
            if double:
                r.take()
            names = []
            while r.peek(False)[1] != "]":
                tok = r.take(False)
                if tok[1] != ".":
                    names.append(_key(tok))
            r.take(False)
            if double:
                r.take(False)
            table = _table_path(names, counts, double)
            for n in range(1, len(table) + 1):
                lines.setdefault(table[:n], token[2])
        else:
            r.value(r.keys(table))
    return lines


def _table_path(names, counts, array):
    """The path of a ``[a.b]`` or ``[[a.b]]`` header: each prefix that is an array
    of tables stands for its last element (counted per parent element)."""
    path = ()
    for k, name in enumerate(names):
        path = path + (name,)
        if array and k == len(names) - 1:
            counts[path] = counts.get(path, -1) + 1
        if path in counts:
            path = path + (counts[path],)
    return path


def parse_path(path):
    """``"segments[2].primitives[0].points"`` -> ``("segments", 2, "primitives", 0, "points")``."""
    out = []
    for name, index in re.findall(r"([^.\[\]]+)|\[(\d+)\]", path):
        out.append(int(index) if index else name)
    return tuple(out)


def line_of(text, format, path):
    """The line where the value at ``path`` (a key-path string) starts, or where its
    nearest enclosing value starts; None if unknown."""
    tokens = _tokens(text)
    if tokens is None:
        return None
    try:
        lines = _toml(tokens) if format == "toml" else _json(tokens)
    except (ValueError, IndexError, RecursionError):
        return None
    keys = parse_path(path)
    for n in range(len(keys), 0, -1):
        if keys[:n] in lines:
            return lines[keys[:n]]
    return None


def _json(tokens):
    lines = {}
    _Reader(tokens, lines).value(())
    return lines
