"""The emulator in the browser (issue 70): an offline page with a slider per factor, drawing the emulators'
stress-strain prediction (strains 0.02 to 0.20) with its 95 % band, computed in the page, in plain JavaScript,
from the emulators' exported numbers (emulator.data.js beside it; the formula of analysis/emulator.py).

The page reads a setting from its address (#dryness=0.55&turgor_kPa=180...), so that a link keeps a setting and
a test can set the sliders; it writes the prediction into a table (id="prediction") and reports in
<div id="status">."""
import html
import json
import pathlib

PAGE = """<!doctype html><html><head><meta charset="utf-8"><title>The cell's emulator</title>
<style>body{font-family:sans-serif;max-width:1000px;margin:auto;padding:1em}
.slider{display:grid;grid-template-columns:11em 1fr 6em;gap:.5em;align-items:center;font-size:90%}
table{border-collapse:collapse;font-size:80%}td,th{border:1px solid #ccc;padding:2px 6px;text-align:right}
svg text{font-size:11px}</style></head><body>
<p class="meta">Made by __PROVENANCE__. Offline: this page and emulator.data.js, nothing fetched.</p>
<h1>The closed cell's stress, predicted by its emulator</h1>
<p>Each slider sets one factor of the design (study <code>__STUDY__</code>) within its range. The curve is the
emulators' median of the plate stress at strains 0.02 to 0.20, the band where 95 % of new runs would fall
(Gaussian processes fitted to the design's runs, in the logarithm of the stress; see the sensitivity page for
their check on held-out runs). A setting outside the design's ranges cannot be chosen.</p>
<div id="sliders"></div>
<svg id="plot" width="640" height="380"></svg>
<table id="prediction"><thead><tr><th>strain</th><th>median [kPa]</th><th>95 % low</th><th>95 % high</th></tr></thead>
<tbody></tbody></table>
<div id="status">loading</div>
<script src="emulator.data.js"></script>
<script>
"use strict";
const D = EMULATOR_DATA;
function toUnit(f, v) {
  const [lo, hi] = f.range;
  return f.scale === "log" ? Math.log(v / lo) / Math.log(hi / lo) : (v - lo) / (hi - lo);
}
function fromUnit(f, u) {
  const [lo, hi] = f.range;
  return f.scale === "log" ? lo * Math.exp(u * Math.log(hi / lo)) : lo + u * (hi - lo);
}
// mean = y_mean + y_std k.alpha; var = (sd_scale y_std)^2 (c + noise - |L^-1 k|^2): analysis/emulator.py predict()
function predict(em, u) {
  const n = em.alpha.length, k = new Float64Array(n);
  for (let i = 0; i < n; i++) {
    let s = 0;
    for (let j = 0; j < u.length; j++) { const d = (u[j] - em.x[i][j]) / em.length_scales[j]; s += d * d; }
    k[i] = em.constant * Math.exp(-0.5 * s);
  }
  let m = 0;
  for (let i = 0; i < n; i++) m += k[i] * em.alpha[i];
  const v = new Float64Array(n);  // L v = k, forward substitution
  let vv = 0;
  for (let i = 0; i < n; i++) {
    let s = k[i];
    for (let j = 0; j < i; j++) s -= em.L[i][j] * v[j];
    v[i] = s / em.L[i][i];
    vv += v[i] * v[i];
  }
  const variance = Math.max(em.constant + em.noise - vv, 0);
  return [em.y_mean + em.y_std * m, (em.sd_scale || 1) * em.y_std * Math.sqrt(variance)];
}
const Z95 = 1.959964;
const sliders = {}, current = {};  // a setting from the address is kept exactly until its slider moves
function setting() {
  return current;
}
function curve(values) {
  const u = D.factors.map(f => toUnit(f, values[f.name]));
  return D.strains.map((e, i) => {
    const [m, s] = predict(D.emulators[i], u);
    return {strain: e, median: Math.exp(m), low: Math.exp(m - Z95 * s), high: Math.exp(m + Z95 * s)};
  });
}
function draw(points) {
  const svg = document.getElementById("plot"), W = 640, H = 380, L = 60, B = 40, T = 15, R = 15;
  const ymax = Math.max(...points.map(p => p.high)) * 1.05;
  const X = e => L + (W - L - R) * e / 0.2, Y = s => H - B - (H - B - T) * s / ymax;
  let g = `<rect x="${L}" y="${T}" width="${W - L - R}" height="${H - B - T}" fill="none" stroke="#888"/>`;
  for (let e = 0; e <= 0.2001; e += 0.05) g += `<text x="${X(e)}" y="${H - B + 15}" text-anchor="middle">${e.toFixed(2)}</text>`;
  const step = Math.pow(10, Math.floor(Math.log10(ymax / 4)));
  const tick = [1, 2, 5].map(m => m * step).find(t => ymax / t <= 6) || 10 * step;
  for (let s = 0; s <= ymax; s += tick) g += `<text x="${L - 5}" y="${Y(s) + 4}" text-anchor="end">${+s.toPrecision(3)}</text>`;
  g += `<text x="${(W + L) / 2}" y="${H - 5}" text-anchor="middle">nominal strain</text>`;
  g += `<text x="14" y="${(H - B) / 2}" transform="rotate(-90 14 ${(H - B) / 2})" text-anchor="middle">plate stress [kPa]</text>`;
  const band = points.map(p => `${X(p.strain)},${Y(p.high)}`).concat(points.slice().reverse().map(p => `${X(p.strain)},${Y(p.low)}`));
  g += `<polygon points="${band.join(" ")}" fill="#1f77b4" fill-opacity="0.25"/>`;
  g += `<polyline points="${points.map(p => `${X(p.strain)},${Y(p.median)}`).join(" ")}" fill="none" stroke="#1f77b4" stroke-width="2"/>`;
  svg.innerHTML = g;
}
function update() {
  const values = setting();
  for (const f of D.factors) document.getElementById("value-" + f.name).textContent = (+values[f.name].toPrecision(4)).toString();
  const points = curve(values);
  draw(points);
  document.querySelector("#prediction tbody").innerHTML = points.map(p =>
    `<tr><td>${p.strain.toFixed(2)}</td><td>${p.median.toPrecision(8)}</td><td>${p.low.toPrecision(8)}</td><td>${p.high.toPrecision(8)}</td></tr>`).join("");
  document.getElementById("status").textContent = "predicted at " + D.factors.map(f => f.name + "=" + (+values[f.name].toPrecision(6))).join("&");
}
try {
  const asked = new URLSearchParams(location.hash.slice(1));
  const div = document.getElementById("sliders");
  for (const f of D.factors) {
    const row = document.createElement("div");
    row.className = "slider";
    row.innerHTML = `<label for="slider-${f.name}">${f.title}</label><input type="range" id="slider-${f.name}" min="0" max="1000" step="1"><span id="value-${f.name}"></span>`;
    div.appendChild(row);
    const s = row.querySelector("input");
    const wanted = asked.has(f.name) ? Number(asked.get(f.name)) : Math.min(Math.max(f.base, f.range[0]), f.range[1]);
    if (!(wanted >= f.range[0] && wanted <= f.range[1])) throw new Error(`${f.name} = ${asked.get(f.name)} is outside its range ${f.range}`);
    s.value = String(Math.round(1000 * toUnit(f, wanted)));
    current[f.name] = wanted;
    s.addEventListener("input", () => { current[f.name] = fromUnit(f, s.value / 1000); update(); });
    sliders[f.name] = s;
  }
  update();
} catch (error) {
  document.getElementById("status").textContent = "error: " + error.message;
}
</script></body></html>
"""


def write(page, data_file, data, provenance_line):
    """The page and its data (a script that sets EMULATOR_DATA), side by side."""
    pathlib.Path(data_file).write_text("const EMULATOR_DATA = " + json.dumps(data) + ";\n")
    text = PAGE.replace("__PROVENANCE__", html.escape(provenance_line)).replace("__STUDY__", html.escape(data["study"]))
    pathlib.Path(page).write_text(text)
