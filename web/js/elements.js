// Where the satellites' element sets come from (the targets screen): each source with its last
// success, its last failure and why, and how many sets it gives (/api/state satellites.sources);
// fetching them now; uploading an element file (POST /api/satellites/elements, checked as a
// download is: docs/satellites.md).

import { S } from './state.js';
import { $, h, setText } from './dom.js';
import { toast } from './toast.js';
import { act } from './actions.js';
import { loadTargets } from './targets.js';

const MAX_BYTES = 16 * 1024 * 1024; // WebApi::kMaxElementUploadBytes
const hm = (iso) => (iso ? iso.replace('T', ' ').replace(/:\d\d(\.\d+)?Z$/, ' UTC') : '—');

function sourceRow(s) {
  const failed = !!s.last_error;
  return h('li', { class: failed ? 'src-failed' : '' },
    h('span', { class: 'tn', text: s.kind === 'download' ? s.url : s.kind === 'file' ? `file: ${s.url}` : 'uploaded in the console' }),
    h('span', { class: 'tp', text: `${s.count} ${s.count === 1 ? 'set' : 'sets'} · last good ${hm(s.last_ok)}` }),
    failed ? h('span', { class: 'error', text: `failed ${hm(s.last_error_at)}: ${s.last_error} (the previous sets stay in use)` }) : '');
}

export function renderElementSources() {
  const sat = (S.state && S.state.satellites) || null;
  const box = $('sat-sources');
  if (!box || !sat) return;
  const key = JSON.stringify(sat);
  if (box.dataset.key === key) return;
  box.dataset.key = key;
  const rows = (sat.sources || []).map(sourceRow);
  box.replaceChildren(h('p', { class: 'hint', text: `${sat.count} satellites in the catalogue${sat.fetching ? ' · fetching…' : ''}` }),
    rows.length ? h('ul', { class: 'sources' }, ...rows) : h('p', { class: 'dimtxt', text: 'No element sources ([satellites] sources, file).' }));
}

async function upload(ev) {
  ev.preventDefault();
  const input = $('elements-file');
  const file = input.files && input.files[0];
  const err = $('elements-error');
  if (!file) { setText(err, 'Choose an element file first.'); return; }
  if (file.size > MAX_BYTES) { setText(err, `${file.name} is ${file.size} bytes: at most 16 MiB.`); return; }
  const text = await file.text();
  const r = await act('upload element sets', 'POST', '/api/satellites/elements', text, { btn: $('elements-upload'), errEl: err, type: 'text/plain' });
  if (!r.ok) {
    if (r.status !== 401) setText(err, `Not used: ${r.data.error || `HTTP ${r.status}`}`);
    return;
  }
  input.value = '';
  $('elements-upload').disabled = true;
  setText(err, '');
  toast(`${file.name}: ${r.data.count} sets, ${r.data.newer} newer than those in use`, 'ok', null, 8000);
  setTimeout(loadTargets, 1000); // the merged catalogue is published a moment later
}

async function refresh() {
  const r = await act('fetch the element sources', 'POST', '/api/satellites/refresh', {}, { btn: $('elements-refresh') });
  if (r.ok) toast('Fetching the element sources', 'ok');
}

export function wireElements() {
  $('elements-file').addEventListener('change', () => {
    $('elements-upload').disabled = !($('elements-file').files || []).length;
    setText('elements-error', '');
  });
  $('elements-upload-form').addEventListener('submit', upload);
  $('elements-refresh').addEventListener('click', refresh);
}
