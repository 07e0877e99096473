"""The BSP tree's step table against plan geometry worked here: which walls the root
plane y = 12 cuts, the pieces' lengths, every piece on the side of each node's plane
that the table says, and the drawing order checked by rays cast from the eye (along
any ray, a piece painted later is nearer); and its explorer view."""

import math

import numpy as np
import pytest

import scanline as sl
from scanline.errors import ArgumentValueError
from scanline.studio import explorer
from scanline.trace import bsp


def _hit(eye, direction, seg):
    """Distance along the ray eye + t direction to the plan segment, or None."""
    (x0, y0), (x1, y1) = seg
    a = np.array([[direction[0], x0 - x1], [direction[1], y0 - y1]])
    if abs(np.linalg.det(a)) < 1e-12:
        return None
    t, s = np.linalg.solve(a, [x0 - eye[0], y0 - eye[1]])
    return t if t > 1e-9 and 1e-6 < s < 1 - 1e-6 else None


def test_root_plane_is_wall_0_and_splits_walls_1_and_4():
    t = sl.trace.bsp_tree((6, 22))
    root = t.rows[0]
    a, b, c, d = t.planes[0]
    assert (abs(a), abs(b), abs(c)) == pytest.approx((0, 1, 0))
    assert -d / b == pytest.approx(12)          # the plane y = 12
    assert root["on"] == "0"
    # wall 1 spans y 4..20 at x = 10, wall 4 runs from y 16 to 7: both cross y = 12
    assert root["splits"] == "1 4"
    assert {p[0] for p in root["in front"].split() + root["behind"].split()} == set("1234")


@pytest.mark.parametrize("eye", [(6, 22), (30, 2), (16, 10), (1, 1), (12, 15)])
def test_pieces_cover_the_walls_and_sit_on_their_sides(eye):
    t = sl.trace.bsp_tree(eye)
    for w, (x0, y0, x1, y1) in enumerate(bsp.WALLS):
        mine = [seg for name, seg in t.pieces.items() if name.rstrip("abcdefgh") == str(w)]
        assert sum(math.dist(*seg) for seg in mine) == pytest.approx(math.dist((x0, y0),
                                                                               (x1, y1)))
    for r in (r for r in t.rows if r["phase"] == "build"):
        a, b, c, d = t.planes[r["node"]]
        for names, sign in ((r["in front"], 1), (r["behind"], -1)):
            for name in names.split() if names != "-" else []:
                mid = np.mean(t.pieces[name], axis=0)
                assert sign * (a * mid[0] + b * mid[1] + c * 0.5 + d) > 0


@pytest.mark.parametrize("eye", [(6, 22), (30, 2), (16, 10), (1, 1), (12, 15), (20, 13)])
def test_back_to_front_along_every_ray(eye):
    t = sl.trace.bsp_tree(eye)
    drawn = [r["piece"] for r in t.rows if r["phase"] == "draw"]
    assert sorted(drawn) == sorted(t.pieces)
    rays = 0
    for angle in np.linspace(0, 2 * np.pi, 721)[:-1]:
        d = (np.cos(angle), np.sin(angle))
        hits = [(k, _hit(eye, d, t.pieces[p])) for k, p in enumerate(drawn)]
        hits = [(k, h) for k, h in hits if h is not None]
        rays += len(hits) > 1
        by_order = [h for _, h in sorted(hits)]
        assert by_order == sorted(by_order, reverse=True), (angle, hits)
    assert rays > 50


def test_bsp_eye_is_two_numbers():
    with pytest.raises(ArgumentValueError, match="eye"):
        sl.trace.bsp_tree((1, 2, 3))


def test_bsp_explorer_view():
    view = explorer.explore("bsp-tree", ["--eye", "30", "2"])
    assert view["count"] == len(view["steps"]) == 18
    assert view["handles"][0]["x"] == 30 and view["handles"][0]["y"] == 2
    assert view["steps"][0]["plane"] == [[0, 12], [31, 12]]
    last = view["steps"][-1]
    assert len(last["areas"]) == 9 and last["areas"][-1][1] == "current"
