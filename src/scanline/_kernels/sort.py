"""Sorting inside kernels in O(n log n), for the lists that are usually nearly sorted
and small (active edge lists, the crossings of a scan line) but can be long and
shuffled for hostile input: a self-intersecting polygon of a million vertices, the
outline of a random wide stroke.

The kernels keep their incremental insertion (O(n) on a nearly sorted list) and hand
a list to :func:`sort_keys` once the insertion has moved more than
:func:`insertion_budget` elements: a bottom-up merge sort, written here rather than
numba's ``np.argsort`` (about 1.5 s of compile time on a first call, against about
0.3 s for this helper), with one signature (float64 keys, int64 items) for every
caller.
"""

from ._jit import helper

#: Runs sorted by insertion before the merge passes.
RUN = 16


@helper
def insertion_budget(n):
    """How many element moves an insertion sort of ``n`` nearly sorted items may
    spend before the caller falls back to :func:`sort_keys`: a few per item, so
    that a shuffled list costs O(n log n) and a nearly sorted one O(n)."""
    return 8 * n + 64


@helper
def sort_keys(keys, items, n, tmp_keys, tmp_items):
    """Sort ``keys[:n]`` ascending, stably, permuting ``items[:n]`` alongside;
    ``tmp_keys`` and ``tmp_items`` are scratch of at least ``n`` elements.  A
    bottom-up merge sort over runs of RUN elements sorted by insertion."""
    for lo in range(0, n, RUN):
        hi = min(lo + RUN, n)
        for i in range(lo + 1, hi):
            k = keys[i]
            it = items[i]
            j = i
            while j > lo:
                if keys[j - 1] <= k:
                    break
                keys[j] = keys[j - 1]
                items[j] = items[j - 1]
                j -= 1
            keys[j] = k
            items[j] = it
    width = RUN
    in_tmp = False
    while width < n:
        for lo in range(0, n, 2 * width):
            mid = min(lo + width, n)
            hi = min(lo + 2 * width, n)
            i = lo
            j = mid
            for out in range(lo, hi):
                if in_tmp:
                    take_left = j >= hi or (i < mid and tmp_keys[i] <= tmp_keys[j])
                    if take_left:
                        keys[out] = tmp_keys[i]
                        items[out] = tmp_items[i]
                        i += 1
                    else:
                        keys[out] = tmp_keys[j]
                        items[out] = tmp_items[j]
                        j += 1
                else:
                    take_left = j >= hi or (i < mid and keys[i] <= keys[j])
                    if take_left:
                        tmp_keys[out] = keys[i]
                        tmp_items[out] = items[i]
                        i += 1
                    else:
                        tmp_keys[out] = keys[j]
                        tmp_items[out] = items[j]
                        j += 1
        in_tmp = not in_tmp
        width *= 2
    if in_tmp:
        for i in range(n):
            keys[i] = tmp_keys[i]
            items[i] = tmp_items[i]
