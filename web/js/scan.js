// The pointing-scan page (docs/calibration.md): the form that starts a scan
// (POST /api/scan), the receiver's state, the power read at each point plotted against the offset
// as the points come in, the fitted Gaussian once the scan is fitted, the result, and the
// one-press apply (POST /api/scan/apply). What is shown comes from /api/state's `scan` and
// `receiver`, as the WebSocket brings them (no polling of its own).

import { S } from './state.js';
import { $, h, setText, sv } from './dom.js';
import { deg, fix, isNum, parseNum, sdeg } from './format.js';
import { act } from './actions.js';
import { toast } from './toast.js';
import { loadTargets } from './targets.js';
import { loadConfig } from './setup.js';
import { fitWidth } from './trend.js';

const FOUR_LN2 = 4 * Math.LN2;
const gauss = (s, s0, w) => Math.exp((-FOUR_LN2 * (s - s0) * (s - s0)) / (w * w));
// The optional settings (empty: the daemon's defaults, docs/web-api.md).
const OPTIONAL = [['scan-points', 'points_per_line'], ['scan-span', 'half_span_beams'],
  ['scan-ref', 'reference_beams'], ['scan-settle', 'settle_s'], ['scan-dwell', 'dwell_s']];
const KINDS = { cross: 'cross', 'five-point': 'five-point', raster: 'raster' };

let drawnKey = '';
let resultKey = '';
let wired = false; // the page's controls are wired when it is first opened (navigation.js)
let started = '';  // the start's message stands until that scan has run and ended: '', 'asked', 'seen'

// The page's message line: what the last action did, or why it was refused.
function say(msg, bad = false) {
  const m = $('scan-msg');
  setText(m, msg);
  m.className = bad ? 'error' : 'dimtxt';
}

// ------------------------------------------------------------------ the samples and the fit

// Each sample in its line's plot, by its planned point (the API's planned_xel_deg/planned_el_deg):
// the elevation line's points have a planned cross-elevation offset of 0, the cross-elevation
// line's a planned elevation of 0, so the source's own point (0, 0) lies on both and is drawn in
// the elevation plot as well (marked as shared). A five-point scan's reference points belong to
// neither line's curve but are shown on the cross-elevation plot, where they lie.
export function splitLines(samples) {
  const xel = []; const el = [];
  samples.forEach((s, i) => {
    const p = { i, xel: s.xel_deg, el: s.el_deg, db: s.power_db };
    const onXel = s.planned_el_deg === 0;
    const onEl = s.planned_xel_deg === 0 && !s.reference;
    if (onXel || s.reference) xel.push({ ...p, s: s.xel_deg });
    if (onEl) el.push({ ...p, s: s.el_deg, shared: onXel });
  });
  return { xel, el };
}

// The fitted curve of one line, linear power as a function of the offset, or null: the API's
// fit gives each line's centre, width and curve (core/include/azt/calibration/scan_fit.hpp
// LineCurve): p(s) = baseline + slope·(s − centre) + amplitude·gauss(s − centre).
export function lineModel(scan, axis) {
  const f = scan.fit;
  if (!f) return null;
  const s0 = axis === 'xel' ? f.xel_offset_deg : f.el_offset_deg;
  const w = axis === 'xel' ? f.width_xel_deg : f.width_el_deg;
  const c = f[`${axis}_curve`];
  if (!c || !isNum(s0) || !(w > 0) || !isNum(c.baseline) || !isNum(c.amplitude)) return null;
  return (s) => c.baseline + (c.slope || 0) * (s - s0) + c.amplitude * gauss(s, s0, w);
}

// ------------------------------------------------------------------ plots

