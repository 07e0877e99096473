"""The studio's workstation: a live display file driven by the logical input devices
of GKS / Hearn & Baker chapter 8, in the three input modes, with the interactive
picture-construction techniques of section 8-4.

Logical devices (Hearn & Baker 8-1): *locator* (a position, mapped back to world
coordinates by :meth:`DisplayFile.locate`), *stroke* (a sequence of positions),
*valuator* (a number: here the rotation of a segment, as its segment transformation),
*choice* (a menu item), *pick* (a segment and pick identifier, by
:meth:`DisplayFile.pick`) and *string* (typed text, placed as a text primitive).

Input modes (8-2): in *request* mode the program asks for one input of a device and
waits for the operator's trigger (here: inputs count only after a request); in
*sample* mode each input is taken at once, the device's current value; in *event*
mode inputs are queued and the program takes them one at a time (AWAIT EVENT).

Techniques (8-4): a grid with snapping, a gravity field that pulls a position onto
the nearest line within its radius, horizontal/vertical constraints, rubber-band
lines and rectangles (the page shows the band; the positions come from
:meth:`Workstation.position`), and dragging a segment (its translation).
"""

from __future__ import annotations

import collections
import io
import math
from typing import Any, Optional, Sequence

import numpy as np
from numpy.typing import NDArray

import scanline as sl

from .. import _validate as v
from ..errors import ArgumentTypeError, ArgumentValueError

WIDTH, HEIGHT = 480, 360
WINDOW = (0.0, 0.0, 40.0, 30.0)
MODES = ("request", "sample", "event")
DEVICES = ("locator", "stroke", "valuator", "choice", "pick", "string")
#: The choice device's menu (GKS choice numbers are 1-based).
MENU = ("line", "rectangle", "stroke", "text", "pick", "drag")
CONSTRAINTS = ("none", "horizontal", "vertical", "auto")
COLORS = ("navy", "darkgreen", "firebrick", "purple", "black", "darkorange")
MAX_EVENTS = 64
MAX_SEGMENTS = 200
MAX_STROKE = 2000
MAX_TEXT = 200
#: Positions (stroke and rubber-band points, text characters) the operator's segments
#: hold in all: with MAX_SEGMENTS this bounds what a picture, a pick or the gravity
#: field costs (20,000 random stroke points draw in about half a second).
MAX_POINTS = 20_000


def _scene(df: sl.DisplayFile) -> None:
    df.create_segment("house", priority=1)
    df.set_pick_identifier(1)
    df.polygon([(6, 4), (18, 4), (18, 13), (6, 13)], color="tan", edge="saddlebrown", width=2)
    df.set_pick_identifier(2)
    df.polygon([(5, 13), (19, 13), (12, 20)], color="firebrick")
    df.set_pick_identifier(3)
    df.polygon([(10.5, 4), (13.5, 4), (13.5, 9), (10.5, 9)], color="sienna")
    df.close_segment()
    df.create_segment("tree", priority=1)
    df.set_pick_identifier(1)
    df.polygon([(27.5, 4), (28.5, 4), (28.5, 9), (27.5, 9)], color="saddlebrown")
    df.set_pick_identifier(2)
    df.circle((28, 12.5), 4, color="forestgreen", fill=True)
    df.close_segment()
    df.create_segment("sun", priority=0)
    df.set_pick_identifier(1)
    df.circle((34, 25), 2.5, color="gold", fill=True)
    df.close_segment()
    df.create_segment("label", priority=2)
    df.set_pick_identifier(1)
    df.text((3, 25), "SCANLINE", height=2.5, font="stroke", color="black")
    df.close_segment()


def _point(name: str, value: object) -> tuple[float, float]:
    if not isinstance(value, (list, tuple)) or len(value) != 2:
        raise ArgumentTypeError(f"{name} must be a pair [x, y], got {v._show(value)}")
    x, y = v.number(f"{name}[0]", value[0]), v.number(f"{name}[1]", value[1])
    for c in (x, y):
        if not abs(c) <= 1e6:
            raise ArgumentValueError(f"{name}={value!r} must be finite and within +-1e6")
    return x, y


