"""The studio's endpoints, without a browser: the explorer's views equal sl.trace,
bad input gives 422 with the command line's message, the workstation's input
devices and modes, the device simulations, and fuzzed requests never crash."""

import json

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import scanline as sl
from scanline.cli import main
from scanline.studio import explorer


def post(client, algorithm, args):
    return client.post("/api/explore", json={"algorithm": algorithm, "args": args})


def test_pages_and_assets_are_served(client):
    for path in ("/", "/explorer", "/devices", "/workstation"):
        r = client.get(path)
        assert r.status_code == 200 and "<html" in r.text
    for asset in ("studio.css", "explorer.js", "devices.js", "workstation.js"):
        assert client.get(f"/static/{asset}").status_code == 200
    assert client.get("/static/../server.py").status_code == 404


def test_other_host_names_are_refused(client):
    r = client.get("/explorer", headers={"Host": "attacker.example"})
    assert r.status_code == 400
    assert client.get("/explorer", headers={"Host": "localhost:8765"}).status_code == 200


def test_every_traced_algorithm_is_offered(client):
    names = [a["name"] for a in client.get("/api/algorithms").json()]
    assert sorted(names) == sorted(sl.trace.ALGORITHMS)


def test_bresenham_view_is_the_trace(client):
    view = post(client, "bresenham", ["20", "10", "30", "18"]).json()
    t = sl.trace.bresenham(20, 10, 30, 18)
    assert explorer.rows_of(view) == t.rows and view["columns"] == t.columns
    assert view["before"] == [[20, 10]] and view["pixel_columns"] == ["x", "y"]
    assert {(r["x"], r["y"]) for r in t.rows} | {(20, 10)} == t.pixels()
    rules = view["rules"]
    assert [rules["templates"][i].split(":")[0] for i in rules["pick"][:3]] == [
        "p_{k} = {p} >= 0", "p_{k} = {p} >= 0", "p_{k} = {p} < 0"]     # p = 6, 2, -2
    assert view["handles"][1]["tokens"] == [view["args"].index("30"), view["args"].index("18")]


@pytest.mark.parametrize("algorithm", sorted(explorer.DEFAULTS))
def test_each_default_view_has_one_step_per_row(client, algorithm):
    view = post(client, algorithm, explorer.DEFAULTS[algorithm]).json()
    assert view["count"] == len(view["rows"]) > 0
    assert len(view["steps"] or view["rules"]["pick"]) == view["count"]
    ns = explorer.parse(algorithm, explorer.DEFAULTS[algorithm])
    from scanline.cli.trace import table_of
    assert explorer.rows_of(view) == json.loads(table_of(ns).to_json())
    # the canonical arguments parse to the same case
    again = post(client, algorithm, view["args"]).json()
    assert again["rows"] == view["rows"]
    if algorithm in ("flood-fill", "boundary-fill", "scan-line-fill", "midpoint-circle",
                     "midpoint-ellipse", "dda", "bresenham"):
        steps = view["steps"] or [{"pixels": [[r["x"], r["y"]]]} for r in explorer.rows_of(view)]
        painted = {tuple(p) for s in steps for p in s["pixels"]} | {
            tuple(p) for p in view["before"]}
        assert painted == table_of(ns).pixels()


def test_clipped_pieces_follow_the_table(client):
    view = post(client, "liang-barsky", ["-5", "2", "15", "12"]).json()
    assert view["steps"][-1]["segment"] == [[0.0, 4.5], [10.0, 9.5]]
    view = post(client, "cohen-sutherland", ["-5", "2", "15", "22"]).json()
    assert view["steps"][-1]["segment"] == [[0.0, 7.0], [3.0, 10.0]]
    view = post(client, "sutherland-hodgman", ["--", "-2,2", "6,2", "6,12"]).json()
    assert view["steps"][-1]["output"] == [[float(x), float(y)] for x, y in view["result"]][-len(
        view["steps"][-1]["output"]):]


def cli_error(capsys, args):
    code = main(["trace", *args])
    err = capsys.readouterr().err
    assert code == 2
    return err.strip().removeprefix("scanline: error: ")


@pytest.mark.parametrize("algorithm, args", [
    ("bresenham", ["20", "x", "30", "18"]),
    ("bresenham", ["0", "0", "1000000000", "0"]),
    ("dda", ["1"]),
    ("midpoint-circle", ["-3"]),
    ("flood-fill", ["1", "1", "--grid", "#" * 20000]),
    ("flood-fill", ["99", "1"]),
    ("scan-line-fill", ["0,0", "nan,0", "0,1"]),
    ("cyrus-beck", ["0", "0", "5", "5", "--window-polygon", "0,0,10,0,5"]),
    ("de-casteljau", ["0,0", "--u", "2"]),
    ("sutherland-hodgman", ["0,0", "4,0", "0,4", "--window", "0", "0", "0", "0"]),
])
def test_bad_arguments_give_422_with_the_cli_message(client, capsys, algorithm, args):
    r = post(client, algorithm, args)
    assert r.status_code == 422
    assert r.json()["error"] == cli_error(capsys, [algorithm, *args])


