"""``scanline dither``: the written image equals sl.color.dither's result; bad input
gives one line on stderr, exit 2 and no file."""

import contextlib
import io

import numpy as np
import pytest
from PIL import Image

import scanline as sl
from scanline.cli import main


def call(*args):
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main([str(a) for a in args])
    return code, out.getvalue(), err.getvalue()


@pytest.fixture
def picture(tmp_path):
    y, x = np.mgrid[0:30, 0:50]
    rgb = np.dstack([x * 5, y * 8, 255 - x * 5]).astype(np.uint8)
    path = tmp_path / "in.png"
    Image.fromarray(rgb).save(path)
    return path, rgb


@pytest.mark.parametrize("options, expected", [
    ([], lambda rgb: sl.color.dither(rgb)),
    (["--method", "bayer4", "--levels", "4"], lambda rgb: sl.color.dither(rgb, "bayer4", levels=4)),
    (["--levels", "2", "--color"], lambda rgb: sl.color.dither(rgb, levels=2, mode="RGB")),
    (["--palette", "web", "--serpentine"],
     lambda rgb: sl.color.dither(rgb, palette=sl.color.web_safe_table(), serpentine=True)),
    (["--palette", "gray:3", "--method", "bayer8"],
     lambda rgb: sl.color.dither(rgb, "bayer8", palette=sl.color.gray_table(3))),
    (["--palette", "black, white ,#ff0000"],
     lambda rgb: sl.color.dither(rgb, palette=["black", "white", "red"])),
    (["--palette", "median-cut:6"],
     lambda rgb: sl.color.dither(rgb, palette=sl.color.median_cut_table(rgb, 6))),
])
def test_written_image_is_the_dithered_image(tmp_path, picture, options, expected):
    source, rgb = picture
    out = tmp_path / "out.png"
    code, stdout, stderr = call("dither", source, out, *options)
    assert (code, stderr) == (0, "")
    assert "wrote" in stdout
    fb = expected(rgb)
    with Image.open(out) as written:
        assert written.mode == fb.mode
        assert (np.asarray(written.convert("RGB")) == np.asarray(fb.to_pil().convert("RGB"))).all()


@pytest.mark.parametrize("make_args, words", [
    (lambda d, src: [d / "missing.png", d / "o.png"], "No such file"),
    (lambda d, src: [d / "bad.png", d / "o.png"], "cannot identify"),
    (lambda d, src: [src, d / "o.png", "--levels", "1"], "levels=1"),
    (lambda d, src: [src, d / "o.png", "--levels", "300"], "levels=300"),
    (lambda d, src: [src, d / "o.png", "--palette", "gray"], "gray:16"),
    (lambda d, src: [src, d / "o.png", "--palette", "red,nocolor"], "nocolor"),
    (lambda d, src: [src, d / "o.png", "--palette", "web", "--levels", "4"], "not both"),
    (lambda d, src: [src, d / "o.png", "--method", "atkinson"], "invalid choice"),
    (lambda d, src: [src, d / "o.xyz"], "unknown image type"),   # JPEG is written since issue 16
    (lambda d, src: [src, d / "no" / "o.png"], "does not exist"),
    (lambda d, src: [d, d / "o.png"], "is not a readable image"),   # a folder
    (lambda d, src: [src, d / "o.png", "--scale", "100000"], "smaller --scale"),
    (lambda d, src: [src, d / "folder.png"], "is a folder"),
])
def test_bad_input(tmp_path, picture, make_args, words):
    (tmp_path / "bad.png").write_bytes(b"not an image")
    (tmp_path / "folder.png").mkdir()
    before = set(tmp_path.rglob("*"))
    code, stdout, stderr = call("dither", *make_args(tmp_path, picture[0]))
    assert code == 2
    assert stderr.startswith("scanline: error:") and stderr.count("\n") == 1
    assert words in stderr
    assert set(tmp_path.rglob("*")) == before     # nothing written, not even a temp file
