"""Hardening the second half: sl.projection, sl.transform3d and sl.mesh raise only
ScanlineError, naming the argument.

Each case below raised a raw error (ZeroDivisionError, OverflowError, IndexError,
TypeError or ValueError from numpy) or returned a matrix holding inf or NaN before the
fix; they were found by fuzzing every public function with hostile arguments (NaN, inf,
1e300, 5e-324, 2**63, wrong types, empty arrays, wrong shapes).  Valid input keeps
working: a camera maps onto devices one pixel wide or high.
"""

import numpy as np
import pytest

import scanline as sl
from scanline import projection as pj
from scanline import transform3d as t3
from scanline.errors import ArgumentTypeError, ArgumentValueError

CAM = sl.Camera(eye=(0, 0, 5), target=(0, 0, 0))
CUBE = sl.mesh.cube()

#: (call, a word the message must hold): huge but finite arguments whose matrices
#: overflowed to inf or NaN (or divided by an underflowed zero).
OVERFLOWS = {
    "perspective z_prp=1e300 z_vp=-1e300": (lambda: pj.perspective(z_prp=1e300, z_vp=-1e300),
                                            "z_prp=1e+300, z_vp=-1e+300"),
    "perspective z_prp=5e-324": (lambda: pj.perspective(z_prp=5e-324, z_vp=0), "z_prp"),
    "perspective back=-5e-324 (ZeroDivisionError)": (
        lambda: pj.perspective(z_prp=1, z_vp=0, front=0, back=-5e-324), "back"),
    "perspective near=5e-324": (lambda: pj.perspective(fov=1.0, near=5e-324), "near"),
    "perspective near=5e-324 far (ZeroDivisionError)": (
        lambda: pj.perspective(fov=1.0, near=5e-324, far=1e-323), "near"),
    "perspective aspect": (lambda: pj.perspective(fov=1.0, near=1e-160, aspect=1e-160),
                           "aspect"),
    "frustum prp=1e300": (lambda: pj.frustum((1e300, 1e300, 1e300), z_vp=-1e300), "prp"),
    "frustum prp=5e-324": (lambda: pj.frustum((5e-324, 5e-324, 5e-324)), "prp"),
    "orthographic window 5e-324": (lambda: pj.orthographic(window=(0, 0, 5e-324, 5e-324)),
                                   "window"),
    "oblique alpha 1e-160": (lambda: pj.oblique(alpha=1e-160, window=(-1e-160, -1e-160, 1e-160,
                                                                      1e-160)), "alpha"),
    "projection replace back": (lambda: pj.perspective(z_prp=10, z_vp=0).replace(
        back=-5e-324, front=0), "back"),
    "scaling fixed": (lambda: t3.scaling(1e300, fixed=(1e300, 1e300, 1e300)), "fixed point"),
    "shear": (lambda: t3.shear("z", 1e300, 1e300, 1e300), "reference"),
    "reflection": (lambda: t3.reflection((1e308, 1e308, 1e308), (1, 1, 1)), "point"),
    "compose": (lambda: t3.compose(t3.scaling(1e300), t3.scaling(1e300)), "matrices[1]"),
    "apply": (lambda: t3.apply(t3.scaling(1e300), (1e300, 1e300, 1e300)), "points row 0"),
    "mesh transformed": (lambda: CUBE.transformed(t3.scaling(1e300)).transformed(
        t3.scaling(1e300)), "points row 0"),
}


@pytest.mark.parametrize("name", sorted(OVERFLOWS))
def test_arguments_whose_matrices_overflow_are_refused_by_name(name):
    make, word = OVERFLOWS[name]
    # no floating-point warning on the way either
    with np.errstate(all="raise"), pytest.raises(ArgumentValueError) as info:
        make()
    assert word in str(info.value), str(info.value)


def test_finite_projections_and_cameras_stay_finite():
    for p in (pj.perspective(z_prp=1e6, z_vp=-1e6), pj.perspective(fov=1.0, near=1e-9),
              pj.frustum((1e3, 1e3, 1e4)), pj.orthographic(window=(0, 0, 1e-100, 1e-100))):
        assert np.isfinite(p.matrix).all() and np.isfinite(p.normalization).all()
    assert np.isfinite(sl.Camera(eye=(1e300, 1e300, 1e300), target=(0, 0, 0)).matrix()).all()


