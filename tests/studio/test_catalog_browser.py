"""Every algorithm of the explorer's catalog in a real headless Chromium: the list
comes from the server (``/api/algorithms``), so an algorithm added later is walked
by this test without editing it.

For each: the page loads it with its default arguments and is stepped to the end
(the first step forward by a click, the others by the button's click() in the page);
at every step the rule box names a rule, the table's current row is that step and
the grid shows drawing (pixels in the step colors, not only grid lines, gray
shapes and handles); the last row's cells are those that ``scanline trace ...
--format json`` prints for the command shown under the page (run in the test's
process); no request fails (4xx, 5xx or network), the console has no error or
warning, and the command shown runs in a shell exactly as shown.  Each explore
request's time is printed."""

import contextlib
import io
import json
import math
import os
import shlex
import subprocess
import sys

from scanline.cli import main

#: The canvas pixels in color that are not a handle: the background, grid lines,
#: labels, shapes and seed-fill walls and cells are gray, the handles and their
#: labels lie on the line from white to the handle color (anti-aliasing included).
COLORED_PIXELS = """() => {
    // read through a copy made for reading (the page's own context is not)
    const c = document.getElementById('grid'), copy = document.createElement('canvas');
    copy.width = c.width; copy.height = c.height;
    const ctx = copy.getContext('2d', {willReadFrequently: true});
    ctx.drawImage(c, 0, 0);
    const d = ctx.getImageData(0, 0, c.width, c.height).data;
    const h = [0xc2, 0x25, 0x5c], w = [255, 255, 255];
    let n = 0;
    for (let i = 0; i < d.length; i += 4) {
        const r = d[i], g = d[i + 1], b = d[i + 2];
        if (Math.max(r, g, b) - Math.min(r, g, b) < 40) continue;    // gray
        // on the segment from white to the handle color (a handle or its label)?
        const t = (255 - g) / (255 - h[1]);
        if (Math.abs(w[0] + t * (h[0] - w[0]) - r) < 12 &&
            Math.abs(w[2] + t * (h[2] - w[2]) - b) < 12) continue;
        n++;
    }
    return n;
}"""

#: What one step shows.
STEP = """() => ({rule: document.getElementById('rule').textContent,
                current: document.querySelector('table#table tr.current')?.dataset.step,
                counter: document.getElementById('counter').textContent,
                colored: (%s)()})""" % COLORED_PIXELS

#: What the present step and the ``k - 1`` after it show, stepped by the forward
#: button's click() in the page (its handler draws the step before it returns): one
#: round trip to the browser for the whole walk.
WALK = """(k) => {
    const step = %s, out = [step()];
    for (let j = 1; j < k; j++) {
        document.getElementById('forward').click();
        out.push(step());
    }
    return out;
}""" % STEP


def _environment():
    env = dict(os.environ)
    env["PATH"] = os.path.dirname(sys.executable) + os.pathsep + env.get("PATH", "")
    return env


def _same(shown, value):
    """Whether a table cell's text on the page shows the CLI's JSON value (numbers to
    the page's 6 decimals; a value JSON cannot carry is shown empty)."""
    if value is None:
        return shown == ""
    if isinstance(value, bool) or isinstance(value, str):
        return shown == str(value)
    if isinstance(value, (int, float)):
        if not math.isfinite(value):
            return shown in ("", "inf", "-inf", "nan")
        try:
            return abs(float(shown) - value) <= 1e-6 * max(1.0, abs(value))
        except ValueError:
            return False
    return shown == str(value)


def _walk(page, server, name, problems, timings):
    """Load ``name`` with its defaults, step to the end, run its command; what is
    wrong goes to ``problems``, the explore request's time to ``timings``."""
    bad_requests, console = [], []
    page.on("response", lambda r: bad_requests.append(f"{r.status} {r.url}")
            if r.status >= 400 else None)
    page.on("requestfailed", lambda r: bad_requests.append(f"failed {r.url}"))
    page.on("console", lambda m: console.append(f"{m.type}: {m.text}")
            if m.type in ("error", "warning") else None)
    try:
        _steps(page, server, name, problems, timings)
    finally:
        if bad_requests:
            problems.append(f"{name}: requests failed: {bad_requests}")
        if console:
            problems.append(f"{name}: console: {console}")


