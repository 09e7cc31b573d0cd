// The login session: read-only until logged in; the CSRF token for actions.

import { S } from './state.js';
import { $, setText } from './dom.js';
import { upper1 } from './format.js';
import { toast } from './toast.js';
import { loadJSON, request } from './api.js';

export function setLoggedIn(v, csrf) {
  S.loggedIn = v; S.csrf = v ? csrf : null;
  const st = $('login-state');
  setText(st, v ? (S.token ? 'Kiosk' : 'Logged in') : 'Read-only');
  st.className = `pill ${v ? 'in' : 'out'}`;
  st.title = v ? 'Logged in: the console can control the antenna' : 'Read-only: log in to control the antenna';
  const out = $('logout-btn');
  if (out) out.hidden = !v; // the panel has none: its login pill logs out
  $('login-form').hidden = v || S.loginDismissed;
  if (v) setText('login-error', '');
}
export function showLogin(msg) {
  S.loginDismissed = false; localStorage.removeItem('azt.loginbar');
  $('login-form').hidden = false;
  setText('login-error', msg || '');
  window.scrollTo({ top: 0 });
  $('password').focus({ preventScroll: true });
}
/// The kiosk's token (docs/panel.md "No keyboard"): the panel's unit opens the page with
/// #token=… in its address, which is never sent to the controller; the page keeps it in its own
/// storage (the panel user's, 0700) and takes it out of the address at once.
export function adoptToken() {
  const m = /^#token=([0-9a-f]{64})$/.exec(window.location.hash);
  if (m) {
    localStorage.setItem('azt.token', m[1]);
    window.history.replaceState(null, '', window.location.pathname + window.location.search);
  }
  S.token = localStorage.getItem('azt.token');
}
export function forgetToken() {
  if (!S.token) return;
  S.token = null;
  localStorage.removeItem('azt.token');
}
export async function refreshSession() {
  const j = await loadJSON('/api/session');
  if (!j) return;
  S.passwordSet = j.password_set !== false;
  setLoggedIn(!!j.logged_in && (!!j.csrf || !!S.token), j.csrf || null);
  if (!S.passwordSet && !S.loggedIn) setText('login-error', 'No operator password is set on the controller ([web] password_hash): the console is read-only.');
}
export async function login(ev) {
  ev.preventDefault();
  const pw = $('password').value;
  if (!pw) { setText('login-error', 'Enter the operator password.'); $('password').focus(); return; }
  $('login-btn').classList.add('busy');
  const r = await request('POST', '/api/login', { password: pw });
  $('login-btn').classList.remove('busy');
  if (r.ok && r.data.csrf) {
    $('password').value = '';
    setLoggedIn(true, r.data.csrf);
    toast('Logged in: the console can control the antenna.');
    return;
  }
  let msg;
  if (r.status === 401) msg = `${upper1(r.data.error || 'wrong password')}.`;
  else if (r.status === 429) {
    const ra = r.headers && r.headers.get('Retry-After');
    const e = upper1(r.data.error || 'too many failed logins');
    msg = `${e}${ra && !/\d\s*s\b/.test(e) ? ` (wait ${ra} s)` : ''}.`;
  } else msg = `Login failed: ${r.data.error || (r.status ? `HTTP ${r.status}` : 'no answer from the controller')}.`;
  setText('login-error', msg.replace(/\.\.$/, '.'));
  $('password').select();
}
export async function logout() {
  await request('POST', '/api/logout');
  setLoggedIn(false, null);
  toast('Logged out: read-only.');
}
