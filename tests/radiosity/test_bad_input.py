"""Bad input to the radiosity functions: clear errors naming the argument, or a
bounded result; the memory budget checked before the form-factor matrix."""

import numpy as np
import pytest

import scanline as sl
from scanline.errors import ArgumentTypeError, ArgumentValueError, MemoryBudgetError


def square(z=0.0):
    return sl.mesh.Mesh([(0, 0, z), (1, 0, z), (1, 1, z), (0, 1, z)], [[0, 1, 2, 3]])


def facing():
    return [square(0.0), sl.mesh.Mesh(square(1.0).vertices, [[3, 2, 1, 0]])]


def test_a_degenerate_face_is_refused_naming_the_mesh_and_face():
    flat = sl.mesh.Mesh([(0, 0, 0), (1, 0, 0), (2, 0, 0)], [[0, 1, 2]])     # collinear
    with pytest.raises(ArgumentValueError, match=r"meshes\[1\] face 0 is degenerate"):
        sl.radiosity.patches([square(), flat])


@pytest.mark.parametrize("value, message", [
    (1.0, "reflectance must be below 1"),
    (-0.1, "reflectance must be >= 0"),
    (float("nan"), "reflectance must be finite"),
    ([(0.5, 0.5, 1.2), 0.3], "reflectance must be below 1"),
    ([0.5, 0.5, 0.5, 0.5, 0.5], r"reflectance has shape \(5,\)"),
    ("red", "reflectance must hold real numbers"),
    ([0.5, (1, 2)], r"reflectance\[1\] must be a number or \(r, g, b\)"),
])
def test_reflectance_outside_zero_to_one_is_refused(value, message):
    with pytest.raises((ArgumentValueError, ArgumentTypeError), match=message):
        sl.radiosity.solve(facing(), emission=[1.0, 0.0], reflectance=value)


@pytest.mark.parametrize("value, message", [
    ([float("nan"), 0.0], "emission must be finite"),
    ([1e300, 0.0], "emission must be at most"),
    ([-1.0, 0.0], "emission must be >= 0"),
    (None, "emission: no patch emits light"),
    (0.0, "emission: no patch emits light"),
])
def test_bad_emission_is_refused(value, message):
    with pytest.raises(ArgumentValueError, match=message):
        sl.radiosity.solve(facing(), emission=value, reflectance=0.5)


def test_a_million_emitters_are_refused_before_anything_is_built():
    n = 1000               # 10**6 quadrilaterals, each an emitter
    i, j = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    base = (i * (n + 1) + j).reshape(-1)
    faces = sl.mesh.mesh.Flat(np.stack([base, base + 1, base + n + 2, base + n + 1], 1),
                              np.full(n * n, 4))
    x, y = np.meshgrid(np.arange(n + 1.0), np.arange(n + 1.0), indexing="ij")
    grid = sl.mesh.Mesh(np.stack([x.ravel(), y.ravel(), np.zeros(x.size)], 1), faces)
    for call in (lambda: sl.radiosity.solve(grid, emission=1.0, subdivisions=1),
                 lambda: sl.radiosity.form_factors(grid, subdivisions=1)):
        with pytest.raises(ArgumentValueError, match="1,000,000 patches, more than"):
            call()


def test_the_memory_budget_is_checked_before_the_matrix(monkeypatch):
    box = sl.radiosity.cornell_box()
    monkeypatch.setenv("SCANLINE_MEMORY_LIMIT", "1M")      # 475 patches: 1.8 MB
    with pytest.raises(MemoryBudgetError, match="meshes: a 475 x 475 form-factor matrix"):
        sl.radiosity.form_factors(box["meshes"], subdivisions=5)
    with pytest.raises(MemoryBudgetError, match="method='progressive'"):
        sl.radiosity.solve(box["meshes"], box["emission"], box["reflectance"], subdivisions=5)
    # progressive refinement keeps one row at a time: within the budget
    s = sl.radiosity.solve(box["meshes"], box["emission"], box["reflectance"], subdivisions=5,
                           method="progressive", max_iterations=20)
    assert s.iterations == 20 and np.isfinite(s.radiosity).all()