def _steps(page, server, name, problems, timings):
    page.goto(f"{server}/explorer?algorithm={name}")
    page.wait_for_function("document.body.dataset.ready || document.getElementById('error')"
                           ".textContent", timeout=30000)
    if not page.evaluate("document.body.dataset.ready"):
        problems.append(f"{name}: the default case is refused: {page.inner_text('#error')}")
        return
    view = page.evaluate("""() => { const v = window.explorer.state.view;
        return {algorithm: v.algorithm, title: v.title, count: v.count, columns: v.columns}; }""")
    timings[name] = page.evaluate("window.explorer.state.timing.fetch")
    if view["algorithm"] != name or view["count"] == 0:
        problems.append(f"{name}: the page shows {view['algorithm']!r} with {view['count']} steps")
        return
    n, failed = view["count"], {}
    states = [page.evaluate(STEP)]
    if n > 1:
        page.click("#forward")          # a click as a user makes it, then the rest in the page
        states += page.evaluate(WALK, n - 1)
    for i, s in enumerate(states):
        if s["current"] != str(i) or s["counter"] != f"step {i + 1} of {n}":
            failed.setdefault(f"current row {s['current']}, {s['counter']!r}", []).append(i)
        if not s["rule"].strip():
            failed.setdefault("the rule box is empty", []).append(i)
        if s["colored"] < 10:
            failed.setdefault("the grid shows no drawing", []).append(i)
    problems += [f"{name}: {what} at steps {steps[:5]}{' ...' if len(steps) > 5 else ''} "
                 f"({len(steps)} of {n})" for what, steps in failed.items()]
    shown = page.locator("table#table tr.current td").all_inner_texts()
    if page.locator("table#table th").all_inner_texts() != view["columns"]:
        problems.append(f"{name}: the table's header is not its columns {view['columns']}")

    command = page.inner_text("#command")
    ran = subprocess.run(command, shell=True, capture_output=True, text=True, timeout=120,
                         env=_environment())
    if ran.returncode != 0 or not ran.stdout.startswith(view["title"]):
        problems.append(f"{name}: {command!r} exits {ran.returncode}: {ran.stderr.strip()[-300:]}")
        return
    words = shlex.split(command)
    if words[:2] != ["scanline", "trace"]:
        problems.append(f"{name}: the command shown is not a scanline trace: {command!r}")
        return
    # the same command with --format json, run in this process (its code is the command
    # line's; a second interpreter start per algorithm took a third of the test's time)
    printed = io.StringIO()
    with contextlib.redirect_stdout(printed):
        status = main(words[1:3] + ["--format", "json"] + words[3:])
    if status != 0:
        problems.append(f"{name}: {command!r} with --format json exits {status}")
        return
    last = json.loads(printed.getvalue())[-1]
    wrong = [(c, t, last.get(c)) for c, t in zip(view["columns"], shown)
             if not _same(t, last.get(c))]
    if len(shown) != len(view["columns"]) or wrong:
        problems.append(f"{name}: the last row shows {shown}, the command line {last}: {wrong}")


def test_every_algorithm_of_the_catalog_works_in_the_browser(server, browser):
    catalog = browser.request.get(f"{server}/api/algorithms").json()
    assert len(catalog) >= 19
    problems, timings = [], {}
    for entry in catalog:
        page = browser.new_page()
        errors = []
        page.on("pageerror", lambda e: errors.append(str(e)))
        try:
            _walk(page, server, entry["name"], problems, timings)
        finally:
            page.close()
        if errors:
            problems.append(f"{entry['name']}: page errors {errors}")
    print("\nexplore request times (ms, in the browser, default cases):")
    for name, ms in timings.items():
        print(f"  {name:22s} {ms:8.1f}")
    assert not problems, "\n".join(problems)


def test_event_mode_takes_a_queued_choice_before_the_next_drag(server, browser):
    """Event mode: a menu choice waits in the queue; the drag that follows uses the
    tool chosen (the page takes the queued choice first), not the one before."""
    from .test_browser import screen_point

    page = browser.new_page()
    try:
        page.goto(f"{server}/workstation")
        page.wait_for_function("document.body.dataset.ready === '1'")
        page.click("#modes button[data-mode=event]")
        page.wait_for_function("window.workstation.state.mode === 'event'")
        page.click("#menu button[data-tool=rectangle]")
        page.wait_for_function("window.workstation.state.events.join() === 'choice'")
        assert page.evaluate("window.workstation.state.tool") == "line"
        page.mouse.move(*screen_point(page, 100, 40))
        page.mouse.down()
        page.mouse.move(*screen_point(page, 131, 60), steps=6)
        page.mouse.up()
        page.wait_for_function("window.workstation.state.events.join() === 'locator'")
        assert page.evaluate("window.workstation.state.tool") == "rectangle"
        page.click("#await")
        page.wait_for_function("window.workstation.state.events.length === 0")
        names = page.evaluate("window.workstation.state.segments.map((s) => s.name)")
        assert any(n.startswith("rectangle") for n in names), names
    finally:
        page.close()
