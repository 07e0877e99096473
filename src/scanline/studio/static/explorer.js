// The algorithm explorer: draws the view the server computed from sl.trace (or the
// one embedded by `scanline explain`) and steps through its rows.  It never runs an
// algorithm: every pixel, piece and row comes from the view.
"use strict";

const $ = (id) => document.getElementById(id);
const embedded = $("trace");            // `scanline explain` pages carry their view
const COLORS = {plotted: "#1c7ed6", current: "#f76707", result: "#2b8a3e", shape: "#868e96",
                wall: "#343a40", handle: "#c2255c", mark: "#e8590c"};
const TABLE_WINDOW = 100;               // rows shown either side of the current one

const state = {view: null, step: 0, timer: null, busy: false, queued: null, drag: null,
               geometry: null};

// ---- the server ------------------------------------------------------------------
async function explore(algorithm, args, seed) {
  const t0 = performance.now();
  const [url, body] = seed === undefined ? ["/api/explore", {algorithm, args}] : ["/api/quiz", {algorithm, seed}];
  const response = await fetch(url, {method: "POST",
    headers: {"Content-Type": "application/json"}, body: JSON.stringify(body)});
  const data = await response.json();
  if (!response.ok) throw new Error(data.error || response.statusText);
  data.fetchMs = performance.now() - t0;
  return data;
}

// Ask for a case; while a request is in flight keep only the newest one asked for.
// A quiz (`seed`: the case number) asks for its own case.
async function load(algorithm, args, keepStep, seed) {
  if (state.busy) { state.queued = [algorithm, args, keepStep, seed]; return; }
  state.busy = true;
  try {
    const view = await explore(algorithm, args, seed);
    $("error").textContent = "";
    const t0 = performance.now();
    show(view, keepStep ? state.step : 0);
    state.timing = {fetch: view.fetchMs, draw: performance.now() - t0};
  } catch (error) {
    $("error").textContent = error.message;
  } finally {
    state.busy = false;
    if (state.queued) { const q = state.queued; state.queued = null; load(...q); }
  }
}

// ---- geometry of the grid --------------------------------------------------------
// The grid takes the largest cells that fit MAX_WIDTH x MAX_HEIGHT, and the canvas is
// cut to the grid (no band of blank canvas beside or below it).
const MAX_WIDTH = 720, MAX_HEIGHT = 520;
function layout(view) {
  const canvas = $("grid");
  const [x0, y0, x1, y1] = view.bounds;
  const nx = x1 - x0 + 1, ny = y1 - y0 + 1;
  const cell = Math.max(0.5, Math.min((MAX_WIDTH - 42) / nx, (MAX_HEIGHT - 30) / ny));
  const width = Math.min(MAX_WIDTH, Math.ceil(34 + nx * cell + 8));
  const height = Math.min(MAX_HEIGHT, Math.ceil(8 + ny * cell + 22));
  if (canvas.width !== width) canvas.width = width;
  if (canvas.height !== height) canvas.height = height;
  return {x0, y0, x1, y1, cell, left: 34, top: 8,
          // device (x, y), y up -> canvas coordinates of the pixel's center
          sx: (x) => 34 + (x - x0 + 0.5) * cell,
          sy: (y) => 8 + (y1 - y + 0.5) * cell,
          dx: (px) => x0 + (px - 34) / cell - 0.5,
          dy: (py) => y1 - (py - 8) / cell + 0.5};
}

function fillPixel(ctx, g, x, y, color) {
  ctx.fillStyle = color;
  const inset = g.cell > 6 ? 1 : 0;
  ctx.fillRect(g.sx(x) - g.cell / 2 + inset, g.sy(y) - g.cell / 2 + inset,
               g.cell - 2 * inset, g.cell - 2 * inset);
}

function path(ctx, g, points, closed) {
  ctx.beginPath();
  points.forEach(([x, y], i) => (i ? ctx.lineTo : ctx.moveTo).call(ctx, g.sx(x), g.sy(y)));
  if (closed) ctx.closePath();
}

// ---- one step's content ----------------------------------------------------------------
const cell = (v) => v === null || v === undefined ? "" :
  typeof v === "number" && !Number.isInteger(v) ? String(+v.toFixed(6)) : String(v);
