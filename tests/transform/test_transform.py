"""2-D homogeneous transformations (scanline.transform).

Four kinds of test: exact small examples computed by hand; invariants (inverses,
fixed points, involutions, determinants, distances); cross-checks against
shapely.affinity, an independent implementation; and bad input fuzzed with
hypothesis.  The notes' chapter 3 (Q.1 translation, Q.2 rotation) has formulas but
no numeric worked example; its equations are checked here term by term, and the
misprints around them are listed in docs/errata.md (E12-E15).
"""

import math
import subprocess
import sys
from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest
import shapely
import shapely.affinity
from hypothesis import given
from hypothesis import strategies as st

import scanline as sl
from scanline.transform import (
    AXES,
    apply,
    compose,
    inverse,
    reflection,
    reflection_about_line,
    rotation,
    scaling,
    shear,
    translation,
)
from tests.reference import HYPOTHESIS

I3 = np.eye(3)

coord = st.floats(-100, 100, allow_nan=False, allow_infinity=False)
point = st.tuples(coord, coord)
angle = st.floats(-10, 10, allow_nan=False, allow_infinity=False)
factor = st.one_of(st.floats(0.1, 10), st.floats(-10, -0.1))
slope = st.floats(-3, 3, allow_nan=False, allow_infinity=False)
direction = st.tuples(coord, coord).filter(lambda d: math.hypot(*d) > 1e-3)


def close(a, b, tol=1e-9):
    np.testing.assert_allclose(a, b, rtol=0, atol=tol)


# -- exact small examples (by hand) ---------------------------------------------------
def test_translation_matrix_and_points():
    assert translation(2, -3).tolist() == [[1, 0, 2], [0, 1, -3], [0, 0, 1]]
    assert apply(translation(2, -3), [(0, 0), (1, 1)]).tolist() == [[2, -3], [3, -2]]


def test_every_builder_returns_a_fresh_float64_3x3_with_bottom_row_0_0_1():
    ms = [translation(1, 2), rotation(1.0), rotation(1.0, (1, 2)), scaling(2),
          scaling(2, 3, (1, 1)), reflection("x"), reflection_about_line((1, 2), (3, 4)),
          shear(1, 2, (3, 4)), compose(), inverse(scaling(2))]
    for m in ms:
        assert m.dtype == np.float64 and m.shape == (3, 3)
        assert m[2].tolist() == [0.0, 0.0, 1.0]
        assert not np.signbit(m[m == 0]).any()  # no -0.0: tidy printing
    a, b = translation(1, 2), translation(1, 2)
    a[0, 2] = 99
    assert b[0, 2] == 1


def test_rotation_by_quarter_turns():
    close(rotation(math.pi / 2), [[0, -1, 0], [1, 0, 0], [0, 0, 1]], 1e-15)
    close(rotation(math.pi), [[-1, 0, 0], [0, -1, 0], [0, 0, 1]], 1e-15)
    close(rotation(-math.pi / 2), [[0, 1, 0], [-1, 0, 0], [0, 0, 1]], 1e-15)
    assert rotation(0).tolist() == I3.tolist()


def test_rotation_of_a_point_by_30_degrees():
    # (2, 1) by 30 degrees: x' = 2 cos 30 - sin 30 = sqrt(3) - 1/2, y' = 2 sin 30 + cos 30 = 1 + sqrt(3)/2
    r3 = math.sqrt(3)
    close(apply(rotation(math.radians(30)), (2, 1)), [r3 - 0.5, 1 + r3 / 2], 1e-15)


def test_rotation_about_a_pivot_by_hand():
    # (5, 5) by 90 degrees about (2, 2): offset (3, 3) -> (-3, 3) -> (-1, 5)
    close(apply(rotation(math.pi / 2, pivot=(2, 2)), (5, 5)), [-1, 5], 1e-14)
    # a triangle by 180 degrees about its vertex (1, 1)
    tri = [(1, 1), (3, 1), (1, 4)]
    close(apply(rotation(math.pi, (1, 1)), tri), [(1, 1), (-1, 1), (1, -2)], 1e-14)


