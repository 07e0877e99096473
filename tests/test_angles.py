"""Angles that cannot be mistaken (issue 16, item 3): numbers are radians, strings
carry a unit, and a whole number beyond one turn -- most likely degrees -- warns."""

import math
import warnings

import numpy as np
import pytest

import scanline as sl


def image(build, size=(48, 40)):
    fb = sl.FrameBuffer(*size)
    build(fb)
    return fb.to_array()


#: Each public entry point that takes an angle, called with the angle ``a``.
ENTRY_POINTS = {
    "text": lambda a: image(lambda fb: sl.draw.text(fb, 4, 4, "Hi", angle=a)),
    "pie": lambda a: image(lambda fb: sl.draw.pie(fb, 24, 20, 15, 12, 0.0, a)),
    "arc": lambda a: image(lambda fb: sl.draw.arc(fb, 24, 20, 15, 12, a, 3.0)),
    "hatch": lambda a: image(lambda fb: sl.draw.fill_circle(
        fb, 24, 20, 15, style=sl.FillStyle.hatch(angle=a, spacing=5))),
    "rotation": lambda a: sl.transform.rotation(a, pivot=(2, 3)),
    "rotation3d": lambda a: sl.transform3d.rotation(a, "x"),
    "oblique": lambda a: sl.projection.oblique("cavalier", phi=a).matrix,
    "TextStyle": lambda a: sl.TextStyle(angle=a).angle,
}


@pytest.mark.parametrize("name", ENTRY_POINTS)
@pytest.mark.parametrize("written, radians", [("30deg", math.pi / 6), ("30°", math.pi / 6),
                                               (" 0.5 rad", 0.5), ("0.125turn", math.pi / 4)])
def test_a_unit_says_what_is_meant(name, written, radians):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert np.array_equal(ENTRY_POINTS[name](written), ENTRY_POINTS[name](radians))


@pytest.mark.parametrize("name", ENTRY_POINTS)
def test_a_whole_number_beyond_a_turn_warns_at_the_callers_line(name):
    with pytest.warns(sl.AngleWarning, match=r"\b(angle|start|end|phi)=30 is read as "
                      r"radians.*='30deg' or math.radians\(30\)") as got:
        ENTRY_POINTS[name](30)
    assert {w.filename for w in got} == {__file__}      # the user's line, not scanline's


def test_what_does_not_warn():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for a in (0, 1, 3, 6, -6, 2 * math.pi, 30.0, 12.566370614359172, np.float64(45),
                  "720deg", 721, -10**9):
            sl.transform.rotation(a)
        sl.draw.pie(sl.FrameBuffer(8, 8), 4, 4, 3, 3, 0.0, 4 * math.pi)   # a whole turn, twice


@pytest.mark.parametrize("a", [7, -7, 45, 90, 180, -270, 360, 720])
def test_degree_like_whole_numbers_warn(a):
    with pytest.warns(sl.AngleWarning, match=f"angle={a} is read as radians"):
        sl.transform.rotation(a)


def test_numpy_integers_warn_too():
    with pytest.warns(sl.AngleWarning, match="phi=45"):
        sl.projection.oblique("cavalier", phi=np.int64(45))


@pytest.mark.parametrize("bad, error, message", [
    ("30 degrees", sl.ArgumentValueError, r"angle='30 degrees' is not an angle.*'30deg'"),
    ("deg", sl.ArgumentValueError, "is not an angle"),
    ("nandeg", sl.ArgumentValueError, "is not an angle"),
    ("1e400deg", sl.ArgumentValueError, "finite"),
    (None, sl.ArgumentTypeError, r"angle must be an angle.*'30deg'"),
    (True, sl.ArgumentTypeError, "angle must be an angle"),
])
def test_bad_angles_are_refused_naming_the_argument(bad, error, message):
    with pytest.raises(error, match=message):
        sl.transform.rotation(bad)


def test_field_of_view_in_degrees():
    assert np.allclose(sl.projection.perspective(fov="60deg", near=1, far=5).matrix,
                       sl.projection.perspective(fov=math.pi / 3, near=1, far=5).matrix)
    with pytest.raises(sl.ArgumentValueError, match=r"fov must be between.*got 60.*fov='30deg'"), \
            pytest.warns(sl.AngleWarning, match="fov=60"):
        sl.projection.perspective(fov=60, near=1, far=5)      # degrees as radians: refused


def test_the_command_line_keeps_degrees(tmp_path):
    from scanline.cli.draw import parse_items, render
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        cli = render(parse_items("angle 30 text 4 4 Hi".split()), 48, 40).to_array()
    assert np.array_equal(cli, ENTRY_POINTS["text"]("30deg"))
