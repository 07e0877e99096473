"""Hardening of sl.animation, the animated scene and the animate / storyboard commands
(issue "Hardening the second half"): each test pins a crash, hang, unbounded allocation,
raw error or accepted bad input that an audit found, and what happens now."""

import contextlib
import io
import json
import math
import os
import signal
import socket
import subprocess
import sys
import textwrap
import threading
import tracemalloc

import numpy as np
import pytest

import scanline as sl
from scanline.animation import Animation
from scanline.animation import render as render_module
from scanline.cli import main
from scanline.errors import MemoryBudgetError
from scanline.scene import SceneError, loads_animated
from tests.reference import peer

EXAMPLE_SCENE = os.path.join(os.path.dirname(sl.__file__), "data", "scenes",
                             "bouncing_ball.toml")


def frame(i):
    fb = sl.FrameBuffer(8, 6, background="white")
    sl.draw.line(fb, 0, 0, int(i) % 8, 5, color="navy")
    return fb


def run_cli(argv):
    err = io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
        status = main(argv)
    return status, err.getvalue()


def one_error_line(err):
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("scanline: error: "), err
    return lines[0]


@contextlib.contextmanager
def within(seconds):
    """Fail (instead of hanging the run) when the body takes more than ``seconds``."""
    def alarm(signum, frame):
        raise AssertionError(f"still running after {seconds} s: it hangs")

    old = signal.signal(signal.SIGALRM, alarm)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)


# -- crashes: Beier-Neely with NaN sample points ------------------------------------------
def test_beier_neely_audit_cases_are_errors_not_crashes():
    """Each of these died with SIGSEGV (a NaN used as an index in the kernel); run in a
    child process so that a crash is a failed test, not a dead test run."""
    script = textwrap.dedent("""
        import numpy as np, scanline as sl
        img = np.zeros((8, 8), np.uint8); img[2:5] = 200
        L = [[1, 1, 6, 6]]
        calls = [
            lambda: sl.animation.beier_neely(img, img, [[-1e308, 0, 1e308, 0]],
                                             [[-1e308, 0, 1e308, 0]], 0.5),
            lambda: sl.animation.beier_neely(img, img, [[0, 0, 1e-300, 0]], L, 0.0),
            lambda: sl.animation.beier_neely(img, img, L, L, 0.5, b=1e308),
            lambda: sl.animation.beier_neely(img, img, L, L, 0.5, p=1e308),
            lambda: sl.animation.beier_neely(img, img, L, L, 0.5, a=1e-320, b=100),
            lambda: sl.animation.beier_neely(img, img, [[0, 0, 2, 0]], [[2, 0, 0, 0]], 0.5),
            lambda: sl.animation.warp(img, [[0, 0, 1e-300, 0]], L),
        ]
        for call in calls:
            try:
                call()
                print("drawn")
            except sl.ScanlineError as error:
                print(type(error).__name__, str(error).split(":")[0])
    """)
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                          timeout=600)
    assert done.returncode == 0, (done.returncode, done.stderr[-2000:])
    lines = done.stdout.strip().splitlines()
    assert len(lines) == 7 and all(line.startswith("ArgumentValueError") for line in lines), \
        lines


@pytest.mark.parametrize("kwargs, words", [
    ({"lines_a": [[-1e308, 0, 1e308, 0]], "lines_b": [[-1e308, 0, 1e308, 0]]},
     r"lines_a\[0\] .* beyond the device coordinate range"),
    ({"lines_a": [[0, 0, 1e-300, 0]], "t": 0.0}, r"lines_a\[0\] has length 1e-300, too short"),
    ({"b": 1e308}, r"b=1e\+308.*weights .* would range"),
    ({"p": 1e308}, r"p=1e\+308.*weights"),
    ({"a": 1e-320, "b": 100}, r"a=.*b=100.*to 1e\+\d+ \(on a line\)"),
    ({"lines_a": [[0, 0, 2, 0]], "lines_b": [[2, 0, 0, 0]]},
     r"at t=0.5 feature line 0 .* shrinks to length 0"),
    ({"t": [0.2, 0.5]}, "t must be one fraction"),
])
def test_beier_neely_refuses_degenerate_lines_and_overflowing_weights(kwargs, words):
    img = np.zeros((8, 8), np.uint8)
    args = {"lines_a": [[1, 1, 6, 6]], "lines_b": [[1, 1, 6, 6]], "t": 0.5}
    args.update(kwargs)
    with pytest.raises(sl.ScanlineError, match=words):
        sl.animation.beier_neely(img, img, **args)