def test_scaling_by_hand():
    assert scaling(3).tolist() == [[3, 0, 0], [0, 3, 0], [0, 0, 1]]
    assert scaling(2, 0.5).tolist() == [[2, 0, 0], [0, 0.5, 0], [0, 0, 1]]
    # about (2, 1): x' = 2 + (x - 2) * 3, y' = 1 + (y - 1) * 0.5
    m = scaling(3, 0.5, fixed=(2, 1))
    assert m.tolist() == [[3, 0, -4], [0, 0.5, 0.5], [0, 0, 1]]
    assert apply(m, [(2, 1), (4, 5), (0, 0)]).tolist() == [[2, 1], [8, 3], [-4, 0.5]]
    assert scaling(0).tolist() == [[0, 0, 0], [0, 0, 0], [0, 0, 1]]  # allowed; no inverse


REFLECTED = {  # axis -> image of (1, 2)
    "x": (1, -2), "y": (-1, 2), "origin": (-1, -2), "y=x": (2, 1), "y=-x": (-2, -1),
}


@pytest.mark.parametrize("axis", AXES)
def test_reflections_by_hand(axis):
    assert apply(reflection(axis), (1, 2)).tolist() == list(REFLECTED[axis])


@pytest.mark.parametrize("axis, through, along", [
    ("x", (0, 0), (1, 0)), ("x", (7, 0), (-3, 0)), ("y", (0, 0), (0, 2)), ("y", (0, -5), (0, -1)),
    ("y=x", (0, 0), (1, 1)), ("y=x", (3, 3), (-2, -2)), ("y=-x", (0, 0), (1, -1)), ("y=-x", (4, -4), (-5, 5)),
])
def test_reflection_about_line_is_exact_for_the_axes_and_diagonals(axis, through, along):
    assert reflection_about_line(through, along).tolist() == reflection(axis).tolist()


def test_reflection_about_line_by_hand():
    # about y = 5: (2, 7) -> (2, 3); about x = -1: (1, 0) -> (-3, 0)
    assert apply(reflection_about_line((0, 5), (1, 0)), (2, 7)).tolist() == [2, 3]
    assert apply(reflection_about_line((-1, 0), (0, 1)), (1, 0)).tolist() == [-3, 0]
    # about y = 2x (direction (1, 2)): c = (1 - 4) / 5, s = 4 / 5; (5, 0) -> (-3, 4)
    close(reflection_about_line((0, 0), (1, 2))[:2, :2], [[-0.6, 0.8], [0.8, 0.6]], 1e-15)
    close(apply(reflection_about_line((0, 0), (1, 2)), (5, 0)), [-3, 4], 1e-14)
    # tiny and huge directions are rescaled, not underflowed or overflowed
    for d in [(1e-320, 1e-320), (1e308, 1e308), (-1e200, -1e200)]:
        assert reflection_about_line((0, 0), d).tolist() == reflection("y=x").tolist()


def test_shear_by_hand():
    square = [(0, 0), (1, 0), (1, 1), (0, 1)]
    assert shear(shx=2).tolist() == [[1, 2, 0], [0, 1, 0], [0, 0, 1]]
    assert apply(shear(shx=2), square).tolist() == [[0, 0], [1, 0], [3, 1], [2, 1]]
    # x-shear relative to y = -1 (Hearn & Baker's example, shx = 1/2): x' = x + (y + 1) / 2
    m = shear(shx=0.5, reference=(0, -1))
    assert m.tolist() == [[1, 0.5, 0.5], [0, 1, 0], [0, 0, 1]]
    assert apply(m, square).tolist() == [[0.5, 0], [1.5, 0], [2, 1], [1, 1]]
    # y-shear relative to x = -1: y' = y + (x + 1) / 2
    m = shear(shy=0.5, reference=(-1, 0))
    assert m.tolist() == [[1, 0, 0], [0.5, 1, 0.5], [0, 0, 1]]
    assert apply(m, square).tolist() == [[0, 0.5], [1, 1], [1, 2], [0, 1.5]]
    assert shear().tolist() == I3.tolist()


def test_simultaneous_shear_differs_from_one_after_the_other():
    both = shear(2, 3)
    assert both.tolist() == [[1, 2, 0], [3, 1, 0], [0, 0, 1]]
    assert compose(shear(shy=3), shear(shx=2)).tolist() == [[1, 2, 0], [3, 7, 0], [0, 0, 1]]
    assert np.linalg.det(both) == pytest.approx(1 - 2 * 3)


