// The schedule's priority list ([[schedule]] tables: sat, min_el_deg, preempt), edited on the
// Schedule page: rows added, removed and moved, each satellite found with the Targets page's
// search. Saved whole (POST /api/schedule): the controller checks the list as the file's loader
// does, saves it atomically and follows it at once; a refusal names the row and key and saves
// nothing.

import { S } from './state.js';
import { $, h, setText } from './dom.js';
import { isNum, parseNum } from './format.js';
import { act } from './actions.js';
import { toast } from './toast.js';
import { matches } from './targets.js';
import { entryOf } from './schedule_timeline.js';

let saved = []; // as the controller follows them: {id, sat, min_el_deg, preempt}
let rows = []; // being edited; a saved row keeps its id (its place in the saved list)

const preemptOf = (r) => r.preempt || 'take_over';
const same = (a, b) => a.sat.trim() === b.sat.trim() && a.min_el_deg === b.min_el_deg && preemptOf(a) === preemptOf(b);
const dirty = () => rows.length !== saved.length || rows.some((r, i) => r.id !== i || !same(r, saved[i]));

/// The list the controller follows (GET /api/schedule `entries`), unless edits are waiting
/// (`force`: anyway).
export function loadList(entries, force) {
  if (!force && dirty()) return;
  saved = (Array.isArray(entries) ? entries : []).map((e, i) => ({ id: i, sat: String((e && e.sat) ?? ''),
    min_el_deg: e && isNum(e.min_el_deg) ? e.min_el_deg : null, preempt: (e && e.preempt) || null }));
  rows = saved.map((r) => ({ ...r }));
  render();
}

function changed() {
  const n = rows.length - saved.length;
  const d = dirty();
  $('sch-save').disabled = !d;
  $('sch-undo').disabled = !d;
  setText('sch-count', d ? `changed, not saved${n ? ` (${n > 0 ? '+' : ''}${n} row${Math.abs(n) === 1 ? '' : 's'})` : ''}` : '');
}

function move(i, by) {
  const j = i + by;
  if (j < 0 || j >= rows.length) return;
  [rows[i], rows[j]] = [rows[j], rows[i]];
  render();
  $('sch-rows').children[j].querySelector(by < 0 ? '.up' : '.down')?.focus();
}

// The catalogue's satellites that match what is typed (the Targets page's search), to pick from.
function suggest(input, box, r) {
  const all = S.targets && Array.isArray(S.targets.satellites) ? S.targets.satellites : [];
  const q = input.value.trim();
  const found = q ? all.filter((o) => matches(o, q)).slice(0, 6) : [];
  box.hidden = !found.length || (found.length === 1 && found[0].name === q);
  box.replaceChildren(...found.map((o) => h('button', {
    type: 'button', class: 'sugg', role: 'option', text: `${o.name} · ${o.norad}`,
    onmousedown: (ev) => ev.preventDefault(), // keeps the focus: the input's blur would hide the list first
    onclick: () => { input.value = o.name; r.sat = o.name; box.hidden = true; known(input, r); changed(); },
  })));
}
// A word under the row when the catalogue has no such satellite now (the daemon skips it).
function known(input, r) {
  const all = S.targets && Array.isArray(S.targets.satellites) ? S.targets.satellites : [];
  const none = r.sat.trim() && all.length && !all.some((o) => entryOf([r], { sat: o.name, norad: o.norad }) === 0);
  setText(input.closest('.sch-row').querySelector('.sch-note'), none ? `“${r.sat.trim()}” is not in the satellite catalogue now.` : '');
}

function rowEl(r, i) {
  const sat = h('input', { class: 'sat-in', value: r.sat, autocomplete: 'off', spellcheck: 'false', 'data-field': 'sat',
    placeholder: 'name or NORAD number', 'aria-label': `Priority ${i + 1}: satellite` });
  const box = h('div', { class: 'sat-sugg', role: 'listbox', hidden: true });
  const el = h('input', { inputmode: 'decimal', value: r.min_el_deg == null ? '' : String(r.min_el_deg), placeholder: '0',
    'data-field': 'min_el_deg', 'aria-label': `Priority ${i + 1}: minimum elevation, degrees` });
  const pre = h('select', { 'data-field': 'preempt', 'aria-label': `Priority ${i + 1}: at its AOS` },
    h('option', { value: 'take_over', text: 'takes over' }), h('option', { value: 'finish', text: 'waits for LOS' }));
  pre.value = preemptOf(r);
  sat.addEventListener('input', () => { r.sat = sat.value; suggest(sat, box, r); known(sat, r); changed(); });
  sat.addEventListener('focus', () => suggest(sat, box, r));
  sat.addEventListener('blur', () => { box.hidden = true; });
  el.addEventListener('input', () => { const v = parseNum(el.value); r.min_el_deg = el.value.trim() === '' ? null : v; changed(); });
  pre.addEventListener('change', () => { r.preempt = pre.value; changed(); });
  const btn = (cls, label, text, fn, off) => h('button', { type: 'button', class: `btn small ghost ${cls}`, 'aria-label': label, title: label, text, disabled: off, onclick: fn });
  const row = h('div', { class: 'sch-row', 'data-i': i },
    h('span', { class: 'sch-n', text: String(i + 1) }),
    h('label', { class: 'sch-sat' }, 'Satellite', sat, box),
    h('label', {}, 'Min el °', el),
    h('label', {}, 'At its AOS', pre),
    h('div', { class: 'sch-btns' }, btn('up', 'Move up', '↑', () => move(i, -1), i === 0),
      btn('down', 'Move down', '↓', () => move(i, 1), i === rows.length - 1),
      btn('rm', 'Remove', '✕', () => { rows.splice(i, 1); render(); })),
    h('p', { class: 'hint sch-note' }), h('p', { class: 'error sch-err' }));
  return row;
}

