"""The radiosity solutions: a closed room of uniform reflectance against B = E / (1 -
rho), energy balance (emitted = absorbed), the Gauss-Seidel and progressive
solutions against numpy.linalg.solve of the same system, the Cornell box against a
dense reference (numpy.linalg.solve with ray-cast form factors at a high
resolution), the ambient term's exact total in a closed room, the node averages and
the rendered pixels."""

import numpy as np
import pytest

import scanline as sl


def closed_room(size=2.0):
    cube = sl.mesh.cube(size)
    return sl.mesh.Mesh(cube.vertices, cube.faces[:, ::-1])       # every face inward


def room_faces(size=2.0):
    """The closed room as six meshes, one per face (-x, +x, -y, +y, -z, +z)."""
    room = closed_room(size)
    return [sl.mesh.Mesh(room.vertices, [room.face(k)]) for k in range(6)]


def dense(pts, f):
    """The radiosity equations (I - rho F) B = E solved by numpy, per channel."""
    eye = np.eye(len(pts))
    return np.stack([np.linalg.solve(eye - pts.reflectance[:, c, None] * f, pts.emission[:, c])
                     for c in range(3)], axis=1)


def test_a_closed_room_that_glows_everywhere_has_b_equal_to_e_over_one_minus_rho():
    # every row of F adds up to 1, so B = E + rho B everywhere: B = E / (1 - rho)
    s = sl.radiosity.solve(closed_room(), emission=(1.0, 2.0, 0.5), reflectance=(0.5, 0.25, 0.8),
                           subdivisions=3, tolerance=1e-5)
    assert s.converged
    expected = np.array([1.0, 2.0, 0.5]) / (1 - np.array([0.5, 0.25, 0.8]))
    assert s.radiosity == pytest.approx(np.broadcast_to(expected, (54, 3)), rel=2e-3)
    assert s.vertex_radiosity == pytest.approx(
        np.broadcast_to(expected, s.vertex_radiosity.shape), rel=2e-3)


def test_a_closed_room_that_glows_everywhere_by_progressive_refinement():
    # shooting receives through the columns of F (F_ji = F_ij A_i / A_j), which add up
    # to 1 only in the limit of small patches: the total is exact (the rows add up to
    # 1, and the ambient term accounts for what is unshot), each patch within 6%
    rho = np.array([0.5, 0.25, 0.6])
    s = sl.radiosity.solve(closed_room(), emission=(1.0, 2.0, 0.5), reflectance=rho,
                           subdivisions=3, method="progressive", tolerance=1e-3)
    assert s.converged
    expected = np.array([1.0, 2.0, 0.5]) / (1 - rho)
    p = s.patches
    total = (p.area[:, None] * s.radiosity).sum(axis=0) / p.area.sum()
    assert total == pytest.approx(expected, rel=1e-3)
    assert s.radiosity == pytest.approx(np.broadcast_to(expected, (54, 3)), rel=0.06)


@pytest.mark.parametrize("method", ["gauss-seidel", "progressive"])
@pytest.mark.parametrize("form_factors", ["hemicube", "ray-casting"])
def test_energy_balance_emitted_equals_absorbed(method, form_factors):
    # a closed room: the light emitted is all absorbed at last; patch i absorbs
    # (1 - rho_i) H_i A_i, H_i = (B_i - E_i) / rho_i the light arriving
    rho = [0.3, 0.5, 0.7, 0.6, 0.4, 0.8]
    emission = [0, 0, 0, 0, 0, (2.0, 1.0, 0.5)]                  # the ceiling
    s = sl.radiosity.solve(room_faces(), emission=emission, reflectance=rho, subdivisions=4,
                           method=method, form_factors=form_factors, tolerance=1e-7)
    p = s.patches
    arriving = (s.radiosity - p.emission) / p.reflectance
    absorbed = (p.area[:, None] * (1 - p.reflectance) * arriving).sum(axis=0)
    emitted = (p.area[:, None] * p.emission).sum(axis=0)
    assert absorbed == pytest.approx(emitted, rel=0.01)


def test_gauss_seidel_and_progressive_solve_the_same_system_as_numpy():
    box = sl.radiosity.cornell_box()
    pts = sl.radiosity.patches(box["meshes"], 3, box["emission"], box["reflectance"])
    f = sl.radiosity.form_factors(pts)
    reference = dense(pts, f)
    gs = sl.radiosity.solve(pts, form_factors=f, tolerance=1e-10)
    assert gs.converged and gs.radiosity == pytest.approx(reference, rel=1e-8, abs=1e-10)
    assert gs.form_factors is f or np.array_equal(gs.form_factors, f)
    pr = sl.radiosity.solve(pts, method="progressive", form_factors=f, tolerance=1e-10)
    assert pr.converged and pr.radiosity == pytest.approx(reference, rel=1e-7, abs=1e-9)


