// The workstation page: sends the operator's inputs (locator, stroke, valuator, choice,
// pick, string) to the server's display file and shows what it draws.  Positions,
// snapping, gravity, constraints, picking and the segment transformations are all the
// server's (scanline.studio.workstation); the page draws only the rubber band.
"use strict";

const $ = (id) => document.getElementById(id);
const DEVICES = ["locator", "stroke", "valuator", "choice", "pick", "string"];
const ws = {id: null, state: null, drag: null, moving: false, down: null};

async function call(action, body) {
  const response = await fetch(`/api/ws/${ws.id}/${action}`, {method: "POST",
    headers: {"Content-Type": "application/json"}, body: JSON.stringify(body || {})});
  const data = await response.json();
  if (!response.ok) { $("error").textContent = data.error; throw new Error(data.error); }
  $("error").textContent = "";
  if (data.state) update(data.state);
  return data;
}

function text(parent, tag, content) {
  const e = document.createElement(tag); e.textContent = content; parent.appendChild(e); return e;
}

function update(state) {
  const changed = !ws.state || ws.state.version !== state.version;
  ws.state = state;
  for (const b of $("modes").children) b.classList.toggle("on", b.dataset.mode === state.mode);
  $("requests").hidden = state.mode !== "request";
  $("eventbox").hidden = state.mode !== "event";
  for (const b of $("requests").querySelectorAll("button")) b.classList.toggle("on", b.dataset.device === state.requested);
  $("queue").textContent = state.events.length ? `queue: ${state.events.join(", ")}` : "queue empty";
  for (const b of $("menu").children) b.classList.toggle("on", b.dataset.tool === state.tool);
  $("snap").checked = state.snap;
  const select = $("segment"), keep = select.value;
  select.replaceChildren();
  for (const s of state.segments) { const o = text(select, "option", s.name); o.value = s.name; }
  if (state.segments.some((s) => s.name === keep)) select.value = keep;
  else if (state.selected) select.value = state.selected;
  const seg = state.segments.find((s) => s.name === select.value);
  if (seg && document.activeElement !== $("valuator")) { $("valuator").value = seg.angle; $("valuator-value").textContent = ` ${seg.angle}°`; }
  $("log").replaceChildren(); for (const line of state.log) text($("log"), "li", line);
  const table = $("segments"); table.replaceChildren();
  const head = table.insertRow();
  for (const c of ["segment", "priority", "primitives", "highlighted", "transformation"]) text(head, "th", c);
  for (const s of state.segments) {
    const tr = table.insertRow();
    tr.dataset.segment = s.name;
    for (const v of [s.name, s.priority, s.primitives, s.highlighted ? "yes" : "",
                     s.matrix.slice(0, 2).map((r) => r.map((x) => x.toFixed(3)).join(" ")).join(" | ")])
      tr.insertCell().textContent = String(v);
  }
  if (changed) $("screen").src = `/api/ws/${ws.id}/image.png?v=${state.version}`;
}

// ---- positions -----------------------------------------------------------------------
function devicePosition(event) {     // canvas pixel -> device coordinates (y up, centers at integers)
  const c = $("overlay"), r = c.getBoundingClientRect();
  const px = (event.clientX - r.left) * c.width / r.width, py = (event.clientY - r.top) * c.height / r.height;
  return [px - 0.5, c.height - 0.5 - py];
}
function canvasPoint([x, y]) { return [x + 0.5, $("overlay").height - 0.5 - y]; }

async function position(p, anchor) {
  const response = await fetch(`/api/ws/${ws.id}/position`, {method: "POST",
    headers: {"Content-Type": "application/json"}, body: JSON.stringify({position: p, anchor})});
  return response.json();
}

function band(points, closed) {          // the rubber band, in the overlay
  const ctx = $("overlay").getContext("2d");
  ctx.clearRect(0, 0, 480, 360);
  if (!points) return;
  ctx.strokeStyle = "#c2255c"; ctx.setLineDash([6, 4]); ctx.lineWidth = 1.5;
  ctx.beginPath();
  points.map(canvasPoint).forEach(([x, y], i) => (i ? ctx.lineTo(x, y) : ctx.moveTo(x, y)));
  if (closed) ctx.closePath();
  ctx.stroke();
}

function rectangle(a, b) { return [a, [b[0], a[1]], b, [a[0], b[1]]]; }

// ---- the canvas's gestures, by tool -----------------------------------------------------
// In event mode a menu choice waits in the queue: take the choices at its head before a
// gesture starts, so that the drag uses the tool the operator chose (AWAIT EVENT).
async function takeChoices() {
  while (ws.state.mode === "event" && ws.state.events[0] === "choice") await call("await");
}

