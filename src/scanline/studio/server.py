"""The studio's web application (Starlette, served by uvicorn).

Pages: ``/`` (the index), ``/explorer``, ``/devices``, ``/workstation``; their
scripts and style under ``/static``.  The JSON API:

``GET  /api/algorithms``                      the explorer's algorithms
``POST /api/explore {algorithm, args}``       the view of one case (422: the CLI's message)
``POST /api/quiz {algorithm, seed}``          quiz case ``seed``: the view and its questions
``GET  /api/devices/{kind}/info``    a simulation's timing (kind: devices.KINDS)
``GET  /api/devices/{kind}/frame?t`` the screen at time t (raw RGBA, beam in headers)
``GET  /api/devices/raster/plane/{k}.png``    a bit plane of the frame buffer
``POST /api/ws``                              a new workstation; then ``/api/ws/{id}/...``:
``GET  state``, ``GET image.png``, ``POST settings|position|request|input|await|drag|delete|close``

How the studio keeps its neighbours (and itself) safe, on one machine shared with
other work and other web pages (docs/studio.md says the same for users):

* **Expensive work runs in worker processes** (:mod:`scanline.studio.pool`): the
  explorer's traces and the device simulations.  A request past :data:`TIME_LIMIT`
  is answered 503 and its worker killed, so its CPU is free at once; at most
  ``pool.WORKERS`` run at once, a few more wait briefly, the rest are answered 503.
* **Memory per request is bounded**: the explorer estimates a case's memory from its
  sizes and refuses one over :data:`REQUEST_MEMORY` (422 naming the argument, from
  :func:`scanline.budget.check`); behind the estimates each worker's address space is
  limited.  Workstations hold at most ``workstation.MAX_SEGMENTS`` segments and
  ``workstation.MAX_POINTS`` positions, so their actions stay cheap.
* **Bodies are read in chunks** and refused (413) as soon as they pass
  :data:`MAX_BODY`, whatever Content-Length says; a body that is not a JSON object,
  nests deeper than :data:`MAX_DEPTH`, or has a field of the wrong type is 400.
* **Only the studio's own pages may act**: a POST needs ``Content-Type:
  application/json`` and an ``Origin`` equal to the studio's own (browsers send it;
  other pages cannot forge it), and an API request a browser marks
  ``Sec-Fetch-Site: cross-site`` or ``same-site`` is refused (403).  Workstations
  belong to the session (a cookie) that created them: another session gets 404 for
  them, and a session may hold :data:`MAX_WORKSTATIONS_PER_SESSION` of them (429 past
  that; 503 when the studio holds :data:`MAX_WORKSTATIONS`), never evicting another's.
* **Each workstation has its own lock**: a slow action on one delays no other.
* **Ctrl-C stops the server at once**, workers killed, also while they are busy.
* The Host header must name this machine (DNS rebinding), static files come only from
  the package's static folder, and the pages show server text with ``textContent``.
"""

import contextlib
import gc
import math
import re
import secrets
import socket
import threading
import time
from importlib import resources
from types import FrameType
from typing import Any, AsyncIterator, Awaitable, Callable, Mapping, Optional, Sequence, TypeVar

import anyio
import orjson
from starlette.applications import Starlette
from starlette.middleware import Middleware
from starlette.middleware.trustedhost import TrustedHostMiddleware
from starlette.requests import ClientDisconnect, Request
from starlette.responses import FileResponse, Response
from starlette.routing import Mount, Route
from starlette.staticfiles import StaticFiles

from ..errors import ScanlineError
from . import explorer
from .pool import Pool, PoolError
from .workstation import Workstation

