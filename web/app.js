// azeltrack web console: live state over /ws, actions over the JSON API (docs/web-api.md).
// Plain ES2020, no dependencies. Text from the server only ever goes into textContent/attributes.
'use strict';
(() => {
  const $ = (id) => document.getElementById(id);
  const SVGNS = 'http://www.w3.org/2000/svg';
  const SCREENS = ['main', 'targets', 'sky', 'manual', 'antenna', 'setup'];
  const BAND_NAMES = { 50: '6 m', 70: '4 m', 144: '2 m', 222: '1.25 m', 432: '70 cm', 902: '33 cm',
    1296: '23 cm', 2304: '13 cm', 3400: '9 cm', 5760: '6 cm', 10368: '3 cm', 24048: '1.2 cm',
    47088: '6 mm', 76032: '4 mm' };
  const DEFAULT_BANDS = Object.keys(BAND_NAMES);
  const TREND_S = 300;

  const S = {
    state: null, config: null, targets: null, sky: null, screen: 'main',
    loggedIn: false, csrf: null, passwordSet: true,
    loginDismissed: localStorage.getItem('azt.loginbar') === 'hidden',
    sel: null, // what TRACK starts: {body, label, serverName}
    ws: null, connected: false, backoff: 250, attempts: 0, lastMsg: 0, openedAt: 0, retryTimer: 0,
    trend: [], trendDrawn: 0, skyDrawn: 0, skyListDrawn: 0, faultsKey: '', eventsKey: '', commandsKey: '', ioKey: '', dopKey: '',
  };

  // ------------------------------------------------------------------ small helpers ----------
  function h(tag, props, ...kids) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(props || {})) {
      if (v == null || v === false) continue;
      if (k === 'class') e.className = v;
      else if (k === 'text') e.textContent = v;
      else if (k.startsWith('on')) e.addEventListener(k.slice(2), v);
      else e.setAttribute(k, v === true ? '' : String(v));
    }
    for (const kid of kids) if (kid != null) e.append(kid instanceof Node ? kid : String(kid));
    return e;
  }
  function sv(tag, attrs, text) {
    const e = document.createElementNS(SVGNS, tag);
    for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, String(v));
    if (text != null) e.textContent = text;
    return e;
  }
  function setText(el, txt) { if (typeof el === 'string') el = $(el); if (el && el.textContent !== txt) el.textContent = txt; }
  const isNum = (v) => typeof v === 'number' && Number.isFinite(v);
  function fix(v, n) { let t = v.toFixed(n); if (/^-0(\.0*)?$/.test(t)) t = t.slice(1); return t; }
  const deg = (v, n = 2) => (isNum(v) ? `${fix(v, n)}°` : '—');
  function sdeg(v, n = 2) { if (!isNum(v)) return '—'; const t = fix(v, n); return `${t.startsWith('-') ? t : `+${t}`}°`; }
  function hz(v) { if (!isNum(v)) return '—'; const r = Math.round(v); return `${r < 0 ? '-' : '+'}${Math.abs(r)} Hz`; }
  function parseNum(s) {
    const t = String(s).trim().replace(',', '.');
    if (t === '' || !/^[-+]?(\d+\.?\d*|\.\d+)(e[-+]?\d+)?$/i.test(t)) return NaN;
    return Number(t);
  }
  const bandLabel = (b) => `${b} MHz${BAND_NAMES[b] ? ` (${BAND_NAMES[b]})` : ''}`;
  const pad = (n, w = 2) => String(n).padStart(w, '0');
  const upper1 = (s) => (s ? s[0].toUpperCase() + s.slice(1) : s);

  // Maidenhead locator <-> position (centre of the square), for showing the other representation.
  const GRID_RE = /^[A-R]{2}(?:\d{2}(?:[A-X]{2}(?:\d{2}(?:[A-X]{2})?)?)?)?$/i;
  function gridToLatLon(g) {
    g = g.trim().toUpperCase();
    if (g.length < 4 || g.length % 2 || !GRID_RE.test(g)) return null;
    let lonS = 20; let latS = 10;
    let lon = -180 + (g.charCodeAt(0) - 65) * lonS; let lat = -90 + (g.charCodeAt(1) - 65) * latS;
    for (let i = 2; i < g.length; i += 2) {
      if ((i / 2) % 2 === 1) { lonS /= 10; latS /= 10; lon += +g[i] * lonS; lat += +g[i + 1] * latS; } else {
        lonS /= 24; latS /= 24; lon += (g.charCodeAt(i) - 65) * lonS; lat += (g.charCodeAt(i + 1) - 65) * latS;
      }
    }
    return { lat: lat + latS / 2, lon: lon + lonS / 2 };
  }
  function latLonToGrid(lat, lon) {
    if (!isNum(lat) || !isNum(lon) || Math.abs(lat) > 90 || Math.abs(lon) > 180) return null;
    let x = Math.min(lon + 180, 359.9999999); let y = Math.min(lat + 90, 179.9999999);
    let s = String.fromCharCode(65 + Math.floor(x / 20), 65 + Math.floor(y / 10));
    x %= 20; y %= 10; s += `${Math.floor(x / 2)}${Math.floor(y)}`; x %= 2; y %= 1;
    return s + String.fromCharCode(97 + Math.floor(x * 12), 97 + Math.floor(y * 24));
  }
  const fmtLatLon = (lat, lon) => `${fix(Math.abs(lat), 4)}° ${lat < 0 ? 'S' : 'N'}, ${fix(Math.abs(lon), 4)}° ${lon < 0 ? 'W' : 'E'}`;

  // ------------------------------------------------------------------ toasts ------------------
  function toast(msg, kind = 'ok', action = null, ms = 0) {
    const t = h('div', { class: `toast${kind === 'err' ? ' err' : ''}`, role: kind === 'err' ? 'alert' : 'status' }, h('span', { text: msg }));
    const close = () => t.remove();
    if (action) t.append(h('button', { type: 'button', class: 'btn small', text: action.label, onclick: () => { close(); action.fn(); } }));
    $('toasts').append(t);
    while ($('toasts').children.length > 4) $('toasts').firstChild.remove();
    setTimeout(close, ms || (kind === 'err' ? 8000 : action ? 8000 : 3000));
  }

  // ------------------------------------------------------------------ API ---------------------
  async function request(method, path, body) {
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
  async function act(label, method, path, body, opts = {}) {
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

  async function loadJSON(path) {
    const r = await request('GET', path);
    return r.ok ? r.data : null;
  }

  // ------------------------------------------------------------------ session / login -------
  function setLoggedIn(v, csrf) {
    S.loggedIn = v; S.csrf = v ? csrf : null;
    const st = $('login-state');
    setText(st, v ? 'Logged in' : 'Read-only');
    st.className = `pill ${v ? 'in' : 'out'}`;
    st.title = v ? 'Logged in: the console can control the antenna' : 'Read-only: log in to control the antenna';
    $('logout-btn').hidden = !v;
    $('login-form').hidden = v || S.loginDismissed;
    if (v) setText('login-error', '');
  }
  function showLogin(msg) {
    S.loginDismissed = false; localStorage.removeItem('azt.loginbar');
    $('login-form').hidden = false;
    setText('login-error', msg || '');
    window.scrollTo({ top: 0 });
    $('password').focus({ preventScroll: true });
  }
  async function refreshSession() {
    const j = await loadJSON('/api/session');
    if (!j) return;
    S.passwordSet = j.password_set !== false;
    setLoggedIn(!!j.logged_in && !!j.csrf, j.csrf || null);
    if (!S.passwordSet && !S.loggedIn) setText('login-error', 'No operator password is set on the controller ([web] password_hash): the console is read-only.');
  }
  async function login(ev) {
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
  async function logout() {
    await request('POST', '/api/logout');
    setLoggedIn(false, null);
    toast('Logged out: read-only.');
  }

  // ------------------------------------------------------------------ navigation --------------
  function show(name) {
    if (!SCREENS.includes(name)) name = 'main';
    const changed = S.screen !== name;
    S.screen = name;
    for (const n of SCREENS) {
      $(`screen-${n}`).hidden = n !== name;
      $(`nav-${n}`).setAttribute('aria-selected', String(n === name));
    }
    if (changed) window.scrollTo({ top: 0 });
    if (name === 'main') { drawTrend(true); }
    if (name === 'targets') loadTargets();
    if (name === 'sky') { loadSky(); drawSky(true); }
    if (name === 'setup' || name === 'antenna' || name === 'manual') loadConfig();
    if (name === 'antenna') drawTilt();
  }
  function go(name) { if (location.hash === `#${name}`) show(name); else location.hash = name; }

  // ------------------------------------------------------------------ WebSocket --------------
  function connect() {
    clearTimeout(S.retryTimer);
    S.attempts += 1;
    let ws;
    try {
      ws = new WebSocket(`${location.protocol === 'https:' ? 'wss:' : 'ws:'}//${location.host}/ws`);
    } catch (e) { retry(); return; }
    S.ws = ws; S.openedAt = performance.now();
    ws.onopen = () => { if (S.ws === ws) { S.lastMsg = performance.now(); setConnected(true); } };
    ws.onmessage = (ev) => {
      if (S.ws !== ws) return;
      S.lastMsg = performance.now(); S.backoff = 250; S.attempts = 0;
      if (!S.connected) setConnected(true);
      let st;
      try { st = JSON.parse(ev.data); } catch (e) { return; }
      if (st && typeof st === 'object') onState(st);
    };
    ws.onclose = () => { if (S.ws === ws) { S.ws = null; setConnected(false); retry(); } };
    ws.onerror = () => { try { ws.close(); } catch (e) { /* closed */ } };
  }
  function retry() {
    clearTimeout(S.retryTimer);
    const wait = S.backoff;
    S.backoff = Math.min(2000, S.backoff * 2);
    setText('disc-detail', `Reconnecting in ${fix(wait / 1000, 1)} s${S.attempts > 1 ? ` (attempt ${S.attempts})` : ''}…`);
    S.retryTimer = setTimeout(connect, wait);
  }
  function dropSocket() { // a silent or stuck socket: abandon it and start again
    const ws = S.ws; S.ws = null;
    if (ws) { ws.onclose = ws.onmessage = ws.onopen = ws.onerror = null; try { ws.close(); } catch (e) { /* */ } }
    setConnected(false); retry();
  }
  function setConnected(v) {
    const was = S.connected;
    S.connected = v;
    $('disconnected').hidden = v;
    $('conn-dot').className = `dot${v ? ' on' : ''}`;
    $('conn-dot').title = v ? 'Live: connected to the controller' : 'Not connected';
    document.body.classList.toggle('stale', !v);
    if (v && !was) {
      if (!S.config) loadConfig();
      if (!S.targets) loadTargets();
      refreshSession();
    }
  }
  setInterval(() => {
    const now = performance.now();
    if (S.ws && S.ws.readyState === WebSocket.OPEN && now - S.lastMsg > 3000) dropSocket();
    else if (S.ws && S.ws.readyState === WebSocket.CONNECTING && now - S.openedAt > 4000) dropSocket();
  }, 500);
  document.addEventListener('visibilitychange', () => {
    if (!document.hidden && !S.ws) { S.backoff = 250; connect(); }
  });

  // ------------------------------------------------------------------ live state -------------
  function parkSlotAt(az, el) {
    const park = (S.config && S.config.park) || (S.targets && S.targets.park) || [];
    return park.find((p) => isNum(az) && Math.abs(p.az_deg - az) < 0.01 && Math.abs(p.el_deg - el) < 0.01);
  }
  function targetLabel(st) {
    const t = st.target || {};
    switch (st.mode) {
      case 'TRACK': return t.name || '—';
      case 'PARK': { const p = parkSlotAt(t.az_deg, t.el_deg); return p ? `Park ${p.slot} · ${p.name}` : 'Park'; }
      case 'MAN': return 'Manual position';
      case 'EXT': return 'PC program';
      default: return t.name || (S.sel ? S.sel.label : '—');
    }
  }
  const sameName = (a, b) => a != null && b != null && String(a).toLowerCase() === String(b).toLowerCase();

  function onState(st) {
    S.state = st;
    const t = st.target || {};
    // TRACK starts the selected target: the one chosen here last, or the one the controller last
    // switched to (a change of the tracked target, by anyone, becomes the selection).
    if (st.mode === 'TRACK' && t.name && !sameName(t.name, S.lastTracked)) {
      S.lastTracked = t.name;
      const mine = S.sel && (sameName(S.sel.serverName, t.name) || sameName(S.sel.label, t.name) || (S.sel.body.ra_deg !== undefined && !S.sel.serverName));
      if (mine) S.sel.serverName = t.name; else S.sel = { body: { name: t.name }, label: t.name, serverName: t.name };
    }
    // A: target
    setText('target-name', targetLabel(st));
    setText('target-az', deg(t.az_deg));
    setText('target-el', deg(t.el_deg));
    const m = st.moon;
    setText('doppler', m ? hz(m.echo_doppler_hz) : '—');
    setText('doppler-band', m && m.band ? `${m.band} MHz` : '');
    $('doppler').parentElement.classList.toggle('off', !(st.mode === 'TRACK' && sameName(t.name, 'moon')));
    const dx = m && isNum(m.dx_echo_doppler_hz);
    $('dx-row').hidden = !dx;
    if (dx) setText('dx-doppler', hz(m.dx_echo_doppler_hz));
    const clk = st.clock || {};
    setText('clock-source', clk.source || '—');
    setText('clock-status', Object.entries(clk).filter(([k]) => k !== 'source').map(([k, v]) => `${k}: ${typeof v === 'object' ? JSON.stringify(v) : v}`).join(' · '));
    // B: corrections
    const c = st.corrections || {};
    setText('az-corr', sdeg(c.az_user_deg));
    setText('el-corr', sdeg(c.el_user_deg));
    // C: antenna
    const a = st.antenna || {};
    const known = a.known !== false && isNum(a.az_deg);
    setText('ant-az', known ? deg(a.az_deg) : '—');
    setText('ant-el', known ? deg(a.el_deg) : '—');
    const e = st.error_deg;
    setText('err-az', e ? sdeg(e.az) : '—');
    setText('err-el', e ? sdeg(e.el) : '—');
    const pe = $('pointing-error');
    if (e && isNum(e.az) && isNum(e.el)) {
      const tot = Math.hypot(e.az * Math.cos(((isNum(a.el_deg) ? a.el_deg : 0) * Math.PI) / 180), e.el);
      setText(pe, deg(tot));
      const win = S.config && S.config.control ? S.config.control.window_deg : 0.1;
      pe.className = `perr ${tot <= Math.max(win, 0.02) + 0.01 ? 'good' : tot > 3 ? 'far' : ''}`;
    } else { setText(pe, '—'); pe.className = 'perr'; }
    const mv = $('ant-moving');
    setText(mv, !known ? 'position unknown' : a.moving ? 'moving' : 'still');
    mv.className = `moving${known && a.moving ? ' on' : ''}`;
    const showMount = known && isNum(a.az_mount_deg) && Math.abs(a.az_mount_deg - a.az_deg) > 0.005;
    $('mount-row').hidden = !showMount;
    if (showMount) setText('ant-mount', deg(a.az_mount_deg));
    // D: mode, time
    const mode = st.mode || '—';
    setText('mode', mode);
    $('mode').className = `mode m-${mode}`;
    setText('mode-who', st.who ? `by ${st.who}${st.pc_locked_out ? ' · PC programs locked out' : ''}` : '');
    setText('track-name', S.sel ? S.sel.label : 'choose a target');
    const d = st.utc ? new Date(st.utc) : null;
    if (d && !Number.isNaN(d.getTime())) {
      setText('utc', `${pad(d.getUTCHours())}:${pad(d.getUTCMinutes())}:${pad(d.getUTCSeconds())}`);
      setText('date', `${['Sun', 'Mon', 'Tue', 'Wed', 'Thu', 'Fri', 'Sat'][d.getUTCDay()]}, ${pad(d.getUTCDate())} ${
        ['Jan', 'Feb', 'Mar', 'Apr', 'May', 'Jun', 'Jul', 'Aug', 'Sep', 'Oct', 'Nov', 'Dec'][d.getUTCMonth()]} ${d.getUTCFullYear()}`);
    }
    // header
    setText('mini-az', known ? `${fix(a.az_deg, 2)}°` : '—');
    setText('mini-el', known ? `${fix(a.el_deg, 2)}°` : '—');
    setText('mini-mode', mode);
    $('mini-mode').className = `mini-mode m-${mode}`;
    renderFaults(Array.isArray(st.faults) ? st.faults : []);
    renderIo(st.station_io);
    renderLog('event-list', 'eventsKey', Array.isArray(st.events) ? st.events : [], 10);
    renderLog('command-list', 'commandsKey', Array.isArray(st.commands) ? st.commands : [], 6);
    renderMoon(m);
    // trend
    const now = performance.now() / 1000;
    S.trend.push([now, e && isNum(e.az) ? e.az : null, e && isNum(e.el) ? e.el : null]);
    while (S.trend.length && S.trend[0][0] < now - TREND_S - 5) S.trend.shift();
    if (S.screen === 'main') drawTrend();
    if (S.screen === 'sky') drawSky();
    if (S.screen === 'manual') {
      setText('man-cur-az', known ? deg(a.az_deg) : '—');
      setText('man-cur-el', known ? deg(a.el_deg) : '—');
      setText('man-cur-mode', `${mode}${st.who ? ` (${st.who})` : ''}`);
    }
    if (S.screen === 'targets') markActiveTarget();
  }

  function renderFaults(list) {
    const key = JSON.stringify(list);
    if (key === S.faultsKey) return;
    S.faultsKey = key;
    $('faults').hidden = list.length === 0;
    $('faults-plural').hidden = list.length === 1;
    $('fault-list').replaceChildren(...list.map((f) => h('li', { text: String(f) })));
  }

  // A newest-first list of {utc, text, count}: the refusals any source was given ("events") and
  // the accepted motion commands with their sources ("commands"), docs/web-api.md.
  function renderLog(listId, keyName, list, max) {
    const key = JSON.stringify(list);
    if (key === S[keyName]) return;
    S[keyName] = key;
    if (!list.length) { $(listId).replaceChildren(h('li', { class: 'dimtxt', text: 'none yet' })); return; }
    $(listId).replaceChildren(...list.slice(0, max).map((e) => h('li', {
      text: `${String(e.utc || '').slice(11, 19)}  ${String(e.text)}${e.count > 1 ? ` (×${e.count})` : ''}`,
    })));
  }

  // E-stop, limit switches and the T/R chain (docs/web-api.md "station_io").
  function renderIo(io) {
    const key = JSON.stringify(io || null);
    if (key === S.ioKey) return;
    S.ioKey = key;
    const es = io && io.estop ? io.estop : null;
    const estop = $('io-estop');
    if (!es || (!es.wired && !es.latched)) { setText(estop, 'not wired'); estop.className = ''; } else {
      setText(estop, es.latched ? (es.input ? 'PRESSED · latched' : 'latched · clear faults to resume') : 'ready');
      estop.className = es.latched ? 'io-bad' : '';
    }
    const lim = io && io.limits ? io.limits : null;
    const names = { az_ccw: 'AZ CCW', az_cw: 'AZ CW', el_down: 'EL DOWN', el_up: 'EL UP' };
    const tripped = lim ? Object.keys(names).filter((k) => lim[k]).map((k) => names[k]) : [];
    setText('io-limits', !lim ? 'not wired' : tripped.length ? `tripped: ${tripped.join(', ')}` : 'all clear');
    $('io-limits').className = tripped.length ? 'io-bad' : '';
    const seq = io && io.sequencer ? io.sequencer : null;
    let ptt = '—';
    if (seq) {
      ptt = seq.timed_out ? 'time-out: release PTT' : seq.inhibited ? 'inhibited' : seq.transmitting ? 'TRANSMIT'
        : seq.ptt ? 'keying…' : 'receive';
      if (!seq.wired) ptt += ' (no GPIO lines)';
    }
    setText('io-ptt', ptt);
    $('io-ptt').className = seq && (seq.transmitting || seq.timed_out) ? 'io-bad' : '';
    const outs = seq && Array.isArray(seq.outputs) ? seq.outputs : [];
    $('io-seq').replaceChildren(...outs.map((o) => h('span', { class: `out${o.on ? ' on' : ''}`, text: String(o.name) })));
  }

  function renderMoon(m) {
    if (!m) {
      setText('moon-azel', 'not available'); setText('moon-dist', '—'); setText('moon-delay', '—');
      if (S.dopKey) { $('moon-doppler').replaceChildren(); S.dopKey = ''; }
      return;
    }
    setText('moon-azel', `${deg(m.az_deg)} / ${deg(m.el_deg)}${isNum(m.el_deg) && m.el_deg < 0 ? ' (below horizon)' : ''}`);
    setText('moon-dist', isNum(m.distance_km) ? `${Math.round(m.distance_km).toLocaleString('en-US')} km` : '—');
    setText('moon-delay', isNum(m.echo_delay_s) ? `${m.echo_delay_s.toFixed(3)} s` : '—');
    const dop = m.doppler_hz && typeof m.doppler_hz === 'object' ? m.doppler_hz : {};
    const bands = Object.keys(dop).sort((x, y) => Number(x) - Number(y));
    const key = `${bands.join(',')}|${m.band}`;
    if (key !== S.dopKey) {
      S.dopKey = key;
      $('moon-doppler').replaceChildren(h('div', { class: 'dophead', text: 'Self-echo Doppler by band (MHz)' }),
        ...bands.map((b) => h('div', { class: `dop${String(b) === String(m.band) ? ' sel' : ''}` },
          h('span', {}, String(b), ' ', h('small', { text: BAND_NAMES[b] || '' })), h('b', { 'data-band': b }))));
    }
    for (const el of $('moon-doppler').querySelectorAll('b[data-band]')) setText(el, hz(dop[el.dataset.band]));
  }

  // ------------------------------------------------------------------ trend chart ------------
  function niceScale(m) {
    for (const s of [0.05, 0.1, 0.2, 0.5, 1, 2, 5]) if (m <= s) return s;
    return 5;
  }
  function drawTrend(force) {
    const nowMs = performance.now();
    if (!force && nowMs - S.trendDrawn < 400) return;
    S.trendDrawn = nowMs;
    const svg = $('trend');
    const W = fitWidth(svg, 190);
    const TR = { L: 48, R: W - 8, T: 10, B: 166 };
    const kids = [];
    const now = nowMs / 1000;
    let m = 0;
    for (const [t, az, el] of S.trend) if (t >= now - TREND_S) m = Math.max(m, Math.abs(az || 0), Math.abs(el || 0));
    const win = S.config && S.config.control && isNum(S.config.control.window_deg) ? S.config.control.window_deg : 0;
    const sc = niceScale(Math.max(m, win * 1.25));
    const mid = (TR.T + TR.B) / 2; const half = (TR.B - TR.T) / 2;
    const y = (v) => mid - (Math.max(-sc, Math.min(sc, v)) / sc) * half;
    const x = (t) => TR.R - ((now - t) / TREND_S) * (TR.R - TR.L);
    if (win > 0) kids.push(sv('rect', { class: 'winband', x: TR.L, width: TR.R - TR.L, y: y(win), height: Math.max(0, y(-win) - y(win)) }));
    for (const v of [sc, sc / 2, 0, -sc / 2, -sc]) {
      kids.push(sv('line', { class: v === 0 ? 'zero' : 'gl', x1: TR.L, x2: TR.R, y1: y(v), y2: y(v) }),
        sv('text', { x: TR.L - 6, y: y(v), 'text-anchor': 'end', 'dominant-baseline': 'middle' }, v === 0 ? '0°' : `${v > 0 ? '+' : '−'}${Math.abs(v)}°`));
    }
    const step = W < 420 ? 2 : 1;
    for (let k = 0; k <= 5; k += 1) {
      const xx = TR.L + ((TR.R - TR.L) * k) / 5;
      kids.push(sv('line', { class: 'gl', x1: xx, x2: xx, y1: TR.T, y2: TR.B, 'stroke-dasharray': '2 4' }));
      if (k === 5 || (5 - k) % step === 0) kids.push(sv('text', { x: xx, y: TR.B + 17, 'text-anchor': k === 5 ? 'end' : 'middle' }, k === 5 ? 'now' : `−${5 - k} min`));
    }
    for (const [idx, cls] of [[1, 'laz'], [2, 'lel']]) {
      let d = ''; let prev = null;
      for (const p of S.trend) {
        if (p[0] < now - TREND_S || p[idx] === null) { prev = null; continue; }
        const gap = !prev || p[0] - prev[0] > 2;
        d += `${gap ? 'M' : 'L'}${x(p[0]).toFixed(1)} ${y(p[idx]).toFixed(1)}`;
        prev = p;
      }
      kids.push(sv('path', { class: cls, d }));
    }
    svg.replaceChildren(...kids);
  }
  // Charts are drawn in CSS pixels (viewBox = the element's width), so text keeps its size on a phone.
  function fitWidth(svg, height) {
    const W = Math.max(260, Math.round(svg.clientWidth || (svg.parentElement && svg.parentElement.clientWidth) || 600));
    const vb = `0 0 ${W} ${height}`;
    if (svg.getAttribute('viewBox') !== vb) svg.setAttribute('viewBox', vb);
    return W;
  }

  // ------------------------------------------------------------------ sky plot ---------------
  let skyEls = null;
  function proj(az, el) {
    const r = (100 * (90 - Math.max(0, el))) / 90; const a = (az * Math.PI) / 180;
    return [r * Math.sin(a), -r * Math.cos(a)];
  }
  function drawSkyStatic() {
    const svg = $('sky-plot');
    svg.append(sv('circle', { class: 'horizon', r: 100 }));
    for (const el of [30, 60]) {
      const r = (100 * (90 - el)) / 90;
      svg.append(sv('circle', { class: 'gl', r }), sv('text', { class: 'ringl', x: 1.5, y: -r - 1.5 }, `${el}°`));
    }
    svg.append(sv('line', { class: 'gl', x1: -100, x2: 100, y1: 0, y2: 0 }), sv('line', { class: 'gl', y1: -100, y2: 100, x1: 0, x2: 0 }));
    for (const [t, x, y] of [['N', 0, -109], ['E', 110, 0], ['S', 0, 110], ['W', -110, 0]]) {
      svg.append(sv('text', { class: 'card-l', x, y, 'text-anchor': 'middle', 'dominant-baseline': 'middle' }, t));
    }
    skyEls = { paths: sv('g'), srcs: sv('g'), bodies: sv('g'), marks: sv('g') };
    svg.append(skyEls.paths, skyEls.srcs, skyEls.bodies, skyEls.marks);
    skyEls.sun = sv('g', { class: 'sunm', id: 'sky-sun' }); skyEls.sun.append(sv('circle', { r: 5.5 }), sv('text', { class: 'bodyl', x: 11, y: 3 }, 'Sun'));
    skyEls.moon = sv('g', { class: 'moonm', id: 'sky-moon' }); skyEls.moon.append(sv('circle', { r: 5 }), sv('text', { class: 'bodyl', x: 11, y: 3 }, 'Moon'));
    skyEls.sun.lastChild.setAttribute('style', 'fill: var(--sun)');
    skyEls.moon.lastChild.setAttribute('style', 'fill: var(--moon)');
    skyEls.bodies.append(skyEls.sun, skyEls.moon);
    skyEls.tgt = sv('g', { class: 'tgtm', id: 'sky-target' });
    skyEls.tgt.append(sv('circle', { r: 8 }), sv('title', {}, 'target'));
    skyEls.ant = sv('g', { class: 'antm', id: 'sky-antenna' });
    skyEls.ant.append(sv('circle', { r: 4.5 }), sv('path', { d: 'M-10 0H-5M5 0H10M0 -10V-5M0 5V10' }), sv('title', {}, 'antenna'));
    skyEls.marks.append(skyEls.tgt, skyEls.ant);
  }
  function place(g, az, el) {
    const ok = isNum(az) && isNum(el) && el >= -0.5;
    g.style.display = ok ? '' : 'none';
    if (ok) { const [x, y] = proj(az, el); g.setAttribute('transform', `translate(${x.toFixed(2)} ${y.toFixed(2)})`); }
  }
  function drawSkyPaths() {
    if (!skyEls) drawSkyStatic();
    const out = [];
    const sky = S.sky || {};
    for (const [list, cls, labels] of [[sky.sun_path, 'spath', false], [sky.moon_path, 'mpath', true]]) {
      if (!Array.isArray(list)) continue;
      let d = ''; let up = false;
      list.forEach((p, i) => {
        if (!isNum(p.el_deg) || p.el_deg < 0) { up = false; return; }
        const [x, y] = proj(p.az_deg, p.el_deg);
        d += `${up ? 'L' : 'M'}${x.toFixed(1)} ${y.toFixed(1)}`; up = true;
        if (labels && i % 6 === 0 && i > 0) {
          const dt = new Date(p.utc);
          out.push(sv('circle', { class: 'ptick', cx: x.toFixed(1), cy: y.toFixed(1), r: 1.6 }));
          if (i % 12 === 0 && !Number.isNaN(dt.getTime())) out.push(sv('text', { class: 'plbl', x: (x + 3).toFixed(1), y: (y - 3).toFixed(1) }, `${pad(dt.getUTCHours())}h`));
        }
      });
      out.unshift(sv('path', { class: cls, d, id: labels ? 'sky-moon-path' : 'sky-sun-path' }));
    }
    if (Array.isArray(sky.pass_path) && sky.pass_path.length) {
      let d = ''; let up = false;
      for (const p of sky.pass_path) {
        if (!isNum(p.el_deg) || p.el_deg < 0) { up = false; continue; }
        const [x, y] = proj(p.az_deg, p.el_deg);
        d += `${up ? 'L' : 'M'}${x.toFixed(1)} ${y.toFixed(1)}`; up = true;
      }
      out.push(sv('path', { class: 'ppath', d, id: 'sky-pass-path' }));
    }
    skyEls.paths.replaceChildren(...out);
    const srcs = [];
    for (const o of (Array.isArray(sky.now) ? sky.now : [])) {
      if (o.kind !== 'source' || !isNum(o.el_deg) || o.el_deg < 0) continue;
      const [x, y] = proj(o.az_deg, o.el_deg);
      const g = sv('g', { transform: `translate(${x.toFixed(1)} ${y.toFixed(1)})` });
      g.append(sv('circle', { class: 'src', r: 2.2 }), sv('text', { class: 'srcl', x: 3.5, y: 2.5 }, String(o.name)), sv('title', {}, String(o.name)));
      srcs.push(g);
    }
    skyEls.srcs.replaceChildren(...srcs);
  }
  function drawSky(force) {
    const nowMs = performance.now();
    if (!skyEls) { drawSkyStatic(); drawSkyPaths(); }
    if (!force && nowMs - S.skyDrawn < 300) return;
    S.skyDrawn = nowMs;
    const st = S.state || {};
    const nowList = (S.sky && S.sky.now) || [];
    const sun = st.sun || nowList.find((o) => o.kind === 'sun') || {};
    const moon = st.moon || nowList.find((o) => o.kind === 'moon') || {};
    place(skyEls.sun, sun.az_deg, sun.el_deg);
    place(skyEls.moon, moon.az_deg, moon.el_deg);
    const t = st.target || {};
    place(skyEls.tgt, t.az_deg, t.el_deg);
    const a = st.antenna || {};
    place(skyEls.ant, a.known !== false ? a.az_deg : null, a.el_deg);
    const key = `${st.mode}|${t.name}`;
    if (force || key !== S.skyListKey || nowMs - S.skyListDrawn > 5000) { S.skyListDrawn = nowMs; S.skyListKey = key; drawSkyList(); }
  }
  function drawSkyList() {
    const st = S.state || {};
    const rows = [];
    const nowList = (S.sky && S.sky.now) || [];
    for (const o of nowList) {
      let p = o;
      if (o.kind === 'sun' && st.sun) p = { ...o, ...st.sun };
      if (o.kind === 'moon' && st.moon) p = { ...o, az_deg: st.moon.az_deg, el_deg: st.moon.el_deg };
      rows.push(p);
    }
    if (!rows.length) {
      if (st.sun) rows.push({ name: 'Sun', ...st.sun });
      if (st.moon) rows.push({ name: 'Moon', az_deg: st.moon.az_deg, el_deg: st.moon.el_deg });
    }
    rows.sort((x, y) => (y.el_deg ?? -99) - (x.el_deg ?? -99));
    const tn = st.mode === 'TRACK' && st.target ? st.target.name : null;
    $('sky-list').replaceChildren(...rows.map((o) => h('tr', { class: sameName(o.name, tn) ? 'sel' : isNum(o.el_deg) && o.el_deg < 0 ? 'below' : null },
      h('td', { text: String(o.name) }), h('td', { text: deg(o.az_deg, 1) }), h('td', { text: deg(o.el_deg, 1) }))));
  }
  async function loadSky() {
    const hours = $('sky-hours').value;
    const j = await loadJSON(`/api/sky?hours=${encodeURIComponent(hours)}`);
    if (!j) { setText('sky-error', 'Could not read /api/sky.'); return; }
    setText('sky-error', '');
    S.sky = j; drawSkyPaths(); drawSky(true);
  }

  // ------------------------------------------------------------------ targets ----------------
  async function loadTargets() {
    const j = await loadJSON('/api/targets');
    if (!j) { setText('targets-error', S.targets ? '' : 'Could not read the target list.'); return; }
    setText('targets-error', '');
    S.targets = j;
    renderTargets();
    fillBands();
  }
  const posText = (o) => (isNum(o.el_deg) ? `az ${deg(o.az_deg, 1)} · el ${deg(o.el_deg, 1)}${o.el_deg < 0 ? ' · below' : ''}` : '');
  function renderTargets() {
    const list = (S.targets && S.targets.targets) || [];
    for (const kind of ['sun', 'moon']) {
      const o = list.find((x) => x.kind === kind);
      const b = $(`tgt-${kind}`);
      if (o) { b.dataset.tname = o.name; setText(`tgt-${kind}-pos`, posText(o)); b.classList.toggle('down', o.el_deg < 0); }
    }
    const box = $('sources');
    const srcs = list.filter((x) => x.kind === 'source');
    const names = srcs.map((x) => x.name).join('\n');
    if (box.dataset.names !== names) {
      box.dataset.names = names;
      box.replaceChildren(...srcs.map((o) => h('button', { type: 'button', class: 'tgt src', 'data-name': o.name },
        h('span', { class: 'tn', text: o.name }), h('span', { class: 'tp' }))));
      if (!srcs.length) box.append(h('p', { class: 'dimtxt', text: 'No radio sources configured.' }));
    }
    for (const o of srcs) {
      const b = [...box.children].find((x) => x.dataset.name === o.name);
      if (b) { setText(b.lastChild, posText(o)); b.classList.toggle('down', o.el_deg < 0); }
    }
    renderSatellites();
    renderSpacecraft(list.filter((x) => x.kind === 'spacecraft'));
    const park = (S.targets && S.targets.park) || [];
    for (let n = 1; n <= 4; n++) {
      const p = park.find((x) => x.slot === n);
      const b = $(`park-${n}`);
      setText(b.firstChild, p ? `${n} · ${p.name}` : `Park ${n}`);
      setText(b.lastChild, p ? `az ${deg(p.az_deg, 1)} · el ${deg(p.el_deg, 1)}` : 'not set');
    }
    markActiveTarget();
  }
  function renderSpacecraft(crafts) {
    const box = $('spacecraft');
    const key = JSON.stringify(crafts.map((o) => [o.name, o.description, o.frequency_mhz, o.error || '',
      isNum(o.el_deg) ? Math.round(o.el_deg * 10) : null]));
    if (box.dataset.key === key) return;
    box.dataset.key = key;
    if (!crafts.length) { box.replaceChildren(h('p', { class: 'dimtxt', text: 'None configured.' })); return; }
    box.replaceChildren(...crafts.map((o) => {
      const f = isNum(o.frequency_mhz) && o.frequency_mhz > 0 ? ` · ${o.frequency_mhz} MHz` : '';
      const where = o.error ? 'outside its table' : posText(o);
      return h('button', { type: 'button', class: 'tgt src', 'data-name': o.name, title: o.description || '' },
        h('span', { class: 'tn', text: o.name }),
        h('span', { class: 'tp', text: `${o.description ? `${o.description}${f} · ` : f ? `${f.slice(3)} · ` : ''}${where}` }));
    }));
  }
  // Every satellite's passes in the next 24 h, merged in time order (the first 15).
  function renderPasses(sats) {
    const rows = [];
    for (const o of sats) for (const p of (Array.isArray(o.passes) ? o.passes : [])) rows.push({ name: o.name, ...p });
    rows.sort((a, b) => (a.aos < b.aos ? -1 : a.aos > b.aos ? 1 : 0));
    const hm = (iso) => { const t = new Date(iso); return Number.isNaN(t.getTime()) ? '—' : `${pad(t.getUTCHours())}:${pad(t.getUTCMinutes())}`; };
    const table = $('sat-passes');
    table.hidden = rows.length === 0;
    table.tBodies[0].replaceChildren(...rows.slice(0, 15).map((r) => h('tr', {},
      h('td', { text: r.name }), h('td', { text: hm(r.aos) }), h('td', { text: deg(r.aos_az_deg, 0) }),
      h('td', { text: deg(r.max_el_deg, 0) }), h('td', { text: hm(r.los) }), h('td', { text: deg(r.los_az_deg, 0) }))));
  }
  function renderSatellites() {
    const sats = (S.targets && Array.isArray(S.targets.satellites)) ? S.targets.satellites : [];
    const box = $('satellites');
    const key = JSON.stringify(sats.map((o) => [o.norad, o.name, o.next_pass, o.el_deg && Math.round(o.el_deg)]));
    if (box.dataset.key === key) return;
    box.dataset.key = key;
    renderPasses(sats);
    if (!sats.length) { box.replaceChildren(h('p', { class: 'dimtxt', text: 'No satellite catalogue ([satellites] file).' })); return; }
    box.replaceChildren(...sats.map((o) => {
      const np = o.next_pass;
      const t = np ? new Date(np.aos) : null;
      let info = np && t && !Number.isNaN(t.getTime())
        ? `AOS ${pad(t.getUTCHours())}:${pad(t.getUTCMinutes())} · max ${deg(np.max_el_deg, 0)}` : 'no pass in 24 h';
      if (isNum(o.el_deg) && o.el_deg >= 0) info = `up now · el ${deg(o.el_deg, 1)}`;
      const stale = isNum(o.element_age_days) && Math.abs(o.element_age_days) > 7;
      return h('button', { type: 'button', class: 'tgt sat', 'data-name': `sat:${o.name}`, 'data-norad': o.norad },
        h('span', { class: 'tn', text: o.name }),
        h('span', { class: `tp${stale ? ' stale' : ''}`, text: stale ? `${info} · elements ${Math.round(o.element_age_days)} d old` : info }));
    }));
  }
  function markActiveTarget() {
    const st = S.state || {};
    const tn = st.mode === 'TRACK' && st.target ? st.target.name : null;
    document.querySelectorAll('#screen-targets .tgt[data-name], #screen-targets .tgt[data-tname]').forEach((b) => b.classList.toggle('active', sameName(b.dataset.name || b.dataset.tname, tn)));
    const pk = st.mode === 'PARK' && st.target ? parkSlotAt(st.target.az_deg, st.target.el_deg) : null;
    for (let n = 1; n <= 4; n++) $(`park-${n}`).classList.toggle('active', !!pk && pk.slot === n);
  }
  async function track(body, label, btn) {
    const r = await act(`track ${label}`, 'POST', '/api/target', body, { btn });
    if (r.ok || r.status === 401) { // chosen: TRACK starts it after logging in
      S.sel = { body, label, serverName: r.data.target || null };
      setText('track-name', label);
    }
    if (r.ok) toast(`TRACK ${label}`);
    return r;
  }

  // RA as degrees or h:m:s (also "5h34m31.9s"); Dec as degrees or d:m:s.
  function parseAngle(str, hours) {
    const s = String(str).trim().replace(/,/g, '.');
    if (!s) return NaN;
    const sign = s.startsWith('-') || s.startsWith('−') ? -1 : 1;
    const body = s.replace(/^[-+−]/, '').trim();
    if (/[:hms°'"\s]/i.test(body)) {
      const parts = body.split(/[:hms°'"\s]+/i).filter(Boolean).map(parseNum);
      if (!parts.length || parts.length > 3 || parts.some(Number.isNaN)) return NaN;
      const v = parts[0] + (parts[1] || 0) / 60 + (parts[2] || 0) / 3600;
      return sign * v * (hours ? 15 : 1);
    }
    const v = parseNum(body);
    return sign * v;
  }
  function radecHint() {
    const ra = parseAngle($('ra').value, true); const dec = parseAngle($('dec').value, false);
    const parts = [];
    if (isNum(ra)) { const hh = ra / 15; const H = Math.floor(hh); const M = Math.floor((hh - H) * 60); parts.push(`RA ${fix(ra, 4)}° = ${pad(H)}h${pad(M)}m${fix(((hh - H) * 60 - M) * 60, 1).padStart(4, '0')}s`); }
    if (isNum(dec)) parts.push(`Dec ${dec >= 0 ? '+' : ''}${fix(dec, 4)}°`);
    setText('radec-hint', parts.join(' · '));
  }

  // ------------------------------------------------------------------ config forms -----------
  async function loadConfig(force) {
    const j = await loadJSON('/api/config');
    if (!j) return;
    S.config = j;
    fillConfig(force);
  }
  function field(id, value, force) {
    const i = $(id);
    if (!i || (!force && (i.dataset.dirty || document.activeElement === i))) return;
    i.value = value == null ? '' : String(value);
    delete i.dataset.dirty;
    i.classList.remove('bad');
  }
  function clean(form) { form.querySelectorAll('input').forEach((i) => { delete i.dataset.dirty; i.classList.remove('bad'); }); }
  const num6 = (v) => (isNum(v) ? String(Math.round(v * 1e6) / 1e6) : '');
  function fillConfig(force) {
    const c = S.config;
    if (!c) return;
    const st = c.station || {};
    field('grid', st.grid || latLonToGrid(st.lat_deg, st.lon_deg) || '', force);
    field('lat', num6(st.lat_deg), force);
    field('lon', num6(st.lon_deg), force);
    field('alt', isNum(st.alt_m) ? String(st.alt_m) : '', force);
    showOther();
    fillBands();
    setText('dx-grid', c.dx_grid || 'none');
    // servers
    const sv2 = c.servers || {};
    const addr = (x) => (x && x.port ? `${x.bind}:${x.port}` : 'off');
    const rows = [['rotctld (Hamlib, TCP)', addr(sv2.rotctld)], ['PstRotator (UDP)', addr(sv2.pstrotator)], ['Web console', addr(sv2.web)]];
    for (const s of Array.isArray(sv2.serial) ? sv2.serial : []) rows.push([`Serial ${s.protocol}`, `${s.device} · ${s.baud} Bd`]);
    $('servers').replaceChildren(...rows.map(([k, v]) => h('div', {}, h('span', { class: 'lbl', text: k }), h('span', { text: v }))));
    setText('setup-clock', (S.state && S.state.clock && S.state.clock.source) || 'system');
    // control, offsets
    const ctl = c.control || {};
    field('window', ctl.window_deg, force); field('ramp', ctl.ramp_s, force); field('tracking-speed', ctl.tracking_speed, force);
    const corr = c.corrections || {};
    field('az-offset', corr.az_offset_deg, force); field('el-offset', corr.el_offset_deg, force);
    const rn = Array.isArray(c.restart_needed) ? c.restart_needed : [];
    document.querySelectorAll('[data-key]').forEach((i) => {
      const note = i.nextElementSibling;
      if (note && note.classList.contains('restart-note')) note.hidden = !rn.includes(i.dataset.key);
    });
    fillPark(force);
    fillTilt(force);
    const g = c.geometry || {};
    $('geometry').replaceChildren(
      h('div', {}, h('span', { class: 'lbl', text: 'Azimuth' }), h('span', { text: `${deg(g.az_min_deg, 1)} … ${deg(g.az_max_deg, 1)}` })),
      h('div', {}, h('span', { class: 'lbl', text: 'Elevation' }), h('span', { text: `${deg(g.el_min_deg, 1)} … ${deg(g.el_max_deg, 1)}` })));
    setText('man-limits', isNum(g.az_min_deg) ? `Azimuth 0 … 360°, elevation ${fix(g.el_min_deg, 1)} … ${fix(g.el_max_deg, 1)}°.` : '');
  }
  function showOther() {
    const ll = gridToLatLon($('grid').value);
    setText('grid-other', ll ? `Centre of the square: ${fmtLatLon(ll.lat, ll.lon)}` : $('grid').value.trim() ? 'Not a valid locator: 2 letters A–R, 2 digits, then optional pairs (like FN06HE).' : '');
    const g = latLonToGrid(parseNum($('lat').value), parseNum($('lon').value));
    setText('latlon-other', g ? `Locator ${g.slice(0, 4).toUpperCase()}${g.slice(4)}` : '');
  }
  function fillBands() {
    const sel = $('band');
    if (document.activeElement === sel) return;
    const bands = (S.targets && Array.isArray(S.targets.bands) && S.targets.bands.length) ? S.targets.bands.map(String) : DEFAULT_BANDS;
    const cur = S.config ? String(S.config.band) : (S.state && S.state.moon ? String(S.state.moon.band) : '');
    const all = cur && !bands.includes(cur) ? [...bands, cur] : bands;
    if (sel.dataset.bands !== all.join(',')) {
      sel.dataset.bands = all.join(',');
      sel.replaceChildren(...all.map((b) => h('option', { value: b, text: bandLabel(b) })));
    }
    if (cur) sel.value = cur;
  }

  function buildPark() {
    const box = $('park-editor');
    for (let n = 1; n <= 4; n++) {
      const f = h('form', { class: 'park-row', id: `park-form-${n}`, novalidate: true },
        h('span', { class: 'slotn', text: String(n) }),
        h('label', { class: 'pname' }, 'Name', h('input', { id: `park-name-${n}`, 'data-f': 'name', autocomplete: 'off', maxlength: 32 })),
        h('label', { class: 'paz' }, 'Az °', h('input', { id: `park-az-${n}`, 'data-f': 'az_deg', inputmode: 'decimal', autocomplete: 'off' })),
        h('label', { class: 'pel' }, 'El °', h('input', { id: `park-el-${n}`, 'data-f': 'el_deg', inputmode: 'decimal', autocomplete: 'off' })),
        h('button', { type: 'submit', class: 'btn small psave', id: `park-save-${n}`, text: 'Save' }),
        h('p', { class: 'error', id: `park-error-${n}` }));
      f.addEventListener('submit', (ev) => { ev.preventDefault(); savePark(n, f); });
      box.append(f);
    }
  }
  function fillPark(force) {
    const park = (S.config && S.config.park) || [];
    for (let n = 1; n <= 4; n++) {
      const p = park.find((x) => x.slot === n) || {};
      field(`park-name-${n}`, p.name, force); field(`park-az-${n}`, p.az_deg, force); field(`park-el-${n}`, p.el_deg, force);
    }
  }
  async function savePark(n, f) {
    const errEl = $(`park-error-${n}`);
    const az = parseNum($(`park-az-${n}`).value); const el = parseNum($(`park-el-${n}`).value);
    const name = $(`park-name-${n}`).value.trim();
    if (Number.isNaN(az) || Number.isNaN(el)) { setText(errEl, 'Azimuth and elevation must be numbers.'); return; }
    const r = await act(`save park slot ${n}`, 'PUT', '/api/config/park', { slot: n, name, az_deg: az, el_deg: el }, { btn: $(`park-save-${n}`), errEl, form: f });
    if (r.ok) { clean(f); toast(`Park slot ${n} saved.`); await loadConfig(true); loadTargets(); }
  }

  // Tilt table: 60 entries, az 0, 6 … 354. Shown as 10 rows × 6 columns, read down the columns.
  const tiltPending = {};
  function buildTilt() {
    const box = $('tilt-grid');
    for (let i = 0; i < 60; i++) {
      const az = i * 6;
      const inp = h('input', { id: `tilt-${i}`, inputmode: 'decimal', autocomplete: 'off', 'data-index': i, 'aria-label': `Tilt correction at azimuth ${az}°` });
      inp.addEventListener('change', () => saveTilt(i));
      inp.addEventListener('keydown', (ev) => { if (ev.key === 'Enter') { ev.preventDefault(); saveTilt(i); } });
      inp.addEventListener('input', () => { inp.dataset.dirty = '1'; inp.classList.remove('saved'); });
      box.append(h('label', { class: 'tcell' }, h('span', { text: pad(az, 3) }), inp));
    }
  }
  function tiltValues() { const t = S.config && S.config.corrections && S.config.corrections.tilt_el_deg; return Array.isArray(t) ? t : []; }
  function fillTilt(force) {
    const t = tiltValues();
    for (let i = 0; i < 60; i++) if (isNum(t[i])) field(`tilt-${i}`, String(t[i]), force);
    drawTilt();
  }
  async function saveTilt(i) {
    const inp = $(`tilt-${i}`);
    const v = parseNum(inp.value);
    const az = pad(i * 6, 3);
    if (Number.isNaN(v)) { inp.classList.add('bad'); setText('tilt-error', `Az ${az}°: “${inp.value}” is not a number.`); return; }
    const t = tiltValues();
    if (t[i] === v && !inp.classList.contains('bad')) { delete inp.dataset.dirty; return; }
    if (tiltPending[i] === v) return;
    tiltPending[i] = v;
    const r = await act(`save the tilt table at az ${az}°`, 'PUT', '/api/config/tilt', { index: i, value: v }, { errEl: $('tilt-error') });
    delete tiltPending[i];
    if (r.ok) {
      if (S.config && S.config.corrections && Array.isArray(S.config.corrections.tilt_el_deg)) S.config.corrections.tilt_el_deg[i] = v;
      delete inp.dataset.dirty;
      inp.classList.remove('bad'); inp.classList.add('saved');
      setTimeout(() => inp.classList.remove('saved'), 1500);
      drawTilt();
    } else {
      inp.classList.add('bad');
      if (r.status !== 401 && r.data.error) setText('tilt-error', `Az ${az}°: ${r.data.error} (not saved)`);
    }
  }
  function drawTilt() {
    const t = tiltValues();
    const svg = $('tilt-plot');
    const W = fitWidth(svg, 170);
    const L = 48; const R = W - 10; const T = 10; const B = 146;
    const m = Math.max(0.1, ...t.filter(isNum).map(Math.abs));
    const sc = niceScale(m);
    const x = (az) => L + (az / 360) * (R - L);
    const y = (v) => (T + B) / 2 - (v / sc) * ((B - T) / 2);
    const kids = [];
    for (const v of [sc, 0, -sc]) {
      kids.push(sv('line', { class: v === 0 ? 'zero' : 'gl', x1: L, x2: R, y1: y(v), y2: y(v) }),
        sv('text', { x: L - 6, y: y(v), 'text-anchor': 'end', 'dominant-baseline': 'middle' }, v === 0 ? '0°' : `${v > 0 ? '+' : '−'}${sc}°`));
    }
    for (let az = 0; az <= 360; az += W < 420 ? 90 : 60) {
      kids.push(sv('line', { class: 'gl', x1: x(az), x2: x(az), y1: T, y2: B, 'stroke-dasharray': '2 4' }),
        sv('text', { x: x(az), y: B + 16, 'text-anchor': az === 0 ? 'start' : az === 360 ? 'end' : 'middle' }, `${az}°`));
    }
    if (t.length === 60 && t.every(isNum)) {
      let d = '';
      for (let i = 0; i <= 60; i++) d += `${i ? 'L' : 'M'}${x(i * 6).toFixed(1)} ${y(t[i % 60]).toFixed(1)}`;
      kids.push(sv('path', { class: 'tilt', d }));
      t.forEach((v, i) => kids.push(sv('circle', { class: 'tiltpt', cx: x(i * 6).toFixed(1), cy: y(v).toFixed(1), r: 2.2 }, null)));
    }
    svg.replaceChildren(...kids);
  }

  // ------------------------------------------------------------------ wiring -----------------
  function confirmTwice(btn, label, fn) { // a second press within 4 s confirms
    if (btn.dataset.armed) { delete btn.dataset.armed; setText(btn, btn.dataset.label); fn(); return; }
    btn.dataset.label = btn.textContent; btn.dataset.armed = '1'; setText(btn, label);
    setTimeout(() => { if (btn.dataset.armed) { delete btn.dataset.armed; setText(btn, btn.dataset.label); } }, 4000);
  }

  function wire() {
    for (const n of SCREENS) $(`nav-${n}`).addEventListener('click', () => go(n));
    window.addEventListener('hashchange', () => show(location.hash.slice(1)));
    $('target-pick').addEventListener('click', () => go('targets'));
    $('offset-btn').addEventListener('click', () => go('antenna'));

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
      const ra = parseAngle($('ra').value, true); const dec = parseAngle($('dec').value, false);
      f.querySelectorAll('.bad').forEach((e) => e.classList.remove('bad'));
      if (Number.isNaN(ra) || Number.isNaN(dec)) {
        if (Number.isNaN(ra)) $('ra').classList.add('bad');
        if (Number.isNaN(dec)) $('dec').classList.add('bad');
        setText('radec-error', 'RA and Dec must be numbers: degrees (83.633), or h:m:s for RA and d:m:s for Dec.');
        return;
      }
      const body = { ra_deg: ra, dec_deg: dec };
      const label = `RA ${fix(ra, 3)}° Dec ${dec >= 0 ? '+' : ''}${fix(dec, 3)}°`;
      const r = await act(`track ${label}`, 'POST', '/api/target', body, { btn: $('radec-go'), errEl: $('radec-error'), form: f });
      if (r.ok || r.status === 401) { S.sel = { body, label, serverName: r.data.target || null }; setText('track-name', label); }
      if (r.ok) toast(`TRACK ${label}`);
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

  function applyTheme(t) {
    if (!['dark', 'night', 'light'].includes(t)) t = 'dark';
    document.documentElement.dataset.theme = t;
    const meta = document.querySelector('meta[name="theme-color"]');
    if (meta) meta.setAttribute('content', t === 'light' ? '#ffffff' : t === 'night' ? '#000000' : '#0b0b0d');
  }

  // ------------------------------------------------------------------ start ------------------
  function start() {
    applyTheme(localStorage.getItem('azt.theme') || 'dark');
    buildPark();
    buildTilt();
    wire();
    setLoggedIn(false, null);
    $('login-form').hidden = true; // until /api/session has answered
    setConnected(false);
    setText('disc-detail', 'Connecting…');
    show(location.hash.slice(1) || 'main');
    refreshSession();
    loadConfig();
    loadTargets();
    connect();
    setInterval(() => {
      if (document.hidden) return;
      if (S.screen === 'targets') loadTargets();
    }, 30000);
    setInterval(() => { if (!document.hidden && S.screen === 'sky') loadSky(); }, 60000);
    setInterval(() => { if (S.screen === 'main' && !S.connected) drawTrend(true); }, 1000);
    let rt = 0;
    window.addEventListener('resize', () => { clearTimeout(rt); rt = setTimeout(() => { if (S.screen === 'main') drawTrend(true); if (S.screen === 'antenna') drawTilt(); }, 150); });
  }
  if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', start); else start();
})();
