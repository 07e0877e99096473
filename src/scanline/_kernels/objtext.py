"""Wavefront OBJ text read in compiled passes over its bytes (:mod:`scanline.mesh.obj`).

:func:`obj_count` counts the statements so that the arrays can be allocated (and the
memory budget checked) before anything is stored; :func:`obj_parse` tokenizes the
bytes once more and fills them: positions ``v``, texture coordinates ``vt``, normals
``vn`` and the faces' corners ``f v/vt/vn`` (relative indices resolved against what
was read so far), and notes the lines of ``usemtl`` and ``mtllib`` statements for
the Python layer to read their names.  A malformed statement stops the parse with
an error code, its line and the offending token's bytes (``err``), which the caller
turns into a message naming the line.  :func:`obj_split` gives each distinct
(v, vt, vn) triple its own mesh vertex, as OBJ indexes the three separately.

Every read of ``data`` checks its position against the length, and every store is
to an index below the counts of the first pass (the second pass stops at the first
statement beyond them), whatever the bytes are.
"""

import math

import numpy as np

from ._jit import helper, kernel

# statement kinds (the events' first column)
EVENT_USEMTL = 1
EVENT_MTLLIB = 2

# error codes (err[0]); err = code, line, token start, token end, kind (0 v, 1 vt, 2 vn),
# and err[5] the rows noted in ``slow``
ERR_FEW_COORDS = 1
ERR_NOT_NUMBER = 2
ERR_NOT_FINITE = 3
ERR_FEW_CORNERS = 4
ERR_NOT_INDEX = 5
ERR_INDEX_ZERO = 6
ERR_BEFORE_FIRST = 7
ERR_OUT_OF_RANGE = 8

#: Largest index magnitude kept exactly; longer digit strings are out of range anyway.
_BIG = 10 ** 18


@helper
def _space(c):
    return c == 32 or c == 9 or c == 13 or c == 11 or c == 12


@helper
def _line_end(data, i, n):
    """The position of the end of the line at ``i`` (its newline, or ``n``)."""
    while i < n and data[i] != 10:
        i += 1
    return i


@helper
def _skip(data, i, end):
    while i < end and _space(data[i]):
        i += 1
    return i


@helper
def _token_end(data, i, end):
    while i < end and not _space(data[i]) and data[i] != 35:      # '#' starts a comment
        i += 1
    return i


@helper
def _keyword(data, s, e):
    """0 unknown (o, g, s, vp, ...: skipped), 1 v, 2 vt, 3 vn, 4 f, 5 l, 6 usemtl,
    7 mtllib."""
    n = e - s
    c = data[s]
    if n == 1:
        if c == 118:
            return 1
        if c == 102:
            return 4
        if c == 108:
            return 5
        return 0
    if n == 2 and c == 118:
        if data[s + 1] == 116:
            return 2
        if data[s + 1] == 110:
            return 3
        return 0
    if n == 6 and c == 117 and data[s + 1] == 115 and data[s + 2] == 101 \
            and data[s + 3] == 109 and data[s + 4] == 116 and data[s + 5] == 108:
        return 6
    if n == 6 and c == 109 and data[s + 1] == 116 and data[s + 2] == 108 \
            and data[s + 3] == 108 and data[s + 4] == 105 and data[s + 5] == 98:
        return 7
    return 0


@helper
def _pow10(e):
    """10.0 ** e, exact for |e| <= 22."""
    r = 1.0
    b = 10.0
    k = abs(e)
    while k > 0:
        if k & 1:
            r *= b
        b *= b
        k >>= 1
    return r if e >= 0 else 1.0 / r


