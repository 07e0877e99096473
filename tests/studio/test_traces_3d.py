"""The back-face and the Gouraud / Phong step tables against closed forms and against
what the renderer draws, and their explorer views."""

import numpy as np
import pytest

import scanline as sl
from scanline.errors import ArgumentValueError
from scanline.studio import explorer
from scanline.trace import backface, shading


def _numbers(text):
    return np.array([float(c) for c in text.strip("()").split(", ")])


@pytest.mark.parametrize("eye", [(3, 2, 4), (0, 0, 5), (-6, 1, 0.5), (0.5, -4, -3),
                                 (2.5, 2.5, 2.5), (0, 5, 0), (0, -3, 0)])
def test_back_face_is_the_sign_of_v_dot_n(eye):
    """Each face of the cube (edge 2 about the origin) lies in the plane N . P = 1, so
    V . N = (P - eye) . N = 1 - eye . N whatever the vertex P: a back face where it is
    positive."""
    t = sl.trace.back_face(eye)
    normals = {tuple(_numbers(r["N"])) for r in t.rows}
    assert normals == {tuple(s * e) for s in (1.0, -1.0) for e in np.eye(3)}
    for r in t.rows:
        n, p = _numbers(r["N"]), _numbers(r["P"])
        assert n @ p == pytest.approx(1.0)
        expected = 1.0 - np.dot(eye, n)
        assert r["V.N"] == pytest.approx(expected, abs=1e-6)
        if abs(expected) > 1e-9:    # edge-on (eye in the face's plane): either verdict
            assert r["result"] == ("back" if expected > 0 else "front")


def test_back_face_refuses_an_eye_inside_the_cube():
    with pytest.raises(ArgumentValueError, match="inside the cube"):
        sl.trace.back_face((0.5, 0, 0))
    with pytest.raises(ArgumentValueError, match="eye"):
        sl.trace.back_face((1, 2))


def _drawn_row(model, row):
    """Row ``row`` (y up) of the built-in sphere as sl.render draws it, gamma 1."""
    prepared, lights = shading.scene()
    fb = sl.FrameBuffer(shading.WIDTH, shading.HEIGHT, background="black")
    sl.render(fb, sl.mesh.sphere(1.5, resolution=8), prepared.camera, shading=model,
              lights=list(lights), materials=prepared.materials[0], gamma=1.0)
    return fb.to_array()[::-1][row, :, 0]


@pytest.mark.parametrize("model, row", [("gouraud", 12), ("gouraud", 5), ("phong", 12),
                                        ("phong", 18)])
def test_shading_rows_are_what_the_renderer_stores(model, row):
    t = getattr(sl.trace, model)(row)
    drawn = _drawn_row(model, row)
    assert [r["x"] for r in t.rows] == np.flatnonzero(drawn).tolist()
    stored = np.rint(255 * np.clip([r["I"] for r in t.rows], 0, 1))
    assert np.abs(stored - drawn[[r["x"] for r in t.rows]]).max() <= 1
    for r in t.rows:
        lam = np.array([r["l0"], r["l1"], r["l2"]])
        assert lam.sum() == pytest.approx(1.0, abs=1e-5) and (lam >= -1e-6).all()
        if model == "gouraud":      # I = sum l_k I_k
            assert r["I"] == pytest.approx(lam @ [r["I0"], r["I1"], r["I2"]], abs=1e-5)
        else:
            assert np.linalg.norm(_numbers(r["N"])) == pytest.approx(1.0, abs=1e-5)


def test_phong_normals_turn_across_the_sphere():
    """On the row through the center the sphere's normal runs from -x to +x: the
    interpolated normals' x grows along the row, mirror-symmetric about the middle."""
    t = sl.trace.phong(12)
    nx = [_numbers(r["N"])[0] for r in t.rows]
    assert all(b > a for a, b in zip(nx, nx[1:]))
    assert nx[0] == pytest.approx(-nx[-1], abs=1e-6)


def test_shading_refuses_a_row_off_the_device():
    with pytest.raises(ArgumentValueError, match="row must be a scan line 0..23"):
        sl.trace.gouraud(24)


@pytest.mark.parametrize("algorithm", ["back-face", "gouraud", "phong"])
def test_explorer_views_draw_each_step(algorithm):
    view = explorer.explore(algorithm, explorer.DEFAULTS[algorithm])
    assert view["count"] == len(view["steps"]) > 0
    assert all(s["areas"] and s["rule"] for s in view["steps"])
