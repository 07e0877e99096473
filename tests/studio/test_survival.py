"""The studio survives its neighbours (and they survive it), over loopback: a request
past its time limit is stopped and its CPU freed, slow requests are bounded, memory per
request is bounded, bodies are cut at the limit, only the studio's own pages may post,
workstations belong to their session and lock one by one, malformed bodies are 400,
Ctrl-C stops the server with busy workers, and a fuzz of hostile requests never gets
a 500 nor stops the server.

Small limits (a 1 s deadline, a one-worker pool, short queue waits) are set by
monkeypatching the modules' constants, which the server reads at each request."""

import http.client
import json
import math
import os
import random
import re
import signal
import socket
import subprocess
import threading
import time
import urllib.parse

import anyio
import pytest

from scanline.studio import pool as pool_module
from scanline.studio import server as server_module
from scanline.studio.server import create_app
from tests import terminal

#: A valid explorer case that takes many seconds of CPU (11,325 rows of Cox-de Boor on
#: 50,000 knots), in little memory.
SLOW = {"algorithm": "cox-de-boor",
        "args": ["--knots", ",".join(map(str, range(50_000))), "--order", "150", "--u", "25000"]}
QUICK = {"algorithm": "bresenham", "args": ["0", "0", "5", "3"]}


# -- a live server on loopback, one worker ---------------------------------------------------
def serve_in_thread(app):
    import uvicorn

    sock = socket.socket()
    sock.bind(("127.0.0.1", 0))
    port = sock.getsockname()[1]
    sock.close()
    srv = uvicorn.Server(uvicorn.Config(app, host="127.0.0.1", port=port, log_level="error"))
    thread = threading.Thread(target=srv.run, daemon=True)
    thread.start()
    deadline = time.monotonic() + 30
    while not srv.started:
        assert time.monotonic() < deadline, "the studio did not start in 30 s"
        time.sleep(0.05)
    return srv, thread, f"http://127.0.0.1:{port}"


@pytest.fixture(scope="module")
def live():
    app = create_app(workers=1)
    srv, thread, url = serve_in_thread(app)
    live = type("Live", (), {"url": url, "app": app, "pool": app.state.pool, "thread": thread})
    yield live
    srv.should_exit = True
    thread.join(15)
    assert not app.state.pool.pids()          # the workers went with the server


def request(base, method, path, body=None, headers=None, timeout=30):
    """(status, headers, body) of one request on a fresh connection."""
    u = urllib.parse.urlsplit(base)
    conn = http.client.HTTPConnection(u.hostname, u.port, timeout=timeout)
    try:
        conn.request(method, path, body=body, headers=headers or {})
        r = conn.getresponse()
        return r.status, dict((k.lower(), v) for k, v in r.getheaders()), r.read()
    finally:
        conn.close()


def post(base, path, data, cookie=None, **headers):
    """A POST as the studio's pages send it: JSON, with the studio's Origin."""
    h = {"Content-Type": "application/json", "Origin": base}
    if cookie:
        h["Cookie"] = cookie
    h.update(headers)
    body = data if isinstance(data, bytes) else json.dumps(data).encode()
    return request(base, "POST", path, body, h)


def error_of(body):
    return json.loads(body)["error"]


def new_workstation(base, cookie=None):
    """(status, id, cookie) of a new workstation."""
    status, headers, body = post(base, "/api/ws", {}, cookie)
    if status != 200:
        return status, error_of(body), cookie
    if "set-cookie" in headers:
        cookie = headers["set-cookie"].split(";")[0]
    return status, json.loads(body)["id"], cookie


def alive(pid):
    """Whether process ``pid`` exists and is not a zombie."""
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().rsplit(")", 1)[1].split()[0] != "Z"
    except OSError:
        return False


def cpu_ticks(pid):
    try:
        with open(f"/proc/{pid}/stat") as f:
            fields = f.read().rsplit(")", 1)[1].split()
        return int(fields[11]) + int(fields[12])          # utime + stime
    except OSError:
        return None