@pytest.fixture(scope="module")
def cornell_reference():
    """The Cornell box at 5 x 5 patches per face and its dense reference: ray-cast
    form factors at 8 x 8 points per patch, the system solved by numpy."""
    box = sl.radiosity.cornell_box()
    pts = sl.radiosity.patches(box["meshes"], 5, box["emission"], box["reflectance"])
    fine = sl.radiosity.form_factors(pts, method="ray-casting", resolution=8)
    return box, pts, dense(pts, fine)


# Gauss-Seidel gathers through the rows of F like the reference.  Progressive
# refinement receives what the shooter sends: by ray casting from each receiver to
# the shooter (Wallace et al. 1989) as accurate as gathering; by the shooter's
# hemicube and reciprocity F_ji = F_ij A_i / A_j (Cohen et al. 1988), whose
# centre-point error is largest next to the shooter and on the floor around the
# blocks.  Patches shooting in groups of 3 x 3 (Cohen et al. 1986's patches and
# elements) shoot their mean unshot radiosity from their centroid: a coarser
# shooter, a larger error.  Tolerances: each surface's mean, and the patches'
# area-weighted RMS difference over the reference's RMS.
@pytest.mark.parametrize("method, form_factors, group, surfaces, patches", [
    ("gauss-seidel", "hemicube", 1, 0.03, 0.04),
    ("gauss-seidel", "ray-casting", 1, 0.02, 0.03),
    ("progressive", "ray-casting", 1, 0.02, 0.03),
    ("progressive", "hemicube", 1, 0.06, 0.12),
    ("progressive", "ray-casting", 3, 0.06, 0.08),
    ("progressive", "hemicube", 3, 0.15, 0.25),
])
def test_the_cornell_box_is_close_to_a_dense_reference(cornell_reference, method, form_factors,
                                                        group, surfaces, patches):
    box, pts, reference = cornell_reference
    s = sl.radiosity.solve(pts, method=method, form_factors=form_factors, tolerance=1e-5,
                           shooting_group=group)
    assert s.converged

    def by_surface(b):
        return np.array([(pts.area[pts.mesh == k, None] * b[pts.mesh == k]).sum(axis=0)
                         / pts.area[pts.mesh == k].sum() for k in range(len(box["names"]))])

    assert by_surface(s.radiosity) == pytest.approx(by_surface(reference), rel=surfaces)
    lit = pts.emission.max(axis=1) == 0
    w = pts.area[lit, None]
    rms = np.sqrt((w * (s.radiosity[lit] - reference[lit]) ** 2).sum() / w.sum())
    assert rms < patches * np.sqrt((w * reference[lit] ** 2).sum() / w.sum())


def test_the_cornell_box_bleeds_color(cornell_reference):
    box, pts, _ = cornell_reference
    s = sl.radiosity.solve(pts)
    # the floor next to the red wall is redder than next to the green one, and
    # the other way round for green
    floor = pts.mesh == box["names"].index("floor")
    red_side = floor & (pts.centre[:, 0] > 0.45)
    green_side = floor & (pts.centre[:, 0] < 0.10)
    b = s.radiosity
    assert (b[red_side, 0] / b[red_side, 1]).mean() > 1.1 * (b[green_side, 0]
                                                            / b[green_side, 1]).mean()
    assert (b[green_side, 1] / b[green_side, 0]).mean() > 1.1 * (b[red_side, 1]
                                                                / b[red_side, 0]).mean()


def test_progressive_history_unshot_energy_falls_at_every_shot():
    box = sl.radiosity.cornell_box()
    s = sl.radiosity.solve(box["meshes"], box["emission"], box["reflectance"], subdivisions=2,
                           method="progressive", tolerance=1e-3)
    assert s.converged and s.history[-1] <= 1e-3 < s.history[-2]
    assert (np.diff(s.history) < 0).all()
    assert (np.diff(s.power) >= 0).all()      # (a patch under a block shoots nothing)
    assert s.form_factors is None


def test_gauss_seidel_history_is_the_largest_change_of_each_sweep():
    box = sl.radiosity.cornell_box()
    s = sl.radiosity.solve(box["meshes"], box["emission"], box["reflectance"], subdivisions=2,
                           tolerance=1e-6)
    assert s.converged and s.history[-1] <= 1e-6 < s.history[-2]
    assert (np.diff(s.history) < 0).all()


@pytest.mark.parametrize("method", ["gauss-seidel", "progressive"])
def test_max_iterations_bounds_the_solution(method):
    box = sl.radiosity.cornell_box()
    s = sl.radiosity.solve(box["meshes"], box["emission"], box["reflectance"], subdivisions=2,
                           method=method, tolerance=1e-9, max_iterations=3)
    assert s.iterations == 3 and not s.converged
    assert np.isfinite(s.radiosity).all()


