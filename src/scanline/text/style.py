"""Text attributes (notes, syllabus: "Character attributes. Text attributes";
Hearn & Baker, section 4-5; the GKS text attributes of ISO 7942).

:class:`TextStyle` bundles them; every text function also takes them as keywords,
which override the style's values.
"""

import math
import os
from typing import TYPE_CHECKING, Any, Callable, Optional, Sequence, Union, cast

from .. import _validate as v
from .._typing import Angle, Color
from ..errors import ArgumentTypeError, ArgumentValueError

PATHS = ("right", "left", "up", "down")
HORIZONTAL = ("left", "center", "right")
VERTICAL = ("top", "cap", "half", "base", "bottom")

#: Largest character height accepted (device units).
MAX_HEIGHT = 2.0 ** 20

if TYPE_CHECKING:
    from .catalog import Font

#: A font as the text functions take it: a name, a path or a loaded Font.
FontSpec = Union[str, "os.PathLike[str]", "Font"]
#: An alignment: (horizontal, vertical), or a string such as "center half".
Align = Union[str, Sequence[str]]


def _align(value: object) -> tuple[str, str]:
    if isinstance(value, str):
        parts = value.replace(",", " ").split()
        value = tuple(parts) if len(parts) == 2 else (parts[0], "base") if parts else value
    if not (isinstance(value, (tuple, list)) and len(value) == 2):
        raise ArgumentValueError(
            f"align must be a pair (horizontal, vertical) such as ('left', 'base'), with "
            f"horizontal in {HORIZONTAL} and vertical in {VERTICAL}; got {v._show(value)}")
    h = v.choice("align[0] (horizontal alignment)", value[0], HORIZONTAL)
    vert = v.choice("align[1] (vertical alignment)", value[1], VERTICAL)
    return (h, vert)


def _height(value: object) -> Optional[float]:
    if value is None:
        return None
    h = v.number("height", value)
    if not 0 < h <= MAX_HEIGHT:
        raise ArgumentValueError(
            f"height must be > 0 and <= {MAX_HEIGHT:g} (the cap height in device pixels), "
            f"got {v._show(value)}")
    return h


def _angle_from_up(up: object) -> float:
    try:
        ux, uy = cast("tuple[object, object]", up)    # a non-pair raises, caught below
    except (TypeError, ValueError):
        raise ArgumentTypeError(f"up must be a vector (ux, uy), got {v._show(up)}") from None
    ux = v.number("up[0]", ux)
    uy = v.number("up[1]", uy)
    if ux == 0 and uy == 0:
        raise ArgumentValueError("up must not be the zero vector (0, 0)")
    return math.atan2(uy, ux) - math.pi / 2


