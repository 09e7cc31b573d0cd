// The Login and tokens page (#account, reached from Setup and Settings): the operator password
// changed with the current one (POST /api/password: 401 for a wrong current password, 400 for a
// new one under 8 characters), and the API tokens by label (GET /api/tokens, POST /api/tokens
// {label} gives the token once, DELETE /api/tokens/LABEL revokes it).

import { $, h, setText } from './dom.js';
import { toast } from './toast.js';
import { request } from './api.js';
import { act } from './actions.js';
import { ask } from './confirm.js';

const MIN_PASSWORD = 8;
let wired = false;

export async function openAccount() {
  if (!wired) { wired = true; wire(); }
  await loadTokens();
}

function wire() {
  $('pw-form').addEventListener('submit', changePassword);
  $('token-form').addEventListener('submit', createToken);
  $('token-copy').addEventListener('click', copyToken);
  $('token-done').addEventListener('click', () => { $('token-new').hidden = true; setText('token-value', ''); });
}

async function changePassword(ev) {
  ev.preventDefault();
  const f = $('pw-form');
  const old = $('pw-old').value; const pw = $('pw-new').value; const again = $('pw-again').value;
  const err = $('pw-error');
  f.querySelectorAll('.bad').forEach((e) => e.classList.remove('bad'));
  const refuse = (id, msg) => { $(id).classList.add('bad'); $(id).focus(); setText(err, msg); };
  if (!old) return refuse('pw-old', 'Enter the current password.');
  if (pw.length < MIN_PASSWORD) return refuse('pw-new', `The new password is too short: at least ${MIN_PASSWORD} characters.`);
  if (pw !== again) return refuse('pw-again', 'The two new passwords differ.');
  const r = await act('change the password', 'POST', '/api/password', { old_password: old, new_password: pw },
    { btn: $('pw-save'), form: f, quiet: true, passwordCheck: true });
  if (!r.ok) {
    if (r.status === 401 && !/login required/i.test(r.data.error || '')) return refuse('pw-old', 'The current password is wrong: nothing changed.');
    if (r.status === 401) return setText(err, 'Not changed: log in first.');
    if (r.status === 404) return setText(err, 'This controller cannot change its password from the console yet (it answered 404): use azeltrack web password.');
    const field = r.data.field === 'old_password' ? 'pw-old' : r.data.field === 'new_password' ? 'pw-new' : null;
    const msg = `Not changed: ${r.data.error || `HTTP ${r.status}`}`;
    return field ? refuse(field, msg) : setText(err, msg);
  }
  f.reset();
  setText(err, '');
  toast('Password changed. Other sessions logged in with the old one have ended.', 'ok', null, 6000);
}

function when(iso) { return iso ? `${String(iso).slice(0, 16).replace('T', ' ')} UTC` : 'not known'; }

async function loadTokens() {
  const r = await request('GET', '/api/tokens');
  const list = $('token-list');
  const note = (t) => list.replaceChildren(h('tr', {}, h('td', { colspan: 3, class: 'dimtxt', text: t })));
  $('token-form').hidden = r.status === 404;
  if (r.status === 404) return note('This controller does not manage tokens from the console yet (it answered 404): azeltrack web token makes one.');
  if (r.status === 401) return note('Log in to see the tokens.');
  if (!r.ok) return note(`The tokens could not be read: ${r.data.error || `HTTP ${r.status}`}`);
  const tokens = Array.isArray(r.data.tokens) ? r.data.tokens : [];
  if (!tokens.length) return note('No API token: scripts and the kiosk panel need one.');
  list.replaceChildren(...tokens.map((t) => {
    // The file's single [web] api_token_sha256 is no record: it goes with the file, not from here.
    if (t.legacy) return h('tr', {}, h('td', { class: 'tlabel', text: String(t.label) }), h('td', { text: when(t.created_utc) }), h('td', { class: 'dimtxt', text: 'in the file' }));
    const btn = h('button', { type: 'button', class: 'btn small', text: 'Revoke…', 'data-label': t.label, 'aria-label': `Revoke the token ${t.label}` });
    btn.addEventListener('click', () => revoke(t.label, btn));
    return h('tr', {}, h('td', { class: 'tlabel', text: String(t.label) }), h('td', { text: when(t.created_utc) }), h('td', {}, btn));
  }));
}

async function revoke(label, btn) {
  const yes = await ask({ title: `Revoke the token “${label}”?`,
    text: 'Whatever uses it (a script, the kiosk panel) can no longer act from now on. This cannot be undone: a new token must be made and given to it.',
    ok: 'Revoke', danger: true });
  if (!yes) return;
  const r = await act(`revoke the token ${label}`, 'DELETE', `/api/tokens/${encodeURIComponent(label)}`, undefined, { btn, errEl: $('token-error') });
  if (r.ok) { toast(`Token “${label}” revoked.`); await loadTokens(); }
}

async function createToken(ev) {
  ev.preventDefault();
  const label = $('token-label').value.trim();
  if (!label) { $('token-label').classList.add('bad'); setText('token-error', 'Give the token a label: what will use it.'); return; }
  const r = await act('make a token', 'POST', '/api/tokens', { label }, { btn: $('token-create'), errEl: $('token-error'), form: $('token-form') });
  if (!r.ok) return;
  $('token-label').value = '';
  $('token-label').classList.remove('bad');
  setText('token-new-label', String(r.data.label || label));
  setText('token-value', String(r.data.token || ''));
  $('token-new').hidden = false;
  $('token-copy').focus();
  await loadTokens();
}

async function copyToken() {
  const v = $('token-value').textContent;
  let ok = false;
  try { await navigator.clipboard.writeText(v); ok = true; } catch (e) { /* not a secure context */ }
  if (!ok) { // select it for Ctrl-C
    const range = document.createRange();
    range.selectNodeContents($('token-value'));
    const sel = window.getSelection(); sel.removeAllRanges(); sel.addRange(range);
  }
  toast(ok ? 'Token copied.' : 'Selected: press Ctrl-C (or ⌘-C) to copy it.');
}