# -- composition ------------------------------------------------------------------------
def test_composition_order_matches_hand_computed_points():
    t, r = translation(2, 0), rotation(math.pi / 2)
    # translate first, then rotate: (1, 0) -> (3, 0) -> (0, 3)
    close(apply(compose(r, t), (1, 0)), [0, 3], 1e-15)
    # rotate first, then translate: (1, 0) -> (0, 1) -> (2, 1)
    close(apply(compose(t, r), (1, 0)), [2, 1], 1e-15)
    assert not np.allclose(compose(r, t), compose(t, r))
    # the docstring's exact example
    assert apply(compose(translation(1, 0), reflection("y=x")), (2, 0)).tolist() == [1, 2]
    assert apply(compose(reflection("y=x"), translation(1, 0)), (2, 0)).tolist() == [0, 3]


def test_compose_is_the_right_to_left_matrix_product():
    a, b, c = scaling(2, 3), translation(1, -1), reflection("y=x")
    assert compose().tolist() == I3.tolist()
    assert compose(a).tolist() == a.tolist()
    assert compose(a, b, c).tolist() == (a @ b @ c).tolist()
    p = np.array([1.5, -2.0])
    assert apply(compose(a, b, c), p).tolist() == apply(a, apply(b, apply(c, p))).tolist()
    # plain nested lists and integer arrays are matrices too
    assert compose([[1, 0, 1], [0, 1, 0], [0, 0, 1]], np.eye(3, dtype=int)).tolist() == translation(1, 0).tolist()


@HYPOTHESIS
@given(st.lists(st.sampled_from(range(5)), min_size=2, max_size=5), point, angle, factor, slope)
def test_composition_applies_right_to_left(kinds, p, theta, s, sh):
    makers = [lambda: translation(*p), lambda: rotation(theta, p), lambda: scaling(s, 1 / s, p),
              lambda: shear(sh, 0, p), lambda: reflection_about_line(p, (1, 2))]
    ms = [makers[k]() for k in kinds]
    pts = np.random.default_rng(len(kinds)).uniform(-50, 50, (7, 2))
    step = pts
    for m in reversed(ms):
        step = apply(m, step)
    close(apply(compose(*ms), pts), step, 1e-6)


# -- inverses -----------------------------------------------------------------------------
@st.composite
def affine(draw):
    """A random invertible affine matrix: a product of 1 to 5 basic transformations."""
    kinds = draw(st.lists(st.sampled_from(["t", "r", "s", "h", "f", "a"]), min_size=1, max_size=5))
    ms = []
    for k in kinds:
        if k == "t":
            ms.append(translation(draw(coord), draw(coord)))
        elif k == "r":
            ms.append(rotation(draw(angle), draw(st.none() | point)))
        elif k == "s":
            ms.append(scaling(draw(factor), draw(st.none() | factor), draw(st.none() | point)))
        elif k == "h":
            ms.append(shear(draw(slope), 0.0, draw(st.none() | point)) if draw(st.booleans())
                      else shear(0.0, draw(slope), draw(st.none() | point)))
        elif k == "f":
            ms.append(reflection(draw(st.sampled_from(AXES))))
        else:
            ms.append(reflection_about_line(draw(point), draw(direction)))
    return compose(*ms)


@HYPOTHESIS
@given(affine())
def test_inverse_times_matrix_is_the_identity(m):
    mi = inverse(m)
    assert mi[2].tolist() == [0, 0, 1]
    scale = max(1.0, np.abs(m).max() * np.abs(mi).max())
    close(compose(mi, m), I3, 1e-12 * scale)
    close(compose(m, mi), I3, 1e-12 * scale)
    close(inverse(mi), m, 1e-9 * max(1.0, np.abs(m).max()) * scale)


@HYPOTHESIS
@given(point, angle, factor, factor, point)
def test_inverses_of_the_basic_transformations(p, theta, sx, sy, f):
    assert inverse(translation(*p)).tolist() == translation(-p[0], -p[1]).tolist()
    close(inverse(rotation(theta)), rotation(-theta), 1e-15)
    close(inverse(rotation(theta, f)), rotation(-theta, f), 1e-12)
    close(inverse(scaling(sx, sy, f)), scaling(1 / sx, 1 / sy, f), 1e-11)
    # the inverse of a composite is the composite of the inverses in reverse order
    a, b = rotation(theta, f), scaling(sx, sy)
    close(inverse(compose(a, b)), compose(inverse(b), inverse(a)), 1e-11)


