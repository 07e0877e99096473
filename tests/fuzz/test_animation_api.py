"""Every public entry point of sl.animation (and the animated scene) on generated
hostile arguments: numbers of every kind (NaN, +-inf, 1e300, 5e-324, 2**63 ...),
wrong types, arrays of every dtype, shape and memory layout.  Each call runs in
:func:`tests.fuzz.harness.bounded` (time and memory limits; only ScanlineError may
escape); frame buffers drawn on or read sit between guard rows (no byte outside may
change); a save or write that fails leaves no file.  The tests that reach a compiled
kernel (Beier-Neely's field morph, the frames' drawing) are marked ``boundscheck``:
.ci/run runs them again with NUMBA_BOUNDSCHECK=1, where an out-of-bounds access is an
IndexError.

The memory budget is lowered to 256 MiB here (SCANLINE_MEMORY_LIMIT), half the
harness's 512 MiB, so that whatever the budget lets through stays within the harness.
"""

import json
import math
import os
import shutil
import tempfile
import warnings

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import scanline as sl
from tests.fuzz.harness import SPECIAL, arrays, bounded, guard_intact, guarded, index_arrays, values

A = sl.animation

#: Anything at all: the harness's numbers, and values of the wrong type.
WRONG = [None, "x", "", b"x", True, [], (), {"a": 1}, 1j, object(), [[1, 2], [3]],
         np.zeros((2, 3, 4)), np.array(["a", "b"]), slice(None), 2**1100]
anything = st.one_of(values, st.sampled_from(WRONG), arrays(2, max_rows=3))
counts = st.one_of(st.integers(-3, 40), st.sampled_from(SPECIAL + WRONG))
flags = st.sampled_from([True, False, 0, 1, None, "yes", np.nan, np.array([1, 0]), 2])
EASE_NAMES = st.one_of(st.sampled_from(sorted(A.EASINGS)), st.sampled_from(WRONG),
                       st.text(max_size=10))
MODES = st.sampled_from(["L", "RGB", "RGBA"])


@pytest.fixture(autouse=True, scope="module")
def small_budget():
    with pytest.MonkeyPatch.context() as mp:
        mp.setenv("SCANLINE_MEMORY_LIMIT", "256M")
        yield


def scratch():
    return tempfile.mkdtemp(prefix="scanline-fuzz-")


# -- timing and easing ---------------------------------------------------------------------
@given(a=anything, b=anything, n=counts, spacing=st.one_of(EASE_NAMES, st.just(lambda t: t)))
def test_timing(a, b, n, spacing):
    with bounded():
        A.frames_needed(a, b, inbetweens=n)
    with bounded():
        A.duration_of(n, b, inbetweens=n)
    with bounded():
        A.frame_count(a, b)
    with bounded():
        A.inbetween_times(a, b, n, spacing=spacing)


@given(name=EASE_NAMES, t=st.one_of(anything, arrays(1, max_rows=8)),
       x1=values, y1=values, x2=values, y2=values)
def test_easing(name, t, x1, y1, x2, y2):
    with bounded():
        A.ease(name, t)
    with bounded():
        A.ease(A.cubic_bezier(x1, y1, x2, y2), t)


# -- key frames and timelines --------------------------------------------------------------
@given(times=st.one_of(arrays(1, max_rows=6, flavour=False).map(np.ravel), anything),
       vals=st.one_of(arrays(2, max_rows=6), anything),
       interpolation=st.sampled_from(list(A.INTERPOLATIONS) + ["spline", 3]),
       ease=st.one_of(EASE_NAMES, st.lists(EASE_NAMES, max_size=5)),
       tension=anything, t=st.one_of(anything, arrays(1, max_rows=5)))
def test_keyframes(times, vals, interpolation, ease, tension, t):
    track = None
    with bounded():
        track = A.KeyFrames(times, vals, interpolation=interpolation, ease=ease,
                            tension=tension, continuity=tension, bias=tension)
    if track is None:
        return
    with bounded():
        track(t)
    with bounded():
        track.segment(t)


@given(fps=anything, duration=st.one_of(st.none(), anything), start=anything, frame=counts,
       name=st.one_of(st.text(max_size=4), st.sampled_from(WRONG)))
