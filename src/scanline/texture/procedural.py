"""Procedural textures (Hearn & Baker 14-9, "Procedural texturing methods"): images
computed from a function of texture space rather than read, as
:class:`~scanline.texture.Texture` sources -- a checkerboard, and marble and wood
from Perlin's noise and turbulence (Perlin 1985, "An image synthesizer": marble is
sin(x + turbulence) mapped through a color ramp; wood is rings around an axis
perturbed by noise).  Each is deterministic for a given ``seed``.
"""

from typing import Optional, Sequence, Tuple

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from .._typing import Color
from ..errors import ArgumentValueError
from .noise import noise, turbulence
from .texture import Texture


def _size(size: int) -> int:
    n = v.positive_int("size", size)
    if n > 8192:
        raise ArgumentValueError(f"size must be 1..8192 texels, got {n}")
    return n


def _rgb(name: str, color: Color) -> NDArray[np.float64]:
    """A color spec as stored values / 255 (3,)."""
    from ..color import rgba

    return np.array(rgba(color, name)[:3], np.float64) / 255.0


def _grid(n: int, scale: float) -> NDArray[np.float64]:
    """Texel centers of an n x n texture in image order, times ``scale``: (n, n, 3)
    points with z = 0.5 (off the lattice)."""
    t = (np.arange(n) + 0.5) / n * scale
    x, y = np.meshgrid(t, t[::-1])
    return np.stack([x, y, np.full_like(x, 0.5)], axis=-1)


def _ramp(t: NDArray[np.float64], a: NDArray[np.float64], b: NDArray[np.float64]
          ) -> NDArray[np.float64]:
    """Colors from ``a`` (t = 0) to ``b`` (t = 1), (..., 3)."""
    t = np.clip(t, 0.0, 1.0)[..., None]
    return (1 - t) * a + t * b


def checker(size: int = 256, squares: int = 8, colors: Sequence[Color] = ("white", "black"),
            **texture: str) -> Texture:
    """A ``size`` x ``size`` checkerboard of ``squares`` x ``squares`` squares of the
    two ``colors`` (the bottom-left square the first), as a :class:`Texture`
    (``texture``: its ``filter`` and ``wrap``).

    Parameters
    ----------
    size : int
        Texels per side, 1..8192.
    squares : int
        Squares per side, at most ``size``.
    colors : two colors
        The bottom-left square's color and the other one.
    **texture : str
        ``filter`` and ``wrap`` of the :class:`Texture`.

    Returns
    -------
    Texture
        The checkerboard.

    Raises
    ------
    ArgumentValueError
        ``size`` outside 1..8192 or ``squares`` more than ``size``.

    Notes
    -----
    Hearn & Baker 14-9, "Procedural texturing methods".

    Examples
    --------
    >>> from scanline.texture import checker
    >>> checker(2, 2).image[..., 0].tolist()     # top row first: white bottom-left
    [[0.0, 1.0], [1.0, 0.0]]
    """
    n = _size(size)
    k = v.positive_int("squares", squares)
    if k > n:
        raise ArgumentValueError(f"squares must be at most size ({n}), got {k}")
    a, b = (_rgb(f"colors[{i}]", c) for i, c in enumerate(colors))
    i = (np.arange(n) * k) // n
    odd = (i[None, :] + i[::-1, None]) % 2 == 1
    return Texture(np.where(odd[..., None], b, a), **texture)


def _tile(k: int, tileable: bool) -> Optional[Tuple[int, int, None]]:
    """The lattice periods (x, y, z) of the noise of a tileable texture whose square
    spans ``k`` lattice cells: k across and up, none for z (constant); None when not
    ``tileable``."""
    return (k, k, None) if tileable else None


