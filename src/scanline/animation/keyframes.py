"""Key frames and in-betweens for any numeric parameter (notes, chapter 6, Q1 and Q4;
Hearn & Baker §16-1 and §16-5).

A :class:`KeyFrames` track holds the values a parameter takes at key times — a
position, an angle, a scale, a color, a whole array of control points, a camera's
eye point — and interpolates the in-betweens: linearly, held (``"step"``), or along
a cardinal, Catmull–Rom or Kochanek–Bartels spline through the key values (built
with :mod:`scanline.curves`).  Each segment between two key frames has its own easing
(:mod:`scanline.animation.easing`), which is how accelerations are simulated.

A :class:`Timeline` gathers named tracks with a frame rate and a duration and gives
the values of every track at each frame.

>>> import scanline as sl
>>> x = sl.animation.KeyFrames([0, 1, 2], [0.0, 10.0, 0.0])
>>> x(0.5), x(1.0), x(1.25)
(5.0, 10.0, 7.5)
>>> y = sl.animation.KeyFrames([0, 2], [(0, 0), (100, 50)], ease="ease-in-quad")
>>> y(1.0).tolist()
[25.0, 12.5]
"""

import bisect
import numbers
from collections.abc import Callable
from typing import Any, TypeVar, Union, cast

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError
from .easing import Easing, apply, resolve
from ..budget import check as budget
from ._checks import floats
from .timing import MAX_FRAMES, frame_count

#: Interpolation methods between key values.
INTERPOLATIONS = ("linear", "step", "catmull-rom", "cardinal", "kochanek-bartels")


def _times(times: object) -> NDArray[np.float64]:
    t = floats("times", times, "a sequence of numbers")
    if t.ndim != 1 or len(t) < 1:
        raise ArgumentValueError(f"times must be a 1-D sequence of at least one time, got "
                                 f"shape {t.shape}")
    if not np.isfinite(t).all():
        k = int(np.flatnonzero(~np.isfinite(t))[0])
        raise ArgumentValueError(f"times must be finite; times[{k}] is {t[k]}")
    steps = np.diff(t)
    if (steps <= 0).any():
        k = int(np.flatnonzero(steps <= 0)[0])
        what = "equal" if steps[k] == 0 else "out of order"
        raise ArgumentValueError(
            f"times must increase strictly: times[{k}] = {t[k]:g} and times[{k + 1}] = "
            f"{t[k + 1]:g} are {what}; give each key frame its own, later time")
    return t


def _values(values: object, count: int) -> NDArray[np.float64]:
    a = floats("values", values, "numbers or equally shaped arrays of numbers, one per "
               "key frame")
    if a.ndim == 0 or len(a) != count:
        raise ArgumentValueError(
            f"values must hold one value per key frame ({count}), got "
            f"{'a scalar' if a.ndim == 0 else len(a)}")
    if not np.isfinite(a).all():
        k = int(np.argwhere(~np.isfinite(a))[0][0])
        raise ArgumentValueError(f"values must be finite; the value of key frame {k} is "
                                 f"{a[k].tolist()}")
    return a


_T = TypeVar("_T")


def _per_segment(name: str, value: Any, segments: int,
                 convert: Callable[[Any, str], _T]) -> list[_T]:
    if isinstance(value, (list, tuple)):
        if len(value) != segments:
            raise ArgumentValueError(
                f"{name} must be one value or a list of one per segment ({segments}), "
                f"got {len(value)}")
        return [convert(x, f"{name}[{k}]") for k, x in enumerate(value)]
    one = convert(value, name)
    return [one] * segments


def _spline_parameter(name: str, value: object, count: int) -> NDArray[np.float64]:
    a = floats(name, value, f"a number or one per key frame ({count})") \
        if not isinstance(value, numbers.Real) else None
    if a is None or a.ndim == 0:
        return np.full(count, v.number(name, value if a is None else float(a)), np.float64)
    if a.shape != (count,) or not np.isfinite(a).all():
        raise ArgumentValueError(f"{name} must be a finite number or one per key frame "
                                 f"({count}), got {v._show(value)}")
    return a


