"""The color CRTs, the direct-view storage tube and the flat panels (Hearn & Baker
2-1; the notes' chapter 1, Q.5 and the quiz's "selective or part erasing of screen
is not possible in DVST"): each fact of the notes worked in a test."""

import numpy as np
import pytest

import scanline as sl
from scanline.display import crt
from scanline.display.color_crt import (PENETRATION_COLORS, PENETRATION_VOLTAGES,
                                        BeamPenetration, ShadowMask, penetration_colors)
from scanline.display.flat_panel import LCD, NEON, PlasmaPanel
from scanline.display.storage_tube import STORED, SelectiveEraseError, StorageTube
from scanline.errors import ScanlineError

RED, GREEN, BLUE = (255, 0, 0), (0, 255, 0), (0, 0, 255)


def display_file(colors=("red",)):
    df = sl.DisplayFile()
    df.set_viewing(window=(0, 0, 100, 100))
    for i, color in enumerate(colors):
        df.create_segment(f"s{i}")
        y = 10 + 80 * i / max(len(colors) - 1, 1)
        df.polyline([(10, y), (90, y)], color=color)
        df.close_segment()
    return df


# -- beam penetration ------------------------------------------------------------------------
def test_beam_penetration_has_four_colors_from_red_to_green():
    assert list(PENETRATION_COLORS) == ["red", "orange", "yellow", "green"]
    volts = [PENETRATION_VOLTAGES[c] for c in PENETRATION_COLORS]
    assert volts == sorted(volts) and len(set(volts)) == 4      # faster beam, deeper layer
    for name, (r, g, b) in PENETRATION_COLORS.items():
        assert b == 0                                          # two layers: red and green only
    assert PENETRATION_COLORS["red"] == RED and PENETRATION_COLORS["green"] == GREEN
    # intermediate speeds: combinations of red and green light
    for mid in ("orange", "yellow"):
        r, g, _ = PENETRATION_COLORS[mid]
        assert r > 0 and g > 0


def test_beam_penetration_screen_shows_only_the_four_colors():
    colors = ["red", "darkorange", "gold", "lime", "cyan", "navy", "white"]
    scan = BeamPenetration(display_file(colors), 101, 101, writing_speed=1e5, settle_time=0.0,
                           persistence=10.0)
    img = scan.screen(scan.drawing_time).reshape(-1, 3).astype(float)
    lit = img[img.max(axis=1) > 0]
    assert len(lit) > 100
    # each lit spot is a palette color scaled by its glow
    palette = np.array(list(PENETRATION_COLORS.values()), float)
    unit = lit / lit.max(axis=1, keepdims=True)
    pal_unit = palette / palette.max(axis=1, keepdims=True)
    d = np.abs(unit[:, None, :] - pal_unit[None]).max(axis=2).min(axis=1)
    assert d.max() < 0.02
    assert [name for _, name in scan.voltages] == [
        "red", "orange", "yellow", "green", "green", "off", "yellow"]


def test_frame_buffer_quantized_to_the_palette_matches_a_brute_force_nearest():
    rng = np.random.default_rng(7)
    a = rng.integers(0, 256, (12, 9, 3), dtype=np.uint8)
    out = penetration_colors(sl.FrameBuffer.from_array(a)).to_array()
    choices = [(0, 0, 0)] + list(PENETRATION_COLORS.values())
    for (i, j), _ in np.ndenumerate(a[..., 0]):
        p = a[i, j].astype(int)
        best = min(choices, key=lambda c: sum((int(x) - y) ** 2 for x, y in zip(p, c)))
        assert tuple(out[i, j]) == best


# -- shadow mask ------------------------------------------------------------------------------
def one_pixel(color, arrangement, dots=12, **kw):
    tube = ShadowMask(sl.FrameBuffer(1, 1, background=color), arrangement=arrangement,
                      dots=dots, persistence=1e3, **kw)
    return tube, tube.screen(tube.hits[0, 0]).astype(int)


