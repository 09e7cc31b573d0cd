// Acting needs a login (docs/web-api.md "Acting"); reading does not. The panel shows the keyboard
// only when the controller refuses an action for want of one (act() calls session.js showLogin on
// a 401), and does that action once the password is accepted: one tap, then the password.

import { S } from './state.js';
import { $ } from './dom.js';
import { toast } from './toast.js';
import { login, logout, showLogin } from './session.js';
import { buildKeyboard } from './panel_keys.js';

let pending = null; // the action the login is for
let keyboard = null;

// Runs fn (an action returning act()'s answer); refused with 401, it is kept for after the login.
export async function perform(fn) {
  const r = await fn();
  if (r.status === 401) pending = fn; else if (pending === fn) pending = null;
  return r;
}

function hideKeyboard() {
  // The keyboard is for an action: a session lost later (a daemon restart) must not open it
  // unasked, as setLoggedIn(false) would for the console's login bar.
  S.loginDismissed = true;
  $('login-form').hidden = true;
  $('password').value = '';
  if (keyboard) keyboard.reset();
}
export function cancelLogin() { pending = null; hideKeyboard(); }

async function submit(ev) {
  await login(ev);
  if (!S.loggedIn) { $('password').value = ''; return; }
  hideKeyboard();
  const fn = pending;
  pending = null;
  if (fn) await perform(fn);
}

function type(ch) { const p = $('password'); if (p.value.length < 256) p.value += ch; }
function back() { const p = $('password'); p.value = p.value.slice(0, -1); }

// A keyboard plugged into the kiosk types too.
function physicalKeys(ev) {
  if ($('login-form').hidden || ev.ctrlKey || ev.metaKey || ev.altKey) return;
  if (ev.key === 'Enter') { ev.preventDefault(); $('login-form').requestSubmit($('login-btn')); } else if (ev.key === 'Escape') cancelLogin();
  else if (ev.key === 'Backspace') { ev.preventDefault(); back(); } else if (ev.key.length === 1) { ev.preventDefault(); type(ev.key); }
}

export function wireLogin() {
  S.loginDismissed = true; // closed until an action asks for it
  const ok = document.createElement('button');
  Object.assign(ok, { type: 'submit', id: 'login-btn', textContent: 'OK' });
  keyboard = buildKeyboard($('keys'), ok, { type, back });
  $('login-form').addEventListener('submit', submit);
  $('login-cancel').addEventListener('click', cancelLogin);
  $('pw-show').addEventListener('click', () => {
    const p = $('password'); const shown = p.type === 'text';
    p.type = shown ? 'password' : 'text';
    $('pw-show').textContent = shown ? 'Show' : 'Hide';
  });
  $('login-state').addEventListener('click', () => {
    // The kiosk's token is the screen's own: it is revoked in the console, not logged out here.
    if (S.token) toast('This screen acts with its kiosk token (the console\'s Settings can revoke it).');
    else if (S.loggedIn) logout(); else showLogin('Enter the operator password.');
  });
  document.addEventListener('keydown', physicalKeys);
}
