// The Software page (docs/web-api.md "software"; the AnTrack-Pro manual's "Software Updating"):
// the version running, a new Debian package sent to the controller (POST /api/software/update)
// and how the root update helper gets on with it, read from GET /api/software every second while
// an update is under way and every 10 s otherwise, only while the page is shown. The package's
// postinst restarts the daemon: a controller that does not answer then is restarting, not broken.

import { S } from './state.js';
import { $, h, setText } from './dom.js';
import { ago, isNum } from './format.js';
import { request } from './api.js';
import { refreshSession, setLoggedIn, showLogin } from './session.js';

const LIMIT = 64 * 1024 * 1024; // the daemon's limit: a larger package would be refused (413) after it was all sent
const WATCH = 'azt.update';     // the package this tab waits for, so that a reload still shows the outcome
const RESTARTING = 'Restarting…';
const STALE_S = 30 * 60;        // a report this old of work going on was abandoned (the daemon's rule too)

let sw = null;         // the controller's last answer
let problem = '';      // why the last reading failed ('' when it did not)
let sending = null;    // {percent, name, bytes} while the package goes up
let cur = null;        // the progress shown: progressOf()'s answer
let lastPercent = 0;   // kept while the controller restarts
let timer = 0;
let epoch = 0;         // bumped when a package has been sent: readings asked for before then are old
let watched = sessionStorage.getItem(WATCH) || '';
let ended = '';        // the package whose outcome was announced: its result stays on the bar
let wired = false;      // the page's controls are wired when it is first opened

function watch(sha) {
  watched = sha || '';
  if (watched) sessionStorage.setItem(WATCH, watched); else sessionStorage.removeItem(WATCH);
}

const pct = (v) => (isNum(v) ? Math.max(0, Math.min(100, Math.round(v))) : null);
const stop = (s) => String(s || '').trim().replace(/\.+$/, '');
function size(n) {
  if (!isNum(n)) return '—';
  if (n < 1024) return `${n} bytes`;
  if (n < 1048576) return `${(n / 1024).toFixed(1)} KiB`;
  return `${(n / 1048576).toFixed(1)} MiB`;
}
function when(t) {
  if (!isNum(t)) return '—';
  const iso = new Date(t * 1000).toISOString().slice(0, 16).replace('T', ' ');
  return `${iso} UTC (${ago(Math.max(0, Date.now() / 1000 - t))} ago)`;
}
const versions = (hp) => (hp.from || hp.to ? `${hp.from || '?'} → ${hp.to || '?'}` : '—');
const working = (hp) => hp.phase === 'checking' || hp.phase === 'installing';
const stale = (hp) => isNum(hp.at_unix_s) && Date.now() / 1000 - hp.at_unix_s > STALE_S;

// What the page says about an update, from the controller's answer `s` (null when it did not
// answer), the package this tab waits for (`watching`), the one whose outcome it has announced
// (`ended`) and the upload going on: {stage, percent, tone, detail, sha, busy, outcome}, or null
// when there is nothing to show. One bar: the upload's percent, then the helper's.
export function progressOf(s, watching, upload, ended = '') {
  if (upload) return { stage: 'Sending', percent: upload.percent, busy: true, detail: `${upload.name}, ${size(upload.bytes)}` };
  if (!s) return watching ? { stage: RESTARTING, percent: null, busy: true, sha: watching,
    detail: 'The controller is restarting with the new version; this page carries on when it answers again.' } : null;
  const up = s.upload; const hp = s.helper;
  if (up && (!hp || hp.sha256 !== up.sha256)) {
    return { stage: 'Waiting for the update helper', percent: 100, busy: true, sha: up.sha256,
      detail: `The package (${size(up.bytes)}) is stored on the controller; the update helper takes it from there.` };
  }
  if (!hp) return null;
  const base = { sha: hp.sha256, detail: hp.message ? String(hp.message) : '' };
  if (working(hp)) {
    if (stale(hp)) return null; // a power cut in the middle: "Last update" says how old it is
    return { ...base, stage: hp.phase === 'checking' ? 'Checking' : 'Installing', percent: pct(hp.percent) ?? 0, busy: true };
  }
  if (!hp.sha256 || (hp.sha256 !== watching && hp.sha256 !== ended)) return null; // an earlier update: "Last update" shows it
  if (hp.phase === 'installed') {
    if (s.version !== hp.to) return { ...base, stage: RESTARTING, percent: 100, busy: true, detail: `Installed; waiting for version ${hp.to} to start.` };
    return { ...base, stage: 'Installed', percent: 100, tone: 'ok', outcome: 'installed', detail: `${versions(hp)}. The configuration parameters are unchanged.` };
  }
  if (hp.phase === 'refused') return { ...base, stage: 'Refused', percent: pct(hp.percent) ?? 0, tone: 'bad', outcome: 'refused' };
  if (hp.phase === 'failed') return { ...base, stage: 'Failed', percent: pct(hp.percent) ?? 0, tone: 'bad', outcome: 'failed' };
  return { ...base, stage: String(hp.phase || '—'), percent: pct(hp.percent) ?? 0 };
}