def test_timelines(fps, duration, start, frame, name):
    track = A.KeyFrames([0, 1, 2], [(0, 0), (10, 5), (0, 0)], interpolation="catmull-rom")
    timeline = None
    with bounded():
        timeline = A.Timeline({"x": track}, fps=fps, duration=duration, start=start)
    with bounded():
        A.Timeline(fps=4).add(name, [0, frame], [0, 1])
    if timeline is None:
        return
    with bounded():
        len(timeline)
    with bounded():
        timeline.values(frame)
    with bounded():
        timeline.key_frames()
    with bounded():
        timeline.times()


# -- motion -----------------------------------------------------------------------------------
@given(points=arrays(2, max_rows=6), control=arrays(2, max_rows=5, flavour=False),
       arc=flags, intervals=st.one_of(st.none(), counts),
       s=st.one_of(anything, arrays(1, max_rows=4)), t=anything, start=anything, end=anything,
       ease=EASE_NAMES)
def test_motion_paths(points, control, arc, intervals, s, t, start, end, ease):
    paths = []
    with bounded():
        paths.append(A.MotionPath(points, arc_length=arc))
    with bounded():
        paths.append(A.MotionPath(sl.curves.Bezier(control), arc_length=arc,
                                  intervals=intervals))
    for path in paths:
        for method in (path.point, path.tangent, path.parameter, path.distance, path.heading,
                       path.transform):
            with bounded():
                method(s)
        with bounded():
            path.at(t, start, end, ease)


@given(x=st.one_of(anything, arrays(1, max_rows=5)), amplitude=anything, omega=anything,
       theta=anything, damping=anything, t=anything, p=anything, v=anything, g=anything)
def test_direct_motion(x, amplitude, omega, theta, damping, t, p, v, g):
    with bounded():
        A.bouncing_ball(x, amplitude, omega, theta, damping)
    with bounded():
        A.ballistic(t, p, v, g)
    with bounded():
        A.ballistic(t, (0, 0), (1, 2), (0, -9.81))


@given(lengths=st.one_of(arrays(1, max_rows=4, flavour=False).map(np.ravel), anything),
       base=anything, limits=st.one_of(st.none(), arrays(2, max_rows=3), anything),
       axes=st.one_of(st.none(), arrays(3, max_rows=3)), angles=anything, target=anything,
       method=st.sampled_from([None, "analytic", "ccd", "dls", "x", 3]),
       iterations=st.sampled_from([1, 20, 200, 0, -1, 2.5, "x", 2**63]), tolerance=anything,
       damping=anything, strict=flags)
def test_kinematics(lengths, base, limits, axes, angles, target, method, iterations, tolerance,
                    damping, strict):
    chain = None
    with bounded():
        chain = A.Chain(lengths, base=base, axes=axes, limits=limits)
    if chain is None:
        chain = A.Chain([2.0, 1.0, 0.5])
    for call in (chain.forward, chain.end, chain.jacobian):
        with bounded():
            call(angles)
    with bounded():
        chain.inverse(target, method=method, initial=angles, tolerance=tolerance,
                      max_iterations=iterations, damping=damping, strict=strict)
    with bounded():
        chain.follow([target, target], max_iterations=20)


def _steps(duration, dt):
    """The steps Particles.run(duration, dt) would take, or 0 for arguments it
    refuses (a fuzzed run is kept to a moment)."""
    try:
        d, h = float(duration), float(dt)
        return d / h if h > 0 and d >= 0 else 0
    except (TypeError, ValueError, OverflowError, ZeroDivisionError):
        return 0


@given(positions=arrays(2, max_rows=5), velocities=st.one_of(st.none(), arrays(2, max_rows=5)),
       masses=anything, g=anything, pairs=index_arrays(), stiffness=anything, rest=anything,
       drag=anything, point=anything, normal=anything, restitution=anything, dt=anything,
       duration=anything, method=st.sampled_from(["euler", "semi-implicit-euler", "verlet",
                                                  "rk4", "x"]))
