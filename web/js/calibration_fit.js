// The Calibration page's fit (docs/calibration.md "The model fitted"): the terms with their
// standard errors, the held terms with their reasons, the rms before and after, each scan's
// residual as an arrow on a polar sky plot (azimuth around, elevation as the radius) before and
// after the fit at one scale, the apply; the models applied, each restorable; the scan log's CSV
// out and in. From GET /api/calibration/fit and /history (404 here: said so, nothing shown).

import { $, h, setText, sv } from './dom.js';
import { isNum, sdeg } from './format.js';
import { request } from './api.js';
import { act } from './actions.js';
import { toast } from './toast.js';
import { drawPolarGrid, polarXY } from './polar.js';
import { num, say, why } from './calibration_ui.js';

const TERMS = [['ia_deg', 'IA', 'azimuth encoder zero'], ['ie_deg', 'IE', 'elevation encoder zero'],
  ['ca_deg', 'CA', 'collimation'], ['npae_deg', 'NPAE', 'axes not square'], ['an_deg', 'AN', 'azimuth axis tilt north'],
  ['aw_deg', 'AW', 'azimuth axis tilt east'], ['sag_deg', 'SAG', 'elevation sag']];
const ARROW_UNITS = 25; // the largest residual before the fit: an eighth of the plot across

function niceStep(v) {
  const p = 10 ** Math.floor(Math.log10(v)); const m = v / p;
  return (m < 2 ? 1 : m < 5 ? 2 : 5) * p;
}

/// The arrow of one residual at its place on the sky: `xel` along increasing azimuth, `el` up
/// (towards the zenith, the plot's centre), `k` plot units per degree. [x0, y0, x1, y1].
export function residualArrow(az, el, xel, del, k) {
  const [x, y] = polarXY(az, el);
  const a = (az * Math.PI) / 180;
  const dx = k * (xel * Math.cos(a) - del * Math.sin(a));
  const dy = k * (xel * Math.sin(a) + del * Math.cos(a));
  return [x, y, x + dx, y + dy];
}

function arrow(x0, y0, x1, y1, cls) {
  const len = Math.hypot(x1 - x0, y1 - y0);
  const kids = [sv('circle', { class: 'at', cx: x0.toFixed(2), cy: y0.toFixed(2), r: 1.1 })];
  if (len < 0.3) return kids;
  const ux = (x1 - x0) / len; const uy = (y1 - y0) / len; const s = Math.min(3.5, len * 0.5);
  kids.push(sv('line', { class: `res ${cls}`, x1: x0.toFixed(2), y1: y0.toFixed(2), x2: x1.toFixed(2), y2: y1.toFixed(2) }),
    sv('path', { class: `head ${cls}`, d: `M${x1.toFixed(2)} ${y1.toFixed(2)}L${(x1 - ux * s + uy * s * 0.5).toFixed(2)} ${(y1 - uy * s - ux * s * 0.5).toFixed(2)}L${(x1 - ux * s - uy * s * 0.5).toFixed(2)} ${(y1 - uy * s + ux * s * 0.5).toFixed(2)}Z` }));
  return kids;
}

/// One sky plot of the residuals (`which`: before or after), at `k` units per degree, with a
/// scale bar of `bar` degrees.
export function drawResidualSky(svg, residuals, which, k, bar) {
  svg.replaceChildren();
  drawPolarGrid(svg);
  for (const r of residuals) {
    if (!isNum(r.az_deg) || !isNum(r.el_deg)) continue;
    const xel = r[`xel_${which}_deg`]; const del = r[`el_${which}_deg`];
    if (!isNum(xel) || !isNum(del)) continue;
    const [x0, y0, x1, y1] = residualArrow(r.az_deg, r.el_deg, xel, del, k);
    const g = sv('g', { class: 'resid' });
    g.append(...arrow(x0, y0, x1, y1, `${which}${r.used === false ? ' unused' : ''}`),
      sv('title', {}, `${r.source || ''} ${String(r.utc || '').slice(0, 16)}: az ${num(r.az_deg, 1)}°, el ${num(r.el_deg, 1)}°, ${which}: ${sdeg(xel, 4)} xel, ${sdeg(del, 4)} el${r.used === false ? ' (left out)' : ''}`));
    svg.append(g);
  }
  const len = bar * k;
  svg.append(sv('line', { class: 'scale', x1: -112, x2: -112 + len, y1: 112, y2: 112 }),
    sv('text', { class: 'scalel', x: -112, y: 108 }, `${num(bar, bar < 0.01 ? 4 : 3)}°`));
}

function termRows(fit) {
  return TERMS.map(([key, name, what]) => {
    const held = fit.held && fit.held[key];
    const std = fit.std_errors && fit.std_errors[key];
    return h('tr', { 'data-term': key }, h('td', { title: what, text: name }), h('td', { class: 'num', text: sdeg(fit.terms[key], 4) }),
      h('td', { class: 'num', text: held ? '—' : `± ${num(std || 0, 4)}°` }), h('td', { text: held || '' }));
  });
}