def test_beier_neely_still_takes_strong_but_representable_weights():
    img = (np.arange(64, dtype=np.uint8) * 3).reshape(8, 8)
    same = sl.animation.beier_neely(img, img, [[1, 1, 6, 6]], [[1, 1, 6, 6]], 0.5, a=1, b=100,
                                    p=1)
    np.testing.assert_array_equal(same, img)        # identical lines: a cross-dissolve


def _guarded(h, w, c):
    big = np.full((h + 4, w, c), 77, np.uint8)
    return big[2:-2], big


def _table(rows, value):
    from scanline._kernels.morph import COLUMNS

    table = np.full((rows, COLUMNS), value)
    return table


@pytest.mark.boundscheck
@pytest.mark.parametrize("twin", [False, True])
@pytest.mark.parametrize("fill", [np.nan, np.inf, -np.inf, 1e308, -1e308, 0.0])
def test_morph_kernel_clamps_every_sample_point(fill, twin):
    """The kernel on tables the API would refuse (NaN, infinite, huge, zero lengths):
    every pixel is written with a level, nothing outside ``out`` changes, nothing
    outside the sources is read (NUMBA_BOUNDSCHECK=1 turns that into an IndexError).
    The Python twin (first calls run as Python) computes the same."""
    from scanline._kernels._jit import python
    from scanline._kernels.morph import field_morph

    kernel = python(field_morph) if twin else field_morph
    src = np.arange(5 * 7 * 3, dtype=np.uint8).reshape(5, 7, 3)
    out, big = _guarded(5, 7, 3)
    with np.errstate(all="ignore"):            # (as the kernels' error model)
        kernel(src, src, _table(2, fill), 0.5, 1.0, 2.0, out)
    assert (big[:2] == 77).all() and (big[-2:] == 77).all()
    assert out.dtype == np.uint8


@pytest.mark.boundscheck
def test_morph_kernel_draws_nothing_it_cannot_read():
    """Tables too narrow, empty sources, sources smaller than ``out``: nothing read
    outside, nothing written outside."""
    from scanline._kernels.morph import COLUMNS, field_morph

    out, big = _guarded(4, 4, 4)
    field_morph(np.zeros((4, 4, 4), np.uint8), np.zeros((4, 4, 4), np.uint8),
                np.zeros((1, COLUMNS - 5)), 0.5, 1.0, 2.0, out)
    field_morph(np.zeros((0, 4, 4), np.uint8), np.zeros((4, 0, 4), np.uint8),
                np.zeros((1, COLUMNS)), 0.5, 1.0, 2.0, out)
    small = np.full((2, 3, 1), 9, np.uint8)
    table = np.zeros((1, COLUMNS))
    table[0, 2:4] = (1.0, 0.0)                     # Q = (1, 0)
    table[0, 4:6] = (1.0, 0.0)                     # d
    table[0, 6:9] = 1.0                            # 1/|d|^2, 1/|d|, |d|^p
    table[0, 10] = 1.0                             # n = (0, 1)
    field_morph(small, small, table, 0.5, 1.0, 2.0, out)
    assert (big[:2] == 77).all() and (big[-2:] == 77).all()
    assert (out[:, :, 0] == 9).all()               # one channel read, clamped to 2 x 3


# -- hangs: a scheduler that accepts and never speaks ---------------------------------------
@pytest.fixture
def silent_server():
    """A TCP server on this machine that accepts connections and never says a word."""
    server = socket.socket()
    server.bind(("127.0.0.1", 0))
    server.listen(16)
    held, stop = [], threading.Event()

    def accept():
        server.settimeout(0.2)
        while not stop.is_set():
            try:
                held.append(server.accept()[0])
            except OSError:
                continue

    thread = threading.Thread(target=accept, daemon=True)
    thread.start()
    yield f"tcp://127.0.0.1:{server.getsockname()[1]}", held
    stop.set()
    thread.join()
    for conn in held:
        conn.close()
    server.close()


