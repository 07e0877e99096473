"""numpy and Pillow interop (issue 16, item 1): the array protocol, float and
(h, w, 1) arrays, FrameBuffer.open and save in every Pillow format, to paths and file
objects, the notebook preview, and the refusals of bad files.

Expected values come from numpy and Pillow directly, or are written out by hand.
"""

import io
import os
import struct
import zlib

import numpy as np
import pytest
from PIL import Image

import scanline as sl
from scanline import FrameBuffer, ImageFileError, ScanlineError
from tests.reference import peer

TABLE = [(0, 0, 0), (255, 0, 0), (0, 255, 0), (0, 0, 255)]


def sample(mode, h=5, w=11, seed=0):
    rng = np.random.default_rng(seed)
    if mode == "1":
        return FrameBuffer.from_array(rng.random((h, w)) < 0.5)
    if mode == "L":
        return FrameBuffer.from_array(rng.integers(0, 256, (h, w), dtype=np.uint8))
    if mode == "P":
        return FrameBuffer.from_array(rng.integers(0, 4, (h, w), dtype=np.uint8), mode="P",
                                      color_table=TABLE)
    return FrameBuffer.from_array(rng.integers(0, 256, (h, w, len(mode)), dtype=np.uint8))


# -- the array protocol -------------------------------------------------------------------
@pytest.mark.parametrize("mode", ["1", "L", "P", "RGB", "RGBA"])
def test_asarray_is_the_image_in_image_order(mode):
    fb = sample(mode)
    a = np.asarray(fb)
    assert a.dtype != object and a.shape == fb.to_array().shape
    assert np.array_equal(a, fb.to_array())
    assert a.dtype == (bool if mode == "1" else np.uint8)


def test_asarray_bottom_left_pixel_is_the_last_row():
    fb = FrameBuffer(3, 2, mode="RGB")
    fb.set_pixel(0, 0, (1, 2, 3))
    assert np.asarray(fb)[1, 0].tolist() == [1, 2, 3]
    assert np.asarray(fb)[0].tolist() == [[0, 0, 0]] * 3


@pytest.mark.parametrize("mode", ["L", "P", "RGB", "RGBA"])
def test_asarray_shares_memory_read_only_and_array_copies(mode):
    fb = sample(mode)
    view = np.asarray(fb)
    assert np.shares_memory(view, fb._buf) and not view.flags.writeable
    fb.set_pixel(0, fb.height - 1, 3)                # the top-left pixel, row 0
    assert np.array_equal(view, fb.to_array())        # the view follows the drawing
    copy = np.array(fb)
    assert copy.flags.writeable and not np.shares_memory(copy, fb._buf)
    copy[...] = 1
    assert not np.array_equal(copy, fb.to_array())
    assert np.asarray(fb, dtype=np.float64).dtype == np.float64


def test_mode_1_cannot_be_viewed_without_a_copy():
    fb = sample("1")
    assert np.array_equal(np.asarray(fb), fb.to_array())
    with pytest.raises(ValueError):
        np.asarray(fb, copy=False)
    with pytest.raises(ValueError):
        np.asarray(sample("L"), dtype=np.float32, copy=False)
    assert np.asarray(sample("L"), copy=False).dtype == np.uint8


def test_pillow_and_numpy_functions_take_a_frame_buffer():
    fb = sample("RGB")
    assert np.array_equal(np.array(Image.fromarray(np.asarray(fb))), fb.to_array())
    assert np.mean(fb) == pytest.approx(fb.to_array().mean())


# -- from_array: floats and (h, w, 1) -----------------------------------------------------
def test_from_array_reads_floats_in_unit_range():
    a = np.array([[0.0, 0.5, 1.0], [0.2, 1 / 255, 0.998]])
    fb = FrameBuffer.from_array(a)
    assert fb.mode == "L"
    # floor(255 v + 0.5): 0, 128 (127.5), 255; 51, 1, 254 (254.49)
    assert fb.to_array().tolist() == [[0, 128, 255], [51, 1, 254]]
    rgb = FrameBuffer.from_array(np.full((2, 2, 3), 0.25, np.float32))
    assert rgb.mode == "RGB" and (rgb.to_array() == 64).all()      # 63.75 -> 64
    rgba = FrameBuffer.from_array(np.dstack([np.zeros((1, 1, 3)), np.full((1, 1), 0.5)]))
    assert rgba.mode == "RGBA" and rgba.get_pixel(0, 0) == (0, 0, 0, 128)


