// The setup and antenna screens' forms: station, band, control, park slots, tilt table.

import { S } from './state.js';
import { $, h, setText, sv } from './dom.js';
import { deg, fix, fmtLatLon, isNum, pad, parseNum } from './format.js';
import { toast } from './toast.js';
import { loadJSON, request } from './api.js';
import { act } from './actions.js';
import { fillBands } from './bands.js';
import { fitWidth, niceScale } from './trend.js';
import { loadTargets } from './targets.js';

export async function loadConfig(force) {
  const j = await loadJSON('/api/config');
  if (!j) return;
  S.config = j;
  fillConfig(force);
}
// Setup's Software line (the Software page, loaded when opened, keeps it up to date there).
export async function softwareLine() {
  const r = await request('GET', '/api/software');
  if (r.ok && typeof r.data.version === 'string') setText('setup-software', [`version ${r.data.version}`, r.data.architecture].filter(Boolean).join(' · '));
}
export function field(id, value, force) {
  const i = $(id);
  if (!i || (!force && (i.dataset.dirty || document.activeElement === i))) return;
  i.value = value == null ? '' : String(value);
  delete i.dataset.dirty;
  i.classList.remove('bad');
}
export function clean(form) { form.querySelectorAll('input').forEach((i) => { delete i.dataset.dirty; i.classList.remove('bad'); }); }
const num6 = (v) => (isNum(v) ? String(Math.round(v * 1e6) / 1e6) : '');
function fillConfig(force) {
  const c = S.config;
  if (!c) return;
  const st = c.station || {};
  field('grid', st.grid || '', force);
  field('lat', num6(st.lat_deg), force);
  field('lon', num6(st.lon_deg), force);
  field('alt', isNum(st.alt_m) ? String(st.alt_m) : '', force);
  showOther();
  fillBands();
  setText('dx-grid', c.dx_grid || 'none');
  // servers
  const sv2 = c.servers || {};
  const addr = (x) => (x && x.port ? `${x.bind}:${x.port}` : 'off');
  const rows = [['rotctld (Hamlib, TCP)', addr(sv2.rotctld)], ['PstRotator (UDP)', addr(sv2.pstrotator)], ['Web console', addr(sv2.web)]];
  for (const s of Array.isArray(sv2.serial) ? sv2.serial : []) rows.push([`Serial ${s.protocol}`, `${s.device} · ${s.baud} Bd`]);
  $('servers').replaceChildren(...rows.map(([k, v]) => h('div', {}, h('span', { class: 'lbl', text: k }), h('span', { text: v }))));
  // control, offsets
  const ctl = c.control || {};
  field('window', ctl.window_deg, force); field('ramp', ctl.ramp_s, force); field('tracking-speed', ctl.tracking_speed, force);
  const corr = c.corrections || {};
  field('az-offset', corr.az_offset_deg, force); field('el-offset', corr.el_offset_deg, force);
  const rn = Array.isArray(c.restart_needed) ? c.restart_needed : [];
  setText('setup-settings', rn.length ? `${rn.length} saved setting${rn.length === 1 ? '' : 's'} wait${rn.length === 1 ? 's' : ''} for a restart` : 'every setting of the controller');
  document.querySelectorAll('[data-key]').forEach((i) => {
    const note = i.nextElementSibling;
    if (note && note.classList.contains('restart-note')) note.hidden = !rn.includes(i.dataset.key);
  });
  fillPark(force);
  fillTilt(force);
  const g = c.geometry || {};
  $('geometry').replaceChildren(
    h('div', {}, h('span', { class: 'lbl', text: 'Azimuth' }), h('span', { text: `${deg(g.az_min_deg, 1)} … ${deg(g.az_max_deg, 1)}` })),
    h('div', {}, h('span', { class: 'lbl', text: 'Elevation' }), h('span', { text: `${deg(g.el_min_deg, 1)} … ${deg(g.el_max_deg, 1)}` })));
  setText('man-limits', isNum(g.az_min_deg) ? `Azimuth 0 … 360°, elevation ${fix(g.el_min_deg, 1)} … ${fix(g.el_max_deg, 1)}°.` : '');
}
// The other representation of what the operator types (a locator's centre, a position's
// locator), from the controller's Maidenhead (GET /api/locator); a newer keystroke's answer wins.
let locatorAsked = 0;
export async function showOther() {
  const asked = ++locatorAsked;
  const grid = $('grid').value.trim();
  const lat = parseNum($('lat').value);
  const lon = parseNum($('lon').value);
  const [square, locator] = await Promise.all([
    grid ? loadJSON(`/api/locator?grid=${encodeURIComponent(grid)}`) : null,
    isNum(lat) && isNum(lon) ? loadJSON(`/api/locator?lat=${lat}&lon=${lon}`) : null]);
  if (asked !== locatorAsked) return;
  setText('grid-other', square ? `Centre of the square: ${fmtLatLon(square.lat_deg, square.lon_deg)}` : grid ? 'Not a valid locator: 2 letters A–R, 2 digits, then optional pairs (like FN06HE).' : '');
  const g = locator ? locator.grid : '';
  setText('latlon-other', g ? `Locator ${g.slice(0, 4).toUpperCase()}${g.slice(4)}` : '');
}

