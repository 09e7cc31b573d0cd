// The Calibration page's recording (docs/calibration.md "Recording"): start at a rate, stop, the
// state from /api/state `recording`, and the recordings under the state directory with their
// download links (GET /api/recordings, /api/recordings/NAME).

import { S } from './state.js';
import { $, h, setText } from './dom.js';
import { request } from './api.js';
import { act } from './actions.js';
import { markBad, readNumbers, num, say, why } from './calibration_ui.js';

let lastState = '';

function size(bytes) {
  if (!(bytes >= 0)) return '—';
  return bytes < 1024 * 1024 ? `${num(bytes / 1024, 1)} KB` : `${num(bytes / 1024 / 1024, 2)} MB`;
}

function stateLine(r) {
  const what = `${r.file || ''}, ${r.rows} rows, ${size(r.bytes)}`;
  switch (r.state) {
    case 'recording': return `Recording at ${r.rate_hz} Hz: ${what}.`;
    case 'stopped': return `Stopped: ${what} (${r.reason}).`;
    case 'failed': return `Failed: ${r.reason}.`;
    default: return 'Not recording.';
  }
}

export function renderRecording() {
  const r = (S.state && S.state.recording) || { state: 'idle' };
  setText('rec-state', stateLine(r));
  $('rec-state').className = r.state === 'failed' ? 'cal-line error' : 'cal-line';
  $('rec-start').disabled = r.state === 'recording';
  $('rec-stop').disabled = r.state !== 'recording';
  if (lastState === 'recording' && r.state !== 'recording') setTimeout(loadRecordings, 500); // the last batch's write
  lastState = r.state;
}

export async function loadRecordings() {
  const r = await request('GET', '/api/recordings');
  if (!r.ok) { say('rec-msg', `The recordings could not be listed: ${why(r)}.`, true); return; }
  const list = r.data.recordings || [];
  $('rec-list-rows').replaceChildren(...(list.length ? list.map((f) => h('tr', {},
    h('td', {}, h('a', { href: `/api/recordings/${encodeURIComponent(f.name)}`, download: f.name, text: f.name })),
    h('td', { class: 'num', text: String(f.rows) }), h('td', { class: 'num', text: size(f.bytes) })))
    : [h('tr', {}, h('td', { colspan: 3, class: 'dimtxt', text: 'No recordings yet.' }))]));
}

async function start(ev) {
  ev.preventDefault();
  const form = $('rec-form');
  const body = {};
  const bad = readNumbers(body, [['rec-rate', 'rate_hz'], ['rec-max', 'max_mb']]);
  markBad(form, bad);
  if (bad.length) { say('rec-msg', 'Not started: the rate and the size are numbers.', true); return; }
  const r = await act('start recording', 'POST', '/api/recording', body, { btn: $('rec-start'), form, quiet: true });
  say('rec-msg', r.ok ? `Recording to ${r.data.recording.file}.` : `Not started: ${why(r)}.`, !r.ok);
  if (r.ok) loadRecordings();
}

async function stop() {
  const r = await act('stop recording', 'POST', '/api/recording/stop', undefined, { btn: $('rec-stop'), quiet: true });
  say('rec-msg', r.ok ? `Stopped: ${r.data.recording.rows} rows in ${r.data.recording.file}.` : `Not stopped: ${why(r)}.`, !r.ok);
  if (r.ok) setTimeout(loadRecordings, 500);
}

export function wireRecording() {
  $('rec-form').addEventListener('submit', start);
  $('rec-stop').addEventListener('click', stop);
}
