"""Saving animations: formats read back, timing, parallel and Dask rendering, failures."""

import io
import os
import signal
import textwrap
import time

import av
import numpy as np
import pytest
from PIL import Image

import scanline as sl
from scanline.animation import Animation
from scanline.animation import render as render_module
from tests import terminal
from tests.reference import peer


def frame(i):
    """A module-level render function (picklable for worker processes)."""
    fb = sl.FrameBuffer(64, 48, background="white")
    sl.draw.fill_circle(fb, 6 + 2 * i, 24, 5, color="crimson")
    sl.draw.line(fb, 0, i, 63, 47 - i, color="navy")
    return fb


def _frames_of(path):
    with Image.open(path) as im:
        out = []
        for k in range(im.n_frames):
            im.seek(k)
            im.load()
            out.append((np.asarray(im.convert("RGB")).copy(), im.info.get("duration")))
        return out


def test_gif_png_webp_read_back(tmp_path):
    anim = Animation(frame, frames=24, fps=24)
    truth = [np.asarray(frame(i).to_pil()) for i in range(24)]
    for ext in ("gif", "png", "webp"):
        anim.save(tmp_path / f"a.{ext}")
        got = _frames_of(tmp_path / f"a.{ext}")
        assert len(got) == 24, ext
        assert all(g.shape == (48, 64, 3) for g, _ in got)
        if ext != "gif":                             # lossless formats: exact pixels
            for (g, _), want in zip(got, truth):
                np.testing.assert_array_equal(g, want)
    durations = [d for _, d in _frames_of(tmp_path / "a.gif")]
    assert durations == [40, 40, 50, 40, 40, 40] * 4 and sum(durations) == 1000   # frame-exact
    webp = [d for _, d in _frames_of(tmp_path / "a.webp")]
    assert sum(webp) == 1000 and set(webp) == {41, 42}
    apng = [d for _, d in _frames_of(tmp_path / "a.png")]
    assert all(d == pytest.approx(1000 / 24) for d in apng)            # stored as 1/24 s


def test_mp4_read_back(tmp_path):
    Animation(frame, frames=30, fps=29.97).save(tmp_path / "a.mp4")
    with av.open(str(tmp_path / "a.mp4")) as container:
        stream = container.streams.video[0]
        decoded = list(container.decode(stream))
        assert stream.average_rate == pytest.approx(29.97)
        times = [float(f.pts * stream.time_base) for f in decoded]
    assert len(decoded) == 30 and (decoded[0].width, decoded[0].height) == (64, 48)
    np.testing.assert_allclose(times, np.arange(30) / 29.97, atol=1e-9)
    first = decoded[0].to_ndarray(format="rgb24").astype(int)
    assert np.abs(first - np.asarray(frame(0).to_pil())).mean() < 6     # CRF 18: close


def test_odd_sizes_are_padded_for_mp4(tmp_path):
    frames = [sl.FrameBuffer(15, 9, background=(10 * i, 0, 0)) for i in range(3)]
    Animation(frames, fps=10).save(tmp_path / "odd.mp4")
    with av.open(str(tmp_path / "odd.mp4")) as c:
        f = next(c.decode(c.streams.video[0]))
        assert (f.width, f.height) == (16, 10)


def test_frame_kinds_and_selection(tmp_path):
    arrays = [np.full((8, 8, 3), 40 * i, np.uint8) for i in range(5)]
    pil = [Image.fromarray(a) for a in arrays]
    files = []
    for i, im in enumerate(pil):
        files.append(tmp_path / f"f{i}.png")
        im.save(files[-1])
    for source in (arrays, pil, files, [sl.FrameBuffer.from_array(a) for a in arrays]):
        anim = Animation(source, fps=5)
        anim.save(tmp_path / "k.png", frames=(1, 4))
        got = _frames_of(tmp_path / "k.png")
        assert [int(g[0, 0, 0]) for g, _ in got] == [40, 80, 120]


