"""The studio's pages in a real headless Chromium (Debian's, driven by Playwright):
what the explorer highlights is sl.trace's table, dragging re-traces, the
workstation's pick, valuator and string devices reach the server's display file,
and the explain page works from file:// with the network off."""

import re

import numpy as np
import pytest

import scanline as sl
from scanline.studio.workstation import Workstation

PLOTTED, CURRENT = (0x1c, 0x7e, 0xd6), (0xf7, 0x67, 0x07)


def wait_ready(page, before=None):
    page.wait_for_function("(b) => document.body.dataset.ready && document.body.dataset.ready !== b",
                           arg=before, timeout=30000)


def cell_colors(page, pixels):
    """The canvas color of each device pixel's cell, sampled up and left of its center
    (the center may carry a handle; the line through the centers runs the other way)."""
    return [tuple(c) for c in page.evaluate("""(pixels) => {
        const ctx = document.getElementById('grid').getContext('2d');
        return pixels.map(([x, y]) => {
            const [cx, cy] = window.explorer.cellCenter(x, y), c = window.explorer.state.geometry.cell;
            return Array.from(ctx.getImageData(Math.round(cx - 0.3 * c), Math.round(cy - 0.3 * c),
                                               1, 1).data.slice(0, 3));
        });
    }""", [list(p) for p in pixels])]


def canvas_point(page, x, y):
    """Page coordinates of device pixel (x, y)'s center on the explorer's canvas."""
    box = page.locator("#grid").bounding_box()
    cx, cy = page.evaluate("([x, y]) => window.explorer.cellCenter(x, y)", [x, y])
    w = page.evaluate("document.getElementById('grid').width")
    return box["x"] + cx * box["width"] / w, box["y"] + cy * box["width"] / w


def test_explorer_steps_through_bresenham(server, page):
    page.goto(f"{server}/explorer?algorithm=bresenham&args=20 10 30 18")
    wait_ready(page)
    t = sl.trace.bresenham(20, 10, 30, 18)
    (x0, y0, x1, y1) = page.evaluate("window.explorer.state.view.bounds")
    everything = [(x, y) for x in range(x0, x1 + 1) for y in range(y0, y1 + 1)]
    for i, row in enumerate(t.rows):
        if i:
            page.click("#forward")
        current = page.locator("table#table tr.current")
        assert current.get_attribute("data-step") == str(i)
        cells = current.locator("td").all_inner_texts()
        assert cells == [str(row[c]) for c in t.columns]
        assert page.inner_text("#counter") == f"step {i + 1} of {len(t.rows)}"
        # the pixels: the start pixel and rows 0..i-1 plotted, row i highlighted, no other
        colors = dict(zip(everything, cell_colors(page, everything)))
        plotted = {(20, 10)} | {(r["x"], r["y"]) for r in t.rows[:i]}
        assert {p for p, c in colors.items() if c == CURRENT} == {(row["x"], row["y"])}
        assert {p for p, c in colors.items() if c == PLOTTED} == plotted
    page.click("#back")
    assert page.locator("tr.current").get_attribute("data-step") == str(len(t.rows) - 2)
    page.click("#first")
    assert page.locator("tr.current").get_attribute("data-step") == "0"


def test_dragging_an_endpoint_traces_the_new_line(server, page):
    page.goto(f"{server}/explorer?algorithm=bresenham&args=20 10 30 18")
    wait_ready(page)
    sx, sy = canvas_point(page, 30, 18)
    tx, ty = canvas_point(page, 26, 21)
    page.mouse.move(sx, sy)
    page.mouse.down()
    page.mouse.move(tx, ty, steps=8)
    page.mouse.up()
    page.wait_for_function("window.explorer.state.view.title === 'Bresenham line (20, 10) -> (26, 21)'"
                           " && !window.explorer.state.busy", timeout=30000)
    t = sl.trace.bresenham(20, 10, 26, 21)
    rows = page.locator("table#table tr[data-step]")
    assert rows.count() == len(t.rows)
    for i, row in enumerate(t.rows):
        assert rows.nth(i).locator("td").all_inner_texts() == [str(row[c]) for c in t.columns]
    assert page.input_value("#args") == "20 10 26 21"


def test_typed_arguments_and_errors(server, page):
    page.goto(f"{server}/explorer?algorithm=midpoint-circle")
    wait_ready(page)
    before = page.evaluate("document.body.dataset.ready")
    page.fill("#args", "5 --center 3 3")
    page.click("#run")
    wait_ready(page, before)
    assert page.locator("tr[data-step]").count() == len(sl.trace.midpoint_circle(5).rows)
    page.fill("#args", "5 --center 3 x")
    page.click("#run")
    page.wait_for_function("document.getElementById('error').textContent.length > 0")
    assert "argument --center: 'x' is not an integer" in page.inner_text("#error")


def ws_state(page, server):
    key = page.evaluate("window.workstation.id")
    return page.request.get(f"{server}/api/ws/{key}/state").json()


def screen_point(page, x, y):
    box = page.locator("#overlay").bounding_box()
    return box["x"] + (x + 0.5) * box["width"] / 480, box["y"] + (359.5 - y) * box["height"] / 360