def test_inverse_by_hand():
    assert inverse(translation(2, 3)).tolist() == [[1, 0, -2], [0, 1, -3], [0, 0, 1]]
    assert inverse(scaling(2, 4, fixed=(1, 1))).tolist() == [[0.5, 0, 0.5], [0, 0.25, 0.75], [0, 0, 1]]
    assert inverse(shear(shx=2)).tolist() == shear(shx=-2).tolist()
    for axis in AXES:
        assert inverse(reflection(axis)).tolist() == reflection(axis).tolist()
    # extreme but invertible scales
    for s in [(1e200, 1e200), (1e-300, 1e-300), (1e-13, 1), (-3e150, 1e150)]:
        np.testing.assert_allclose(inverse(scaling(*s)), scaling(1 / s[0], 1 / s[1]), rtol=1e-15)
    # ... but a ratio of scales beyond 1/(64 eps) is numerically singular (as for
    # numpy.linalg.matrix_rank): cond(A) > 7e13
    with pytest.raises(sl.ArgumentValueError, match="^m is singular"):
        inverse(scaling(1e-14, 1))
    # a bottom row off (0, 0, 1) by rounding only is accepted, and the result is tidy
    m = translation(1, 1)
    m[2] = [1e-17, -1e-17, 1 + 2e-16]
    assert inverse(m).tolist() == translation(-1, -1).tolist()


@pytest.mark.parametrize("m", [
    scaling(0), scaling(2, 0), scaling(0, 2, fixed=(3, 4)), shear(2, 0.5), shear(-4, -0.25, (1, 1)),
    np.zeros((3, 3)) + np.diag([0, 0, 1]),
    compose(rotation(0.3), scaling(1, 0), rotation(-0.3)),  # rank 1, rounding leaves det ~1e-17
    [[1, 1 / 3, 5], [3, 1, 7], [0, 0, 1]],
])
def test_inverse_of_a_singular_matrix_is_a_clear_error(m):
    with pytest.raises(sl.ArgumentValueError, match=r"^m is singular"):
        inverse(m)


def test_inverse_overflow_is_a_clear_error():
    with pytest.raises(sl.ArgumentValueError, match="inverse of m overflows"):
        inverse(scaling(1e-310))
    with pytest.raises(sl.ArgumentValueError, match="inverse of m overflows"):
        inverse(compose(translation(1e300, 0), scaling(1e-10)))


# -- invariants -----------------------------------------------------------------------------
@HYPOTHESIS
@given(angle, point)
def test_rotation_about_a_pivot_is_t_r_t_inverse_and_keeps_the_pivot(theta, p):
    t = translation(*p)
    close(rotation(theta, p), compose(t, rotation(theta), inverse(t)), 1e-12)
    close(apply(rotation(theta, p), p), p, 1e-12)
    assert np.linalg.det(rotation(theta, p)) == pytest.approx(1, abs=1e-12)


@HYPOTHESIS
@given(angle, st.none() | point, st.lists(point, min_size=2, max_size=8))
def test_rotation_preserves_distances(theta, p, pts):
    pts = np.array(pts)
    q = apply(rotation(theta, p), pts)
    d0 = np.linalg.norm(pts[:, None] - pts[None], axis=-1)
    d1 = np.linalg.norm(q[:, None] - q[None], axis=-1)
    close(d1, d0, 1e-11)
    r = rotation(theta)[:2, :2]
    close(r.T @ r, np.eye(2), 1e-15)  # orthogonal


@HYPOTHESIS
@given(factor, st.none() | factor, point)
def test_scaling_about_a_fixed_point_keeps_it_and_is_t_s_t_inverse(sx, sy, f):
    m = scaling(sx, sy, fixed=f)
    close(apply(m, f), f, 1e-12)
    t = translation(*f)
    close(m, compose(t, scaling(sx, sy), inverse(t)), 1e-12)
    assert np.linalg.det(m) == pytest.approx(sx * (sx if sy is None else sy))


@pytest.mark.parametrize("axis", AXES)
def test_reflections_are_exact_involutions(axis):
    m = reflection(axis)
    assert (m @ m).tolist() == I3.tolist()
    assert round(np.linalg.det(m)) == (1 if axis == "origin" else -1)


def test_reflection_through_the_origin_is_the_half_turn():
    close(reflection("origin"), rotation(math.pi), 1e-15)