def test_dynamics(positions, velocities, masses, g, pairs, stiffness, rest, drag, point,
                  normal, restitution, dt, duration, method):
    forces, obstacles = [], []
    with bounded():
        forces.append(A.Gravity(g))
    with bounded():
        forces.append(A.Spring(np.asarray(pairs).reshape(-1, 2) if np.size(pairs) % 2 == 0
                               else pairs, stiffness, rest_length=rest, damping=0.1))
    with bounded():
        forces.append(A.Drag(drag, drag))
    with bounded():
        obstacles.append(A.Plane(point, normal, restitution=restitution, friction=drag))
    system = None
    with bounded():
        system = A.Particles(positions, velocities, masses=masses, forces=forces,
                             obstacles=obstacles)
    if system is None:
        return
    with bounded():
        system.step(dt, method)
    with bounded():
        system.energy()
    if _steps(duration, dt) <= 2000:
        with bounded():
            system.run(duration, dt, method)


# -- morphing --------------------------------------------------------------------------------
@given(a=arrays(2, max_rows=8), b=arrays(2, max_rows=8), count_a=counts, count_b=counts,
       closed=flags, align=flags, t=st.one_of(anything, arrays(1, max_rows=3)))
def test_shape_morphing(a, b, count_a, count_b, closed, align, t):
    with bounded():
        A.equalization(count_a, count_b, closed=closed)
    with bounded():
        A.equalize(a, b, a, closed=closed, align=align, return_added=align)
    with bounded():
        A.morph(a, b, t, closed=closed, align=align)


def _image(kind, mode, w, h):
    """(the image, its guard storage or None)."""
    if kind == "fb":
        return guarded(w, h, mode)
    channels = {"L": (), "RGB": (3,), "RGBA": (4,)}[mode]
    return np.random.default_rng(w * h).integers(0, 256, (h, w) + channels, np.uint8), None


@pytest.mark.boundscheck
@given(lines_a=arrays(4, max_rows=4), lines_b=arrays(4, max_rows=4), t=anything, a=anything,
       b=anything, p=anything, mode=MODES, kind=st.sampled_from(["fb", "array"]),
       w=st.integers(1, 12), h=st.integers(1, 12), other=st.sampled_from(["same", "other"]))
def test_beier_neely(lines_a, lines_b, t, a, b, p, mode, kind, w, h, other):
    image_a, big_a = _image(kind, mode, w, h)
    image_b, big_b = (image_a, big_a) if other == "same" else _image(kind, mode, w, h)
    with bounded():
        A.beier_neely(image_a, image_b, lines_a, lines_b, t, a=a, b=b, p=p)
    with bounded():
        A.warp(image_a, lines_a, lines_b, a=a, b=b, p=p)
    for big in (big_a, big_b):
        assert big is None or guard_intact(big)


@pytest.mark.boundscheck
@given(table=arrays(23, max_rows=3, flavour=False), t=values, a=values, b=values,
       w=st.integers(1, 9), h=st.integers(1, 9), channels=st.sampled_from([1, 3, 4]))
def test_morph_kernel_on_any_table(table, t, a, b, w, h, channels):
    """The compiled kernel itself, given any table and weights (the API refuses most):
    every write inside ``out``, every read inside the sources."""
    from scanline._kernels.morph import field_morph

    src = np.arange(w * h * channels, dtype=np.uint8).reshape(h, w, channels)
    big = np.full((h + 4, w, channels), 77, np.uint8)
    out = big[2:-2]
    try:
        with np.errstate(all="ignore"), warnings.catch_warnings():
            warnings.simplefilter("ignore")
            table = np.ascontiguousarray(table, dtype=np.float64)
            t, a, b = float(t), float(a), float(b)
    except (TypeError, ValueError, OverflowError):
        table, t, a, b = np.zeros((1, 23)), 0.5, 1.0, 2.0
    if table.ndim != 2 or table.shape[1] != 23:
        table = np.zeros((1, 23))
    with bounded(), np.errstate(all="ignore"):
        field_morph(src, src, table, t, a, b, out)
    assert (big[:2] == 77).all() and (big[-2:] == 77).all()


