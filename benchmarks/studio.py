"""Benchmark: the studio, measured in a real headless Chromium (Debian's, Playwright).

Issue targets (absolute, on this machine; there is no peer to compare with):

* an explorer round trip -- arguments sent, trace computed by ``sl.trace`` on the
  server, view returned, grid and table drawn -- under 50 ms for tables of up to
  10,000 rows (Bresenham lines of 10, 1,000 and 10,000 steps), measured in the page
  from the request to the end of drawing; a step (forward) on the 10,000-row table;
* the raster-scan simulation of a 256 x 256 frame buffer shown at 30 frames per
  second or more in the display-device page (each frame computed on the server by
  ``scanline.display.crt.RasterScan`` and drawn in the canvas).

Usage: ``python benchmarks/studio.py [--quick]``; writes
``benchmarks/results/studio.json``.  Timings on a shared machine are indicative.
"""

import argparse
import datetime as _dt
import json
import os
import platform
import socket
import statistics
import tempfile
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
         "--disable-component-update", "--disable-sync", "--no-first-run"]


def start_server():
    import uvicorn

    from scanline.studio.server import create_app

    sock = socket.socket()
    sock.bind(("127.0.0.1", 0))
    port = sock.getsockname()[1]
    sock.close()
    server = uvicorn.Server(uvicorn.Config(create_app(), host="127.0.0.1", port=port,
                                           log_level="warning"))
    threading.Thread(target=server.run, daemon=True).start()
    while not server.started:
        time.sleep(0.05)
    return server, f"http://127.0.0.1:{port}"


ROUND_TRIP = """async ([args, n]) => {
    const times = [], fetches = [], draws = [];
    for (let i = 0; i < n; i++) {
        const t0 = performance.now();
        await window.explorer.load('bresenham', args, false);
        times.push(performance.now() - t0);
        fetches.push(window.explorer.state.timing.fetch);
        draws.push(window.explorer.state.timing.draw);
    }
    return [times, fetches, draws];
}"""

STEP = """(n) => {
    const times = [];
    for (let i = 0; i < n; i++) {
        const t0 = performance.now();
        window.explorer.go(5000 + (i % 2));
        times.push(performance.now() - t0);
    }
    return times;
}"""


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args()
    from playwright.sync_api import sync_playwright

    server, url = start_server()
    repeats = 5 if args.quick else 20
    results = {"date": _dt.date.today().isoformat(), "machine": platform.processor() or
               platform.machine(), "python": platform.python_version(), "rows": []}
    with sync_playwright() as pw, tempfile.TemporaryDirectory() as profile:
        browser = pw.chromium.launch_persistent_context(
            profile, executable_path="/usr/bin/chromium", headless=True, args=FLAGS,
            viewport={"width": 1280, "height": 900})
        page = browser.new_page()
        page.goto(f"{url}/explorer")
        page.wait_for_function("document.body.dataset.ready")
        for steps in (10, 1000, 10000):
            line = ["0", "0", str(steps), "3"]
            page.evaluate(ROUND_TRIP, [line, 2])                     # warm: compile, caches
            times, fetches, draws = page.evaluate(ROUND_TRIP, [line, repeats])
            row = {"case": f"explorer round trip, {steps} rows", "median_ms": statistics.median(times),
                   "max_ms": max(times), "target_ms": 50,
                   "median_request_ms": statistics.median(fetches),
                   "median_draw_ms": statistics.median(draws)}
            results["rows"].append(row)
            print(f"  {row['case']:<36} median {row['median_ms']:7.1f} ms (request "
                  f"{row['median_request_ms']:.1f}, drawing {row['median_draw_ms']:.1f}), "
                  f"max {row['max_ms']:7.1f} ms")
        times = page.evaluate(STEP, repeats)
        row = {"case": "explorer step, 10000 rows", "median_ms": statistics.median(times),
               "max_ms": max(times), "target_ms": 50}
        results["rows"].append(row)
        print(f"  {row['case']:<36} median {row['median_ms']:7.1f} ms, max {row['max_ms']:7.1f} ms")

        page.goto(f"{url}/devices")
        page.wait_for_function("window.devices && window.devices.raster.total > 5", timeout=60000)
        seconds = 3 if args.quick else 8
        a = page.evaluate("[window.devices.raster.total, window.devices.random.total, performance.now()]")
        page.wait_for_timeout(seconds * 1000)
        b = page.evaluate("[window.devices.raster.total, window.devices.random.total, performance.now()]")
        elapsed = (b[2] - a[2]) / 1000
        for i, name in enumerate(("raster", "random")):
            fps = (b[i] - a[i]) / elapsed
            row = {"case": f"{name}-scan screen 256 x 256, both screens running",
                   "frames_per_second": fps, "target_fps": 30 if name == "raster" else None}
            results["rows"].append(row)
            print(f"  {row['case']:<52} {fps:6.1f} frames per second")
        browser.close()
    server.should_exit = True
    os.makedirs(os.path.join(HERE, "results"), exist_ok=True)
    with open(os.path.join(HERE, "results", "studio.json"), "w") as f:
        json.dump(results, f, indent=2)


if __name__ == "__main__":
    main()