@pytest.mark.parametrize("dtype", [np.uint8, bool, np.float64])
def test_from_array_reads_a_single_channel_last_axis(dtype):
    a = (np.arange(6).reshape(2, 3) % 2).astype(dtype)
    fb = FrameBuffer.from_array(a[:, :, None])
    assert fb.mode == ("1" if dtype is bool else "L")
    assert np.array_equal(fb.to_array(), FrameBuffer.from_array(a).to_array())


def test_matplotlib_imshow_arrays_round_trip(tmp_path):
    mpl_image = peer("matplotlib.image")
    fb = sample("RGB")
    fb.save(tmp_path / "x.png")
    a = mpl_image.imread(tmp_path / "x.png")          # float32 in [0, 1]
    assert a.dtype == np.float32
    assert np.array_equal(FrameBuffer.from_array(a).to_array(), fb.to_array())


@pytest.mark.parametrize("array, words", [
    (np.array([[0.0, 1.5]]), ["0..1.5", "[0, 1]", "divide by 255"]),
    (np.array([[0.0, 255.0]]), ["0..255", "integer dtype"]),
    (np.array([[0.0, -0.1]]), ["-0.1", "[0, 1]"]),
    (np.array([[0.0, np.nan]]), ["nan", "finite"]),
    (np.array([[0, 256]], np.int32), ["0..256", "0..255"]),
    (np.array([[0, 40000]], np.uint16), ["16-bit"]),
    (np.array([["a", "b"]]), ["dtype <U1"]),
    (np.zeros((2, 2, 2)), ["(h, w, 3)"]),
])
def test_from_array_refuses_values_it_cannot_read(array, words):
    with pytest.raises(sl.ArgumentValueError) as e:
        FrameBuffer.from_array(array)
    for w in words:
        assert w in str(e.value), (w, str(e.value))


def test_from_array_refuses_floats_as_color_table_indices():
    with pytest.raises(sl.ArgumentValueError, match="indices"):
        FrameBuffer.from_array(np.zeros((2, 2)), mode="P", color_table=TABLE)


# -- open ---------------------------------------------------------------------------------
FORMATS = [("PNG", ".png"), ("JPEG", ".jpg"), ("WEBP", ".webp"), ("TIFF", ".tif"),
           ("GIF", ".gif"), ("BMP", ".bmp")]


@pytest.mark.parametrize("fmt, ext", FORMATS)
def test_open_reads_what_pillow_wrote(tmp_path, fmt, ext):
    a = np.random.default_rng(1).integers(0, 256, (6, 9, 3), dtype=np.uint8)
    path = tmp_path / f"x{ext}"
    Image.fromarray(a).save(path, format=fmt)
    fb = FrameBuffer.open(path)
    with Image.open(path) as im:
        expected = np.array(im.convert("RGB") if im.mode not in ("RGB", "P") else im)
    if fb.mode == "P":
        assert np.array_equal(np.array(fb.color_table)[fb.to_array()], np.array(Image.open(path).convert("RGB")))
    else:
        assert fb.mode == "RGB" and np.array_equal(fb.to_array(), expected)
    with open(path, "rb") as f:                      # a binary file object too
        assert np.array_equal(FrameBuffer.open(f).to_array(), fb.to_array())
    assert np.array_equal(FrameBuffer.open(io.BytesIO(path.read_bytes())).to_array(),
                          fb.to_array())


def test_open_converts_the_other_pillow_modes(tmp_path):
    la = Image.fromarray(np.dstack([np.full((2, 2), 10, np.uint8), np.full((2, 2), 99, np.uint8)]), "LA")
    la.save(tmp_path / "la.png")
    fb = FrameBuffer.open(tmp_path / "la.png")
    assert fb.mode == "RGBA" and fb.get_pixel(0, 0) == (10, 10, 10, 99)
    gray16 = np.array([[0, 256], [65535, 4095]], np.uint16)
    Image.fromarray(gray16).save(tmp_path / "g16.png")
    fb = FrameBuffer.open(tmp_path / "g16.png")
    assert fb.mode == "L" and fb.to_array().tolist() == [[0, 1], [255, 15]]   # the high byte
    Image.new("CMYK", (2, 1), (0, 255, 255, 0)).save(tmp_path / "cmyk.tif")
    fb = FrameBuffer.open(tmp_path / "cmyk.tif")
    assert fb.mode == "RGB" and fb.get_pixel(0, 0) == (255, 0, 0)
    p = Image.new("P", (2, 1))
    p.putpalette([0, 0, 0, 255, 0, 0])
    p.putpixel((1, 0), 1)
    p.info["transparency"] = 0
    p.save(tmp_path / "t.png", transparency=0)
    fb = FrameBuffer.open(tmp_path / "t.png")
    assert fb.mode == "RGBA" and fb.get_pixel(0, 0)[3] == 0 and fb.get_pixel(1, 0) == (255, 0, 0, 255)


