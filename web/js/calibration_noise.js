// The Calibration page's Sun noise (docs/calibration.md "Sun noise and the figure of merit"):
// the measurement's form (POST /api/noise), each pointing as it is read, the Y-factor with each
// pair's value beside the mean and the expected value, and the noise log over time
// (GET /api/noise/log). What runs comes from /api/state `noise`, as the WebSocket brings it.

import { S } from './state.js';
import { $, h, setText, sv } from './dom.js';
import { isNum } from './format.js';
import { request } from './api.js';
import { act } from './actions.js';
import { markBad, readNumbers, num, say, why } from './calibration_ui.js';

const NUMBERS = [['noise-beam', 'beamwidth_deg'], ['noise-offset', 'offset_beams'], ['noise-repeats', 'repeats'],
  ['noise-settle', 'settle_s'], ['noise-dwell', 'dwell_s'], ['noise-dish', 'dish_m'], ['noise-eff', 'efficiency'],
  ['noise-tsys', 'tsys_k'], ['noise-freq', 'freq_mhz'], ['noise-moon-k', 'moon_k']];
let stepsKey = '';
let resultKey = '';
let lastState = '';

function stateLine(n) {
  const of = isNum(n.steps_total) ? ` ${n.steps_done} of ${n.steps_total} pointings` : '';
  switch (n.state) {
    case 'running': return `Measuring ${n.source}:${of} read.`;
    case 'done': return `Done: ${n.source},${of}.`;
    case 'refused': return `No result: ${n.reason}`;
    case 'stopped': return `Stopped: ${n.source} (${n.reason || 'stopped'}).`;
    default: return 'No measurement yet.';
  }
}

function renderSteps(n) {
  const key = JSON.stringify(n.steps || []);
  if (key === stepsKey) return;
  stepsKey = key;
  $('noise-step-rows').replaceChildren(...(n.steps || []).map((s, i) => h('tr', {},
    h('td', { text: String(i + 1) }), h('td', { text: s.on ? 'on the source' : `cold sky, ${s.side > 0 ? 'clockwise' : 'anticlockwise'}` }),
    h('td', { class: 'num', text: isNum(s.power_db) ? num(s.power_db, 2) : 'missed' }), h('td', { text: String(s.readings ?? '') }))));
}

/// Each pair's Y as a dot, their mean as a line, the expected value dashed.
export function drawPairs(svg, ys, mean, expected) {
  const W = 320; const H = 150; const P = { L: 40, R: W - 70, T: 10, B: H - 20 };
  const all = [...ys, mean, ...(isNum(expected) ? [expected] : [])].filter(isNum);
  let lo = Math.min(...all); let hi = Math.max(...all);
  if (hi - lo < 0.2) { const c = (lo + hi) / 2; lo = c - 0.1; hi = c + 0.1; }
  const pad = (hi - lo) * 0.15; lo -= pad; hi += pad;
  const Y = (v) => P.B - ((v - lo) / (hi - lo)) * (P.B - P.T);
  const X = (i) => P.L + ((i + 0.5) / Math.max(1, ys.length)) * (P.R - P.L);
  const kids = [sv('rect', { class: 'frame', x: P.L, y: P.T, width: P.R - P.L, height: P.B - P.T })];
  for (const v of [lo + pad, hi - pad]) kids.push(sv('text', { x: P.L - 4, y: Y(v), 'text-anchor': 'end', 'dominant-baseline': 'middle' }, num(v, 2)));
  if (isNum(mean)) kids.push(sv('line', { class: 'mean', x1: P.L, x2: P.R, y1: Y(mean), y2: Y(mean) }), sv('text', { class: 'lbl-mean', x: P.R + 4, y: Y(mean), 'dominant-baseline': 'middle' }, `Y ${num(mean, 2)}`));
  if (isNum(expected)) kids.push(sv('line', { class: 'expect', x1: P.L, x2: P.R, y1: Y(expected), y2: Y(expected) }), sv('text', { class: 'lbl-expect', x: P.R + 4, y: Y(expected) + (Math.abs(Y(expected) - Y(mean)) < 10 ? 11 : 0), 'dominant-baseline': 'middle' }, `exp. ${num(expected, 2)}`));
  ys.forEach((v, i) => { const c = sv('circle', { class: 'pt', cx: X(i), cy: Y(v), r: 3.5 }); c.append(sv('title', {}, `pair ${i + 1}: ${num(v, 3)} dB`)); kids.push(c); });
  kids.push(sv('text', { x: (P.L + P.R) / 2, y: H - 4, 'text-anchor': 'middle' }, 'each on/off pair, dB'));
  svg.replaceChildren(...kids);
}

function renderResult(n) {
  const key = JSON.stringify([n.state, n.result]);
  if (key === resultKey) return;
  resultKey = key;
  const r = n.result;
  const kv = (l, v, id) => h('div', {}, h('span', { class: 'lbl', text: l }), h('span', { class: 'num', id, text: v }));
  if (!r) { $('noise-result').replaceChildren(); $('noise-pairs').replaceChildren(); return; }
  const x = r.expected;
  const kids = [kv('Y-factor', `${num(r.y_factor_db, 2)} ± ${num(r.std_error_db, 2)} dB (${r.pairs} pairs${r.missed ? `, ${r.missed} missed` : ''})`, 'noise-y')];
  if (x) {
    kids.push(kv('Expected', `${num(x.y_db, 2)} dB (${num(x.flux_sfu, 1)} SFU at the band, T_A ${num(x.antenna_k, 0)} K)`, 'noise-expected'),
      kv('Measured − expected', `${num(r.y_factor_db - x.y_db, 2)} dB`),
      kv('G/T', `${num(x.g_over_t_db, 2)} dB/K`), kv('T_sys implied', `${num(x.implied_tsys_k, 0)} K`));
  }
  $('noise-result').replaceChildren(...kids);
  drawPairs($('noise-pairs'), r.pair_y_db || [], r.y_factor_db, x && x.y_db);
}