def test_serial_processes_and_dask_are_byte_identical(tmp_path, monkeypatch):
    distributed = peer("distributed")
    made = []                                    # the shared files of the Dask renders
    shared_file = render_module._Slots.in_shared_file

    def recorded(count):
        slots = shared_file(count)
        made.append(slots.path)
        return slots

    monkeypatch.setattr(render_module._Slots, "in_shared_file", recorded)
    anim = Animation(frame, frames=20, fps=12)
    anim.save(tmp_path / "again.mp4")
    for ext in ("gif", "mp4"):
        anim.save(tmp_path / f"serial.{ext}")
        anim.save(tmp_path / f"jobs.{ext}", jobs=2)
        assert (tmp_path / f"serial.{ext}").read_bytes() == (tmp_path / f"jobs.{ext}").read_bytes()
    assert (tmp_path / "serial.mp4").read_bytes() == (tmp_path / "again.mp4").read_bytes()
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        anim.save(tmp_path / "dask.gif", client=client)
        assert (tmp_path / "serial.gif").read_bytes() == (tmp_path / "dask.gif").read_bytes()
        # the workers of this machine's cluster put the pixels in a shared file, which
        # is gone after the render, whole or stopped early
        if os.path.isdir("/dev/shm"):
            assert len(made) == 1 and not os.path.exists(made[0])
            images = anim.images(client=client)
            next(images)
            assert len(made) == 2 and os.path.exists(made[1])
            images.close()
            assert not os.path.exists(made[1])
        # a long film: workers write the frames, this process encodes them at the end
        paths = anim.write_frames(tmp_path / "frames", client=client)
    assert [os.path.basename(p) for p in paths] == [f"frame-{i:05d}.png" for i in range(20)]
    Animation(paths, fps=12).save(tmp_path / "from-files.gif")
    assert (tmp_path / "serial.gif").read_bytes() == (tmp_path / "from-files.gif").read_bytes()


def test_lambdas_reach_worker_processes(tmp_path):
    anim = Animation(lambda i: np.full((4, 4), 50 * i, np.uint8), frames=4, fps=4)
    anim.save(tmp_path / "a.png", jobs=2)
    assert [int(g[0, 0, 0]) for g, _ in _frames_of(tmp_path / "a.png")] == [0, 50, 100, 150]


def test_unreachable_scheduler_is_a_clear_error(tmp_path, monkeypatch):
    peer("distributed")
    monkeypatch.setattr(render_module, "CONNECT_TIMEOUT", 1.0)
    start = time.perf_counter()
    with pytest.raises(sl.animation.SchedulerUnreachable, match="tcp://127.0.0.1:9.*within 1 s"):
        Animation(frame, frames=3, fps=3).save(tmp_path / "x.gif", client="tcp://127.0.0.1:9")
    assert time.perf_counter() - start < 15
    assert os.listdir(tmp_path) == []


def _interrupt_at(n):
    def render(i):
        if i == n:
            raise KeyboardInterrupt
        return frame(i)
    return render


def test_errors_leave_no_file(tmp_path):
    with pytest.raises(KeyboardInterrupt):
        Animation(_interrupt_at(5), frames=10, fps=10).save(tmp_path / "x.gif")
    sizes = [sl.FrameBuffer(8, 8), sl.FrameBuffer(9, 8)]
    with pytest.raises(sl.ScanlineError, match="frame 1 is 9x8, frame 0 is 8x8"):
        Animation(sizes, fps=2).save(tmp_path / "y.mp4")
    with pytest.raises(sl.ScanlineError, match="must be a FrameBuffer"):
        Animation(lambda i: 3.5, frames=2, fps=2).save(tmp_path / "z.webp")
    # an empty frame (no rows, or no columns) is named, in every format (the fuzz found
    # Pillow's bare "cannot write empty image" escaping from a (0, 3) array)
    for k, empty in enumerate([np.zeros((0, 3), np.uint8), np.zeros((4, 0, 3), np.uint8),
                               Image.new("L", (0, 5))]):
        for ext in (".png", ".gif", ".webp"):
            with pytest.raises(sl.ScanlineError, match=r"frame 1 is empty \(\d x \d pixels\)"):
                Animation([np.zeros((4, 3), np.uint8), empty], fps=2).save(tmp_path / f"e{k}{ext}")
    assert os.listdir(tmp_path) == []


