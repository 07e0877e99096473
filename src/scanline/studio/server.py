"""The studio's web application (Starlette, served by uvicorn).

Pages: ``/`` (the index), ``/explorer``, ``/devices``, ``/workstation``; their
scripts and style under ``/static``.  The JSON API:

``GET  /api/algorithms``                      the explorer's algorithms
``POST /api/explore {algorithm, args}``       the view of one case (422: the CLI's message)
``GET  /api/devices/{raster|random}/info``    a simulation's timing
``GET  /api/devices/{raster|random}/frame?t`` the screen at time t (raw RGBA, beam in headers)
``GET  /api/devices/raster/plane/{k}.png``    a bit plane of the frame buffer
``POST /api/ws``                              a new workstation; then ``/api/ws/{id}/...``:
``GET  state``, ``GET image.png``, ``POST settings|position|request|input|await|drag|delete``

Every request runs in a worker thread with a time limit (:data:`TIME_LIMIT`);
bad input answers 422 with the message the Python API (or the command line) gives.
No endpoint reads or writes files, except the package's own static assets.
"""

import collections
import gc
import secrets
import threading
from importlib import resources

import anyio
import orjson
from starlette.applications import Starlette
from starlette.middleware import Middleware
from starlette.middleware.trustedhost import TrustedHostMiddleware
from starlette.responses import FileResponse, Response
from starlette.routing import Mount, Route
from starlette.staticfiles import StaticFiles

from ..errors import ScanlineError
from . import devices, explorer
from .workstation import Workstation

#: Seconds a request may take before it is answered 503.
TIME_LIMIT = 10.0
#: Workstations kept (least recently used dropped first).
MAX_WORKSTATIONS = 32
#: Largest request body, in bytes.
MAX_BODY = 1 << 20

STATIC = resources.files("scanline.studio") / "static"
BAD = (ScanlineError, ValueError, TypeError, KeyError, explorer.BadArguments)


class JSONResponse(Response):
    """JSON encoded by orjson: a 10,000-row table encodes in about a millisecond
    (the standard library takes ten times as long)."""

    media_type = "application/json"

    def render(self, content):
        return orjson.dumps(content)


def _error(status, message):
    return JSONResponse({"error": " ".join(str(message).split())}, status_code=status)


#: Set once the start-up warm-up has compiled the kernels the pages use.
_WARM = threading.Event()


def warm_up():
    """Compile (or load from numba's cache) what the pages reach first: the device
    simulations' frame buffer, the workstation's picture and a few traces.  On an
    empty cache this takes a while; requests wait for it before their time limit
    starts, so the limit bounds their own work, not a one-off compilation."""
    try:
        devices.frame_buffer()
        Workstation().png()
        for name in ("bresenham", "midpoint-circle", "cohen-sutherland"):
            explorer.explore(name, explorer.DEFAULTS[name])
    finally:
        _WARM.set()


async def _run(fn, *args):
    """Run ``fn(*args)`` in a worker thread within the time limit (after the warm-up);
    map bad input to 422 and a timeout to 503."""
    if not _WARM.is_set():
        await anyio.to_thread.run_sync(_WARM.wait)
    try:
        with anyio.fail_after(TIME_LIMIT):
            return await anyio.to_thread.run_sync(fn, *args, abandon_on_cancel=True)
    except TimeoutError:
        raise _Fail(503, f"the request took longer than {TIME_LIMIT:g} s and was stopped; "
                         "ask for a smaller case") from None
    except BAD as error:
        message = error.args[0] if isinstance(error, KeyError) and error.args else error
        raise _Fail(422, message) from None


class _Fail(Exception):
    def __init__(self, status, message):
        super().__init__(message)
        self.status = status


async def _body(request):
    raw = await request.body()
    if len(raw) > MAX_BODY:
        raise _Fail(413, f"the request body is {len(raw)} bytes; at most {MAX_BODY}")
    try:
        import json

        data = json.loads(raw or b"{}")
    except ValueError as error:
        raise _Fail(400, f"the body is not JSON: {error}") from None
    if not isinstance(data, dict):
        raise _Fail(400, "the body must be a JSON object")
    return data


def _endpoint(fn):
    async def wrapped(request):
        try:
            return await fn(request)
        except _Fail as fail:
            return _error(fail.status, fail)
    return wrapped


def _page(name):
    async def page(request):
        return FileResponse(str(STATIC / name), media_type="text/html")
    return page


class Sessions:
    """The workstations, by id, least recently used dropped first."""

    def __init__(self):
        self._items = collections.OrderedDict()
        self._lock = threading.Lock()

    def new(self):
        ws = Workstation()
        key = secrets.token_hex(8)
        with self._lock:
            self._items[key] = ws
            while len(self._items) > MAX_WORKSTATIONS:
                self._items.popitem(last=False)
        return key, ws

    def get(self, key):
        with self._lock:
            ws = self._items.get(key)
            if ws is None:
                raise _Fail(404, f"no workstation {key!r} (it may have expired): reload the page")
            self._items.move_to_end(key)
            return ws


#: The Host names a loopback studio answers to: a page elsewhere that rebinds its own
#: name to 127.0.0.1 (DNS rebinding) is refused.
LOOPBACK = ("127.0.0.1", "localhost", "::1", "[::1]")


