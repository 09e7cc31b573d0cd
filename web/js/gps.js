// The GPS page (docs/gps.md): the receiver's fix, the station's surveyed position and a polar
// plot of the satellites gpsd reports.

import { $, h, setText, sv } from './dom.js';
import { fix, fmtLatLon, isNum, pad } from './format.js';
import { loadJSON } from './api.js';
import { drawPolarGrid, polarXY } from './polar.js';

const STATES = {
  off: 'off', no_gpsd: 'gpsd not reachable', no_fix: 'no fix', fix2d: '2D fix', fix3d: '3D fix',
};
const hasFix = (g) => !!g && (g.state === 'fix2d' || g.state === 'fix3d');

// off: not enabled; bad: no gpsd or no fix; fix: a fix from at least 3 satellites.
export function gpsLevel(g) {
  if (!g || !g.state || g.state === 'off') return 'off';
  return hasFix(g) && isNum(g.sats_used) && g.sats_used >= 3 ? 'fix' : 'bad';
}
function satsText(g) {
  return isNum(g.sats_used) && isNum(g.sats_visible) ? `${g.sats_used} used of ${g.sats_visible} seen` : '';
}
export function gpsSummary(g) {
  if (!g || !g.state) return 'not reported';
  if (g.state === 'off') return 'off ([gps] enabled = false)';
  const s = STATES[g.state] || String(g.state);
  return hasFix(g) || g.state === 'no_fix' ? [s, satsText(g)].filter(Boolean).join(', ') : s;
}

function utcText(iso) {
  const d = iso ? new Date(iso) : null;
  if (!d || Number.isNaN(d.getTime())) return '—';
  return `${d.getUTCFullYear()}-${pad(d.getUTCMonth() + 1)}-${pad(d.getUTCDate())} ${pad(d.getUTCHours())}:${pad(d.getUTCMinutes())}:${pad(d.getUTCSeconds())} UTC`;
}
const posText = (p) => (p && isNum(p.lat_deg) && isNum(p.lon_deg)
  ? `${fmtLatLon(p.lat_deg, p.lon_deg)}${isNum(p.alt_m) ? ` · ${fix(p.alt_m, 1)} m` : ''}` : '—');

// The fix's locator, from the controller's Maidenhead (GET /api/locator), asked again only when
// the position has moved by more than a few metres.
const loc = { key: '', grid: '', asked: 0 };
async function showLocator(g) {
  if (!hasFix(g) || !isNum(g.lat_deg) || !isNum(g.lon_deg)) { loc.key = ''; setText('gps-locator', '—'); return; }
  const key = `${g.lat_deg.toFixed(4)},${g.lon_deg.toFixed(4)}`;
  if (key === loc.key) { setText('gps-locator', loc.grid || '…'); return; }
  loc.key = key;
  const asked = ++loc.asked;
  const j = await loadJSON(`/api/locator?lat=${g.lat_deg}&lon=${g.lon_deg}`);
  if (asked !== loc.asked) return;
  const grid = j && j.grid ? String(j.grid) : '';
  loc.grid = grid ? `${grid.slice(0, 4).toUpperCase()}${grid.slice(4)}` : '';
  setText('gps-locator', loc.grid || '—');
}

let lastKey = '';
export function renderGps(g, force) {
  const key = JSON.stringify(g);
  if (!force && key === lastKey) return;
  lastKey = key;
  const lvl = gpsLevel(g);
  const badge = $('gps-badge');
  setText(badge, !g || !g.state ? 'not reported' : (STATES[g.state] || String(g.state)).toUpperCase());
  badge.className = `badge b-${lvl}`;
  setText('gps-state-text', !g || !g.state ? 'The controller does not report a GPS.'
    : g.state === 'off' ? 'Not enabled: [gps] enabled = true in the configuration uses one through gpsd.'
      : g.state === 'no_gpsd' ? 'gpsd does not answer at the configured address ([gps] gpsd).'
        : g.state === 'no_fix' ? 'gpsd is running; the receiver has no fix yet.' : '');
  g = g || {};
  setText('gps-pos', hasFix(g) ? posText({ lat_deg: g.lat_deg, lon_deg: g.lon_deg }) : '—');
  setText('gps-alt', hasFix(g) && isNum(g.alt_m) ? `${fix(g.alt_m, 1)} m` : '—');
  showLocator(g);
  setText('gps-sats', satsText(g) || '—');
  setText('gps-hdop', isNum(g.hdop) ? fix(g.hdop, 2) : '—');
  setText('gps-time', utcText(g.time_utc));
  setText('gps-in-use', g.position_in_use ? 'the GPS survey (this run)' : 'the configured one ([station])');
  setText('gps-surveyed', g.surveyed ? posText(g.surveyed) : 'not yet');
  const j = g.jump_refused;
  $('gps-jump').hidden = !j;
  setText('gps-jump', j ? `A survey at ${posText(j)} is far from the station's position and was not adopted while tracking.` : '');
  drawSats(Array.isArray(g.satellites) ? g.satellites : []);
}

let marks = null;
function drawStatic() {
  const svg = $('gps-sky');
  drawPolarGrid(svg);
  marks = sv('g', { id: 'gps-sats-marks' });
  svg.append(marks);
}
// Each satellite a circle (filled when used in the fix, larger for a stronger signal) and its PRN.
function drawSats(list) {
  if (!marks) drawStatic();
  const out = [];
  for (const s of list) {
    if (!isNum(s.az_deg) || !isNum(s.el_deg)) continue;
    const [x, y] = polarXY(s.az_deg, s.el_deg);
    const snr = isNum(s.snr_dbhz) ? s.snr_dbhz : 0;
    const g = sv('g', { class: `gsat${s.used ? ' used' : ''}`, 'data-prn': s.prn, transform: `translate(${x.toFixed(1)} ${y.toFixed(1)})` });
    g.append(sv('circle', { r: (3 + Math.min(50, Math.max(0, snr)) / 10).toFixed(1) }),
      sv('text', { class: 'prn', x: 0, y: -9, 'text-anchor': 'middle' }, String(s.prn)),
      sv('title', {}, `PRN ${s.prn}: az ${Math.round(s.az_deg)}°, el ${Math.round(s.el_deg)}°, ${isNum(s.snr_dbhz) ? `${Math.round(s.snr_dbhz)} dB-Hz` : 'no signal'}${s.used ? ', used' : ''}`));
    out.push(g);
  }
  marks.replaceChildren(...out);
  const rows = [...list].sort((a, b) => (b.used ? 1 : 0) - (a.used ? 1 : 0) || (b.el_deg ?? -99) - (a.el_deg ?? -99));
  $('gps-sat-list').replaceChildren(...(rows.length ? rows.map((s) => h('tr', { class: s.used ? null : 'below' },
    h('td', { text: String(s.prn) }), h('td', { text: isNum(s.az_deg) ? `${Math.round(s.az_deg)}°` : '—' }),
    h('td', { text: isNum(s.el_deg) ? `${Math.round(s.el_deg)}°` : '—' }),
    h('td', { text: isNum(s.snr_dbhz) ? String(Math.round(s.snr_dbhz)) : '—' }), h('td', { text: s.used ? 'yes' : 'no' })))
    : [h('tr', {}, h('td', { colspan: 5, class: 'dimtxt', text: 'No satellites reported.' }))]));
}