def children(pid):
    out = []
    for name in os.listdir("/proc"):
        if name.isdigit():
            try:
                with open(f"/proc/{name}/stat") as f:
                    if int(f.read().rsplit(")", 1)[1].split()[1]) == pid:
                        out.append(int(name))
            except (OSError, ValueError, IndexError):
                pass
    return out


def until(condition, seconds, what):
    deadline = time.monotonic() + seconds
    while not condition():
        assert time.monotonic() < deadline, f"{what} (waited {seconds} s)"
        time.sleep(0.02)


# -- 1. a request past its deadline is stopped, its CPU freed --------------------------------
def test_a_request_past_its_time_limit_is_stopped_and_its_worker_killed(live, monkeypatch):
    assert post(live.url, "/api/explore", QUICK)[0] == 200             # the worker is ready
    monkeypatch.setattr(server_module, "TIME_LIMIT", 1.0)
    replaced = live.pool.replaced
    got, busy = {}, []
    thread = threading.Thread(target=lambda: got.update(r=post(live.url, "/api/explore", SLOW)))
    thread.start()
    until(lambda: live.pool.busy_pids(), 10, "the slow request never reached a worker")
    busy = live.pool.busy_pids()[0]
    start = cpu_ticks(busy)
    until(lambda: (cpu_ticks(busy) or 0) > start or not alive(busy), 10, "the worker is not working")
    thread.join(30)
    status, _, body = got["r"]
    assert status == 503 and "longer than 1 s" in error_of(body)
    # killed before the answer: nothing is left using the CPU for the abandoned work
    until(lambda: not alive(busy), 1.0, f"worker {busy} still runs after the 503")
    assert busy not in live.pool.pids() and live.pool.replaced == replaced + 1
    monkeypatch.setattr(server_module, "TIME_LIMIT", 30.0)
    assert post(live.url, "/api/explore", QUICK)[0] == 200             # its replacement serves