#: Calls that raised a raw (non-Scanline) error: the error class they raised.
RAW = {
    "is_affine tolerance str (UFuncTypeError)": lambda: t3.is_affine(np.eye(4), tolerance="x"),
    "is_affine tolerance None (TypeError)": lambda: t3.is_affine(np.eye(4), tolerance=None),
    "is_affine tolerance [] (ValueError)": lambda: t3.is_affine(np.eye(4), tolerance=[]),
    "foreshortening NaN (IndexError)": lambda: pj.foreshortening(np.nan),
    "foreshortening str (ValueError)": lambda: pj.foreshortening("x"),
    "foreshortening object (TypeError)": lambda: pj.foreshortening(object()),
    "mapping NaN box (TypeError)": lambda: CAM.mapping(np.nan),
    "mapping str box (ValueError)": lambda: CAM.mapping("x"),
    "mapping flat box (ZeroDivisionError)": lambda: CAM.mapping((0, 0, 0, 4)),
    "mapping aspect str (TypeError)": lambda: CAM.mapping((0, 0, 9, 9), aspect="x"),
    "mapping aspect [] (ValueError)": lambda: CAM.mapping((0, 0, 9, 9), aspect=np.zeros(0)),
    "mapping aspect complex (TypeError)": lambda: CAM.mapping((0, 0, 9, 9), aspect=3 + 1j),
    "linear_depth str (ValueError)": lambda: CAM.linear_depth("x"),
    "linear_depth object (TypeError)": lambda: CAM.linear_depth(object()),
    "camera replace keep_aspect array (ValueError)": lambda: CAM.replace(
        keep_aspect=np.zeros(0)),
    "Mesh colors NaN (TypeError)": lambda: sl.mesh.Mesh(CUBE.vertices, CUBE.faces,
                                                        colors=np.nan),
    "Mesh normals NaN (IndexError)": lambda: sl.mesh.Mesh(CUBE.vertices, CUBE.faces,
                                                          normals=np.nan),
    "translated NaN (TypeError)": lambda: CUBE.translated(np.nan),
    "colored NaN (TypeError)": lambda: CUBE.colored(np.nan),
    "plane_equations tolerance str (ValueError)": lambda: CUBE.plane_equations("x"),
    "plane_equations tolerance None (TypeError)": lambda: CUBE.plane_equations(None),
    "face 2**63 (OverflowError)": lambda: CUBE.face(2**63),
    "face NaN (IndexError)": lambda: CUBE.face(np.nan),
    "face None (TypeError)": lambda: CUBE.face(None),
    "merge NaN (TypeError)": lambda: sl.mesh.merge(np.nan),
    "save to NaN (TypeError)": lambda: sl.mesh.save(CUBE, np.nan),
    "load NaN (TypeError)": lambda: sl.mesh.load(np.nan),
    "rotational_sweep closed [] (ValueError)": lambda: sl.mesh.rotational_sweep(
        [(1, 0), (1, 1)], closed=np.zeros(0)),
    "translational_sweep caps [] (ValueError)": lambda: sl.mesh.translational_sweep(
        [(1, 0), (1, 1), (0, 1)], (0, 0, 1), caps=np.zeros(0)),
    "sweep of a curve samples 2**63 (IndexError)": lambda: sl.mesh.rotational_sweep(
        sl.curves.Bezier([(1, 0), (2, 1), (1, 2)]), samples=2**63),
    "sweep of a curve samples 2**64 (ValueError)": lambda: sl.mesh.rotational_sweep(
        sl.curves.Bezier([(1, 0), (2, 1), (1, 2)]), samples=2**64),
    "teapot parts NaN (TypeError)": lambda: sl.mesh.teapot(2, parts=np.nan),
    "teapot parts [] (ValueError)": lambda: sl.mesh.teapot(2, parts=[]),
    "PolygonTables vertices NaN (IndexError)": lambda: sl.mesh.PolygonTables(
        np.nan, CUBE.edges, []),
    "PolygonTables surfaces NaN (TypeError)": lambda: sl.mesh.PolygonTables(
        CUBE.vertices, CUBE.edges, np.nan),
    "PolygonTables surfaces str (ValueError)": lambda: sl.mesh.PolygonTables(
        CUBE.vertices, CUBE.edges, "x"),
    "PolygonTables surfaces 1e300 (OverflowError)": lambda: sl.mesh.PolygonTables(
        CUBE.vertices, CUBE.edges, [[1e300, 1e300, 1e300]]),
    "PolygonTables surface 5e-324 (TypeError)": lambda: sl.mesh.PolygonTables(
        CUBE.vertices, CUBE.edges, [5e-324] * 3),
    "PolygonTables surface inf (OverflowError)": lambda: sl.mesh.PolygonTables(
        CUBE.vertices, CUBE.edges, [np.inf] * 3),
    "PolygonTables surface 2-d (ValueError)": lambda: sl.mesh.PolygonTables(
        CUBE.vertices, CUBE.edges, [np.zeros((2, 2))] * 3),
    "PolygonTables edge_surfaces NaN (TypeError)": lambda: sl.mesh.PolygonTables(
        CUBE.vertices, CUBE.edges, [[0, 1, 2]], [np.nan] * 12),
    "PolygonTables edge_surfaces str (TypeError)": lambda: sl.mesh.PolygonTables(
        CUBE.vertices, CUBE.edges, [[0, 1, 2]], ["x"] * 12).check(),
    "DepthBuffer.like of a non-frame buffer (AttributeError)": lambda: sl.DepthBuffer.like(3),
}


