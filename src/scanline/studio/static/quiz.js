// Quiz mode of the explorer: the view carries `quiz`, one question per step (or null),
// each answered by the step's own row (scanline.studio.quiz).  The page shows the
// steps before the one asked, asks for it -- a pixel clicked on the grid, a choice,
// a number -- then reveals the step (its pixels, row and rule) and keeps the score.
// Loaded before explorer.js, which calls quiz.begin() when a view with a quiz is shown.
"use strict";

window.quiz = (() => {
  const q = {view: null, k: 0, right: 0, asked: 0, waiting: false};
  const el = (id) => document.getElementById(id);
  const text = (v) => v === "" ? "(none)" : String(v);

  function score() {
    el("quiz-score").textContent = `score: ${q.right} of ${q.asked}`;
    document.body.dataset.score = `${q.right}/${q.asked}`;
  }

  function buttons(labels, onPick) {
    const box = el("quiz-answer");
    box.replaceChildren();
    for (const label of labels) {
      const b = document.createElement("button");
      b.textContent = text(label);
      b.dataset.choice = label;
      b.onclick = () => onPick(label);
      box.appendChild(b);
    }
  }

  function ask(k) {
    const n = q.view.count;
    q.k = k;
    window.explorer.go(k - 1);               // the steps before this one, nothing after
    if (k >= n) {
      el("quiz-prompt").textContent = `Done: ${q.right} of ${q.asked} right.`;
      el("quiz-given").textContent = "";
      el("quiz-answer").replaceChildren();
      el("quiz-verdict").textContent = "";
      q.waiting = false;
      document.body.dataset.quiz = "done";
      return;
    }
    const question = q.view.quiz[k];
    el("quiz-given").textContent = question && question.given.length ? "given: " +
      question.given.map(([c, v]) => `${c} = ${window.explorer.cell(v)}`).join(", ") : "";
    el("quiz-verdict").textContent = "";
    el("quiz-verdict").className = "";
    if (!question) {                         // a row this algorithm does not ask
      el("quiz-prompt").textContent = `Step ${k + 1} of ${n} asks nothing: see it.`;
      buttons(["show"], () => reveal(null));
      q.waiting = false;
      return;
    }
    el("quiz-prompt").textContent = `Step ${k + 1} of ${n}: ${question.prompt}` +
      (question.kind === "pixel" ? " Click it on the grid." : "");
    q.waiting = question.kind === "pixel";
    if (question.kind === "choice") buttons(question.choices, (c) => reveal(c === String(question.answer[0])));
    else if (question.kind === "number") {
      const box = el("quiz-answer"), input = document.createElement("input"), b = document.createElement("button");
      input.type = "text"; input.id = "quiz-number"; input.size = 10;
      b.textContent = "check";
      b.onclick = () => {
        const v = Number(input.value.trim()), a = Number(question.answer[0]);
        if (input.value.trim() === "" || !Number.isFinite(v)) { el("quiz-verdict").textContent = "type a number"; return; }
        reveal(Math.abs(v - a) <= question.tolerance * Math.max(1, Math.abs(a)));
      };
      input.addEventListener("keydown", (e) => { if (e.key === "Enter") b.click(); });
      box.replaceChildren(input, b);
    } else el("quiz-answer").replaceChildren();
    document.body.dataset.quiz = `asking ${k}`;
  }

  function reveal(right) {
    const k = q.k, question = q.view.quiz[k];
    q.waiting = false;
    window.explorer.go(k);                    // the step itself: pixels, row, rule
    if (right !== null) {
      q.asked += 1;
      if (right) q.right += 1;
      const answer = question.kind === "pixel" ? `(${question.answer.join(", ")})` : text(question.answer[0]);
      el("quiz-verdict").textContent = right ? `Right: ${answer}.` : `Not quite: the answer is ${answer}.`;
      el("quiz-verdict").className = right ? "right" : "wrong";
      el("quiz-verdict").textContent += ` The rule: ${el("rule").textContent}`;
    }
    score();
    buttons(["next"], () => ask(k + 1));
    document.body.dataset.quiz = `revealed ${k}`;
  }

  // a click on the grid answers a pixel question
  function click(x, y) {
    if (!q.waiting) return false;
    const a = q.view.quiz[q.k].answer;
    reveal(x === a[0] && y === a[1]);
    return true;
  }

  function begin(view) {
    if (q.view === view) return;
    Object.assign(q, {view, right: 0, asked: 0});
    el("quiz").hidden = false;
    el("stepper").hidden = true;
    score();
    ask(0);
  }

  return {begin, click, state: q};
})();