@pytest.mark.parametrize("body, status", [
    ({"algorithm": "nope", "args": []}, 422),
    ({"algorithm": "bresenham", "args": "20 10 30 18"}, 400),     # wrong types: 400
    ({"algorithm": "bresenham", "args": [1, 2, 3, 4]}, 400),
    ({"algorithm": "bresenham", "args": ["--help"]}, 422),
])
def test_malformed_requests(client, body, status):
    r = client.post("/api/explore", json=body)
    assert r.status_code == status and r.json()["error"]


def test_non_json_and_huge_bodies(client):
    json = {"Content-Type": "application/json"}
    assert client.post("/api/explore", content=b"{not json", headers=json).status_code == 400
    assert client.post("/api/explore", content=b"[1, 2]", headers=json).status_code == 400
    assert client.post("/api/explore", content=b" " * (2 << 20), headers=json).status_code == 413


def test_the_explorer_refuses_tables_too_long_to_show(client):
    r = post(client, "bresenham", ["0", "0", "30000", "1"])
    assert r.status_code == 422 and "at most 20000" in r.json()["error"]


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(algorithm=st.sampled_from(sorted(explorer.DEFAULTS)),
       args=st.lists(st.one_of(st.integers(-10**12, 10**12).map(str),
                               st.floats(allow_nan=True, allow_infinity=True).map(str),
                               st.sampled_from(["--center", "--window", "--grid", "--u", "--",
                                                "0,0", "3,4", "-1,2", "nan,1", "#./#.", "x",
                                                "--connectivity", "8", "--rule", "--knots"])),
                     max_size=8))
def test_fuzzed_explore_requests_never_crash(client, algorithm, args):
    r = post(client, algorithm, args)
    assert r.status_code in (200, 422), r.text
    if r.status_code == 200:
        v = r.json()
        steps = v["steps"] if v["steps"] is not None else v["rules"]["pick"]
        assert len(steps) == len(v["rows"]) == v["count"]


# -- the workstation ------------------------------------------------------------------
@pytest.fixture
def ws(client):
    r = client.post("/api/ws", json={})
    key = r.json()["id"]

    def act(action, **body):
        return client.post(f"/api/ws/{key}/{action}", json=body)

    act.key = key
    yield act
    assert client.post(f"/api/ws/{key}/close", json={}).status_code == 200


def device_of(ws_obj, wx, wy):
    return ws_obj.device(wx, wy)


def test_pick_selects_and_highlights_the_segment(ws):
    from scanline.studio.workstation import Workstation
    here = Workstation()
    x, y = here.device(12, 16)                  # inside the house's roof
    r = ws("input", device="pick", value={"position": [x, y], "aperture": 2})
    assert r.status_code == 200
    assert r.json()["result"]["segment"] == "house" and r.json()["result"]["pick_id"] == 2
    state = r.json()["state"]
    assert state["selected"] == "house"
    assert [s["name"] for s in state["segments"] if s["highlighted"]] == ["house"]
    x, y = here.device(2, 2)
    r = ws("input", device="pick", value={"position": [x, y]})
    assert r.json()["result"]["segment"] is None and r.json()["state"]["selected"] is None


def test_valuator_sets_the_segment_rotation(ws):
    r = ws("input", device="valuator", value={"segment": "tree", "angle": 90})
    m = np.array(r.json()["result"]["matrix"])
    assert np.allclose(m[:2, :2] @ [1, 0], [0, 1], atol=1e-9) or np.allclose(
        np.linalg.det(m[:2, :2]), 1)
    # the tree's pivot (its center) stays where it is, in world coordinates
    from scanline.studio.workstation import Workstation
    w = Workstation()
    c = w._center("tree")
    n = w.df.normalization
    p = sl.transform.apply(np.linalg.inv(n) @ m @ n, [c])[0]
    assert np.allclose(p, c)
    assert ws("input", device="valuator", value={"segment": "nope", "angle": 1}).status_code == 422
    assert ws("input", device="valuator", value={"segment": "tree", "angle": 1e9}).status_code == 422


