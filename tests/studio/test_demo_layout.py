"""The demo page as a person sees it (issue 16, item 8): a responsive grid in headless
Chromium -- several figures side by side on a wide window, one column on a phone, no
sideways scrolling -- with a screenshot written beside the page to look at."""

import numpy as np
import pytest
from PIL import Image

from scanline.cli.demo import page
from scanline.gallery.primitives import Figure


@pytest.fixture
def demo_page(tmp_path):
    rng = np.random.default_rng(0)
    figures = []
    for i in range(12):
        w, h = (480, 320) if i % 3 else (900, 260)       # wide pictures shrink to fit
        Image.fromarray(rng.integers(0, 255, (h, w, 3), dtype=np.uint8)).save(tmp_path / f"f{i}.png")
        table = "\n".join(f"{k:2d}  {k * k:4d}" for k in range(40)) if i % 2 else None
        figures.append(Figure(f"f{i}", f"Figure {i}", "A caption with an en dash – " * 4,
                              "Notes, chapter 2", None, table))
    (tmp_path / "index.html").write_text(page(figures), encoding="utf-8")
    return tmp_path


def layout(page_, url, width):
    page_.set_viewport_size({"width": width, "height": 900})
    page_.goto(url)
    page_.wait_for_load_state("load")
    boxes = page_.eval_on_selector_all("main.gallery > section", "s => s.map(e => {"
                                       "const r = e.getBoundingClientRect();"
                                       "return [r.left, r.top, r.width, r.height]; })")
    overflow = page_.evaluate("document.documentElement.scrollWidth > window.innerWidth")
    images = page_.eval_on_selector_all("img", "i => i.map(e => [e.naturalWidth, "
                                        "e.getBoundingClientRect().width, e.parentElement"
                                        ".getBoundingClientRect().width])")
    return boxes, overflow, images


def test_wide_window_is_a_grid_and_a_phone_one_column(page, demo_page):
    url = (demo_page / "index.html").as_uri()
    boxes, overflow, images = layout(page, url, 1280)
    page.screenshot(path=str(demo_page / "wide.png"), full_page=True)
    columns = len({round(b[0]) for b in boxes})
    assert columns >= 3 and not overflow
    assert len({round(b[1]) for b in boxes[:columns]}) == 1          # a row shares its top
    assert all(0 < shown <= cell + 0.5 and natural > 0 for natural, shown, cell in images)
    rows = -(-len(boxes) // columns)
    assert page.evaluate("document.documentElement.scrollHeight") < rows * 1200
    boxes, overflow, images = layout(page, url, 390)
    page.screenshot(path=str(demo_page / "phone.png"))
    assert len({round(b[0]) for b in boxes}) == 1 and not overflow
    assert all(shown <= cell + 0.5 for _, shown, cell in images)
    shot = Image.open(demo_page / "wide.png")
    assert shot.width == 1280 and np.asarray(shot).std() > 10        # something was drawn
