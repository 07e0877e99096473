"""Key-frame interpolation: every key value exactly, splines, easing, timelines."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import scanline as sl
from scanline.animation import INTERPOLATIONS, KeyFrames, Timeline

RNG = np.random.default_rng(14)


@pytest.mark.parametrize("interpolation", INTERPOLATIONS)
@pytest.mark.parametrize("trial", range(5))
def test_hits_every_key_value_exactly(interpolation, trial):
    k = int(RNG.integers(2, 9))
    times = np.cumsum(RNG.uniform(0.05, 3.0, k)) - 1.0
    values = RNG.normal(0, 50, (k, 2, 3))          # e.g. three 2-D control points
    kf = KeyFrames(times, values, interpolation=interpolation, ease="ease-in-out-cubic",
                   tension=0.3, continuity=-0.2, bias=0.4)
    got = kf(times)
    np.testing.assert_array_equal(got, values)
    for t, value in zip(times, values):
        np.testing.assert_array_equal(kf(t), value)


def test_linear_and_step():
    kf = KeyFrames([0, 2, 3], [0.0, 10.0, 4.0])
    assert kf(1.0) == 5.0 and kf(2.5) == 7.0
    assert kf(-5) == 0.0 and kf(99) == 4.0          # held outside the keys
    step = KeyFrames([0, 2, 3], [0.0, 10.0, 4.0], interpolation="step")
    assert step([0.5, 1.999, 2.0, 2.9, 3.0]).tolist() == [0.0, 0.0, 10.0, 10.0, 4.0]


def test_per_segment_easing():
    kf = KeyFrames([0, 1, 2], [0.0, 100.0, 0.0], ease=["ease-in-quad", "ease-out-quad"])
    assert kf(0.5) == pytest.approx(25.0)            # 100 * 0.5**2
    assert kf(1.5) == pytest.approx(100 - 100 * 0.75)  # 1 - (1 - 0.5)**2 = 0.75 of the way down
    with pytest.raises(sl.ScanlineError, match="one per segment"):
        KeyFrames([0, 1, 2], [0, 1, 2], ease=["linear"])


def test_catmull_rom_uniform_matches_the_curve_formula():
    # evenly spaced keys: the time-scaled tangents equal the plain (P_k+1 - P_k-1)/2
    p = np.array([0.0, 4.0, 1.0, 7.0, 3.0])
    kf = KeyFrames(np.arange(5.0), p, interpolation="catmull-rom")
    u = 0.3                                         # in segment 1 -> 2
    m1, m2 = (p[2] - p[0]) / 2, (p[3] - p[1]) / 2
    h = [2 * u**3 - 3 * u**2 + 1, -2 * u**3 + 3 * u**2, u**3 - 2 * u**2 + u, u**3 - u**2]
    assert kf(1.3) == pytest.approx(h[0] * p[1] + h[1] * p[2] + h[2] * m1 + h[3] * m2)
    # the phantom end points make the end tangents P1 - P0 and P4 - P3
    u = 0.5
    h = [2 * u**3 - 3 * u**2 + 1, -2 * u**3 + 3 * u**2, u**3 - 2 * u**2 + u, u**3 - u**2]
    m0, m1 = p[1] - p[0], (p[2] - p[0]) / 2
    assert kf(0.5) == pytest.approx(h[0] * p[0] + h[1] * p[1] + h[2] * m0 + h[3] * m1)


def test_uneven_keys_keep_the_speed_continuous():
    # Kochanek & Bartels' step-size adjustment: the velocity does not jump at a key
    kf = KeyFrames([0.0, 1.0, 4.0, 4.5], [0.0, 3.0, 5.0, 9.0], interpolation="catmull-rom")
    eps = 1e-6
    for key in (1.0, 4.0):
        before = (kf(key) - kf(key - eps)) / eps
        after = (kf(key + eps) - kf(key)) / eps
        assert before == pytest.approx(after, rel=1e-4)


def test_kochanek_bartels_tension_one_stops_at_keys():
    kf = KeyFrames([0, 1, 2], [0.0, 5.0, 1.0], interpolation="kochanek-bartels", tension=1.0)
    eps = 1e-7
    assert abs(kf(1 + eps) - kf(1)) / eps < 1e-4      # zero tangent at the middle key


def test_colors_and_arrays_keep_their_shape():
    kf = KeyFrames([0, 1], [[[0, 0], [10, 0]], [[0, 10], [10, 10]]])
    assert kf(0.5).shape == (2, 2)
    assert kf([0.25, 0.75]).shape == (2, 2, 2)


def test_timeline_frames():
    tl = Timeline({"x": KeyFrames([0, 2], [0, 100])}, fps=10)
    assert len(tl) == 21 and tl.times()[-1] == pytest.approx(2.0)   # the last key is shown
    assert tl.values(10) == {"x": 50.0}
    tl.add("y", [0.5, 1.0], [0, 1], ease="ease-in-quad")
    assert tl.key_times().tolist() == [0.0, 0.5, 1.0, 2.0]
    assert tl.key_frames().tolist() == [0, 5, 10, 20]
    fixed = Timeline({"x": KeyFrames([0, 2], [0, 100])}, fps=24, duration=60)
    assert len(fixed) == sl.animation.frames_needed(60, 24).frames == 1440


@pytest.mark.parametrize("call,words", [
    (lambda: KeyFrames([0, 1, 1], [0, 1, 2]), r"times\[1\] = 1 and times\[2\] = 1 are equal"),
    (lambda: KeyFrames([0, 2, 1], [0, 1, 2]), "out of order"),
    (lambda: KeyFrames([0, float("nan")], [0, 1]), "times must be finite"),
    (lambda: KeyFrames([0, 1], [0, float("nan")]), "values must be finite"),
    (lambda: KeyFrames([0, 1], [0, 1, 2]), "one value per key frame"),
    (lambda: KeyFrames([0, 1], [[0, 1], [2]]), "values must be"),
    (lambda: KeyFrames([0, 1], [0, 1], interpolation="cubic"), "interpolation must be one of"),
    (lambda: KeyFrames([0, 1], [0, 1], ease="ease-in-nope"), "not an easing"),
    (lambda: KeyFrames([0, 1], [0, 1])(float("nan")), "t must be finite"),
    (lambda: Timeline(fps=0), "fps must be > 0"),
    (lambda: Timeline(duration=-1), "duration must be > 0"),
])
def test_bad_input(call, words):
    with pytest.raises(sl.ScanlineError, match=words):
        call()


@settings(max_examples=150, deadline=None)
@given(k=st.integers(1, 5), interpolation=st.sampled_from(INTERPOLATIONS),
       shape=st.sampled_from([(), (2,), (3, 2)]), seed=st.integers(0, 2**32 - 1),
       ease=st.lists(st.sampled_from(sorted(sl.animation.EASINGS)), min_size=4, max_size=4))
def test_one_time_gives_the_values_of_an_array_of_times(k, interpolation, shape, seed, ease):
    # an animated scene evaluates each track at one time per frame, by a shorter path
    rng = np.random.default_rng(seed)
    times = np.sort(rng.choice(40, k, replace=False)) / rng.choice([1, 3, 7])
    kf = KeyFrames(times, rng.normal(0, 100, (k,) + shape), interpolation=interpolation,
                   ease=ease[:max(k - 1, 1)], tension=0.3, continuity=-0.2, bias=0.4)
    ts = np.concatenate([times, rng.uniform(times[0] - 1, times[-1] + 1, 20),
                         np.arange(50) / 24])
    together = kf(ts)
    for t, value in zip(ts, together):
        one = kf(float(t))
        assert type(one) is (float if shape == () else np.ndarray)
        np.testing.assert_array_equal(one, value)
