"""``scanline exercises``: printable sheets whose answer key is ``scanline trace``'s
output, and the command's bad input (one line on stderr, exit 2, no file)."""

import html
import re
import shlex

import pytest

from scanline.cli import exercises as cli_exercises
from scanline.cli import main
from scanline.studio import exercises, quiz


def traced(capsys, command):
    """What ``command`` (a ``scanline trace ...`` line) prints."""
    capsys.readouterr()
    assert main(shlex.split(command)[1:]) == 0
    return capsys.readouterr().out


@pytest.mark.parametrize("algorithm", ["bresenham", "cohen-sutherland", "z-buffer", "gouraud"])
def test_the_answer_key_is_scanline_trace_output(tmp_path, capsys, algorithm):
    out = tmp_path / "sheet.html"
    assert main(["exercises", algorithm, "--count", "3", "--seed", "17", "-o", str(out)]) == 0
    assert "cases 17..19" in capsys.readouterr().out
    page = out.read_text()
    exercise, key = page.split('<section class="key">')
    commands = [html.unescape(c) for c in re.findall(r"<code>(scanline trace [^<]*)</code>", exercise)]
    assert [shlex.split(c)[3:] for c in commands] == [quiz.case(algorithm, s) for s in (17, 18, 19)]
    answers = [html.unescape(p) for p in re.findall(r"<pre>(.*?)</pre>", key, re.S)]
    assert len(answers) == 3
    blanks = re.findall(r'<table class="blank">(.*?)</table>', exercise)
    for command, answer, blank in zip(commands, answers, blanks):
        printed = traced(capsys, command)
        assert answer + "\n" == printed
        # one blank line per row of the printed table (after its title, notes, header, rule)
        body = printed.split("\n\n", 1)[1].strip().splitlines()[2:]
        assert blank.count("<tr>") == 1 + len(body)
        assert "<td>" not in blank.replace("<td></td>", "")         # blank: nothing filled in


def test_the_key_starts_on_a_new_page_when_printed():
    page = exercises.sheet_html("dda", 1, 0)
    assert re.search(r"\.key \{[^}]*break-before: page", page)
    assert "@media print" in page


def test_the_command_line_and_the_module_agree_on_the_limits():
    assert cli_exercises.MAX_COUNT == exercises.MAX_COUNT
    assert cli_exercises.MAX_SEED == quiz.MAX_SEED


@pytest.mark.parametrize("argv, message", [
    (["bresenham", "--count", "0"], "invalid count 0: give 1..200"),
    (["bresenham", "--count", "-3"], "invalid count -3: give 1..200"),
    (["bresenham", "--count", "1000000000"], "invalid count 1000000000: give 1..200"),
    (["bresenham", "--count", "two"], "invalid count 'two'"),
    (["bresenham", "--seed", "-1"], "invalid seed -1"),
    (["bresenham", "--seed", "2147483647", "--count", "2"], "seed must be 0..2147483645"),
    (["bresenhm"], "unknown algorithm 'bresenhm'; choose one of bresenham, dda"),
])
def test_bad_input_is_one_line_exit_2_and_no_file(tmp_path, capsys, argv, message):
    out = tmp_path / "sheet.html"
    capsys.readouterr()
    assert main(["exercises", *argv, "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and message in err
    assert not out.exists() and list(tmp_path.iterdir()) == []


def test_a_directory_as_output_is_refused(tmp_path, capsys):
    assert main(["exercises", "dda", "-o", str(tmp_path)]) == 2
    assert capsys.readouterr().err.startswith("scanline: error:")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("count, seed, error", [(0, 1, ValueError), (1.0, 1, TypeError),
                                                (1, -1, ValueError), (True, 1, TypeError)])
def test_the_functions_refuse_bad_sizes(count, seed, error):
    with pytest.raises(error, match="count|seed"):
        exercises.sheet_html("dda", count, seed)
