"""The Utah teapot: the data, shared patch boundaries, watertightness where the
teapot is closed, the bounding box, orientation and outward normals."""

from collections import Counter

import numpy as np
import pytest

import scanline as sl
from scanline.curves.teapot import PARTS, teapot_data


def test_data_has_newells_32_patches_and_306_vertices():
    patches, vertices = teapot_data()
    assert patches.shape == (32, 16) and vertices.shape == (306, 3)
    assert patches.min() == 0 and patches.max() == 305
    # four points 0.002 from the lid's axis are listed but unused (1-based 205, 206, 216, 223)
    assert sorted(set(range(306)) - set(patches.ravel().tolist())) == [204, 205, 215, 222]
    assert vertices[0].tolist() == [1.4, 0.0, 2.4] and vertices[-1].tolist() == [1.425, -0.798, 0.0]
    assert sum(len(r) for r in PARTS.values()) == 32


def test_data_is_symmetric_about_the_xz_plane():
    _, vertices = teapot_data()
    points = {tuple(p) for p in vertices.round(9).tolist()}
    mirrored = {(x, -y + 0.0, z) for x, y, z in points}
    assert points == mirrored


def test_shared_patch_boundaries_coincide():
    """Wherever two patches share a boundary row of control points, their boundary
    curves are the same points (C0 continuity, notes ch. 5 Q.1)."""
    patches, _ = teapot_data()
    surfaces = sl.curves.teapot()
    t = np.linspace(0, 1, 33)
    sides = {"u0": (0.0, t), "u1": (1.0, t), "v0": (t, 0.0), "v1": (t, 1.0)}

    def rows(p):
        grid = patches[p].reshape(4, 4).T          # teapot() transposes each net
        return {"u0": grid[0], "u1": grid[-1], "v0": grid[:, 0], "v1": grid[:, -1]}

    shared = 0
    for p in range(32):
        for q in range(p + 1, 32):
            for a, ra in rows(p).items():
                for b, rb in rows(q).items():
                    if len(set(ra.tolist())) == 1:
                        continue                   # a pole, not an edge
                    for flip in (False, True):
                        if (ra == (rb[::-1] if flip else rb)).all():
                            pa = surfaces[p].evaluate(*sides[a])
                            pb = surfaces[q].evaluate(*sides[b])
                            np.testing.assert_allclose(pa, pb[::-1] if flip else pb, atol=1e-12)
                            shared += 1
    # rim 4 + body 8 x 2 rings + ... : each part's seams and the rings between parts
    assert shared >= 40


def _edges(triangles):
    return np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]])


@pytest.mark.parametrize("parts,openings", [
    (("rim", "body", "bottom"), [(2.4, 1.4)]),     # closed but for the opening under the lid
    ("lid", [(2.4, 1.3)]),                          # closed but for the lid's rim
])
def test_teapot_is_watertight_where_it_is_closed(parts, openings):
    verts, tris, _ = sl.curves.teapot_mesh(8, parts=parts)
    undirected = Counter(tuple(sorted(e)) for e in _edges(tris).tolist())
    assert max(undirected.values()) == 2                   # manifold
    border = np.array([e for e, n in undirected.items() if n == 1])
    ends = verts[np.unique(border)]
    (z, r), = openings
    np.testing.assert_allclose(ends[:, 2], z, atol=1e-12)
    radius = np.hypot(ends[:, 0], ends[:, 1])
    # the opening is the rim's cubic approximation of a circle: r within 1 % of z's
    assert np.all(np.abs(radius - r) <= 0.01 * r)
    assert len(border) == 4 * 8                            # one loop: 4 patches x 8 intervals


@pytest.mark.parametrize("part", ["handle", "spout"])
def test_handle_and_spout_are_tubes_open_at_both_ends(part):
    verts, tris, _ = sl.curves.teapot_mesh(6, parts=part)
    undirected = Counter(tuple(sorted(e)) for e in _edges(tris).tolist())
    assert max(undirected.values()) == 2
    assert sum(n == 1 for n in undirected.values()) == 2 * 2 * 6   # two rings of 2 patches