def test_a_silent_scheduler_is_refused_within_the_timeout(tmp_path, monkeypatch,
                                                          silent_server):
    """Before: Animation.save(client=ADDRESS) waited past 60 s (Dask's handshake has no
    timeout).  Now the connection and the first exchange are bounded together."""
    peer("distributed")
    address, held = silent_server
    monkeypatch.setattr(render_module, "CONNECT_TIMEOUT", 1.0)
    with within(30):
        with pytest.raises(sl.animation.SchedulerUnreachable,
                           match=r"did not answer as a Dask scheduler within 1 s"):
            Animation(frame, frames=3, fps=3).save(tmp_path / "x.gif", client=address)
    assert held                                   # it did connect: the handshake hung
    assert os.listdir(tmp_path) == []


def test_animate_with_a_silent_scheduler_is_one_error_line(tmp_path, monkeypatch,
                                                           silent_server):
    peer("distributed")
    address, _ = silent_server
    monkeypatch.setattr(render_module, "CONNECT_TIMEOUT", 1.0)
    out = tmp_path / "out.gif"
    with within(60):
        status, err = run_cli(["animate", "--example", "bouncing_ball", "-o", str(out),
                               "--scheduler", address])
    assert status == 2
    assert "within 1 s" in one_error_line(err)
    assert os.listdir(tmp_path) == []


def test_a_scheduler_given_by_address_renders(tmp_path):
    """The probe and the client of a real scheduler's address (tcp): the same file."""
    distributed = peer("distributed")
    anim = Animation(frame, frames=6, fps=6)
    anim.save(tmp_path / "serial.gif")
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=False,
                                  protocol="tcp", dashboard_address=None) as cluster:
        anim.save(tmp_path / "dask.gif", client=cluster.scheduler_address)
    assert (tmp_path / "serial.gif").read_bytes() == (tmp_path / "dask.gif").read_bytes()


MALFORMED = ["", "nope", "tcp://", "tcp://:", "tcp://host:notaport", "tcp://127.0.0.1:99999",
             "tcp://127.0.0.1:-1", "foo://x:1", "tcp://[::1", "\x00", "tls://127.0.0.1:1",
             "ucx://1.2.3.4:5", "inproc://x", "tcp://a b:1", "tcp://h:0"]


@pytest.mark.parametrize("address", MALFORMED)
def test_malformed_scheduler_addresses_are_one_clear_error(tmp_path, address, capfd):
    """Before: tracebacks (an AssertionError, TypeErrors of Dask's UCX and TLS
    connectors), 10 s waits for ports out of range, and Dask's 'Exception ignored in
    Client.__del__' on stderr.  Now: refused before anything connects."""
    with within(20):
        with pytest.raises(sl.ScanlineError, match="(tcp://HOST:PORT|the port must be|"
                                                   "tcp:// addresses only)"):
            Animation(frame, frames=2, fps=2).save(tmp_path / "x.gif", client=address)
        status, err = run_cli(["animate", "--example", "bouncing_ball", "-o",
                               str(tmp_path / "y.gif"), "--scheduler", address])
    assert status == 2 and "--scheduler" in one_error_line(err)
    assert "Traceback" not in capfd.readouterr().err
    assert os.listdir(tmp_path) == []


def test_scheduler_addresses_written_out():
    assert render_module.scheduler_address("10.0.0.5:8786") == "tcp://10.0.0.5:8786"
    assert render_module.scheduler_address("tcp://[::1]:8786") == "tcp://[::1]:8786"
    assert render_module.scheduler_address("TCP://host-1.example.org:01") == \
        "tcp://host-1.example.org:1"


# -- unbounded memory ---------------------------------------------------------------------------
class Stop(Exception):
    pass


def _stop_at(n, calls):
    def render(i):
        calls.append(i)
        if i == n:
            raise Stop
        return frame(i)
    return render


def test_a_billion_frame_mp4_streams(tmp_path):
    """Before: about 4 GB (the list of 10**9 frame numbers and their chunks) before
    frame 3.  Now the frames come from a range, chunk by chunk."""
    peer("av")
    frame(0)                                      # (compiled before the count starts)
    Animation(frame, frames=2, fps=25).save(tmp_path / "warm.mp4")
    os.remove(tmp_path / "warm.mp4")
    calls = []
    tracemalloc.start()
    try:
        with pytest.raises(Stop):
            Animation(_stop_at(3, calls), frames=10**9, fps=25).save(tmp_path / "a.mp4")
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert calls == [0, 1, 2, 3]
    assert peak < 64 * 2**20, f"{peak / 2**20:.0f} MiB"
    assert os.listdir(tmp_path) == []


