"""Hostile arguments for the fractal, quaternion and blobby entry points (hypothesis,
the harness of tests/fuzz): only ScanlineError may escape, within the fuzz suite's time
and memory limits, under a 128 MiB memory budget; what comes back is finite."""

import os
import warnings
from unittest import mock

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import scanline as sl
from tests.fuzz.harness import bounded, values

pytestmark = pytest.mark.boundscheck

BUDGET = {"SCANLINE_MEMORY_LIMIT": "128M"}
sizes = st.one_of(st.integers(-3, 40), st.sampled_from([0, 2**31, 2**62, 10**6]),
                  st.sampled_from([np.nan, 1.5, -1e300, 2**63]))


@settings(max_examples=60, deadline=None)
@given(w=sizes, h=sizes, cx=values, cy=values, span=values,
       n=st.one_of(st.integers(-2, 100), st.sampled_from([2**40, 10**9])), julia=st.booleans())
def test_escape_time(w, h, cx, cy, span, n, julia):
    with mock.patch.dict(os.environ, BUDGET), bounded():
        call = sl.fractals.julia if julia else sl.fractals.mandelbrot
        counts = call(w, h, center=(cx, cy), span=span, max_iterations=n)
        assert counts.shape == (h, w) and counts.min() >= 0 and counts.max() <= n


@settings(max_examples=80, deadline=None)
@given(text=st.text(alphabet="FGf+-|[]XAB", max_size=60), angle=values, step=values,
       start=st.tuples(values, values), heading=values)
def test_turtle(text, angle, step, start, heading):
    with mock.patch.dict(os.environ, BUDGET), bounded(), warnings.catch_warnings():
        warnings.simplefilter("ignore", sl.AngleWarning)     # 30 read as radians: meant
        lines = sl.fractals.turtle(text, angle, step=step, start=start, heading=heading)
        assert sum(len(p) - 1 for p in lines) == text.count("F") + text.count("G")


@settings(max_examples=40, deadline=None)
@given(axiom=st.text(alphabet="FX+-[]", min_size=1, max_size=5),
       rule=st.text(alphabet="FX+-[]", max_size=8),
       n=st.one_of(st.integers(-1, 10), st.sampled_from([10**6, 2**40])))
def test_lsystem(axiom, rule, n):
    with mock.patch.dict(os.environ, BUDGET), bounded():
        system = sl.fractals.LSystem(axiom, {"F": rule, "X": "F" + rule})
        assert len(system.string(n)) == system.length(n)


@settings(max_examples=40, deadline=None)
@given(maps=st.lists(st.lists(values, min_size=6, max_size=6), min_size=1, max_size=3),
       n=st.one_of(st.integers(-1, 200), st.sampled_from([2**40])), seed=st.integers(0, 9))
def test_ifs(maps, n, seed):
    with mock.patch.dict(os.environ, BUDGET), bounded():
        p = np.full(len(maps), 1 / len(maps))
        with np.errstate(all="ignore"):
            sl.fractals.ifs(maps, p, n, seed=seed)


@settings(max_examples=40, deadline=None)
@given(depth=st.one_of(st.integers(-1, 30), values), H=values, levels=st.integers(-1, 30))
def test_curves_and_terrain(depth, H, levels):
    with mock.patch.dict(os.environ, BUDGET):
        for call in (lambda: sl.fractals.koch(depth), lambda: sl.fractals.dragon(depth),
                     lambda: sl.fractals.hilbert(depth),
                     lambda: sl.fractals.midpoint_displacement(levels, H, seed=1),
                     lambda: sl.fractals.fbm_surface(levels, H, seed=1)):
            with bounded():
                assert np.isfinite(call()).all()


@settings(max_examples=60, deadline=None)
@given(q=st.tuples(values, values, values, values), t=values,
       m=st.lists(st.lists(values, min_size=3, max_size=3), min_size=3, max_size=3))
def test_quaternions(q, t, m):
    Q = sl.transform3d.Quaternion
    with bounded():
        a = Q(*q)
        assert np.isfinite(a.matrix()).all()
        assert np.isfinite(sl.transform3d.slerp(a, Q(), t).wxyz).all()
    with bounded():
        assert np.isfinite(Q.from_matrix(m).wxyz).all()


@settings(max_examples=30, deadline=None)
@given(centers=st.lists(st.tuples(values, values, values), min_size=0, max_size=3),
       radius=values, threshold=values, kind=st.sampled_from(["blinn", "metaball", "soft"]),
       resolution=st.one_of(st.integers(-1, 24), st.sampled_from([2**20]), values))
def test_blobby(centers, radius, threshold, kind, resolution):
    with mock.patch.dict(os.environ, BUDGET), bounded():
        mesh = sl.mesh.blobby(centers, radius, threshold=threshold, resolution=resolution,
                              kind=kind)
        assert np.isfinite(mesh.vertices).all()