def test_workstation_pick_valuator_and_string(server, page):
    page.goto(f"{server}/workstation")
    page.wait_for_function("document.body.dataset.ready === '1'")
    here = Workstation()
    # pick: click a pixel that the tree's canopy drew
    fb = sl.FrameBuffer(480, 360, background="white")
    here.df.draw(fb)
    a = fb.to_array()[::-1]
    ys, xs = np.nonzero((a == (34, 139, 34)).all(axis=2))
    x, y = int(xs[len(xs) // 2]), int(ys[len(ys) // 2])
    page.click("#menu button[data-tool=pick]")
    page.wait_for_function("window.workstation.state.tool === 'pick'")
    page.mouse.click(*screen_point(page, x, y))
    page.wait_for_function("window.workstation.state.selected === 'tree'")
    state = ws_state(page, server)
    assert state["selected"] == "tree"
    assert [s["name"] for s in state["segments"] if s["highlighted"]] == ["tree"]
    assert "segment 'tree', pick id 2" in page.inner_text("#picked")

    # valuator: turn the sun by 40 degrees
    page.select_option("#segment", "sun")
    page.fill("#valuator", "40")
    page.dispatch_event("#valuator", "input")
    page.wait_for_function("window.workstation.state.segments.find(s => s.name === 'sun').angle === 40")
    sun = next(s for s in ws_state(page, server)["segments"] if s["name"] == "sun")
    here._turns["sun"] = 40.0
    here._transform("sun")
    assert np.allclose(sun["matrix"], here.df.segment("sun").transformation, atol=1e-6)

    # string: type a text and place it
    page.click("#menu button[data-tool=text]")
    page.wait_for_function("window.workstation.state.tool === 'text'")
    page.fill("#string", "Hello <GKS> & co")
    page.mouse.click(*screen_point(page, 40, 40))
    page.wait_for_function("window.workstation.state.segments.some(s => s.name.startsWith('text-'))")
    state = ws_state(page, server)
    assert any(line.startswith("string: text-") and "'Hello <GKS> & co'" in line
               for line in state["log"])
    assert "Hello <GKS> & co" in page.inner_text("#log")      # shown as text, not markup


def test_workstation_rubber_band_line_on_the_grid(server, page):
    page.goto(f"{server}/workstation")
    page.wait_for_function("document.body.dataset.ready === '1'")
    page.check("#snap")
    page.wait_for_function("window.workstation.state.snap === true")
    page.click("#menu button[data-tool=line]")
    page.mouse.move(*screen_point(page, 100.4, 40.2))
    page.mouse.down()
    page.mouse.move(*screen_point(page, 131, 47), steps=6)
    page.mouse.up()
    page.wait_for_function("window.workstation.state.segments.some(s => s.name.startsWith('line-'))")
    log = ws_state(page, server)["log"][0]
    assert re.search(r"line line-\d+ from \(8\.00, 3\.00\) to \(11\.00, 4\.00\)", log), log


def test_explain_page_works_offline_from_file(tmp_path, browser):
    from scanline.cli import main

    out = tmp_path / "dda.html"
    assert main(["explain", "dda", "2", "3", "14", "9", "-o", str(out)]) == 0
    text = out.read_text()
    assert "http://" not in text and "https://" not in text and 'src="/' not in text
    browser.set_offline(True)
    requests = []
    page = browser.new_page()
    page.on("request", lambda r: requests.append(r.url))
    try:
        page.goto(out.as_uri())
        wait_ready(page)
        t = sl.trace.dda(2, 3, 14, 9)
        page.click("#last")
        assert page.locator("tr.current").get_attribute("data-step") == str(len(t.rows) - 1)
        assert page.locator("#editor").is_hidden()
        colors = cell_colors(page, sorted(t.pixels()))
        assert all(c in (PLOTTED, CURRENT) for c in colors)
    finally:
        page.close()
        browser.set_offline(False)
    assert all(u.startswith(("file:", "data:")) for u in requests), requests


def test_devices_page_animates_both_screens(server, page):
    page.goto(f"{server}/devices")
    page.wait_for_function("window.devices && window.devices.raster.t > 0 && window.devices.random.t > 0",
                           timeout=30000)
    page.wait_for_timeout(500)
    lit = page.evaluate("""() => ['raster', 'random'].map((id) => {
        const d = document.getElementById(id).getContext('2d').getImageData(0, 0, 256, 256).data;
        let n = 0; for (let i = 0; i < d.length; i += 4) if (d[i] + d[i + 1] + d[i + 2] > 60) n++;
        return n; })""")
    assert lit[0] > 1000 and lit[1] > 50
    assert "refresh period 16.67 ms" in page.inner_text("#raster-info")
    assert page.locator("#planes img").count() == 8
    captions = page.locator("#planes figcaption").all_inner_texts()
    assert captions[0] == "bit 0 (value 1)" and captions[7] == "bit 7 (value 128): all 0"
    assert page.locator("#planes figure.unused").count() == 5
    assert "need 3 of the 8 bit planes" in page.inner_text("#planes-notes")


@pytest.mark.parametrize("kind", ["penetration", "shadow-mask", "storage", "plasma", "lcd"])
def test_devices_page_steps_each_color_and_flat_panel_display(server, page, kind):
    errors = []
    page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
    page.goto(f"{server}/devices")
    page.wait_for_function("window.devices && window.devices.device.t > 0", timeout=30000)
    page.select_option("#kind", kind)
    page.wait_for_function(f"window.devices.device.kind === '{kind}' && "
                           "window.devices.device.t > 0.002", timeout=30000)
    page.wait_for_timeout(700)
    size, lit = page.evaluate("""() => { const c = document.getElementById('device');
        const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
        let n = 0; for (let i = 0; i < d.length; i += 4) if (d[i] + d[i + 1] + d[i + 2] > 60) n++;
        return [[c.width, c.height], n]; }""")
    info = page.evaluate(f"fetch('/api/devices/{kind}/info').then((r) => r.json())")
    assert size == info["screen"] and lit > 50
    assert page.locator(f"[data-for='{kind}']").count() == 0 or \
        page.locator(f"[data-for='{kind}']").is_visible()
    assert page.inner_text("#kind-notes") and page.inner_text("#device-info")
    assert not errors