def test_string_stroke_and_rubber_band_add_segments(ws):
    r = ws("input", device="string", value={"position": [100, 100], "text": "<b>hi</b>"})
    name = r.json()["result"]["segment"]
    assert name.startswith("text-") and name in [s["name"] for s in r.json()["state"]["segments"]]
    r = ws("input", device="stroke", value={"points": [[10, 10], [20, 30], [40, 35]]})
    assert r.json()["result"]["points"] == 3
    ws("settings", snap=True, grid=1.0)
    r = ws("input", device="locator", value={"position": [131, 47], "anchor": [100.4, 40.2],
                                             "tool": "line"})
    a, b = r.json()["result"]["text"].split(" from ")[1].split(" to ")
    assert a == "(8.00, 3.00)" and b == "(11.00, 4.00)"      # both ends on the grid
    assert ws("input", device="string", value={"position": [1, 1], "text": ""}).status_code == 422


def test_grid_gravity_and_constraints(ws):
    ws("settings", snap=True, grid=2.0)
    p = ws("position", position=[101, 61]).json()
    assert p["world"] == [8.0, 6.0] and p["applied"] == ["grid"]
    ws("settings", snap=False, constraint="horizontal")
    p = ws("position", position=[200, 100], anchor=[50, 40]).json()
    assert p["device"][1] == pytest.approx(40) and p["applied"] == ["horizontal"]
    ws("settings", constraint="auto")
    p = ws("position", position=[60, 140], anchor=[50, 40]).json()
    assert p["applied"] == ["vertical"] and p["device"][0] == pytest.approx(50)
    ws("settings", constraint="none", gravity=6)
    from scanline.studio.workstation import Workstation
    x, y = Workstation().device(6, 8)           # on the house's left wall, x = 6
    p = ws("position", position=[x - 4, y]).json()
    assert p["applied"] == ["gravity"] and p["world"][0] == pytest.approx(6)
    assert ws("settings", constraint="diagonal").status_code == 422
    assert ws("settings", grid=0).status_code == 422


def test_choice_and_the_three_input_modes(ws):
    r = ws("input", device="choice", value={"item": 4})
    assert r.json()["state"]["tool"] == "text"
    ws("settings", mode="event")
    r = ws("input", device="choice", value={"item": 2})
    assert r.json()["queued"] is True and r.json()["state"]["tool"] == "text"
    ws("input", device="valuator", value={"segment": "sun", "angle": 45})
    assert ws("input", device="choice", value={"item": 99}).status_code == 422  # refused, not queued
    r = ws("await")
    assert r.json()["event"]["device"] == "choice" and r.json()["state"]["tool"] == "rectangle"
    r = ws("await")
    assert r.json()["event"]["device"] == "valuator"
    assert ws("await").json()["event"] is None
    ws("settings", mode="request")
    r = ws("input", device="choice", value={"item": 1})
    assert r.status_code == 422 and "request the device first" in r.json()["error"]
    ws("request", device="choice")
    r = ws("input", device="choice", value={"item": 1})
    assert r.status_code == 200 and r.json()["state"]["tool"] == "line"
    assert ws("input", device="choice", value={"item": 2}).status_code == 422  # one request, one input


def test_drag_moves_a_segment(ws):
    r = ws("drag", segment="sun", delta=[-24, -12]).json()
    m = np.array(r["matrix"])
    from scanline.studio.workstation import Workstation
    w = Workstation()
    moved = sl.transform.apply(sl.viewing.ndc_to_device(480, 360) @ m @ w.df.normalization,
                               [(34, 25)])[0]
    assert np.allclose(moved, np.array(w.device(34, 25)) + [-24, -12])
    assert ws("drag", segment="sun", delta="x").status_code == 400       # a wrong type


def test_workstation_image_and_unknowns(client, ws):
    r = client.get(f"/api/ws/{ws.key}/image.png")
    assert r.status_code == 200 and r.content[:4] == b"\x89PNG"
    assert client.get("/api/ws/nope/state").status_code == 404
    assert ws("explode").status_code == 404


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(action=st.sampled_from(["input", "settings", "position", "request", "await", "drag", "delete"]),
       body=st.dictionaries(st.sampled_from(["device", "value", "mode", "grid", "snap", "segment",
                                             "position", "anchor", "delta", "gravity", "tool"]),
                            st.recursive(st.one_of(st.none(), st.booleans(), st.integers(-10**9, 10**9),
                                                   st.floats(allow_nan=False, allow_infinity=False),
                                                   st.text(max_size=5),
                                                   st.sampled_from(["locator", "pick", "house",
                                                                    "event", "sample"])),
                                         lambda c: st.lists(c, max_size=3) | st.dictionaries(
                                             st.sampled_from(["position", "item", "text", "angle",
                                                              "points", "segment", "tool"]), c,
                                             max_size=3), max_leaves=6), max_size=4))