function niceStep(span, n) {
  const raw = span / n; const p = 10 ** Math.floor(Math.log10(raw)); const m = raw / p;
  return (m <= 1 ? 1 : m <= 2 ? 2 : m <= 5 ? 5 : 10) * p;
}
function ticks(lo, hi, n) {
  const step = niceStep(hi - lo, n);
  const list = [];
  for (let v = Math.ceil(lo / step - 1e-9) * step; v <= hi + step * 1e-9; v += step) list.push(Math.abs(v) < step * 1e-9 ? 0 : v);
  return { list, places: Math.max(0, -Math.floor(Math.log10(step) + 1e-9)) };
}
function span(values, pad, min) {
  let lo = Math.min(...values); let hi = Math.max(...values);
  if (!values.length) { lo = -min; hi = min; }
  if (hi - lo < min) { const c = (lo + hi) / 2; lo = c - min / 2; hi = c + min / 2; }
  const p = (hi - lo) * pad;
  return [lo - p, hi + p];
}
const sign = (v, n) => (v > 0 ? `+${fix(v, n)}` : v < 0 ? `−${fix(-v, n)}` : fix(0, n));

// Axes with ticks and their labels, the frame of a plot; returns the kids to append first.
function axes(P, xr, yr, X, Y, xTitle, yTitle, yDeg = false) {
  const kids = [];
  const xt = ticks(xr[0], xr[1], Math.max(3, Math.round((P.R - P.L) / 80)));
  const yt = ticks(yr[0], yr[1], 5);
  for (const v of xt.list) {
    kids.push(sv('line', { class: v === 0 ? 'zero' : 'gl', x1: X(v), x2: X(v), y1: P.T, y2: P.B }),
      sv('text', { x: X(v), y: P.B + 15, 'text-anchor': 'middle' }, `${sign(v, xt.places)}°`));
  }
  for (const v of yt.list) {
    kids.push(sv('line', { class: 'gl', x1: P.L, x2: P.R, y1: Y(v), y2: Y(v) }),
      sv('text', { x: P.L - 6, y: Y(v), 'text-anchor': 'end', 'dominant-baseline': 'middle' }, yDeg ? `${sign(v, yt.places)}°` : fix(v, yt.places)));
  }
  kids.push(sv('rect', { class: 'frame', x: P.L, y: P.T, width: P.R - P.L, height: P.B - P.T }),
    sv('text', { class: 'axt', x: (P.L + P.R) / 2, y: P.B + 31, 'text-anchor': 'middle' }, xTitle),
    sv('text', { class: 'axt', x: 4, y: P.T - 2, 'dominant-baseline': 'auto' }, yTitle));
  return kids;
}

// Power (dB) against the offset along one line: the readings as circles, the fitted curve, the
// fitted centre as a dashed line. A missing reading is a cross on the bottom edge.
function drawLine(svg, pts, model, centre, cls, xTitle) {
  const H = 230;
  const W = fitWidth(svg, H);
  const P = { L: 46, R: W - 12, T: 16, B: H - 42 };
  const xr = span([...pts.map((p) => p.s), ...(isNum(centre) ? [centre] : [])], 0.06, 0.5);
  const curve = [];
  if (model) {
    for (let k = 0; k <= 160; k += 1) {
      const s = xr[0] + ((xr[1] - xr[0]) * k) / 160; const p = model(s);
      if (p > 0) curve.push([s, 10 * Math.log10(p)]);
    }
  }
  const dbs = pts.filter((p) => isNum(p.db)).map((p) => p.db);
  const yr = span([...dbs, ...curve.map((c) => c[1])], 0.08, 1);
  const X = (s) => P.L + ((s - xr[0]) / (xr[1] - xr[0])) * (P.R - P.L);
  const Y = (v) => P.B - ((v - yr[0]) / (yr[1] - yr[0])) * (P.B - P.T);
  const kids = axes(P, xr, yr, X, Y, xTitle, 'dB');
  if (!pts.length) kids.push(sv('text', { class: 'empty', x: (P.L + P.R) / 2, y: (P.T + P.B) / 2, 'text-anchor': 'middle' }, 'no points read yet'));
  if (curve.length > 1) {
    kids.push(sv('path', { class: `fitc ${cls}`, d: curve.map((c, k) => `${k ? 'L' : 'M'}${X(c[0]).toFixed(1)} ${Y(c[1]).toFixed(1)}`).join('') }));
  }
  if (model && isNum(centre)) kids.push(sv('line', { class: `fitx ${cls}`, 'data-deg': centre, x1: X(centre), x2: X(centre), y1: P.T, y2: P.B }));
  for (const p of pts) {
    if (!isNum(p.db)) {
      const x = X(p.s); const y = P.B - 6;
      kids.push(sv('path', { class: 'miss', 'data-i': p.i, d: `M${x - 4} ${y - 4}L${x + 4} ${y + 4}M${x - 4} ${y + 4}L${x + 4} ${y - 4}` },
        null));
      continue;
    }
    const c = sv('circle', { class: `spt ${cls}${p.shared ? ' shared' : ''}`, 'data-i': p.i, cx: X(p.s).toFixed(1), cy: Y(p.db).toFixed(1), r: 4.5 });
    c.append(sv('title', {}, `${sign(p.s, 3)}°: ${fix(p.db, 2)} dB${p.shared ? ' (the point on the source, on both lines)' : ''}`));
    kids.push(c);
  }
  svg.replaceChildren(...kids);
}