@pytest.mark.parametrize("arrangement", ["delta", "in-line"])
def test_three_dots_per_pixel_each_its_own_color(arrangement):
    tube, img = one_pixel("white", arrangement)
    for k in range(3):
        dot = img[tube.mask == k]
        assert len(dot) > 0 and (dot[:, k] == 255).all()
        assert (np.delete(dot, k, axis=1) == 0).all()           # only its own phosphor
    assert (img[tube.mask == -1] == 0).all()                    # the mask between dots
    # white: all three dots with equal intensity
    assert len({int(img[tube.mask == k][:, k].sum()) for k in range(3)}) <= 3


def test_in_line_triads_lie_along_the_scan_line():
    tube, _ = one_pixel("white", "in-line")
    c = tube.triad_centers()
    assert np.ptp(c[:, 1]) == pytest.approx(0)                  # one scan line
    assert c[0, 0] < c[1, 0] < c[2, 0]                           # red, green, blue along it


def test_delta_triads_form_a_triangle():
    tube, _ = one_pixel("white", "delta")
    c = tube.triad_centers()
    (ux, uy), (wx, wy) = c[1] - c[0], c[2] - c[0]
    area = 0.5 * abs(ux * wy - uy * wx)
    sides = [np.linalg.norm(c[i] - c[j]) for i, j in ((0, 1), (1, 2), (2, 0))]
    assert area > 0.1 * tube.dots ** 2 / 4                       # not on one line
    assert max(sides) / min(sides) < 1.2                        # nearly equilateral


@pytest.mark.parametrize("color, dots_lit", [("yellow", {0, 1}), ("magenta", {0, 2}),
                                             ("cyan", {1, 2}), ("blue", {2}),
                                             ("white", {0, 1, 2}), ("black", set())])
@pytest.mark.parametrize("arrangement", ["delta", "in-line"])
def test_colors_from_the_three_beams(color, dots_lit, arrangement):
    tube, img = one_pixel(color, arrangement)
    lit = {k for k in range(3) if img[tube.mask == k][:, k].max() > 0}
    assert lit == dots_lit


@pytest.mark.parametrize("arrangement", ["delta", "in-line"])
def test_misconvergence_shows_color_fringes(arrangement):
    fb = sl.FrameBuffer(9, 3, background="black")
    fb.to_array()
    a = np.zeros((3, 9, 3), np.uint8)
    a[:, 3:6] = 255                                              # a white bar, columns 3-5
    fb = sl.FrameBuffer.from_array(a)

    def lit_channels(tube):
        img = tube.screen(tube.period * 0.999)
        d = tube.dots
        return [{k for k in range(3) if img[d:2 * d, col * d:(col + 1) * d][..., k].max() > 0}
                for col in range(9)]

    exact = lit_channels(ShadowMask(fb, arrangement=arrangement, persistence=1e3))
    assert exact == [set()] * 3 + [{0, 1, 2}] * 3 + [set()] * 3
    off = lit_channels(ShadowMask(fb, arrangement=arrangement, persistence=1e3,
                                  misconvergence=1.0))
    # red lands one pixel to the left, blue one to the right: a red fringe on the
    # left edge, a blue one on the right, green where it was
    assert off[2] == {0} and off[6] == {2}
    assert off[3] == {0, 1} and off[5] == {1, 2}
    assert off[4] == {0, 1, 2}


def test_shadow_mask_is_refreshed_like_a_raster_scan():
    tube = ShadowMask(sl.FrameBuffer(8, 6, background="white"), dots=4, persistence=0.002)
    raster = crt.RasterScan(sl.FrameBuffer(8, 6, background="white"), persistence=0.002)
    np.testing.assert_array_equal(tube.hits, raster.hits)
    assert tube.beam(0.004) == raster.beam(0.004)
    # a just-refreshed row glows, one refreshed long ago has faded
    t = tube.hits[5, 7] + 1e-5
    img = tube.screen(t)
    assert img[5 * 4:6 * 4].max() > 200 and img[:4].max() < 10