def marble(size: int = 256, veins: float = 4.0, turbulence_power: float = 5.0,
           octaves: int = 5, seed: int = 0,
           colors: Sequence[Color] = ((235, 232, 225), (70, 70, 90)), tileable: bool = True,
           **texture: str) -> Texture:
    """Perlin's marble (1985): the stripes of sin(2 pi (veins x + turbulence_power
    turbulence(4 p))) through a ramp from the first of ``colors`` (1) to the second
    (-1), a ``size`` x ``size`` :class:`Texture`.  ``tileable``: the turbulence
    repeats across the texture square (:func:`~scanline.texture.noise`'s
    ``period``) and ``veins`` must be whole, so that repeated copies meet without
    seams.

    Parameters
    ----------
    size : int
        Texels per side, 1..8192.
    veins : float
        Stripes across the texture (whole when ``tileable``).
    turbulence_power : float
        How far the turbulence bends the stripes.
    octaves : int
        The turbulence's octaves, 1..16.
    seed : int
        The noise's seed.
    colors : two colors
        The ramp's ends: the light (sine 1) and the dark (sine -1) color.
    tileable : bool
        Whether copies of the texture meet without seams.
    **texture : str
        ``filter`` and ``wrap`` of the :class:`Texture`.

    Returns
    -------
    Texture
        The marble.

    Raises
    ------
    ArgumentValueError
        ``veins`` not whole for a tileable marble, or a bad size, octaves or seed.

    Notes
    -----
    Hearn & Baker 14-9, "Procedural texturing methods"; Perlin (1985), "An image
    synthesizer", SIGGRAPH '85.

    Examples
    --------
    >>> from scanline.texture import marble
    >>> m = marble(8, colors=((255, 255, 255), (0, 0, 0)))
    >>> m.image.shape
    (8, 8, 3)
    >>> bool(((0 <= m.image) & (m.image <= 1)).all())
    True
    >>> bool((m.image[..., 0] == m.image[..., 2]).all())   # a gray ramp: r = g = b
    True
    """
    n = _size(size)
    p = _grid(n, 1.0)
    veins = v.number("veins", veins)
    if tileable and veins != round(veins):
        raise ArgumentValueError(f"veins must be a whole number for a tileable marble (the "
                                 f"stripes must repeat across the texture), got {veins!r}; "
                                 f"or give tileable=False")
    t = turbulence(4.0 * p, octaves, seed, _tile(4, tileable))
    s = np.sin(2 * np.pi * (veins * p[..., 0]
                            + v.number("turbulence_power", turbulence_power) * t / 4))
    light, dark = (_rgb(f"colors[{i}]", c) for i, c in enumerate(colors))
    return Texture(_ramp((1 - s) / 2, light, dark), **texture)


def wood(size: int = 256, rings: float = 12.0, grain: float = 0.08, seed: int = 0,
         colors: Sequence[Color] = ((200, 150, 90), (120, 75, 35)), tileable: bool = True,
         **texture: str) -> Texture:
    """Wood: rings around an axis at the texture's left edge, the distance to the axis
    times ``rings`` perturbed by ``grain`` times noise, its fraction through a ramp
    from the first of ``colors`` to the second; a ``size`` x ``size``
    :class:`Texture`.  ``tileable``: the distance is to the nearest of the axis and
    its copies one texture square apart (periodic: the rings of the neighboring
    copies meet it half way, as the rings of two branches meet) and the noise
    repeats, so that repeated copies meet without seams.

    Parameters
    ----------
    size : int
        Texels per side, 1..8192.
    rings : float
        Rings per unit of distance from the axis.
    grain : float
        How much the noise perturbs the rings.
    seed : int
        The noise's seed.
    colors : two colors
        The ramp's ends.
    tileable : bool
        Whether copies of the texture meet without seams.
    **texture : str
        ``filter`` and ``wrap`` of the :class:`Texture`.

    Returns
    -------
    Texture
        The wood.

    Raises
    ------
    ArgumentValueError
        A bad size or seed.

    Notes
    -----
    Hearn & Baker 14-9, "Procedural texturing methods".

    Examples
    --------
    >>> from scanline.texture import wood
    >>> w = wood(2, rings=1.0, grain=0.0, tileable=False, colors=((0, 0, 0), (255, 255, 255)))
    >>> w.image[..., 0].round(6).tolist()    # r^3, r = |(x, y - 1/2)|: sqrt(1/8), sqrt(5/8)
    [[0.044194, 0.494106], [0.044194, 0.494106]]
    """
    n = _size(size)
    p = _grid(n, 1.0)
    if tileable:             # the distance to the nearest copy of the axis
        dx, dy = p[..., 0], p[..., 1] - 0.5
        r = np.hypot(dx - np.round(dx), dy - np.round(dy))
    else:
        r = np.hypot(p[..., 0], p[..., 1] - 0.5)
    g = r * v.number("rings", rings) + v.number("grain", grain) * rings * noise(
        p * 8.0, seed, _tile(8, tileable))
    f = g - np.floor(g)
    light, dark = (_rgb(f"colors[{i}]", c) for i, c in enumerate(colors))
    return Texture(_ramp(f ** 3, light, dark), **texture)
