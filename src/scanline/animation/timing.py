"""Counting frames and spacing in-betweens (notes, chapter 6, Q1; Hearn & Baker §16-1
and §16-5).

A film shows 24 frames per second, a graphics terminal 30 to 60 (notes, Q1).  Between
two key frames come ``n`` in-betweens; a sequence of K key frames with n in-betweens
between each pair has K + (K - 1) n frames.  :func:`frames_needed` counts the frames
and key frames of a sequence of given duration; :func:`duration_of` is its inverse;
:func:`inbetween_times` spaces the in-betweens of one pair of key frames.

>>> plan = frames_needed(60, 24, inbetweens=5)     # the notes' one-minute film
>>> plan.frames, plan.key_frames
(1440, 241)
>>> duration_of(241, 24, inbetweens=5).frames
1441
"""

import math
from typing import NamedTuple, Union

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from ..budget import check as budget
from ..errors import ArgumentValueError
from .easing import SPACINGS, Easing, apply, resolve


#: The most frames a sequence may have.
MAX_FRAMES = 2**31 - 1

#: The frame rates an animation may have: from one frame every 1000 seconds (a slide
#: show) to a million frames a second (a simulation sampled finely).  Beyond them the
#: times i / fps of the formats (MP4's rational time base, APNG's and WebP's delays)
#: overflow or round to nothing.
MIN_FPS, MAX_FPS = 1e-3, 1e6


class FramePlan(NamedTuple):
    """The frame counts of a sequence.

    Attributes
    ----------
    duration : float
        Seconds.
    fps : float
        Frames per second.
    frames : int
        Frames shown: ``ceil(duration * fps)`` (frame i is shown from i / fps on).
    inbetweens : int
        In-betweens between each pair of key frames.
    key_frames : int
        Key frames needed so that the first and the last frame are key frames and at
        most ``inbetweens`` frames lie between two key frames:
        ``ceil((frames - 1) / (inbetweens + 1)) + 1`` (every frame when there are no
        in-betweens).

    Examples
    --------
    Two seconds at 24 fps are 48 frames; blocks of a key frame and 3 in-betweens
    cover 47 of them in 12 blocks, and a 13th key frame closes the sequence:

    >>> from scanline.animation import frames_needed
    >>> frames_needed(2, 24, inbetweens=3)
    FramePlan(duration=2.0, fps=24.0, frames=48, inbetweens=3, key_frames=13)
    """

    duration: float
    fps: float
    frames: int
    inbetweens: int
    key_frames: int


def _fps(fps: object, name: str = "fps") -> float:
    fps = v.number(name, fps)
    if fps <= 0:
        raise ArgumentValueError(f"{name} must be > 0 (frames per second), got {fps}")
    if not MIN_FPS <= fps <= MAX_FPS:
        raise ArgumentValueError(
            f"{name}={fps:g} frames per second is outside {MIN_FPS:g} to {MAX_FPS:g} (one frame "
            "every 1000 s to a million a second), the rates the animation formats can time")
    return fps


def _count(name: str, value: object, minimum: int) -> int:
    return v.positive_int(name, value, minimum=minimum)


def frame_count(duration: float, fps: float) -> int:
    """Frames of a sequence of ``duration`` seconds at ``fps``: ``ceil(duration * fps)``,
    at least 1 (a product within 1e-9 of an integer counts as that integer, so that
    ``frame_count(1.0, 29.97)`` is 30 and not 31 for a rounding error).

    Parameters
    ----------
    duration : float
        Seconds, > 0.
    fps : float
        Frames per second, within 0.001 to 1e6.

    Returns
    -------
    int

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If ``duration`` is not > 0, ``fps`` is out of range, or the count exceeds
        :data:`MAX_FRAMES`.

    Notes
    -----
    Notes, chapter 6, Q1 (frames per second of film and terminals).

    Examples
    --------
    >>> frame_count(60, 24), frame_count(2.5, 25), frame_count(0.1, 30)
    (1440, 63, 3)
    """
    duration = v.number("duration", duration)
    if duration <= 0:
        raise ArgumentValueError(f"duration must be > 0 seconds, got {duration}")
    product = duration * _fps(fps)
    if not product <= MAX_FRAMES:
        raise ArgumentValueError(
            f"duration x fps = {duration:g} x {fps:g} is {product:g} frames; the limit is "
            f"{MAX_FRAMES:,} (more than two years of film at 24 fps)")
    nearest = round(product)
    return max(1, nearest if abs(product - nearest) <= 1e-9 * max(1.0, product)
               else math.ceil(product))