def test_eight_slow_requests_cannot_hold_the_cores(live, monkeypatch):
    assert post(live.url, "/api/explore", QUICK)[0] == 200
    monkeypatch.setattr(server_module, "TIME_LIMIT", 1.5)
    monkeypatch.setattr(pool_module, "QUEUE_WAIT", 0.3)
    monkeypatch.setattr(pool_module, "MAX_WAITING", 1)
    replies, most = [], [0]

    def watch():
        while len(replies) < 8:
            most[0] = max(most[0], len(live.pool.busy_pids()))
            time.sleep(0.01)

    def one():
        replies.append(post(live.url, "/api/explore", SLOW))

    threads = [threading.Thread(target=one) for _ in range(8)] + [threading.Thread(target=watch)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(60)
    errors = sorted(error_of(body) for status, _, body in replies if status == 503)
    assert len(errors) == 8, [r[0] for r in replies]
    # one ran until its limit and was stopped; one waited briefly; six were refused at once
    assert sum("longer than 1.5 s" in e for e in errors) == 1
    assert sum("busy" in e for e in errors) == 7
    assert most[0] == 1                                                  # one worker, one task
    until(lambda: not live.pool.busy_pids(), 1.0, "a worker is still busy")
    monkeypatch.setattr(server_module, "TIME_LIMIT", 30.0)
    assert post(live.url, "/api/explore", QUICK)[0] == 200


# -- 2. memory per request -------------------------------------------------------------------
@pytest.mark.parametrize("algorithm, args, argument", [
    ("floating-horizon", ["--width", "100000000"], "--width"),
    ("floating-horizon", ["--nx", "5000", "--ny", "5000"], "--nx"),
    ("cox-de-boor", ["--knots", ",".join(map(str, range(5000))), "--order", "4999", "--u", "2"],
     "--order"),
    ("scan-line-fill", ["0,0", "2000,0", "2000,2000", "0,2000"], "points"),
    ("sutherland-hodgman", [f"{i % 17},{i // 17}" for i in range(300)] + ["--window-polygon", ",".join(
        f"{1000 * math.cos(2 * math.pi * i / 3000):.4f},{1000 * math.sin(2 * math.pi * i / 3000):.4f}"
        for i in range(3000))], "--window-polygon"),
    ("sutherland-hodgman", [f"{i % 100},{i // 100}" for i in range(5000)], "points"),
    ("midpoint-ellipse", ["90000", "90000"], "RX"),
])
def test_sizes_past_the_memory_budget_are_refused_naming_the_argument(live, algorithm, args,
                                                                      argument):
    status, _, body = post(live.url, "/api/explore", {"algorithm": algorithm, "args": args})
    message = error_of(body)
    assert status == 422 and message.startswith(f"{argument}: ")
    assert f"{server_module.REQUEST_MEMORY:,} bytes per request" in message


def test_a_wrong_estimate_meets_the_workers_address_space_limit(monkeypatch):
    from starlette.testclient import TestClient

    monkeypatch.setattr(server_module, "REQUEST_MEMORY", 1 << 40)      # estimates pass
    app = create_app(workers=1, address_space=64 << 20)
    with TestClient(app, base_url="http://127.0.0.1", headers={"Origin": "http://127.0.0.1"}) as c:
        assert c.post("/api/explore", json=QUICK).status_code == 200
        first = app.state.pool.pids()
        r = c.post("/api/explore", json={"algorithm": "floating-horizon",
                                         "args": ["--width", "30000000"]})     # 240 MB arrays
        assert r.status_code == 422 and "more memory than the studio allows" in r.json()["error"]
        assert not any(alive(p) for p in first)                         # replaced, not reused
        assert c.post("/api/explore", json=QUICK).status_code == 200
    assert not any(alive(p) for p in app.state.pool.pids() + first)


# -- 3. bodies are read in chunks and cut at the limit --------------------------------------
def raw_exchange(base, head, chunks):
    """Send ``head`` then ``chunks`` (ignoring a closed connection), never finishing the
    body; the status line the server answers."""
    u = urllib.parse.urlsplit(base)
    with socket.create_connection((u.hostname, u.port), timeout=20) as s:
        s.sendall(head)
        try:
            for c in chunks:
                s.sendall(c)
        except OSError:
            pass                                  # it stopped reading: fine
        reply = b""
        while b"\r\n" not in reply:
            data = s.recv(4096)
            if not data:
                break
            reply += data
    return reply.split(b"\r\n")[0]


def test_a_chunked_body_is_cut_as_soon_as_it_passes_the_limit(live):
    port = urllib.parse.urlsplit(live.url).port
    head = (f"POST /api/explore HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nOrigin: {live.url}\r\n"
            "Content-Type: application/json\r\nTransfer-Encoding: chunked\r\n\r\n").encode()
    piece = b" " * 65536
    chunk = b"%x\r\n%s\r\n" % (len(piece), piece)
    # 1 MiB and 64 KiB, and the body never ends: the answer must not wait for its end
    line = raw_exchange(live.url, head, [chunk] * 17)
    assert line.startswith(b"HTTP/1.1 413")


def test_a_declared_length_past_the_limit_is_refused_before_reading(live):
    port = urllib.parse.urlsplit(live.url).port
    head = (f"POST /api/explore HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nOrigin: {live.url}\r\n"
            f"Content-Type: application/json\r\nContent-Length: {512 << 20}\r\n\r\n").encode()
    assert raw_exchange(live.url, head, [b"{"]).startswith(b"HTTP/1.1 413")


def test_the_body_reader_stops_at_the_limit_whatever_the_length_says(live):
    """At the ASGI level: a body that never ends, under a Content-Length that lies, is
    read only one chunk past the limit."""
    read = [0]
    sent = []

    async def receive():
        read[0] += 1
        return {"type": "http.request", "body": b" " * 65536, "more_body": True}

    async def send(message):
        sent.append(message)

    scope = {"type": "http", "asgi": {"version": "3.0"}, "http_version": "1.1", "method": "POST",
             "scheme": "http", "path": "/api/explore", "raw_path": b"/api/explore",
             "query_string": b"", "root_path": "", "server": ("127.0.0.1", 80),
             "client": ("127.0.0.1", 5000),
             "headers": [(b"host", b"127.0.0.1"), (b"origin", b"http://127.0.0.1"),
                         (b"content-type", b"application/json"), (b"content-length", b"10")]}
    # in a thread of its own: Playwright's sync API may hold an event loop in this one
    thread = threading.Thread(target=anyio.run, args=(live.app, scope, receive, send))
    thread.start()
    thread.join(30)
    assert sent[0]["status"] == 413
    assert read[0] == server_module.MAX_BODY // 65536 + 1


# -- 4. only the studio's pages may act; workstations belong to their session ---------------
@pytest.mark.parametrize("headers, why", [
    ({"Content-Type": "text/plain"}, "Content-Type"),
    ({"Content-Type": "application/x-www-form-urlencoded"}, "Content-Type"),
    ({"Origin": "http://evil.example"}, "origin"),
    ({"Origin": "null"}, "origin"),
    ({"Origin": None}, "Origin"),
    ({"Origin": "http://127.0.0.1:1"}, "origin"),                     # another port
])
def test_posts_need_json_from_the_studios_own_origin(live, headers, why):
    before = len(live.app.state.workstations)
    h = {"Content-Type": "application/json", "Origin": live.url, **headers}
    h = {k: v for k, v in h.items() if v is not None}
    for path in ("/api/ws", "/api/explore"):
        status, _, body = request(live.url, "POST", path, json.dumps(QUICK).encode(), h)
        assert status == 403 and why in error_of(body)
    assert len(live.app.state.workstations) == before                 # nothing was created
    assert post(live.url, "/api/explore", QUICK)[0] == 200


@pytest.mark.parametrize("site", ["cross-site", "same-site"])
def test_other_sites_pages_cannot_read_the_api(live, site):
    status, _, body = request(live.url, "GET", "/api/algorithms", headers={"Sec-Fetch-Site": site})
    assert status == 403 and site in error_of(body)
    assert request(live.url, "GET", "/api/algorithms",
                   headers={"Sec-Fetch-Site": "same-origin"})[0] == 200


def test_workstations_belong_to_their_session_and_are_never_evicted(live, monkeypatch):
    monkeypatch.setattr(server_module, "MAX_WORKSTATIONS_PER_SESSION", 3)
    status, mine, alice = new_workstation(live.url)
    assert status == 200 and alice.startswith(server_module.SESSION_COOKIE + "=")
    # another caller (no cookie, or its own) can neither see nor act on it
    _, _, bob = new_workstation(live.url)
    for cookie in (None, bob, f"{server_module.SESSION_COOKIE}={'0' * 32}"):
        h = {"Cookie": cookie} if cookie else {}
        assert request(live.url, "GET", f"/api/ws/{mine}/state", headers=h)[0] == 404
        assert request(live.url, "GET", f"/api/ws/{mine}/image.png", headers=h)[0] == 404
        for action, body in (("settings", {"snap": True}), ("delete", {"segment": "house"}),
                             ("close", {})):
            assert post(live.url, f"/api/ws/{mine}/{action}", body, cookie)[0] == 404
    # bob fills his own quota: 429, and alice's workstation is still there
    assert new_workstation(live.url, bob)[0] == 200
    assert new_workstation(live.url, bob)[0] == 200
    status, message, _ = new_workstation(live.url, bob)
    assert status == 429 and "close a workstation page" in message
    # the studio's total: 503 for a newcomer, still no eviction
    monkeypatch.setattr(server_module, "MAX_WORKSTATIONS", len(live.app.state.workstations))
    status, message, _ = new_workstation(live.url)
    assert status == 503 and "its limit" in message
    r = post(live.url, f"/api/ws/{mine}/settings", {"snap": True}, alice)
    assert r[0] == 200 and json.loads(r[2])["state"]["snap"] is True
    assert request(live.url, "GET", f"/api/ws/{mine}/image.png", headers={"Cookie": alice})[0] == 200
    # closing gives the place back
    assert post(live.url, f"/api/ws/{mine}/close", {}, alice)[0] == 200
    assert request(live.url, "GET", f"/api/ws/{mine}/state", headers={"Cookie": alice})[0] == 404
    assert new_workstation(live.url, alice)[0] == 200


# -- 5. one lock per workstation ------------------------------------------------------------
def test_a_slow_action_on_one_workstation_delays_no_other(live):
    _, a, cookie = new_workstation(live.url)
    _, b, _ = new_workstation(live.url, cookie)
    entry = live.app.state.workstations.get(a, cookie.split("=", 1)[1])
    entered, release = threading.Event(), threading.Event()
    state = entry.ws.state

    def slow_state():
        entered.set()
        assert release.wait(30)
        return state()

    entry.ws.state = slow_state
    got = {}
    thread = threading.Thread(target=lambda: got.update(a=post(
        live.url, f"/api/ws/{a}/settings", {"grid": 2}, cookie)))
    thread.start()
    try:
        assert entered.wait(20)
        # A is held inside its lock; B answers meanwhile
        r = post(live.url, f"/api/ws/{b}/settings", {"snap": True}, cookie)
        assert r[0] == 200 and json.loads(r[2])["state"]["snap"] is True
        assert request(live.url, "GET", f"/api/ws/{b}/image.png", headers={"Cookie": cookie})[0] == 200
        assert thread.is_alive() and "a" not in got
    finally:
        release.set()
        thread.join(30)
    assert got["a"][0] == 200 and json.loads(got["a"][2])["state"]["grid"] == 2


# -- 6. malformed bodies are 400, naming what is wrong ---------------------------------------
@pytest.mark.parametrize("path, body, says", [
    ("/api/explore", b"{not json", "not JSON"),
    ("/api/explore", b'{"algorithm": "bresenham", "args": ["1", NaN]}', "not JSON"),
    ("/api/explore", b'{"algorithm": "\xff\xfe"}', "UTF-8"),
    ("/api/explore", b"[" * 100_000 + b"]" * 100_000, "not JSON"),
    ("/api/explore", b'{"args": ' + b"[" * 40 + b"]" * 40 + b"}", "deep"),
    ("/api/explore", b"[1, 2]", "object"),
    ("/api/explore", b'"bresenham"', "object"),
    ("/api/explore", b'{"algorithm": 5, "args": []}', "algorithm"),
    ("/api/explore", b'{"args": ["1"]}', "algorithm"),
    ("/api/explore", b'{"algorithm": "bresenham", "args": "20 10 30 18"}', "args"),
    ("/api/explore", b'{"algorithm": "bresenham", "args": [20, 10, 30, 18]}', "args"),
    ("WS/settings", b'{"grid": "fine"}', "grid"),
    ("WS/settings", b'{"snap": 1}', "snap"),
    ("WS/input", b'{"device": "choice", "value": [1]}', "value"),
    ("WS/position", b'{"position": "1,2"}', "position"),
    ("WS/position", b'{"position": [1, 2, 3]}', "position"),
    ("WS/drag", b'{"segment": "sun", "delta": 5}', "delta"),
    ("WS/delete", b'{"segment": {"name": "sun"}}', "segment"),
])
def test_malformed_bodies_are_400_naming_what_is_wrong(client, path, body, says):
    if path.startswith("WS/"):
        key = client.post("/api/ws", json={}).json()["id"]
        path = f"/api/ws/{key}/{path[3:]}"
    r = client.post(path, content=body, headers={"Content-Type": "application/json"})
    assert r.status_code == 400 and says in r.json()["error"], r.text
    if path.startswith("/api/ws/"):
        assert client.post(path.rsplit("/", 1)[0] + "/close", json={}).status_code == 200


# -- 7. Ctrl-C ------------------------------------------------------------------------------
def test_ctrl_c_stops_the_server_at_once_with_busy_workers():
    proc = terminal.python("-m", "scanline", "studio", "--port", "0",
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    workers = []
    try:
        url = None
        for line in proc.stdout:
            match = re.search(r"(http://\S+)/ ", line)
            if match:
                url = match.group(1)
                break
        assert url, proc.stderr.read()
        assert post(url, "/api/explore", QUICK)[0] == 200             # workers are ready
        workers = children(proc.pid)
        assert workers
        before = {p: cpu_ticks(p) for p in workers}
        threading.Thread(target=lambda: post(url, "/api/explore", SLOW), daemon=True).start()
        until(lambda: any((cpu_ticks(p) or 0) > before[p] + 20 for p in workers), 15,
              "no worker started on the slow request")
        proc.send_signal(signal.SIGINT)
        assert proc.wait(10) == 130
        until(lambda: not any(alive(p) for p in workers), 2.0, "a worker outlived the server")
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait(10)
        for p in workers:
            if alive(p):
                os.kill(p, signal.SIGKILL)


# -- 8. a fuzz of hostile requests -----------------------------------------------------------
def _value(rng, depth=0):
    kinds = ["int", "float", "str", "none", "bool", "list", "dict", "huge", "unicode"]
    kind = rng.choice(kinds if depth < 6 else kinds[:5])
    if kind == "int":
        return rng.choice([0, -1, 1, 7, 2**31, -2**63, 10**18, rng.randint(-10**6, 10**6)])
    if kind == "float":
        return rng.choice([0.5, -1e-300, 1e308, -1e308, 3.25, rng.uniform(-1e6, 1e6)])
    if kind == "str":
        return rng.choice(["", "x", "house", "sun", "locator", "pick", "event", "request",
                           "nan", "inf", "-1e400", "<script>", "../", "20", "--grid"])
    if kind == "none":
        return None
    if kind == "bool":
        return rng.random() < 0.5
    if kind == "huge":
        return rng.choice([10**30, 1e300, "9" * 400])
    if kind == "unicode":
        return "\u0000\u202e\ud7ff€" * rng.randint(1, 5)
    if kind == "list":
        return [_value(rng, depth + 1) for _ in range(rng.randint(0, 4))]
    return {rng.choice(["position", "anchor", "value", "device", "item", "text", "angle",
                        "points", "segment", "tool", "mode", "grid", "snap", "delta", "gravity",
                        "algorithm", "args", "constraint"]): _value(rng, depth + 1)
            for _ in range(rng.randint(0, 4))}


def _args(rng):
    name = rng.choice(sorted(server_module.explorer.DEFAULTS) + ["floating-horizon", "z-buffer",
                                                                  "depth-sort", "nope"])
    args = list(server_module.explorer.DEFAULTS.get(name, []))
    for _ in range(rng.randint(0, 3)):
        token = rng.choice(["nan", "inf", "-inf", "1e308", "-5", "0", "99999999", "1e9",
                            "--width", "--height", "--nx", "--order", "--knots", "--center",
                            "--window", "--grid", "#", "--", "0,0", "1e300,1", "x", ""])
        if args and rng.random() < 0.5:
            args[rng.randrange(len(args))] = token
        else:
            args.append(token)
    return name, args


def _body(rng):
    r = rng.random()
    if r < 0.3:
        name, args = _args(rng)
        return json.dumps({"algorithm": name, "args": args}).encode()
    if r < 0.55:
        return json.dumps(_value(rng)).encode()
    if r < 0.65:
        depth = rng.choice([20, 33, 200, 5000])
        return b'{"a": ' + b"[" * depth + b"]" * depth + b"}"
    if r < 0.75:
        return rng.choice([b"{", b'{"a": NaN}', b'{"a": Infinity}', b"\xff\xfe\x00{", b"",
                           b'{"a": 1e400}', b'{"algorithm": "bresenham"} trailing',
                           b"\x00" * 50, b'{"a": "\\ud800"}'])
    return bytes(rng.getrandbits(8) for _ in range(rng.randint(0, 200)))


def test_a_fuzz_of_hostile_requests_never_gets_a_500_nor_stops_the_server(live, monkeypatch):
    monkeypatch.setattr(server_module, "TIME_LIMIT", 1.0)
    rng = random.Random(20240601)
    _, key, cookie = new_workstation(live.url)
    actions = ["settings", "position", "request", "input", "await", "drag", "delete", "state",
               "image.png", "explode"]
    posts = [lambda: "/api/explore", lambda: "/api/explore", lambda: "/api/ws",
             lambda: f"/api/ws/{key}/{rng.choice(actions)}"]
    gets = [lambda: "/api/algorithms", lambda: f"/api/ws/{key}/{rng.choice(['state', 'image.png'])}",
             lambda: f"/api/ws/{rng.choice(['x', key[:-1] + '0', '..', '%00'])}/state",
             lambda: f"/api/devices/{rng.choice(['raster', 'random', 'plasma'])}/"
                     f"{rng.choice(['info', 'frame'])}?" + urllib.parse.urlencode(
                         {k: rng.choice(["nan", "inf", "-1", "0", "1e308", "1e-300", "5000",
                                         "99999", "x", "1"])
                          for k in rng.sample(["t", "rate", "interlaced", "persistence",
                                               "lines", "speed"], rng.randint(0, 4))}),
             lambda: f"/api/devices/raster/plane/{rng.choice([-1, 0, 7, 8, 10**30])}.png",
             lambda: rng.choice(["/", "/explorer", "/static/../server.py",
                                 "/static/%2e%2e/server.py", "/static/studio.css", "/nope",
                                 "//etc/passwd", "/api/" + "a" * 3000, "/api/ws/",
                                 "/static/" + "%ff" * 10])]
    statuses = []
    for i in range(200):
        post_path = rng.random() < 0.6
        path = rng.choice(posts if post_path else gets)()
        method = ("POST" if post_path else "GET") if rng.random() < 0.9 else rng.choice(
            ["GET", "POST", "PUT", "DELETE", "PATCH", "OPTIONS", "HEAD"])
        headers = {}
        if rng.random() < 0.85:
            headers["Content-Type"] = rng.choice(["application/json"] * 4 + [
                "application/json; charset=utf-8", "text/plain", "multipart/form-data; b=x",
                "application/JSON", "\u00e9"])
        headers["Origin"] = rng.choice([live.url] * 5 + ["http://evil.example", "null", ""])
        if rng.random() < 0.8:
            headers["Cookie"] = cookie
        if rng.random() < 0.1:
            headers["Sec-Fetch-Site"] = rng.choice(["cross-site", "same-site", "same-origin",
                                                    "none", "???"])
        if rng.random() < 0.05:
            headers["Host"] = rng.choice(["evil.example", "127.0.0.1.evil", "localhost:1"])
        headers = {k: v.encode("latin-1", "replace").decode("latin-1") for k, v in headers.items()}
        body = _body(rng) if method in ("POST", "PUT", "PATCH") else None
        try:
            status, _, payload = request(live.url, method, path, body, headers, timeout=30)
        except (http.client.HTTPException, OSError) as error:
            pytest.fail(f"request {i} ({method} {path[:80]}) got no answer: {error!r}")
        statuses.append(status)
        assert 200 <= status < 300 or 400 <= status < 500 or status == 503, (
            i, method, path[:80], headers, (body or b"")[:200], status, payload[:300])
        if status == 400 and payload.startswith(b"{"):
            assert error_of(payload)
    assert live.thread.is_alive()
    # still healthy, and the fuzz reached real work as well as refusals
    monkeypatch.setattr(server_module, "TIME_LIMIT", 30.0)
    assert request(live.url, "GET", "/api/algorithms")[0] == 200
    assert post(live.url, "/api/explore", QUICK)[0] == 200
    assert {200, 400, 403, 404, 422} <= set(statuses)