class Workstation:
    """One display file on a WIDTH x HEIGHT raster, with its input state."""

    def __init__(self) -> None:
        self.df = sl.DisplayFile(aspect=(HEIGHT - 1) / (WIDTH - 1))
        self.df.set_viewing(window=WINDOW)
        _scene(self.df)
        self.mode = "sample"
        self.requested: Optional[str] = None
        self.events: collections.deque[tuple[str, dict[str, Any]]] = collections.deque()
        self.tool = "line"
        self.grid = 1.0
        self.snap = False
        self.gravity = 0.0
        self.constraint = "none"
        self.selected: Optional[str] = None
        self.log: collections.deque[str] = collections.deque(maxlen=12)
        self.version = 0
        self._count = 0
        self._moves: dict[str, tuple[float, float]] = {}     # segment -> (tx, ty) world translation
        self._turns: dict[str, float] = {}     # segment -> degrees
        self._sizes: dict[str, int] = {}     # segment -> positions it holds (MAX_POINTS)

    # -- geometry -------------------------------------------------------------------
    @property
    def size(self) -> tuple[int, int]:
        return (WIDTH, HEIGHT)

    def world(self, x: float, y: float) -> tuple[float, float]:
        """Device -> world: the locator's inverse mapping."""
        return self.df.locate(x, y, self.size)

    def device(self, wx: float, wy: float) -> tuple[float, float]:
        """World -> device (the forward mapping), for the page's echo."""
        x, y = sl.transform.apply(self._forward(), [(wx, wy)])[0]
        return float(x), float(y)

    def _forward(self) -> NDArray[np.float64]:
        m: NDArray[np.float64] = sl.viewing.ndc_to_device(WIDTH, HEIGHT) @ self.df.normalization
        return m

    def _worlds(self, points: Sequence[tuple[float, float]]) -> list[tuple[float, ...]]:
        """Device -> world for an (N, 2) array at once (the locator's inverse mapping,
        as :meth:`world`)."""
        m = sl.transform.compose(sl.transform.inverse(self.df.normalization),
                                 sl.transform.inverse(sl.viewing.ndc_to_device(WIDTH, HEIGHT)))
        return [tuple(p) for p in sl.transform.apply(m, np.asarray(points, float)).tolist()]

    def _lines(self) -> NDArray[np.float64]:
        """Every polyline and polygon edge of the visible segments, in world
        coordinates after the segment transformations (for the gravity field)."""
        n_inv = sl.transform.inverse(self.df.normalization)
        out: list[NDArray[np.float64]] = []
        for seg in self.df.segments:
            if not seg.visible:
                continue
            m = n_inv @ seg.transformation
            for prim in seg.primitives:
                rings = ([prim.geometry["points"]] if prim.kind == "polyline"
                         else prim.geometry.get("contours", []) if prim.kind == "polygon" else [])
                for r in rings:
                    w = sl.transform.apply(m, r)
                    closed = prim.kind == "polygon" or prim.attributes.get("closed")
                    q = np.vstack([w, w[:1]]) if closed else w
                    out += [np.hstack([q[:-1], q[1:]])]
        return np.vstack(out) if out else np.zeros((0, 4))

    def position(self, x: object, y: object, anchor: object = None) -> dict[str, Any]:
        """The position an input at device (x, y) gives after the techniques: the
        gravity field (onto the nearest line within ``gravity`` device units), else
        grid snapping, then the constraint relative to ``anchor`` (device).  Returns
        the world and device positions and what was applied."""
        x, y = _point("position", (x, y))
        wx, wy = self.world(x, y)
        applied: list[str] = []
        pulled = False
        if self.gravity > 0:
            segs = self._lines()
            if len(segs):
                a, b = segs[:, :2], segs[:, 2:]
                d = b - a
                den = (d * d).sum(axis=1)
                t = np.clip(((np.array([wx, wy]) - a) * d).sum(axis=1) / np.where(den == 0, 1, den), 0, 1)
                near = a + t[:, None] * d
                dev = sl.transform.apply(self._forward(), near)
                dist = np.hypot(dev[:, 0] - x, dev[:, 1] - y)
                i = int(np.argmin(dist))
                if dist[i] <= self.gravity:
                    wx, wy = map(float, near[i])
                    pulled = True
                    applied.append("gravity")
        if self.snap and not pulled:
            wx, wy = round(wx / self.grid) * self.grid, round(wy / self.grid) * self.grid
            applied.append("grid")
        if anchor is not None and self.constraint != "none":
            ax, ay = self.world(*_point("anchor", anchor))
            if self.snap:
                ax, ay = round(ax / self.grid) * self.grid, round(ay / self.grid) * self.grid
            c = self.constraint
            if c == "auto":
                c = "horizontal" if abs(wx - ax) >= abs(wy - ay) else "vertical"
            if c == "horizontal":
                wy = ay
            else:
                wx = ax
            applied.append(c)
        dx, dy = self.device(wx, wy)
        return {"world": [wx, wy], "device": [dx, dy], "applied": applied}

    # -- settings -------------------------------------------------------------------
    def settings(self, mode: Optional[str] = None, grid: Optional[float] = None,
                 snap: Optional[bool] = None, gravity: Optional[float] = None,
                 constraint: Optional[str] = None, tool: Optional[str] = None) -> None:
        if mode is not None:
            self.mode = v.choice("mode", mode, MODES)
            self.requested = None
        if grid is not None:
            g = v.number("grid", grid)
            if not 0.25 <= g <= 10:
                raise ArgumentValueError(f"grid={g} must be between 0.25 and 10 world units")
            self.grid = g
        if snap is not None:
            if not isinstance(snap, bool):
                raise ArgumentTypeError(f"snap must be true or false, got {v._show(snap)}")
            self.snap = snap
        if gravity is not None:
            g = v.number("gravity", gravity)
            if not 0 <= g <= 50:
                raise ArgumentValueError(f"gravity={g} must be between 0 and 50 device units")
            self.gravity = g
        if constraint is not None:
            self.constraint = v.choice("constraint", constraint, CONSTRAINTS)
        if tool is not None:
            self.tool = v.choice("tool", tool, MENU)
        self.version += 1

    # -- input ----------------------------------------------------------------------
    def request(self, device: str) -> None:
        """REQUEST a device (request mode): the next input of it is taken."""
        if self.mode != "request":
            raise ArgumentValueError(f"request needs the request mode; the mode is {self.mode!r}")
        self.requested = v.choice("device", device, DEVICES)

    def input(self, device: str, value: dict[str, Any]) -> dict[str, Any]:
        """An operator's input: taken at once (sample mode, or request mode when that
        device was requested) or queued (event mode).  Returns what happened."""
        device = v.choice("device", device, DEVICES)
        if not isinstance(value, dict):
            raise ArgumentTypeError(f"value must be an object, got {v._show(value)}")
        if self.mode == "event":
            if len(self.events) >= MAX_EVENTS:
                raise ArgumentValueError(
                    f"the event queue is full ({MAX_EVENTS} events): await some first")
            self._check(device, value)
            self.events.append((device, value))
            return {"queued": True, "events": len(self.events)}
        if self.mode == "request":
            if self.requested != device:
                raise ArgumentValueError(
                    f"no request is pending for the {device}: in request mode, request the "
                    f"device first (pending: {self.requested or 'none'})")
            self.requested = None
        return {"queued": False, "result": self._apply(device, value)}

    def await_event(self) -> Optional[dict[str, Any]]:
        """AWAIT EVENT: take the oldest queued input and apply it (None if empty)."""
        if not self.events:
            return None
        device, value = self.events.popleft()
        return {"device": device, "result": self._apply(device, value)}

    def _check(self, device: str, value: dict[str, Any]) -> None:
        """Validate an input before it is queued (so a bad one is refused at once)."""
        getattr(self, "_" + device)(value, dry=True)

    def _apply(self, device: str, value: dict[str, Any]) -> dict[str, Any]:
        result: dict[str, Any] = getattr(self, "_" + device)(value, dry=False)
        self.log.appendleft(f"{device}: {result['text']}")
        self.version += 1
        return result

    def _new_name(self, kind: str) -> str:
        if len(self.df) >= MAX_SEGMENTS:
            raise ArgumentValueError(f"the display file holds {MAX_SEGMENTS} segments; delete some")
        self._count += 1
        return f"{kind}-{self._count}"

    def _room(self, n: int, argument: str) -> None:
        """Refuse ``n`` more positions past MAX_POINTS."""
        held = sum(self._sizes.values())
        if held + n > MAX_POINTS:
            raise ArgumentValueError(
                f"{argument}: {n} more positions would make {held + n}; a workstation holds "
                f"at most {MAX_POINTS}: delete some segments")

    def _color(self) -> str:
        return COLORS[self._count % len(COLORS)]

    def _locator(self, value: dict[str, Any], dry: bool) -> dict[str, Any]:
        p = self.position(*_point("value.position", value.get("position")),
                          anchor=value.get("anchor"))
        tool = value.get("tool", "point")
        tool = v.choice("value.tool", tool, ("point", "line", "rectangle"))
        if tool == "point" or value.get("anchor") is None:
            return {"world": p["world"], "text": f"world ({p['world'][0]:.3f}, {p['world'][1]:.3f})"}
        a = self.position(*_point("value.anchor", value["anchor"]))["world"]
        b = p["world"]
        size = 2 if tool == "line" else 4
        self._room(size, "value.position")
        if dry:
            return {}
        name = self._new_name(tool)
        self._sizes[name] = size
        self.df.create_segment(name, priority=3)
        pts = [a, b] if tool == "line" else [a, (b[0], a[1]), b, (a[0], b[1])]
        self.df.polyline(pts, color=self._color(), closed=tool == "rectangle", width=2)
        self.df.close_segment()
        return {"segment": name, "world": b,
                "text": f"{tool} {name} from ({a[0]:.2f}, {a[1]:.2f}) to ({b[0]:.2f}, {b[1]:.2f})"}

    def _stroke(self, value: dict[str, Any], dry: bool) -> dict[str, Any]:
        pts = value.get("points")
        if not isinstance(pts, list) or not 2 <= len(pts) <= MAX_STROKE:
            raise ArgumentValueError(
                f"value.points must be a list of 2 to {MAX_STROKE} device positions")
        world = self._worlds([_point(f"value.points[{i}]", p) for i, p in enumerate(pts)])
        self._room(len(world), "value.points")
        if dry:
            return {}
        name = self._new_name("stroke")
        self._sizes[name] = len(world)
        self.df.create_segment(name, priority=3)
        self.df.polyline(world, color=self._color(), width=2, cap="round", join="round")
        self.df.close_segment()
        return {"segment": name, "points": len(world), "text": f"{name}, {len(world)} positions"}

    def _valuator(self, value: dict[str, Any], dry: bool) -> dict[str, Any]:
        name: Any = value.get("segment")    # JSON: DisplayFile.segment checks it
        seg = self.df.segment(name)
        angle = v.number("value.angle", value.get("angle"))
        if not -360 <= angle <= 360:
            raise ArgumentValueError(f"value.angle={angle} must be between -360 and 360 degrees")
        if dry:
            return {}
        self._turns[seg.name] = angle
        self._transform(seg.name)
        return {"segment": seg.name, "angle": angle,
                "matrix": seg.transformation.tolist(), "text": f"{seg.name} turned {angle:g} degrees"}

    def _choice(self, value: dict[str, Any], dry: bool) -> dict[str, Any]:
        item = value.get("item")
        if isinstance(item, bool) or not isinstance(item, int) or not 1 <= item <= len(MENU):
            raise ArgumentValueError(
                f"value.item must be a menu number 1..{len(MENU)} ({', '.join(MENU)}), "
                f"got {v._show(item)}")
        if dry:
            return {}
        self.tool = MENU[item - 1]
        return {"item": item, "tool": self.tool, "text": f"item {item}: {self.tool}"}

    def _pick(self, value: dict[str, Any], dry: bool) -> dict[str, Any]:
        x, y = _point("value.position", value.get("position"))
        aperture = v.number("value.aperture", value.get("aperture", 3))
        got = self.df.pick(x, y, aperture, self.size)
        if dry:
            return {}
        if self.selected is not None and self.selected in self.df:
            self.df.set_highlighting(self.selected, False)
        self.selected = got.segment if got else None
        if got:
            self.df.set_highlighting(got.segment, True)
        return {"segment": got.segment if got else None, "pick_id": got.pick_id if got else None,
                "text": f"segment {got.segment!r}, pick id {got.pick_id}" if got else "nothing"}

    def _string(self, value: dict[str, Any], dry: bool) -> dict[str, Any]:
        text = value.get("text")
        if not isinstance(text, str) or not 0 < len(text) <= MAX_TEXT:
            raise ArgumentValueError(f"value.text must be a string of 1 to {MAX_TEXT} characters")
        w = self.position(*_point("value.position", value.get("position")))["world"]
        self._room(len(text), "value.text")
        if dry:
            return {}
        name = self._new_name("text")
        self._sizes[name] = len(text)
        self.df.create_segment(name, priority=3)
        self.df.text(w, text, height=1.5, font="stroke", color=self._color())
        self.df.close_segment()
        return {"segment": name, "world": w, "text": f"{name} {text!r} at ({w[0]:.2f}, {w[1]:.2f})"}

    # -- dragging ---------------------------------------------------------------------
    def drag(self, segment: str, dx: float, dy: float) -> dict[str, Any]:
        """Move a segment by the device displacement (dx, dy) (dragging, 8-4)."""
        seg = self.df.segment(segment)
        dx, dy = _point("delta", (dx, dy))
        a, b = self.world(0, 0), self.world(dx, dy)
        tx, ty = self._moves.get(seg.name, (0.0, 0.0))
        self._moves[seg.name] = (tx + b[0] - a[0], ty + b[1] - a[1])
        self._transform(seg.name)
        self.version += 1
        return {"segment": seg.name, "matrix": seg.transformation.tolist()}

    def _center(self, name: str) -> tuple[float, ...]:
        """The world center of a segment's untransformed geometry (its pivot)."""
        n_inv = sl.transform.inverse(self.df.normalization)
        pts: list[NDArray[np.float64]] = []
        for prim in self.df.segment(name).primitives:
            g = prim.geometry
            for key in ("points", "center", "anchor"):
                if key in g:
                    pts.append(np.atleast_2d(g[key]))
            pts += list(g.get("contours", []))
        w = sl.transform.apply(n_inv, np.vstack(pts))
        lo, hi = w.min(axis=0), w.max(axis=0)
        return tuple(((lo + hi) / 2).tolist())

    def _transform(self, name: str) -> None:
        """The segment transformation: rotation about its center, then the drag."""
        turn = sl.transform.rotation(math.radians(self._turns.get(name, 0.0)),
                                     pivot=self._center(name))
        move = sl.transform.translation(*self._moves.get(name, (0.0, 0.0)))
        self.df.set_transformation(name, self.df.world_transformation(
            sl.transform.compose(move, turn)))

    def delete(self, segment: str) -> None:
        name = self.df.segment(segment).name
        self.df.delete_segment(name)
        self._sizes.pop(name, None)
        if self.selected == segment:
            self.selected = None
        self.version += 1

    # -- output ---------------------------------------------------------------------
    def state(self) -> dict[str, Any]:
        return {
            "size": [WIDTH, HEIGHT], "window": list(WINDOW), "mode": self.mode,
            "requested": self.requested, "events": [d for d, _ in self.events],
            "tool": self.tool, "menu": list(MENU), "grid": self.grid, "snap": self.snap,
            "gravity": self.gravity, "constraint": self.constraint, "selected": self.selected,
            "log": list(self.log), "version": self.version,
            "segments": [{"name": s.name, "priority": s.priority, "visible": s.visible,
                          "highlighted": s.highlighted, "detectable": s.detectable,
                          "angle": self._turns.get(s.name, 0.0),
                          "matrix": np.round(s.transformation, 6).tolist(),
                          "primitives": len(s.primitives)} for s in self.df.segments],
        }

    def png(self) -> bytes:
        """The display file drawn on the workstation's raster, with the grid's points
        when snapping is on, as PNG bytes."""
        fb = sl.FrameBuffer(WIDTH, HEIGHT, mode="RGB", background="white")
        if self.snap:
            xs = np.arange(math.ceil(WINDOW[0] / self.grid), math.floor(WINDOW[2] / self.grid) + 1)
            ys = np.arange(math.ceil(WINDOW[1] / self.grid), math.floor(WINDOW[3] / self.grid) + 1)
            pts = np.array([self.device(x * self.grid, y * self.grid) for x in xs for y in ys])
            dots = np.rint(pts).astype(np.int64)
            sl.draw.lines(fb, np.hstack([dots, dots]), color=(190, 190, 210))
        self.df.draw(fb, highlight="magenta")
        out = io.BytesIO()
        fb.to_pil().save(out, format="PNG", compress_level=1)
        return out.getvalue()