function renderFit(fit) {
  $('cal-fit').hidden = false;
  $('cal-term-rows').replaceChildren(...termRows(fit));
  const kv = (l, v, id) => h('div', {}, h('span', { class: 'lbl', text: l }), h('span', { class: 'num', id, text: v }));
  $('cal-rms').replaceChildren(kv('rms before', `${num(fit.rms_before_deg, 4)}°`, 'cal-rms-before'),
    kv('rms after', `${num(fit.rms_after_deg, 4)}°`, 'cal-rms-after'),
    kv('largest after', isNum(fit.max_after_deg) ? `${num(fit.max_after_deg, 4)}°` : '—'), kv('scans', String(fit.scans ?? '—')));
  const res = fit.residuals || [];
  const biggest = Math.max(1e-4, ...res.map((r) => Math.hypot(r.xel_before_deg || 0, r.el_before_deg || 0)));
  const k = ARROW_UNITS / biggest;
  const bar = niceStep(biggest / 2);
  drawResidualSky($('cal-sky-before'), res, 'before', k, bar);
  drawResidualSky($('cal-sky-after'), res, 'after', k, bar);
  setText('cal-sky-legend', `Each arrow: the beam's offset from the source at one scan (azimuth around, elevation as the radius, the zenith in the middle), ${num(ARROW_UNITS / k, 4)}° drawn as the longest arrow before the fit; both plots at one scale (the bar: ${num(bar, 4)}°). Dashed grey: scans left out of the fit (weight 0).`);
}

export async function loadFit() {
  say('cal-fit-msg', 'Fitting the scan log…');
  const r = await request('GET', '/api/calibration/fit');
  if (r.ok) { say('cal-fit-msg', ''); renderFit(r.data); return; }
  $('cal-fit').hidden = true;
  $('cal-fit-load').hidden = r.status === 404; // nothing to fit again here
  if (r.status === 404) say('cal-fit-msg', 'The fit is not available on this controller (GET /api/calibration/fit answers 404).', true);
  else say('cal-fit-msg', `No model fitted: ${r.data.refused || why(r)}.`, r.status !== 409);
}

function termsLine(terms) {
  return TERMS.filter(([key]) => isNum(terms && terms[key]) && terms[key] !== 0)
    .map(([key, name]) => `${name} ${sdeg(terms[key], 3)}`).join(' · ') || 'all zero';
}

export async function loadHistory() {
  const r = await request('GET', '/api/calibration/history');
  const list = r.ok ? (r.data.models || []) : [];
  if (r.status === 404) {
    say('cal-history-msg', 'The history of applied models is not available on this controller (404).', true);
    $('cal-export').hidden = true;
    $('cal-import').closest('label').hidden = true;
    $('cal-history').hidden = true;
    say('cal-csv-msg', 'The scan log\'s export and import are not available on this controller.', true);
  } else say('cal-history-msg', r.ok ? (list.length ? '' : 'No model applied yet.') : `Not read: ${why(r)}.`, !r.ok);
  $('cal-history-rows').replaceChildren(...list.map((m, i) => h('tr', {},
    h('td', { text: String(m.utc || '').replace('T', ' ').slice(0, 19) }), h('td', { text: m.why || '' }),
    h('td', { text: String(m.scans ?? '—') }), h('td', { text: isNum(m.rms_after_deg) ? `${num(m.rms_after_deg, 4)}°` : '—' }),
    h('td', { class: 'terms', text: termsLine(m.terms) }),
    h('td', {}, i === 0 ? h('span', { class: 'dimtxt', text: 'in use' }) : h('button', { type: 'button', class: 'btn small', onclick: () => restore(m) }, 'Restore')))));
}

async function apply() {
  const r = await act('apply the model', 'POST', '/api/calibration/apply', undefined, { btn: $('cal-apply'), quiet: true });
  say('cal-fit-msg', r.ok ? 'Applied: the fitted terms are saved as [pointing] and in use.' : `Not applied: ${why(r)}.`, !r.ok);
  if (r.ok) { toast('Pointing model applied'); loadHistory(); }
}

async function restore(m) {
  const r = await act('restore the model', 'POST', '/api/calibration/restore', { id: m.id }, { quiet: true });
  say('cal-history-msg', r.ok ? `Restored the model of ${m.utc}.` : `Not restored: ${why(r)}.`, !r.ok);
  if (r.ok) loadHistory();
}

async function importCsv() {
  const file = $('cal-import').files[0];
  if (!file) return;
  const text = await file.text();
  const r = await act('import the scan log', 'POST', '/api/calibration/log', text, { quiet: true, type: 'text/csv' });
  say('cal-csv-msg', r.ok ? `Imported ${file.name}: ${r.data.imported} rows added to the log (${r.data.log_rows} in all).` : `Not imported: ${why(r)}.`, !r.ok);
  $('cal-import').value = '';
  if (r.ok) loadFit();
}

export function wireFit() {
  $('cal-fit-load').addEventListener('click', loadFit);
  $('cal-apply').addEventListener('click', apply);
  $('cal-import').addEventListener('change', importCsv);
}