@pytest.mark.parametrize("shots", [1, 3, 10])
def test_the_ambient_term_makes_the_total_exact_in_a_closed_uniform_room(shots):
    # rho uniform and rows adding up to 1: the energy still unshot, U, will add
    # rho U / (1 - rho) more, which is what the ambient term adds (Cohen et al. 1988)
    rho, e = 0.6, np.zeros((6, 3))
    e[5] = (1.0, 0.5, 0.25)
    s = sl.radiosity.solve(room_faces(), emission=e, reflectance=rho, subdivisions=2,
                           method="progressive", max_iterations=shots)
    p = s.patches
    total = (p.area[:, None] * s.radiosity).sum(axis=0)
    exact = (p.area[:, None] * p.emission).sum(axis=0) / (1 - rho)
    assert total == pytest.approx(exact, rel=1e-3)
    assert (s.ambient > 0).all()


def test_node_radiosity_is_the_mean_of_the_patches_around_it():
    square = sl.mesh.Mesh([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], [[0, 1, 2, 3]])
    pts = sl.radiosity.patches(square, subdivisions=2)
    b = np.array([[1.0, 0, 0], [2.0, 0, 0], [4.0, 0, 0], [8.0, 0, 0]])
    nodes = sl.radiosity.vertex_radiosity(pts, b)
    at = {tuple(np.round(x, 6)): value for x, value in zip(pts.vertices, nodes[:, 0])}
    centre = pts.centre[:, :2]
    # the middle node touches all four patches; an edge midpoint two; a corner one
    assert at[(0.5, 0.5, 0.0)] == pytest.approx(15 / 4)
    low_left = int(np.argmin(centre.sum(axis=1)))
    assert at[(0.0, 0.0, 0.0)] == b[low_left, 0]
    bottom = np.flatnonzero(centre[:, 1] < 0.5)
    assert at[(0.5, 0.0, 0.0)] == pytest.approx(b[bottom, 0].mean())


def test_shooting_groups_are_blocks_of_a_face_grid():
    square = sl.mesh.Mesh([(0, 0, 0), (4, 0, 0), (4, 4, 0), (0, 4, 0)], [[0, 1, 2, 3]])
    tri = sl.mesh.Mesh([(0, 0, 1), (1, 0, 1), (0, 1, 1)], [[0, 1, 2]])
    pts = sl.radiosity.patches([square, tri], subdivisions=4)
    group = pts.groups(2)
    assert sorted(np.bincount(group).tolist()) == [1] * 16 + [4] * 4     # triangles alone
    for g in set(group[:16].tolist()):          # each block: one quadrant of the square
        c = pts.centre[group == g, :2]
        assert len({tuple(x) for x in np.floor(c / 2)}) == 1
    assert len(set(pts.groups(3)[:16].tolist())) == 4              # 3 + 1 rows and columns


def test_a_triangle_is_cut_into_n_squared_triangles_of_equal_area():
    tri = sl.mesh.Mesh([(0, 0, 0), (3, 0, 0), (0, 3, 0)], [[0, 1, 2]])
    pts = sl.radiosity.patches(tri, subdivisions=3)
    assert len(pts) == 9 and pts.area == pytest.approx(np.full(9, 4.5 / 9))
    assert pts.normal == pytest.approx(np.tile([0, 0, 1.0], (9, 1)))
    assert (pts.corners[:, 3] == pts.corners[:, 2]).all()


def test_default_reflectance_is_kd_times_the_linear_color():
    red = sl.mesh.cube(colors="red")
    gray = sl.mesh.cube(material=sl.lighting.Material(kd=0.5, color=(128, 128, 128)))
    pts = sl.radiosity.patches([red, gray], subdivisions=1)
    assert pts.reflectance[:6] == pytest.approx(np.tile([0.7, 0.0, 0.0], (6, 1)))
    assert pts.reflectance[6:] == pytest.approx(np.full((6, 3), 0.5 * (128 / 255) ** 2.2))


def test_the_render_shows_each_radiosity_gouraud_shaded():
    # a room glowing uniformly: B = 1 / (1 - 0.5) = 2 everywhere; exposure 0.25 shows
    # linear 0.5, stored as 255 x 0.5 ** (1 / 2.2) = 186
    s = sl.radiosity.solve(closed_room(), emission=1.0, reflectance=0.5, subdivisions=2)
    fb = sl.FrameBuffer(40, 30, mode="RGB", background="black")
    cam = sl.Camera(eye=(0, 0, 0.5), target=(0, 0, -1), up=(0, 1, 0),
                    projection=sl.projection.perspective(fov=1.2, near=0.1, far=10))
    s.render(fb, cam, exposure=0.25)
    pixels = fb.to_array().reshape(-1, 3)
    assert np.abs(pixels.astype(int) - 186).max() <= 1
    mesh = s.mesh(exposure=0.25)
    assert mesh.face_count == 24 and mesh.color_on == "vertex"