// ------------------------------------------------------------------ reading the controller

async function load() {
  const asked = epoch;
  const r = await request('GET', '/api/software');
  if (asked !== epoch) return; // asked before the upload ended: it would hide the upload
  if (r.ok && typeof r.data.version === 'string') { sw = r.data; problem = ''; } else {
    sw = null;
    problem = r.status === 404 ? 'This controller does not report its software (no /api/software).'
      : `No answer from the controller${r.status ? ` (HTTP ${r.status})` : ''}: the values shown are the last it gave.`;
  }
  render();
}

const busy = () => !!sending || !!(cur && cur.busy);
function schedule() {
  clearTimeout(timer);
  if (S.screen === 'software') timer = setTimeout(poll, busy() ? 1000 : 10000);
}
async function poll() {
  if (S.screen !== 'software') return;
  if (!document.hidden) await load();
  schedule();
}
export function openSoftware() { if (!wired) wire(); clearTimeout(timer); poll(); }

function summary() {
  if (sw) setText('setup-software', [`version ${sw.version}`, sw.architecture].filter(Boolean).join(' · '));
}

// ------------------------------------------------------------------ the page

function render() {
  cur = progressOf(problem ? null : sw, watched, sending, ended);
  if (cur && cur.busy && cur.sha && !watched) watch(cur.sha); // another console's update: see it through too
  if (!cur && !problem && watched) watch('');                 // restarted without it: nothing to wait for
  summary();
  renderVersion();
  renderForm();
  renderProgress();
  renderLast();
  if (cur && cur.outcome && cur.sha === watched) { ended = watched; watch(''); popup(cur); }
}

function renderVersion() {
  setText('sw-version', sw ? String(sw.version) : '—');
  setText('sw-arch', sw && sw.architecture ? String(sw.architecture) : sw ? 'not known' : '—');
  const p = $('sw-problem');
  const says = cur && cur.stage === RESTARTING && problem ? '' : problem; // "Restarting…" says it already
  p.hidden = !says;
  setText(p, says);
}

const setDisabled = (id, v) => { if ($(id).disabled !== v) $(id).disabled = v; };
// The form follows the login, which can change anywhere (the header, a 401 elsewhere): main.js
// calls this with every state message while the page is shown.
export function renderForm() {
  $('sw-no-updates').hidden = !sw || sw.updates !== false;
  if (sw && sw.updates === false) setText('sw-no-reason', stop(sw.updates_reason) || 'no reason given');
  $('sw-form').hidden = !sw || sw.updates !== true;
  const file = $('sw-file').files[0];
  setDisabled('sw-file', !S.loggedIn || busy());
  setDisabled('sw-update', !S.loggedIn || busy() || !file);
  $('sw-login').hidden = S.loggedIn;
  setText('sw-hint', !S.loggedIn ? 'Log in to update the software (reading works without).'
    : busy() ? 'An update is under way.'
      : file ? `${file.name}, ${size(file.size)}: Update sends it to the controller.`
        : 'Choose the package file, then Update.');
}

function renderProgress() {
  $('sw-progress').hidden = !cur;
  if (!cur) { lastPercent = 0; setText('sw-stage', ''); return; } // the next update starts afresh
  if (cur.percent != null) lastPercent = cur.percent;
  setText('sw-stage', cur.stage);
  const tone = cur.tone || (cur.busy ? 'busy' : '');
  if ($('sw-stage').className !== `swstage ${tone}`) $('sw-stage').className = `swstage ${tone}`;
  if ($('sw-bar').className !== `swbar ${tone}`) $('sw-bar').className = `swbar ${tone}`;
  setText('sw-percent', `Percent complete: ${lastPercent}%`);
  $('sw-bar-fill').style.width = `${lastPercent}%`;
  $('sw-bar').setAttribute('aria-valuenow', String(lastPercent));
  setText('sw-detail', cur.detail || '');
  $('sw-sha-row').hidden = !cur.sha;
  setText('sw-sha', cur.sha || '');
}

const PHASES = { checking: 'checking the package', refused: 'refused', installing: 'installing',
  installed: 'installed', failed: 'failed' };
