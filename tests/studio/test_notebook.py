"""The notebook widget (anywidget), without a Jupyter server: its traits, and its ESM
rendered in Chromium on a small harness page with a stand-in model (the calls
anywidget's front end makes: get, set, on, save_changes), from file:// with the
network refused."""

import base64
import json

import pytest

import scanline as sl

anywidget = pytest.importorskip("anywidget")

from scanline.studio import notebook  # noqa: E402
from scanline.studio.explorer import rows_of  # noqa: E402

HARNESS = """<!doctype html><html><head><meta charset="utf-8"><title>widget harness</title></head>
<body><h3>scanline.studio.explore(...) in a stand-in notebook cell</h3><div id="cell"></div>
<script type="module">
const data = %(state)s, listeners = {};
window.saved = [];
const model = {
  get: (k) => data[k],
  set: (k, v) => { data[k] = v; (listeners["change:" + k] || []).forEach((f) => f()); },
  on: (event, f) => { (listeners[event] = listeners[event] || []).push(f); },
  save_changes: () => window.saved.push(JSON.parse(JSON.stringify(data))),
};
window.model = model;
const widget = (await import("data:text/javascript;base64,%(esm)s")).default;
widget.render({model, el: document.getElementById("cell")});
</script></body></html>"""


def test_sl_studio_explore_builds_the_widget():
    import scanline.studio

    w = scanline.studio.explore("bresenham", 20, 10, 30, 18)
    assert isinstance(w, anywidget.AnyWidget) and isinstance(w, notebook.Explorer)
    assert (w.algorithm, w.args, w.quiz, w.step) == ("bresenham", ["20", "10", "30", "18"], False, 0)
    assert set(w.keys) >= {"algorithm", "args", "quiz", "step", "html"}
    assert "window.explorer" in w.html and "<script src=" not in w.html
    first = w.html
    w.args = ["0", "0", "5", "2"]
    assert w.html != first
    assert '"title":"Bresenham line (0, 0) -\\u003e (5, 2)"' in w.html
    assert '"quiz"' in scanline.studio.explore("dda", 0, 0, 3, 1, quiz=True).html


def test_bad_arguments_are_the_command_line_s_message():
    with pytest.raises(ValueError, match="the following arguments are required: X1, Y1"):
        notebook.explore("bresenham", 1, 2)
    with pytest.raises(ValueError, match="unknown algorithm 'bresenhm'"):
        notebook.explore("bresenhm", 1, 2, 3, 4)


def test_the_widget_s_esm_renders_the_explorer_offline(browser, page, tmp_path):
    w = notebook.explore("bresenham", 20, 10, 30, 18)
    state = {k: getattr(w, k) for k in ("algorithm", "args", "quiz", "step", "html")}
    harness = tmp_path / "harness.html"
    harness.write_text(HARNESS % {"state": json.dumps(state).replace("</", "<\\/"),
                                  "esm": base64.b64encode(w._esm.encode()).decode()})
    asked = []
    page.route("http*://**", lambda route: (asked.append(route.request.url), route.abort()))
    page.goto(harness.as_uri())
    frame = page.frame_locator("iframe")
    page.wait_for_function("() => { const f = document.querySelector('iframe'); return f && "
                           "f.contentWindow.explorer && f.contentWindow.document.body.dataset.ready; }",
                           timeout=30000)
    inner = page.frames[1]
    view = inner.evaluate("window.explorer.state.view")
    assert rows_of(view) == sl.trace.bresenham(20, 10, 30, 18).rows
    # the page steps: the model hears of it
    frame.locator("#forward").click()
    page.wait_for_function("window.saved.length > 0 && window.saved.at(-1).step === 1")
    # the model steps: the page follows
    page.evaluate("window.model.set('step', 4)")
    assert inner.evaluate("window.explorer.state.step") == 4
    assert frame.locator("tr.current").get_attribute("data-step") == "4"
    assert asked == []
    page.screenshot(path=str(tmp_path / "widget.png"), full_page=True)