const stepOf = (k) => state.view.steps ? state.view.steps[k] || {} : {};
function pixelsOf(k) {        // a line's row holds its pixel; other views list them per step
  const v = state.view;
  if (v.pixel_columns) {
    const r = v.rows[k];
    return r ? [[r[v.index[v.pixel_columns[0]]], r[v.index[v.pixel_columns[1]]]]] : [];
  }
  return stepOf(k).pixels || [];
}
function ruleOf(k) {          // a rule template filled with the row's values, or the step's text
  const v = state.view;
  if (k < 0) return "";       // a quiz before its first step
  if (!v.rules) return stepOf(k).rule || "";
  const row = v.rows[k];
  return v.rules.templates[v.rules.pick[k]].replace(/\{(\w+)\}/g, (m, c) => c in v.index ? cell(row[v.index[c]]) : m);
}

// ---- drawing -------------------------------------------------------------------------
function drawGrid() {
  const view = state.view, canvas = $("grid"), ctx = canvas.getContext("2d");
  const g = layout(view);
  state.geometry = g;
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  // grid lines between pixels and axis labels every 5
  ctx.strokeStyle = "#e9ecef"; ctx.lineWidth = 1; ctx.fillStyle = "#868e96";
  ctx.font = "10px sans-serif";
  if (g.cell >= 4) {
    for (let x = g.x0; x <= g.x1 + 1; x++) {
      ctx.beginPath(); ctx.moveTo(g.sx(x) - g.cell / 2, g.top);
      ctx.lineTo(g.sx(x) - g.cell / 2, g.sy(g.y0) + g.cell / 2); ctx.stroke();
    }
    for (let y = g.y0; y <= g.y1 + 1; y++) {
      ctx.beginPath(); ctx.moveTo(g.left, g.sy(y) + g.cell / 2);
      ctx.lineTo(g.sx(g.x1) + g.cell / 2, g.sy(y) + g.cell / 2); ctx.stroke();
    }
  }
  // labels every 5 cells or more: at most about 40 along the longer axis, however
  // far apart the case's points are
  const span = Math.max(g.x1 - g.x0, g.y1 - g.y0);
  const every = Math.max(1, Math.ceil(5 / Math.max(g.cell / 10, 0.01) / 5) * 5,
                         Math.ceil(span / 40 / 5) * 5);
  for (let x = Math.ceil(g.x0 / every) * every; x <= g.x1; x += every)
    ctx.fillText(String(x), g.sx(x) - 6, g.sy(g.y0) + g.cell / 2 + 11);
  for (let y = Math.ceil(g.y0 / every) * every; y <= g.y1; y += every)
    ctx.fillText(String(y), 2, g.sy(y) + 3);

  for (const [x, y, c] of view.cells || [])     // seed-fill grids: walls and colors
    if (c !== ".") fillPixel(ctx, g, x, y, c === "#" ? COLORS.wall : "#adb5bd");

  const steps = view.steps, i = state.step, step = stepOf(i);
  for (const [x, y] of view.before) fillPixel(ctx, g, x, y, COLORS.plotted);
  const shade = view.shade_column !== undefined ? view.index[view.shade_column] : undefined;
  for (let k = 0; k < i; k++) {        // a shading's pixels in their own gray (linear I)
    const color = shade === undefined ? COLORS.plotted :
      `rgb(${Array(3).fill(Math.round(255 * Math.min(1, Math.max(0, view.rows[k][shade])))).join(",")})`;
    const own = stepOf(k).colors;     // visible surfaces: each pixel in its polygon's color
    pixelsOf(k).forEach(([x, y], m) => fillPixel(ctx, g, x, y, own ? own[m] : color));
  }
  for (const [x, y] of pixelsOf(i)) fillPixel(ctx, g, x, y, COLORS.current);

  ctx.lineWidth = 1.5; ctx.setLineDash([5, 4]); ctx.strokeStyle = COLORS.shape;
  for (const s of view.shapes) { path(ctx, g, s.points, s.kind === "polygon"); ctx.stroke(); }
  ctx.setLineDash([]);

  if (step.segment) {                              // a line clipper's visible piece
    ctx.strokeStyle = COLORS.result; ctx.lineWidth = 4; path(ctx, g, step.segment, false); ctx.stroke();
  }
  if (step.polygon) {                              // Sutherland-Hodgman
    ctx.strokeStyle = "#495057"; ctx.lineWidth = 1.5; path(ctx, g, step.polygon, true); ctx.stroke();
    ctx.strokeStyle = "#e03131"; ctx.lineWidth = 2; path(ctx, g, step.boundary, false); ctx.stroke();
    ctx.strokeStyle = COLORS.current; ctx.lineWidth = 4; path(ctx, g, step.edge, false); ctx.stroke();
    ctx.fillStyle = COLORS.result;
    for (const [x, y] of step.output) { ctx.beginPath(); ctx.arc(g.sx(x), g.sy(y), 5, 0, 7); ctx.fill(); }
    if (step.output.length > 1) { ctx.strokeStyle = COLORS.result; ctx.lineWidth = 2; path(ctx, g, step.output, false); ctx.stroke(); }
  }
  for (const [points, role] of step.areas || []) {  // depth sort: the pair compared
    ctx.fillStyle = COLORS[role]; ctx.globalAlpha = 0.35; path(ctx, g, points, true); ctx.fill();
    ctx.globalAlpha = 1; ctx.strokeStyle = COLORS[role];
    ctx.lineWidth = points.length === 2 ? 4 : 2; ctx.stroke();     // a wall in plan: a segment
  }
  if (step.plane && step.plane.length) {   // a BSP node's splitting plane in plan; a scan line
    ctx.strokeStyle = "#e03131"; ctx.lineWidth = 2; ctx.setLineDash([8, 4]);
    path(ctx, g, step.plane, false); ctx.stroke(); ctx.setLineDash([]);
  }
  if (view.horizon) drawHorizons(ctx, g, view, i);
  if (view.algorithm === "de-casteljau") {         // the triangle up to this step
    for (let k = 0; k <= i; k++) {
      const [x, y] = steps[k].points[0];
      ctx.fillStyle = k === i ? COLORS.current : `hsl(${210 - 40 * steps[k].level}, 70%, 45%)`;
      ctx.beginPath(); ctx.arc(g.sx(x), g.sy(y), k === i ? 6 : 4, 0, 7); ctx.fill();
    }
  }
  if (view.algorithm === "cox-de-boor") {
    for (let k = 0; k <= i; k++) {
      const [kk, r, b] = steps[k].bar;
      ctx.fillStyle = k === i ? COLORS.current : COLORS.plotted;
      ctx.globalAlpha = 0.25 + 0.75 * b;
      ctx.fillRect(g.sx(kk) - g.cell / 2, g.sy(r) - g.cell / 2, g.cell - 2, g.cell - 2);
      ctx.globalAlpha = 1; ctx.fillStyle = "#000";
      ctx.fillText(b.toFixed(3), g.sx(kk) - g.cell / 2 + 2, g.sy(r) + 3);
    }
  }
  ctx.fillStyle = COLORS.mark;                     // the seed popped, the active edges' keys
  for (const [x, y] of step.mark || []) {
    ctx.beginPath(); ctx.arc(g.sx(x), g.sy(y), Math.max(2, g.cell / 4), 0, 7); ctx.fill();
  }
  if (!embedded && !state.quiz) {
    ctx.fillStyle = COLORS.handle; ctx.font = "11px sans-serif";
    for (const h of view.handles) {
      ctx.fillRect(g.sx(h.x) - 5, g.sy(h.y) - 5, 10, 10);
      ctx.fillText(h.label, g.sx(h.x) + 7, g.sy(h.y) - 7);
    }
  }
}

