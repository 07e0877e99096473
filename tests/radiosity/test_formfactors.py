"""Form factors against closed forms written here: two parallel, directly opposed
rectangles and two perpendicular rectangles with a common edge (Howell's catalog of
radiation configuration factors, configurations C-11 and C-14), the centre of a
square seeing a parallel coaxial square (configuration B-3, differential to
finite), reciprocity A_i F_ij = A_j F_ji, rows adding up to 1 in a closed room,
and a screen that hides one plate from another."""

import math

import numpy as np
import pytest

import scanline as sl

METHODS = [("hemicube", 100), ("ray-casting", 4)]


def parallel_rectangles(a, b, c):
    """Howell C-11: rectangle a x b to the identical rectangle directly opposite at
    distance c."""
    x, y = a / c, b / c
    return 2 / (math.pi * x * y) * (
        math.log(math.sqrt((1 + x * x) * (1 + y * y) / (1 + x * x + y * y)))
        + x * math.sqrt(1 + y * y) * math.atan(x / math.sqrt(1 + y * y))
        + y * math.sqrt(1 + x * x) * math.atan(y / math.sqrt(1 + x * x))
        - x * math.atan(x) - y * math.atan(y))


def perpendicular_rectangles(l, w, h):
    """Howell C-14: from rectangle l x w to rectangle l x h, perpendicular to it,
    sharing the edge of length l."""
    hh, ww = h / l, w / l
    a = (1 + ww * ww) * (1 + hh * hh) / (1 + ww * ww + hh * hh)
    b = (ww * ww * (1 + ww * ww + hh * hh) / ((1 + ww * ww) * (ww * ww + hh * hh))) ** (ww * ww)
    c = (hh * hh * (1 + hh * hh + ww * ww) / ((1 + hh * hh) * (hh * hh + ww * ww))) ** (hh * hh)
    return 1 / (math.pi * ww) * (ww * math.atan(1 / ww) + hh * math.atan(1 / hh)
                                 - math.sqrt(hh * hh + ww * ww)
                                 * math.atan(1 / math.sqrt(hh * hh + ww * ww))
                                 + 0.25 * math.log(a * b * c))


def square_centre_to_coaxial_square(half, c):
    """Howell B-3 (by the sum of four corner rectangles): from a differential area
    facing a parallel square of side 2 half, its normal through the square's centre,
    at distance c."""
    x = y = half / c
    corner = 1 / (2 * math.pi) * (x / math.sqrt(1 + x * x) * math.atan(y / math.sqrt(1 + x * x))
                                  + y / math.sqrt(1 + y * y) * math.atan(x / math.sqrt(1 + y * y)))
    return 4 * corner


def rectangle(corners):
    return sl.mesh.Mesh(corners, [[0, 1, 2, 3]])


def between(f, patches, a, b):
    """F from mesh a to mesh b: the area-weighted mean over a's patches of the sum
    of their rows over b's patches."""
    sa, sb = patches.mesh == a, patches.mesh == b
    return float((patches.area[sa, None] * f[np.ix_(sa, sb)]).sum() / patches.area[sa].sum())


@pytest.mark.parametrize("method, resolution", METHODS)
@pytest.mark.parametrize("a, b, c", [(1.0, 1.0, 1.0), (2.0, 1.0, 1.0), (1.0, 1.0, 0.5)])
def test_parallel_rectangles_match_howell_c11(method, resolution, a, b, c):
    low = rectangle([(0, 0, 0), (a, 0, 0), (a, b, 0), (0, b, 0)])       # faces +z
    high = rectangle([(0, 0, c), (0, b, c), (a, b, c), (a, 0, c)])      # faces -z
    pts = sl.radiosity.patches([low, high], subdivisions=8)
    f = sl.radiosity.form_factors(pts, method=method, resolution=resolution)
    expected = parallel_rectangles(a, b, c)
    # the centre of each patch stands for the patch: 1% at 8 x 8 patches
    assert between(f, pts, 0, 1) == pytest.approx(expected, rel=0.01)
    assert between(f, pts, 1, 0) == pytest.approx(expected, rel=0.01)


# (a receiving patch next to the common edge is near the sending patch's centre: the
# ray cast takes more points on it there)
@pytest.mark.parametrize("method, resolution", [("hemicube", 100), ("ray-casting", 8)])
@pytest.mark.parametrize("l, w, h", [(1.0, 1.0, 1.0), (2.0, 1.0, 0.5), (1.0, 0.5, 2.0)])
def test_perpendicular_rectangles_match_howell_c14(method, resolution, l, w, h):
    floor = rectangle([(0, 0, 0), (l, 0, 0), (l, w, 0), (0, w, 0)])     # faces +z
    wall = rectangle([(0, 0, 0), (0, 0, h), (l, 0, h), (l, 0, 0)])      # faces +y
    pts = sl.radiosity.patches([floor, wall], subdivisions=8)
    f = sl.radiosity.form_factors(pts, method=method, resolution=resolution)
    # the patch centres next to the common edge make the largest error: 3% at 8 x 8
    assert between(f, pts, 0, 1) == pytest.approx(perpendicular_rectangles(l, w, h), rel=0.03)
    assert between(f, pts, 1, 0) == pytest.approx(perpendicular_rectangles(l, h, w), rel=0.03)