function row(label, value, cls) {
  return h('div', {}, h('span', { class: 'lbl', text: label }), h('span', { class: cls || null, text: value }));
}
function renderLast() {
  const hp = sw && sw.helper;
  if (!hp) {
    const unread = sw && sw.helper_error ? `The update helper's report cannot be read: ${stop(sw.helper_error)}.` : '';
    $('sw-last').replaceChildren(h('p', { class: unread ? 'io-bad' : 'dimtxt', text: unread || (sw ? 'The update helper has not reported an update.' : '—') }));
    return;
  }
  const tone = hp.phase === 'installed' ? 'ok-txt' : hp.phase === 'refused' || hp.phase === 'failed' ? 'io-bad' : null;
  const sha = String(hp.sha256 || '');
  const word = PHASES[hp.phase] || String(hp.phase || '—');
  $('sw-last').replaceChildren(
    row('Result', working(hp) && stale(hp) ? `${word}, then no word: abandoned` : word, tone),
    row('Versions', versions(hp)),
    row('Signed by', hp.signer ? String(hp.signer) : '—'),
    row('When', when(hp.at_unix_s)),
    row('Message', hp.message ? String(hp.message) : '—'),
    h('div', { title: sha }, h('span', { class: 'lbl', text: 'Package' }), h('code', { text: sha ? `${sha.slice(0, 16)}…` : '—' })));
}

// The small window that says how an update ended. Not modal: STOP must stay within reach.
function popup(p) {
  const hp = (sw && sw.helper) || {};
  const running = sw ? `Version ${sw.version} is running.` : '';
  const says = {
    installed: ['Update installed', `The software was updated from ${hp.from || '?'} to ${hp.to || '?'}, signed by ${hp.signer || '?'}. The configuration parameters are unchanged.`],
    refused: ['Update refused', `The update helper refused the package: ${stop(hp.message) || 'no reason given'}. Nothing was installed. ${running}`],
    failed: ['Update failed', `The update failed: ${stop(hp.message) || 'no reason given'}. ${running}`],
  }[p.outcome];
  const d = $('sw-popup');
  d.className = `popup ${p.tone}`;
  d.dataset.outcome = p.outcome;
  setText('sw-popup-title', says[0]);
  setText('sw-popup-text', says[1].trim());
  if (!d.open) d.show();
}

// ------------------------------------------------------------------ sending the package

// The package as the request's body. XMLHttpRequest, not fetch: only it reports the upload's progress.
function send(file) {
  return new Promise((resolve) => {
    const x = new XMLHttpRequest();
    x.open('POST', '/api/software/update');
    x.setRequestHeader('Content-Type', 'application/vnd.debian.binary-package');
    x.setRequestHeader('Accept', 'application/json');
    if (S.csrf) x.setRequestHeader('X-CSRF-Token', S.csrf);
    x.upload.onprogress = (e) => {
      if (!e.lengthComputable || !sending) return;
      sending.percent = Math.floor((100 * e.loaded) / e.total); // 100 only once it is all sent
      render();
    };
    x.onload = () => {
      let data = {};
      try { data = JSON.parse(x.responseText); } catch (e) { /* not JSON */ }
      resolve({ ok: x.status >= 200 && x.status < 300, status: x.status, data: data && typeof data === 'object' ? data : {} });
    };
    x.onerror = x.onabort = x.ontimeout = () => resolve({ ok: false, status: 0, data: { error: 'no answer from the controller' } });
    x.send(file);
  });
}

function refusal(r) {
  const e = stop(r.data.error);
  if (r.status === 401) {
    setLoggedIn(false, null);
    showLogin(`Log in to update the software — the controller answered: “${e || 'login required'}”.`);
    return 'Not sent: log in first.';
  }
  if (r.status === 413) return 'Not sent: the package is larger than the controller takes (64 MiB).';
  if (r.status === 0) return 'Not sent: no answer from the controller.';
  return `Not sent: ${e || `HTTP ${r.status}`}.`;
}

async function update(ev) {
  ev.preventDefault();
  const file = $('sw-file').files[0];
  if (!file || !S.loggedIn || busy()) return;
  if (file.size > LIMIT) { setText('sw-error', `Not sent: ${file.name} is ${size(file.size)}; the controller takes packages up to 64 MiB.`); return; }
  setText('sw-error', '');
  sending = { percent: 0, name: file.name, bytes: file.size };
  ended = '';
  render();
  let r = await send(file);
  if (r.status === 403 && /csrf/i.test(r.data.error || '')) {
    await refreshSession(); // the session may have been renewed elsewhere: take its token, send once more
    if (S.csrf) { sending.percent = 0; r = await send(file); }
  }
  sending = null;
  epoch += 1;
  if (r.ok) {
    watch(r.data.sha256);
    // What the controller now says, without waiting for the next reading.
    if (sw) sw = { ...sw, upload: { sha256: r.data.sha256, bytes: r.data.bytes, at_unix_s: Date.now() / 1000 } };
    $('sw-file').value = '';
  } else setText('sw-error', refusal(r));
  render();
  clearTimeout(timer);
  await poll();
}

function wire() {
  wired = true;
  $('sw-form').addEventListener('submit', update);
  $('sw-file').addEventListener('change', () => { setText('sw-error', ''); renderForm(); });
  $('sw-login').addEventListener('click', () => showLogin(''));
  $('sw-popup-ok').addEventListener('click', () => $('sw-popup').close());
}