// The floating horizon: the upper (result color) and lower (plotted color) horizons as
// the table's rows up to this one leave them, one polyline per run of finite columns.
function drawHorizons(ctx, g, view, i) {
  const [c, up, lo] = [view.horizon.column, view.horizon.upper, view.horizon.lower].map((k) => view.index[k]);
  const upper = new Map(), lower = new Map();
  for (let k = 0; k <= i; k++) {
    const r = view.rows[k];
    upper.set(r[c], r[up]); lower.set(r[c], r[lo]);
  }
  for (const [values, color] of [[upper, COLORS.result], [lower, COLORS.plotted]]) {
    ctx.strokeStyle = color; ctx.lineWidth = 2; ctx.beginPath();
    let open = false;
    for (const x of [...values.keys()].sort((a, b) => a - b)) {
      const y = values.get(x);
      if (y === null || y === undefined) { open = false; continue; }
      (open ? ctx.lineTo : ctx.moveTo).call(ctx, g.sx(x), g.sy(y));
      open = true;
    }
    ctx.stroke();
  }
}

function drawTable() {
  const view = state.view, table = $("table"), i = state.step;
  // a quiz shows no row after the current one
  const lo = Math.max(0, i - TABLE_WINDOW), hi = Math.min(view.count, i + (state.quiz ? 1 : TABLE_WINDOW + 1));
  table.replaceChildren();
  const head = table.insertRow();
  for (const c of view.columns) { const th = document.createElement("th"); th.textContent = c; head.appendChild(th); }
  for (let k = lo; k < hi; k++) {
    const tr = table.insertRow();
    tr.dataset.step = String(k);
    if (k === i) tr.className = "current";
    for (const v of view.rows[k]) tr.insertCell().textContent = cell(v);
  }
  $("window").textContent = view.count > hi - lo ? `rows ${lo}..${hi - 1} of ${view.count} shown` : "";
  // scroll the table's box (not the page) to keep the current row in view, below the
  // sticky header
  const current = table.querySelector("tr.current"), box = table.parentElement;
  if (current) {
    const r = current.getBoundingClientRect(), b = box.getBoundingClientRect();
    if (r.top < b.top + head.offsetHeight || r.bottom > b.bottom)
      box.scrollTop += r.top - b.top - (b.height - r.height) / 2;
  }
}

