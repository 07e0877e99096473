"""Quiz mode in a real headless Chromium: the offline page (``scanline explain
--quiz``) from file:// with the network refused, answered right and wrong by a
click on the grid; the studio's quiz case answered by its choice buttons.  The
expected answers are ``sl.trace``'s rows, read here, not the page's."""

import json

import scanline as sl
from scanline.cli import main
from scanline.studio.quiz import case

from .test_browser import canvas_point, wait_ready


def verdict(page):
    return page.inner_text("#quiz-verdict")


def test_offline_quiz_page_scores_pixels_clicked_on_the_grid(browser, page, tmp_path):
    out = tmp_path / "quiz.html"
    assert main(["explain", "bresenham", "20", "10", "30", "18", "--quiz", "-o", str(out)]) == 0
    asked = []
    page.route("http*://**", lambda route: (asked.append(route.request.url), route.abort()))
    page.goto(out.as_uri())
    wait_ready(page)
    rows = sl.trace.bresenham(20, 10, 30, 18).rows
    assert page.evaluate("document.body.dataset.quiz") == "asking 0"
    assert page.locator("table#table tr[data-step]").count() == 0      # nothing shown ahead
    assert page.is_hidden("#stepper")
    # right: row 0's pixel
    page.mouse.click(*canvas_point(page, rows[0]["x"], rows[0]["y"]))
    assert page.evaluate("document.body.dataset.score") == "1/1"
    assert verdict(page).startswith(f"Right: ({rows[0]['x']}, {rows[0]['y']}).")
    assert f"p_0 = {rows[0]['p']} >= 0" in verdict(page)            # the rule revealed
    assert page.locator("table#table tr[data-step]").count() == 1
    page.click("button[data-choice=next]")
    assert page.evaluate("document.body.dataset.quiz") == "asking 1"
    # wrong: a pixel two rows above row 1's
    page.mouse.click(*canvas_point(page, rows[1]["x"], rows[1]["y"] + 2))
    assert page.evaluate("document.body.dataset.score") == "1/2"
    assert verdict(page).startswith(f"Not quite: the answer is ({rows[1]['x']}, {rows[1]['y']}).")
    assert page.inner_text("#quiz-score") == "score: 1 of 2"
    assert asked == []
    page.screenshot(path=str(tmp_path / "quiz.png"))


def test_studio_quiz_case_asks_write_or_keep(server, page):
    page.goto(f"{server}/explorer?algorithm=z-buffer&case=17")
    wait_ready(page)
    args = case("z-buffer", 17)
    assert page.evaluate("window.explorer.state.view.args") == args
    row = int(args[1])
    results = [r["result"] for r in sl.trace.z_buffer(row=row).rows]
    assert sorted(page.locator("#quiz-answer button").all_inner_texts()) == ["keep", "write"]
    first = sl.trace.z_buffer(row=row).rows[0]
    assert page.inner_text("#quiz-given") == (f"given: triangle = {first['triangle']}, "
                                               f"x = {first['x']}, z = {round(first['z'], 6)}, "
                                               f"depth = {first['depth']}")
    page.click(f"button[data-choice={results[0]}]")
    assert page.evaluate("document.body.dataset.score") == "1/1"
    assert page.inner_text("#rule") in verdict(page)
    page.click("button[data-choice=next]")
    wrong = "keep" if results[1] == "write" else "write"
    page.click(f"button[data-choice={wrong}]")
    assert page.evaluate("document.body.dataset.score") == "1/2"
    assert verdict(page).startswith(f"Not quite: the answer is {results[1]}.")


def test_the_index_and_the_quiz_me_button_start_quizzes(server, page):
    page.goto(f"{server}/")
    page.click("text=Quiz")
    wait_ready(page)
    assert page.evaluate("window.explorer.state.view.args") == case("bresenham", 1)
    assert page.evaluate("document.body.dataset.quiz") == "asking 0"
    before = page.evaluate("document.body.dataset.ready")
    page.select_option("#algorithm", "dda")
    wait_ready(page, before)                       # the explorer shows dda's default case
    assert page.is_hidden("#quiz") and page.is_visible("#stepper")
    before = page.evaluate("document.body.dataset.ready")
    page.fill("#case", "5")
    page.click("#quiz-me")
    wait_ready(page, before)
    assert page.evaluate("window.explorer.state.view.args") == case("dda", 5)
    assert page.is_visible("#quiz") and page.is_hidden("#stepper")
    assert page.inner_text("#quiz-score") == "score: 0 of 0"


def answer_right(page, question):
    """Answer ``question`` (from the quiz's data) the right way for its kind."""
    if question["kind"] == "pixel":
        page.mouse.click(*canvas_point(page, *question["answer"]))
    elif question["kind"] == "choice":
        page.click(f"#quiz-answer button[data-choice={json.dumps(str(question['answer'][0]))}]")
    else:
        page.fill("#quiz-number", repr(question["answer"][0]))
        page.click("#quiz-answer button")


def test_every_algorithm_s_offline_quiz_takes_a_right_answer(browser, page, tmp_path):
    from scanline.studio.explorer import parse
    from scanline.studio.page import explain_html
    from scanline.studio.quiz import algorithms

    for name in algorithms():
        args = case(name, 2)
        out = tmp_path / f"{name}.html"
        out.write_text(explain_html(parse(name, args), quiz=True), encoding="utf-8")
        page.goto(out.as_uri())
        wait_ready(page)
        asked = page.evaluate("window.explorer.state.view.quiz")
        k = next(i for i, q in enumerate(asked) if q)
        for _ in range(k):                                   # steps that ask nothing
            page.click("button[data-choice=show]")
            page.click("button[data-choice=next]")
        answer_right(page, asked[k])
        assert page.evaluate("document.body.dataset.score") == "1/1", name
        assert page.evaluate("document.body.dataset.quiz") == f"revealed {k}", name
        assert page.locator("tr.current").get_attribute("data-step") == str(k), name
