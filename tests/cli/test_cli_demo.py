"""``scanline demo``: the gallery, its page and its pictures."""

import importlib
import re

import pytest
from PIL import Image

from scanline.cli import demo
from scanline.gallery import primitives as figures


@pytest.fixture(scope="module")
def gallery(run, tmp_path_factory):
    """Run ``scanline demo`` once, as a user would: a subprocess in a fresh folder,
    writing into the default folder; (that folder, the run's :class:`Result`)."""
    cwd = tmp_path_factory.mktemp("demo")
    return cwd / demo.DEFAULT_DIR, run("demo", cwd=cwd)


def test_demo_writes_every_figure_gallery_and_page(gallery):
    out, result = gallery
    assert result.code == 0
    assert str(out / "index.html") in result.out
    assert len(figures.FIGURES) == 13
    every = demo.all_figures()
    assert every[:13] == list(figures.FIGURES)  # the chapter 2 figures come first
    assert len(every) == sum(len(importlib.import_module(f"scanline.gallery.{name}").FIGURES)
                             for name in demo.FIGURE_MODULES)
    pngs = sorted(p.name for p in out.glob("*.png"))
    assert "gallery.png" in pngs and len(pngs) == len(every) + 1
    for png in pngs:
        with Image.open(out / png) as image:
            image.verify()
    gifs = sorted(p.name for p in out.glob("*.gif"))
    assert len(gifs) == sum(demo.all_animations().values()) >= 2   # short animations too
    for gif in gifs:
        with Image.open(out / gif) as image:
            assert image.n_frames > 1
    assert sorted(p.name for p in out.iterdir()) == sorted(pngs + gifs + [
        "index.html", "explain-bresenham.html"])


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
    assert not re.search(r'src="https?:', page)  # self-contained: nothing loaded from a server
    # the links to the interactive half: the explain page beside it and the local studio
    assert 'href="explain-bresenham.html"' in page
    assert set(re.findall(r'href="(https?://[^/"]+)', page)) == {"http://127.0.0.1:8765"}
    explain = (out / "explain-bresenham.html").read_text(encoding="utf-8")
    assert r"Bresenham line (20, 10) -\u003e (30, 18)" in explain and 'src="http' not in explain


def test_demo_says_what_it_draws(gallery):
    folder, result = gallery
    assert result.code == 0
    # stderr, not a terminal here: what it is doing, then one plain line per figure
    # or animation (item k of n, its name, the time so far) -- nothing else
    n = len(demo.all_figures())
    m = sum(demo.all_animations().values())
    lines = result.err.splitlines()
    assert lines[0].startswith(f"scanline demo: drawing {n} figures and {m} animations with ")
    progress = [re.fullmatch(r"scanline demo: (\d+)/(\d+) (\S+) \((\d+\.\d) s\)", line)
                for line in lines[1:]]
    assert all(progress) and len(progress) == n + m
    assert [int(p[1]) for p in progress] == list(range(1, n + m + 1))
    assert {int(p[2]) for p in progress} == {n + m}
    files = {p.stem for p in folder.glob("*.png")} - {"gallery"}
    assert {p[3] for p in progress} == files | {p.name for p in folder.glob("*.gif")}
    times = [float(p[4]) for p in progress]
    assert times == sorted(times)


def test_demo_in_two_processes_writes_the_same_gallery(gallery, call, tmp_path):
    out = tmp_path / "two"
    result = call("demo", "--out", out, "--jobs", "2")
    assert result.code == 0
    serial = sorted(p.name for p in gallery[0].iterdir())
    assert sorted(p.name for p in out.iterdir()) == serial
    for name in serial:
        if name.endswith(".png") and name != "gallery.png":
            with Image.open(out / name) as a, Image.open(gallery[0] / name) as b:
                assert a.size == b.size, name
    # the page lists the figures in gallery order whichever process drew them
    assert re.findall(r'<img src="([^"]+)"', (out / "index.html").read_text()) == \
        re.findall(r'<img src="([^"]+)"', (gallery[0] / "index.html").read_text())


@pytest.mark.parametrize("jobs", ["0", "-1", "two", "1.5"])
def test_demo_jobs_must_be_a_whole_number(call, one_line_error, tmp_path, jobs):
    one_line_error(call("demo", "--out", tmp_path / "x", "--jobs", jobs), "--jobs")
    assert not (tmp_path / "x").exists()


def test_demo_into_a_file_fails_cleanly(call, one_line_error, tmp_path):
    (tmp_path / "taken").write_text("")
    one_line_error(call("demo", "--out", tmp_path / "taken"), "taken")


def test_a_gallery_module_runs_alone(tmp_path):
    """``python -m scanline.gallery.curves -o DIR`` writes that chapter's figures."""
    import subprocess
    import sys

    proc = subprocess.run([sys.executable, "-m", "scanline.gallery.curves", "-o", str(tmp_path)],
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr[-3000:]
    pngs = sorted(p.name for p in tmp_path.iterdir())
    assert pngs == sorted(["de-casteljau.png", "bspline-blending.png", "hermite-splines.png",
                           "nurbs-circle.png"])
    assert "de Casteljau's construction at u = 0.5" in proc.stdout