@HYPOTHESIS
@given(point, direction, st.floats(-5, 5), point)
def test_reflection_about_line_invariants(p0, d, k, q):
    m = reflection_about_line(p0, d)
    close(m @ m, I3, 1e-12)
    assert np.linalg.det(m) == pytest.approx(-1)
    on_line = np.add(p0, np.multiply(k, d))
    close(apply(m, on_line), on_line, 1e-9)
    # q and its image: the midpoint is on the line, the segment is perpendicular to it
    q2 = apply(m, q)
    mid = (np.asarray(q) + q2) / 2
    cross = (mid[0] - p0[0]) * d[1] - (mid[1] - p0[1]) * d[0]
    assert abs(cross) <= 1e-9 * max(1.0, math.hypot(*d)) * 300
    assert abs(np.dot(q2 - q, d)) <= 1e-9 * math.hypot(*d) * 300
    # Hearn & Baker's composite: translate, rotate the line onto the x axis, reflect, undo
    a = math.atan2(d[1], d[0])
    h = compose(translation(*p0), rotation(a), reflection("x"), rotation(-a), translation(-p0[0], -p0[1]))
    close(m, h, 1e-11)


@HYPOTHESIS
@given(slope, slope, point, coord)
def test_shear_keeps_its_reference_line(shx, shy, ref, u):
    xs = shear(shx=shx, reference=ref)
    ys = shear(shy=shy, reference=ref)
    on_x_ref = (u, ref[1])  # on y = yref
    on_y_ref = (ref[0], u)  # on x = xref
    close(apply(xs, on_x_ref), on_x_ref, 1e-12)
    close(apply(ys, on_y_ref), on_y_ref, 1e-12)
    close(apply(shear(shx, shy, ref), ref), ref, 1e-12)
    assert np.linalg.det(xs) == pytest.approx(1)
    # points move parallel to the reference line, by shx times their distance from it
    close(apply(xs, (u, ref[1] + 2)), (u + 2 * shx, ref[1] + 2), 1e-12)


# -- cross-check against shapely.affinity -------------------------------------------------------
def _shapely_points(rng):
    pts = rng.uniform(-100, 100, (25, 2))
    return pts, shapely.LineString(pts)


def _coords(geom):
    return np.asarray(geom.coords)


@HYPOTHESIS
@given(st.integers(0, 2**32 - 1), st.floats(-720, 720), point)
def test_rotation_matches_shapely(seed, degrees, origin):
    pts, line = _shapely_points(np.random.default_rng(seed))
    ref = _coords(shapely.affinity.rotate(line, degrees, origin=origin))  # degrees, counterclockwise
    close(apply(rotation(math.radians(degrees), pivot=origin), pts), ref)
    ref = _coords(shapely.affinity.rotate(line, math.radians(degrees), origin=(0, 0), use_radians=True))
    close(apply(rotation(math.radians(degrees)), pts), ref)


@HYPOTHESIS
@given(st.integers(0, 2**32 - 1), st.floats(-10, 10), st.floats(-10, 10), point)
def test_scaling_matches_shapely(seed, sx, sy, origin):
    pts, line = _shapely_points(np.random.default_rng(seed))
    ref = _coords(shapely.affinity.scale(line, sx, sy, origin=origin))
    close(apply(scaling(sx, sy, fixed=origin), pts), ref)
    ref = _coords(shapely.affinity.scale(line, sx, sx, origin=(0, 0)))
    close(apply(scaling(sx), pts), ref)


@HYPOTHESIS
@given(st.integers(0, 2**32 - 1), st.floats(-80, 80), st.floats(-80, 80), point)
def test_shear_matches_shapely_skew(seed, xs, ys, origin):
    # shapely skews by angles (degrees by default): shx = tan(xs), shy = tan(ys)
    pts, line = _shapely_points(np.random.default_rng(seed))
    ref = _coords(shapely.affinity.skew(line, xs, ys, origin=origin))
    got = apply(shear(math.tan(math.radians(xs)), math.tan(math.radians(ys)), reference=origin), pts)
    close(got, ref)
    ref = _coords(shapely.affinity.skew(line, math.radians(xs), 0, origin=origin, use_radians=True))
    close(apply(shear(shx=math.tan(math.radians(xs)), reference=origin), pts), ref)