# -- direct-view storage tube -----------------------------------------------------------------
def test_storage_tube_needs_no_refresh():
    df = display_file(["white", "white"])
    tube = StorageTube(df, 101, 101, writing_speed=1e4, settle_time=0.0, hold=5.0)
    done = tube.phases[0][2]
    first = tube.screen(done + 1e-6)
    later = tube.screen(done + 4.9)                              # seconds later: unchanged
    np.testing.assert_array_equal(first, later)
    lit = first.reshape(-1, 3)
    lit = lit[lit.max(axis=1) > 0]
    assert len(lit) > 100 and (lit == STORED).all()              # full intensity, no decay
    # a refresh CRT with the same lines has faded long before then
    scan = crt.RandomScan(df, 101, 101, writing_speed=1e4, settle_time=0.0, persistence=0.02,
                          max_rate=1e-3)
    assert scan.screen(done + 4.9).max() == 0
    assert tube.beam(done + 1.0)[2] == "off"                    # the writing gun is idle


def test_storage_tube_writes_the_picture_once_in_beam_order():
    tube = StorageTube(display_file(["white", "white"]), 101, 101, writing_speed=1e4,
                       settle_time=0.0)
    mid = tube.screen(tube.phases[0][2] / 2)
    rows_lit = {r for r in range(101) if mid[r].max() > 0}
    assert rows_lit == {100 - 10}                                # the first line only (y = 10)


def test_removing_a_segment_erases_the_whole_screen_and_redraws():
    tube = StorageTube(display_file(["white", "white"]), 101, 101, writing_speed=1e4,
                       settle_time=0.0, hold=1.0, remove="s1", erase_time=0.5)
    names = [p[0] for p in tube.phases]
    assert names == ["writing", "holding", "erasing", "rewriting", "holding"]
    _, start, end = tube.phases[2]
    flash = tube.screen(start + 0.01)
    assert (flash > 0).all()                                     # the whole screen lights
    assert len(np.unique(flash.reshape(-1, 3), axis=0)) == 1
    before = tube.screen(tube.phases[1][1] + 0.5)
    after = tube.screen(tube.phases[4][1] + 0.5)
    rows = lambda img: {r for r in range(101) if img[r].max() > 0}    # noqa: E731
    assert rows(before) == {90, 10} and rows(after) == {90}      # s1 (y = 90, row 10) gone


def test_selective_erase_is_impossible():
    tube = StorageTube(display_file(["white"]), 101, 101)
    with pytest.raises(SelectiveEraseError, match="whole screen"):
        tube.erase_segment("s0")
    assert issubclass(SelectiveEraseError, ScanlineError)
    with pytest.raises(ScanlineError, match="no segment"):
        StorageTube(display_file(["white"]), 101, 101, remove="nope")


# -- plasma panel -----------------------------------------------------------------------------
def test_plasma_cells_are_addressed_row_by_row_at_conductor_intersections():
    fb = sl.FrameBuffer(5, 3, background="white")
    panel = PlasmaPanel(fb, refresh_rate=50, dots=1)
    times = (np.arange(15) + 0.5) * panel.cell_time
    order = [panel.conductors(t) for t in times]
    assert order == [(r, c) for r in range(3) for c in range(5)]   # each intersection once
    assert panel.cell_time * 15 == pytest.approx(panel.period)
    # the cell just fired glows at full intensity in neon orange; the beam is there
    t = panel.hits[1, 2] + 1e-9
    row, col = panel.conductors(t)
    assert (row, col) == (1, 2)
    img = panel.screen(t)
    assert tuple(img[row, col]) == pytest.approx(NEON, abs=3)
    x, y, state = panel.beam(t)
    assert (x, y, state) == (col, 2 - row, "firing")


def test_plasma_cells_are_on_or_off_and_fade_without_refresh():
    a = np.zeros((2, 4, 3), np.uint8)
    a[:, :2] = 255
    panel = PlasmaPanel(sl.FrameBuffer.from_array(a), persistence=0.001, dots=3)
    assert panel.on.tolist() == [[True, True, False, False]] * 2
    img = panel.screen(panel.hits[1, 1] + 1e-9)
    assert img[:, 6:].max() == 0                                 # off cells never glow
    assert img[:2, :2].max() < 20                                # fired 4 cells ago: faded
    assert tuple(img[3, 3]) == NEON                              # the cell just fired
    assert (img[2::3] == 0).all() and (img[:, 2::3] == 0).all()   # gaps between the cells