@helper
def _number(data, s, e):
    """(value, ok, exact) of the decimal number data[s:e] (sign, digits, point,
    exponent): the digits as an integer scaled by a power of ten -- one rounding, so
    the correctly rounded double, when the digits' integer is below 2**53 and the
    power within 10**22 (Clinger 1990's fast path: ``exact``); else close to it, and
    the caller reads the token again exactly.  ok is False when the token is not a
    number.  'nan' and 'inf' give themselves."""
    i = s
    neg = False
    if i < e and (data[i] == 45 or data[i] == 43):
        neg = data[i] == 45
        i += 1
    if i < e and ((data[i] | 32) == 110 or (data[i] | 32) == 105):      # nan, inf
        word = e - i
        if word == 3 and (data[i] | 32) == 110 and (data[i + 1] | 32) == 97 \
                and (data[i + 2] | 32) == 110:
            return math.nan, True, True
        if (word == 3 or word == 8) and (data[i] | 32) == 105 and (data[i + 1] | 32) == 110 \
                and (data[i + 2] | 32) == 102:
            return -math.inf if neg else math.inf, True, True
        return 0.0, False, False
    mant = np.int64(0)
    digits = 0
    scale = 0
    seen = False
    point = False
    while i < e:
        c = data[i]
        if c == 46 and not point:            # the decimal point
            point = True
            i += 1
            continue
        if c < 48 or c > 57:
            break
        seen = True
        if digits < 18:                      # 18 significant digits kept (< 2**63)
            mant = mant * 10 + (c - 48)
            if mant:
                digits += 1
            if point:
                scale -= 1
        elif not point:
            scale += 1
        i += 1
    if not seen:
        return 0.0, False, False
    if i < e and (data[i] == 101 or data[i] == 69):
        i += 1
        eneg = False
        if i < e and (data[i] == 45 or data[i] == 43):
            eneg = data[i] == 45
            i += 1
        if i >= e:
            return 0.0, False, False
        ex = 0
        while i < e and 48 <= data[i] <= 57:
            if ex < 100000:
                ex = ex * 10 + (data[i] - 48)
            i += 1
        scale += -ex if eneg else ex
    if i != e:
        return 0.0, False, False
    x = float(mant)
    exact = mant == 0 or (mant < 9007199254740992 and -22 <= scale <= 22)
    if mant == 0:
        x = 0.0
    elif -22 <= scale <= 22:
        x = x * _pow10(scale) if scale >= 0 else x / _pow10(-scale)
    elif scale > 0:
        x = x * 10.0 ** scale if scale < 400 else math.inf
    else:
        x = x * 10.0 ** scale if scale > -400 else 0.0
    return (-x if neg else x), True, exact


@helper
def _index(data, s, e):
    """(value, negative, ok) of the integer data[s:e]; magnitudes beyond about 10**18
    are kept as 10**18 + 1 (out of range for any file)."""
    i = s
    neg = False
    if i < e and (data[i] == 45 or data[i] == 43):
        neg = data[i] == 45
        i += 1
    if i >= e:
        return np.int64(0), neg, False
    value = np.int64(0)
    while i < e:
        c = data[i]
        if c < 48 or c > 57:
            return np.int64(0), neg, False
        if value <= _BIG // 10:
            value = value * 10 + (c - 48)
        else:
            value = np.int64(_BIG + 1)
        i += 1
    return value, neg, True


@kernel
def obj_count(data, counts):
    """counts[:] = statements v, vt, vn, f, face corners, events (usemtl, mtllib),
    l lines, lines."""
    n = data.shape[0]
    i = np.int64(0)
    for k in range(8):
        counts[k] = 0
    while i < n:
        end = _line_end(data, i, n)
        counts[7] += 1
        s = _skip(data, i, end)
        if s < end and data[s] != 35:
            t = _token_end(data, s, end)
            key = _keyword(data, s, t)
            if key == 1 or key == 2 or key == 3:
                counts[key - 1] += 1
            elif key == 4:
                counts[3] += 1
                j = _skip(data, t, end)
                while j < end and data[j] != 35:
                    counts[4] += 1
                    j = _skip(data, _token_end(data, j, end), end)
            elif key == 5:
                counts[6] += 1
            elif key >= 6:
                counts[5] += 1
        i = end + 1


@helper
def _fail(err, code, line, s, e, kind):
    err[0] = code
    err[1] = line
    err[2] = s
    err[3] = e
    err[4] = kind


