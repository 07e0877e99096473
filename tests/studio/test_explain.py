"""``scanline explain``: one self-contained HTML file per case."""

import json
import re

import scanline as sl
from scanline.cli import main


def embedded(path):
    text = path.read_text()
    m = re.search(r'<script id="trace" type="application/json">(.*?)</script>', text, re.S)
    return text, json.loads(m.group(1))


def test_the_page_embeds_the_trace_and_needs_nothing_else(tmp_path):
    out = tmp_path / "b.html"
    assert main(["explain", "bresenham", "20", "10", "30", "18", "-o", str(out)]) == 0
    text, view = embedded(out)
    from scanline.studio.explorer import rows_of
    assert rows_of(view) == sl.trace.bresenham(20, 10, 30, 18).rows
    assert not re.search(r'(src|href)="(?!data:)', text)     # no scripts, styles or links to load
    assert "<style>" in text and "window.explorer" in text


def test_text_from_the_table_cannot_close_the_script(tmp_path):
    out = tmp_path / "f.html"
    grid = "#######/#<.>.&#/#######"
    assert main(["explain", "flood-fill", "1", "1", "--grid", grid, "-o", str(out)]) == 0
    text, view = embedded(out)
    assert [c for c in view["cells"] if c[2] == "<"] == [[1, 1, "<"]]
    assert "</script" not in text.split('<script id="trace"')[1].split("</script>")[0]


def test_bad_arguments_write_nothing(tmp_path, capsys):
    out = tmp_path / "x.html"
    assert main(["explain", "bresenham", "0", "0", "1000000000", "0", "-o", str(out)]) == 2
    assert "a trace lists at most 100000" in capsys.readouterr().err
    assert not out.exists()
    assert main(["explain", "bresenham", "0", "0", "5", "5", "-o", str(tmp_path)]) == 2