@pytest.mark.parametrize("kwargs, message", [
    ({"method": "jacobi"}, "method"),
    ({"form_factors": "monte-carlo"}, "form_factors"),
    ({"resolution": 7}, "resolution of a hemicube must be even"),
    ({"resolution": 0}, "resolution"),
    ({"resolution": 10**6}, "resolution must be at most"),
    ({"form_factors": "ray-casting", "resolution": 65}, "resolution must be at most 64"),
    ({"tolerance": 0}, "tolerance must be between 0 and 1"),
    ({"tolerance": float("nan")}, "tolerance"),
    ({"max_iterations": 0}, "max_iterations"),
    ({"subdivisions": 0}, "subdivisions"),
    ({"subdivisions": 10**6}, "subdivisions must be at most"),
    ({"form_factors": np.zeros((3, 3))}, r"form_factors must be a \(2, 2\) matrix"),
    ({"form_factors": np.full((2, 2), np.nan)}, "form_factors must be finite"),
    ({"form_factors": np.full((2, 2), 0.9)}, "rows must add up to at most 1"),
])
def test_bad_options_are_refused_naming_them(kwargs, message):
    kwargs.setdefault("subdivisions", 1)
    with pytest.raises((ArgumentValueError, ArgumentTypeError), match=message):
        sl.radiosity.solve(facing(), emission=[1.0, 0.0], reflectance=0.5, **kwargs)


def test_unknown_keywords_and_non_meshes_are_refused():
    with pytest.raises(ArgumentTypeError, match="did you mean tolerance="):
        sl.radiosity.solve(facing(), emission=[1.0, 0.0], tolerence=1e-3)
    with pytest.raises(ArgumentTypeError, match=r"meshes\[1\] must be a scanline.mesh.Mesh"):
        sl.radiosity.patches([square(), "box"])
    with pytest.raises(ArgumentValueError, match="meshes is empty"):
        sl.radiosity.form_factors([])
    s = sl.radiosity.solve(facing(), emission=[1.0, 0.0], subdivisions=1)
    fb = sl.FrameBuffer(8, 8, mode="RGB")
    with pytest.raises(ArgumentTypeError, match="shading= is set by the radiosity solution"):
        s.render(fb, sl.Camera(eye=(0.5, 0.5, 3), target=(0.5, 0.5, 0)), shading="flat")
    with pytest.raises(ArgumentValueError, match="exposure"):
        s.mesh(exposure=-1)


def test_nan_geometry_never_reaches_the_kernels():
    with pytest.raises(ArgumentValueError):
        sl.mesh.Mesh([(0, 0, np.nan), (1, 0, 0), (0, 1, 0)], [[0, 1, 2]])


def test_patches_made_by_hand_are_checked_before_the_kernels():
    import dataclasses

    pts = sl.radiosity.patches(facing(), subdivisions=2, emission=[1.0, 0.0], reflectance=0.5)
    for change, message in [({"area": pts.area[:3]}, r"area must have shape \(8,\)"),
                            ({"corners": pts.corners + 100}, "corners must be vertex numbers"),
                            ({"normal": np.full((8, 3), np.nan)}, "normal must be finite"),
                            ({"mesh": pts.mesh[:, None]}, "mesh must have shape")]:
        bad = dataclasses.replace(pts, **change)
        with pytest.raises(ArgumentValueError, match="meshes: the Patches' " + message):
            sl.radiosity.solve(bad)
        with pytest.raises(ArgumentValueError, match="meshes: the Patches' " + message):
            sl.radiosity.form_factors(bad)


@pytest.mark.parametrize("far", [1e61, 1e300, -1e300])
def test_scenes_too_wide_for_finite_form_factors_are_refused(far):
    wide = sl.mesh.Mesh([(far, 0, 0), (0, 0, 0), (0, 0, 1), (1, 0, 1)], [[0, 1, 2, 3]])
    light = sl.mesh.Mesh([(0, 1, 0), (1, 1, 0), (1, 1, 1), (0, 1, 1)], [[0, 1, 2, 3]])
    with pytest.raises(sl.ScanlineError, match="span .* scale the meshes down"):
        sl.radiosity.solve([wide, light], [0, 1], 0.5, subdivisions=2)
