// The Calibration page (docs/calibration.md): the calibration session (the sources worth a scan,
// the plan's settings, its progress and the scan log's last rows), the fitted model with its
// residuals on the sky (calibration_fit.js), Sun noise (calibration_noise.js) and recording
// (calibration_recording.js). The session's routes are the daemon's calibration API; a
// controller without them answers 404, and the page says so instead of showing anything made up.

import { S } from './state.js';
import { $, h, setText } from './dom.js';
import { isNum, sdeg } from './format.js';
import { request } from './api.js';
import { act } from './actions.js';
import { markBad, readNumbers, num, say, why } from './calibration_ui.js';
import { loadFit, loadHistory, wireFit } from './calibration_fit.js';
import { renderNoise, loadNoiseLog, wireNoise } from './calibration_noise.js';
import { renderRecording, loadRecordings, wireRecording } from './calibration_recording.js';

let wired = false;
let sessionAvailable = null; // null: not asked yet; false: the routes answer 404
let rowsKey = '';
let lastState = '';

function unavailable(msg) {
  sessionAvailable = false;
  const na = $('cal-session-na');
  na.hidden = false;
  setText(na, msg);
  $('cal-session-body').hidden = true;
}

function sourceBox(s) {
  const snr = isNum(s.snr_db) ? `${num(s.snr_db, 0)} dB` : '';
  const box = h('input', { type: 'checkbox', value: s.name, checked: s.worth ? true : null });
  return h('label', { class: s.worth ? '' : 'weak', title: s.why || '' }, box,
    `${s.name}${snr ? ` · ${snr}` : ''}${!s.worth && s.why ? ` (${s.why})` : ''}`);
}

async function loadSources() {
  const r = await request('GET', '/api/calibration/sources');
  if (r.status === 404) {
    unavailable('The calibration session is not available on this controller: its routes (/api/calibration/…) answer 404. Sun noise and recording below work without it.');
    return;
  }
  if (!r.ok) { say('cal-session-msg', `The sources could not be read: ${why(r)}.`, true); return; }
  sessionAvailable = true;
  const list = r.data.sources || [];
  $('cal-sources').replaceChildren(...list.map(sourceBox));
  setText('cal-sources-note', r.data.given ? 'Ticked: the sources whose scans rise clearly above the noise.'
    : 'Without [station] dish_m, efficiency and [receiver] tsys_k every source is offered: tick those the receiver hears.');
}

async function startSession(ev) {
  ev.preventDefault();
  const form = $('cal-session-form');
  const sources = [...$('cal-sources').querySelectorAll('input:checked')].map((b) => b.value);
  const body = { sources, kind: $('cal-kind').value };
  const bad = readNumbers(body, [['cal-hours', 'hours'], ['cal-sun-every', 'sun_every_min'], ['cal-beam', 'beamwidth_deg']]);
  markBad(form, bad);
  if (bad.length) { say('cal-session-msg', 'Not started: hours, minutes and the beamwidth are numbers.', true); return; }
  if (!sources.length) { say('cal-session-msg', 'Not started: tick at least one source.', true); return; }
  const r = await act('start the session', 'POST', '/api/calibration/session', body, { btn: $('cal-start'), form, quiet: true });
  say('cal-session-msg', r.ok ? `Session started: ${sources.join(', ')} for ${body.hours ?? 2} h.` : `Not started: ${why(r)}.`, !r.ok);
}

async function stopSession() {
  const r = await act('stop the session', 'POST', '/api/calibration/session/stop', undefined, { btn: $('cal-stop'), quiet: true });
  say('cal-session-msg', r.ok ? 'Session stopped: its scans stay in the log.' : `Not stopped: ${why(r)}.`, !r.ok);
}

function progressLine(c) {
  const cur = c.current ? ` · now ${c.current.source} (${c.current.kind})` : '';
  const n = `${c.scans_done ?? 0} of ${c.scans_planned ?? '?'} scans`;
  switch (c.state) {
    case 'running': return `Running: ${n}${cur}; ${c.log_rows ?? 0} rows in the log.`;
    case 'done': return `Done: ${n}; ${c.log_rows ?? 0} rows in the log.`;
    case 'stopped': return `Stopped: ${n} (${c.reason || 'stopped'}); ${c.log_rows ?? 0} rows in the log.`;
    default: return `No session running; ${c.log_rows ?? 0} rows in the log.`;
  }
}

function renderRows(rows) {
  const key = JSON.stringify(rows);
  if (key === rowsKey) return;
  rowsKey = key;
  $('cal-rows').replaceChildren(...rows.map((r) => h('tr', {},
    h('td', { text: String(r.utc || '').replace('T', ' ').slice(0, 19) }), h('td', { text: r.source || '' }),
    h('td', { text: num(r.az_deg, 2) }), h('td', { text: num(r.el_deg, 2) }),
    h('td', { text: sdeg(r.daz_deg, 3) }), h('td', { text: sdeg(r.del_deg, 3) }),
    h('td', { text: r.measured || '' }), h('td', { text: isNum(r.snr_db) ? num(r.snr_db, 1) : '—' }),
    h('td', { text: isNum(r.beamwidth_deg) ? num(r.beamwidth_deg, 2) : '—' }))));
}

function renderSession() {
  if (sessionAvailable === false) return;
  const c = S.state && S.state.calibration;
  if (!c) {
    if (S.state) setText('cal-progress', 'The controller reports no calibration session (/api/state has no calibration).');
    $('cal-start').disabled = true;
    return;
  }
  const running = c.state === 'running';
  $('cal-start').disabled = running || sessionAvailable !== true;
  $('cal-stop').disabled = !running;
  setText('cal-progress', progressLine(c));
  renderRows(c.last_rows || []);
  // A session that ended has new rows: the fit is read again.
  if (lastState === 'running' && !running) loadFit();
  lastState = c.state;
}

export function renderCalibration() {
  if (S.screen !== 'calibration') return;
  renderSession();
  renderNoise();
  renderRecording();
}

function wire() {
  wired = true;
  $('cal-session-form').addEventListener('submit', startSession);
  $('cal-stop').addEventListener('click', stopSession);
  wireFit();
  wireNoise();
  wireRecording();
}

export async function openCalibration() {
  if (!wired) wire();
  renderCalibration();
  await Promise.all([loadSources(), loadFit(), loadHistory(), loadNoiseLog(), loadRecordings()]);
  renderCalibration();
}
