// Actions (POST/PUT): a 401 opens the login form, a stale CSRF token is renewed once, and a
// refusal is shown beside the form's field or as a toast.

import { S } from './state.js';
import { $, setText } from './dom.js';
import { toast } from './toast.js';
import { request } from './api.js';
import { forgetToken, refreshSession, setLoggedIn, showLogin } from './session.js';

// An action (POST/PUT). 401 opens the login form; a 403 (stale CSRF token) re-reads the session
// once and retries. errEl: the form's .error element that shows a refusal instead of a toast;
// quiet: neither (the caller shows the refusal itself); form: its field named by a 400 is marked;
// type: the body's Content-Type when it is sent as it is (a file's text); passwordCheck: a 401
// that is not "login required" is a wrong password typed in the form, not a session lost.
export async function act(label, method, path, body, opts = {}) {
  const btn = opts.btn;
  if (btn) btn.classList.add('busy');
  let r = await request(method, path, body, opts.type);
  if (r.status === 403 && /csrf/i.test(r.data.error || '')) {
    await refreshSession(); // the session may have been renewed elsewhere: take its token, retry once
    if (S.csrf) r = await request(method, path, body, opts.type);
    else r = { ok: false, status: 401, data: { error: 'login required (the session has ended)' } };
  }
  if (btn) btn.classList.remove('busy');
  if (r.status === 401 && !(opts.passwordCheck && !/login required/i.test(r.data.error || ''))) {
    const hadToken = !!S.token;
    forgetToken(); // revoked in the console: from now on the password, as anywhere else
    setLoggedIn(false, null);
    // Short first: the panel shows one line of it.
    showLogin(hadToken ? `This screen's token was revoked: log in to ${label.toLowerCase()}.`
      : `Log in to ${label.toLowerCase()} — the controller answered: “${r.data.error || 'login required'}”.`);
    if (opts.errEl) setText(opts.errEl, 'Not saved: log in first.');
    return r;
  }
  if (!r.ok) {
    const msg = r.data.error || (r.status ? `HTTP ${r.status}` : 'no answer from the controller');
    if (opts.errEl) setText(opts.errEl, msg); else if (!opts.quiet) toast(`${label}: ${msg}`, 'err');
    markField(opts.form, r.data.field);
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
    ra_deg: 'ra', dec_deg: 'dec', band: 'band', servers: 'ntp-servers', source: 'scan-source',
    kind: 'scan-kind', beamwidth_deg: 'scan-beam', points_per_line: 'scan-points',
    half_span_beams: 'scan-span', reference_beams: 'scan-ref', settle_s: 'scan-settle', dwell_s: 'scan-dwell' };
  let el = field && map[field] ? $(map[field]) : null;
  // Forms built from the schema name each control by its key (data-field).
  const named = field ? [...form.querySelectorAll('[data-field]')].find((e) => e.dataset.field === field) : null;
  if (named) el = named;
  if (form.id === 'man-form') el = field === 'el_deg' ? $('man-el') : field === 'az_deg' ? $('man-az') : null;
  if (form.classList.contains('park-row') && field) el = form.querySelector(`[data-f="${field}"]`);
  if (el && form.contains(el)) {
    el.classList.add('bad');
    const more = el.closest('details');
    if (more) more.open = true;
  }
}
