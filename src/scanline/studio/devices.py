"""The display-device page's simulations: the studio's demo scene on a raster-scan
display (a mode "P" frame buffer, so that its bit planes and color table can be
shown) and on a random-scan display (its display file, with extra lines to show the
refresh cycle growing), from :mod:`scanline.display.crt`."""

import functools
import io

import numpy as np

import scanline as sl

from .. import _validate as v
from ..display.crt import RandomScan, RasterScan, bit_planes
from ..errors import ArgumentValueError
from .workstation import _scene

SIZE = 256
MAX_EXTRA_LINES = 5000


def _display_file(extra=0):
    df = sl.DisplayFile()
    df.set_viewing(window=(0, -5, 40, 35), keep_aspect=True)
    _scene(df)
    if extra:
        rng = np.random.default_rng(extra)
        df.create_segment("extra lines")
        for a in rng.uniform((2, -3), (38, 33), (extra, 2)):   # inside the window
            df.polyline([a, a + rng.uniform(-2, 2, 2)], color="cyan")
        df.close_segment()
    return df


@functools.lru_cache(maxsize=1)
def frame_buffer():
    """The demo scene on a SIZE x SIZE mode "P" frame buffer."""
    fb = sl.FrameBuffer(SIZE, SIZE, mode="P", background="midnightblue")
    _display_file().draw(fb)
    return fb


def _flag(name, text):
    if text in ("1", "true", "yes", "on"):
        return True
    if text in ("0", "false", "no", "off", "", None):
        return False
    raise ArgumentValueError(f"{name} must be true or false, got {text!r}")


@functools.lru_cache(maxsize=16)
def raster(rate=60.0, interlaced=False, persistence=0.02):
    return RasterScan(frame_buffer(), refresh_rate=rate, interlaced=interlaced,
                      persistence=persistence)


@functools.lru_cache(maxsize=16)
def random(lines=0, speed=2e5, persistence=0.02):
    return RandomScan(_display_file(lines), SIZE, SIZE, writing_speed=speed,
                      persistence=persistence)


def simulation(kind, query):
    """The simulation a query string asks for (validated by the simulation's own
    checks)."""
    persistence = v.number("persistence", float(query.get("persistence", 0.02)))
    if kind == "raster":
        return raster(v.number("rate", float(query.get("rate", 60))),
                      _flag("interlaced", query.get("interlaced", "0")), persistence)
    lines = int(query.get("lines", 0))
    if not 0 <= lines <= MAX_EXTRA_LINES:
        raise ArgumentValueError(f"lines={lines} must be between 0 and {MAX_EXTRA_LINES}")
    return random(lines, v.number("speed", float(query.get("speed", 2e5))), persistence)


def info(sim):
    """What the page prints beside the screen."""
    out = {"period": sim.period, "refresh_rate": 1 / sim.period, "size": [sim.width, sim.height]}
    if isinstance(sim, RasterScan):
        fb = frame_buffer()
        counts = np.bincount(fb.to_array().ravel(), minlength=len(fb.color_table))
        out.update(line_time=sim.line_time, field_time=sim.field_time,
                   interlaced=sim.interlaced, planes=8,
                   color_table=[{"index": i, "rgb": c, "pixels": int(n)} for i, (c, n) in
                                enumerate(zip(fb.color_table.tolist(), counts.tolist()))])
    else:
        out.update(drawing_time=sim.drawing_time, commands=len(sim.commands),
                   lines=sum(1 for c in sim.commands if c[0] == "LINE"),
                   listing=[" ".join(str(round(x, 1)) if isinstance(x, float) else str(x)
                                     for x in c) for c in sim.commands[:40]])
    return out


def frame(sim, t):
    """The screen at time ``t`` as raw RGBA bytes, and the beam."""
    rgb = sim.screen(t)
    rgba = np.concatenate([rgb, np.full(rgb.shape[:2] + (1,), 255, np.uint8)], axis=2)
    return rgba.tobytes(), sim.beam(t)


def plane_png(k):
    """Bit plane ``k`` of the frame buffer as a PNG (black 0, white 1)."""
    from PIL import Image

    planes = bit_planes(frame_buffer())
    if not 0 <= k < len(planes):
        raise ArgumentValueError(f"plane={k} must be between 0 and {len(planes) - 1}")
    out = io.BytesIO()
    Image.fromarray((planes[k] * 255).astype(np.uint8)).save(out, format="PNG")
    return out.getvalue()
