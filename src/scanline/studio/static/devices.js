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

// One screen: fetches the frame at simulated time t (raw RGBA) and paints it, with the
// beam as a ring; `clock` advances t in slow motion.
class Screen {
  constructor(kind, canvas, query) {
    Object.assign(this, {kind, canvas, query, t: 0, running: true, frames: 0, last: performance.now()});
    this.ctx = canvas.getContext("2d");
  }
  async frame() {
    const response = await fetch(`/api/devices/${this.kind}/frame?t=${this.t}&${this.query()}`);
    if (!response.ok) throw new Error((await response.json()).error);
    const data = new Uint8ClampedArray(await response.arrayBuffer());
    const w = this.canvas.width, h = this.canvas.height;
    this.ctx.putImageData(new ImageData(data, w, h), 0, 0);
    const [x, y, state] = response.headers.get("X-Beam").split(",");
    this.ctx.strokeStyle = state === "drawing" ? "#fff" : "#ff4040";
    this.ctx.beginPath(); this.ctx.arc(Number(x) + 0.5, h - 0.5 - Number(y), 3, 0, 7); this.ctx.stroke();
    this.beam = state;
    this.frames++;
    this.total = (this.total || 0) + 1;
  }
  async loop() {
    while (true) {
      const now = performance.now(), dt = (now - this.last) / 1000;
      this.last = now;
      if (this.running) this.t += dt * $("slow").value / 1000;
      try { await this.frame(); } catch (e) { $(`${this.kind}-info`).textContent = e.message; await new Promise((r) => setTimeout(r, 500)); }
      await new Promise((r) => requestAnimationFrame(r));
    }
  }
}

async function info(kind, query) {
  return (await fetch(`/api/devices/${kind}/info?${query}`)).json();
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
    for (let k = 0; k < r.planes; k++) {
      const img = document.createElement("img");
      img.src = `/api/devices/raster/plane/${k}.png`; img.alt = img.title = `bit plane ${k}`;
      $("planes").appendChild(img);
    }
  }
}

const raster = new Screen("raster", $("raster"), rasterQuery);
const random = new Screen("random", $("random"), randomQuery);
window.devices = {raster, random};
for (const id of ["rate", "interlaced", "slow", "persistence", "lines", "speed"]) $(id).oninput = refreshInfo;
$("raster-play").onclick = () => {
  raster.running = random.running = !raster.running;
  $("raster-play").textContent = raster.running ? "pause" : "play";
};
setInterval(() => {
  $("fps").textContent = `raster ${raster.frames} frames/s, random ${random.frames} frames/s (shown)`;
  raster.frames = random.frames = 0;
}, 1000);
refreshInfo().then(() => { raster.loop(); random.loop(); });