def test_a_billion_frames_stream_through_worker_processes():
    frame(0)
    tracemalloc.start()
    try:
        images = Animation(frame, frames=10**9, fps=25).images(jobs=2)
        got = [next(images) for _ in range(5)]
        images.close()
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert [g.size for g in got] == [(8, 6)] * 5
    assert peak < 64 * 2**20, f"{peak / 2**20:.0f} MiB"


@pytest.mark.parametrize("ext", ["gif", "png", "webp"])
def test_formats_that_hold_every_frame_check_the_budget_first(tmp_path, ext, monkeypatch):
    """GIF, APNG and WebP writers keep every frame: refused after the first frame,
    naming ``frames``, instead of collecting 10**9 frames (WebP: its 32-bit times)."""
    calls = []
    anim = Animation(_stop_at(10**9, calls), frames=10**9, fps=25)
    with pytest.raises(sl.ScanlineError, match="^frames: "):
        anim.save(tmp_path / f"a.{ext}")
    assert len(calls) <= 1 and os.listdir(tmp_path) == []
    monkeypatch.setenv("SCANLINE_MEMORY_LIMIT", "1M")
    with pytest.raises(MemoryBudgetError, match="frames: 5000 frames of 8 x 6"):
        Animation(frame, frames=5000, fps=25).save(tmp_path / "b.gif")
    assert os.listdir(tmp_path) == []


def test_in_betweens_motion_path_tables_and_runs_check_the_budget(monkeypatch):
    with pytest.raises(MemoryBudgetError, match="^n: 1000000000 in-between times"):
        sl.animation.inbetween_times(0, 1, 10**9)
    with pytest.raises(MemoryBudgetError, match="^n: "):
        sl.animation.inbetween_times(0, 1, 2**1100)
    bezier = sl.curves.Bezier([(0, 0), (0, 100), (100, 100), (100, 0)])
    tracemalloc.start()
    try:
        with pytest.raises(MemoryBudgetError, match="^intervals: "):
            sl.animation.MotionPath(bezier, intervals=10**9)
        assert tracemalloc.get_traced_memory()[1] < 2**20
    finally:
        tracemalloc.stop()
    with pytest.raises(MemoryBudgetError, match="^duration: "):
        sl.animation.Particles([(0, 0)]).run(1e6, 1e-6)
    with pytest.raises(sl.ScanlineError, match="duration / dt"):
        sl.animation.Particles([(0, 0)]).run(1e300, 1e-300)
    monkeypatch.setenv("SCANLINE_MEMORY_LIMIT", "64M")
    timeline = sl.animation.Timeline({"x": sl.animation.KeyFrames([0, 1], [0, 1])}, fps=1000,
                                     duration=1e6)
    assert len(timeline) == 10**9 and timeline.time(10**9 - 1) == pytest.approx(999999.999)
    with pytest.raises(MemoryBudgetError, match="^duration: "):
        timeline.times()


def test_motion_path_tables_in_pieces_are_the_same():
    bezier = sl.curves.Bezier([(0, 0), (0, 100), (100, 100), (100, 0)])
    from scanline.animation import paths

    whole = sl.animation.MotionPath(bezier, intervals=3000)
    old = paths.CHUNK
    try:
        paths.CHUNK = 7
        pieces = sl.animation.MotionPath(bezier, intervals=3000)
    finally:
        paths.CHUNK = old
    np.testing.assert_allclose(pieces._cumulative, whole._cumulative, rtol=1e-14)
    assert pieces.length == pytest.approx(whole.length, rel=1e-14)


def test_contact_sheet_panel_is_checked_before_anything_is_drawn(monkeypatch):
    tracemalloc.start()
    try:
        with pytest.raises(sl.ScanlineError, match="panel 100000x100000"):
            sl.animation.contact_sheet([frame(0)], ["a"], panel=(100000, 100000))
        assert tracemalloc.get_traced_memory()[1] < 2**20
    finally:
        tracemalloc.stop()
    monkeypatch.setenv("SCANLINE_MEMORY_LIMIT", "8M")
    with pytest.raises(MemoryBudgetError, match="^panel: a .* contact sheet"):
        sl.animation.contact_sheet([frame(0)] * 8, ["a"] * 8, panel=(1000, 1000))
    sheet = sl.animation.contact_sheet([frame(0)] * 2, ["a", "b"], panel=(40, 30))
    assert sheet.size == (16 + 2 * 56, 16 + 30 + 22 + 16)


