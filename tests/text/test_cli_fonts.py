"""``scanline fonts``."""

from scanline.cli import main
from scanline.text import catalog


def test_lists_the_builtin_fonts(capsys):
    assert main(["fonts"]) == 0
    out = capsys.readouterr().out.splitlines()
    rows = {line.split()[0]: line.split() for line in out[1:]}
    assert rows["sans"][1:3] == ["outline", "6253"]
    assert rows["bitmap"][1:3] == ["bitmap", "95"]
    assert rows["stroke"][1:3] == ["stroke", "95"]
    assert "Bitstream Vera" in out[1 + list(rows).index("sans")]


def test_describes_a_font_file(capsys):
    assert main(["fonts", str(catalog.DATA / "DejaVuSans.ttf")]) == 0
    assert "DejaVuSans.ttf outline" in capsys.readouterr().out


def test_bad_font_file_is_one_error_line(capsys, tmp_path):
    bad = tmp_path / "bad.ttf"
    bad.write_bytes(b"not a font")
    assert main(["fonts", str(bad)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "bad.ttf" in err[0] and "not a readable" in err[0]
