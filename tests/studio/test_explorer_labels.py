"""The explorer's axis labels stay few however far apart a case's points are (a
segment from x = -1e9 to 1e9 once drew 2e7 labels per frame and stalled the page)."""

from .test_browser import wait_ready

COUNT_LABELS = """
window.labels = 0;
const fillText = CanvasRenderingContext2D.prototype.fillText;
CanvasRenderingContext2D.prototype.fillText = function (...a) { window.labels += 1; return fillText.apply(this, a); };
"""


def test_a_billion_wide_case_draws_few_labels(server, page):
    page.add_init_script(COUNT_LABELS)
    page.goto(f"{server}/explorer?algorithm=cohen-sutherland&args=-1000000000 2 1000000000 12")
    wait_ready(page)
    assert page.evaluate("window.explorer.state.view.bounds") == [-1000000002, -2, 1000000002, 14]
    drawn = page.evaluate("window.labels")
    # one frame: about 40 labels along x, one or two along y
    assert 2 <= drawn <= 60
    page.evaluate("window.labels = 0")
    page.click("#forward")
    assert 2 <= page.evaluate("window.labels") <= 60
