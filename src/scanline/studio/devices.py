"""The display-device page's simulations: the studio's demo scene on a raster-scan
display (a mode "P" frame buffer, so that its bit planes and color table can be
shown) and on a random-scan display (its display file, with extra lines to show the
refresh cycle growing), from :mod:`scanline.display.crt`; and on the color CRTs
(beam penetration, shadow mask), the direct-view storage tube and the flat panels
(plasma, LCD) of :mod:`scanline.display.color_crt`, :mod:`~scanline.display.storage_tube`
and :mod:`~scanline.display.flat_panel`.  ``KINDS`` lists the devices; each takes
its parameters from the query string (checked by the simulation's own checks)."""

from __future__ import annotations

import functools
import io
from typing import Any, Literal, Mapping, Optional

import numpy as np

import scanline as sl

from .. import _validate as v
from ..display.color_crt import BeamPenetration, ShadowMask
from ..display.crt import Beam, RandomScan, RasterScan, _Simulation, bit_planes
from ..display.flat_panel import LCD, PlasmaPanel
from ..display.storage_tube import StorageTube
from ..errors import ArgumentValueError
from .workstation import _scene

SIZE = 256
MAX_EXTRA_LINES = 5000
#: The devices of the page (the ``kind`` of /api/devices/{kind}/...).
KINDS = ("raster", "random", "penetration", "shadow-mask", "storage", "plasma", "lcd")
#: The matrix and triad displays show a smaller frame buffer, each pixel a cell of
#: several screen pixels: SMALL x SMALL pixels of DOTS x DOTS.
SMALL, DOTS = 64, 4
MASK_DOTS = 6


def _display_file(extra: int = 0) -> sl.DisplayFile:
    df = sl.DisplayFile()
    df.set_viewing(window=(0, -5, 40, 35), keep_aspect=True)
    _scene(df)
    # the scene's label is black, for the workstation's white page: on this page's
    # dark screen it is drawn in white
    df.delete_segment("label")
    df.create_segment("label", priority=2)
    df.text((3, 25), "SCANLINE", height=2.5, font="stroke", color="white")
    df.close_segment()
    if extra:
        rng = np.random.default_rng(extra)
        df.create_segment("extra lines")
        for a in rng.uniform((2, -3), (38, 33), (extra, 2)):   # inside the window
            df.polyline([a, a + rng.uniform(-2, 2, 2)], color="cyan")
        df.close_segment()
    return df


@functools.lru_cache(maxsize=4)
def frame_buffer(size: int = SIZE) -> sl.FrameBuffer:
    """The demo scene on a size x size mode "P" frame buffer."""
    fb = sl.FrameBuffer(size, size, mode="P", background="midnightblue")
    _display_file().draw(fb)
    return fb


def _flag(name: str, text: Optional[str]) -> bool:
    if text in ("1", "true", "yes", "on"):
        return True
    if text in ("0", "false", "no", "off", "", None):
        return False
    raise ArgumentValueError(f"{name} must be true or false, got {text!r}")


@functools.lru_cache(maxsize=16)
def raster(rate: float = 60.0, interlaced: bool = False, persistence: float = 0.02
           ) -> RasterScan:
    return RasterScan(frame_buffer(), refresh_rate=rate, interlaced=interlaced,
                      persistence=persistence)


@functools.lru_cache(maxsize=16)
def random(lines: int = 0, speed: float = 2e5, persistence: float = 0.02) -> RandomScan:
    return RandomScan(_display_file(lines), SIZE, SIZE, writing_speed=speed,
                      persistence=persistence)


@functools.lru_cache(maxsize=16)
def penetration(lines: int = 0, speed: float = 2e5, persistence: float = 0.02
                ) -> BeamPenetration:
    return BeamPenetration(_display_file(lines), SIZE, SIZE, writing_speed=speed,
                           persistence=persistence)