class KeyFrames:
    """A parameter's key values at key times, and the in-betweens.

    Parameters
    ----------
    times : sequence of float
        Key times in seconds, strictly increasing.
    values : sequence
        One value per key time: numbers, or arrays of one shape (a point, a color, a
        polygon's vertices ...).
    interpolation : str
        ``"linear"``, ``"step"`` (hold each key value until the next key),
        ``"catmull-rom"``, ``"cardinal"`` (with ``tension``) or
        ``"kochanek-bartels"`` (``tension``, ``continuity``, ``bias``).
    ease : str, callable or list
        The easing of each segment (one for all, or a list of one per segment):
        the segment's time fraction passes through it before interpolating.
    tension, continuity, bias : float or sequence of float
        Spline parameters, one for all key frames or one per key frame.

    Notes
    -----
    The splines are the ones of :mod:`scanline.curves` (Kochanek–Bartels with t = c = b
    = 0 is Catmull–Rom) through the key values, with phantom end points P₋₁ = 2P₀ - P₁
    and P_K = 2P_{K-1} - P_{K-2} so that the curve runs through the first and the last
    key value.  Key frames are rarely evenly spaced in time; as Kochanek and Bartels
    prescribe, the tangent leaving key k is scaled by 2 Δ_k / (Δ_{k-1} + Δ_k) and the
    tangent arriving by 2 Δ_{k-1} / (Δ_{k-1} + Δ_k) (Δ_k = t_{k+1} - t_k), so that
    the speed does not jump at a key frame.  Outside [times[0], times[-1]] a track
    holds its first or last value.  At a key time the value is the key value exactly.

    References
    ----------
    D. Kochanek and R. Bartels, "Interpolating splines with local tension, continuity,
    and bias control", *SIGGRAPH '84*, 1984, section 5 (parameter step size).
    Hearn & Baker, §16-5, "Key-frame systems" and "Simulating accelerations".

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If the times do not increase strictly, the values are not one finite value (of
        one shape) per key time, or an option is unknown.

    Examples
    --------
    >>> import scanline as sl
    >>> x = sl.animation.KeyFrames([0, 1, 2], [0.0, 10.0, 0.0])
    >>> x(0.5), x(1.0), x(1.25)
    (5.0, 10.0, 7.5)
    >>> x
    KeyFrames(3 keys, 0 s to 2 s, linear, value shape ())
    """

    _curve: Any

    def __init__(self, times: ArrayLike, values: ArrayLike, interpolation: str = "linear",
                 ease: Union[str, Easing, list[Union[str, Easing]]] = "linear",
                 tension: ArrayLike = 0.0, continuity: ArrayLike = 0.0,
                 bias: ArrayLike = 0.0) -> None:
        self.times = _times(times)
        k = len(self.times)
        self.values = _values(values, k)
        self.times.flags.writeable = False
        self.values.flags.writeable = False
        self.interpolation = v.choice("interpolation", interpolation, INTERPOLATIONS)
        self.ease = _per_segment("ease", ease, max(k - 1, 1), resolve)
        self._flat = self.values.reshape(k, -1)
        self._keys = self.times.tolist()
        self._curve = None
        if self.interpolation in ("catmull-rom", "cardinal", "kochanek-bartels") and k >= 2:
            params = {name: _spline_parameter(name, value, k) for name, value in
                      (("tension", tension), ("continuity", continuity), ("bias", bias))}
            if self.interpolation == "catmull-rom":
                params = {name: np.zeros(k) for name in params}
            elif self.interpolation == "cardinal":
                params["continuity"] = params["bias"] = np.zeros(k)
            self._curve = self._spline(**params)

    def _spline(self, tension: NDArray[np.float64], continuity: NDArray[np.float64],
                bias: NDArray[np.float64]) -> Any:
        from ..curves import Hermite, KochanekBartels

        p = self._flat
        padded = np.vstack([2 * p[0] - p[1], p, 2 * p[-1] - p[-2]])

        def pad(a: NDArray[np.float64]) -> NDArray[np.float64]:
            return np.concatenate([[0.0], a, [0.0]])

        kb = KochanekBartels(padded, tension=pad(tension), continuity=pad(continuity),
                             bias=pad(bias))
        leave, arrive = kb.tangents.copy(), kb.incoming.copy()
        steps = np.diff(self.times)
        inner = slice(1, -1)
        before, after = steps[:-1], steps[1:]
        leave[inner] *= (2 * after / (before + after))[:, None]
        arrive[inner] *= (2 * before / (before + after))[:, None]
        return Hermite(p, leave, incoming=arrive)

    def __len__(self) -> int:
        return len(self.times)

    @property
    def shape(self) -> tuple[int, ...]:
        """The shape of one value."""
        return self.values.shape[1:]

    @property
    def start(self) -> float:
        """The first key time."""
        return float(self.times[0])

    @property
    def end(self) -> float:
        """The last key time."""
        return float(self.times[-1])

    def __call__(self, t: ArrayLike) -> Any:
        """The value at time ``t`` (seconds); an array of times gives an array of
        values, shape ``np.shape(t) + shape``."""
        return self.at(t)

    def at(self, t: ArrayLike) -> Any:
        """The value at time(s) ``t``; see :meth:`__call__`.

        Parameters
        ----------
        t : float or array_like
            Times in seconds, finite.

        Returns
        -------
        float or numpy.ndarray
            A float for one time of a scalar track, else an array of shape
            ``np.shape(t) + shape``.

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If ``t`` is not finite numbers.

        Examples
        --------
        >>> import scanline as sl
        >>> x = sl.animation.KeyFrames([0, 1, 2], [0.0, 10.0, 0.0])
        >>> x.at([0.5, 1.5]).tolist()
        [5.0, 5.0]
        """
        ts = floats("t", t, "a time or an array of times")
        if not np.isfinite(ts).all():
            raise ArgumentValueError(f"t must be finite, got {v._show(t)}")
        if ts.ndim == 0:
            out = self._at_one(float(ts))
            return float(out[0]) if self.values.ndim == 1 else out.reshape(self.shape)
        flat = ts.ravel()
        out = self._evaluate(flat).reshape(flat.shape + self.shape)
        out = out.reshape(ts.shape + self.shape)
        if out.ndim == 0:
            return float(out)
        return out

    def segment(self, t: ArrayLike) -> tuple[NDArray[np.int64], NDArray[np.float64]]:
        """The segment index k (key k to key k + 1) and the eased fraction of it at
        each of the times ``t`` (a 1-D array), clamped to the track.

        Parameters
        ----------
        t : array_like, shape (N,)
            Times in seconds, finite.

        Returns
        -------
        k : ndarray of int64, shape (N,)
        fraction : ndarray of float64, shape (N,)
            The segment's eased time fraction, in [0, 1].

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If ``t`` is not a 1-D array of finite numbers.

        Examples
        --------
        1.25 s is a quarter of the way through segment 1 (1 s to 2 s):

        >>> import scanline as sl
        >>> x = sl.animation.KeyFrames([0, 1, 2], [0.0, 10.0, 0.0])
        >>> k, s = x.segment([0.5, 1.25])
        >>> k.tolist(), s.tolist()
        ([0, 1], [0.5, 0.25])
        """
        t = floats("t", t, "a 1-D array of times")
        if t.ndim != 1:
            raise ArgumentValueError(f"t must be a 1-D array of times, got shape {t.shape}")
        if not np.isfinite(t).all():
            raise ArgumentValueError(f"t must be finite, got {v._show(t.tolist())}")
        times = self.times
        if len(times) == 1:
            return np.zeros(len(t), np.int64), np.zeros(len(t))
        tc = np.clip(t, times[0], times[-1])
        k = np.clip(np.searchsorted(times, tc, side="right") - 1, 0, len(times) - 2)
        s = (tc - times[k]) / (times[k + 1] - times[k])
        s = np.clip(s, 0.0, 1.0)
        eased = np.empty_like(s)
        for j in np.unique(k):
            rows = k == j
            eased[rows] = apply(self.ease[j], s[rows])
        return k, eased

    def _at_one(self, t: float) -> NDArray[np.float64]:
        """The flat value at one time ``t`` (a float): the arithmetic of
        :meth:`_evaluate` on one time, bit for bit, without its array bookkeeping
        (an animated scene evaluates every track once a frame)."""
        times, flat = self._keys, self._flat
        hit = bisect.bisect_left(times, t)
        if hit < len(times) and times[hit] == t:
            return cast("NDArray[np.float64]", flat[hit].copy())   # a key time: the key value
        if len(times) == 1 or t < times[0]:
            return cast("NDArray[np.float64]", flat[0].copy())
        if t > times[-1]:
            return cast("NDArray[np.float64]", flat[-1].copy())
        k = hit - 1                                 # times[k] < t < times[k + 1]
        s = min(max((t - times[k]) / (times[k + 1] - times[k]), 0.0), 1.0)
        eased = apply(self.ease[k], np.array([s]))
        if self.interpolation == "step":
            return cast("NDArray[np.float64]", (flat[k + 1] if eased[0] >= 1 else flat[k]).copy())
        if self._curve is None:
            return cast("NDArray[np.float64]", flat[k] + eased[0] * (flat[k + 1] - flat[k]))
        u = min(max(k + float(eased[0]), 0.0), len(flat) - 1.0)
        return cast("NDArray[np.float64]", self._curve.evaluate(np.array([u]))[0])

    def _evaluate(self, t: NDArray[np.float64]) -> NDArray[np.float64]:
        flat = self._flat
        if len(flat) == 1:
            return np.repeat(flat, len(t), axis=0)
        k, s = self.segment(t)
        if self.interpolation == "step":
            out = np.where((s >= 1)[:, None], flat[k + 1], flat[k])
        elif self._curve is None:
            out = flat[k] + s[:, None] * (flat[k + 1] - flat[k])
        else:
            u = np.clip(k + s, 0.0, len(flat) - 1.0)
            out = self._curve.evaluate(u)
        hits = np.searchsorted(self.times, t)
        exact = (hits < len(self.times)) & (self.times[np.minimum(hits, len(self.times) - 1)] == t)
        out[exact] = flat[hits[exact]]
        out[t < self.times[0]] = flat[0]
        out[t > self.times[-1]] = flat[-1]
        return out

    def __repr__(self) -> str:
        return (f"KeyFrames({len(self)} keys, {self.start:g} s to {self.end:g} s, "
                f"{self.interpolation}, value shape {self.shape})")