function render() {
  const n = state.view.count;
  $("counter").textContent = n ? `step ${state.step + 1} of ${n}` : "no steps";
  $("quiz").hidden = !state.quiz;
  $("rule").textContent = n ? ruleOf(state.step) : "";
  drawGrid();
  drawTable();
  document.body.dataset.step = String(state.step);
}

function show(view, step) {
  // while a handle is dragged the grid stays put, so the pointer keeps its meaning
  if (state.drag && state.view) view.bounds = state.view.bounds;
  view.index = Object.fromEntries(view.columns.map((c, j) => [c, j]));   // column -> position
  state.view = view;
  state.quiz = Boolean(view.quiz);
  state.step = Math.max(first(), Math.min(step, view.count - 1));
  $("title").textContent = view.title;
  $("notes").textContent = view.notes.join("\n");
  $("command").textContent = view.command;
  if (!embedded) $("args").value = view.args.join(" ");
  $("stepper").hidden = state.quiz;
  render();
  if (state.quiz) window.quiz.begin(view);
  document.body.dataset.ready = String(Date.now());
}

const first = () => state.quiz ? -1 : 0;    // a quiz may show the grid before step 0

function go(step) {
  if (!state.view) return;
  state.step = Math.max(first(), Math.min(step, state.view.count - 1));
  render();
}

function play() {
  if (state.timer) { clearInterval(state.timer); state.timer = null; $("play").textContent = "play"; return; }
  $("play").textContent = "pause";
  state.timer = setInterval(() => {
    if (state.step >= state.view.count - 1) return play();
    go(state.step + 1);
  }, 1000 / Number($("speed").value));
}

// ---- dragging handles ----------------------------------------------------------------
function tokensFor(handle, x, y) {
  const args = state.view.args.slice();
  if (handle.token !== undefined) args[handle.token] = `${x},${y}`;
  else if (handle.kind === "radius-x") args[handle.tokens[0]] = String(Math.abs(x - state.view.center[0]));
  else if (handle.kind === "radius-y") args[handle.tokens[0]] = String(Math.abs(y - state.view.center[1]));
  else { args[handle.tokens[0]] = String(x); args[handle.tokens[1]] = String(y); }
  return args;
}

