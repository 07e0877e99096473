// The display-device page: shows the screens the server's simulations
// (scanline.display.crt) compute, frame after frame, and the beam they report.
"use strict";

const $ = (id) => document.getElementById(id);

function rasterQuery() {
  return `rate=${$("rate").value}&interlaced=${$("interlaced").checked ? 1 : 0}` +
         `&persistence=${$("persistence").value / 1000}`;
}
function randomQuery() {
  return `lines=${$("lines").value}&speed=${$("speed").value * 1000}` +
         `&persistence=${$("persistence").value / 1000}`;
}

const DEVICE_NOTES = {
  "penetration": "Two phosphor layers, red outside and green inside: slow electrons excite only the red layer, very fast ones only the green, intermediate speeds both (orange, yellow). The beam voltage picks one of four colors; every other color of the display file goes to the nearest (the table lists the voltages set).",
  "shadow-mask": "Three phosphor dots per pixel, red, green and blue, each reached by its own gun through a hole in the shadow mask: a triangle (delta-delta) or side by side along the scan line (in-line). Misconvergence shifts the red and blue beams: color fringes at every edge.",
  "storage": "A direct-view storage tube keeps the picture as a charge pattern that a flood gun holds lit: no refresh, no flicker, no fading. Selective erase is impossible: to remove one segment the whole screen is erased (the flash) and the picture written again without it.",
  "plasma": "Neon between two glass plates, horizontal conductors on one, vertical on the other: firing voltages on one pair light the cell at their intersection. The refresh addresses the cells one intersection at a time, row by row (white cross: the energized pair).",
  "lcd": "Active matrix: one row select line at a time (white mark on the left), every column driver writing that row's values at once; a transistor at each cell holds the value until the next refresh, and the liquid crystal turns toward it with its response time. Here the picture and black take turns, one per refresh.",
};

// One screen: fetches the frame at simulated time t (raw RGBA) and paints it, with the
// beam (a ring; a crosshair for a plasma panel's conductors, a mark for an LCD's
// selected row); `clock` advances t in slow motion.
class Screen {
  constructor(kind, canvas, query) {
    Object.assign(this, {kind, canvas, query, t: 0, dots: 1, running: true, frames: 0, last: performance.now()});
    this.ctx = canvas.getContext("2d");
  }
  async frame() {
    const kind = this.kind;
    const response = await fetch(`/api/devices/${kind}/frame?t=${this.t}&${this.query()}`);
    if (!response.ok) throw new Error((await response.json()).error);
    const data = new Uint8ClampedArray(await response.arrayBuffer());
    const w = this.canvas.width, h = this.canvas.height;
    if (kind !== this.kind || data.length !== w * h * 4) return;    // the device changed meanwhile
    this.ctx.putImageData(new ImageData(data, w, h), 0, 0);
    const [x, y, state] = response.headers.get("X-Beam").split(",");
    const k = this.dots, cx = (Number(x) + 0.5) * k, cy = h - (Number(y) + 0.5) * k;
    this.ctx.strokeStyle = ["drawing", "firing", "row select"].includes(state) ? "#fff" : "#ff4040";
    this.ctx.beginPath();
    if (state === "firing") { this.ctx.moveTo(0, cy); this.ctx.lineTo(w, cy); this.ctx.moveTo(cx, 0); this.ctx.lineTo(cx, h); }
    else if (state === "row select") { this.ctx.moveTo(0, cy); this.ctx.lineTo(6, cy); }
    else if (state !== "off") this.ctx.arc(cx, cy, 3, 0, 7);
    this.ctx.stroke();
    this.beam = state;
    this.frames++;
    this.total = (this.total || 0) + 1;
  }
  async loop() {
    while (true) {
      const now = performance.now(), dt = (now - this.last) / 1000;
      this.last = now;
      if (this.running) this.t += dt * $("slow").value / 1000;
      try { await this.frame(); } catch (e) { ($(`${this.kind}-info`) || $("device-info")).textContent = e.message; await new Promise((r) => setTimeout(r, 500)); }
      await new Promise((r) => requestAnimationFrame(r));
    }
  }
}

async function info(kind, query) {
  return (await fetch(`/api/devices/${kind}/info?${query}`)).json();
}

function deviceQuery() {
  const kind = $("kind").value;
  const shared = `rate=${$("rate").value}&persistence=${$("persistence").value / 1000}`;
  if (kind === "penetration") return randomQuery();
  if (kind === "shadow-mask") return `${shared}&arrangement=${$("arrangement").value}&misconvergence=${$("misconvergence").value}`;
  if (kind === "storage") return `remove=${$("remove").value}`;
  if (kind === "lcd") return `rate=${$("rate").value}&response=${$("response").value / 1000}`;
  return shared;
}

