"""The refresh-CRT simulations: the raster scan's beam, retraces, interlace and
refresh rate; the random scan's cycle; phosphor persistence; frames and GIFs."""

import math

from pathlib import Path

import numpy as np
import pytest
from PIL import Image

import scanline as sl
from scanline.display.crt import RandomScan, RasterScan, bit_planes, glow
from scanline.errors import ArgumentTypeError, ArgumentValueError


def picture(w=16, h=10):
    fb = sl.FrameBuffer(w, h, mode="RGB", background=(200, 100, 50))
    sl.draw.line(fb, 0, 0, w - 1, h - 1, color="white")
    return fb


def test_raster_visits_every_pixel_once_per_refresh_in_scan_order():
    scan = RasterScan(picture(), refresh_rate=50, horizontal_retrace=0.25, vertical_retrace=0.1)
    hits = scan.hits
    assert scan.period == pytest.approx(0.02)
    assert (hits >= 0).all() and (hits < scan.period).all()
    order = np.argsort(hits, axis=None, kind="stable")
    assert (order == np.arange(hits.size)).all()          # row after row from the top, left to right
    # a line's pixels take (1 - horizontal retrace) of the line time
    assert hits[0, -1] - hits[0, 0] == pytest.approx(0.75 * scan.line_time * 15 / 16)
    assert scan.line_time == pytest.approx(0.02 * 0.9 / 10)


def test_interlaced_fields_take_half_the_period_each():
    scan = RasterScan(picture(8, 6), refresh_rate=30, interlaced=True, vertical_retrace=0.1)
    even, odd = scan.hits[0::2], scan.hits[1::2]
    half = scan.period / 2
    assert (even < half).all() and (odd >= half).all()
    assert scan.line_time == pytest.approx(half * 0.9 / 3)
    assert [scan.beam(t)[1] for t in (0.0, scan.line_time, half, half + scan.line_time)] == [
        5.0, 3.0, 4.0, 2.0]                                 # device y of rows 0, 2, 1, 3


def test_beam_states_and_retrace_paths():
    scan = RasterScan(picture(10, 4), refresh_rate=100, horizontal_retrace=0.2, vertical_retrace=0.2)
    lt = scan.line_time
    x, y, state = scan.beam(0.5 * lt)
    assert state == "drawing" and y == 3.0 and x == pytest.approx(0.5 / 0.8 * 10 - 0.5)
    x, y, state = scan.beam(0.9 * lt)                        # halfway back to the left
    assert state == "horizontal retrace" and x == pytest.approx(4.5) and y == pytest.approx(2.5)
    x, y, state = scan.beam(4 * lt + 0.5 * (scan.period - 4 * lt))
    assert state == "vertical retrace" and x == pytest.approx(4.5) and y == pytest.approx(1.5)
    later = scan.beam(scan.period + 0.5 * lt)
    assert later[:2] == pytest.approx(scan.beam(0.5 * lt)[:2]) and later[2] == "drawing"


def test_persistence_is_the_time_to_a_tenth():
    fb = picture()
    scan = RasterScan(fb, refresh_rate=60, persistence=0.004)
    pixels = np.asarray(fb.to_pil().convert("RGB"), np.float64)
    r, c = 3, 5
    t = scan.hits[r, c] + 0.004
    assert scan.screen(t)[r, c] == pytest.approx(np.rint(pixels[r, c] / 10), abs=1)
    just = scan.screen(scan.hits[r, c] + 1e-9)
    assert (just[r, c] == pixels[r, c]).all()
    assert (scan.screen(0.0)[5:] == 0).all()                 # not yet visited: dark
    assert glow(np.inf, 1.0) == 0.0 and glow(0.0, 1.0) == 1.0 and glow(2.0, 1.0) == pytest.approx(0.01)


def test_frames_gif_and_beam_marker(tmp_path):
    scan = RasterScan(picture(), refresh_rate=60)
    frames = scan.frames(frames_per_refresh=6, refreshes=2, scale=3)
    assert len(frames) == 12 and frames[0].shape == (30, 48, 3) and frames[0].dtype == np.uint8
    out = tmp_path / "raster.gif"
    scan.save(out, frames_per_refresh=6, refreshes=2, scale=3, fps=10)
    with Image.open(out) as gif:
        assert gif.n_frames == 12 and gif.size == (48, 30) and gif.info["duration"] == 100
    with pytest.raises(ArgumentValueError, match="frames"):
        scan.frames(frames_per_refresh=1000, refreshes=3)
    with pytest.raises(ArgumentValueError, match="scale"):
        scan.frames(scale=100)