def test_storyboard_panel_is_refused_before_the_sheet_is_made(tmp_path, monkeypatch):
    """Before: --panel 16384x16384 made a 16416 x 16438 sheet (with its copy, 1.6 GB)
    and then failed or wrote a file no one can open."""
    out = tmp_path / "board.png"
    tracemalloc.start()
    try:
        status, err = run_cli(["storyboard", "--example", "bouncing_ball", "-o", str(out),
                               "--panel", "16384x16384"])
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert status == 2 and "--panel 16384x16384" in one_error_line(err)
    assert peak < 64 * 2**20 and os.listdir(tmp_path) == []
    monkeypatch.setenv("SCANLINE_MEMORY_LIMIT", "16M")
    status, err = run_cli(["storyboard", "--example", "bouncing_ball", "-o", str(out),
                           "--panel", "2000x1500"])
    assert status == 2 and one_error_line(err).startswith("scanline: error: --panel: ")
    assert os.listdir(tmp_path) == []


def _long_scene(tmp_path, duration):
    with open(EXAMPLE_SCENE) as f:
        text = f.read().replace("duration = 3", f"duration = {duration}")
    path = tmp_path / "long.toml"
    path.write_text(text)
    return path


def test_a_scene_of_a_million_seconds_is_refused_for_gif_and_streams_otherwise(tmp_path):
    scene = _long_scene(tmp_path, "1e6")
    out = tmp_path / "out"
    out.mkdir()
    status, err = run_cli(["animate", str(scene), "-o", str(out / "long.gif")])
    assert status == 2 and "--frames: 12000000 frames" in one_error_line(err)
    assert os.listdir(out) == []
    status, err = run_cli(["animate", str(scene), "-o", str(out / "long.png"),
                           "--frames", "0:3"])
    assert status == 0, err
    status, err = run_cli(["storyboard", str(scene), "-o", str(out / "board.png")])
    assert status == 0, err
    assert sorted(os.listdir(out)) == ["board.png", "long.png"]


def test_write_frames_of_a_billion_frames_is_refused_up_front(tmp_path):
    with pytest.raises(MemoryBudgetError, match="^frames: the names of 1000000000"):
        Animation(frame, frames=10**9, fps=25).write_frames(tmp_path / "f")
    assert os.listdir(tmp_path) == []


# -- raw errors -------------------------------------------------------------------------------
def _scene_with_track(target, values):
    with open(EXAMPLE_SCENE) as f:
        import tomllib

        data = tomllib.loads(f.read())
    data["animation"]["tracks"].insert(0, {"target": target, "keys": [
        {"time": 0, "value": values[0]}, {"time": 1, "value": values[1]}]})
    return json.dumps(data)


@pytest.mark.parametrize("target, values", [
    ("segments[ball].name", ["red", "blue"]),
    ("segments[ball].name", [1, 2]),
    ("segments[ball].primitives[0].type", ["red", "blue"]),
    ("segments[ball].primitives[0].fill", [0, 1]),
    ("segments[ground].viewport", ["red", "blue"]),
])
def test_tracks_at_names_and_flags_are_scene_errors(target, values):
    """Before: StopIteration (the name animated away, then not found)."""
    with pytest.raises(SceneError, match="target"):
        loads_animated(_scene_with_track(target, values), format="json")


def test_morph_and_path_targets_are_checked_too():
    with open(EXAMPLE_SCENE) as f:
        text = f.read()
    bad = text.replace('target = "segments[blob].primitives[0].points"',
                       'target = "segments[blob].name"')
    with pytest.raises(SceneError, match="names or picks a part of the scene"):
        loads_animated(bad)


@pytest.mark.parametrize("fps", [1e-300, 1e300, 1e-6, 0.0, -1.0, math.nan, math.inf])
def test_frame_rates_out_of_range_are_errors(tmp_path, fps):
    """Before: OverflowError, ZeroDivisionError, ValueError and RuntimeError from the
    writers (fps = 1e-300 overflowed a GIF's delay, made MP4's time base 1/0)."""
    with pytest.raises(sl.ScanlineError, match="fps"):
        Animation(frame, frames=3, fps=fps)
    with pytest.raises(sl.ScanlineError, match="fps"):
        sl.animation.Timeline(fps=fps)
    status, err = run_cli(["animate", "--example", "bouncing_ball", "-o",
                           str(tmp_path / "x.gif"), "--fps", repr(fps)])
    assert status == 2 and "--fps" in one_error_line(err)
    assert os.listdir(tmp_path) == []