@kernel
def obj_parse(data, totals, pos, uv, nrm, corners, sizes, face_line, events, slow, err):
    """Fill ``pos`` (V, 6: x, y, z and, where a line has six numbers, a color r, g, b;
    err[6] counts those lines), ``uv`` (T, 2), ``nrm`` (N, 3), ``corners`` (K, 3: 0-based
    v, vt, vn; -1 where absent), ``sizes`` and ``face_line`` (F,) and ``events`` (E,
    5: kind, first and end byte of the statement's argument, the faces read before
    it, its line) from the OBJ bytes ``data``, whose :func:`obj_count` gave the array
    sizes (``totals``: V, T, N, the bounds of absolute indices).  A v/vt/vn row with
    a number off the exact fast path is noted in ``slow`` (kind 0/1/2, row, first
    and end byte of its numbers; err[5] counts them) for the caller to read again.
    Stops at the first malformed statement, setting ``err``; err[0] stays 0 when all
    is well."""
    n = data.shape[0]
    counts = np.zeros(6, np.int64)        # v, vt, vn, f, corners, events stored
    limits = np.array([pos.shape[0], uv.shape[0], nrm.shape[0], sizes.shape[0],
                       corners.shape[0], events.shape[0]], np.int64)
    err[0] = 0
    err[5] = 0
    err[6] = 0
    line = np.int64(0)
    i = np.int64(0)
    while i < n:
        end = _line_end(data, i, n)
        line += 1
        s = _skip(data, i, end)
        i = end + 1
        if s >= end or data[s] == 35:
            continue
        t = _token_end(data, s, end)
        key = _keyword(data, s, t)
        if key == 1 or key == 2 or key == 3:
            k = key - 1
            if counts[k] >= limits[k]:
                return
            need = 1 if key == 2 else 3
            most = 2 if key == 2 else 6 if key == 1 else 3
            got = 0
            j = _skip(data, t, end)
            first = j
            inexact = False
            while j < end and data[j] != 35 and got < most:
                q = _token_end(data, j, end)
                x, ok, exact = _number(data, j, q)
                if got >= 3 and not (ok and math.isfinite(x)):
                    got = 3                   # extra values that are not numbers: no color
                    break
                inexact = inexact or not exact
                if not ok:
                    _fail(err, np.int64(ERR_NOT_NUMBER), line, j, q, k)
                    return
                if not math.isfinite(x):
                    _fail(err, np.int64(ERR_NOT_FINITE), line, j, q, k)
                    return
                if key == 1:
                    pos[counts[0], got] = x
                elif key == 2:
                    uv[counts[1], got] = x
                else:
                    nrm[counts[2], got] = x
                got += 1
                j = _skip(data, q, end)
            if got < need:
                _fail(err, np.int64(ERR_FEW_COORDS), line, s, _token_end(data, s, end), k)
                err[3] = end
                return
            if key == 2 and got == 1:
                uv[counts[1], 1] = 0.0
            if key == 1 and got == 6:
                err[6] += 1
            if inexact and err[5] < slow.shape[0]:
                slow[err[5], 0] = k
                slow[err[5], 1] = counts[k]
                slow[err[5], 2] = first
                slow[err[5], 3] = end
                err[5] += 1
            counts[k] += 1
        elif key == 4:
            f = counts[3]
            if f >= limits[3]:
                return
            start = counts[4]
            j = _skip(data, t, end)
            while j < end and data[j] != 35:
                q = _token_end(data, j, end)
                c = counts[4]
                if c >= limits[4]:
                    return
                # v, v/vt, v//vn, v/vt/vn
                a = j
                for part in range(3):
                    b = a
                    while b < q and data[b] != 47:
                        b += 1
                    if b == a:
                        if part == 0:
                            _fail(err, np.int64(ERR_NOT_INDEX), line, j, q, np.int64(0))
                            return
                        corners[c, part] = -1
                    else:
                        value, neg, ok = _index(data, a, b)
                        if not ok:
                            _fail(err, np.int64(ERR_NOT_INDEX), line, j, q, part)
                            return
                        if value == 0:
                            _fail(err, np.int64(ERR_INDEX_ZERO), line, a, b, part)
                            return
                        if neg:
                            if value > counts[part]:
                                _fail(err, np.int64(ERR_BEFORE_FIRST), line, a, b, part)
                                return
                            corners[c, part] = counts[part] - value
                        else:
                            if value > totals[part]:
                                _fail(err, np.int64(ERR_OUT_OF_RANGE), line, a, b, part)
                                return
                            corners[c, part] = value - 1
                    if b >= q:
                        for rest in range(part + 1, 3):
                            corners[c, rest] = -1
                        break
                    a = b + 1
                    if part == 2:
                        _fail(err, np.int64(ERR_NOT_INDEX), line, j, q, np.int64(0))
                        return
                counts[4] += 1
                j = _skip(data, q, end)
            if counts[4] - start < 3:
                _fail(err, np.int64(ERR_FEW_CORNERS), line, s, end, counts[4] - start)
                return
            sizes[f] = counts[4] - start
            face_line[f] = line
            counts[3] += 1
        elif key >= 6:
            e = counts[5]
            if e >= limits[5]:
                return
            a = _skip(data, t, end)
            b = end
            while b > a and (_space(data[b - 1])):
                b -= 1
            events[e, 0] = EVENT_USEMTL if key == 6 else EVENT_MTLLIB
            events[e, 1] = a
            events[e, 2] = b
            events[e, 3] = counts[3]
            events[e, 4] = line
            counts[5] += 1