#: Seconds of work a request may take before it is answered 503 and stopped.
TIME_LIMIT = 10.0
#: Bytes one explorer request may need, by the estimate of
#: :func:`scanline.studio.explorer.check_memory` (past it: 422 naming the argument).
REQUEST_MEMORY = 256 << 20
#: Workstations the studio holds in all (past it: 503).
MAX_WORKSTATIONS = 64
#: Workstations one session (one browser) may hold (past it: 429).
MAX_WORKSTATIONS_PER_SESSION = 8
#: Seconds a workstation may go unused before it is dropped.
WORKSTATION_IDLE = 3600.0
#: Largest request body, in bytes.
MAX_BODY = 1 << 20
#: Deepest nesting of lists and objects in a request body.
MAX_DEPTH = 32
#: Threads that run workstation actions at once.
WORKSTATION_THREADS = 4
#: The session cookie: which workstations a browser owns.
SESSION_COOKIE = "scanline_studio"

STATIC = resources.files("scanline.studio") / "static"
BAD = (ScanlineError, ValueError, TypeError, KeyError, explorer.BadArguments)

#: A route's handler.
Endpoint = Callable[[Request], Awaitable[Response]]
T = TypeVar("T")


class JSONResponse(Response):
    """JSON encoded by orjson: a 10,000-row table encodes in about a millisecond
    (the standard library takes ten times as long)."""

    media_type = "application/json"

    def render(self, content: Any) -> bytes:
        return orjson.dumps(content)


def _error(status: int, message: object) -> JSONResponse:
    return JSONResponse({"error": " ".join(str(message).split())}, status_code=status)


#: Set once the start-up warm-up has compiled the kernels the workstation uses.
_WARM = threading.Event()


def warm_up() -> None:
    """Compile (or load from numba's cache) what the workstation draws with; the
    explorer and the device pages warm up in their worker processes.  Workstation
    requests wait for it."""
    try:
        Workstation().png()
    finally:
        _WARM.set()


class _Fail(Exception):
    def __init__(self, status: int, message: object) -> None:
        super().__init__(message)
        self.status = status


# -- what a request must be ------------------------------------------------------------
def _origin(request: Request) -> str:
    return f"{request.url.scheme}://{request.headers.get('host', '')}".lower()


def _check_site(request: Request) -> None:
    """Refuse an API request that a browser says comes from another site's page."""
    site = request.headers.get("sec-fetch-site")
    if site is not None and site not in ("same-origin", "none"):
        raise _Fail(403, f"a request from another site's page ({site}) is refused: only "
                         f"the studio's own pages ({_origin(request)}) may use its API")


def _check_post(request: Request) -> None:
    """A POST must carry JSON and come from one of the studio's own pages."""
    media = request.headers.get("content-type", "").split(";")[0].strip().lower()
    if media != "application/json":
        raise _Fail(403, f"a POST must have Content-Type: application/json, not {media!r}")
    origin = request.headers.get("origin")
    expected = _origin(request)
    if origin is None:
        raise _Fail(403, f"a POST needs the header Origin: {expected} (the studio's pages send "
                         "it)")
    if origin.strip().lower() != expected:
        raise _Fail(403, f"a POST from the origin {origin!r} is refused: only the studio's own "
                         f"pages ({expected}) may post")


def _too_deep(data: object, limit: int) -> bool:
    stack: list[tuple[object, int]] = [(data, 1)]
    while stack:
        item, depth = stack.pop()
        if isinstance(item, (dict, list)):
            if depth > limit:
                return True
            stack.extend((v, depth + 1) for v in (item.values() if isinstance(item, dict)
                                                   else item))
    return False


