"""Quiz mode's data: every algorithm of the catalog has a question, a seeded case
that asks something, and answers that are ``scanline trace``'s rows."""

import json

import pytest

from scanline.cli import main
from scanline.studio import quiz
from scanline.studio.explorer import catalog


def trace_rows(capsys, algorithm, args):
    """The rows ``scanline trace ALGORITHM ARGS --format json`` prints."""
    capsys.readouterr()
    assert main(["trace", algorithm, "--format", "json", *args]) == 0
    return json.loads(capsys.readouterr().out)


def test_every_algorithm_of_the_catalog_has_a_quiz():
    assert quiz.algorithms() == [c["name"] for c in catalog()]
    assert len(quiz.algorithms()) == 28


@pytest.mark.parametrize("algorithm", [c["name"] for c in catalog()])
def test_answers_are_the_trace_rows(capsys, algorithm):
    args = quiz.case(algorithm, 5)
    rows = trace_rows(capsys, algorithm, args)
    asked = quiz.quiz(algorithm, args)["quiz"]
    assert len(asked) == len(rows) and any(asked)
    question = quiz.QUESTIONS[algorithm]
    for q, row in zip(asked, rows):
        values = [row.get(c) for c in question.columns]
        if None in values:
            assert q is None
            continue
        assert q["answer"] == values
        assert q["given"] == [[c, row.get(c)] for c in question.given]
        if q["kind"] == "choice":
            assert str(values[0]) in q["choices"]


@pytest.mark.parametrize("algorithm", ["bresenham", "scan-line-fill", "back-face", "gouraud"])
def test_the_same_seed_gives_the_same_case(algorithm):
    assert quiz.case(algorithm, 17) == quiz.case(algorithm, 17)
    assert len({tuple(quiz.case(algorithm, s)) for s in range(8)}) > 1


def test_pixel_questions_ask_bresenham_s_next_pixel():
    q = quiz.quiz("bresenham", ["0", "0", "5", "2"])["quiz"]
    # by hand: dx = 5, dy = 2, p0 = 2dy - dx = -1 -> (1, 0); p1 = -1 + 4 = 3 -> (2, 1);
    # p2 = 3 + 4 - 10 = -3 -> (3, 1); p3 = 1 -> (4, 2); p4 = -5 -> (5, 2)
    assert [a["answer"] for a in q] == [[1, 0], [2, 1], [3, 1], [4, 2], [5, 2]]


def test_choices_offer_both_answers_even_when_the_table_holds_one():
    for seed in range(3):
        view = quiz.quiz("z-buffer", quiz.case("z-buffer", seed))
        assert all(a["choices"] == ["keep", "write"] for a in view["quiz"] if a)


@pytest.mark.parametrize("seed, error", [(-1, ValueError), (2**31, ValueError), (1.5, TypeError),
                                         (True, TypeError)])
def test_bad_seeds(seed, error):
    with pytest.raises(error, match="seed must be"):
        quiz.case("bresenham", seed)


def test_unknown_algorithm():
    with pytest.raises(ValueError, match="unknown algorithm 'bresenhm'"):
        quiz.case("bresenhm", 1)


def test_the_quiz_endpoint(client):
    r = client.post("/api/quiz", json={"algorithm": "back-face", "seed": 17})
    assert r.status_code == 200
    view = r.json()
    assert view["args"] == quiz.case("back-face", 17)
    assert [q["answer"] for q in view["quiz"]] == [[r[-1]] for r in view["rows"]]
    assert client.post("/api/quiz", json={"algorithm": "back-face"}).status_code == 400
    assert client.post("/api/quiz", json={"algorithm": "back-face", "seed": "1"}).status_code == 400
    r = client.post("/api/quiz", json={"algorithm": "back-face", "seed": -1})
    assert r.status_code == 422 and "seed must be 0.." in r.json()["error"]
    r = client.post("/api/quiz", json={"algorithm": "nope", "seed": 1})
    assert r.status_code == 422 and "unknown algorithm 'nope'" in r.json()["error"]