def test_fuzzed_workstation_requests_never_crash(ws, action, body):
    r = ws(action, **body)
    assert r.status_code in (200, 400, 404, 422), r.text


# -- display devices ------------------------------------------------------------------
def test_raster_frames_and_info(client):
    info = client.get("/api/devices/raster/info?rate=50&interlaced=1").json()
    assert info["period"] == pytest.approx(0.02) and info["interlaced"] is True
    assert sum(e["pixels"] for e in info["color_table"]) == 256 * 256
    r = client.get("/api/devices/raster/frame?t=0.004&rate=50&interlaced=1")
    assert len(r.content) == 256 * 256 * 4
    x, y, state = r.headers["X-Beam"].split(",")
    from scanline.studio.devices import raster
    assert state == raster(50.0, True, 0.02).beam(0.004)[2]
    assert client.get("/api/devices/raster/plane/3.png").content[:4] == b"\x89PNG"
    assert client.get("/api/devices/raster/plane/8.png").status_code == 422


def test_random_scan_cycle_grows_with_lines(client):
    few = client.get("/api/devices/random/info?lines=0&speed=100000").json()
    many = client.get("/api/devices/random/info?lines=2000&speed=100000").json()
    assert many["lines"] == few["lines"] + 2000
    assert many["period"] > few["period"] and many["refresh_rate"] < few["refresh_rate"] <= 60


@pytest.mark.parametrize("kind, query, device", [
    ("penetration", "lines=10", "BeamPenetration"), ("shadow-mask", "arrangement=in-line",
                                                     "ShadowMask"),
    ("storage", "remove=sun", "StorageTube"), ("plasma", "rate=50", "PlasmaPanel"),
    ("lcd", "response=0.002", "LCD")])
def test_color_storage_and_flat_panel_devices(client, kind, query, device):
    from scanline.studio import devices

    info = client.get(f"/api/devices/{kind}/info?{query}").json()
    w, h = info["screen"]
    r = client.get(f"/api/devices/{kind}/frame?t=0.01&{query}")
    assert r.status_code == 200 and len(r.content) == w * h * 4
    sim = devices.simulation(kind, dict(p.split("=") for p in query.split("&")))
    assert type(sim).__name__ == device
    assert r.content == devices.frame(sim, 0.01)[0]
    assert r.headers["X-Beam"].split(",")[2] == sim.beam(0.01)[2]


def test_devices_page_text_is_readable_and_planes_are_explained(client):
    from scanline.studio import devices

    info = client.get("/api/devices/raster/info").json()
    assert info["bits_needed"] == 3 and info["plane_used"] == [True] * 3 + [False] * 5
    # the label is drawn in white on the dark blue screen
    table = [tuple(e["rgb"]) for e in info["color_table"] if e["pixels"]]
    assert (255, 255, 255) in table and (0, 0, 0) not in table
    assert devices.frame_buffer().color_table[0].tolist() == [25, 25, 112]


@pytest.mark.parametrize("query", ["rate=nan", "rate=-1", "lines=99999", "persistence=0",
                                   "interlaced=maybe", "t=abc", "speed=inf",
                                   "kind=shadow-mask&misconvergence=99",
                                   "kind=shadow-mask&arrangement=trinitron",
                                   "kind=storage&remove=moon", "kind=lcd&response=-1",
                                   "kind=plasma&rate=x"])
def test_bad_device_parameters(client, query):
    kind = "random" if "lines" in query or "speed" in query else "raster"
    if query.startswith("kind="):
        kind, query = query[5:].split("&")
    r = client.get(f"/api/devices/{kind}/frame?{query}")
    assert r.status_code == 422 and r.json()["error"]
    assert client.get("/api/devices/teletype/info").status_code == 404


def test_a_long_request_is_stopped_with_503(client, monkeypatch):
    from scanline.studio import server

    monkeypatch.setattr(server, "TIME_LIMIT", 0.05)
    slow = ["--knots", ",".join(map(str, range(20_000))), "--order", "150", "--u", "9000"]
    r = post(client, "cox-de-boor", slow)                     # seconds of work
    assert r.status_code == 503 and "longer than 0.05 s" in r.json()["error"]


def test_bresenham_views_plot_the_traced_pixels_in_every_direction():
    rng = np.random.default_rng(4)
    for a in rng.integers(-25, 26, (300, 4)).tolist() + [[3, 3, 3, 3], [0, 0, 0, 9], [5, 0, -5, 0]]:
        view = explorer.explore("bresenham", ["--", *map(str, a)])
        plotted = {tuple(p) for p in view["before"]} | {(r["x"], r["y"]) for r in explorer.rows_of(view)}
        assert plotted == sl.trace.bresenham(*a).pixels(), a