def test_ctrl_c_stops_the_workers(tmp_path):
    """Ctrl-C while the workers render: the save stops with KeyboardInterrupt, every
    worker exits and no file is left.  The test waits for states, not for times: the
    signal is sent once two workers have each started a frame (each frame leaves a
    marker with its worker's pid), and the workers' exit is polled."""
    markers = tmp_path / "markers"
    markers.mkdir()
    script = tmp_path / "slow.py"
    script.write_text(textwrap.dedent(f"""
        import os, sys, time
        import scanline as sl
        def slow(i):
            open(os.path.join({str(markers)!r}, f"{{i}}-{{os.getpid()}}"), "w").close()
            time.sleep(0.3)
            return sl.FrameBuffer(8, 8)
        if __name__ == "__main__":
            try:
                sl.animation.Animation(slow, frames=400, fps=10).save({str(tmp_path / 'out.gif')!r}, jobs=2)
            except KeyboardInterrupt:
                sys.exit(130)
    """))
    proc = terminal.python(str(script))
    try:
        workers = set()
        deadline = time.monotonic() + 120
        while len(workers) < 2 and proc.poll() is None and time.monotonic() < deadline:
            time.sleep(0.05)
            workers = {int(name.split("-")[1]) for name in os.listdir(markers)}
        assert len(workers) == 2, f"two workers did not start rendering (pids {workers})"
        proc.send_signal(signal.SIGINT)
        assert proc.wait(timeout=60) == 130
    finally:
        proc.kill()
        proc.wait()

    def running(pid):
        try:
            with open(f"/proc/{pid}/stat") as f:
                return f.read().rsplit(")", 1)[1].split()[0] != "Z"
        except FileNotFoundError:
            return False
    deadline = time.monotonic() + 30
    while any(running(pid) for pid in workers) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert not any(running(pid) for pid in workers), "a worker outlived the interrupted save"
    assert len(os.listdir(markers)) < 400                     # stopped before the end
    assert sorted(os.listdir(tmp_path)) == ["markers", "slow.py"]


def test_jupyter_display_and_progress(capsys):
    anim = Animation(frame, frames=6, fps=6)
    html = anim._repr_html_()
    assert html.startswith('<img src="data:image/png;base64,')
    import base64
    data = base64.b64decode(html.split(",", 1)[1].split('"')[0])
    with Image.open(io.BytesIO(data)) as im:
        assert im.n_frames == 6
    list(anim.images(progress=True))
    assert "scanline: 0%| | 0/6" in " ".join(capsys.readouterr().err.split())   # shown, then cleared
    list(anim.images(progress=False))
    assert capsys.readouterr().err == ""


@pytest.mark.parametrize("call,words", [
    (lambda: Animation(frame, fps=10), "needs the number of frames"),
    (lambda: Animation([], fps=10), "at least one frame"),
    (lambda: Animation(frame, frames=0, fps=10), "frames must be >= 1"),
    (lambda: Animation(frame, frames=3, fps=0), "fps must be > 0"),
    (lambda: Animation(frame, frames=3, fps=10).save("x.avi"), "no writer for '.avi'"),
    (lambda: Animation(frame, frames=3, fps=60).save("x.gif"), "too fast for GIF"),
    (lambda: Animation(frame, frames=3, fps=10).save("x.gif", frames=(2, 9)), "stop <= 3"),
    (lambda: Animation(frame, frames=3, fps=10).save("x.gif", jobs=0), "jobs must be >= 1"),
    (lambda: Animation(frame, frames=3, fps=10).save("x.gif", jobs=2, client="tcp://h:1"),
     "not both"),
    (lambda: Animation(frame, frames=3, fps=10).save("x.mp4", quality=99), "CRF"),
    (lambda: Animation(frame, frames=3, fps=10).write_frames("/tmp/f", pattern="f.png{"),
     "must format a frame number"),
])
def test_bad_input(call, words):
    with pytest.raises(sl.ScanlineError, match=words):
        call()