def test_slow_frame_rates_within_range_are_written(tmp_path):
    with pytest.raises(sl.ScanlineError, match="too slow for GIF"):
        Animation(frame, frames=2, fps=0.001).save(tmp_path / "a.gif")
    Animation(frame, frames=2, fps=1 / 600).save(tmp_path / "a.gif")
    Animation(frame, frames=2, fps=0.001).save(tmp_path / "a.png")
    assert sorted(os.listdir(tmp_path)) == ["a.gif", "a.png"]


HUGE = 2**1100


@pytest.mark.parametrize("call", [
    lambda: sl.animation.ease("linear", HUGE),
    lambda: sl.animation.morph([(0, 0), (4, 0), (0, 3)], [(0, 0), (4, 0), (4, 4)], HUGE),
    lambda: sl.animation.equalize([(0, 0), (4, 0), (0, HUGE)], [(0, 0), (4, 0), (4, 4)]),
    lambda: sl.animation.equalize([(0, 0), (4, 0), (0, 3)], [(0, 0), (4, 0), (4, 4)],
                                  closed=np.array([1, 0])),
    lambda: sl.animation.KeyFrames([0, HUGE], [0, 1]),
    lambda: sl.animation.KeyFrames([0, 1, 2], [0, 1, 0], "cardinal", tension="x"),
    lambda: sl.animation.KeyFrames([0, 1], [0, 1]).segment(np.array(["a"])),
    lambda: sl.animation.KeyFrames([0, 1], [0, 1]).segment([None]),
    lambda: sl.animation.Timeline([1, 2]),
    lambda: sl.animation.Timeline(fps=4).time(HUGE),
    lambda: sl.animation.MotionPath([(0, 0), (1, HUGE)]),
    lambda: sl.animation.MotionPath([(0, 0), (1, 1)], arc_length=np.array([1, 1])),
    lambda: sl.animation.MotionPath([(0, 0), (1, 1)]).transform([0.1, 0.2]),
    lambda: sl.animation.MotionPath([(0, 0), (1, 1)]).progress("x"),
    lambda: sl.animation.bouncing_ball("x"),
    lambda: sl.animation.bouncing_ball(-1e300, damping=1.0),
    lambda: sl.animation.ballistic(1.0, "ab", (0, 0)),
    lambda: sl.animation.ballistic(1e300, (0, 0), (1e300, 0)),
    lambda: sl.animation.Chain([1, 1], base="xy"),
    lambda: sl.animation.Chain([1, 1], limits=[[0, 1], [2]]),
    lambda: sl.animation.Chain([1, 1]).forward([0, HUGE]),
    lambda: sl.animation.Chain([1, 1]).inverse({"a": 1}),
    lambda: sl.animation.Chain([1, 1]).inverse((1, 1), strict=np.array([1, 0])),
    lambda: sl.animation.Chain([1, 1]).follow(["ab"]),
    lambda: sl.animation.Gravity(["x", 1]),
    lambda: sl.animation.Spring([(0, 1.5)], 1.0),
    lambda: sl.animation.Spring([0, 1], 1.0, anchors=5.0),
    lambda: sl.animation.Particles([(0, 0)], masses="heavy"),
    lambda: sl.animation.Particles([(0, 0)], forces=5),
    lambda: sl.animation.Particles([(0, 0)], obstacles=[object()]),
    lambda: sl.animation.Particles([(0, 0)]).accelerations(x=[[1, 2, 3]]),
    lambda: sl.animation.Particles([(0, 0)], forces=[
        sl.animation.Force(lambda t, x, v: x, lambda x: "x")]).energy(),
    lambda: sl.animation.Plane((0, "a"), (0, 1)),
    lambda: sl.animation.beier_neely([[1, 2], [3]], [[1, 2], [3]], [[0, 0, 1, 1]],
                                     [[0, 0, 1, 1]], 0.5),
    lambda: Animation(frame, frames=2, fps=2).images(progress=np.array([1, 0])),
    lambda: Animation(frame, frames=2, fps=2).images(frames=5),
    lambda: Animation(frame, frames=2, fps=2).images(frames=(0, 1, 2)),
    lambda: Animation(frame, frames=2, fps=2).images(frames=slice(0, 2, 0)),
    lambda: Animation(frame, frames=2**40, fps=2),
    lambda: Animation(frame, frames=2, fps=2, loop=10**6),
    lambda: Animation(frame, frames=2, fps=2).save(5),
    lambda: sl.animation.contact_sheet([frame(0)], ["a"], panel=5),
    lambda: sl.animation.contact_sheet([frame(0)], [5]),
    lambda: sl.animation.contact_sheet([np.zeros((0, 4), np.uint8)], ["a"]),
])
def test_raw_errors_found_by_fuzzing_are_scanline_errors(call, tmp_path, monkeypatch):
    """Each of these raised numpy's or Python's own error (OverflowError, TypeError,
    ValueError, AttributeError, ZeroDivisionError, StopIteration) before."""
    monkeypatch.chdir(tmp_path)
    with pytest.raises(sl.ScanlineError):
        out = call()
        if hasattr(out, "__next__"):
            next(out)