def create_app(allowed_hosts=LOOPBACK):
    """The studio's Starlette application, answering requests whose Host is one of
    ``allowed_hosts`` (``("*",)``: any)."""
    sessions = Sessions()
    lock = threading.Lock()   # one workstation change at a time

    @_endpoint
    async def algorithms(request):
        return JSONResponse(explorer.catalog())

    @_endpoint
    async def explore(request):
        data = await _body(request)
        view = await _run(explorer.explore, data.get("algorithm"), data.get("args", []))
        return JSONResponse(view)

    def _kind(request):
        kind = request.path_params["kind"]
        if kind not in ("raster", "random"):
            raise _Fail(404, f"no display device {kind!r}: raster or random")
        return kind

    @_endpoint
    async def device_info(request):
        kind = _kind(request)
        q = dict(request.query_params)
        return JSONResponse(await _run(lambda: devices.info(devices.simulation(kind, q))))

    @_endpoint
    async def device_frame(request):
        kind = _kind(request)
        q = dict(request.query_params)

        def make():
            sim = devices.simulation(kind, q)
            return devices.frame(sim, float(q.get("t", 0)))

        data, (x, y, state) = await _run(make)
        return Response(data, media_type="application/octet-stream",
                        headers={"X-Beam": f"{x:.3f},{y:.3f},{state}", "Cache-Control": "no-store"})

    @_endpoint
    async def device_plane(request):
        png = await _run(devices.plane_png, int(request.path_params["k"]))
        return Response(png, media_type="image/png")

    @_endpoint
    async def ws_new(request):
        key, ws = sessions.new()
        return JSONResponse({"id": key, "state": ws.state()})

    @_endpoint
    async def ws_state(request):
        return JSONResponse(sessions.get(request.path_params["id"]).state())

    @_endpoint
    async def ws_image(request):
        ws = sessions.get(request.path_params["id"])
        return Response(await _run(ws.png), media_type="image/png",
                        headers={"Cache-Control": "no-store"})

    @_endpoint
    async def ws_action(request):
        ws = sessions.get(request.path_params["id"])
        action = request.path_params["action"]
        data = await _body(request)

        def act():
            with lock:
                if action == "settings":
                    ws.settings(**{k: data[k] for k in ("mode", "grid", "snap", "gravity",
                                                         "constraint", "tool") if k in data})
                    out = {}
                elif action == "position":
                    out = ws.position(*data.get("position", (None, None)),
                                      anchor=data.get("anchor"))
                elif action == "request":
                    ws.request(data.get("device"))
                    out = {}
                elif action == "input":
                    out = ws.input(data.get("device"), data.get("value"))
                elif action == "await":
                    out = {"event": ws.await_event()}
                elif action == "drag":
                    delta = data.get("delta", (None, None))
                    if not isinstance(delta, (list, tuple)) or len(delta) != 2:
                        raise TypeError(f"delta must be a pair [dx, dy], got {delta!r}")
                    out = ws.drag(data.get("segment"), *delta)
                elif action == "delete":
                    ws.delete(data.get("segment"))
                    out = {}
                else:
                    raise _Fail(404, f"no workstation action {action!r}")
                return {**out, "state": ws.state()}

        try:
            return JSONResponse(await _run(act))
        except _Fail as fail:
            return _error(fail.status, fail)

    routes = [
        Route("/", _page("index.html")),
        Route("/explorer", _page("explorer.html")),
        Route("/devices", _page("devices.html")),
        Route("/workstation", _page("workstation.html")),
        Route("/api/algorithms", algorithms),
        Route("/api/explore", explore, methods=["POST"]),
        Route("/api/devices/{kind:str}/info", device_info),
        Route("/api/devices/{kind:str}/frame", device_frame),
        Route("/api/devices/raster/plane/{k:int}.png", device_plane),
        Route("/api/ws", ws_new, methods=["POST"]),
        Route("/api/ws/{id:str}/state", ws_state),
        Route("/api/ws/{id:str}/image.png", ws_image),
        Route("/api/ws/{id:str}/{action:str}", ws_action, methods=["POST"]),
        Mount("/static", StaticFiles(directory=str(STATIC)), name="static"),
    ]

    # The app's long-lived objects (numba, numpy, the kernels) go to the permanent
    # generation, so that the garbage collections a large table's rows trigger do not
    # walk them all (they made a 10,000-row request take 20 to 110 ms).
    gc.collect()
    gc.freeze()
    threading.Thread(target=warm_up, daemon=True, name="scanline-studio-warm-up").start()
    return Starlette(routes=routes, middleware=[
        Middleware(TrustedHostMiddleware, allowed_hosts=list(allowed_hosts))])


def serve(host="127.0.0.1", port=8765):
    """Serve the studio with uvicorn until interrupted, printing its address."""
    import uvicorn

    hosts = LOOPBACK
    if host not in LOOPBACK:
        print(f"scanline studio: listening on {host}, not only this machine: anyone who can "
              "reach this address can use the studio")
        hosts = ("*",)
    config = uvicorn.Config(create_app(hosts), host=host, port=port, log_level="warning")
    server = uvicorn.Server(config)

    original = server.startup

    async def startup(sockets=None):
        await original(sockets)
        for s in server.servers:
            for sock in s.sockets:
                h, p = sock.getsockname()[:2]
                print(f"scanline studio: http://{'[' + h + ']' if ':' in h else h}:{p}/ "
                      "(Ctrl-C stops it)", flush=True)

    server.startup = startup
    server.run()
