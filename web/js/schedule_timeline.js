// The schedule's next hours as one SVG (schedule.js): the hours in UTC with the local time below
// them, a row per scheduled satellite in priority order with its passes as bars, the plan's steps
// (track, pre-position, park, power off) on a lane of their own, and a line at "now".

import { sv } from './dom.js';
import { fix, pad, utcLocal } from './format.js';

const W = 1000; // viewBox units; the SVG is as wide as its card (at least 720 px: css/schedule.css)
const LABEL = 150;
const RIGHT = 8;
const HEAD = 34;
const ROW = 26;
const LANE = 30;
export const KIND_WORDS = { track: 'Track', preposition: 'Pre-position', park: 'Park', power_off: 'Motors off' };

let span = null; // {t0, t1, height}: where "now" goes

const xOf = (t) => LABEL + ((t - span.t0) / (span.t1 - span.t0)) * (W - LABEL - RIGHT);
const clampX = (t) => xOf(Math.min(span.t1, Math.max(span.t0, t)));

// Which row (entry) a pass belongs to, as the daemon reads `sat` (docs/satellites.md "The
// schedule"): the entry that names it whole, else by its NORAD number, else by the start of its
// name ("AO-7" is not taken for AO-73 when AO-73 has an entry of its own). -1: none.
export function entryOf(entries, pass) {
  const name = String(pass.sat || '').toLowerCase();
  const norad = String(pass.norad ?? '').replace(/^0+/, '');
  const sats = entries.map((e) => String(e.sat || '').trim().toLowerCase());
  const whole = sats.indexOf(name);
  if (whole >= 0) return whole;
  const byNumber = sats.findIndex((s) => /^\d+$/.test(s) && s.replace(/^0+/, '') === norad);
  if (byNumber >= 0) return byNumber;
  return sats.findIndex((s) => s && !/^\d+$/.test(s) && name.startsWith(s));
}

function hourTicks(height) {
  const out = [];
  const first = Math.ceil(span.t0 / 3600e3) * 3600e3;
  const every = (span.t1 - span.t0) > 12 * 3600e3 ? 3 : 1;
  for (let t = first; t <= span.t1; t += 3600e3) {
    const d = new Date(t);
    const x = xOf(t).toFixed(1);
    const labelled = d.getUTCHours() % every === 0;
    out.push(sv('line', { class: labelled ? 'gl major' : 'gl', x1: x, x2: x, y1: HEAD - 6, y2: height }));
    if (!labelled) continue;
    out.push(sv('text', { class: 'tick', x, y: 12, 'text-anchor': 'middle' }, `${pad(d.getUTCHours())}:00`));
    if (d.getTimezoneOffset() !== 0) out.push(sv('text', { class: 'tick loc', x, y: 24, 'text-anchor': 'middle' }, `${pad(d.getHours())}:${pad(d.getMinutes())}`));
  }
  out.push(sv('text', { class: 'tick', x: LABEL - 8, y: 12, 'text-anchor': 'end' }, 'UTC'));
  if (new Date(span.t0).getTimezoneOffset() !== 0) out.push(sv('text', { class: 'tick loc', x: LABEL - 8, y: 24, 'text-anchor': 'end' }, 'local'));
  return out;
}

function rowOf(e, i, passes) {
  const y = HEAD + i * ROW;
  const g = sv('g', { class: 'srow', 'data-sat': String(e.sat) });
  g.append(sv('text', { class: 'rowl', x: 6, y: y + 17 }, `${i + 1}. ${e.sat}`));
  for (const p of passes) {
    const a = Date.parse(p.aos); const b = Date.parse(p.los);
    if (!(b > span.t0 && a < span.t1)) continue;
    // Not worked: below the entry's minimum elevation, or given way to a higher priority.
    const low = p.worked === false || (p.worked == null && Number.isFinite(e.min_el_deg) && p.max_el_deg < e.min_el_deg);
    const x = clampX(a);
    const bar = sv('rect', { class: `pass${low ? ' low' : ''}`, x: x.toFixed(1), y: y + 5, width: Math.max(2, clampX(b) - x).toFixed(1), height: ROW - 10, rx: 2 });
    bar.append(sv('title', {}, `${p.sat}: AOS ${utcLocal(p.aos)}, max ${fix(p.max_el_deg, 0)}°, LOS ${utcLocal(p.los)}${low ? ' (not worked)' : ''}`));
    g.append(bar);
  }
  return g;
}

function laneOf(plan, y) {
  const g = sv('g', { class: 'lane' });
  g.append(sv('text', { class: 'rowl', x: 6, y: y + 19 }, 'Plan'));
  for (const s of plan) {
    const a = Date.parse(s.from); const b = Date.parse(s.to);
    if (!(b > span.t0 && a < span.t1) || !KIND_WORDS[s.kind]) continue;
    const x = clampX(a); const w = Math.max(2, clampX(b) - x);
    const r = sv('rect', { class: `seg seg-${s.kind}`, x: x.toFixed(1), y: y + 4, width: w.toFixed(1), height: LANE - 8, rx: 2 });
    r.append(sv('title', {}, `${KIND_WORDS[s.kind]}${s.sat ? ` ${s.sat}` : ''}: ${utcLocal(s.from)} to ${utcLocal(s.to)}`));
    g.append(r);
  }
  return g;
}

/// Draws `sched` (GET /api/schedule) into `svg`.
export function drawTimeline(svg, sched) {
  const entries = Array.isArray(sched.entries) ? sched.entries : [];
  const t0 = Date.parse(sched.from);
  const hours = Number(sched.hours) > 0 ? Number(sched.hours) : 24;
  const laneY = HEAD + entries.length * ROW + 4;
  const height = laneY + LANE + 4;
  span = { t0, t1: t0 + hours * 3600e3, height };
  svg.setAttribute('viewBox', `0 0 ${W} ${height}`);
  const passes = Array.isArray(sched.passes) ? sched.passes : [];
  const rows = entries.map((e, i) => rowOf(e, i, passes.filter((p) => entryOf(entries, p) === i)));
  const now = sv('g', { id: 'sch-now', class: 'now' });
  now.append(sv('line', { x1: 0, x2: 0, y1: HEAD - 8, y2: height }), sv('text', { x: 3, y: HEAD - 2 }, 'now'));
  svg.replaceChildren(...hourTicks(height), ...rows, laneOf(Array.isArray(sched.plan) ? sched.plan : [], laneY), now);
}

/// Moves the "now" line to `ms` (the daemon's clock); hidden outside the drawn hours.
export function placeNow(svg, ms) {
  const g = svg.querySelector('#sch-now');
  if (!g || !span) return;
  const inside = Number.isFinite(ms) && ms >= span.t0 && ms <= span.t1;
  g.style.display = inside ? '' : 'none';
  if (inside) g.setAttribute('transform', `translate(${xOf(ms).toFixed(1)} 0)`);
}