@pytest.mark.parametrize("method, resolution, tolerance", [("hemicube", 200, 0.002),
                                                           ("ray-casting", 16, 0.002)])
def test_one_patch_row_is_the_differential_form_factor_b3(method, resolution, tolerance):
    # a row is the form factor from the centre of the patch: exactly Howell B-3
    low = rectangle([(-0.5, -0.5, 0), (0.5, -0.5, 0), (0.5, 0.5, 0), (-0.5, 0.5, 0)])
    high = rectangle([(-1, -1, 1), (-1, 1, 1), (1, 1, 1), (1, -1, 1)])
    f = sl.radiosity.form_factors([low, high], subdivisions=1, method=method,
                                  resolution=resolution)
    assert f[0, 1] == pytest.approx(square_centre_to_coaxial_square(1.0, 1.0), abs=tolerance)


def closed_room(size=2.0):
    cube = sl.mesh.cube(size)
    return sl.mesh.Mesh(cube.vertices, cube.faces[:, ::-1])       # every face inward


@pytest.mark.parametrize("method, resolution, tolerance", [("hemicube", 100, 2e-3),
                                                           ("ray-casting", 4, 2e-2)])
def test_rows_add_up_to_one_in_a_closed_room(method, resolution, tolerance):
    f = sl.radiosity.form_factors(closed_room(), subdivisions=4, method=method,
                                  resolution=resolution)
    assert f.shape == (96, 96)
    assert np.abs(f.sum(axis=1) - 1).max() < tolerance
    assert (np.diag(f) == 0).all()             # a flat patch does not see itself


@pytest.mark.parametrize("method, resolution, tolerance", [("hemicube", 400, 0.01),
                                                           ("ray-casting", 4, 1e-9)])
def test_reciprocity_between_patches_of_opposed_plates(method, resolution, tolerance):
    # equal patches of two opposed plates: the row from the centre of i to j equals
    # the row from the centre of j to i (the pair's half turn), so A_i F_ij = A_j F_ji
    # patch by patch; the hemicube's cells alias by up to 1% at 400 cells
    first = rectangle([(0, 0, 0), (1, 0, 0), (1, 2, 0), (0, 2, 0)])
    second = rectangle([(0, 0, 1), (0, 2, 1), (1, 2, 1), (1, 0, 1)])
    pts = sl.radiosity.patches([first, second], subdivisions=6)
    f = sl.radiosity.form_factors(pts, method=method, resolution=resolution)
    af = pts.area[:, None] * f
    assert np.abs(af - af.T).max() <= tolerance * af.max()
    assert (f[np.ix_(pts.mesh == 0, pts.mesh == 1)] > 0).all()


@pytest.mark.parametrize("method, resolution", METHODS)
def test_reciprocity_between_the_surfaces_of_the_empty_cornell_box(method, resolution):
    # (without the blocks: a floor patch partly under a block is seen by the block
    # but sees nothing from its centre, which only finer patches make up for)
    box = sl.radiosity.cornell_box()
    meshes = [m for m, name in zip(box["meshes"], box["names"]) if "block" not in name]
    pts = sl.radiosity.patches(meshes, subdivisions=4)
    f = sl.radiosity.form_factors(pts, method=method, resolution=resolution)
    n = len(meshes)
    total = np.zeros((n, n))           # A_a F_ab between whole surfaces a and b
    np.add.at(total, (pts.mesh[:, None], pts.mesh[None, :]), pts.area[:, None] * f)
    assert total == pytest.approx(total.T, rel=0.05, abs=0.01 * total.max())


@pytest.mark.parametrize("method, resolution", [("hemicube", 100), ("ray-casting", 16)])
def test_a_screen_hides_one_plate_from_the_other(method, resolution):
    low = rectangle([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)])
    high = rectangle([(0, 0, 2), (0, 1, 2), (1, 1, 2), (1, 0, 2)])
    screen = rectangle([(-5, -5, 1), (5, -5, 1), (5, 5, 1), (-5, 5, 1)])  # faces +z
    pts = sl.radiosity.patches([low, high, screen], subdivisions=2)
    f = sl.radiosity.form_factors(pts, method=method, resolution=resolution)
    assert between(f, pts, 0, 1) == 0.0 and between(f, pts, 1, 0) == 0.0
    # the high plate sees the screen's front over nearly all of its hemisphere
    assert between(f, pts, 1, 2) > 0.95
    assert between(f, pts, 0, 2) == 0.0       # the screen's back (seen from below) sends nothing


def test_delta_form_factors_add_up_to_one():
    top, side = sl.radiosity.delta_form_factors(200)
    assert top.shape == (200, 200) and side.shape == (100, 200)
    assert top.sum() + 4 * side.sum() == pytest.approx(1.0, abs=1e-4)
    # the top's centre cell: dA / pi (Cohen and Greenberg 1985, equation 9 at x = y = 0)
    assert top[100, 100] == pytest.approx((2 / 200) ** 2 / math.pi, rel=1e-3)
