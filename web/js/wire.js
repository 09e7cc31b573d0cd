// Every button and form of the page, wired to its action.

import { S } from './state.js';
import { $, setText } from './dom.js';
import { deg, fix, isNum, parseNum, sdeg } from './format.js';
import { toast } from './toast.js';
import { act } from './actions.js';
import { bandLabel } from './bands.js';
import { login, logout, showLogin } from './session.js';
import { go, SCREENS, show } from './navigation.js';
import { loadSky } from './sky.js';
import { radecHint, radecTarget, track } from './targets.js';
import { clean, loadConfig, showOther } from './setup.js';
import { wireStation } from './station.js';
import { wirePol } from './pol.js';

function confirmTwice(btn, label, fn) { // a second press within 4 s confirms
  if (btn.dataset.armed) { delete btn.dataset.armed; setText(btn, btn.dataset.label); fn(); return; }
  btn.dataset.label = btn.textContent; btn.dataset.armed = '1'; setText(btn, label);
  setTimeout(() => { if (btn.dataset.armed) { delete btn.dataset.armed; setText(btn, btn.dataset.label); } }, 4000);
}

export function wire() {
  for (const n of SCREENS) $(`nav-${n}`).addEventListener('click', () => go(n));
  window.addEventListener('hashchange', () => show(location.hash.slice(1)));
  $('target-pick').addEventListener('click', () => go('targets'));
  $('offset-btn').addEventListener('click', () => go('antenna'));
  wireStation(go);
  wirePol();

  // login
  $('login-form').addEventListener('submit', login);
  $('login-state').addEventListener('click', () => {
    if (S.loggedIn) toast('Logged in: actions are allowed.');
    else showLogin(S.passwordSet ? '' : $('login-error').textContent);
  });
  $('login-close').addEventListener('click', () => {
    S.loginDismissed = true; localStorage.setItem('azt.loginbar', 'hidden'); $('login-form').hidden = true;
  });
  $('logout-btn').addEventListener('click', logout);

  // theme
  $('theme-btn').addEventListener('click', () => {
    const order = ['dark', 'night', 'light'];
    const next = order[(order.indexOf(document.documentElement.dataset.theme) + 1) % order.length];
    applyTheme(next); localStorage.setItem('azt.theme', next);
    toast(`Theme: ${next}${next === 'night' ? ' (red, for dark-adapted eyes)' : ''}`);
  });

  // actions
  $('btn-stop').addEventListener('click', async () => {
    const r = await act('STOP', 'POST', '/api/stop', undefined, { btn: $('btn-stop') });
    if (r.ok) toast('STOP: motors stopped, PC programs locked out.');
    else if (r.status === 401) setText('login-error', 'STOP was refused: not logged in. Log in here, or stop the antenna at the controller.');
  });
  // The hand-over to PC programs after a console STOP: EXT with nothing to go to, so nothing moves.
  $('btn-allow-pc').addEventListener('click', async () => {
    const r = await act('Allow PC control', 'POST', '/api/control/pc', undefined, { btn: $('btn-allow-pc') });
    if (r.ok) toast('PC programs may move the antenna again; nothing moved.');
  });
  $('btn-track').addEventListener('click', () => {
    const t = S.state && S.state.target;
    const sel = S.sel || (t && t.name ? { body: { name: t.name }, label: t.name } : null);
    if (!sel) { toast('Choose a target first.', 'err'); go('targets'); return; }
    track(sel.body, sel.label, $('btn-track'));
  });
  const step = (axis, n, id) => $(id).addEventListener('click', () => act(`correct ${axis.toUpperCase()}`, 'POST', '/api/correction', { axis, steps: n }, { btn: $(id) }));
  step('az', -1, 'az-minus'); step('az', 1, 'az-plus'); step('el', -1, 'el-down'); step('el', 1, 'el-up');
  $('corr-reset').addEventListener('click', async () => {
    const c = (S.state && S.state.corrections) || {};
    const was = [c.az_user_deg || 0, c.el_user_deg || 0];
    const r = await act('reset the corrections', 'POST', '/api/correction', { reset: true }, { btn: $('corr-reset') });
    if (r.ok && (was[0] || was[1])) {
      toast(`Corrections reset (were AZ ${sdeg(was[0])}, EL ${sdeg(was[1])}).`, 'ok', { label: 'Undo', fn: async () => {
        for (const [axis, v] of [['az', was[0]], ['el', was[1]]]) {
          const n = Math.round(v * 100);
          if (n) await act('restore the corrections', 'POST', '/api/correction', { axis, steps: n });
        }
      } });
    } else if (r.ok) toast('Corrections are zero.');
  });
  $('faults-clear').addEventListener('click', async () => {
    const r = await act('clear the faults', 'POST', '/api/faults/clear', undefined, { btn: $('faults-clear') });
    if (r.ok) toast('Faults cleared. Choose a mode to move again.');
  });

  // targets
  $('tgt-sun').addEventListener('click', () => track({ name: 'sun' }, 'Sun', $('tgt-sun')));
  $('tgt-moon').addEventListener('click', () => track({ name: 'moon' }, 'Moon', $('tgt-moon')));
  $('spacecraft').addEventListener('click', (ev) => {
    const b = ev.target.closest('button[data-name]');
    if (b) track({ name: b.dataset.name }, b.dataset.name, b);
  });
  $('satellites').addEventListener('click', (ev) => {
    const b = ev.target.closest('button[data-norad]');
    if (b) track({ name: `sat:${b.dataset.norad}` }, b.firstChild.textContent, b);
  });
  $('sources').addEventListener('click', (ev) => {
    const b = ev.target.closest('button[data-name]');
    if (b) track({ name: b.dataset.name }, b.dataset.name, b);
  });
  for (let n = 1; n <= 4; n++) {
    $(`park-${n}`).addEventListener('click', async () => {
      const r = await act(`park at slot ${n}`, 'POST', '/api/target', { park: n }, { btn: $(`park-${n}`) });
      if (r.ok) toast(`PARK at slot ${n}.`);
    });
  }
  $('ra').addEventListener('input', radecHint); $('dec').addEventListener('input', radecHint);
  $('radec-form').addEventListener('submit', async (ev) => {
    ev.preventDefault();
    const f = $('radec-form');
    const t = radecTarget($('ra').value, $('dec').value);
    f.querySelectorAll('.bad').forEach((e) => e.classList.remove('bad'));
    if (!t.body) {
      if (Number.isNaN(t.ra)) $('ra').classList.add('bad');
      if (Number.isNaN(t.dec)) $('dec').classList.add('bad');
      setText('radec-error', 'RA and Dec must be numbers: degrees (83.633), or h:m:s for RA and d:m:s for Dec.');
      return;
    }
    await track(t.body, t.label, $('radec-go'), { errEl: $('radec-error'), form: f });
  });

  // manual
  $('man-form').addEventListener('submit', async (ev) => {
    ev.preventDefault();
    const f = $('man-form');
    const az = parseNum($('man-az').value); const el = parseNum($('man-el').value);
    f.querySelectorAll('.bad').forEach((e) => e.classList.remove('bad'));
    if (Number.isNaN(az) || Number.isNaN(el)) {
      if (Number.isNaN(az)) $('man-az').classList.add('bad');
      if (Number.isNaN(el)) $('man-el').classList.add('bad');
      setText('man-error', 'Azimuth and elevation must be numbers in degrees.');
      return;
    }
    const r = await act('move the antenna', 'POST', '/api/target', { az_deg: az, el_deg: el }, { btn: $('man-go'), errEl: $('man-error'), form: f });
    if (r.ok) toast(`MAN: moving to az ${deg(az)} el ${deg(el)} (not saved).`);
  });
  $('man-here').addEventListener('click', () => {
    const a = S.state && S.state.antenna;
    if (a && isNum(a.az_deg)) { $('man-az').value = fix(a.az_deg, 2); $('man-el').value = fix(a.el_deg, 2); }
  });

  // setup
  $('grid').addEventListener('input', showOther);
  $('lat').addEventListener('input', showOther); $('lon').addEventListener('input', showOther);
  $('grid-form').addEventListener('submit', async (ev) => {
    ev.preventDefault();
    const f = $('grid-form');
    const grid = $('grid').value.trim();
    const r = await act('save the locator', 'PUT', '/api/config/station', { grid }, { btn: $('grid-save'), errEl: $('grid-error'), form: f });
    if (!r.ok) { $('grid').classList.add('bad'); return; }
    clean(f); clean($('latlon-form'));
    toast('Station locator saved.');
    await loadConfig(true);
  });
  $('latlon-form').addEventListener('submit', async (ev) => {
    ev.preventDefault();
    const f = $('latlon-form');
    const lat = parseNum($('lat').value); const lon = parseNum($('lon').value); const altTxt = $('alt').value.trim();
    const alt = altTxt === '' ? undefined : parseNum(altTxt);
    if ([lat, lon].some(Number.isNaN) || (alt !== undefined && Number.isNaN(alt))) {
      setText('latlon-error', 'Latitude, longitude and height must be numbers (degrees, north and east positive; metres).');
      return;
    }
    const body = { lat_deg: lat, lon_deg: lon };
    if (alt !== undefined) body.alt_m = alt;
    const r = await act('save the position', 'PUT', '/api/config/station', body, { btn: $('latlon-save'), errEl: $('latlon-error'), form: f });
    if (!r.ok) return;
    clean(f); clean($('grid-form')); setText('grid-error', '');
    toast('Station position saved.');
    await loadConfig(true);
  });
  $('dx-form').addEventListener('submit', async (ev) => {
    ev.preventDefault();
    const dx_grid = $('dx-input').value.trim();
    const r = await act('save the DX locator', 'PUT', '/api/config/dx', { dx_grid }, { btn: $('dx-save'), errEl: $('dx-error'), form: $('dx-form') });
    if (!r.ok) return;
    toast(dx_grid ? `DX locator ${dx_grid}.` : 'DX locator cleared.');
    await loadConfig(true);
  });
  $('band-form').addEventListener('submit', (ev) => ev.preventDefault());
  $('band').addEventListener('change', async () => {
    const sel = $('band'); const band = sel.value;
    const r = await act('change the band', 'PUT', '/api/config/band', { band }, { errEl: $('band-error'), form: $('band-form') });
    if (r.ok) { toast(`Band ${bandLabel(band)}.`); await loadConfig(true); } else {
      sel.classList.add('bad');
      if (S.config) sel.value = String(S.config.band);
    }
  });

  // antenna
  $('control-form').addEventListener('submit', async (ev) => {
    ev.preventDefault();
    const f = $('control-form');
    const ctl = (S.config && S.config.control) || {};
    const body = {}; const bad = [];
    for (const [id, key] of [['window', 'window_deg'], ['ramp', 'ramp_s'], ['tracking-speed', 'tracking_speed']]) {
      const raw = $(id).value.trim();
      if (raw === '') continue;
      const v = parseNum(raw);
      if (Number.isNaN(v)) { bad.push(id); continue; }
      if (v !== ctl[key]) body[key] = v;
    }
    f.querySelectorAll('.bad').forEach((e) => e.classList.remove('bad'));
    if (bad.length) { bad.forEach((id) => $(id).classList.add('bad')); setText('control-error', 'Enter numbers.'); return; }
    if (!Object.keys(body).length) { setText('control-error', ''); toast('Nothing changed.'); return; }
    const r = await act('save the movement settings', 'PUT', '/api/config/control', body, { btn: $('control-save'), errEl: $('control-error'), form: f });
    if (r.ok) { clean(f); toast('Saved: applies at the next start of the controller.'); await loadConfig(true); }
  });
  $('offsets-form').addEventListener('submit', async (ev) => {
    ev.preventDefault();
    const f = $('offsets-form');
    const az = parseNum($('az-offset').value); const el = parseNum($('el-offset').value);
    if (Number.isNaN(az) || Number.isNaN(el)) { setText('offsets-error', 'Offsets must be numbers in degrees.'); return; }
    const r = await act('save the offsets', 'PUT', '/api/config/offsets', { az_offset_deg: az, el_offset_deg: el }, { btn: $('offsets-save'), errEl: $('offsets-error'), form: f });
    if (r.ok) { clean(f); toast('Encoder offsets saved and applied.'); await loadConfig(true); }
  });
  $('tilt-clear').addEventListener('click', () => confirmTwice($('tilt-clear'), 'Press again: all 60 → 0', async () => {
    const r = await act('clear the tilt table', 'PUT', '/api/config/tilt', { tilt_el_deg: new Array(60).fill(0) }, { errEl: $('tilt-error') });
    if (r.ok) { toast('Tilt table cleared.'); await loadConfig(true); }
  }));
  $('sky-hours').addEventListener('change', loadSky);

  // mark edited fields so live refreshes never overwrite typing
  document.querySelectorAll('#screen-setup input, #screen-antenna input').forEach((i) => {
    i.addEventListener('input', () => { i.dataset.dirty = '1'; });
  });
}

export function applyTheme(t) {
  if (!['dark', 'night', 'light'].includes(t)) t = 'dark';
  document.documentElement.dataset.theme = t;
  const meta = document.querySelector('meta[name="theme-color"]');
  if (meta) meta.setAttribute('content', t === 'light' ? '#ffffff' : t === 'night' ? '#000000' : '#0b0b0d');
}
