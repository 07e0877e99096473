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

import numpy as np

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError
from .easing import apply, resolve
from ..budget import check as budget
from ._checks import floats
from .timing import MAX_FRAMES, frame_count

#: Interpolation methods between key values.
INTERPOLATIONS = ("linear", "step", "catmull-rom", "cardinal", "kochanek-bartels")


def _times(times):
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


def _values(values, count):
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


def _per_segment(name, value, segments, convert):
    if isinstance(value, (list, tuple)):
        if len(value) != segments:
            raise ArgumentValueError(
                f"{name} must be one value or a list of one per segment ({segments}), "
                f"got {len(value)}")
        return [convert(x, f"{name}[{k}]") for k, x in enumerate(value)]
    one = convert(value, name)
    return [one] * segments


def _spline_parameter(name, value, count):
    a = floats(name, value, f"a number or one per key frame ({count})") \
        if not isinstance(value, numbers.Real) else None
    if a is None or a.ndim == 0:
        return np.full(count, v.number(name, value if a is None else float(a)))
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
    """

    def __init__(self, times, values, interpolation="linear", ease="linear", tension=0.0,
                 continuity=0.0, bias=0.0):
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

    def _spline(self, tension, continuity, bias):
        from ..curves import Hermite, KochanekBartels

        p = self._flat
        padded = np.vstack([2 * p[0] - p[1], p, 2 * p[-1] - p[-2]])

        def pad(a):
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

    def __len__(self):
        return len(self.times)

    @property
    def shape(self):
        """The shape of one value."""
        return self.values.shape[1:]

    @property
    def start(self):
        """The first key time."""
        return float(self.times[0])

    @property
    def end(self):
        """The last key time."""
        return float(self.times[-1])

    def __call__(self, t):
        """The value at time ``t`` (seconds); an array of times gives an array of
        values, shape ``np.shape(t) + shape``."""
        return self.at(t)

    def at(self, t):
        """The value at time(s) ``t``; see :meth:`__call__`."""
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

    def segment(self, t):
        """The segment index k (key k to key k + 1) and the eased fraction of it at
        each of the times ``t`` (a 1-D array), clamped to the track."""
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

    def _at_one(self, t):
        """The flat value at one time ``t`` (a float): the arithmetic of
        :meth:`_evaluate` on one time, bit for bit, without its array bookkeeping
        (an animated scene evaluates every track once a frame)."""
        times, flat = self._keys, self._flat
        hit = bisect.bisect_left(times, t)
        if hit < len(times) and times[hit] == t:
            return flat[hit].copy()                 # a key time: the key value
        if len(times) == 1 or t < times[0]:
            return flat[0].copy()
        if t > times[-1]:
            return flat[-1].copy()
        k = hit - 1                                 # times[k] < t < times[k + 1]
        s = min(max((t - times[k]) / (times[k + 1] - times[k]), 0.0), 1.0)
        eased = apply(self.ease[k], np.array([s]))
        if self.interpolation == "step":
            return (flat[k + 1] if eased[0] >= 1 else flat[k]).copy()
        if self._curve is None:
            return flat[k] + eased[0] * (flat[k + 1] - flat[k])
        u = min(max(k + float(eased[0]), 0.0), len(flat) - 1.0)
        return self._curve.evaluate(np.array([u]))[0]

    def _evaluate(self, t):
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

    def __repr__(self):
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

    >>> import scanline as sl
    >>> tl = sl.animation.Timeline({"x": sl.animation.KeyFrames([0, 1], [0, 100])}, fps=4)
    >>> len(tl), tl.times().tolist()
    (5, [0.0, 0.25, 0.5, 0.75, 1.0])
    >>> tl.values(2)
    {'x': 50.0}
    """

    def __init__(self, tracks=None, fps=24, duration=None, start=0.0):
        from .timing import _fps

        self.fps = _fps(fps)
        self.start = v.number("start", start)
        self.tracks = {}
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

    def add(self, name, track, *args, **kwargs):
        """Add a track: ``add(name, KeyFrames(...))``, ``add(name, function_of_time)``
        or ``add(name, times, values, **options)`` (builds the :class:`KeyFrames`)."""
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
    def duration(self):
        """Seconds of the sequence."""
        if self._duration is not None:
            return self._duration
        ends = [t.end for t in self.tracks.values() if isinstance(t, KeyFrames)]
        last = max(ends, default=self.start) - self.start
        return max(last, 0.0) + 1.0 / self.fps

    def __len__(self):
        return frame_count(self.duration, self.fps)

    def time(self, frame):
        """The time of ``frame``."""
        frame = v.positive_int("frame", frame, minimum=0)
        if frame > MAX_FRAMES:
            raise ArgumentValueError(f"frame={frame} is beyond the {MAX_FRAMES:,} frames a "
                                     "sequence may have")
        return self.start + frame / self.fps

    def times(self):
        """The times of all frames."""
        count = len(self)
        budget(count * 8 * 3, "duration", f"the times of {count} frames",
               hint="use a shorter duration or a lower fps, or compute the times of a "
                    "range of frames with time(frame)")
        return self.start + np.arange(count) / self.fps

    def values(self, frame):
        """Every track's value at ``frame``: a dict name -> value."""
        t = self.time(frame)
        return {name: track(t) for name, track in self.tracks.items()}

    def key_times(self):
        """The sorted union of the tracks' key times (the storyboard's key frames)."""
        times = [t.times for t in self.tracks.values() if isinstance(t, KeyFrames)]
        return np.unique(np.concatenate(times)) if times else np.array([self.start])

    def key_frames(self):
        """The frames nearest the key times (one per key time inside the sequence)."""
        frames = np.floor((self.key_times() - self.start) * self.fps + 0.5).astype(np.int64)
        return np.unique(np.clip(frames, 0, len(self) - 1))

    def __repr__(self):
        return (f"Timeline({len(self.tracks)} tracks, {len(self)} frames at {self.fps:g} fps, "
                f"{self.duration:g} s)")