function pointer(event) {
  const canvas = $("grid"), r = canvas.getBoundingClientRect();
  const px = (event.clientX - r.left) * canvas.width / r.width;
  const py = (event.clientY - r.top) * canvas.height / r.height;
  const g = state.geometry;
  return {px, py, x: Math.round(g.dx(px)), y: Math.round(g.dy(py))};
}

function onDown(event) {
  if (!state.view) return;
  const p = pointer(event), g = state.geometry;
  if (state.quiz) { window.quiz.click(p.x, p.y); return; }     // a pixel answered
  if (embedded) return;
  const hit = state.view.handles.find((h) => Math.hypot(g.sx(h.x) - p.px, g.sy(h.y) - p.py) < 9);
  if (hit) { state.drag = {handle: hit, x: hit.x, y: hit.y}; $("grid").setPointerCapture(event.pointerId); }
}

function onMove(event) {
  if (!state.drag) return;
  const p = pointer(event), d = state.drag;
  if (p.x === d.x && p.y === d.y) return;
  d.x = p.x; d.y = p.y;
  load(state.view.algorithm, tokensFor(d.handle, p.x, p.y), true);
}

function onUp() {
  if (!state.drag) return;
  const d = state.drag;
  state.drag = null;
  // handles are re-read from the newest view: find the same one by label
  const h = state.view.handles.find((k) => k.label === d.handle.label) || d.handle;
  load(state.view.algorithm, tokensFor(h, d.x, d.y), true);
}

// ---- start ---------------------------------------------------------------------------
function bind() {
  $("first").onclick = () => go(0);
  $("back").onclick = () => go(state.step - 1);
  $("forward").onclick = () => go(state.step + 1);
  $("last").onclick = () => go(state.view.count - 1);
  $("play").onclick = play;
  $("table").onclick = (e) => { const tr = e.target.closest("tr"); if (tr && tr.dataset.step) go(Number(tr.dataset.step)); };
  document.addEventListener("keydown", (e) => {
    if (e.target.tagName === "INPUT" || state.quiz) return;     // a quiz reveals by answers
    if (e.key === "ArrowRight") go(state.step + 1);
    if (e.key === "ArrowLeft") go(state.step - 1);
  });
  const canvas = $("grid");
  canvas.addEventListener("pointerdown", onDown);
  canvas.addEventListener("pointermove", onMove);
  canvas.addEventListener("pointerup", onUp);
}

// The page's programmatic face, for tests and the curious: the current view, the step,
// and where a device pixel's center is on the canvas.
window.explorer = {state, go, load, cell, cellCenter: (x, y) => [state.geometry.sx(x), state.geometry.sy(y)]};

async function start() {
  bind();
  if (embedded) {
    $("editor").hidden = true;
    show(JSON.parse(embedded.textContent), 0);
    return;
  }
  const algorithms = await (await fetch("/api/algorithms")).json();
  const select = $("algorithm");
  for (const a of algorithms) {
    const o = document.createElement("option");
    o.value = a.name; o.textContent = `${a.name}: ${a.description}`; select.appendChild(o);
  }
  const byName = Object.fromEntries(algorithms.map((a) => [a.name, a]));
  const params = new URLSearchParams(location.search);
  select.value = byName[params.get("algorithm")] ? params.get("algorithm") : "bresenham";
  const choose = (args) => {
    $("usage").textContent = byName[select.value].usage;
    load(select.value, args || byName[select.value].defaults, false);
  };
  select.onchange = () => choose();
  const words = (text) => text.trim() ? text.trim().split(/\s+/) : [];
  $("run").onclick = () => load(select.value, words($("args").value), false);
  const quizCase = () => Math.max(0, Math.floor(Number($("case").value)) || 0);
  $("quiz-me").onclick = () => load(select.value, [], false, quizCase());
  $("args").addEventListener("keydown", (e) => { if (e.key === "Enter") $("run").click(); });
  if (params.get("case") !== null) {          // ?algorithm=...&case=17: quiz case 17
    $("usage").textContent = byName[select.value].usage;
    $("case").value = params.get("case");
    load(select.value, [], false, quizCase());
  } else choose(params.get("args") ? words(params.get("args")) : null);
}

start();
