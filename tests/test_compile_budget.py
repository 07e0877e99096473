"""The compile-time rule of the kernel layer (:mod:`scanline._kernels`), checked by
counting compiled specializations, never by timing them.

Every call of :data:`scanline.warmup.CALLS` (every entry point that reaches a kernel,
in every mode where the mode matters) runs in fresh processes that compile every
kernel and helper they reach (numba's cache is not read, so the helpers' own
specializations exist to be counted; it is written, so this module, which
``tests/conftest.py`` runs first, also warms the cache for the rest of the suite,
two processes in parallel).  Then each kernel's specializations are read back from
numba and checked against the rule: variants arrive as tokens, arrays arrive
normalized, and no argument is compiled both as a literal and as a value.
"""

import json
import os
import shutil
import subprocess
import sys
import tempfile

import pytest

from scanline import warmup

#: Run in a fresh process: make the calls of every group of calls that no other process
#: has claimed (a claim: a file created in the claims folder), print every kernel's
#: signatures.
REPORT = r"""
import importlib, json, os, pkgutil, sys
from numba.core import caching, types
from numba.core.dispatcher import Dispatcher
caching.Cache.load_overload = lambda self, sig, target_context: None   # compile everything
import scanline._kernels as package
from scanline import warmup

groups, modes, claims = json.loads(sys.argv[1]), tuple(json.loads(sys.argv[2])), sys.argv[3]
for i, names in enumerate(groups):
    try:
        os.close(os.open(os.path.join(claims, str(i)), os.O_CREAT | os.O_EXCL))
    except FileExistsError:
        continue
    warmup.run(names, modes)

def describe(t):
    if isinstance(t, types.Literal):
        return {"literal": str(t.literal_type)}
    if isinstance(t, types.UniTuple) and all(isinstance(x, types.Integer) for x in t):
        return {"token": t.count}
    if isinstance(t, types.Array):
        return {"array": str(t.dtype), "ndim": t.ndim, "layout": t.layout,
                "writable": t.mutable}
    return {"type": str(t)}

out = {}
for info in pkgutil.iter_modules(package.__path__):
    module = importlib.import_module(f"{package.__name__}.{info.name}")
    for name, obj in vars(module).items():
        if isinstance(obj, Dispatcher) and obj.py_func.__module__ == module.__name__:
            sigs = [[describe(t) for t in sig] for sig in obj.signatures]
            if sigs:
                out[f"{info.name}.{name}"] = sigs
print(json.dumps(out))
"""