async def _body(request: Request) -> dict[str, Any]:
    """The request's JSON object, read in chunks and refused as soon as it passes
    MAX_BODY (400: not a JSON object; 413: too large)."""
    declared = request.headers.get("content-length")
    if declared is not None:
        if not declared.strip().isdigit():
            raise _Fail(400, f"Content-Length {declared!r} is not a number of bytes")
        if int(declared) > MAX_BODY:
            raise _Fail(413, f"the request body is {int(declared)} bytes; at most {MAX_BODY}")
    raw = bytearray()
    try:
        async for chunk in request.stream():
            raw += chunk
            if len(raw) > MAX_BODY:
                raise _Fail(413, f"the request body is more than {MAX_BODY} bytes; at most "
                                 f"{MAX_BODY}")
    except ClientDisconnect:
        raise _Fail(400, "the client went away before sending the whole body") from None
    if not raw.strip():
        return {}
    try:
        data = orjson.loads(raw)
    except orjson.JSONDecodeError as error:
        raise _Fail(400, f"the body is not JSON (UTF-8, no NaN or Infinity): {error}") from None
    if not isinstance(data, dict):
        raise _Fail(400, f"the body must be a JSON object, not a {type(data).__name__}")
    if _too_deep(data, MAX_DEPTH):
        raise _Fail(400, f"the body nests lists and objects more than {MAX_DEPTH} deep")
    body: dict[str, Any] = data
    return body


def _kind_of(value: type) -> str:
    names: dict[type, str] = {bool: "true or false", str: "a string", list: "a list",
                              dict: "an object", float: "a number"}
    return names.get(value, value.__name__)


def _fields(data: dict[str, Any], spec: Mapping[str, type]) -> dict[str, Any]:
    """Check the types of the body's fields that ``spec`` names ({name: type}; a
    number is ``float``); None stands for a field not given.  400 names the field."""
    for name, kind in spec.items():
        value = data.get(name)
        if value is None:
            continue
        ok = (isinstance(value, (int, float)) and not isinstance(value, bool)) if kind is float \
            else isinstance(value, kind)
        if not ok:
            shown = orjson.dumps(value)[:60].decode("utf-8", "replace")
            raise _Fail(400, f"{name} must be {_kind_of(kind)}, got {shown}")
    return data


def _endpoint(fn: Endpoint, post: bool = False) -> Endpoint:
    async def wrapped(request: Request) -> Response:
        try:
            _check_site(request)
            if post:
                _check_post(request)
            return await fn(request)
        except _Fail as fail:
            return _error(fail.status, fail)
        except PoolError as fail:
            return _error(fail.status, fail)
    return wrapped


def _page(name: str) -> Endpoint:
    async def page(request: Request) -> Response:
        return FileResponse(str(STATIC / name), media_type="text/html")
    return page


# -- workstations -------------------------------------------------------------------------
class _Entry:
    """A workstation, its owner (a session), its own lock, when it was last used, and
    its last picture (version, PNG)."""

    def __init__(self, ws: Workstation, owner: str) -> None:
        self.ws, self.owner = ws, owner
        self.lock = threading.Lock()
        self.used = time.monotonic()
        self.png: tuple[Optional[int], bytes] = (None, b"")


class Workstations:
    """The workstations, by id; each belongs to the session that created it."""

    def __init__(self) -> None:
        self._items: dict[str, _Entry] = {}
        self._lock = threading.Lock()

    def __len__(self) -> int:
        return len(self._items)

    def _expire(self, now: float) -> None:
        for key, entry in list(self._items.items()):
            if now - entry.used > WORKSTATION_IDLE and not entry.lock.locked():
                del self._items[key]

    def new(self, owner: str) -> tuple[str, _Entry]:
        ws = Workstation()
        now = time.monotonic()
        with self._lock:
            self._expire(now)
            mine = sum(1 for e in self._items.values() if e.owner == owner)
            if mine >= MAX_WORKSTATIONS_PER_SESSION:
                raise _Fail(429, f"this browser has {mine} workstations open, the most one "
                                 "session may hold: close a workstation page first (unused "
                                 f"ones are dropped after {WORKSTATION_IDLE:g} s)")
            if len(self._items) >= MAX_WORKSTATIONS:
                raise _Fail(503, f"the studio holds {len(self._items)} workstations, its limit; "
                                 "try again later")
            key = secrets.token_hex(16)
            entry = self._items[key] = _Entry(ws, owner)
        return key, entry

    def get(self, key: str, owner: Optional[str]) -> _Entry:
        with self._lock:
            entry = self._items.get(key)
            if entry is None or owner is None or not secrets.compare_digest(entry.owner, owner):
                raise _Fail(404, f"no workstation {key[:40]!r} in this session (it may have "
                                 "expired): reload the page")
            entry.used = time.monotonic()
            return entry

    def close(self, key: str, owner: Optional[str]) -> None:
        entry = self.get(key, owner)
        with self._lock:
            if self._items.get(key) is entry:
                del self._items[key]