export function renderNoise() {
  const n = (S.state && S.state.noise) || { state: 'idle' };
  setText('noise-state', stateLine(n));
  const running = n.state === 'running';
  $('noise-start').disabled = running;
  $('noise-stop').disabled = !running;
  renderSteps(n);
  renderResult(n);
  if (lastState === 'running' && n.state === 'done') loadNoiseLog();
  lastState = n.state;
}

/// The log's Y-factors over time, one dot each, by source.
function drawHistory(svg, entries) {
  const pts = entries.map((e) => [Date.parse(e.utc), e.y_factor_db, String(e.source || '').toLowerCase()]).filter((p) => isNum(p[0]) && isNum(p[1]));
  if (!pts.length) { svg.replaceChildren(sv('text', { x: 300, y: 75, 'text-anchor': 'middle' }, 'no measurements logged yet')); return; }
  const W = 600; const H = 150; const P = { L: 44, R: W - 10, T: 10, B: H - 24 };
  let t0 = Math.min(...pts.map((p) => p[0])); let t1 = Math.max(...pts.map((p) => p[0]));
  if (t1 - t0 < 3600e3) { t0 -= 1800e3; t1 += 1800e3; }
  let lo = Math.min(...pts.map((p) => p[1])); let hi = Math.max(...pts.map((p) => p[1]));
  if (hi - lo < 1) { lo -= 0.5; hi += 0.5; }
  const X = (t) => P.L + ((t - t0) / (t1 - t0)) * (P.R - P.L);
  const Y = (v) => P.B - ((v - lo) / (hi - lo)) * (P.B - P.T);
  const kids = [sv('rect', { class: 'frame', x: P.L, y: P.T, width: P.R - P.L, height: P.B - P.T }),
    sv('text', { x: P.L - 4, y: Y(hi), 'text-anchor': 'end', 'dominant-baseline': 'middle' }, num(hi, 1)),
    sv('text', { x: P.L - 4, y: Y(lo), 'text-anchor': 'end', 'dominant-baseline': 'middle' }, num(lo, 1)),
    sv('text', { x: P.L, y: H - 6 }, new Date(t0).toISOString().slice(0, 10)),
    sv('text', { x: P.R, y: H - 6, 'text-anchor': 'end' }, new Date(t1).toISOString().slice(0, 10))];
  for (const [t, v, src] of pts) {
    const c = sv('circle', { class: `pt ${src === 'sun' || src === 'moon' ? src : ''}`, cx: X(t), cy: Y(v), r: 3.5 });
    c.append(sv('title', {}, `${new Date(t).toISOString().slice(0, 16)} ${src}: ${num(v, 2)} dB`));
    kids.push(c);
  }
  svg.replaceChildren(...kids);
}

export async function loadNoiseLog() {
  const r = await request('GET', '/api/noise/log');
  if (!r.ok) { say('noise-log-msg', r.status === 404 ? 'The noise log is not available on this controller.' : `The noise log could not be read: ${why(r)}.`, true); return; }
  const entries = r.data.entries || [];
  say('noise-log-msg', `${entries.length ? '' : 'Nothing logged yet. '}${r.data.bad_lines ? `${r.data.bad_lines} unreadable lines skipped.` : ''}`);
  $('noise-log-rows').replaceChildren(...entries.map((e) => h('tr', {},
    h('td', { text: String(e.utc || '').replace('T', ' ').slice(0, 19) }), h('td', { text: e.source || '' }),
    h('td', { class: 'num', text: `${num(e.y_factor_db, 2)} ± ${num(e.std_error_db || 0, 2)}` }),
    h('td', { class: 'num', text: e.expected ? num(e.expected.y_db, 2) : '—' }),
    h('td', { class: 'num', text: e.expected && isNum(e.expected.g_over_t_db) ? num(e.expected.g_over_t_db, 2) : '—' }),
    h('td', { class: 'num', text: isNum(e.el_deg) ? `${num(e.el_deg, 0)}°` : '—' }))));
  drawHistory($('noise-history'), entries);
}

async function start(ev) {
  ev.preventDefault();
  const form = $('noise-form');
  const body = { source: $('noise-source').value };
  const bad = readNumbers(body, [...NUMBERS, ['noise-flux', $('noise-flux-kind').value]]);
  markBad(form, bad);
  if (bad.length) { say('noise-msg', 'Not started: the marked fields must be numbers.', true); return; }
  const r = await act('measure the noise', 'POST', '/api/noise', body, { btn: $('noise-start'), form, quiet: true });
  say('noise-msg', r.ok ? `Measuring ${body.source}: the antenna tracks it, then cold sky either side; any other command or STOP ends it.` : `Not started: ${why(r)}.`, !r.ok);
}

async function stop() {
  const r = await act('stop the measurement', 'POST', '/api/noise/stop', undefined, { btn: $('noise-stop'), quiet: true });
  say('noise-msg', r.ok ? 'Stopped: the antenna keeps tracking the source.' : `Not stopped: ${why(r)}.`, !r.ok);
}

export function wireNoise() {
  $('noise-form').addEventListener('submit', start);
  $('noise-stop').addEventListener('click', stop);
  // The flux field's key follows the choice of what the number is.
  $('noise-flux-kind').addEventListener('change', () => { $('noise-flux').dataset.field = $('noise-flux-kind').value; });
}
