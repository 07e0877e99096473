"""Fixtures of the studio tests: the application in-process (Starlette's test
client), a real server on a free loopback port, and a real headless Chromium."""

import os
import shutil
import socket
import tempfile
import threading
import time

import pytest

from scanline.studio.server import create_app

CHROMIUM = os.environ.get("SCANLINE_CHROMIUM", "/usr/bin/chromium")
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
         "--disable-component-update", "--disable-sync", "--no-first-run"]


@pytest.fixture(scope="session")
def client():
    from starlette.testclient import TestClient

    # the studio's pages send their Origin with every POST (and the server wants it)
    with TestClient(create_app(), base_url="http://127.0.0.1",
                    headers={"Origin": "http://127.0.0.1"}) as c:
        yield c


@pytest.fixture(scope="session")
def server():
    """The studio served by uvicorn on 127.0.0.1 in a thread; yields its base URL."""
    import uvicorn

    sock = socket.socket()
    sock.bind(("127.0.0.1", 0))
    port = sock.getsockname()[1]
    sock.close()
    config = uvicorn.Config(create_app(), host="127.0.0.1", port=port, log_level="warning")
    srv = uvicorn.Server(config)
    thread = threading.Thread(target=srv.run, daemon=True)
    thread.start()
    deadline = time.time() + 30
    while not srv.started:
        if time.time() > deadline:
            raise RuntimeError("the studio server did not start in 30 s")
        time.sleep(0.05)
    yield f"http://127.0.0.1:{port}"
    srv.should_exit = True
    thread.join(10)


def _no_browser(reason):
    """A browser test that cannot start its browser: a failure in CI, a skip elsewhere."""
    if os.environ.get("CI") == "true":
        pytest.fail(f"headless Chromium is needed in CI: {reason}")
    pytest.skip(f"headless Chromium not available: {reason}")


@pytest.fixture(scope="session")
def browser():
    """Debian's Chromium, headless, driven by Playwright (no browser download), with a
    fresh profile folder."""
    try:
        from playwright.sync_api import sync_playwright
    except ImportError as error:
        _no_browser(f"playwright is not installed ({error})")
    if not os.path.exists(CHROMIUM):
        _no_browser(f"{CHROMIUM} does not exist (apt-get install chromium)")
    profile = tempfile.mkdtemp(prefix="scanline-chromium-")
    pw = sync_playwright().start()
    try:
        context = pw.chromium.launch_persistent_context(
            profile, executable_path=CHROMIUM, headless=True, args=FLAGS,
            viewport={"width": 1280, "height": 900})
    except Exception as error:  # noqa: BLE001 - any launch failure is reported
        pw.stop()
        shutil.rmtree(profile, ignore_errors=True)
        _no_browser(str(error).splitlines()[0])
    yield context
    context.close()
    pw.stop()
    shutil.rmtree(profile, ignore_errors=True)


@pytest.fixture
def page(browser):
    p = browser.new_page()
    errors = []
    p.on("pageerror", lambda e: errors.append(str(e)))
    yield p
    p.close()
    assert not errors, errors