@kernel
def obj_split(corners, table, vertex, unique):
    """One mesh vertex per distinct (v, vt, vn) triple of ``corners`` (K, 3), in the
    order first met: ``vertex[c]`` the mesh vertex of corner c, ``unique`` (K, 3)
    the triples (first rows); returns their count.  ``table`` (a power of two >= 2 K,
    filled with -1) is an open-addressing hash table of corner numbers."""
    mask = table.shape[0] - 1
    count = 0
    for c in range(corners.shape[0]):
        a = corners[c, 0]
        b = corners[c, 1]
        d = corners[c, 2]
        h = (a * 0x9E3779B1 + (b + 1) * 0x85EBCA77 + (d + 1) * 0xC2B2AE3D) & mask
        while True:
            slot = table[h]
            if slot < 0:
                table[h] = count
                unique[count, 0] = a
                unique[count, 1] = b
                unique[count, 2] = d
                vertex[c] = count
                count += 1
                break
            if unique[slot, 0] == a and unique[slot, 1] == b and unique[slot, 2] == d:
                vertex[c] = slot
                break
            h = (h + 1) & mask
    return count


@kernel
def obj_tokens(data, rows, widths, tokens, where, long_rows):
    """The numbers of the ``rows`` noted by :func:`obj_parse` (kind, row, first and
    end byte), copied for an exact conversion: ``tokens[m]`` the bytes of number m
    (zero-padded), ``where[m]`` its kind, row and column; at most ``widths[kind]``
    numbers a row, up to the first word that is not a number.  A row with a number
    longer than a token row is flagged in ``long_rows`` (and left to the caller);
    returns the count of numbers."""
    n = data.shape[0]
    size = tokens.shape[1]
    m = 0
    for r in range(rows.shape[0]):
        kind = rows[r, 0]
        if kind < 0 or kind >= widths.shape[0]:
            continue
        j = max(min(rows[r, 2], n), 0)
        b = max(min(rows[r, 3], n), 0)
        j = _skip(data, j, b)
        col = 0
        while j < b and data[j] != 35 and col < widths[kind] and m < tokens.shape[0]:
            q = _token_end(data, j, b)
            x, ok, exact = _number(data, j, q)
            if not ok:
                break
            if q - j >= size:
                long_rows[r] = True
                break
            for c in range(size):
                tokens[m, c] = data[j + c] if c < q - j else 0
            where[m, 0] = kind
            where[m, 1] = rows[r, 1]
            where[m, 2] = col
            m += 1
            col += 1
            j = _skip(data, q, b)
    return m