// A raster: the points on the sky (cross-elevation right, elevation up, to one scale), each
// shaded by its power, and the fitted beam as its half-power circle around the fitted centre.
function drawMap(svg, scan) {
  const H = 320;
  const W = fitWidth(svg, H);
  const P = { L: 46, R: W - 12, T: 16, B: H - 42 };
  const samples = scan.samples || [];
  const f = scan.fit;
  const xs = samples.map((s) => s.xel_deg); const ys = samples.map((s) => s.el_deg);
  let xr = span(xs, 0.08, 1); let yr = span(ys, 0.08, 1);
  // one scale on both axes: widen the narrower range
  const perPx = Math.max((xr[1] - xr[0]) / (P.R - P.L), (yr[1] - yr[0]) / (P.B - P.T));
  const cx = (xr[0] + xr[1]) / 2; const cy = (yr[0] + yr[1]) / 2;
  xr = [cx - (perPx * (P.R - P.L)) / 2, cx + (perPx * (P.R - P.L)) / 2];
  yr = [cy - (perPx * (P.B - P.T)) / 2, cy + (perPx * (P.B - P.T)) / 2];
  const X = (s) => P.L + ((s - xr[0]) / (xr[1] - xr[0])) * (P.R - P.L);
  const Y = (v) => P.B - ((v - yr[0]) / (yr[1] - yr[0])) * (P.B - P.T);
  const kids = axes(P, xr, yr, X, Y, 'cross-elevation offset (az · cos el)', 'elevation offset', true);
  const dbs = samples.filter((s) => isNum(s.power_db)).map((s) => s.power_db);
  const lo = Math.min(...dbs); const hi = Math.max(...dbs);
  samples.forEach((s, i) => {
    if (!isNum(s.power_db)) {
      kids.push(sv('path', { class: 'miss', 'data-i': i, d: `M${X(s.xel_deg) - 4} ${Y(s.el_deg) - 4}l8 8m-8 0l8 -8` }));
      return;
    }
    const k = hi > lo ? (s.power_db - lo) / (hi - lo) : 1;
    const c = sv('circle', { class: 'spt smap', 'data-i': i, cx: X(s.xel_deg).toFixed(1), cy: Y(s.el_deg).toFixed(1), r: 6, 'fill-opacity': (0.12 + 0.88 * k).toFixed(2) });
    c.append(sv('title', {}, `${sign(s.xel_deg, 3)}°, ${sign(s.el_deg, 3)}°: ${fix(s.power_db, 2)} dB`));
    kids.push(c);
  });
  if (f && isNum(f.xel_offset_deg) && f.width_xel_deg > 0) {
    kids.push(sv('circle', { class: 'fitc fitbeam', cx: X(f.xel_offset_deg), cy: Y(f.el_offset_deg), r: f.width_xel_deg / 2 / perPx }),
      sv('path', { class: 'fitx', d: `M${X(f.xel_offset_deg) - 7} ${Y(f.el_offset_deg)}h14M${X(f.xel_offset_deg)} ${Y(f.el_offset_deg) - 7}v14` }));
  }
  svg.replaceChildren(...kids);
}