export function buildPark() {
  const box = $('park-editor');
  for (let n = 1; n <= 4; n++) {
    const f = h('form', { class: 'park-row', id: `park-form-${n}`, novalidate: true },
      h('span', { class: 'slotn', text: String(n) }),
      h('label', { class: 'pname' }, 'Name', h('input', { id: `park-name-${n}`, 'data-f': 'name', autocomplete: 'off', maxlength: 32 })),
      h('label', { class: 'paz' }, 'Az °', h('input', { id: `park-az-${n}`, 'data-f': 'az_deg', inputmode: 'decimal', autocomplete: 'off' })),
      h('label', { class: 'pel' }, 'El °', h('input', { id: `park-el-${n}`, 'data-f': 'el_deg', inputmode: 'decimal', autocomplete: 'off' })),
      h('button', { type: 'submit', class: 'btn small psave', id: `park-save-${n}`, text: 'Save' }),
      h('p', { class: 'error', id: `park-error-${n}` }));
    f.addEventListener('submit', (ev) => { ev.preventDefault(); savePark(n, f); });
    box.append(f);
  }
}
function fillPark(force) {
  const park = (S.config && S.config.park) || [];
  for (let n = 1; n <= 4; n++) {
    const p = park.find((x) => x.slot === n) || {};
    field(`park-name-${n}`, p.name, force); field(`park-az-${n}`, p.az_deg, force); field(`park-el-${n}`, p.el_deg, force);
  }
}
async function savePark(n, f) {
  const errEl = $(`park-error-${n}`);
  const az = parseNum($(`park-az-${n}`).value); const el = parseNum($(`park-el-${n}`).value);
  const name = $(`park-name-${n}`).value.trim();
  if (Number.isNaN(az) || Number.isNaN(el)) { setText(errEl, 'Azimuth and elevation must be numbers.'); return; }
  const r = await act(`save park slot ${n}`, 'PUT', '/api/config/park', { slot: n, name, az_deg: az, el_deg: el }, { btn: $(`park-save-${n}`), errEl, form: f });
  if (r.ok) { clean(f); toast(`Park slot ${n} saved.`); await loadConfig(true); loadTargets(); }
}