def specializations(names=None, modes=warmup.MODES, cache_dir=None, jobs=1):
    """{kernel: [signature, ...]} after the warm-up calls ``names`` (default: all) in
    ``modes``, made by ``jobs`` processes that take whole groups of calls, the largest
    first, each the next one left when it is done with one (the groups' compile times
    differ too much for a split made beforehand: 126 against 180 s on 2 cores)."""
    env = dict(os.environ)
    if cache_dir is not None:
        env["NUMBA_CACHE_DIR"] = str(cache_dir)
    todo = [names] if names else warmup.by_group(modes)
    claims = tempfile.mkdtemp(prefix="scanline-claims-")
    procs = [subprocess.Popen([sys.executable, "-c", REPORT, json.dumps(todo), json.dumps(modes),
                               claims],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
             for _ in range(min(jobs, len(todo)))]
    merged = {}
    try:
        for proc in procs:
            out, err = proc.communicate(timeout=1800)
            assert proc.returncode == 0, err[-3000:]
            for kernel, sigs in json.loads(out.strip().splitlines()[-1]).items():
                merged.setdefault(kernel, [])
                merged[kernel] += [s for s in sigs if s not in merged[kernel]]
    finally:
        shutil.rmtree(claims)
    return merged


def canonical(sig):
    """A signature with literals replaced by their types and tokens by 'token'."""
    out = []
    for arg in sig:
        if "literal" in arg:
            out.append(arg["literal"])
        elif "token" in arg:
            out.append("token")
        else:
            out.append(json.dumps(arg, sort_keys=True))
    return tuple(out)


@pytest.fixture(scope="module")
def everything():
    # the whole suite compiled every kernel before its first test (conftest.py) and
    # recorded what it counted; otherwise compile them here
    recorded = os.environ.get("SCANLINE_TEST_KERNELS")
    if recorded:
        with open(recorded) as f:
            return json.load(f)
    return specializations(jobs=2)


def test_every_call_reaches_kernels(everything):
    # the warm-up really compiles the kernel layer (a broken report would pass the
    # checks below vacuously)
    assert len(everything) > 60
    for kernel in ("lines.draw_line", "antialias.draw_lines", "polygon.fill_polygons",
                   "coverage.fill_shapes", "seedfill.seed_fill", "text.stamp_line",
                   "strokes.stroke_outlines", "blend.over"):
        assert kernel in everything, kernel


def test_arrays_reach_kernels_contiguous_and_writable(everything):
    bad = {k: sig for k, sigs in everything.items() for sig in sigs
           for arg in sig if "array" in arg and (arg["layout"] != "C" or not arg["writable"])}
    assert not bad


def test_one_specialization_per_variant(everything):
    # Beyond the tokens (and intended literal flags), a kernel sees one combination of
    # argument types: int32 vs int64, float vs int, read-only or strided arrays would
    # each compile again.
    over = {k: sorted({canonical(s) for s in sigs}) for k, sigs in everything.items()
            if len({canonical(s) for s in sigs}) > 1}
    # the one deliberate exception: the fixed-point modes of the antialiased line take
    # the color as integers, the others as "over"'s float row -- one type per mode
    over.pop("antialias.wu_line", None)
    assert not over


def test_no_argument_is_compiled_as_a_literal_and_as_a_value(everything):
    # numba compiles a helper again for a constant argument (a literal 0, True) and a
    # loop-carried variable starting at one; the rule: typed start values
    doubled = {}
    for kernel, sigs in everything.items():
        for i in range(len(sigs[0])):
            kinds = {"literal" in sig[i] for sig in sigs if canonical(sig) == canonical(sigs[0])}
            if kinds == {True, False}:
                doubled.setdefault(kernel, []).append(i)
    assert not doubled


def test_a_mode_compiles_its_own_code_only(tmp_path):
    # an RGB user compiles RGB: one specialization, for the RGB token (3 zeros), of
    # the antialiased line kernel and of the blend it composites with
    sigs = specializations(["line aa", "polygon aa"], ("RGB",), cache_dir=tmp_path)
    for kernel, mode_arg in (("antialias.draw_lines", 1), ("coverage.fill_shapes", 1),
                             ("blend.composite_row", 1)):
        assert [s[mode_arg] for s in sigs[kernel]] == [{"token": 3}], kernel
    # and a plain line in mode "L" compiles the byte layout and Bresenham only
    sigs = specializations(["line"], ("L",), cache_dir=tmp_path)
    assert [(s[1], s[-1]) for s in sigs["lines.draw_line"]] == [({"token": 2}, {"token": 1})]
    assert "dda_line" not in " ".join(sigs)


UNCACHED = r"""
import numba.core.caching as caching
from numba import njit
def read_only(self):                         # no folder numba may write its cache to
    raise PermissionError(13, "read-only", self.get_cache_path())
caching._CacheLocator.ensure_cache_path = read_only    # (every locator, the kernels' too)
try:
    njit(cache=True)(lambda x: x)
except RuntimeError as exc:
    print("numba refuses:", exc)
import scanline as sl
from scanline._kernels import lines
fb = sl.FrameBuffer(8, 4, mode="1")
sl.draw.line(fb, 0, 0, 7, 3)
print(sl.text_image(fb))
print(type(lines.draw_line._cache).__name__)
"""


def test_kernels_work_uncached_where_no_cache_folder_can_be_written():
    proc = subprocess.run([sys.executable, "-c", UNCACHED], capture_output=True, text=True,
                          timeout=600)
    assert proc.returncode == 0, proc.stderr[-3000:]
    lines = proc.stdout.splitlines()
    assert lines[0].startswith("numba refuses: cannot cache")   # the premise
    assert lines[1:5] == ["------##", "----##--", "--##----", "##------"]
    assert lines[5] == "NullCache"