@pytest.mark.parametrize("name", sorted(RAW))
def test_former_raw_errors_are_scanline_errors(name):
    with pytest.raises(sl.ScanlineError):
        RAW[name]()


def test_the_tables_still_report_their_problems():
    tables = sl.mesh.PolygonTables(CUBE.vertices, np.array([[0, 2**62], [-1, 5]]),
                                   [[0, 1, 2], [7, -3]], [[0], [1, 9]])
    problems = tables.check()
    assert any("V4611686018427387905" in p for p in problems)   # numbered from 1
    assert any("E8" in p for p in problems)


# -- devices one pixel wide or high -------------------------------------------------------
def test_the_device_box_of_a_one_pixel_axis_is_the_pixel_about_its_center():
    assert CAM._device_box(1, 5) == (-0.5, 0.0, 0.5, 4.0)
    assert CAM._device_box(7, 1) == (0.0, -0.5, 6.0, 0.5)
    assert CAM._device_box(1, 1) == (-0.5, -0.5, 0.5, 0.5)
    assert CAM._device_box(640, 480) == (0.0, 0.0, 639.0, 479.0)
    with pytest.raises(ArgumentValueError, match="width"):
        CAM._device_box(0, 5)


@pytest.mark.parametrize("width, height", [(1, 1), (1, 9), (9, 1)])
def test_a_camera_projects_onto_a_one_pixel_axis(width, height):
    # the target, at the middle of the window, falls on the middle pixel's center
    x, y, depth = CAM.project((0, 0, 0), width, height)
    assert (x, y) == ((width - 1) / 2, (height - 1) / 2)
    assert 0 < depth < 1
    assert np.isfinite(CAM.matrix(width, height)).all()
    assert CAM.vanishing_point((1, 0, -1), width, height) is not None
    assert np.isfinite(CAM.volume_corners(width, height)).all()


@pytest.mark.parametrize("width, height", [(1, 1), (1, 7), (7, 1)])
def test_one_pixel_wide_frames_render(width, height):
    fb = sl.FrameBuffer(width, height, mode="L")
    sl.render(fb, sl.mesh.sphere(resolution=8), CAM)
    pixels = fb.to_array().ravel()
    assert pixels[len(pixels) // 2] > 0                 # the sphere covers the middle
    wire = sl.FrameBuffer(width, height, mode="L")
    sl.draw3d.wireframe(wire, CUBE, CAM)
    assert wire.to_array().ravel()[len(pixels) // 2] == 255


def test_mapping_takes_any_box_with_an_area():
    _, scale, offset = CAM.mapping((-0.5, 0, 0.5, 4))
    assert scale[:2].tolist() == [1.0, 4.0] and offset[:2].tolist() == [-0.5, 0.0]
    with pytest.raises(ArgumentValueError, match="x0 < x1"):
        CAM.mapping((3, 0, 3, 4))
    with pytest.raises(ArgumentTypeError, match="box"):
        CAM.mapping((0, 0, 1))
    with pytest.raises(ArgumentValueError, match="aspect"):
        CAM.mapping((0, 0, 1, 1), aspect=-2)
