"""trace de-casteljau / cox-de-boor: tables agree with the evaluators (one truth)."""

import json
import numpy as np
import pytest

import scanline as sl


def test_de_casteljau_table_matches_evaluation_and_subdivision():
    rng = np.random.default_rng(0)
    for n in (1, 2, 3, 5):
        for dim in (2, 3):
            P = rng.uniform(-20, 20, (n + 1, dim))
            u = float(rng.uniform())
            t = sl.trace.de_casteljau(P, u=u)
            axes = ["x", "y", "z"][:dim]
            assert t.columns == ["r", "i", *axes]
            assert len(t.rows) == (n + 1) * (n + 2) // 2
            last = [t.rows[-1][a] for a in axes]
            np.testing.assert_allclose(last, sl.curves.Bezier(P).evaluate(u), atol=1e-12)
            left, right = sl.curves.Bezier(P).subdivide(u)
            firsts = [[r[a] for a in axes] for r in t.rows if r["i"] == 0]
            np.testing.assert_allclose(firsts, left.points, atol=1e-12)


def test_cox_de_boor_table_gives_the_curve_weights():
    rng = np.random.default_rng(1)
    for order in (1, 2, 3, 4, 5):
        P = rng.normal(size=(9, 2))
        knots = np.sort(rng.uniform(0, 10, 9 + order))
        c = sl.curves.BSpline(P, order, knots=knots)
        for u in rng.uniform(*c.domain, 5):
            t = sl.trace.cox_de_boor(knots, order, u)
            top = [r for r in t.rows if r["r"] == order]
            assert len(top) == order
            b = c.basis(u)
            for r in top:
                assert r["B"] == pytest.approx(b[r["k"]], abs=1e-14)
            point = sum(r["B"] * P[r["k"]] for r in top)
            np.testing.assert_allclose(point, c.evaluate(u), atol=1e-12)
            assert sum(r["B"] for r in top) == pytest.approx(1.0)


def test_cox_de_boor_notes_open_knots_by_hand():
    # [0 0 1 2 3 3], d = 2: at u = 2.5, B_2,2 = B_3,2 = 1/2 (linear hat functions)
    t = sl.trace.cox_de_boor([0, 0, 1, 2, 3, 3], 2, 2.5)
    assert [(r["r"], r["k"], r["B"]) for r in t.rows] == [(1, 3, 1.0), (2, 2, 0.5), (2, 3, 0.5)]
    # [0 0 0 0 1 2 2 2 2], d = 4, u = 1.5: B_1..B_4 = 1/32, 1/4, 19/32, 1/8
    t = sl.trace.cox_de_boor([0, 0, 0, 0, 1, 2, 2, 2, 2], 4, 1.5)
    assert [r["B"] for r in t.rows if r["r"] == 4] == [1 / 32, 1 / 4, 19 / 32, 1 / 8]


def test_cli(capsys):
    from scanline.cli import main

    def run(*args):
        code = main(["trace", *args])
        out, err = capsys.readouterr()
        return code, out, err

    code, out, err = run("de-casteljau", "0,0", "0,4", "4,4", "4,0", "--u", "0.5",
                         "--format", "json")
    assert code == 0, err
    assert json.loads(out)[-1] == {"r": 3, "i": 0, "x": 2.0, "y": 3.0}
    code, out, err = run("cox-de-boor", "--knots", "0,0,1,2,3,3", "--order", "2", "--u",
                         "2.5", "--format", "csv")
    assert code == 0, err
    assert out.splitlines()[0] == "r,k,interval,B"
    code, out, err = run("cox-de-boor", "--knots", "0,0,1,2,3,3", "--order", "2", "--u", "9")
    assert code == 2 and out == ""
    assert err.startswith("scanline: error: u must lie in [0, 3]") and "Traceback" not in err