def test_open_takes_the_first_frame_of_an_animation(tmp_path):
    frames = [Image.new("L", (3, 2), v) for v in (10, 200)]
    frames[0].save(tmp_path / "a.gif", save_all=True, append_images=frames[1:])
    fb = FrameBuffer.open(tmp_path / "a.gif")
    assert fb.size == (3, 2) and len(set(np.array(fb.to_pil().convert("L")).ravel())) == 1


def _png(width, height, noise=False):
    buf = io.BytesIO()
    a = np.random.default_rng(0).integers(0, 256, (height, width), dtype=np.uint8)
    Image.fromarray(a if noise else a * 0).save(buf, format="PNG")
    return buf.getvalue()


def _bomb():
    """A PNG of 100,000 x 100,000 gray pixels (10 GB decoded) in a few hundred bytes:
    a valid header and one compressed row repeated by an IDAT that claims the rest."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    header = struct.pack(">IIBBBBB", 100_000, 100_000, 8, 0, 0, 0, 0)
    idat = zlib.compress(b"\0" * 100_001 * 10)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", idat) + chunk(b"IEND", b"")


@pytest.mark.parametrize("content, words", [
    (b"not an image at all", ["not an image file"]),
    (b"", ["not an image file"]),
    (_png(40, 30, noise=True)[:600], ["truncated or damaged"]),
    (_bomb(), ["decompression bomb", "MAX_IMAGE_PIXELS"]),
])
def test_open_refuses_bad_files_clearly(tmp_path, content, words):
    path = tmp_path / "bad.png"
    path.write_bytes(content)
    for source in (path, io.BytesIO(content)):
        with pytest.raises(ImageFileError) as e:
            FrameBuffer.open(source)
        assert isinstance(e.value, ScanlineError) and isinstance(e.value, ValueError)
        assert "file=" in str(e.value)
        for w in words:
            assert w in str(e.value), (w, str(e.value))


def test_open_keeps_pillows_limit_at_its_value(tmp_path, monkeypatch):
    monkeypatch.setattr(Image, "MAX_IMAGE_PIXELS", 1000)
    (tmp_path / "big.png").write_bytes(_png(40, 30))            # 1200 pixels: refused
    with pytest.raises(ImageFileError, match="1,000 pixels"):
        FrameBuffer.open(tmp_path / "big.png")
    assert Image.MAX_IMAGE_PIXELS == 1000
    (tmp_path / "ok.png").write_bytes(_png(20, 30))             # 600 pixels
    assert FrameBuffer.open(tmp_path / "ok.png").size == (20, 30)


def test_open_refuses_missing_files_folders_and_wrong_types(tmp_path):
    with pytest.raises(ImageFileError, match="no such file"):
        FrameBuffer.open(tmp_path / "missing.png")
    with pytest.raises(ImageFileError, match="not a regular file"):
        FrameBuffer.open(tmp_path)
    with pytest.raises(sl.ArgumentTypeError, match="binary"):
        FrameBuffer.open(io.StringIO("text"))
    with pytest.raises(sl.ArgumentTypeError, match="read"):
        FrameBuffer.open(42)


# -- save ---------------------------------------------------------------------------------
def _decoded(data):
    with Image.open(io.BytesIO(data)) as im:
        return im.format, np.array(im.convert("RGBA"))


@pytest.mark.parametrize("mode", ["1", "L", "P", "RGB", "RGBA"])
@pytest.mark.parametrize("fmt, ext", FORMATS)
def test_save_writes_every_common_format_that_fits(tmp_path, mode, fmt, ext):
    fb = sample(mode, seed=3)
    path = tmp_path / f"out{ext}"
    if fmt == "JPEG" and mode == "RGBA":
        with pytest.raises(sl.ArgumentValueError) as e:
            fb.save(path)
        assert "JPEG" in str(e.value) and "RGBA" in str(e.value)
        assert os.listdir(tmp_path) == []
        return
    fb.save(path)
    with Image.open(path) as im:
        assert im.format == fmt and im.size == fb.size
        if fmt not in ("JPEG", "WEBP") and not (fmt == "GIF" and mode in ("RGB", "RGBA")):
            # lossless (GIF: up to 256 colors): the exact colors come back
            got = np.array(im.convert("RGBA"))
            want = np.array(fb.to_pil().convert("RGBA"))
            if fmt in ("GIF", "BMP"):              # no alpha channel kept
                got, want = got[..., :3], want[..., :3]
            assert np.array_equal(got, want)
    # the same bytes to a binary file object
    buf = io.BytesIO()
    fb.save(buf, format=fmt.lower())
    assert _decoded(buf.getvalue())[0] == fmt


def test_save_passes_format_options_through(tmp_path):
    fb = sample("RGB", 64, 64, seed=4)
    fb.save(tmp_path / "lo.jpg", quality=5)
    fb.save(tmp_path / "hi.jpg", quality=95)
    assert (tmp_path / "lo.jpg").stat().st_size < (tmp_path / "hi.jpg").stat().st_size
    fb.save(tmp_path / "lossless.webp", lossless=True)
    assert np.array_equal(FrameBuffer.open(tmp_path / "lossless.webp").to_array(), fb.to_array())
    fb.save(tmp_path / "lzw.tif", compression="tiff_lzw")
    with Image.open(tmp_path / "lzw.tif") as im:
        assert im.info["compression"] == "tiff_lzw"


def test_save_format_names_and_extensions(tmp_path):
    fb = sample("L")
    fb.save(tmp_path / "a.jpeg")
    fb.save(tmp_path / "b.data", format="png")     # format= wins over the extension
    fb.save(tmp_path / "c.img", format=".tiff")
    assert [Image.open(tmp_path / n).format for n in ("a.jpeg", "b.data", "c.img")] == \
        ["JPEG", "PNG", "TIFF"]


def test_save_scale_keyword_still_works(tmp_path):
    fb = FrameBuffer(2, 1, mode="L")
    fb.set_pixel(1, 0, 9)
    fb.save(tmp_path / "s.png", scale=2)
    assert np.array(Image.open(tmp_path / "s.png")).tolist() == [[0, 0, 9, 9], [0, 0, 9, 9]]


def test_save_to_a_named_file_object_takes_the_format_from_its_name(tmp_path):
    with open(tmp_path / "n.bmp", "wb") as f:
        sample("RGB").save(f)
    assert Image.open(tmp_path / "n.bmp").format == "BMP"


@pytest.mark.parametrize("call, error, words", [
    (lambda fb, d: fb.save(io.BytesIO()), sl.ArgumentValueError, ["format="]),
    (lambda fb, d: fb.save(io.StringIO(), format="png"), sl.ArgumentTypeError, ["binary"]),
    (lambda fb, d: fb.save(object(), format="png"), sl.ArgumentTypeError, ["write"]),
    (lambda fb, d: fb.save(d / "x.png", format="nope"), sl.ArgumentValueError, ["format='nope'", "PNG"]),
    (lambda fb, d: fb.save(d / "x.png", format=3), sl.ArgumentTypeError, ["format"]),
    (lambda fb, d: fb.save(d / "x.jpg", quality="best"), sl.ArgumentValueError, ["quality='best'"]),
    (lambda fb, d: fb.save(d / "x.webp", quality=[1]), sl.ArgumentValueError, ["quality=[1]"]),
])
def test_save_refuses_bad_arguments_and_writes_nothing(tmp_path, call, error, words):
    fb = sample("RGB")
    with pytest.raises(error) as e:
        call(fb, tmp_path)
    for w in words:
        assert w in str(e.value), (w, str(e.value))
    assert os.listdir(tmp_path) == []


def test_save_to_a_file_object_writes_nothing_on_refusal():
    buf = io.BytesIO(b"keep")
    with pytest.raises(sl.ArgumentValueError):
        sample("RGBA").save(buf, format="jpeg")
    assert buf.getvalue() == b"keep"


def test_save_is_atomic_for_a_new_format(tmp_path, monkeypatch):
    path = tmp_path / "x.tif"
    path.write_bytes(b"old")
    real = Image.Image.save

    def fail(self, fp, *args, **kwargs):
        real(self, fp, *args, **kwargs)
        raise OSError("disk full")

    monkeypatch.setattr(Image.Image, "save", fail)
    with pytest.raises(OSError, match="disk full"):
        sample("RGB").save(path)
    assert os.listdir(tmp_path) == ["x.tif"] and path.read_bytes() == b"old"


# -- notebooks ----------------------------------------------------------------------------
@pytest.mark.parametrize("size, scale", [((16, 16), 16), ((100, 20), 2), ((300, 10), 1),
                                         ((1, 1), 16)])
def test_repr_png_enlarges_small_frame_buffers(size, scale):
    fb = FrameBuffer(*size, mode="L")
    fb.set_pixel(0, 0, 255)
    with Image.open(io.BytesIO(fb._repr_png_())) as im:
        assert im.size == (size[0] * scale, size[1] * scale)
        a = np.array(im)
    assert (a[-scale:, :scale] == 255).all() and a.sum() == 255 * scale * scale