_SESSION = re.compile(r"[0-9a-f]{32}")


def _session(request: Request) -> Optional[str]:
    value = request.cookies.get(SESSION_COOKIE, "")
    return value if _SESSION.fullmatch(value) else None


#: The Host names a loopback studio answers to: a page elsewhere that rebinds its own
#: name to 127.0.0.1 (DNS rebinding) is refused.
LOOPBACK = ("127.0.0.1", "localhost", "::1", "[::1]")

_WS_FIELDS: dict[str, dict[str, type]] = {
    "settings": {"mode": str, "grid": float, "snap": bool, "gravity": float,
                 "constraint": str, "tool": str},
    "position": {"position": list, "anchor": list},
    "request": {"device": str},
    "input": {"device": str, "value": dict},
    "await": {},
    "drag": {"segment": str, "delta": list},
    "delete": {"segment": str},
    "close": {},
}


def _given(data: dict[str, Any], name: str) -> Any:
    """A body field as given, None when absent (a JSON value the workstation checks and
    names when it is wrong)."""
    return data.get(name)


def create_app(allowed_hosts: Sequence[str] = LOOPBACK, workers: Optional[int] = None,
               address_space: Optional[int] = None) -> Starlette:
    """The studio's Starlette application, answering requests whose Host is one of
    ``allowed_hosts`` (``("*",)``: any); ``workers`` and ``address_space`` size its
    worker pool (default: :data:`scanline.studio.pool.WORKERS`, ``ADDRESS_SPACE``).
    The pool is ``app.state.pool``, the workstations ``app.state.workstations``."""
    sessions = Workstations()
    pool = Pool(workers, address_space)
    limiter: list[anyio.CapacityLimiter] = []

    async def on_workstation(entry: _Entry, fn: Callable[[Workstation], T]) -> T:
        """``fn(ws)`` in a thread, holding the workstation's own lock; bad input: 400
        (a wrong type) or 422."""
        if not _WARM.is_set():
            await anyio.to_thread.run_sync(_WARM.wait)
        if not limiter:
            limiter.append(anyio.CapacityLimiter(WORKSTATION_THREADS))

        def locked() -> T:
            if not entry.lock.acquire(timeout=TIME_LIMIT):
                raise _Fail(503, "the workstation is busy with another request; try again")
            try:
                return fn(entry.ws)
            finally:
                entry.lock.release()

        try:
            return await anyio.to_thread.run_sync(locked, limiter=limiter[0])
        except _Fail:
            raise
        except TypeError as error:
            raise _Fail(400, error) from None
        except BAD as error:
            message = error.args[0] if isinstance(error, KeyError) and error.args else error
            raise _Fail(422, message) from None

    async def in_worker(task: str, *args: Any) -> Any:
        return await pool.run(task, args, TIME_LIMIT)

    async def algorithms(request: Request) -> Response:
        return JSONResponse(explorer.catalog())

    async def explore(request: Request) -> Response:
        data = _fields(await _body(request), {"algorithm": str, "args": list})
        algorithm, args = data.get("algorithm"), data.get("args", [])
        if algorithm is None:
            raise _Fail(400, "algorithm must be a string: one of " + ", ".join(explorer._SUBS))
        if args is None or not all(isinstance(a, str) for a in args):
            raise _Fail(400, "args must be a list of strings, as on the command line")
        body = await in_worker("explore", algorithm, args, REQUEST_MEMORY)
        return Response(body, media_type="application/json")

    async def quiz(request: Request) -> Response:
        data = _fields(await _body(request), {"algorithm": str, "seed": int})
        algorithm, seed = data.get("algorithm"), data.get("seed")
        if algorithm is None or seed is None:
            raise _Fail(400, "algorithm (a string) and seed (an integer, the case number) "
                        "are both needed")
        return Response(await in_worker("quiz", algorithm, seed), media_type="application/json")

    def _kind(request: Request) -> str:
        kind: str = request.path_params["kind"]
        from .devices import KINDS

        if kind not in KINDS:
            raise _Fail(404, f"no display device {kind[:40]!r}: one of {', '.join(KINDS)}")
        return kind

    async def device_info(request: Request) -> Response:
        kind = _kind(request)
        return Response(await in_worker("device_info", kind, dict(request.query_params)),
                        media_type="application/json")

    async def device_frame(request: Request) -> Response:
        kind = _kind(request)
        q = dict(request.query_params)
        try:
            t = float(q.get("t", 0))
        except ValueError:
            raise _Fail(422, f"t={q['t'][:40]!r} must be a number of seconds") from None
        if not math.isfinite(t):
            raise _Fail(422, f"t={t} must be finite")
        data, (x, y, state) = await in_worker("device_frame", kind, q, t)
        return Response(data, media_type="application/octet-stream",
                        headers={"X-Beam": f"{x:.3f},{y:.3f},{state}", "Cache-Control": "no-store"})

    async def device_plane(request: Request) -> Response:
        png = await in_worker("device_plane", int(request.path_params["k"]))
        return Response(png, media_type="image/png")

    async def ws_new(request: Request) -> Response:
        await _body(request)
        owner = _session(request)
        fresh = owner is None
        if owner is None:
            owner = secrets.token_hex(16)
        key, entry = sessions.new(owner)
        state = await on_workstation(entry, lambda ws: ws.state())
        response = JSONResponse({"id": key, "state": state})
        if fresh:
            response.set_cookie(SESSION_COOKIE, owner, httponly=True, samesite="strict", path="/")
        return response

    async def ws_state(request: Request) -> Response:
        entry = sessions.get(request.path_params["id"], _session(request))
        return JSONResponse(await on_workstation(entry, lambda ws: ws.state()))

    async def ws_image(request: Request) -> Response:
        entry = sessions.get(request.path_params["id"], _session(request))

        def picture(ws: Workstation) -> bytes:
            version, png = entry.png
            if version != ws.version:
                png = ws.png()
                entry.png = (ws.version, png)
            return png

        return Response(await on_workstation(entry, picture), media_type="image/png",
                        headers={"Cache-Control": "no-store"})

    async def ws_action(request: Request) -> Response:
        key: str = request.path_params["id"]
        action: str = request.path_params["action"]
        owner = _session(request)
        entry = sessions.get(key, owner)
        if action not in _WS_FIELDS:
            raise _Fail(404, f"no workstation action {action[:40]!r}")
        data = _fields(await _body(request), _WS_FIELDS[action])
        if action == "close":
            sessions.close(key, owner)
            return JSONResponse({"closed": key})

        def act(ws: Workstation) -> dict[str, Any]:
            out: dict[str, Any]
            if action == "settings":
                ws.settings(**{k: data[k] for k in ("mode", "grid", "snap", "gravity",
                                                     "constraint", "tool") if k in data})
                out = {}
            elif action == "position":
                position = data.get("position") or (None, None)
                if len(position) != 2:
                    raise TypeError(f"position must be a pair [x, y], got {len(position)} numbers")
                out = ws.position(position[0], position[1], anchor=data.get("anchor"))
            elif action == "request":
                ws.request(_given(data, "device"))
                out = {}
            elif action == "input":
                out = ws.input(_given(data, "device"), _given(data, "value"))
            elif action == "await":
                out = {"event": ws.await_event()}
            elif action == "drag":
                delta = data.get("delta")
                if not isinstance(delta, list) or len(delta) != 2:
                    raise TypeError(f"delta must be a pair [dx, dy], got {delta!r}"[:120])
                out = ws.drag(_given(data, "segment"), *delta)
            else:   # delete
                ws.delete(_given(data, "segment"))
                out = {}
            return {**out, "state": ws.state()}

        return JSONResponse(await on_workstation(entry, act))

    routes = [
        Route("/", _page("index.html")),
        Route("/explorer", _page("explorer.html")),
        Route("/devices", _page("devices.html")),
        Route("/workstation", _page("workstation.html")),
        Route("/api/algorithms", _endpoint(algorithms)),
        Route("/api/explore", _endpoint(explore, post=True), methods=["POST"]),
        Route("/api/quiz", _endpoint(quiz, post=True), methods=["POST"]),
        Route("/api/devices/{kind:str}/info", _endpoint(device_info)),
        Route("/api/devices/{kind:str}/frame", _endpoint(device_frame)),
        Route("/api/devices/raster/plane/{k:int}.png", _endpoint(device_plane)),
        Route("/api/ws", _endpoint(ws_new, post=True), methods=["POST"]),
        Route("/api/ws/{id:str}/state", _endpoint(ws_state)),
        Route("/api/ws/{id:str}/image.png", _endpoint(ws_image)),
        Route("/api/ws/{id:str}/{action:str}", _endpoint(ws_action, post=True), methods=["POST"]),
        Mount("/static", StaticFiles(directory=str(STATIC)), name="static"),
    ]

    @contextlib.asynccontextmanager
    async def lifespan(app: Starlette) -> AsyncIterator[None]:
        pool.start()
        try:
            yield
        finally:
            with anyio.CancelScope(shield=True):
                await anyio.to_thread.run_sync(pool.reap)

    # The app's long-lived objects (numba, numpy, the kernels) go to the permanent
    # generation, so that the garbage collections a large table's rows trigger do not
    # walk them all (they made a 10,000-row request take 20 to 110 ms).
    gc.collect()
    gc.freeze()
    threading.Thread(target=warm_up, daemon=True, name="scanline-studio-warm-up").start()
    app = Starlette(routes=routes, lifespan=lifespan, middleware=[
        Middleware(TrustedHostMiddleware, allowed_hosts=list(allowed_hosts))])
    app.router.redirect_slashes = False     # '/api/ws/' is 404, not a redirect to follow
    app.state.pool = pool
    app.state.workstations = sessions
    return app


