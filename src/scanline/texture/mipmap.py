"""Mipmaps (Williams 1983, "Pyramidal parametrics"; Hearn & Baker 14-9 on filtering
texture patterns): the texture and its copies each half the size of the one before,
down to one texel, every texel of a level the mean of the 2 x 2 texels below it (a
box filter).  A level of odd width or height is rounded up, its last column or row
the mean of the texels there are (as Pillow's ``Image.reduce(2)`` does).
"""

from typing import List, Sequence, Tuple

import numpy as np
from numpy.typing import ArrayLike, NDArray


def halved(level: NDArray[np.float64]) -> NDArray[np.float64]:
    """The next level of ``level`` (H, W, C): (ceil(H/2), ceil(W/2), C), each texel the
    mean of the (up to) 2 x 2 texels of its box, boxes counted from the top-left
    corner (image order).

    Parameters
    ----------
    level : ndarray (H, W, C)
        A mipmap level (reals).

    Returns
    -------
    ndarray (ceil(H/2), ceil(W/2), C) float64
        The box-filtered half-size level.

    Notes
    -----
    Williams's mipmap (Hearn & Baker 14-9 on filtering texture patterns): a 2 x 2 box
    filter; a last odd row or column averages the texels there are.

    Examples
    --------
    >>> import numpy as np
    >>> from scanline.texture import halved
    >>> level = np.array([[0, 2, 4], [2, 4, 8]], np.float64)[..., None]
    >>> halved(level)[..., 0].tolist()       # (0+2+2+4)/4 and (4+8)/2
    [[2.0, 6.0]]
    """
    h, w = level.shape[:2]
    ph, pw = h + h % 2, w + w % 2
    total = np.zeros((ph, pw) + level.shape[2:])
    weight = np.zeros((ph, pw))
    total[:h, :w] = level
    weight[:h, :w] = 1.0
    sums = total.reshape(ph // 2, 2, pw // 2, 2, -1).sum(axis=(1, 3))
    counts = weight.reshape(ph // 2, 2, pw // 2, 2).sum(axis=(1, 3))
    level_down: NDArray[np.float64] = sums / counts[..., None]
    return level_down


def pyramid(image: ArrayLike) -> List[NDArray[np.float64]]:
    """The mipmap levels of ``image`` (H, W, C) in image order (top row first): the
    image itself, then :func:`halved` ones down to 1 x 1.

    Parameters
    ----------
    image : array_like (H, W, C)
        The finest level.

    Returns
    -------
    list of ndarray
        The levels, float64, from (H, W, C) down to (1, 1, C).

    Examples
    --------
    >>> import numpy as np
    >>> from scanline.texture import pyramid
    >>> [level.shape for level in pyramid(np.zeros((4, 3, 3)))]
    [(4, 3, 3), (2, 2, 3), (1, 1, 3)]
    """
    levels = [np.asarray(image, np.float64)]
    while levels[-1].shape[0] > 1 or levels[-1].shape[1] > 1:
        levels.append(halved(levels[-1]))
    return levels


def packed(levels: Sequence[NDArray[np.float64]]
           ) -> Tuple[NDArray[np.float32], NDArray[np.int64]]:
    """The levels as the sampling kernels take them
    (:mod:`scanline._kernels.texture`): one (3 N,) float32 array of the texels' R, G,
    B, level after level and each level's rows bottom first, and the table (L, 3)
    int64 of each level's first texel, width and height."""
    table = np.zeros((len(levels), 3), np.int64)
    at = 0
    for i, lv in enumerate(levels):
        h, w = lv.shape[:2]
        table[i] = at, w, h
        at += w * h
    texels = np.empty((at, 3), np.float32)
    for (first, w, h), lv in zip(table, levels):
        texels[first:first + w * h] = lv[::-1].reshape(-1, 3)
    return texels.reshape(-1), table


def joined(parts: Sequence[Tuple[NDArray[np.float32], NDArray[np.int64]]]
           ) -> Tuple[NDArray[np.float32], NDArray[np.int64], List[int]]:
    """Packed textures ``parts`` (``(texels, table)`` pairs of :func:`packed`) as one
    pair, each table's first texels moved past the texels before it: ``(texels,
    table, firsts)`` with ``firsts`` the row of ``table`` where each part begins."""
    tables: List[NDArray[np.int64]] = []
    firsts: List[int] = []
    at, row = 0, 0
    for texels, table in parts:
        moved = table.copy()
        moved[:, 0] += at
        tables.append(moved)
        firsts.append(row)
        at += len(texels) // 3
        row += len(table)
    texels = np.concatenate([p[0] for p in parts]) if parts else np.zeros(0, np.float32)
    table = np.concatenate(tables) if tables else np.zeros((0, 3), np.int64)
    return np.ascontiguousarray(texels, np.float32), np.ascontiguousarray(table), firsts