// ------------------------------------------------------------------ the page

function receiverLine(r) {
  if (!r || r.source === 'none' || r.state === 'off') {
    return ['No receiver: a scan needs one in the configuration ([receiver]: udp, rtl_power, or sim on the simulated antenna; docs/calibration.md).', true];
  }
  const where = `${r.source}${r.listen ? ` ${r.listen}` : r.path ? ` ${r.path}` : ''}`;
  const counts = `good ${r.good}, malformed ${r.malformed}, missing ${r.missing}`;
  const extra = `${r.problem ? ` · ${r.problem}` : ''}${r.malformed && r.last_malformed ? ` · last malformed: ${r.last_malformed}` : ''}`;
  if (r.state !== 'receiving' || !isNum(r.power_db)) {
    return [`Receiver (${where}): no readings — a scan needs them. ${counts}${extra}.`, true];
  }
  return [`Receiver (${where}): ${fix(r.power_db, 2)} dB, ${isNum(r.age_s) ? `${fix(r.age_s, 1)} s ago` : 'now'} · ${counts}${extra}`, false];
}

function stateLine(sc) {
  const what = `${sc.source || '—'}${sc.kind ? `, ${sc.kind}` : ''}${isNum(sc.beamwidth_deg) ? `, ${deg(sc.beamwidth_deg)} beam` : ''}`;
  const pts = isNum(sc.points_total) ? `${sc.points_done} of ${sc.points_total} points` : '';
  switch (sc.state) {
    case 'running': return `Scanning ${what}: ${pts}.`;
    case 'done': return `Done: ${what}, ${pts}, fitted.`;
    case 'refused': return `Not fitted: ${what}, ${pts}.`;
    case 'stopped': return `Stopped: ${what}, ${pts} (${sc.reason || 'stopped'}).`;
    default: return 'No scan yet.';
  }
}

const row = (label, value, id) => h('div', {}, h('span', { class: 'lbl', text: label }), h('span', { class: 'num', id, text: value }));

function renderResult(sc) {
  const key = JSON.stringify([sc.state, sc.reason, sc.kind, sc.beamwidth_deg, sc.fit, sc.found]);
  if (key === resultKey) return;
  resultKey = key;
  const f = sc.fit; const found = sc.found;
  const kids = [];
  if (sc.state === 'refused') kids.push(h('p', { class: 'error', id: 'scan-refusal', text: `The fit was refused: ${sc.reason}` }));
  if (f) {
    const std = (v) => (v > 0 ? ` ± ${fix(v, 4)}°` : '');
    if (found) kids.push(row('Beam found at (mount)', `az ${sdeg(found.az_offset_deg, 3)} · el ${sdeg(found.el_offset_deg, 3)}`, 'scan-found'));
    kids.push(row('Centre on the sky (xel / el)', `${sdeg(f.xel_offset_deg, 3)}${std(f.xel_std_deg)} / ${sdeg(f.el_offset_deg, 3)}${std(f.el_std_deg)}`, 'scan-centre'));
    if (!(f.xel_std_deg > 0 || f.el_std_deg > 0)) kids.push(row('Standard errors', sc.kind === 'five-point' ? 'none (a five-point scan is solved exactly)' : '—'));
    kids.push(row('Beamwidth (xel / el)', `${deg(f.width_xel_deg, 3)} / ${deg(f.width_el_deg, 3)} (expected ${deg(sc.beamwidth_deg, 2)})`, 'scan-width'));
    kids.push(row('Peak above baseline', `${fix(f.peak_db, 2)} dB${f.noise_db > 0 ? ` · noise ${fix(f.noise_db, 3)} dB rms` : ''}`, 'scan-peak'));
    kids.push(row('Readings', `${f.used} used, ${f.missing} missing`));
  }
  if (!kids.length) kids.push(h('p', { class: 'dimtxt', text: sc.state === 'running' ? 'The fit comes when the last point is read.' : 'No result yet.' }));
  $('scan-result').replaceChildren(...kids);
}

