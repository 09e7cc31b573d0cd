// The whole settings file: "Download settings" is GET /api/config/file (TOML, as saved, with its
// comments); "Import" sends a file's text with PUT /api/config/file, checked whole by the
// controller before one save (a refusal saves nothing and names the line). Reading the file
// needs a login, as acting does.

import { S } from './state.js';
import { $, h, setText } from './dom.js';
import { toast } from './toast.js';
import { request } from './api.js';
import { act } from './actions.js';
import { showLogin } from './session.js';
import { ask } from './confirm.js';
import { savedWords } from './settings_forms.js';

const MAX_BYTES = 64 * 1024; // the controller's limit for a request's body

let afterImport = async () => {};

// The file is read with the session's CSRF token, as an action is (it holds who may act), so a
// plain link cannot fetch it: the page fetches it and hands it to the browser as a download.
async function download(ev) {
  ev.preventDefault();
  const headers = { Accept: 'text/plain' };
  if (S.token) headers.Authorization = `Bearer ${S.token}`;
  else if (S.csrf) headers['X-CSRF-Token'] = S.csrf;
  let r;
  try {
    r = await fetch('/api/config/file', { headers, credentials: 'same-origin', cache: 'no-store' });
  } catch (e) {
    setText('cfg-download-note', 'No answer from the controller.');
    return;
  }
  if (r.status === 401) { setText('cfg-download-note', 'Log in to download the file.'); showLogin('Log in to download the settings file.'); return; }
  if (r.status === 404) { setText('cfg-download-note', 'This controller does not give its file from the console yet (it answered 404).'); return; }
  if (!r.ok) { setText('cfg-download-note', `Not downloaded: HTTP ${r.status}.`); return; }
  setText('cfg-download-note', '');
  const url = URL.createObjectURL(await r.blob());
  const a = h('a', { href: url, download: 'azeltrack.toml', hidden: true });
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10000);
}

async function importFile(ev) {
  ev.preventDefault();
  const input = $('cfg-import-file');
  const file = input.files && input.files[0];
  const err = $('cfg-import-error');
  if (!file) { setText(err, 'Choose a settings file first.'); return; }
  if (file.size > MAX_BYTES) { setText(err, `${file.name} is ${file.size} bytes: a settings file is at most 64 KiB.`); return; }
  const yes = await ask({
    title: `Import ${file.name}?`,
    text: 'Its settings replace every setting of the controller. It is checked whole first: nothing is saved if it has an error. Settings applied at the next start wait for a restart.',
    ok: 'Import',
  });
  if (!yes) return;
  const text = await file.text();
  const r = await act('import the settings', 'PUT', '/api/config/file', text, { btn: $('cfg-import'), errEl: err, type: 'application/toml' });
  if (!r.ok) {
    if (r.status === 404) setText(err, 'This controller cannot import a file from the console yet (it answered 404).');
    else if (r.status !== 401) setText(err, `Not imported, nothing saved: ${r.data.error || `HTTP ${r.status}`}`);
    return;
  }
  input.value = '';
  $('cfg-import').disabled = true;
  toast(savedWords(file.name, r.data, 'Imported'), 'ok', null, 8000);
  await afterImport();
}

export function wireFile(reload) {
  afterImport = reload;
  $('cfg-download').addEventListener('click', download);
  $('cfg-import-file').addEventListener('change', () => {
    $('cfg-import').disabled = !($('cfg-import-file').files || []).length;
    setText('cfg-import-error', '');
  });
  $('cfg-import-form').addEventListener('submit', importFile);
}