function render() {
  $('sch-rows').replaceChildren(...rows.map(rowEl));
  if (!rows.length) $('sch-rows').append(h('p', { class: 'hint', text: 'No satellite in the schedule.' }));
  $('sch-rows').querySelectorAll('.sch-row').forEach((e, i) => known(e.querySelector('.sat-in'), rows[i]));
  changed();
}

// The first row's problem as the controller would say it, or null.
function check() {
  for (const [i, r] of rows.entries()) {
    if (!r.sat.trim()) return [i, 'sat', 'a satellite is required'];
    if (r.min_el_deg != null && !(r.min_el_deg >= 0 && r.min_el_deg <= 90)) return [i, 'min_el_deg', 'the minimum elevation is 0 to 90°'];
  }
  return null;
}
function markRow(i, field, words) {
  $('sch-rows').querySelectorAll('.bad').forEach((e) => e.classList.remove('bad'));
  const row = $('sch-rows').children[i];
  if (!row) return false;
  row.querySelector(`[data-field="${field}"]`)?.classList.add('bad');
  setText(row.querySelector('.sch-err'), words);
  return true;
}

let onSaved = () => {};

async function save() {
  $('sch-rows').querySelectorAll('.sch-err').forEach((e) => setText(e, ''));
  const bad = check();
  if (bad) { markRow(...bad); setText('sch-save-error', `Not saved: row ${bad[0] + 1}: ${bad[2]}.`); return; }
  const entries = rows.map((r) => {
    const e = { sat: r.sat.trim() };
    if (r.min_el_deg != null) e.min_el_deg = r.min_el_deg;
    if (r.preempt) e.preempt = r.preempt;
    return e;
  });
  const res = await act('save the schedule', 'POST', '/api/schedule', { entries }, { btn: $('sch-save'), quiet: true });
  if (!res.ok) { refused(res); return; }
  setText('sch-save-error', '');
  toast(`Schedule saved: ${entries.length ? `${entries.length} satellite${entries.length === 1 ? '' : 's'}, followed now` : 'empty, the station follows none'}.`, 'ok', null, 6000);
  const plan = res.data && res.data.schedule;
  if (plan) onSaved(plan);
  loadList(plan ? plan.entries : entries, true);
}

function refused(res) {
  if (res.status === 401) { setText('sch-save-error', 'Not saved: log in first.'); return; }
  const msg = res.data.error || (res.status ? `HTTP ${res.status}` : 'no answer from the controller');
  // The form's refusal names "entries[1].min_el_deg" (from 0); the file loader's, with the field
  // "entries", says "[schedule#2].sat …" (from 1).
  const f = String(res.data.field || '');
  const byField = f.match(/^entries\[(\d+)\](?:\.(\w+))?$/);
  const byWords = String(res.data.error || '').match(/\[schedule#(\d+)\]\.(\w+)/);
  const m = byField || byWords;
  const row = m ? Number(m[1]) - (byField ? 0 : 1) : null;
  const beside = row != null && markRow(row, m[2] || 'sat', msg);
  setText('sch-save-error', `Nothing was saved${beside ? ` (row ${row + 1}, above)` : `: ${msg}`}.`);
}

/// Wires the list's buttons; `whenSaved` gets the plan the controller answers a save with.
export function wireList(whenSaved) {
  onSaved = whenSaved;
  $('sch-add').addEventListener('click', () => {
    rows.push({ id: null, sat: '', min_el_deg: null, preempt: null });
    render();
    $('sch-rows').lastElementChild.querySelector('.sat-in').focus();
  });
  $('sch-undo').addEventListener('click', () => { rows = saved.map((r) => ({ ...r })); render(); setText('sch-save-error', ''); });
  $('sch-save').addEventListener('click', save);
}
