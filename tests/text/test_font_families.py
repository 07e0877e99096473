"""Fonts by family name (issue, part 6, item 4): ``font="DejaVu Sans"`` is the bundled
font on every machine; other families come from fontconfig's ``fc-list`` (here also a
stand-in script, so the parsing and the choice of face are tested everywhere) or
matplotlib's font manager; an unknown family lists what is available."""

import os
import shutil
import stat
import sys

import numpy as np
import pytest

import scanline as sl
from scanline.cli import main
from scanline.text import catalog, system

BUNDLED = str(catalog.DATA / "DejaVuSans.ttf")


@pytest.fixture(autouse=True)
def fresh(monkeypatch):
    """No finder result and no family lookup is kept from another test."""
    monkeypatch.setattr(system, "_CACHE", {})
    monkeypatch.setattr(catalog, "_LOADED", {k: f for k, f in catalog._LOADED.items()
                                             if k in catalog._builtin()})


@pytest.fixture
def fake_fc_list(tmp_path, monkeypatch):
    """Put an ``fc-list`` on PATH that prints ``lines`` (what fontconfig prints for
    --format '%{family}\\t%{style}\\t%{file}\\n'); return a function that sets them."""
    folder = tmp_path / "bin"
    folder.mkdir()
    program = folder / "fc-list"
    listing = tmp_path / "listing.txt"

    def install(lines):
        listing.write_text("".join(line + "\n" for line in lines))
        program.write_text(f"#!{sys.executable}\nimport sys\n"
                           f"sys.stdout.write(open({str(listing)!r}).read())\n")
        program.chmod(program.stat().st_mode | stat.S_IEXEC)
        monkeypatch.setenv("PATH", str(folder))
    return install


def copy_of_bundled(tmp_path, name):
    path = tmp_path / name
    shutil.copyfile(BUNDLED, path)
    return str(path)


def text_pixels(font):
    fb = sl.FrameBuffer(40, 16, mode="1")
    sl.draw.text(fb, 1, 3, "Hag", font=font, height=9)
    return fb.to_array()


# -- the bundled family --------------------------------------------------------------------

@pytest.mark.parametrize("name", ["DejaVu Sans", "dejavu sans", "  DejaVu   SANS "])
def test_the_bundled_family_is_the_builtin_sans(name):
    assert sl.text.font(name) is sl.text.font("sans")
    assert sl.text.font(name).name == "sans"                # the bundled font keeps its name
    assert sl.text.find_font(name) == BUNDLED
    assert np.array_equal(text_pixels(name), text_pixels("sans"))


def test_the_bundled_family_wins_over_an_installed_one(fake_fc_list, tmp_path):
    other = copy_of_bundled(tmp_path, "OtherDejaVu.ttf")
    fake_fc_list([f"DejaVu Sans\tBook\t{other}"])
    assert sl.text.font("DejaVu Sans") is sl.text.font("sans")


# -- fontconfig ----------------------------------------------------------------------------

def test_fc_list_faces_and_the_regular_one(fake_fc_list, tmp_path):
    regular = copy_of_bundled(tmp_path, "Fake-Regular.ttf")
    bold = copy_of_bundled(tmp_path, "Fake-Bold.ttf")
    condensed = copy_of_bundled(tmp_path, "FakeCondensed.ttf")
    fake_fc_list([
        f"Fake Sans\tBold\t{bold}",
        f"Fake Sans,Fake Sans Condensed\tCondensed,Book\t{condensed}",
        f"Fake Sans\tRegular\t{regular}",
        f"Fake Sans\tRegular\t{tmp_path}/fake.pcf.gz",           # a bitmap font: not read
        f"Comma\\, Inc Sans\tBook\t{regular}",                    # an escaped comma
        "a line that is not a face",
    ])
    assert sl.text.find_font("Fake Sans") == regular
    assert sl.text.find_font("fake sans condensed") == condensed
    assert sl.text.find_font("Comma, Inc Sans") == regular
    f = sl.text.font("Fake Sans")
    assert f.source == regular and f.kind == "outline"
    assert sl.text.font("Fake Sans") is f                          # looked up once
    assert np.array_equal(text_pixels("Fake Sans"), text_pixels("sans"))  # (the same glyphs)
    assert sl.text.families() == {"Comma, Inc Sans": regular, "Fake Sans": regular,
                                  "Fake Sans Condensed": condensed}