# -- output ---------------------------------------------------------------------------------
def _render(big_fbs):
    def render(i):
        fb, big = guarded(9, 7, "RGB")
        big_fbs.append(big)
        sl.draw.line(fb, 0, 0, int(i) % 9, 6, color="navy")
        return fb
    return render


@pytest.mark.boundscheck
@given(fps=anything, frames=counts, loop=counts,
       ext=st.sampled_from([".gif", ".png", ".webp", ".mp4", ".apng", ".txt", ""]),
       selection=st.one_of(st.none(), st.tuples(counts, counts), anything,
                           st.sampled_from([slice(0, 2), slice(None, None, -1), slice(0, 0)])),
       quality=st.one_of(st.none(), counts), jobs=st.sampled_from([1, 0, -1, 2.5, 10**9, "x"]),
       client=st.sampled_from([None, None, "", "nope", "tcp://", "tls://h:1", 5, "tcp://h:0"]),
       progress=flags, index=counts)
def test_animation_save(fps, frames, loop, ext, selection, quality, jobs, client, progress,
                        index):
    """Saves of a render function drawing guarded frames; a failed save leaves no file
    (and no temporary file)."""
    folder = scratch()
    try:
        fbs = []
        anim = None
        with bounded():
            anim = A.Animation(_render(fbs), fps=fps, frames=frames, loop=loop)
        if anim is None or len(anim) > 64:
            return
        failed = []
        with bounded():
            try:
                anim.save(os.path.join(folder, "out" + ext), jobs=jobs, client=client,
                          progress=progress, frames=selection, quality=quality)
            except sl.ScanlineError:
                failed.append(True)
                raise
        if failed:
            assert os.listdir(folder) == []
        with bounded():
            anim.frame(index)
        assert all(guard_intact(big) for big in fbs)
    finally:
        shutil.rmtree(folder)


@given(sources=st.lists(st.one_of(st.sampled_from(WRONG), arrays(3, max_rows=3),
                                  st.just(np.zeros((4, 5), np.uint8)),
                                  st.just(np.zeros((4, 5, 3), np.uint8))), max_size=3),
       fps=values, pattern=st.one_of(st.sampled_from(
           ["frame-{:05d}.png", "../x-{:05d}.png", "x.png", "{}-{}.png", "{:1>5}.png", "{}.txt",
            "{", "{0:04d}.gif", "a/{}.png", "{}.png\x00"]), st.text(max_size=12), anything))
def test_animation_sources_and_frame_files(sources, fps, pattern):
    folder = scratch()
    try:
        anim = None
        with bounded():
            anim = A.Animation(sources, fps=fps)
        if anim is not None:
            with bounded():
                anim.save(os.path.join(folder, "a.png"))
        target = os.path.join(folder, "inner", "frames")
        with bounded():
            A.Animation([np.zeros((3, 4), np.uint8)] * 2, fps=2).write_frames(target,
                                                                             pattern=pattern)
        for root, _, files in os.walk(folder):
            # nothing escapes the folder asked for, and no name is written twice
            assert root.startswith(folder)
            for name in files:
                assert root == target or name == "a.png", (root, name)
    finally:
        shutil.rmtree(folder)


@pytest.mark.boundscheck
@given(frames=st.lists(st.one_of(st.sampled_from(["fb", "array", "empty"]),
                                 st.sampled_from(WRONG)), max_size=4),
       labels=st.one_of(st.lists(st.text(max_size=30), max_size=4), anything),
       captions=st.one_of(st.none(), st.lists(st.text(max_size=200), max_size=4), anything),
       columns=counts, panel=st.one_of(st.tuples(counts, counts), anything),
       title=st.one_of(st.none(), st.text(max_size=20), anything))
def test_contact_sheets(frames, labels, captions, columns, panel, title):
    made, bigs = [], []
    for kind in frames:
        if not isinstance(kind, str) or kind not in ("fb", "array", "empty"):
            made.append(kind)
        elif kind == "fb":
            fb, big = guarded(7, 5, "RGB")
            bigs.append(big)
            made.append(fb)
        elif kind == "array":
            made.append(np.zeros((5, 7, 3), np.uint8))
        else:
            made.append(np.zeros((0, 7), np.uint8))
    with bounded():
        A.contact_sheet(made, labels, captions, columns=columns, panel=panel, title=title)
    assert all(guard_intact(big) for big in bigs)


