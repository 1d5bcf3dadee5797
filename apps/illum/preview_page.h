// The page of the live preview (preview_server.h): the image as it converges, exposure and tone-map
// controls, the linear radiance of the pixel under the cursor, progress, and a button to save the EXR.
// It long-polls /status (answered when a newer pass has landed) and reloads /frame.png for each. `?probe=X,Y` makes it read pixel
// (X, Y) through /pixel once the render is done and show it in #probe (the browser test reads it).
#pragma once

namespace illum::cli {

inline constexpr const char* kPreviewPage = R"HTML(<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>illum preview</title>
<style>
  body { font: 14px system-ui, sans-serif; margin: 16px; background: #1e1e1e; color: #ddd; }
  #bar { display: flex; gap: 16px; align-items: center; flex-wrap: wrap; margin-bottom: 10px; }
  #view { image-rendering: pixelated; max-width: 100%; border: 1px solid #444; cursor: crosshair; }
  #stats, #pixel { font-family: ui-monospace, monospace; }
  .dim { color: #888; font-size: 12px; margin-top: 6px; }
  .dim pre { display: inline; }
  a.button { background: #3a6ea5; color: white; padding: 4px 10px; border-radius: 4px; text-decoration: none; }
</style>
</head>
<body>
<div id="bar">
  <strong>illum</strong>
  <label>exposure <input id="exposure" type="range" min="-8" max="8" step="0.1" value="0">
    <span id="exposure-value">0.0</span> stops</label>
  <label>tone map <select id="tonemap">
    <option value="clamp">clamp</option><option value="reinhard">Reinhard</option><option value="aces">ACES</option>
  </select></label>
  <a class="button" id="save" href="/image.exr" download="illum-preview.exr">save EXR</a>
</div>
<div id="stats">waiting for the first pass...</div>
<div id="pixel">move the cursor over the image for its radiance</div>
<img id="view" alt="the render so far">
<div class="dim">frames shown: <pre id="frames">0</pre> <pre id="probe"></pre></div>
<script>
"use strict";
const view = document.getElementById("view");
const exposure = document.getElementById("exposure");
const tonemap = document.getElementById("tonemap");
let shownFrame = -1, shownLook = "", framesLoaded = 0, loading = false, status = null, probed = false;
const probe = new URLSearchParams(location.search).get("probe");

function look() { return "exposure=" + exposure.value + "&tonemap=" + tonemap.value; }
function seconds(s) {
  if (s < 0) return "?";
  if (s < 60) return s.toFixed(1) + " s";
  return Math.floor(s / 60) + " min " + Math.round(s % 60) + " s";
}
function refreshImage() {
  if (!status || loading || status.frames === 0) return;
  if (status.frames === shownFrame && look() === shownLook) return;
  loading = true;
  const frame = status.frames, l = look();
  view.onload = () => {
    loading = false; shownFrame = frame; shownLook = l; framesLoaded++;
    document.getElementById("frames").textContent = String(framesLoaded);
    refreshImage();
  };
  view.onerror = () => { loading = false; };
  view.src = "/frame.png?" + l + "&frame=" + frame;
}
async function readProbe() {
  const [x, y] = probe.split(",").map(Number);
  const p = await (await fetch("/pixel?x=" + x + "&y=" + y)).json();
  document.getElementById("probe").textContent = [p.x, p.y, p.r, p.g, p.b, p.spp].join(" ");
}
async function poll() {
  try {
    const after = status && !status.done ? status.frames : -1;
    status = await (await fetch("/status?after=" + after)).json();
    const total = status.total_spp > 0 ? " of " + status.total_spp : "";
    document.getElementById("stats").textContent =
      status.width + "x" + status.height + ", " + status.spp + total + " spp, " +
      (status.samples_per_second / 1e6).toFixed(3) + "M samples/s, " + seconds(status.elapsed) +
      " elapsed, " + (status.done ? "done" : "ETA " + seconds(status.eta));
    refreshImage();
    if (status.done && probe && !probed) { probed = true; await readProbe(); }
  } catch (e) {
    document.getElementById("stats").textContent = "the render has ended (the server stopped)";
    return;
  }
  if (!status.done) poll(); else setTimeout(poll, 2000);
}
let pixelTimer = null;
view.addEventListener("mousemove", (ev) => {
  const r = view.getBoundingClientRect();
  const x = Math.floor((ev.clientX - r.left) * view.naturalWidth / r.width);
  const y = Math.floor((ev.clientY - r.top) * view.naturalHeight / r.height);
  clearTimeout(pixelTimer);
  pixelTimer = setTimeout(async () => {
    const res = await fetch("/pixel?x=" + x + "&y=" + y);
    if (!res.ok) return;
    const p = await res.json();
    document.getElementById("pixel").textContent = "pixel (" + p.x + ", " + p.y + "): L = " +
      p.r.toPrecision(5) + " " + p.g.toPrecision(5) + " " + p.b.toPrecision(5) + " W m^-2 sr^-1, " + p.spp + " spp";
  }, 30);
});
exposure.addEventListener("input", () => {
  document.getElementById("exposure-value").textContent = Number(exposure.value).toFixed(1);
  refreshImage();
});
tonemap.addEventListener("change", refreshImage);
poll();
</script>
</body>
</html>
)HTML";

} // namespace illum::cli