def test_orientation_is_consistent_over_the_whole_teapot():
    verts, tris, normals = sl.curves.teapot_mesh(8)
    directed = Counter(map(tuple, _edges(tris).tolist()))
    assert max(directed.values()) == 1      # no edge traversed twice the same way
    face = np.cross(verts[tris[:, 1]] - verts[tris[:, 0]], verts[tris[:, 2]] - verts[tris[:, 0]])
    assert ((face * normals[tris].mean(axis=1)).sum(axis=1) > 0).all()
    assert np.isfinite(normals).all()
    np.testing.assert_allclose(np.linalg.norm(normals, axis=1), 1.0)


def test_normals_point_outward():
    surfaces = sl.curves.teapot()
    u, v = np.meshgrid(np.linspace(0, 1, 9), np.linspace(0, 1, 9))
    for p in PARTS["body"]:
        points, normals = surfaces[p].evaluate(u, v), surfaces[p].normal(u, v)
        radial = points * [1, 1, 0]
        assert ((normals * radial).sum(-1) > 0).all()
    for p in PARTS["bottom"]:
        n = surfaces[p].normal(u, v)
        assert (n[..., 2][surfaces[p].evaluate(u, v)[..., 2] < 1e-9] < -0.999).all()
    knob_top = surfaces[PARTS["lid"][0]].normal(0.5, 0.0)   # the lid's pole (v = 0), z = 3.15
    np.testing.assert_allclose(knob_top, [0, 0, 1], atol=1e-6)
    # the handle and the spout's tube (not its tip, whose lip rolls back over itself;
    # consistent orientation with the tube is checked on the whole mesh above)
    for part, patches in (("handle", PARTS["handle"]), ("spout", PARTS["spout"][:2])):
        for p in patches:
            s = surfaces[p]
            # v runs along the tube, u around it from one seam (u = 0) to the other
            # (u = 1), both in the plane y = 0 on opposite sides: the tube's axis at
            # v = t is the midpoint of the two seam points
            t = np.linspace(0.05, 0.95, 7)
            axis = (s.evaluate(0.0, t) + s.evaluate(1.0, t)) / 2
            for w in (0.25, 0.5, 0.75):
                out = s.evaluate(w, t) - axis
                assert ((s.normal(w, t) * out).sum(-1) > 0).all(), (part, p)


def test_bounding_box():
    verts, _, _ = sl.curves.teapot_mesh(24)
    lo, hi = verts.min(axis=0), verts.max(axis=0)
    # the spout's tip: its top seam's x(t) is the cubic Bezier of x = 3.3, 3.525, 3.45, 3.2
    # (the column at v = 1 of patch 19 in the data); its maximum where x'(t) = 0
    x = np.array([3.3, 3.525, 3.45, 3.2])
    dx = 3 * np.diff(x)                         # quadratic Bezier of the derivative
    coeffs = [dx[0] - 2 * dx[1] + dx[2], 2 * (dx[1] - dx[0]), dx[0]]
    t = [r.real for r in np.roots(coeffs) if abs(r.imag) < 1e-12 and 0 <= r.real <= 1]
    x_max = max(sum(x[k] * [1, 3, 3, 1][k] * s**k * (1 - s) ** (3 - k) for k in range(4)) for s in t)
    np.testing.assert_allclose([lo[1], lo[2], hi[1], hi[2]], [-2.0, 0.0, 2.0, 3.15], atol=1e-12)
    np.testing.assert_allclose(lo[0], -3.0, atol=1e-12)  # the handle's outer seam reaches -3
    assert 3.43 < x_max < 3.44
    np.testing.assert_allclose(hi[0], x_max, atol=2e-4)  # a grid of 24 samples its tip
    assert hi[0] <= x_max + 1e-12


def test_bad_parts():
    with pytest.raises(sl.ArgumentValueError, match="parts"):
        sl.curves.teapot("saucer")
    assert len(sl.curves.teapot(["lid", "spout"])) == 12