class Timeline:
    """Named parameter tracks played at a frame rate.

    Parameters
    ----------
    tracks : dict, optional
        name -> :class:`KeyFrames` (or any function of time, such as a
        :meth:`MotionPath.at <scanline.animation.MotionPath.at>` wrapper).
    fps : float
        Frames per second.
    duration : float, optional
        Seconds.  Default: up to and including the last key time, that is last key +
        1 / fps, so that the last key frame is shown.
    start : float
        The time of frame 0.

    Frame i is shown at time ``start + i / fps``.

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        If ``tracks`` is not a dict of tracks, or ``fps``, ``duration`` or ``start`` is
        out of range.

    Notes
    -----
    The frames of a key-frame system (Hearn & Baker, section 16-5; notes, chapter 6).

    Examples
    --------
    >>> import scanline as sl
    >>> tl = sl.animation.Timeline({"x": sl.animation.KeyFrames([0, 1], [0, 100])}, fps=4)
    >>> len(tl), tl.times().tolist()
    (5, [0.0, 0.25, 0.5, 0.75, 1.0])
    >>> tl.values(2)
    {'x': 50.0}
    """

    def __init__(self, tracks: dict[str, Any] | None = None, fps: float = 24,
                 duration: float | None = None, start: float = 0.0) -> None:
        from .timing import _fps

        self.fps = _fps(fps)
        self.start = v.number("start", start)
        self.tracks: dict[str, Any] = {}
        if tracks is not None and not isinstance(tracks, dict):
            raise ArgumentTypeError(f"tracks must be a dict of name -> KeyFrames (or function "
                                    f"of time), got {v._show(tracks)}")
        for name, track in (tracks or {}).items():
            self.add(name, track)
        if duration is not None:
            duration = v.number("duration", duration)
            if duration <= 0:
                raise ArgumentValueError(f"duration must be > 0 seconds, got {duration}")
        self._duration = duration

    def add(self, name: str, track: Any, *args: Any, **kwargs: Any) -> Any:
        """Add a track: ``add(name, KeyFrames(...))``, ``add(name, function_of_time)``
        or ``add(name, times, values, **options)`` (builds the :class:`KeyFrames`).

        Parameters
        ----------
        name : str
            The track's name, not empty.
        track : KeyFrames, callable or array_like
            A track, a function of time, or the key times (with ``args``).
        *args, **kwargs
            The values and options of a :class:`KeyFrames` built from ``track``.

        Returns
        -------
        KeyFrames or callable
            The track added.

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If ``name`` is empty or ``track`` is neither a track nor a function.

        Examples
        --------
        >>> import scanline as sl
        >>> tl = sl.animation.Timeline({"x": sl.animation.KeyFrames([0, 1], [0, 100])}, fps=4)
        >>> tl.add("y", [0, 1], [10, 20])
        KeyFrames(2 keys, 0 s to 1 s, linear, value shape ())
        >>> tl.values(2)
        {'x': 50.0, 'y': 15.0}
        """
        if not isinstance(name, str) or not name:
            raise ArgumentValueError(f"name must be a non-empty string, got {v._show(name)}")
        if args or kwargs:
            track = KeyFrames(track, *args, **kwargs)
        elif not callable(track):
            raise ArgumentTypeError(f"track {name!r} must be KeyFrames or a function of time, "
                                    f"got {v._show(track)}")
        self.tracks[name] = track
        return track

    @property
    def duration(self) -> float:
        """Seconds of the sequence."""
        if self._duration is not None:
            return self._duration
        ends = [t.end for t in self.tracks.values() if isinstance(t, KeyFrames)]
        last = max(ends, default=self.start) - self.start
        return max(last, 0.0) + 1.0 / self.fps

    def __len__(self) -> int:
        return frame_count(self.duration, self.fps)

    def time(self, frame: int) -> float:
        """The time of ``frame``.

        Parameters
        ----------
        frame : int
            A frame index >= 0.

        Returns
        -------
        float
            ``start + frame / fps`` seconds.

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            If ``frame`` is not an integer in 0 ... :data:`MAX_FRAMES`.

        Examples
        --------
        >>> import scanline as sl
        >>> tl = sl.animation.Timeline({"x": sl.animation.KeyFrames([0, 1], [0, 100])}, fps=4)
        >>> tl.time(3)
        0.75
        """
        frame = v.positive_int("frame", frame, minimum=0)
        if frame > MAX_FRAMES:
            raise ArgumentValueError(f"frame={frame} is beyond the {MAX_FRAMES:,} frames a "
                                     "sequence may have")
        return self.start + frame / self.fps

    def times(self) -> NDArray[np.float64]:
        """The times of all frames.

        Returns
        -------
        ndarray of float64, shape (len(self),)

        Raises
        ------
        ArgumentValueError
            If the times would not fit the memory budget.

        Examples
        --------
        >>> import scanline as sl
        >>> tl = sl.animation.Timeline({"x": sl.animation.KeyFrames([0, 1], [0, 100])}, fps=4)
        >>> tl.times().tolist()
        [0.0, 0.25, 0.5, 0.75, 1.0]
        """
        count = len(self)
        budget(count * 8 * 3, "duration", f"the times of {count} frames",
               hint="use a shorter duration or a lower fps, or compute the times of a "
                    "range of frames with time(frame)")
        out: NDArray[np.float64] = self.start + np.arange(count) / self.fps
        return out

    def values(self, frame: int) -> dict[str, Any]:
        """Every track's value at ``frame``: a dict name -> value.

        Parameters
        ----------
        frame : int
            A frame index >= 0.

        Returns
        -------
        dict

        Raises
        ------
        ArgumentTypeError, ArgumentValueError
            As :meth:`time`.

        Examples
        --------
        >>> import scanline as sl
        >>> tl = sl.animation.Timeline({"x": sl.animation.KeyFrames([0, 1], [0, 100])}, fps=4)
        >>> tl.values(1)
        {'x': 25.0}
        """
        t = self.time(frame)
        return {name: track(t) for name, track in self.tracks.items()}

    def key_times(self) -> NDArray[np.float64]:
        """The sorted union of the tracks' key times (the storyboard's key frames).

        Returns
        -------
        ndarray of float64
            ``[start]`` when no track has key times.

        Examples
        --------
        >>> import scanline as sl
        >>> tl = sl.animation.Timeline({"x": sl.animation.KeyFrames([0, 1], [0, 100])}, fps=4)
        >>> tl.key_times().tolist()
        [0.0, 1.0]
        """
        times = [t.times for t in self.tracks.values() if isinstance(t, KeyFrames)]
        out: NDArray[np.float64] = (np.unique(np.concatenate(times)) if times
                                    else np.array([self.start]))
        return out

    def key_frames(self) -> NDArray[np.int64]:
        """The frames nearest the key times (one per key time inside the sequence).

        Returns
        -------
        ndarray of int64

        Examples
        --------
        At 4 fps the key times 0 s and 1 s are frames 0 and 4:

        >>> import scanline as sl
        >>> tl = sl.animation.Timeline({"x": sl.animation.KeyFrames([0, 1], [0, 100])}, fps=4)
        >>> tl.key_frames().tolist()
        [0, 4]
        """
        frames = np.floor((self.key_times() - self.start) * self.fps + 0.5).astype(np.int64)
        out: NDArray[np.int64] = np.unique(np.clip(frames, 0, len(self) - 1))
        return out

    def __repr__(self) -> str:
        return (f"Timeline({len(self.tracks)} tracks, {len(self)} frames at {self.fps:g} fps, "
                f"{self.duration:g} s)")