def serve(host: str = "127.0.0.1", port: int = 8765) -> None:
    """Serve the studio with uvicorn until interrupted, printing its address.  Ctrl-C
    (or SIGTERM) kills the worker processes at once, busy or not, and stops."""
    import uvicorn

    hosts: Sequence[str] = LOOPBACK
    if host not in LOOPBACK:
        print(f"scanline studio: listening on {host}, not only this machine: anyone who can "
              "reach this address can use the studio")
        hosts = ("*",)
    app = create_app(hosts)
    pool = app.state.pool
    config = uvicorn.Config(app, host=host, port=port, log_level="warning",
                            timeout_graceful_shutdown=2)

    class Server(uvicorn.Server):
        async def startup(self, sockets: Optional[list[socket.socket]] = None) -> None:
            await super().startup(sockets)
            for s in self.servers:
                for sock in s.sockets:
                    h, p = sock.getsockname()[:2]
                    print(f"scanline studio: http://{'[' + h + ']' if ':' in h else h}:{p}/ "
                          "(Ctrl-C stops it)", flush=True)

        def handle_exit(self, sig: int, frame: Optional[FrameType]) -> None:
            pool.close()          # no locks: safe in a signal handler
            super().handle_exit(sig, frame)

    server = Server(config)
    try:
        server.run()
    finally:
        pool.reap()
