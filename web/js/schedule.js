// The Schedule page (#schedule, from Targets; docs/satellites.md "The schedule"): what the station
// does now and next by its [[schedule]] (/api/state `schedule`), the next hours as a timeline
// (GET /api/schedule), "held by … — Resume" (POST /api/schedule/resume), and the priority list
// to edit (schedule_edit.js). Loaded when the page is first opened (navigation.js).

import { S } from './state.js';
import { $, h, setText } from './dom.js';
import { countdown, utcLocal } from './format.js';
import { request } from './api.js';
import { act } from './actions.js';
import { toast } from './toast.js';
import { drawTimeline, KIND_WORDS, placeNow } from './schedule_timeline.js';
import { loadList, wireList } from './schedule_edit.js';

let wired = false;
let plan = null; // GET /api/schedule
let readAt = 0; // when it was read (the browser's clock: only to read it again each minute)
let reading = null;
let stepKey = null;

export async function openSchedule() {
  if (!wired) {
    wired = true;
    // A save answers with the new list at once; its plan is made on the controller's worker.
    wireList((p) => { showPlan(p); setTimeout(readPlan, 3000); });
    $('sch-resume').addEventListener('click', resume);
  }
  await readPlan();
  renderSchedule(true);
}

function readPlan() {
  reading = reading || (async () => {
    const r = await request('GET', '/api/schedule');
    readAt = Date.now();
    if (r.ok) { showPlan(r.data); return; }
    plan = null;
    setText('sch-msg', r.status === 404 ? 'This controller has no satellite schedule (GET /api/schedule answered 404).'
      : `The plan could not be read: ${r.data.error || (r.status ? `HTTP ${r.status}` : 'no answer')}.`);
    $('sch-timeline').replaceChildren();
    $('sch-plan-rows').replaceChildren();
  })().finally(() => { reading = null; });
  return reading;
}

// GET /api/schedule's answer (or a save's): the list to edit (unless edits wait), the timeline and
// the steps.
function showPlan(p) {
  plan = p;
  const entries = Array.isArray(p.entries) ? p.entries : [];
  loadList(entries);
  const when = p.from ? '' : ' The controller has not planned them yet.';
  setText('sch-msg', entries.length ? when.trim() : 'No satellite in the schedule: add one to the priority list.');
  drawTimeline($('sch-timeline'), p.from ? p : { ...p, from: S.state ? S.state.utc : new Date().toISOString() });
  renderPlanRows();
  if (S.state) placeNow($('sch-timeline'), Date.parse(S.state.utc));
}

// "Track ISS", "Pre-position for ISS", "Park", "Motors off".
function stepWords(s) {
  if (!s) return '—';
  const what = KIND_WORDS[s.kind] || String(s.kind);
  if (!s.sat) return what;
  return s.kind === 'preposition' ? `${what} for ${s.sat}` : `${what} ${s.sat}`;
}
// "18:26 UTC (23:56 local), in 4 min 12 s", by the daemon's clock.
function whenWords(iso, nowMs) {
  const t = Date.parse(iso);
  if (!Number.isFinite(t)) return '—';
  return `${utcLocal(iso)}${t > nowMs ? `, ${countdown((t - nowMs) / 1000)}` : ''}`;
}

function renderPlanRows() {
  const steps = plan && Array.isArray(plan.plan) ? plan.plan : [];
  const now = S.state ? Date.parse(S.state.utc) : NaN;
  $('sch-plan-rows').replaceChildren(...steps.map((s) => h('tr', { class: Date.parse(s.from) <= now && now < Date.parse(s.to) ? 'sel' : null },
    h('td', { text: KIND_WORDS[s.kind] || String(s.kind) }), h('td', { text: s.sat || '—' }),
    h('td', { text: utcLocal(s.from) }), h('td', { text: utcLocal(s.to) }))));
  setText('sch-plan-count', steps.length ? `(${steps.length})` : '');
  if (!steps.length) $('sch-plan-rows').append(h('tr', {}, h('td', { colspan: 4, class: 'dimtxt', text: 'Nothing planned in these hours.' })));
}

function badge(cls, word, words) {
  const b = $('sch-badge');
  if (b.className !== `badge ${cls}`) b.className = `badge ${cls}`;
  setText(b, word);
  setText('sch-state', words);
}

function renderNow(s, nowMs) {
  if (!s) badge('b-off', 'OFF', 'no satellite in the schedule');
  else if (s.held_by) badge('b-bad', 'HELD', `held by ${s.held_by}`);
  else if (s.running) badge('b-fix', 'RUNNING', 'the station follows the schedule');
  else badge('b-off', 'IDLE', 'nothing scheduled now');
  $('sch-held').hidden = !(s && s.held_by);
  if (s && s.held_by) setText('sch-held-text', `Held by ${s.held_by}: the schedule waits until it is resumed.`);
  const step = s && s.step;
  setText('sch-step', step ? stepWords(step) : 'nothing');
  setText('sch-step-end', step ? whenWords(step.to, nowMs) : '—');
  const next = s && s.next;
  setText('sch-next', next ? stepWords(next) : 'nothing planned');
  setText('sch-next-at', next ? whenWords(next.from, nowMs) : '—');
  const problems = s && Array.isArray(s.problems) ? s.problems : [];
  $('sch-problems').hidden = !problems.length;
  setText('sch-problems', problems.length ? `Not planned: ${problems.join('; ')}.` : '');
  const power = s ? s.power : null;
  setText('sch-power', power === 'on' ? 'on' : power === 'off' ? 'off (switched by the schedule)' : 'no power relay');
}

export function renderSchedule() {
  const st = S.state;
  if (!st || !$('sch-step')) return;
  const s = st.schedule || null;
  const nowMs = Date.parse(st.utc);
  renderNow(s, nowMs);
  placeNow($('sch-timeline'), nowMs);
  // The plan again when the step changes, and each minute.
  const key = JSON.stringify(s ? [s.step, s.next, s.running, s.held_by] : null);
  const changed = stepKey !== null && key !== stepKey;
  stepKey = key;
  if (!reading && (changed || Date.now() - readAt > 60000)) readPlan();
}

async function resume() {
  const r = await act('resume the schedule', 'POST', '/api/schedule/resume', undefined, { btn: $('sch-resume') });
  if (r.ok) toast('The schedule runs again.');
}