@functools.lru_cache(maxsize=16)
def shadow_mask(arrangement: Literal["delta", "in-line"] = "delta", misconvergence: float = 0.0,
                rate: float = 60.0, persistence: float = 0.02) -> ShadowMask:
    return ShadowMask(frame_buffer(SIZE // MASK_DOTS), arrangement=arrangement,
                      dots=MASK_DOTS, misconvergence=misconvergence, refresh_rate=rate,
                      persistence=persistence)


@functools.lru_cache(maxsize=16)
def storage(remove: Optional[str] = None, speed: float = 1e5) -> StorageTube:
    return StorageTube(_display_file(), SIZE, SIZE, writing_speed=speed, hold=0.05,
                       remove=remove, erase_time=0.02)


@functools.lru_cache(maxsize=16)
def plasma(rate: float = 60.0, persistence: float = 0.02) -> PlasmaPanel:
    return PlasmaPanel(frame_buffer(SMALL), refresh_rate=rate, persistence=persistence,
                       threshold=60, dots=DOTS)


@functools.lru_cache(maxsize=16)
def lcd(rate: float = 60.0, response: float = 0.004) -> LCD:
    return LCD(frame_buffer(SMALL), refresh_rate=rate, response_time=response,
               alternate=True, dots=DOTS)


def _number(query: Mapping[str, str], name: str, default: float) -> float:
    try:
        return v.number(name, float(query.get(name, default)))
    except ValueError as e:
        if isinstance(e, ArgumentValueError):
            raise
        raise ArgumentValueError(f"{name}={str(query.get(name))[:40]!r} must be a number") \
            from None


def simulation(kind: str, query: Mapping[str, str]) -> _Simulation:
    """The simulation a query string asks for (validated by the simulation's own
    checks)."""
    persistence = _number(query, "persistence", 0.02)
    rate = _number(query, "rate", 60)
    if kind == "raster":
        return raster(rate, _flag("interlaced", query.get("interlaced", "0")), persistence)
    if kind in ("random", "penetration"):
        lines = int(_number(query, "lines", 0))
        if not 0 <= lines <= MAX_EXTRA_LINES:
            raise ArgumentValueError(f"lines={lines} must be between 0 and {MAX_EXTRA_LINES}")
        make = random if kind == "random" else penetration
        return make(lines, _number(query, "speed", 2e5), persistence)
    if kind == "shadow-mask":
        arrangement = query.get("arrangement", "delta")
        v.choice("arrangement", arrangement, ("delta", "in-line"))
        return shadow_mask(arrangement, _number(query, "misconvergence", 0.0), rate,
                           persistence)
    if kind == "storage":
        remove = query.get("remove") or None
        if remove is not None:
            v.choice("remove", remove, [s.name for s in _display_file().segments])
        return storage(remove, _number(query, "speed", 1e5))
    if kind == "plasma":
        return plasma(rate, persistence)
    if kind == "lcd":
        return lcd(rate, _number(query, "response", 0.004))
    raise ArgumentValueError(f"no display device {kind[:40]!r}; one of {', '.join(KINDS)}")


def info(sim: _Simulation) -> dict[str, Any]:
    """What the page prints beside the screen."""
    img = sim.screen(0.0)
    out: dict[str, Any] = {"period": sim.period, "refresh_rate": 1 / sim.period,
                           "size": [sim.width, sim.height], "screen": [img.shape[1], img.shape[0]]}
    if isinstance(sim, ShadowMask):
        out.update(arrangement=sim.arrangement, dots=sim.dots, offsets=sim.offsets.tolist(),
                   triad=sim.triad_centers().tolist(), line_time=sim.line_time)
    elif isinstance(sim, RasterScan):
        fb = frame_buffer()
        counts = np.bincount(fb.to_array().ravel(), minlength=len(fb.color_table))
        planes = bit_planes(fb)
        out.update(line_time=sim.line_time, field_time=sim.field_time,
                   interlaced=sim.interlaced, planes=len(planes),
                   plane_used=[bool(p.any()) for p in planes],
                   bits_needed=max(1, (len(fb.color_table) - 1).bit_length()),
                   color_table=[{"index": i, "rgb": c, "pixels": int(n)} for i, (c, n) in
                                enumerate(zip(fb.color_table.tolist(), counts.tolist()))])
    elif isinstance(sim, RandomScan):
        out.update(drawing_time=sim.drawing_time, commands=len(sim.commands),
                   lines=sum(1 for c in sim.commands if c[0] == "LINE"),
                   listing=[" ".join(str(round(x, 1)) if isinstance(x, float) else str(x)
                                     for x in c) for c in sim.commands[:40]])
        if isinstance(sim, BeamPenetration):
            out["voltages"] = [{"kV": kv, "color": name} for kv, name in sim.voltages]
    elif isinstance(sim, StorageTube):
        out.update(phases=[{"phase": n, "start": a, "end": b} for n, a, b in sim.phases],
                   segments=[s.name for s in _display_file().segments])
    elif isinstance(sim, PlasmaPanel):
        out.update(cell_time=sim.cell_time, cells_on=int(sim.on.sum()), dots=sim.dots)
    elif isinstance(sim, LCD):
        out.update(line_time=sim.line_time, response_time=sim.response_time, dots=sim.dots)
    return out


def frame(sim: _Simulation, t: float) -> tuple[bytes, Beam]:
    """The screen at time ``t`` as raw RGBA bytes, and the beam."""
    rgb = sim.screen(t)
    rgba = np.concatenate([rgb, np.full(rgb.shape[:2] + (1,), 255, np.uint8)], axis=2)
    return rgba.tobytes(), sim.beam(t)


def plane_png(k: int) -> bytes:
    """Bit plane ``k`` of the frame buffer as a PNG (black 0, white 1)."""
    from PIL import Image

    planes = bit_planes(frame_buffer())
    if not 0 <= k < len(planes):
        raise ArgumentValueError(f"plane={k} must be between 0 and {len(planes) - 1}")
    out = io.BytesIO()
    Image.fromarray((planes[k] * 255).astype(np.uint8)).save(out, format="PNG")
    return out.getvalue()
