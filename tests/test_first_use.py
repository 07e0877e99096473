"""First use: a kernel that is neither compiled nor cached runs as its Python twin
for small work (:func:`scanline._kernels._jit.call`), and the twin computes exactly
what the compiled kernel computes.

Every call of :data:`scanline.warmup.CALLS` (every entry point, in every mode) is made
twice, compiled and as Python, and the pixels (or the values) must be identical; the
kernels most often met first (polygon fill, strokes, antialiased lines and areas,
text, flattening) are compared again on random input.
"""

import contextlib
import os
import subprocess
import sys

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import scanline as sl
from scanline import warmup
from scanline._kernels import _jit


@contextlib.contextmanager
def compiling(mode):
    """Run the kernels compiled (``"always"``) or as their Python twins (``"never"``)."""
    before, _jit.COMPILE = _jit.COMPILE, mode
    try:
        yield
    finally:
        _jit.COMPILE = before


def outcome(mode, code, how):
    """The frame buffer's pixels after ``code`` (or, for a call that draws nothing, the
    value of its expression), run compiled or as Python (``how``)."""
    with compiling(how):
        fb = sl.FrameBuffer(96, 64, mode=mode or "RGB", background="white")
        scope = {"sl": sl, "np": np, "fb": fb}
        try:
            value = eval(code, scope)
        except SyntaxError:      # statements: their effect is on fb
            exec(code, scope)
            value = None
        return fb.to_array(), value


def same(a, b):
    """Equal, recursively: arrays exactly (NaN where NaN), numbers, sequences,
    dictionaries, objects' attributes."""
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        np.testing.assert_array_equal(a, b)
    elif isinstance(a, dict) and isinstance(b, dict):
        assert sorted(a, key=repr) == sorted(b, key=repr)
        for key in a:
            same(a[key], b[key])
    elif isinstance(a, (list, tuple)) and isinstance(b, (list, tuple)):
        assert len(a) == len(b)
        for x, y in zip(a, b):
            same(x, y)
    elif hasattr(a, "__dict__") and type(a) is type(b) and not callable(a):
        same(sorted(vars(a).items()), sorted(vars(b).items()))
    else:
        assert a == b or (a != a and b != b)


@pytest.mark.parametrize("name, mode, code", list(warmup.cases()),
                         ids=[f"{n}[{m}]" for n, m, _ in warmup.cases()])
def test_every_call_gives_the_same_result_as_python(name, mode, code):
    compiled = outcome(mode, code, "always")
    python = outcome(mode, code, "never")
    np.testing.assert_array_equal(compiled[0], python[0])
    same(compiled[1], python[1])


coord = st.floats(-20, 120, allow_nan=False, allow_infinity=False)
points = st.lists(st.tuples(coord, coord), min_size=1, max_size=12)
MODES = st.sampled_from(warmup.MODES)


def both(draw, mode):
    """``draw(fb)`` compiled and as Python: the two images."""
    images = []
    for how in ("always", "never"):
        with compiling(how):
            fb = sl.FrameBuffer(48, 40, mode=mode, background="white")
            draw(fb)
            images.append(fb.to_array())
    return images


@settings(max_examples=60, deadline=None)
@given(st.lists(points, min_size=1, max_size=3), st.sampled_from(["even-odd", "nonzero"]),
       MODES, st.booleans())
def test_random_polygons(contours, rule, mode, antialias):
    a, b = both(lambda fb: sl.draw.polygon(fb, contours, color="navy", rule=rule,
                                           antialias=antialias), mode)
    np.testing.assert_array_equal(a, b)


@settings(max_examples=60, deadline=None)
@given(points, st.floats(1, 9), st.sampled_from(["butt", "round", "square"]),
       st.sampled_from(["miter", "round", "bevel"]), st.booleans(), st.booleans(), MODES)
def test_random_strokes(path, width, cap, join, dashed, antialias, mode):
    dash = (5.0, 3.0) if dashed else None
    a, b = both(lambda fb: sl.draw.polyline(fb, path, color=(200, 30, 30, 160), width=width,
                                            cap=cap, join=join, dash=dash,
                                            antialias=antialias), mode)
    np.testing.assert_array_equal(a, b)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(coord, coord, coord, coord), min_size=1, max_size=8),
       st.lists(st.tuples(coord, coord, st.floats(0, 30)), min_size=1, max_size=5), MODES)
def test_random_antialiased_lines_and_circles(segments, circles, mode):
    def draw(fb):
        sl.draw.lines(fb, segments, color="black", antialias=True)
        sl.draw.circles(fb, circles, color=(0, 90, 200, 200), antialias=True)
        sl.draw.fill_circles(fb, circles, color=(0, 200, 90, 100), antialias=True)
    a, b = both(draw, mode)
    np.testing.assert_array_equal(a, b)


@settings(max_examples=25, deadline=None)
@given(st.text(alphabet="abcdefgAWgjy019.,()", min_size=1, max_size=8), st.floats(5, 30),
       st.floats(-1, 1), st.booleans(), MODES)