@HYPOTHESIS
@given(st.integers(0, 2**32 - 1), point)
def test_translation_matches_shapely(seed, t):
    pts, line = _shapely_points(np.random.default_rng(seed))
    close(apply(translation(*t), pts), _coords(shapely.affinity.translate(line, *t)))


@HYPOTHESIS
@given(st.integers(0, 2**32 - 1), affine())
def test_apply_matches_shapely_affine_transform(seed, m):
    # shapely's 2-D form is [a, b, d, e, xoff, yoff]: x' = a x + b y + xoff, y' = d x + e y + yoff
    pts, line = _shapely_points(np.random.default_rng(seed))
    params = [m[0, 0], m[0, 1], m[1, 0], m[1, 1], m[0, 2], m[1, 2]]
    ref = _coords(shapely.affinity.affine_transform(line, params))
    close(apply(m, pts), ref, 1e-9 * max(1.0, np.abs(ref).max()))


# -- apply: shapes and dtypes ------------------------------------------------------------------
def test_apply_shapes_and_dtypes():
    m = translation(1, 2)
    assert apply(m, (0, 0)).shape == (2,)
    assert apply(m, [(0, 0)]).shape == (1, 2)
    assert apply(m, []).shape == (0, 2)
    assert apply(m, np.empty((0, 2))).shape == (0, 2)
    out = apply(m, np.array([[1, 2], [3, 4]], dtype=np.int32))
    assert out.dtype == np.float64 and out.tolist() == [[2, 4], [4, 6]]
    assert apply(m, [(Fraction(1, 2), Decimal("1.5"))]).tolist() == [[1.5, 3.5]]
    pts = np.array([[1.0, 2.0]])
    apply(m, pts)
    assert pts.tolist() == [[1.0, 2.0]]  # input untouched


# -- the notes, chapter 3 --------------------------------------------------------------------
@HYPOTHESIS
@given(point, point)
def test_notes_q1_translation_equations(p, t):
    # x' = x + tx, y' = y + ty; P' = P + T with column vectors P = [x y]^T (the notes
    # print [x1 x2]^T, erratum E14)
    got = apply(translation(*t), p)
    assert got.tolist() == [p[0] + t[0], p[1] + t[1]]


@HYPOTHESIS
@given(point, angle)
def test_notes_q2_rotation_about_the_origin(p, theta):
    x, y = p
    # the derivation: r and phi are the point's polar coordinates (the notes print
    # "in terms of angles θ and θ": it is φ and θ, erratum E12)
    r, phi = math.hypot(x, y), math.atan2(y, x)
    expanded = (r * math.cos(phi) * math.cos(theta) - r * math.sin(phi) * math.sin(theta),
                r * math.cos(phi) * math.sin(theta) + r * math.sin(phi) * math.cos(theta))
    close(expanded, (r * math.cos(phi + theta), r * math.sin(phi + theta)), 1e-12)
    # eq. 5-6: x' = x cos θ - y sin θ, y' = x sin θ + y cos θ
    eq56 = (x * math.cos(theta) - y * math.sin(theta), x * math.sin(theta) + y * math.cos(theta))
    close(apply(rotation(theta), p), eq56, 1e-12)
    close(expanded, eq56, 1e-12)
    # eq. 5-7: the 2x2 block is R = [[cos θ, -sin θ], [sin θ, cos θ]]
    c, s = math.cos(theta), math.sin(theta)
    assert rotation(theta)[:2, :2].tolist() == [[c, -s], [s, c]]
    # eq. 5-8: row vectors, P'^T = P^T R^T, and R^T is R with the sines' signs changed
    R = rotation(theta)[:2, :2]
    close(np.array(p) @ R.T, R @ np.array(p), 1e-12)
    close(R.T, [[c, s], [-s, c]], 0)
    close(R.T, rotation(-theta)[:2, :2], 1e-15)


@HYPOTHESIS
@given(point, angle, point)
def test_notes_q2_rotation_about_a_pivot(p, theta, pivot):
    # eq. 5-9: x' = xr + (x - xr) cos θ - (y - yr) sin θ, y' = yr + (x - xr) sin θ + (y - yr) cos θ
    (x, y), (xr, yr) = p, pivot
    c, s = math.cos(theta), math.sin(theta)
    eq59 = (xr + (x - xr) * c - (y - yr) * s, yr + (x - xr) * s + (y - yr) * c)
    close(apply(rotation(theta, pivot=pivot), p), eq59, 1e-11)
    # with the pivot at the origin eq. 5-9 is eq. 5-6 (the notes say it "simplifies"
    # eq. 5-6; it generalizes it, erratum E13)
    close(rotation(theta, pivot=(0, 0)), rotation(theta), 0)