def mixed(i):
    """Frames of every kind, one size or another (picklable)."""
    fb = sl.FrameBuffer(40 + 8 * (i % 2), 30, mode=["RGB", "RGBA", "L", "P", "1"][i % 5],
                        background=1 if i % 5 == 4 else "white")
    sl.draw.fill_circle(fb, 5 + 3 * i, 15, 6, color=1 if i % 5 == 4 else "crimson")
    return fb if i % 3 else fb.to_pil()


def test_worker_frames_come_back_whole_through_shared_memory_or_the_pipe(monkeypatch):
    serial = [np.asarray(im) for im in Animation(mixed, frames=12, fps=4).images()]
    modes = [im.mode for im in Animation(mixed, frames=12, fps=4).images()]
    for slot in (render_module.SLOT_BYTES, 5000):     # 5000 bytes: most go by the pipe
        monkeypatch.setattr(render_module, "SLOT_BYTES", slot)
        images = list(Animation(mixed, frames=12, fps=4).images(jobs=2))
        assert [im.mode for im in images] == modes
        for a, im in zip(serial, images):
            np.testing.assert_array_equal(a, np.asarray(im))


def test_dask_workers_send_lz4_compressed_pixels(monkeypatch):
    """What a Dask worker sends: the pixels LZ4-compressed when asked (and lz4 is
    there), raw otherwise; either way the client gets the frames back exactly."""
    lz4 = peer("lz4.block")
    serial = [np.asarray(im) for im in Animation(mixed, frames=10, fps=4).images()]
    sent = render_module.render_chunk(mixed, range(10), compress=True)
    assert all(isinstance(p[0], render_module.Compressed) for p in sent)
    assert sum(len(p[0].data) for p in sent) < sum(a.nbytes for a in serial) / 4
    assert lz4.decompress(sent[0][0].data) == np.ascontiguousarray(serial[0]).tobytes()
    # frame 1 is a frame buffer: compressed from its storage, bottom row first
    assert sent[1][0].bottom_up and not sent[0][0].bottom_up
    assert lz4.decompress(sent[1][0].data) == np.ascontiguousarray(serial[1][::-1]).tobytes()
    raw = render_module.render_chunk(mixed, range(10))
    monkeypatch.setattr(render_module, "_lz4", lambda: None)        # lz4 not installed
    assert all(isinstance(p[0], np.ndarray) for p in
               render_module.render_chunk(mixed, range(10), compress=True))
    monkeypatch.undo()
    for a, packed in zip(serial, sent):
        np.testing.assert_array_equal(a, np.asarray(render_module.unpack(packed)))
    for a, packed in zip(serial, raw):
        np.testing.assert_array_equal(a, np.asarray(render_module.unpack(packed)))


_SHARED_FB = {}


def redrawn(i):
    """Every frame drawn into one frame buffer, returned each time (picklable)."""
    fb = _SHARED_FB.setdefault("fb", sl.FrameBuffer(24, 16, background="white"))
    fb.clear()
    sl.draw.fill_circle(fb, 2 + 2 * i, 8, 4, color="navy")
    return fb


def test_a_frame_buffer_drawn_again_for_each_frame_gives_every_frame(monkeypatch):
    """The pixels a worker sends are taken from the frame before the next frame is
    drawn, whether they are compressed, put in shared memory or sent by the pipe."""
    serial = [np.asarray(im) for im in Animation(redrawn, frames=8, fps=4).images()]
    assert len({a.tobytes() for a in serial}) == 8
    shipped = [render_module.render_chunk(redrawn, range(8))]
    if render_module._lz4() is not None:
        shipped.append(render_module.render_chunk(redrawn, range(8), compress=True))
    slots = render_module._Slots(1)
    shipped.append(render_module.render_chunk(redrawn, range(8), slots=slots, slot=0))
    for packed in shipped:
        images = [render_module.unpack(p, slots.memory) for p in packed]
        assert [np.asarray(im).tobytes() for im in images] == [a.tobytes() for a in serial]
    for slot in (render_module.SLOT_BYTES, 500):
        monkeypatch.setattr(render_module, "SLOT_BYTES", slot)
        images = list(Animation(redrawn, frames=8, fps=4).images(jobs=2))
        assert [np.asarray(im).tobytes() for im in images] == [a.tobytes() for a in serial]