def test_random_text(text, height, angle, antialias, mode):
    a, b = both(lambda fb: sl.draw.text(fb, 3, 12, text, color="black", height=height,
                                        angle=angle, antialias=antialias), mode)
    np.testing.assert_array_equal(a, b)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(coord, coord), min_size=4, max_size=7), st.floats(0.02, 2))
def test_random_curves_flatten_alike(controls, tolerance):
    curve = sl.curves.BSpline(controls, order=4)
    with compiling("always"):
        a = curve.flatten(tolerance)
    with compiling("never"):
        b = curve.flatten(tolerance)
    np.testing.assert_array_equal(a, b)


def test_a_first_call_runs_as_python_and_a_large_one_compiles(tmp_path):
    # in a fresh environment (an empty numba cache), the four-call script of the issue
    # compiles nothing; a large fill compiles the polygon kernel; a later process finds
    # it in the cache and runs it compiled, whatever the size
    script = r"""
import sys
import scanline as sl
from scanline._kernels import polygon
fb = sl.FrameBuffer(96, 64, background="white")
sl.draw.line(fb, 3, 4, 90, 50, color="black")
sl.draw.polygon(fb, [(48, 60), (20, 4), (92, 40), (4, 40), (76, 4)], color="navy",
                rule="nonzero")
sl.draw.text(fb, 4, 20, "Hello", color="black", height=14)
sl.draw.circle(fb, 48, 32, 20.5, color="red", antialias=True)
print("small", bool(polygon.fill_polygons.overloads))
if sys.argv[1] == "large":
    big = sl.FrameBuffer(2000, 2000)
    sl.draw.polygon(big, [(0, 0), (1999, 0), (1000, 1999)], color="white")
    print("large", bool(polygon.fill_polygons.overloads))
"""
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "cache"), SCANLINE_COMPILE="auto")
    run = lambda arg: subprocess.run([sys.executable, "-c", script, arg], capture_output=True,
                                     text=True, env=env, timeout=600)
    first = run("large")
    assert first.returncode == 0, first.stderr
    assert first.stdout.split() == ["small", "False", "large", "True"]
    later = run("small")
    assert later.returncode == 0, later.stderr
    assert later.stdout.split() == ["small", "True"]      # cached: loaded, not interpreted


def test_many_small_calls_end_up_compiled(tmp_path):
    # the twin's time is budgeted: a process that keeps calling compiles after all
    script = r"""
import scanline as sl
from scanline._kernels import _jit, conics
fb = sl.FrameBuffer(40, 30)
calls = 0
while not conics.draw_ellipse.overloads and calls < 100000:
    sl.draw.ellipse(fb, 20, 15, 12, 7)
    calls += 1
print(calls > 1, _jit._SPENT[conics.draw_ellipse] > _jit.TWIN_TIME,
      bool(conics.draw_ellipse.overloads))
"""
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "cache"), SCANLINE_COMPILE="auto")
    proc = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                          env=env, timeout=600)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.split() == ["True", "True", "True"]


@pytest.mark.parametrize("name, kernels", [
    ("render ray-tracing", ["raytrace.trace_all", "raycast.cast_rays"]),
    ("render ray-tracing maps", ["raytrace.trace_all", "raycast.cast_rays"]),
    ("radiosity ray-casting", ["formfactors.raycast_rows"]),
    ("visible depth sort", ["depthsort.depth_sort"])])
def test_the_slowest_kernels_to_compile_answer_a_first_use_as_python(tmp_path, name, kernels):
    # kernels that take seconds to compile (declared slow_to_compile) answer the
    # first-use case as their twins in a fresh environment: none of them is compiled
    script = f"""
import importlib
from scanline import warmup
mode, code = next((m, c) for n, m, c in warmup.cases([{name!r}]))
warmup.run_case(mode, code)
for kernel in {kernels!r}:
    module, function = kernel.split(".")
    found = getattr(importlib.import_module("scanline._kernels." + module), function)
    print(kernel, bool(found.overloads))
"""
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "cache"), SCANLINE_COMPILE="auto")
    proc = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                          env=env, timeout=600)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.split() == [word for k in kernels for word in (k, "False")]


def test_a_first_ray_trace_goes_in_parts_with_the_pixels_of_one_call(monkeypatch):
    # before the tracer is compiled its samples go in parts (the twin's time budget is
    # checked between them): the parts give the pixels of the compiled single call
    from scanline._kernels import raytrace

    code = warmup.CALLS["render ray-tracing"][1]
    whole = outcome("RGB", code, "always")
    twin = _jit.python(raytrace.trace_all)
    parts = []

    class Uncompiled:                 # a stand-in: no overloads, so the call is parted
        overloads = {}

        def __call__(self, *args):
            parts.append(len(args[2]))
            with np.errstate(all="ignore"):
                return twin(*args)

    monkeypatch.setattr(raytrace, "trace_all", Uncompiled())
    monkeypatch.setattr(_jit, "TWIN_WORK", 20_000)
    parted = outcome("RGB", code, "auto")
    assert len(parts) > 3 and len(set(parts[:-1])) == 1
    np.testing.assert_array_equal(parted[0], whole[0])