def test_notes_q2_positive_angles_turn_anticlockwise():
    assert apply(rotation(0.1), (1, 0))[1] > 0
    assert apply(rotation(-0.1), (1, 0))[1] < 0


# -- bad input ----------------------------------------------------------------------------------
BAD_NUMBERS = [float("nan"), float("inf"), -float("inf"), np.float64("nan"), 10**400, None, "1", "",
               True, False, np.bool_(True), 1j, [1], (1,), b"1", Decimal("1"), np.array([1.0])]
BAD_POINTS = [5, 2.5, "ab", b"ab", (1,), (1, 2, 3), [], (float("nan"), 0), (0, float("inf")), ("1", 2),
              (True, 1), (1, None), (1j, 0), np.zeros((2, 2)), np.array(3.0), {1, 2}, {0: 1, 1: 2},
              (10**400, 0), np.array([1, 2, 3])]
BAD_MATRICES = [None, 3, "abc", [], np.eye(2), np.eye(4), np.ones((3, 4)), np.ones((2, 3, 3)),
                np.eye(3) > 0, np.eye(3) * 1j, [[1, 2], [3]], [["1", 0, 0], [0, 1, 0], [0, 0, 1]],
                np.where(np.eye(3) > 0, np.nan, 0.0), np.diag([1.0, np.inf, 1.0]),
                [[10**400, 0, 0], [0, 1, 0], [0, 0, 1]], np.eye(3).astype("datetime64[s]")]

bad_number = st.one_of(st.sampled_from(BAD_NUMBERS), st.text(max_size=3),
                       st.floats().filter(lambda x: not math.isfinite(x)))
bad_point = st.one_of(st.sampled_from(BAD_POINTS), st.tuples(bad_number, coord), st.tuples(coord, bad_number),
                      st.lists(coord, min_size=3, max_size=4), st.text(max_size=4))
bad_matrix = st.one_of(
    st.sampled_from(BAD_MATRICES),
    st.lists(st.lists(st.floats(), min_size=3, max_size=3), min_size=3, max_size=3).filter(
        lambda m: not np.isfinite(m).all()),
    st.lists(st.lists(coord, min_size=0, max_size=4), min_size=0, max_size=4).filter(
        lambda m: not (len(m) == 3 and all(len(r) == 3 for r in m))),
)

CALLS = {  # function -> (argument name, how to call it with the bad value in that place)
    "translation.tx": ("tx", lambda b: translation(b, 0)),
    "translation.ty": ("ty", lambda b: translation(0, b)),
    "rotation.angle": ("angle", lambda b: rotation(b)),
    "scaling.sx": ("sx", lambda b: scaling(b)),
    "scaling.sy": ("sy", lambda b: scaling(1, b)),
    "shear.shx": ("shx", lambda b: shear(b)),
    "shear.shy": ("shy", lambda b: shear(0, b)),
}
POINT_CALLS = {
    "rotation.pivot": ("pivot", lambda b: rotation(1, pivot=b)),
    "scaling.fixed": ("fixed", lambda b: scaling(2, fixed=b)),
    "shear.reference": ("reference", lambda b: shear(1, reference=b)),
    "reflection_about_line.point": ("point", lambda b: reflection_about_line(b, (1, 1))),
    "reflection_about_line.direction": ("direction", lambda b: reflection_about_line((0, 0), b)),
}
MATRIX_CALLS = {
    "inverse": ("m", inverse),
    "apply": ("m", lambda b: apply(b, [(0, 0)])),
    "compose.0": ("matrices[0]", lambda b: compose(b)),
    "compose.2": ("matrices[2]", lambda b: compose(I3, I3, b)),
}


def _raises_naming(call, name, bad):
    with pytest.raises((sl.ArgumentValueError, sl.ArgumentTypeError)) as e:
        call(bad)
    assert isinstance(e.value, sl.ScanlineError)
    assert isinstance(e.value, (ValueError, TypeError))
    assert str(e.value).startswith(name) or f" {name}" in str(e.value), str(e.value)