# -- accepted bad input -------------------------------------------------------------------------
@pytest.mark.parametrize("pattern, words", [
    ("../../x-{:05d}.png", "names a folder"),
    ("sub/x-{:05d}.png", "names a folder"),
    ("/tmp/x-{:05d}.png", "names a folder"),
    ("frame.png", "has 0 fields"),
    ("{}-{}.png", "has 2 fields"),
    ("{:1>5d}.png", "the field must be the frame number"),
    ("{:x}.png", "the field must be the frame number"),
    ("{!r}.png", "the field must be the frame number"),
    ("{name}.png", "the field must be the frame number"),
    ("{:05d}.txt", "frame files must be"),
    (5, "pattern must be a string"),
])
def test_write_frames_refuses_patterns_that_escape_or_overwrite(tmp_path, pattern, words):
    """Before: '../../x-{:05d}.png' wrote outside the folder and 'frame.png' wrote every
    frame over one file.  Nothing is written, not even the folder."""
    folder = tmp_path / "a" / "b" / "frames"
    with pytest.raises(sl.ScanlineError, match=words):
        Animation(frame, frames=3, fps=3).write_frames(folder, pattern=pattern)
    assert os.listdir(tmp_path) == []


def test_write_frames_takes_plain_patterns(tmp_path):
    paths = Animation(frame, frames=3, fps=3).write_frames(tmp_path / "f", pattern="{}.png")
    assert [os.path.basename(p) for p in paths] == ["0.png", "1.png", "2.png"]
    paths = Animation(frame, frames=2, fps=3).write_frames(tmp_path / "g", pattern="s{0:4}.bmp")
    assert [os.path.basename(p) for p in paths] == ["s   0.bmp", "s   1.bmp"]


def test_jobs_are_capped_at_a_few_per_core(tmp_path, monkeypatch):
    """Before: jobs=10**9 forked a worker per frame.  Now refused before any process
    starts, with the limit in the message."""
    most = render_module.max_jobs()
    assert most == render_module.JOBS_PER_CORE * render_module.cores()
    started = []
    monkeypatch.setattr(render_module, "_processes", lambda *a: started.append(a))
    with pytest.raises(sl.ScanlineError, match=rf"jobs=1000000000 .* at most {most} "):
        Animation(frame, frames=100, fps=10).save(tmp_path / "x.gif", jobs=10**9)
    with pytest.raises(sl.ScanlineError, match=f"jobs={most + 1} "):
        list(Animation(frame, frames=100, fps=10).images(jobs=most + 1))
    status, err = run_cli(["animate", "--example", "bouncing_ball", "-o",
                           str(tmp_path / "y.gif"), "--jobs", "1000000000"])
    assert status == 2 and f"--jobs=1000000000 " in one_error_line(err)
    assert started == [] and os.listdir(tmp_path) == []


def test_a_stream_closed_before_it_starts_stops_its_workers():
    """Closing the frames of a render that never started still stops the pool (a
    generator closed before its first step runs no finally clause)."""
    import multiprocessing

    images = Animation(frame, frames=50, fps=10).images(jobs=2)
    assert len(multiprocessing.active_children()) >= 2
    images.close()
    assert multiprocessing.active_children() == []
