"""Frame counts, the notes' one-minute film, and Hearn & Baker's in-between spacing."""

import math

import numpy as np
import pytest

import scanline as sl
from scanline.animation import duration_of, frame_count, frames_needed, inbetween_times


def test_one_minute_of_film_erratum_e60():
    # 60 s x 24 frames/s = 1440 frames; with five in-betweens per pair of key frames a
    # key frame and its in-betweens take 6 frames: 240 blocks plus the closing key.
    plan = frames_needed(60, 24, inbetweens=5)
    assert plan.frames == 1440
    assert plan.key_frames == 241
    # the notes' 288 key frames fit four in-betweens (1440 / 5), not five
    assert frames_needed(60, 24, inbetweens=4).key_frames == 289
    assert duration_of(288, 24, inbetweens=4).frames == 288 + 287 * 4 == 1436
    # and 288 key frames with five in-betweens would make 1723 frames, almost 72 s
    five = duration_of(288, 24, inbetweens=5)
    assert five.frames == 1723 and five.duration == pytest.approx(71.7917, abs=1e-4)


@pytest.mark.parametrize("keys,n,fps", [(2, 0, 24), (241, 5, 24), (10, 3, 30), (7, 11, 25)])
def test_duration_of_inverts_frames_needed(keys, n, fps):
    plan = duration_of(keys, fps, inbetweens=n)
    assert plan.frames == keys + (keys - 1) * n
    back = frames_needed(plan.duration, fps, inbetweens=n)
    assert back.frames == plan.frames and back.key_frames == keys


def test_frame_count_rounding():
    assert frame_count(60, 24) == 1440
    assert frame_count(1.0, 29.97) == 30          # 29.97 frames need 30 slots
    assert frame_count(0.1, 30) == 3              # 3.0000000000000004 is 3
    assert frame_count(2.5, 25) == 63
    assert frames_needed(1, 24).key_frames == 24  # no in-betweens: every frame is a key


# -- Hearn & Baker §16-5, written out here by hand -----------------------------------------
def _hb(t1, t2, n, law):
    dt = t2 - t1
    out = []
    for j in range(1, n + 1):
        if law == "constant":
            out.append(t1 + j * dt / (n + 1))
        elif law == "accelerate":
            out.append(t1 + dt * (1 - math.cos(j * math.pi / (2 * (n + 1)))))
        elif law == "decelerate":
            out.append(t1 + dt * math.sin(j * math.pi / (2 * (n + 1))))
        else:
            out.append(t1 + dt * (1 - math.cos(j * math.pi / (n + 1))) / 2)
    return out


@pytest.mark.parametrize("law", sl.animation.SPACINGS)
@pytest.mark.parametrize("t1,t2,n", [(0, 1, 1), (0, 1, 4), (2.5, 7.0, 9), (-3, -1, 24)])
def test_spacing_laws(law, t1, t2, n):
    got = inbetween_times(t1, t2, n, spacing=law)
    np.testing.assert_allclose(got, _hb(t1, t2, n, law), rtol=0, atol=1e-12)
    assert (np.diff(np.concatenate([[t1], got, [t2]])) > 0).all()


def test_spacing_shapes():
    gaps = np.diff(np.concatenate([[0], inbetween_times(0, 1, 8, "accelerate"), [1]]))
    assert (np.diff(gaps) > 0).all()              # intervals grow: speeding up
    gaps = np.diff(np.concatenate([[0], inbetween_times(0, 1, 8, "decelerate"), [1]]))
    assert (np.diff(gaps) < 0).all()
    gaps = np.diff(np.concatenate([[0], inbetween_times(0, 1, 9, "accelerate-decelerate"), [1]]))
    assert (np.diff(gaps[:5]) > 0).all() and (np.diff(gaps[5:]) < 0).all()
    assert inbetween_times(0, 1, 0).size == 0


def test_spacing_by_easing_name_and_function():
    np.testing.assert_allclose(inbetween_times(0, 2, 3, "ease-in-quad"), [0.125, 0.5, 1.125])
    np.testing.assert_allclose(inbetween_times(0, 1, 1, lambda s: s ** 3), [0.125])


@pytest.mark.parametrize("call,words", [
    (lambda: inbetween_times(1, 1, 3), "before t2"),
    (lambda: inbetween_times(2, 1, 3), "before t2"),
    (lambda: inbetween_times(0, 1, -1), "n must be >= 0"),
    (lambda: inbetween_times(0, float("nan"), 2), "t2 must be a finite"),
    (lambda: inbetween_times(0, 1, 2, "wobble"), "spacing='wobble' is not an easing"),
    (lambda: frames_needed(0, 24), "duration must be > 0"),
    (lambda: frames_needed(1, -24), "fps must be > 0"),
    (lambda: frames_needed(1, 24, inbetweens=2.5), "inbetweens must be an integer"),
    (lambda: duration_of(0, 24), "key_frames must be >= 1"),
    (lambda: frames_needed(1e300, 1e6), "the limit is 2,147,483,647"),
    (lambda: frames_needed(1, 1e10), r"outside 0\.001 to 1e\+06"),
])
def test_bad_input(call, words):
    with pytest.raises(sl.ScanlineError, match=words):
        call()