class TextStyle:
    """The text attributes.

    A style is immutable: :meth:`replace` makes a changed copy.

    Parameters
    ----------
    font : str, path or Font
        ``"sans"`` (DejaVu Sans, an outline font), ``"bitmap"`` (5 x 7 dot matrix),
        ``"stroke"`` (vector font), a path to a .ttf/.otf file, the family name of
        an installed font (``"DejaVu Serif"``; ``"DejaVu Sans"`` is ``"sans"``; see
        :mod:`scanline.text.system`), or a loaded :class:`scanline.text.Font`.
    height : float, optional
        Character height: the *cap height* (baseline to the top of the capitals), in
        device pixels, as GKS and Hearn & Baker define it.  Default: the font's
        native height (7 for the bitmap font, 12 for the stroke font, 10 for outline
        fonts; an outline font's em size is ``height * units_per_em / cap_height``,
        about 1.37 x height for DejaVu Sans).
    expansion : float
        Character width expansion factor (> 0): widths are multiplied by it.
    spacing : float
        Character spacing: extra space between characters as a fraction of the
        height (may be negative).
    angle : float
        Orientation: the baseline's angle in radians, counterclockwise from +x.
    up : (float, float), optional
        Character up vector, the alternative to ``angle``:
        ``angle = atan2(uy, ux) - pi / 2`` (``up=(0, 1)`` is upright).
    path : {"right", "left", "up", "down"}
        Text path: the direction in which successive characters are placed (the
        characters stay upright relative to the up vector).
    align : (str, str)
        Alignment of the text extent on the reference point: horizontal
        ``"left" | "center" | "right"``, vertical ``"top" | "cap" | "half" | "base"
        | "bottom"`` (top line, cap line, half the cap height, baseline, bottom
        line).  A string ``"center half"`` works too.
    color : color, optional
        The text color (the ``color`` argument of :func:`scanline.draw.text` wins).
    antialias : bool
        Coverage-weighted edges (outline and bitmap fonts) or Wu lines (stroke font).

    Examples
    --------
    >>> from scanline.text import TextStyle
    >>> s = TextStyle(font="bitmap", height=14, align="center half")
    >>> s.align, s.replace(height=7).height
    (('center', 'half'), 7.0)
    """

    __slots__ = ("font", "height", "expansion", "spacing", "angle", "path", "align",
                 "color", "antialias")
    font: FontSpec
    height: Optional[float]
    expansion: float
    spacing: float
    angle: float
    path: str
    align: tuple[str, str]
    color: Optional[Color]
    antialias: bool

    def __init__(self, font: FontSpec = "sans", height: Optional[float] = None,
                 expansion: float = 1.0, spacing: float = 0.0, angle: Angle = 0.0,
                 up: Optional[tuple[float, float]] = None, path: str = "right",
                 align: Align = ("left", "base"), color: Optional[Color] = None,
                 antialias: bool = False) -> None:
        self._set(font=font, height=height, expansion=expansion, spacing=spacing,
                  angle=angle, up=up, path=path, align=align, color=color,
                  antialias=antialias)

    def _set(self, **values: Any) -> None:
        """Validate and store the given attributes (only those)."""
        for key, value in values.items():
            if key == "up":
                if value is not None:
                    if values.get("angle"):
                        raise ArgumentValueError("give angle or up, not both")
                    object.__setattr__(self, "angle", _angle_from_up(value))
                continue
            if key == "angle" and values.get("up") is not None:
                continue
            object.__setattr__(self, key, _CHECKS[key](value))

    @property
    def up(self) -> tuple[float, float]:
        """The character up vector (unit length) of ``angle``."""
        return (-math.sin(self.angle), math.cos(self.angle))

    def replace(self, **changes: Any) -> "TextStyle":
        """A copy with some attributes changed (``None`` values are ignored); only
        the changed values are validated again.

        Parameters
        ----------
        **changes
            Attributes by name, as :class:`TextStyle` takes them (``font``,
            ``height``, ``expansion``, ``spacing``, ``angle`` or ``up``, ``path``,
            ``align``, ``color``, ``antialias``).

        Returns
        -------
        TextStyle
            The changed copy (this style is unchanged).

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            A changed value that :class:`TextStyle` would refuse.

        Examples
        --------
        >>> import math
        >>> from scanline.text import TextStyle
        >>> s = TextStyle(height=10).replace(up=(-1, 0))     # the baseline points up
        >>> s.height, round(s.angle / math.pi, 6)
        (10.0, 0.5)
        """
        out = object.__new__(TextStyle)
        for k in self.__slots__:
            object.__setattr__(out, k, getattr(self, k))
        out._set(**{k: val for k, val in changes.items() if val is not None})
        return out

    def __setattr__(self, name: str, value: object) -> None:
        raise AttributeError(f"TextStyle is immutable; use style.replace({name}=...)")

    def __copy__(self) -> "TextStyle":
        return self

    def __deepcopy__(self, memo: object) -> "TextStyle":
        return self

    def __reduce__(self) -> tuple[Callable[[tuple[Any, ...]], "TextStyle"], tuple[tuple[Any, ...]]]:
        return _restore, (tuple(getattr(self, k) for k in self.__slots__),)

    def __repr__(self) -> str:
        fields = ", ".join(f"{k}={getattr(self, k)!r}" for k in self.__slots__)
        return f"TextStyle({fields})"

    def __eq__(self, other: object) -> bool:
        return isinstance(other, TextStyle) and all(
            getattr(self, k) == getattr(other, k) for k in self.__slots__)

    # unhashable on purpose, as before (resolve() memoizes styles by id); mypy wants a
    # method here, None is what disables hashing
    __hash__ = None  # type: ignore[assignment]