# -- animated scenes ------------------------------------------------------------------------
SCENE = {
    "version": 2, "canvas": {"width": 24, "height": 16, "background": "white"},
    "segments": [
        {"name": "ball", "transform": [{"rotate": {"degrees": 0}}, {"translate": [4, 4]}],
         "primitives": [{"type": "circle", "center": [0, 0], "radius": 3, "fill": True,
                         "color": "crimson"},
                        {"type": "polyline", "points": [[0, 0], [5, 0]], "color": "navy"}]},
        {"name": "blob", "primitives": [{"type": "polygon", "color": "teal",
                                         "points": [[14, 2], [20, 2], [20, 8], [14, 8]]}]}],
    "animation": {"fps": 4},
}
TARGETS = ["segments[ball].transform[1].translate", "segments[ball].transform[0].rotate.degrees",
           "segments[ball].primitives[0].radius", "segments[ball].primitives[0].color",
           "segments[ball].primitives[0].center", "segments[ball].name", "segments[blob].name",
           "segments[ball].primitives[0].type", "segments[ball].primitives[0].fill",
           "segments[blob].primitives[0].points", "canvas.width", "canvas.background",
           "segments[9].name", "segments[ball]", "version", "segments[ball].primitives[1].points"]
KEY_VALUES = st.one_of(st.sampled_from([1, 2.5, -3, 1e300, -1e300, 2**63, 10**400, [1, 2],
                                        [[1, 2]], "red", "x", True, None, [], {"a": 1},
                                        [[14, 2], [20, 2], [17, 9]], [1e308, 1e308]]),
                       st.floats(allow_nan=False, allow_infinity=False, width=32))
SCENE_NUMBERS = st.one_of(st.sampled_from([1e-300, 1e300, 0, -1, 5e-324, 2**63, "x", True,
                                           [1], 1e6, 0.5, 3]),
                          st.floats(0.01, 100))


@pytest.mark.boundscheck
@given(target=st.sampled_from(TARGETS), first=KEY_VALUES, second=KEY_VALUES,
       kind=st.sampled_from(["tracks", "morphs", "paths"]), fps=SCENE_NUMBERS,
       duration=st.one_of(st.none(), SCENE_NUMBERS), start=SCENE_NUMBERS,
       interpolation=st.sampled_from(["linear", "step", "catmull-rom", "x"]))
def test_animated_scenes(target, first, second, kind, fps, duration, start, interpolation):
    data = json.loads(json.dumps(SCENE))
    a = data["animation"]
    a["fps"], a["start"] = fps, start
    if duration is not None:
        a["duration"] = duration
    if kind == "tracks":
        a["tracks"] = [{"target": target, "interpolation": interpolation, "keys": [
            {"time": 0, "value": first}, {"time": 1, "value": second}]}]
    elif kind == "morphs":
        a["morphs"] = [{"target": target, "keys": [{"time": 0, "points": first},
                                                   {"time": 1, "points": second}]}]
    else:
        a["paths"] = [{"target": target, "curve": {"type": "polyline",
                                                   "points": [first, second]}}]
    try:
        text = json.dumps(data)
    except (ValueError, OverflowError):
        return
    scene = None
    with bounded():
        scene = sl.scene.loads_animated(text, format="json")
    if scene is None:
        return
    for index in (0, len(scene) // 2, len(scene) - 1):
        with bounded():
            scene.frame(index)
    with bounded():
        scene.storyboard_sheet(columns=2, panel=(32, 24))


@given(value=st.sampled_from([math.nan, 1e-300, 1e300, -5]))
def test_scene_frame_rates(value):
    with bounded():
        sl.scene.loads_animated(json.dumps(dict(SCENE, animation={
            "fps": value, "tracks": [{"target": "segments[ball].primitives[0].radius",
                                      "keys": [{"time": 0, "value": 1},
                                               {"time": 1, "value": 3}]}]})), format="json")