# -- LCD ------------------------------------------------------------------------------------
def test_lcd_refreshes_one_row_at_a_time_every_column_at_once():
    fb = sl.FrameBuffer(6, 4, background="white")
    lcd = LCD(fb, refresh_rate=50, response_time=1e-4, dots=1)
    assert lcd.line_time == pytest.approx(0.005)
    t = 2 * lcd.line_time + 0.5 * lcd.line_time                  # row 2 selected
    assert lcd.selected_row(t) == 2 and lcd.beam(t) == (-0.5, 1.0, "row select")
    img = lcd.screen(t)[..., 0]
    assert (img[:2] == 255).all() and (img[3] == 0).all()         # done rows, rows still to come
    assert len(set(img[2].tolist())) == 1 and img[2, 0] > 200     # the whole row together


def test_lcd_holds_between_refreshes_and_turns_with_its_response_time():
    lcd = LCD(sl.FrameBuffer(2, 2, background="white"), refresh_rate=50, response_time=0.002,
              dots=1)
    # one response time after its selection, a cell has moved 1 - 1/e of the way
    assert lcd.screen(0.002)[0, 0, 0] == pytest.approx(255 * (1 - np.exp(-1)), abs=1)
    a, b = lcd.screen(0.05), lcd.screen(0.059)                   # later cycles: no change
    np.testing.assert_array_equal(a, b)
    flip = LCD(sl.FrameBuffer(2, 2, background="white"), refresh_rate=50,
               response_time=1e-5, alternate=True, dots=1)
    assert flip.screen(0.0099)[0, 0, 0] == 255 and flip.screen(0.0299)[0, 0, 0] == 0


# -- one interface -----------------------------------------------------------------------------
@pytest.mark.parametrize("make", [
    lambda: BeamPenetration(display_file(["gold"]), 40, 40),
    lambda: ShadowMask(sl.FrameBuffer(6, 4, background="red"), dots=3),
    lambda: StorageTube(display_file(["white", "red"]), 40, 40, remove="s0"),
    lambda: PlasmaPanel(sl.FrameBuffer(6, 4, background="white"), dots=2),
    lambda: LCD(sl.FrameBuffer(6, 4, background="white"), dots=2)],
    ids=["penetration", "shadow-mask", "storage", "plasma", "lcd"])
def test_every_device_gives_frames_and_a_gif(make, tmp_path):
    sim = make()
    frames = sim.frames(frames_per_refresh=6, scale=2)
    assert len(frames) == 6 and all(f.dtype == np.uint8 and f.ndim == 3 for f in frames)
    assert frames[0].shape[:2] == (sim.height * sim.dots * 2, sim.width * sim.dots * 2)
    sim.save(tmp_path / "d.gif", frames_per_refresh=4)
    from PIL import Image

    assert Image.open(tmp_path / "d.gif").n_frames >= 2
    assert crt.__getattr__(type(sim).__name__) is type(sim)


@pytest.mark.parametrize("make", [
    lambda: ShadowMask(sl.FrameBuffer(4, 4), arrangement="trinitron"),
    lambda: ShadowMask(sl.FrameBuffer(4, 4), dots=2),
    lambda: ShadowMask(sl.FrameBuffer(4, 4), dots=17),
    lambda: ShadowMask(sl.FrameBuffer(4, 4), misconvergence=float("nan")),
    lambda: ShadowMask(sl.FrameBuffer(4, 4), misconvergence=[(1, 2)]),
    lambda: ShadowMask(sl.FrameBuffer(1000, 1000), dots=8),
    lambda: PlasmaPanel(sl.FrameBuffer(4, 4), threshold=0),
    lambda: PlasmaPanel("fb"),
    lambda: LCD(sl.FrameBuffer(4, 4), previous=sl.FrameBuffer(5, 4)),
    lambda: LCD(sl.FrameBuffer(4, 4), response_time=-1),
    lambda: LCD(sl.FrameBuffer(4, 4), dots=0),
    lambda: StorageTube(display_file(), 40, 40, hold=0),
    lambda: StorageTube(display_file(), 40, 40, erase_time=float("inf"))])
def test_bad_arguments_are_refused_clearly(make):
    with pytest.raises(ScanlineError):
        make()