def _restore(values: tuple[Any, ...]) -> TextStyle:
    """Unpickle a :class:`TextStyle` (its values were checked when it was made)."""
    out = object.__new__(TextStyle)
    for key, value in zip(TextStyle.__slots__, values):
        object.__setattr__(out, key, value)
    return out


def _font(value: object) -> object:
    from .catalog import Font
    if not isinstance(value, (str, Font)) and not hasattr(value, "__fspath__"):
        raise ArgumentTypeError(
            f"font must be a font name, a path or a scanline.text.Font; got {v._show(value)}")
    return value


def _expansion(value: object) -> float:
    e = v.number("expansion", value)
    if not 0 < e <= 1000:
        raise ArgumentValueError(f"expansion must be in (0, 1000], got {v._show(value)}")
    return e


def _spacing(value: object) -> float:
    s = v.number("spacing", value)
    if abs(s) > 1000:
        raise ArgumentValueError(
            f"spacing must be within +-1000 (a fraction of the height), got {v._show(value)}")
    return s


def _antialias(value: object) -> bool:
    if not isinstance(value, bool):
        raise ArgumentTypeError(f"antialias must be True or False, got {v._show(value)}")
    return value


_CHECKS: dict[str, Callable[[Any], Any]] = {"font": _font, "height": _height, "expansion": _expansion,
           "spacing": _spacing, "angle": lambda a: v.angle("angle", a),
           "path": lambda p: v.choice("path", p, PATHS), "align": _align,
           "color": lambda c: c, "antialias": _antialias}


DEFAULT = TextStyle()


_RESOLVED: dict[tuple[Any, ...], tuple[TextStyle, TextStyle]] = {}


def resolve(style: Optional[TextStyle], **attributes: Any) -> TextStyle:
    """The style to use: ``style`` (or the defaults) with the non-None keyword
    attributes applied.  Results are memoized (styles are immutable), so a loop
    drawing with the same keywords validates them once.

    Parameters
    ----------
    style : TextStyle or None
        The base style; None is the default style.
    **attributes
        Attributes by name (None: keep the style's value).

    Returns
    -------
    TextStyle
        ``style`` itself when nothing changes, else the changed copy.

    Raises
    ------
    ArgumentTypeError
        ``style`` is not a TextStyle.
    ArgumentValueError
        An attribute value :class:`TextStyle` would refuse.

    Examples
    --------
    >>> from scanline.text import TextStyle, style
    >>> s = TextStyle(font="bitmap")
    >>> style.resolve(s, height=None) is s, style.resolve(s, height=14).height
    (True, 14.0)
    """
    if style is None:
        style = DEFAULT
    elif not isinstance(style, TextStyle):
        raise ArgumentTypeError(f"style must be a scanline.TextStyle, got {v._show(style)}")
    values = tuple(attributes.values())
    if all(val is None for val in values):
        return style
    try:
        # (the types too: True == 1, but only one of them is a valid height)
        key = (id(style), tuple(attributes), values, tuple(map(type, values)))
        hit = _RESOLVED.get(key)
    except TypeError:  # an unhashable value (a list as a color): no memo
        return style.replace(**attributes)
    if hit is None:
        if len(_RESOLVED) > 512:
            _RESOLVED.clear()
        hit = _RESOLVED[key] = (style, style.replace(**attributes))
    return hit[1]