def frames_needed(duration: float, fps: float, inbetweens: int = 0) -> FramePlan:
    """How many frames, and how many key frames, a sequence needs.

    Parameters
    ----------
    duration : float
        Seconds, > 0.
    fps : float
        Frames per second, > 0 (film 24, PAL video 25, NTSC 30, terminals 30-60).
    inbetweens : int
        In-between frames generated between each pair of key frames, >= 0.

    Returns
    -------
    FramePlan

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        As :func:`frame_count`, or if ``inbetweens`` is not an integer >= 0.

    Notes
    -----
    Notes, chapter 6, Q1: "For a one minutes film sequence with no duplication, we
    would require 288 key frames."  A minute of film is 60 x 24 = 1440 frames.  With
    five in-betweens (Hearn & Baker's premise, §16-1, which the notes dropped) a key
    frame and its five in-betweens take 6 frames, so 1440 frames need 240 key frames
    plus the closing one: 241.  288 = 1440 / 5 counts five frames per key frame, that
    is four in-betweens.  See docs/errata.md, E60.

    Examples
    --------
    >>> frames_needed(60, 24, inbetweens=4).key_frames   # 288 blocks of 5, and the last
    289
    >>> frames_needed(60, 24).key_frames       # no in-betweens: every frame is a key
    1440
    """
    frames = frame_count(duration, fps)
    n = _count("inbetweens", inbetweens, 0)
    keys = frames if n == 0 else -(-(frames - 1) // (n + 1)) + 1
    return FramePlan(float(duration), float(fps), frames, n, max(keys, 1))


def duration_of(key_frames: int, fps: float, inbetweens: int = 0) -> FramePlan:
    """The inverse of :func:`frames_needed`: the sequence that ``key_frames`` key
    frames with ``inbetweens`` in-betweens per pair make at ``fps``.

    Its frames are K + (K - 1) n and its duration frames / fps.

    Parameters
    ----------
    key_frames : int
        K, at least 1.
    fps : float
        Frames per second, within 0.001 to 1e6.
    inbetweens : int, default 0
        n, in-betweens between each pair of key frames, >= 0.

    Returns
    -------
    FramePlan

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If a count is not an integer in range, ``fps`` is out of range, or the frames
        exceed :data:`MAX_FRAMES`.

    Notes
    -----
    Notes, chapter 6, Q1; Hearn & Baker, section 16-1.  See docs/errata.md, E60.

    Examples
    --------
    >>> plan = duration_of(288, 24, inbetweens=5)   # the notes' 288 key frames
    >>> plan.frames, round(plan.duration, 2)
    (1723, 71.79)
    >>> duration_of(288, 24, inbetweens=4).frames   # 288 fits four in-betweens
    1436
    """
    k = _count("key_frames", key_frames, 1)
    fps = _fps(fps)
    n = _count("inbetweens", inbetweens, 0)
    frames = k + (k - 1) * n
    if frames > MAX_FRAMES:
        raise ArgumentValueError(
            f"key_frames={k} with inbetweens={n} make {frames:,} frames; the limit is "
            f"{MAX_FRAMES:,} (more than two years of film at 24 fps)")
    return FramePlan(frames / fps, fps, frames, n, k)


def inbetween_times(t1: float, t2: float, n: int,
                    spacing: Union[str, Easing] = "constant") -> NDArray[np.float64]:
    """The times of the ``n`` in-betweens between key frames at ``t1`` and ``t2``.

    Hearn & Baker, §16-5, with Δt = t2 - t1 and j = 1 ... n:

    - ``"constant"`` (zero acceleration): t_j = t1 + j Δt / (n + 1);
    - ``"accelerate"`` (speeding up): t_j = t1 + Δt (1 - cos(j π / (2(n + 1))));
    - ``"decelerate"`` (slowing down): t_j = t1 + Δt sin(j π / (2(n + 1)));
    - ``"accelerate-decelerate"``: t_j = t1 + Δt (1 - cos(j π / (n + 1))) / 2.

    ``spacing`` may also be any easing name of :mod:`scanline.animation.easing` or a
    function: t_j = t1 + Δt · spacing(j / (n + 1)).

    Parameters
    ----------
    t1, t2 : float
        The key frames' times, t1 < t2.
    n : int
        The number of in-betweens, >= 0.
    spacing : str or callable, default "constant"
        A spacing law, an easing name or an easing function.

    Returns
    -------
    numpy.ndarray
        ``n`` times, strictly between t1 and t2 for the four laws.

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If t1 >= t2, ``n`` is not an integer >= 0, ``spacing`` is unknown, or the
        times would not fit the memory budget.

    Examples
    --------
    >>> inbetween_times(0, 1, 3).tolist()
    [0.25, 0.5, 0.75]
    >>> inbetween_times(0, 1, 3, "accelerate").round(4).tolist()
    [0.0761, 0.2929, 0.6173]
    """
    t1, t2 = v.number("t1", t1), v.number("t2", t2)
    if not t1 < t2:
        raise ArgumentValueError(f"t1 must come before t2, got t1={t1}, t2={t2}")
    n = _count("n", n, 0)
    function = resolve(spacing, "spacing")
    # j, j / (n + 1), the spacing's value (and its temporaries) and the times
    budget(n * 8 * 6, "n", f"{n} in-between times",
          hint="ask for fewer in-betweens, or compute them in pieces (t1 and t2 of each piece)")
    j = np.arange(1, n + 1, dtype=np.float64)
    times: NDArray[np.float64] = t1 + (t2 - t1) * apply(function, j / (n + 1))
    return times


__all__ = ["FramePlan", "frame_count", "frames_needed", "duration_of", "inbetween_times",
           "SPACINGS"]