// Tilt table: 60 entries, az 0, 6 … 354. Shown as 10 rows × 6 columns, read down the columns.
const tiltPending = {};
export function buildTilt() {
  const box = $('tilt-grid');
  for (let i = 0; i < 60; i++) {
    const az = i * 6;
    const inp = h('input', { id: `tilt-${i}`, inputmode: 'decimal', autocomplete: 'off', 'data-index': i, 'aria-label': `Tilt correction at azimuth ${az}°` });
    inp.addEventListener('change', () => saveTilt(i));
    inp.addEventListener('keydown', (ev) => { if (ev.key === 'Enter') { ev.preventDefault(); saveTilt(i); } });
    inp.addEventListener('input', () => { inp.dataset.dirty = '1'; inp.classList.remove('saved'); });
    box.append(h('label', { class: 'tcell' }, h('span', { text: pad(az, 3) }), inp));
  }
}
function tiltValues() { const t = S.config && S.config.corrections && S.config.corrections.tilt_el_deg; return Array.isArray(t) ? t : []; }
function fillTilt(force) {
  const t = tiltValues();
  for (let i = 0; i < 60; i++) if (isNum(t[i])) field(`tilt-${i}`, String(t[i]), force);
  drawTilt();
}
async function saveTilt(i) {
  const inp = $(`tilt-${i}`);
  const v = parseNum(inp.value);
  const az = pad(i * 6, 3);
  if (Number.isNaN(v)) { inp.classList.add('bad'); setText('tilt-error', `Az ${az}°: “${inp.value}” is not a number.`); return; }
  const t = tiltValues();
  if (t[i] === v && !inp.classList.contains('bad')) { delete inp.dataset.dirty; return; }
  if (tiltPending[i] === v) return;
  tiltPending[i] = v;
  const r = await act(`save the tilt table at az ${az}°`, 'PUT', '/api/config/tilt', { index: i, value: v }, { errEl: $('tilt-error') });
  delete tiltPending[i];
  if (r.ok) {
    if (S.config && S.config.corrections && Array.isArray(S.config.corrections.tilt_el_deg)) S.config.corrections.tilt_el_deg[i] = v;
    delete inp.dataset.dirty;
    inp.classList.remove('bad'); inp.classList.add('saved');
    setTimeout(() => inp.classList.remove('saved'), 1500);
    drawTilt();
  } else {
    inp.classList.add('bad');
    if (r.status !== 401 && r.data.error) setText('tilt-error', `Az ${az}°: ${r.data.error} (not saved)`);
  }
}
export function drawTilt() {
  const t = tiltValues();
  const svg = $('tilt-plot');
  const W = fitWidth(svg, 170);
  const L = 48; const R = W - 10; const T = 10; const B = 146;
  const m = Math.max(0.1, ...t.filter(isNum).map(Math.abs));
  const sc = niceScale(m);
  const x = (az) => L + (az / 360) * (R - L);
  const y = (v) => (T + B) / 2 - (v / sc) * ((B - T) / 2);
  const kids = [];
  for (const v of [sc, 0, -sc]) {
    kids.push(sv('line', { class: v === 0 ? 'zero' : 'gl', x1: L, x2: R, y1: y(v), y2: y(v) }),
      sv('text', { x: L - 6, y: y(v), 'text-anchor': 'end', 'dominant-baseline': 'middle' }, v === 0 ? '0°' : `${v > 0 ? '+' : '−'}${sc}°`));
  }
  for (let az = 0; az <= 360; az += W < 420 ? 90 : 60) {
    kids.push(sv('line', { class: 'gl', x1: x(az), x2: x(az), y1: T, y2: B, 'stroke-dasharray': '2 4' }),
      sv('text', { x: x(az), y: B + 16, 'text-anchor': az === 0 ? 'start' : az === 360 ? 'end' : 'middle' }, `${az}°`));
  }
  if (t.length === 60 && t.every(isNum)) {
    let d = '';
    for (let i = 0; i <= 60; i++) d += `${i ? 'L' : 'M'}${x(i * 6).toFixed(1)} ${y(t[i % 60]).toFixed(1)}`;
    kids.push(sv('path', { class: 'tilt', d }));
    t.forEach((v, i) => kids.push(sv('circle', { class: 'tiltpt', cx: x(i * 6).toFixed(1), cy: y(v).toFixed(1), r: 2.2 }, null)));
  }
  svg.replaceChildren(...kids);
}
