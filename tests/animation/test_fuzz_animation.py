"""Bad input, fuzzed: scanline errors only, never a crash; raster writes stay inside."""

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import scanline as sl

anything = st.one_of(st.none(), st.booleans(), st.text(max_size=8),
                     st.floats(allow_nan=True, allow_infinity=True),
                     st.integers(-10**12, 10**12),
                     st.lists(st.floats(allow_nan=True, allow_infinity=True), max_size=4))
FAST = settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def only_scanline_errors(call, *args, **kwargs):
    try:
        call(*args, **kwargs)
    except sl.ScanlineError:
        pass


@FAST
@given(times=st.lists(st.floats(allow_nan=True, allow_infinity=True), min_size=1, max_size=5),
       values=st.lists(st.floats(allow_nan=True, allow_infinity=True), min_size=1, max_size=5),
       interpolation=st.sampled_from(sl.animation.INTERPOLATIONS + ("spline",)),
       ease=st.one_of(st.sampled_from(sorted(sl.animation.EASINGS)), st.text(max_size=12)),
       t=st.floats(allow_nan=True, allow_infinity=True))
def test_keyframes(times, values, interpolation, ease, t):
    def run():
        kf = sl.animation.KeyFrames(times, values, interpolation=interpolation, ease=ease)
        out = kf(t)
        assert np.isfinite(out)
    only_scanline_errors(run)


@FAST
@given(a=anything, b=anything, n=anything, spacing=anything)
def test_inbetweens_and_easing(a, b, n, spacing):
    only_scanline_errors(sl.animation.inbetween_times, a, b, n, spacing)
    only_scanline_errors(sl.animation.ease, spacing, a)
    only_scanline_errors(sl.animation.frames_needed, a, b, n)


@FAST
@given(rect=st.tuples(*[st.integers(-2**31, 2**31)] * 4), at=st.tuples(*[st.integers(-2**31, 2**31)] * 2),
       op=st.integers(-2, 17), mode=st.sampled_from(["1", "L", "RGB", "P"]))
def test_bitblt_clips_anything(rect, at, op, mode):
    kw = {"color_table": ["black", "white"]} if mode == "P" else {}
    dst = sl.FrameBuffer(13, 7, mode=mode, **kw)
    src = sl.FrameBuffer(9, 5, mode=mode, background=1 if mode in ("1", "P") else "white", **kw)
    before = dst.to_array().copy()
    try:
        sl.raster.bitblt(dst, src, rect, at, op=op)
    except sl.ScanlineError:
        np.testing.assert_array_equal(dst.to_array(), before)


@FAST
@given(center=st.tuples(st.floats(-1e12, 1e12), st.floats(-1e12, 1e12)),
       angle=st.floats(-1e6, 1e6), rect=st.tuples(*[st.integers(-50, 50)] * 4))
def test_rotate_block_never_writes_outside(center, angle, rect):
    src = sl.FrameBuffer(12, 9, mode="L", background=255)
    dst = sl.FrameBuffer(10, 10, mode="L")
    only_scanline_errors(sl.raster.rotate_block, dst, src, rect, angle, center=center)
    assert dst.to_array().shape == (10, 10)


@FAST
@given(target=st.tuples(st.floats(allow_nan=True, allow_infinity=True),
                        st.floats(allow_nan=True, allow_infinity=True)),
       method=st.sampled_from(["analytic", "ccd", "dls", "other"]))
def test_inverse_kinematics(target, method):
    arm = sl.animation.Chain([1.0, 2.0])

    def run():
        r = arm.inverse(target, method=method, max_iterations=50)
        assert np.isfinite(r.angles).all()
        assert r.reached == (r.error <= 1e-9 * 3 * (1 + 1e-6))
    only_scanline_errors(run)


@pytest.mark.parametrize("dt", [1e-3, 0.5, 10.0])
def test_dynamics_blow_up_or_finite(dt):
    system = sl.animation.Particles(np.random.default_rng(0).normal(size=(5, 2)),
                                    forces=[sl.animation.Spring([(0, 1), (1, 2), (3, 4)], 5e4)])
    try:
        system.run(20.0, dt, "euler")
        assert np.isfinite(system.positions).all()
    except sl.animation.DynamicsError as error:
        assert error.step >= 1 and math.isfinite(error.time)