function renderApply(sc) {
  const found = sc.found;
  $('scan-apply').disabled = !found;
  const c = (S.state && S.state.corrections) || {};
  if (found && isNum(c.az_offset_deg)) {
    setText('scan-apply-hint', `Sets the encoder offsets to az ${sdeg(c.az_offset_deg - found.az_offset_deg, 3)}, el ${sdeg(c.el_offset_deg - found.el_offset_deg, 3)} (now ${sdeg(c.az_offset_deg, 3)}, ${sdeg(c.el_offset_deg, 3)}), saved.`);
  } else setText('scan-apply-hint', sc.fit ? 'No unapplied result: each result is applied once.' : 'A fitted scan\'s offsets can be applied here.');
}

function renderPlots(sc, force) {
  const key = JSON.stringify([sc.state, sc.kind, sc.samples, sc.fit]);
  if (!force && key === drawnKey) return;
  drawnKey = key;
  const raster = sc.kind === 'raster';
  $('scan-lines').hidden = raster;
  $('scan-map-box').hidden = !raster;
  if (raster) { drawMap($('scan-map'), sc); return; }
  const { xel, el } = splitLines(sc.samples || []);
  const f = sc.fit || {};
  drawLine($('scan-plot-xel'), xel, lineModel(sc, 'xel'), f.xel_offset_deg, 'sxel', 'cross-elevation offset (az · cos el)');
  drawLine($('scan-plot-el'), el, lineModel(sc, 'el'), f.el_offset_deg, 'sel', 'elevation offset');
}

export function renderScan(force) {
  if (S.screen !== 'scan') return;
  const st = S.state || {};
  const [rx, rxBad] = receiverLine(st.receiver);
  setText('scan-receiver', rx);
  $('scan-receiver').className = rxBad ? 'warn-txt' : '';
  const sc = st.scan || { state: 'idle' };
  setText('scan-state', stateLine(sc));
  const running = sc.state === 'running';
  if (started === 'asked' && running) started = 'seen';
  else if (started === 'seen' && !running) { started = ''; say(''); }
  $('scan-stop').disabled = !running;
  $('scan-start').disabled = running;
  fillFromScan(sc);
  renderResult(sc);
  renderApply(sc);
  renderPlots(sc, force);
}

// The form shows the running or last scan's source, kind and beamwidth until the operator
// changes them (then theirs stand).
function fillFromScan(sc) {
  if (!sc || !sc.source) return;
  const sel = $('scan-source');
  if (!sel.dataset.touched && [...sel.options].some((o) => o.value === sc.source)) sel.value = sc.source;
  if (!$('scan-kind').dataset.touched && KINDS[sc.kind]) $('scan-kind').value = sc.kind;
  const bw = $('scan-beam');
  if (!bw.dataset.touched && bw.value === '' && isNum(sc.beamwidth_deg)) bw.value = String(sc.beamwidth_deg);
}

function fillSources() {
  const sel = $('scan-source');
  const list = ((S.targets && S.targets.targets) || []).filter((t) => ['sun', 'moon', 'source'].includes(t.kind));
  const opts = list.length ? list : [{ name: 'Sun' }, { name: 'Moon' }];
  const names = opts.map((o) => o.name).join('\n');
  if (sel.dataset.names !== names) {
    const was = sel.value;
    sel.dataset.names = names;
    sel.replaceChildren(...opts.map((o) => h('option', { value: o.name, text: o.name })));
    const t = S.state && S.state.target;
    const want = was || (t && opts.some((o) => o.name === t.name) ? t.name : opts[0].name);
    if (opts.some((o) => o.name === want)) sel.value = want;
  }
  for (const o of sel.options) {
    const t = list.find((x) => x.name === o.value);
    setText(o, t && isNum(t.el_deg) ? `${t.name} · el ${fix(t.el_deg, 0)}°${t.el_deg < 0 ? ' (below the horizon)' : ''}` : o.value);
  }
}

