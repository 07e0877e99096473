"""The step table returned by every tracer."""

import csv
import io
import json
import math
from typing import Any, Dict, Iterable, Optional, Set, Tuple


def _cell(value: object) -> str:
    """A value as the table prints it: floats to 6 decimals, except one whose
    6-decimal form would round (half up, as the pixels do) to another integer than
    the value itself -- the DDA's 3.4999999999999996 reads as 3.5 but rounds to 3 --
    which is printed with all its digits.

    >>> _cell(0.25), _cell(1 / 3), _cell(3.4999999999999996), _cell(-1.1e-15)
    ('0.25', '0.333333', '3.4999999999999996', '0')
    """
    if value is None:
        return ""
    if isinstance(value, float):
        text = f"{value:.6f}".rstrip("0").rstrip(".")
        if math.isfinite(value) and math.floor(float(text) + 0.5) != math.floor(value + 0.5):
            return repr(value)
        return "0" if text == "-0" else text
    return str(value)


class Table:
    """Rows of an algorithm's steps.

    Parameters
    ----------
    title : str
        What was traced.
    columns : iterable of str
        Column names, in order.
    rows : iterable of dict
        One dict per step, keyed by column names.
    notes : iterable of str, optional
        Set-up lines printed above the table.
    pixels : iterable of (int, int), optional
        The (x, y) pixels the algorithm plots.

    Attributes
    ----------
    title : str
        What was traced.
    notes : list of str
        Set-up lines printed above the table (constants, initial values).
    columns : list of str
        Column names, in order; the keys of each row.
    rows : list of dict
        One dict per step.

    Examples
    --------
    >>> t = Table("demo", ["k", "x"], [{"k": 0, "x": 0.5}], ["x0 = 0.5"], [(0, 0)])
    >>> len(t), t.columns
    (1, ['k', 'x'])
    >>> print(t)
    demo
    x0 = 0.5
    <BLANKLINE>
    k    x
    -  ---
    0  0.5
    """

    def __init__(self, title: str, columns: Iterable[str], rows: Iterable[Dict[str, Any]],
                 notes: Iterable[str] = (), pixels: Iterable[Tuple[int, int]] = ()) -> None:
        self.title = title
        self.columns = list(columns)
        self.rows = list(rows)
        self.notes = list(notes)
        self._pixels = frozenset(pixels)

    def pixels(self) -> Set[Tuple[int, int]]:
        """The set of (x, y) pixels that the algorithm plots, symmetry included.

        Returns
        -------
        set of (int, int)
            A fresh set; changing it leaves the table as it was.

        Examples
        --------
        >>> Table("t", ["k"], [], pixels=[(1, 2), (1, 2), (3, 4)]).pixels() == {(1, 2), (3, 4)}
        True
        """
        return set(self._pixels)

    def __len__(self) -> int:
        return len(self.rows)

    def __repr__(self) -> str:
        return f"<Table {self.title!r}: {len(self.rows)} rows>"

    def __str__(self) -> str:
        cells = [[_cell(r.get(c)) for c in self.columns] for r in self.rows]
        widths = [max([len(c)] + [len(row[i]) for row in cells]) for i, c in enumerate(self.columns)]
        line = "  ".join(c.rjust(w) for c, w in zip(self.columns, widths))
        out = [self.title] + self.notes + ["", line, "  ".join("-" * w for w in widths)]
        out += ["  ".join(v.rjust(w) for v, w in zip(row, widths)) for row in cells]
        return "\n".join(out)

    def to_json(self, indent: Optional[int] = None) -> str:
        """The rows as a JSON list of objects keyed by the column names.

        Parameters
        ----------
        indent : int, optional
            Indentation of the JSON text, as `json.dumps` takes it; None (the
            default) writes one line.

        Returns
        -------
        str
            The JSON text.

        Examples
        --------
        >>> Table("t", ["k", "p"], [{"k": 0, "p": -3}]).to_json()
        '[{"k": 0, "p": -3}]'
        """
        return json.dumps(self.rows, indent=indent)

    def to_csv(self) -> str:
        """The rows as CSV text with a header line.

        Returns
        -------
        str
            The header line and one line per row, cells printed as the table prints
            them (floats to 6 decimals).

        Examples
        --------
        >>> print(Table("t", ["k", "x"], [{"k": 0, "x": 1 / 3}]).to_csv(), end="")
        k,x
        0,0.333333
        """
        out = io.StringIO()
        writer = csv.DictWriter(out, fieldnames=self.columns, lineterminator="\n")
        writer.writeheader()
        for row in self.rows:
            writer.writerow({c: _cell(row.get(c)) for c in self.columns})
        return out.getvalue()
