"""``scanline demo``: the gallery, its page and its pictures."""

import contextlib
import importlib
import io
import re

import pytest
from PIL import Image

from scanline.cli import demo, figures, main


@pytest.fixture(scope="module")
def gallery(tmp_path_factory):
    """Run ``scanline demo`` once (in-process) into a fresh folder."""
    out = tmp_path_factory.mktemp("demo") / "gallery"
    stdout = io.StringIO()
    with contextlib.redirect_stdout(stdout):
        code = main(["demo", "--out", str(out)])
    return out, code, stdout.getvalue()


def test_demo_writes_every_figure_gallery_and_page(gallery):
    out, code, stdout = gallery
    assert code == 0
    assert str(out) in stdout
    assert len(figures.FIGURES) == 13
    every = demo.all_figures()
    assert every[:13] == list(figures.FIGURES)  # the chapter 2 figures come first
    assert len(every) == sum(len(importlib.import_module(f"scanline.cli.{name}").FIGURES)
                             for name in demo.FIGURE_MODULES)
    pngs = sorted(p.name for p in out.glob("*.png"))
    assert "gallery.png" in pngs and len(pngs) == len(every) + 1
    for png in pngs:
        with Image.open(out / png) as image:
            image.verify()
    gifs = sorted(f"{name}.gif" for name, _ in demo.all_animations())
    assert len(gifs) >= 2       # the demo also writes short animations
    for gif in gifs:
        with Image.open(out / gif) as image:
            assert image.n_frames > 1
    assert sorted(p.name for p in out.iterdir()) == sorted(pngs + gifs + ["index.html"])


def test_page_shows_each_figure_with_caption_and_tables(gallery):
    out = gallery[0]
    page = (out / "index.html").read_text(encoding="utf-8")
    images = re.findall(r'<img src="([^"]+)"', page)
    n = len(demo.all_figures())
    assert len(images) == n == len(set(images)) and all((out / name).is_file() for name in images)
    assert page.count("<figcaption>") == n
    assert page.count("Notes, chapter") >= 13
    assert page.count("<pre>") >= 5  # Bresenham, DDA vs Bresenham, circle, ellipse, seed fill, ...
    for value in ("Bresenham line (20, 10) -&gt; (30, 18)", "Midpoint circle r = 10",
                  "Midpoint ellipse r_x = 8, r_y = 6", "-332",
                  "Scan-line seed fill from (1, 2)", "4-connected", "8-connected",
                  "left room (12 pixels)", "right room (22 pixels in all)",  # 4- vs 8-connected
                  "tile the disk exactly"):
        assert value in page
    assert "http" not in page  # self-contained


def test_demo_into_the_default_folder(run, tmp_path):
    result = run("demo", cwd=tmp_path)
    assert result.code == 0 and result.err == ""
    assert (tmp_path / demo.DEFAULT_DIR / "index.html").is_file()


def test_demo_into_a_file_fails_cleanly(call, one_line_error, tmp_path):
    (tmp_path / "taken").write_text("")
    one_line_error(call("demo", "--out", tmp_path / "taken"), "taken")