async function start(ev) {
  ev.preventDefault();
  const f = $('scan-form');
  f.querySelectorAll('.bad').forEach((e) => e.classList.remove('bad'));
  const body = { source: $('scan-source').value, kind: KINDS[$('scan-kind').value] || 'cross' };
  const bw = parseNum($('scan-beam').value);
  const bad = [];
  if (!(bw > 0)) bad.push('scan-beam'); else body.beamwidth_deg = bw;
  for (const [id, key] of OPTIONAL) {
    const raw = $(id).value.trim();
    if (raw === '') continue;
    const v = parseNum(raw);
    if (Number.isNaN(v)) bad.push(id); else body[key] = v;
  }
  if (bad.length) {
    bad.forEach((id) => $(id).classList.add('bad'));
    if (bad.some((id) => id !== 'scan-beam')) $('scan-more').open = true;
    say('Not started: the beamwidth and the settings must be numbers (degrees, beamwidths, seconds).', true);
    return;
  }
  say(`Starting the scan of ${body.source}…`);
  const r = await act('start the scan', 'POST', '/api/scan', body, { btn: $('scan-start'), form: f, quiet: true });
  if (r.ok) {
    started = 'asked';
    say(`Scanning ${r.data.target || body.source}: the antenna tracks it with the scan's offsets; any other command, a fault or STOP ends the scan.`);
    renderScan(true);
  } else say(`Not started: ${r.status === 401 ? 'log in first' : r.data.error || `HTTP ${r.status}`}.`, true);
}

async function stop() {
  const r = await act('stop the scan', 'POST', '/api/scan/stop', undefined, { btn: $('scan-stop'), quiet: true });
  if (r.ok) { started = ''; say('Scan stopped: the antenna keeps tracking the source.'); }
  else say(`Not stopped: ${r.status === 401 ? 'log in first' : r.data.error || `HTTP ${r.status}`}.`, true);
}

async function apply() {
  const c = (S.state && S.state.corrections) || {};
  const was = [c.az_offset_deg, c.el_offset_deg];
  const r = await act('apply the scan\'s offsets', 'POST', '/api/scan/apply', undefined, { btn: $('scan-apply'), quiet: true });
  if (!r.ok) {
    say(`Not applied: ${r.status === 401 ? 'log in first' : r.data.error || `HTTP ${r.status}`}.`, true);
    return;
  }
  const before = S.config;
  await loadConfig(true);
  const now = S.config !== before && S.config && S.config.corrections;
  if (!now) { say('Applied and saved; the new offsets could not be read back: see the Antenna screen.', true); return; }
  const msg = `Applied and saved: encoder offsets az ${sdeg(now.az_offset_deg, 3)}, el ${sdeg(now.el_offset_deg, 3)}${isNum(was[0]) ? ` (were ${sdeg(was[0], 3)}, ${sdeg(was[1], 3)})` : ''}.`;
  say(msg);
  toast(msg);
}

function wire() {
  wired = true;
  $('scan-form').addEventListener('submit', start);
  $('scan-stop').addEventListener('click', stop);
  $('scan-apply').addEventListener('click', apply);
  for (const id of ['scan-source', 'scan-kind', 'scan-beam']) {
    $(id).addEventListener('input', () => { $(id).dataset.touched = '1'; });
    $(id).addEventListener('change', () => { $(id).dataset.touched = '1'; });
  }
}

export async function openScan() {
  if (!wired) wire();
  fillSources();
  renderScan(true);
  await loadTargets();
  fillSources();
}