@pytest.mark.parametrize("n, parts", [(0, 2), (1, 2), (3, 2), (200, 2), (1000, 4), (57, 1)])
def test_chunks_are_consecutive_largest_first_and_end_in_single_frames(n, parts):
    chunks = render_module.chunks(range(n), parts)
    assert [i for c in chunks for i in c] == list(range(n))
    sizes = [len(c) for c in chunks]
    assert all(1 <= s <= 16 for s in sizes)
    assert sizes == sorted(sizes, reverse=True)
    # the frames left after each chunk: at least four chunks' worth per worker
    # until the end, so that the workers finish together
    for k, s in enumerate(sizes):
        left = n - sum(sizes[:k])
        assert s == 1 or s <= left // (4 * parts)
    if n >= 4 * parts:
        assert sizes[-4 * parts + 1:] == [1] * (4 * parts - 1)


def test_workers_draw_on_one_thread_with_the_same_pixels():
    from scanline._kernels import _threads

    rng = np.random.default_rng(3)
    v = rng.uniform(0, 400, (3000, 2))

    def draw():
        fb = sl.FrameBuffer(400, 400)
        sl.draw.polygons(fb, v, counts=np.full(1000, 3), color=rng.integers(0, 255, (1000, 3)))
        return fb.to_array()

    state = rng.bit_generator.state
    many = draw()
    rng.bit_generator.state = state
    with _threads.one_thread():
        assert _threads.threads() == 1
        one = draw()
    assert _threads.threads() == __import__("numba").get_num_threads()
    np.testing.assert_array_equal(many, one)


@pytest.mark.skipif(not os.path.isdir("/dev/shm"), reason="no /dev/shm on this system")
def test_dask_workers_of_this_machine_put_the_frames_in_a_shared_file(monkeypatch):
    """A Dask worker given the client's shared file (by its path) copies the pixels
    there and sends where they are; where it cannot open the file (another machine)
    or reserve its pages (a full /dev/shm), or a frame does not fit its slot, the
    frame goes LZ4-compressed (or copied) instead.  The file is removed on close."""
    serial = [np.asarray(im) for im in Animation(mixed, frames=10, fps=4).images()]
    slots = render_module._Slots.in_shared_file(2)
    path = slots.path
    assert os.path.dirname(path) == "/dev/shm"
    assert os.path.basename(path).startswith("scanline-frames-")
    assert oct(os.stat(path).st_mode & 0o777) == "0o600"
    sent = render_module.render_chunk(mixed, range(10), compress=True, slots=path, slot=1)
    assert all(isinstance(p[0], render_module.InMemory) for p in sent)
    assert sent[0][0].offset == render_module.SLOT_BYTES              # slot 1
    for a, packed in zip(serial, sent):
        np.testing.assert_array_equal(a, np.asarray(render_module.unpack(packed, slots.memory)))
    elsewhere = render_module.render_chunk(mixed, range(3), compress=True,
                                           slots=path + "-not-here", slot=0)
    kinds = (render_module.Compressed if render_module._lz4() is not None else np.ndarray)
    assert all(isinstance(p[0], kinds) for p in elsewhere)

    def full(fd, offset, length):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, "posix_fallocate", full)
    unreserved = render_module.render_chunk(mixed, range(3), compress=False, slots=path, slot=0)
    assert all(isinstance(p[0], np.ndarray) for p in unreserved)
    monkeypatch.undo()
    monkeypatch.setattr(render_module, "SLOT_BYTES", 5000)   # most frames do not fit
    small = render_module._Slots.in_shared_file(1)
    small_path = small.path
    packed = render_module.render_chunk(mixed, range(10), slots=small.path, slot=0)
    assert {type(p[0]) for p in packed} == {render_module.InMemory, np.ndarray}
    for a, p in zip(serial, packed):
        np.testing.assert_array_equal(a, np.asarray(render_module.unpack(p, small.memory)))
    small.close()
    slots.close()
    assert not os.path.exists(path) and not os.path.exists(small_path)