@HYPOTHESIS
@given(st.sampled_from(sorted(CALLS)), bad_number)
def test_bad_numbers_are_clear_errors(which, bad):
    if which == "scaling.sy" and bad is None:
        return  # sy=None means uniform scaling
    name, call = CALLS[which]
    _raises_naming(call, name, bad)


@HYPOTHESIS
@given(st.sampled_from(sorted(POINT_CALLS)), bad_point)
def test_bad_points_are_clear_errors(which, bad):
    name, call = POINT_CALLS[which]
    _raises_naming(call, name, bad)


@pytest.mark.parametrize("which", ["point", "direction"])
def test_reflection_about_line_needs_both_arguments(which):
    with pytest.raises(sl.ArgumentTypeError, match=f"^{which} must be a point"):
        reflection_about_line(**{"point": (0, 0), "direction": (1, 0), which: None})


def test_zero_direction_is_a_clear_error():
    for d in [(0, 0), (0.0, -0.0), np.zeros(2)]:
        with pytest.raises(sl.ArgumentValueError, match=r"^direction must not be \(0, 0\)"):
            reflection_about_line((1, 1), d)


@HYPOTHESIS
@given(st.sampled_from(sorted(MATRIX_CALLS)), bad_matrix)
def test_bad_matrices_are_clear_errors(which, bad):
    name, call = MATRIX_CALLS[which]
    _raises_naming(call, name, bad)


@pytest.mark.parametrize("axis", [None, "X", "xy", "y = x", "", 0, b"x", ("x",)])
def test_bad_axis_is_a_clear_error(axis):
    with pytest.raises(sl.ArgumentValueError, match="^axis must be one of 'x', 'y', 'origin', 'y=x', 'y=-x'"):
        reflection(axis)


@pytest.mark.parametrize("m", [np.ones((3, 3)), [[1, 0, 0], [0, 1, 0], [0.5, 0, 1]], 2 * np.eye(3)])
def test_projective_matrices_are_refused_by_inverse_and_apply(m):
    for call in (lambda: inverse(m), lambda: apply(m, (1, 1))):
        with pytest.raises(sl.ArgumentValueError, match="^m must be an affine 2-D transformation"):
            call()
    compose(m, m)  # the plain product is fine


def test_the_corner_hint_for_a_scaled_homogeneous_matrix():
    with pytest.raises(sl.ArgumentValueError, match="divide the matrix by its corner element 2"):
        inverse(2 * translation(1, 1))


def test_compose_suggests_unpacking_a_stack():
    with pytest.raises(sl.ArgumentValueError, match=r"compose\(\*stack\)"):
        compose(np.stack([I3, I3]))


BAD_POINT_ARRAYS = [None, 3, "ab", [1, 2, 3], [[1, 2, 3]], np.zeros((2, 2, 2)), [[1, np.nan]],
                    [[0, 0], [np.inf, 1]], [1 + 1j, 2], np.array([[True, False]]), [[1, 2], [3]],
                    [[10**400, 0]], [("a", "b")]]


@pytest.mark.parametrize("pts", BAD_POINT_ARRAYS, ids=range(len(BAD_POINT_ARRAYS)))
def test_bad_point_arrays_are_clear_errors(pts):
    _raises_naming(lambda b: apply(I3, b), "points", pts)


@HYPOTHESIS
@given(st.lists(st.lists(st.floats(), min_size=3, max_size=3), min_size=3, max_size=3))
def test_inverse_of_any_finite_3x3_returns_or_says_why(rows):
    """Any 3x3 of floats (huge, tiny, subnormal, NaN): a finite affine result or a clear error."""
    try:
        mi = inverse(rows)
    except sl.ArgumentValueError as e:
        assert str(e).startswith(("m ", "the inverse of m")), str(e)
    else:
        assert np.isfinite(mi).all() and mi[2].tolist() == [0, 0, 1]


def test_zero_scale_is_fine_until_inverted():
    m = scaling(0, 1, fixed=(5, 5))
    assert apply(m, (1, 2)).tolist() == [5, 2]
    with pytest.raises(sl.ArgumentValueError, match="^m is singular"):
        inverse(m)


# -- the lazy package surface ---------------------------------------------------------------
def test_transform_is_lazy_and_does_not_import_numba():
    code = ("import scanline, sys; assert 'scanline.transform' not in sys.modules; "
            "scanline.transform.rotation(1.0); assert 'numba' not in sys.modules, 'numba imported'")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert "transform" in dir(sl)