def vector_scene(n):
    df = sl.DisplayFile()
    df.set_viewing(window=(0, 0, 100, 100))
    df.create_segment("lines")
    for i in range(n):
        df.polyline([(5, 1 + i % 98), (95, 1 + i % 98)])
    df.close_segment()
    return df


def test_random_scan_cycle_is_the_sum_of_its_strokes_and_jumps():
    df = vector_scene(10)
    scan = RandomScan(df, 101, 101, writing_speed=1e4, jump_speed=1e5, settle_time=1e-6)
    device = sl.display.VectorDevice(101, 101)
    sl.display.interpret(df, device)
    beam, expected = (0.0, 100.0), 0.0
    for cmd in device.commands:
        if cmd[0] == "COLOR":
            continue
        d = math.hypot(cmd[1] - beam[0], cmd[2] - beam[1])
        expected += 1e-6 + d / (1e4 if cmd[0] == "LINE" else 1e5)
        beam = cmd[1:]
    assert scan.drawing_time == pytest.approx(expected)
    assert scan.period == pytest.approx(max(expected, 1 / 60))


def test_random_scan_refresh_grows_with_lines_and_is_held_at_max_rate():
    periods = [RandomScan(vector_scene(n), 101, 101, writing_speed=5e4).period
               for n in (1, 5, 100, 400)]
    assert periods[0] == periods[1] == pytest.approx(1 / 60)      # short cycles wait
    assert periods[2] < periods[3]
    assert periods[3] / periods[2] == pytest.approx(4, rel=0.05)   # grows with the line count


def test_random_scan_lights_what_the_vector_device_draws():
    df = vector_scene(5)
    scan = RandomScan(df, 101, 101, persistence=1e9)
    img = scan.screen(scan.period * 0.999)
    lit = {(x, 100 - r) for r, x in zip(*np.nonzero(img.max(axis=2)))}
    fb = sl.FrameBuffer(101, 101, mode="L")
    df.draw(fb)
    drawn = {(x, 100 - r) for r, x in zip(*np.nonzero(fb.to_array()))}
    assert lit == drawn
    x, y, state = scan.beam(scan.drawing_time / 2)
    assert state in ("drawing", "moving") and 0 <= x <= 100


def test_bit_planes_rebuild_the_values():
    a = np.array([[0, 1, 2, 3], [128, 255, 77, 6]], np.uint8)
    planes = bit_planes(sl.FrameBuffer.from_array(a))
    assert planes.shape == (8, 2, 4)
    assert (sum(planes[k].astype(int) << k for k in range(8)) == a).all()
    with pytest.raises(ArgumentValueError, match="mode"):
        bit_planes(sl.FrameBuffer(4, 4, mode="RGB"))


@pytest.mark.parametrize("kwargs, error, text", [
    ({"refresh_rate": 0}, ArgumentValueError, "refresh_rate"),
    ({"refresh_rate": float("nan")}, ArgumentValueError, "refresh_rate"),
    ({"persistence": -1}, ArgumentValueError, "persistence"),
    ({"horizontal_retrace": 1}, ArgumentValueError, "horizontal_retrace"),
    ({"interlaced": "yes"}, ArgumentTypeError, "interlaced"),
])
def test_bad_raster_parameters(kwargs, error, text):
    with pytest.raises(error, match=text):
        RasterScan(picture(), **kwargs)


def test_bad_random_parameters():
    with pytest.raises(ArgumentValueError, match="writing_speed"):
        RandomScan(vector_scene(1), 10, 10, writing_speed=0)
    with pytest.raises(ArgumentValueError, match="pixels"):
        RandomScan(vector_scene(1), 5000, 5000)
    with pytest.raises(ArgumentTypeError, match="fb"):
        RasterScan("picture")


def test_simulate_command_writes_gifs(tmp_path):
    from scanline.cli import main

    scene = str(Path(__file__).parents[2] / "examples" / "scenes" / "rotation.toml")
    for kind in ("raster", "random"):
        out = tmp_path / f"{kind}.gif"
        assert main(["simulate", kind, scene, "-o", str(out), "--frames", "4",
                     "--refreshes", "1"]) == 0
        with Image.open(out) as gif:
            assert gif.n_frames == 4
    assert main(["simulate", "raster", scene, "-o", str(tmp_path / "x.png")]) == 2
    assert not (tmp_path / "x.png").exists()