def test_an_unknown_family_lists_the_available_ones(fake_fc_list, tmp_path):
    regular = copy_of_bundled(tmp_path, "Fake-Regular.ttf")
    fake_fc_list([f"Fake Sans\tRegular\t{regular}", f"Fake Serif\tRegular\t{regular}"])
    with pytest.raises(sl.ArgumentValueError) as e:
        sl.draw.text(sl.FrameBuffer(8, 8), 0, 0, "x", font="Fake Sanz")
    message = str(e.value)
    for words in ["font='Fake Sanz'", "'sans', 'bitmap', 'stroke'", "did you mean 'Fake Sans'",
                  "by fontconfig", "Fake Sans, Fake Serif", "DejaVu Sans", "--system"]:
        assert words in message, message
    with pytest.raises(sl.ArgumentValueError, match="family='Nope'"):
        sl.text.find_font("Nope")
    with pytest.raises(sl.ArgumentTypeError, match="family"):
        sl.text.find_font(12)


def test_a_failing_fc_list_is_no_finder(tmp_path, monkeypatch):
    folder = tmp_path / "bin"
    folder.mkdir()
    (folder / "fc-list").write_text("#!/bin/sh\nexit 3\n")
    (folder / "fc-list").chmod(0o755)
    monkeypatch.setenv("PATH", str(folder))
    assert system._fontconfig() is None


# -- matplotlib, and neither -----------------------------------------------------------------

def test_matplotlib_when_fontconfig_is_missing(tmp_path, monkeypatch):
    font_manager = pytest.importorskip("matplotlib.font_manager")
    monkeypatch.setenv("PATH", str(tmp_path))                    # no fc-list
    names = {e.name for e in font_manager.fontManager.ttflist
             if e.fname.lower().endswith((".ttf", ".otf"))}
    family = "DejaVu Serif" if "DejaVu Serif" in names else sorted(names)[0]
    path = sl.text.find_font(family)
    assert any(e.name == family and e.fname == path for e in font_manager.fontManager.ttflist)
    assert sl.text.font(family.upper()).source == path
    assert family in sl.text.families()
    with pytest.raises(sl.ArgumentValueError, match="by matplotlib"):
        sl.text.font("No Such Family Anywhere")


def test_neither_fontconfig_nor_matplotlib(tmp_path, monkeypatch):
    monkeypatch.setenv("PATH", str(tmp_path))
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    monkeypatch.setitem(sys.modules, "matplotlib.font_manager", None)
    assert sl.text.families() == {}
    assert sl.text.font("DejaVu Sans") is sl.text.font("sans")       # bundled: still there
    with pytest.raises(sl.ArgumentValueError) as e:
        sl.text.font("DejaVu Serif")
    assert "fc-list or matplotlib" in str(e.value) and "neither is installed" in str(e.value)
    assert main(["fonts", "--system"]) == 0


# -- the system's own fonts (skipped where fontconfig finds none) ----------------------------

def test_an_installed_family_draws_text():
    if shutil.which("fc-list") is None:
        pytest.skip("fontconfig (fc-list) is not installed")
    installed = {name: path for name, path in sl.text.families().items()
                 if system.key(name) != "dejavu sans"}
    if not installed:
        pytest.skip("fontconfig lists no TrueType/OpenType font")
    name, path = sorted(installed.items())[0]
    f = sl.text.font(name)
    assert os.path.samefile(f.source, path) and f.kind == "outline"
    assert text_pixels(name).any()


# -- command line ------------------------------------------------------------------------------

def test_cli_fonts_system_and_draw_font_by_family(fake_fc_list, tmp_path, capsys):
    regular = copy_of_bundled(tmp_path, "Fake-Regular.ttf")
    fake_fc_list([f"Fake Sans\tRegular\t{regular}"])
    assert main(["fonts", "--system"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert "by fontconfig" in out[0] and out[1].split() == ["Fake", "Sans", regular]
    image = tmp_path / "hi.png"
    assert main(["draw", "--size", "40x16", "font", "Fake Sans", "text", "1", "3", "Hi",
                 "-o", str(image)]) == 0
    assert sl.FrameBuffer.open(image).to_array().any()
    assert main(["draw", "font", "Fake Sanz", "text", "1", "3", "Hi", "-o", str(image)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "did you mean 'Fake Sans'" in err[0]
