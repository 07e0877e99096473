"""Text attributes (notes, syllabus: "Character attributes. Text attributes";
Hearn & Baker, section 4-5; the GKS text attributes of ISO 7942).

:class:`TextStyle` bundles them; every text function also takes them as keywords,
which override the style's values.
"""

import math

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError

PATHS = ("right", "left", "up", "down")
HORIZONTAL = ("left", "center", "right")
VERTICAL = ("top", "cap", "half", "base", "bottom")

#: Largest character height accepted (device units).
MAX_HEIGHT = 2.0 ** 20


def _align(value):
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


def _height(value):
    if value is None:
        return None
    h = v.number("height", value)
    if not 0 < h <= MAX_HEIGHT:
        raise ArgumentValueError(
            f"height must be > 0 and <= {MAX_HEIGHT:g} (the cap height in device pixels), "
            f"got {v._show(value)}")
    return h


def _angle_from_up(up):
    try:
        ux, uy = up
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

    def __init__(self, font="sans", height=None, expansion=1.0, spacing=0.0, angle=0.0,
                 up=None, path="right", align=("left", "base"), color=None,
                 antialias=False):
        self._set(font=font, height=height, expansion=expansion, spacing=spacing,
                  angle=angle, up=up, path=path, align=align, color=color,
                  antialias=antialias)

    def _set(self, **values):
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
    def up(self):
        """The character up vector (unit length) of ``angle``."""
        return (-math.sin(self.angle), math.cos(self.angle))

    def replace(self, **changes):
        """A copy with some attributes changed (``None`` values are ignored); only
        the changed values are validated again."""
        out = object.__new__(TextStyle)
        for k in self.__slots__:
            object.__setattr__(out, k, getattr(self, k))
        out._set(**{k: val for k, val in changes.items() if val is not None})
        return out

    def __setattr__(self, name, value):
        raise AttributeError(f"TextStyle is immutable; use style.replace({name}=...)")

    def __copy__(self):
        return self

    def __deepcopy__(self, memo):
        return self

    def __reduce__(self):
        return _restore, (tuple(getattr(self, k) for k in self.__slots__),)

    def __repr__(self):
        fields = ", ".join(f"{k}={getattr(self, k)!r}" for k in self.__slots__)
        return f"TextStyle({fields})"

    def __eq__(self, other):
        return isinstance(other, TextStyle) and all(
            getattr(self, k) == getattr(other, k) for k in self.__slots__)

    __hash__ = None


def _restore(values):
    """Unpickle a :class:`TextStyle` (its values were checked when it was made)."""
    out = object.__new__(TextStyle)
    for key, value in zip(TextStyle.__slots__, values):
        object.__setattr__(out, key, value)
    return out


def _font(value):
    from .catalog import Font
    if not isinstance(value, (str, Font)) and not hasattr(value, "__fspath__"):
        raise ArgumentTypeError(
            f"font must be a font name, a path or a scanline.text.Font; got {v._show(value)}")
    return value


def _expansion(value):
    e = v.number("expansion", value)
    if not 0 < e <= 1000:
        raise ArgumentValueError(f"expansion must be in (0, 1000], got {v._show(value)}")
    return e


def _spacing(value):
    s = v.number("spacing", value)
    if abs(s) > 1000:
        raise ArgumentValueError(
            f"spacing must be within +-1000 (a fraction of the height), got {v._show(value)}")
    return s


def _antialias(value):
    if not isinstance(value, bool):
        raise ArgumentTypeError(f"antialias must be True or False, got {v._show(value)}")
    return value


_CHECKS = {"font": _font, "height": _height, "expansion": _expansion,
           "spacing": _spacing, "angle": lambda a: v.angle("angle", a),
           "path": lambda p: v.choice("path", p, PATHS), "align": _align,
           "color": lambda c: c, "antialias": _antialias}


DEFAULT = TextStyle()


_RESOLVED = {}


def resolve(style, **attributes):
    """The style to use: ``style`` (or the defaults) with the non-None keyword
    attributes applied.  Results are memoized (styles are immutable), so a loop
    drawing with the same keywords validates them once."""
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
