// The Moon planner (docs/eme.md): the common Moon windows with a DX station from
// GET /api/moon-windows, asked again as the operator types (after a pause) or presses Find.

import { S } from './state.js';
import { $, h, setText } from './dom.js';
import { request } from './api.js';

let timer = null;
let asked = '';
let wired = false; // the form is wired when the page is first opened (navigation.js)

function query() {
  const q = new URLSearchParams();
  const dx = $('planner-dx').value.trim();
  if (dx) q.set('dx_grid', dx);
  for (const [id, key] of [['planner-days', 'days'], ['planner-min-el', 'min_el'], ['planner-dx-min-el', 'dx_min_el']]) {
    const v = $(id).value.trim();
    if (v) q.set(key, v);
  }
  return q.toString();
}

const hhmm = (iso) => String(iso).slice(11, 16);
const length = (s) => `${Math.floor(s / 3600)}h${String(Math.floor(s / 60) % 60).padStart(2, '0')}`;

function row(w) {
  const cells = [String(w.start).slice(0, 10) + ' ' + hhmm(w.start), hhmm(w.end), length(w.duration_s), hhmm(w.best),
    `${w.dgrd_db.toFixed(1)} dB`, `${Math.round(w.tsky_k)} K`, `${w.dpol_deg > 0 ? '+' : ''}${Math.round(w.dpol_deg)}°`,
    `${Math.round(w.sun_sep_deg)}°`];
  return h('tr', {}, ...cells.map((c) => h('td', { text: c })));
}

async function find() {
  const q = query();
  if (q === asked) return;
  asked = q;
  setText('planner-msg', 'Finding the windows…');
  const r = await request('GET', `/api/moon-windows?${q}`);
  if (q !== asked) return;  // a newer question is on its way
  if (r.status === 503) {  // another search is running: ask again in a moment
    asked = '';
    setTimeout(find, 1000);
    return;
  }
  if (!r.ok) {
    $('planner-rows').replaceChildren();
    cue();
    setText('planner-msg', `Not found: ${r.data.error || `HTTP ${r.status}`}`);
    asked = '';
    return;
  }
  const d = r.data;
  $('planner-rows').replaceChildren(...d.windows.map(row));
  cue();
  setText('planner-msg', `${d.windows.length} windows for ${d.grid} and ${d.dx_grid} in ${d.days} days from ${String(d.from).slice(0, 16)} UTC, ${d.band} MHz (best: the minute with the highest Dgrd).`);
}

// The table scrolls sideways on a narrow screen; the hint above it and the fade at its right edge
// say so while there are columns beyond the edge.
function cue() {
  const s = $('planner-scroll');
  const over = s.scrollWidth - s.clientWidth;
  const box = $('planner-box');
  box.classList.toggle('overflows', over > 1);
  box.classList.toggle('more-right', s.scrollLeft < over - 1);
}

function later() {
  clearTimeout(timer);
  timer = setTimeout(find, 500);
}

function wire() {
  wired = true;
  $('planner-form').addEventListener('submit', (e) => { e.preventDefault(); asked = ''; find(); });
  $('planner-scroll').addEventListener('scroll', cue, { passive: true });
  new ResizeObserver(cue).observe($('planner-scroll'));
  for (const id of ['planner-dx', 'planner-days', 'planner-min-el', 'planner-dx-min-el']) $(id).addEventListener('input', later);
}

export function openPlanner() {
  if (!wired) wire();
  const dx = S.config && S.config.dx_grid;
  if (!$('planner-dx').value && dx) $('planner-dx').value = dx;
  if ($('planner-dx').value) find();
  else setText('planner-msg', 'Type the DX station\'s locator.');
}