async function onDown(event) {
  const p = devicePosition(event);
  $("overlay").setPointerCapture(event.pointerId);
  ws.down = takeChoices();
  await ws.down;
  const tool = ws.state.tool;
  if (tool === "line" || tool === "rectangle") {
    // the drag starts now; the snapped start arrives later (a release before it still counts)
    const d = ws.drag = {tool, anchor: p, start: p};
    d.ready = position(p).then((snapped) => { d.start = snapped.device; }, () => null);
  } else if (tool === "stroke") {
    ws.drag = {tool, points: [p]};
  } else if (tool === "drag") {
    const got = await call("input", {device: "pick", value: {position: p, aperture: 3}});
    const seg = got.result && got.result.segment;
    $("picked").textContent = seg ? `dragging ${seg}` : "nothing to drag here";
    if (seg) ws.drag = {tool, segment: seg, last: p};
  }
}

async function onMove(event) {
  const p = devicePosition(event);
  if (!ws.moving) {                       // the locator's echo (sample): one request at a time
    ws.moving = true;
    const d = ws.drag;
    position(p, d && d.anchor).then((r) => {
      $("locator").textContent = `locator: device (${p[0].toFixed(1)}, ${p[1].toFixed(1)}) -> world ` +
        `(${r.world[0].toFixed(3)}, ${r.world[1].toFixed(3)})${r.applied.length ? " [" + r.applied.join(", ") + "]" : ""}`;
      if (d && d.anchor && ws.drag === d) band(d.tool === "line" ? [d.start, r.device] : rectangle(d.start, r.device), d.tool === "rectangle");
    }).finally(() => { ws.moving = false; });
  }
  const d = ws.drag;
  if (!d) return;
  if (d.tool === "stroke") { d.points.push(p); band(d.points, false); }
  if (d.tool === "drag" && !d.busy) {
    d.busy = true;
    const delta = [p[0] - d.last[0], p[1] - d.last[1]];
    d.last = p;
    call("drag", {segment: d.segment, delta}).finally(() => { d.busy = false; });
  }
}

async function onUp(event) {
  const p = devicePosition(event);
  if (ws.down) await ws.down;             // the gesture's start (and its queued choice) first
  const d = ws.drag, tool = ws.state.tool;
  ws.drag = null;
  band(null);
  if (d && d.ready) await d.ready;
  if (d && (d.tool === "line" || d.tool === "rectangle"))
    await call("input", {device: "locator", value: {position: p, anchor: d.anchor, tool: d.tool}});
  else if (d && d.tool === "stroke" && d.points.length > 1)
    await call("input", {device: "stroke", value: {points: d.points.slice(0, 2000)}});
  else if (tool === "pick") {
    const got = await call("input", {device: "pick", value: {position: p, aperture: 3}});
    if (got.result) $("picked").textContent = got.result.text;
  } else if (tool === "text")
    await call("input", {device: "string", value: {position: p, text: $("string").value}});
}

// ---- start ---------------------------------------------------------------------------
// The server keeps a few workstations per browser: give back this page's when it goes
// (and the one a reload of this tab left behind), so that reloading never runs out.
const JSON_POST = {method: "POST", headers: {"Content-Type": "application/json"}, body: "{}"};
function close(id, keepalive) {
  return fetch(`/api/ws/${id}/close`, {...JSON_POST, keepalive}).catch(() => null);
}

async function start() {
  const previous = sessionStorage.getItem("scanline-workstation");
  if (previous) await close(previous, false);
  const response = await fetch("/api/ws", JSON_POST);
  const data = await response.json();
  if (!response.ok) { $("error").textContent = data.error; throw new Error(data.error); }
  ws.id = data.id;
  sessionStorage.setItem("scanline-workstation", ws.id);
  window.addEventListener("pagehide", (event) => {
    if (!event.persisted) close(ws.id, true);
  });
  data.state.menu.forEach((tool, i) => {
    const b = text($("menu"), "button", `${i + 1} ${tool}`);
    b.dataset.tool = tool;
    b.onclick = () => call("input", {device: "choice", value: {item: i + 1}});
  });
  for (const d of DEVICES) {
    const b = text($("requests"), "button", d);
    b.dataset.device = d;
    b.onclick = () => call("request", {device: d});
  }
  for (const b of $("modes").children) b.onclick = () => call("settings", {mode: b.dataset.mode});
  $("await").onclick = async () => {
    const got = await call("await");
    $("picked").textContent = got.event ? `${got.event.device}: ${got.event.result.text}` : "no event";
  };
  $("snap").onchange = () => call("settings", {snap: $("snap").checked});
  $("gridsize").onchange = () => call("settings", {grid: Number($("gridsize").value)});
  $("gravity").oninput = () => { $("gravity-value").textContent = ` ${$("gravity").value}`; call("settings", {gravity: Number($("gravity").value)}); };
  $("constraint").onchange = () => call("settings", {constraint: $("constraint").value});
  $("valuator").oninput = () => {
    $("valuator-value").textContent = ` ${$("valuator").value}°`;
    call("input", {device: "valuator", value: {segment: $("segment").value, angle: Number($("valuator").value)}});
  };
  $("segment").onchange = () => update(ws.state);
  const overlay = $("overlay");
  overlay.addEventListener("pointerdown", onDown);
  overlay.addEventListener("pointermove", onMove);
  overlay.addEventListener("pointerup", onUp);
  update(data.state);
  document.body.dataset.ready = "1";
}

window.workstation = ws;
start();
