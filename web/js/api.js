// The JSON API (docs/web-api.md): requests, and actions that handle login and refusals.

import { S } from './state.js';
import { $, setText } from './dom.js';
import { toast } from './toast.js';
import { refreshSession, setLoggedIn, showLogin } from './session.js';
import { field } from './setup.js';

export async function request(method, path, body) {
  const headers = { Accept: 'application/json' };
  if (body !== undefined) headers['Content-Type'] = 'application/json';
  if (S.csrf && method !== 'GET') headers['X-CSRF-Token'] = S.csrf;
  let r;
  try {
    r = await fetch(path, { method, headers, credentials: 'same-origin', cache: 'no-store',
      body: body === undefined ? undefined : JSON.stringify(body) });
  } catch (e) {
    return { ok: false, status: 0, data: { error: 'no answer from the controller' } };
  }
  let data = {};
  try { data = await r.json(); } catch (e) { /* not JSON */ }
  if (!data || typeof data !== 'object') data = {};
  return { ok: r.ok, status: r.status, data, headers: r.headers };
}

// An action (POST/PUT). 401 opens the login form; a 403 (stale CSRF token) re-reads the session
// once and retries. errEl: the form's .error element that shows a refusal instead of a toast.
export async function act(label, method, path, body, opts = {}) {
  const btn = opts.btn;
  if (btn) btn.classList.add('busy');
  let r = await request(method, path, body);
  if (r.status === 403 && /csrf/i.test(r.data.error || '')) {
    await refreshSession(); // the session may have been renewed elsewhere: take its token, retry once
    if (S.csrf) r = await request(method, path, body);
    else r = { ok: false, status: 401, data: { error: 'login required (the session has ended)' } };
  }
  if (btn) btn.classList.remove('busy');
  if (r.status === 401) {
    setLoggedIn(false, null);
    showLogin(`Log in to ${label.toLowerCase()} — the controller answered: “${r.data.error || 'login required'}”.`);
    if (opts.errEl) setText(opts.errEl, 'Not saved: log in first.');
    return r;
  }
  if (!r.ok) {
    const msg = r.data.error || (r.status ? `HTTP ${r.status}` : 'no answer from the controller');
    if (opts.errEl) { setText(opts.errEl, msg); markField(opts.form, r.data.field); } else toast(`${label}: ${msg}`, 'err');
    return r;
  }
  if (opts.errEl) setText(opts.errEl, '');
  if (opts.form) opts.form.querySelectorAll('.bad').forEach((e) => e.classList.remove('bad'));
  return r;
}
function markField(form, field) {
  if (!form) return;
  form.querySelectorAll('.bad').forEach((e) => e.classList.remove('bad'));
  const map = { grid: 'grid', lat_deg: 'lat', lon_deg: 'lon', alt_m: 'alt', az_offset_deg: 'az-offset',
    el_offset_deg: 'el-offset', window_deg: 'window', ramp_s: 'ramp', tracking_speed: 'tracking-speed',
    ra_deg: 'ra', dec_deg: 'dec', band: 'band' };
  let el = field && map[field] ? $(map[field]) : null;
  if (form.id === 'man-form') el = field === 'el_deg' ? $('man-el') : field === 'az_deg' ? $('man-az') : null;
  if (form.classList.contains('park-row') && field) el = form.querySelector(`[data-f="${field}"]`);
  if (el && form.contains(el)) el.classList.add('bad');
}

export async function loadJSON(path) {
  const r = await request('GET', path);
  return r.ok ? r.data : null;
}