async function refreshDevice() {
  const kind = $("kind").value;
  for (const div of document.querySelectorAll("[data-for]")) div.hidden = div.dataset.for !== kind;
  $("kind-notes").textContent = DEVICE_NOTES[kind];
  for (const id of ["misconvergence", "response"]) $(`${id}-value`).textContent = ` ${$(id).value}`;
  const d = await info(kind, deviceQuery());
  if (d.error) { $("device-info").textContent = d.error; return; }
  if (kind !== device.kind || d.screen[0] !== $("device").width) {
    device.kind = kind; device.t = 0;
    $("device").width = d.screen[0]; $("device").height = d.screen[1];
    $("device").style.width = `${Math.min(3 * d.screen[0], 512)}px`;
    $("device").style.height = `${Math.min(3 * d.screen[1], 512)}px`;
  }
  device.kind = kind;
  device.dots = d.dots || 1;
  const ms = (s) => (s * 1e3).toFixed(2) + " ms";
  let text = `${d.size[0]} x ${d.size[1]} ${kind === "penetration" || kind === "storage" ? "device units" : "pixels"}`;
  let table = "";
  if (kind === "penetration") {
    text += `, refresh cycle ${ms(d.period)}`;
    table = "beam voltage per COLOR command:\n" + d.voltages.map((e) => `${e.kV.toFixed(1)} kV  ${e.color}`).join("\n");
  } else if (kind === "shadow-mask") {
    text += ` of ${d.dots} x ${d.dots} screen pixels, ${d.arrangement} triads, scan line ${(d.line_time * 1e6).toFixed(1)} µs`;
    table = "dot centers in a cell (x, y from its top left):\n" + ["red", "green", "blue"].map((c, i) =>
      `${c.padEnd(6)} (${d.triad[i][0].toFixed(2)}, ${d.triad[i][1].toFixed(2)})  beam off by (${d.offsets[i].join(", ")})`).join("\n");
  } else if (kind === "storage") {
    text += ", no refresh: " + d.phases.map((p) => `${p.phase} ${ms(p.start)}-${ms(p.end)}`).join(", ");
  } else if (kind === "plasma") {
    text += `, ${d.cells_on} cells fire, ${(d.cell_time * 1e6).toFixed(2)} µs per intersection, refresh ${ms(d.period)}`;
  } else if (kind === "lcd") {
    text += `, ${ms(d.line_time)} per row select, response ${ms(d.response_time)}, refresh ${ms(d.period)}`;
  }
  $("device-info").textContent = text;
  $("device-table").textContent = table;
}

async function refreshInfo() {
  for (const id of ["rate", "slow", "persistence", "lines", "speed"]) $(`${id}-value`).textContent = ` ${$(id).value}`;
  const r = await info("raster", rasterQuery());
  $("raster-info").textContent = `refresh period ${(r.period * 1e3).toFixed(2)} ms, ` +
    `scan line ${(r.line_time * 1e6).toFixed(1)} µs, ${r.interlaced ? "2 fields of " + (r.field_time * 1e3).toFixed(2) + " ms" : "1 field"}`;
  const q = await info("random", randomQuery());
  $("random-info").textContent = `${q.lines} LINE commands (${q.commands} in all): drawing takes ` +
    `${(q.drawing_time * 1e3).toFixed(2)} ms, refresh cycle ${(q.period * 1e3).toFixed(2)} ms = ${q.refresh_rate.toFixed(1)} per second` +
    (q.drawing_time < q.period ? " (held at 60: the cycle waits)" : "");
  $("listing").textContent = q.listing.slice(0, 12).join("\n") + (q.commands > 12 ? `\n... (${q.commands} commands)` : "");
  const table = $("colortable");
  if (!table.rows.length) {
    const head = table.insertRow();
    for (const c of ["index", "color", "rgb", "pixels"]) { const th = document.createElement("th"); th.textContent = c; head.appendChild(th); }
    for (const e of r.color_table) {
      const tr = table.insertRow();
      tr.insertCell().textContent = String(e.index);
      const sw = document.createElement("span"); sw.className = "swatch";
      sw.style.background = `rgb(${e.rgb.join(",")})`; tr.insertCell().appendChild(sw);
      tr.insertCell().textContent = e.rgb.join(" ");
      tr.insertCell().textContent = String(e.pixels);
    }
    $("planes-notes").textContent = `${r.color_table.length} colors in the table: indices 0-${r.color_table.length - 1} need ` +
      `${r.bits_needed} of the ${r.planes} bit planes; the others hold only zeros (white: bit 1).`;
    for (let k = 0; k < r.planes; k++) {
      const fig = document.createElement("figure");
      const img = document.createElement("img");
      img.src = `/api/devices/raster/plane/${k}.png`; img.alt = img.title = `bit plane ${k}`;
      const cap = document.createElement("figcaption");
      cap.textContent = `bit ${k} (value ${2 ** k})` + (r.plane_used[k] ? "" : ": all 0");
      if (!r.plane_used[k]) fig.className = "unused";
      fig.append(img, cap);
      $("planes").appendChild(fig);
    }
  }
  await refreshDevice();
}

const raster = new Screen("raster", $("raster"), rasterQuery);
const random = new Screen("random", $("random"), randomQuery);
const device = new Screen($("kind").value, $("device"), deviceQuery);
window.devices = {raster, random, device};
for (const id of ["rate", "interlaced", "slow", "persistence", "lines", "speed"]) $(id).oninput = refreshInfo;
for (const id of ["kind", "arrangement", "misconvergence", "remove", "response"]) $(id).oninput = refreshDevice;
$("raster-play").onclick = () => {
  raster.running = random.running = device.running = !raster.running;
  $("raster-play").textContent = raster.running ? "pause" : "play";
};
setInterval(() => {
  $("fps").textContent = `raster ${raster.frames} frames/s, random ${random.frames} frames/s (shown)`;
  raster.frames = random.frames = 0;
}, 1000);
refreshInfo().then(() => { raster.loop(); random.loop(); device.loop(); });
