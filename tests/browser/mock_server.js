#!/usr/bin/env node
// Mock of the azeltrack web API (docs/web-api.md) for looking at the console in a browser and for
// browser tests. Dependency-free: Node 18+ built-in modules only.
//
//   node tests/browser/mock_server.js [PORT]          (default 8080; password "azeltrack")
//
// It serves web/index.html, web/app.css and web/app.js (read on every request, so edits show on
// reload), the JSON API, and the state over a minimal RFC 6455 WebSocket at /ws (5 pushes a second).
// The sky is a low-precision model (Sun, Moon, the radio sources) that is good to a fraction of a
// degree; the simulated antenna moves toward its goal at 2 deg/s on each axis.
//
// Test helpers (not part of the real API):
//   POST /mock/fault {"reason": "..."}           latch a supervisor fault
//   POST /mock/ws-drop {"refuse_s": N}            close every WebSocket and refuse new ones N seconds
//   POST /mock/mode {"mode": "EXT", "who": "...", "az_deg", "el_deg"}   as if a PC program took over
//   POST /mock/dx {"grid": "JO65"}               set [sky] dx_grid (DX echo Doppler); "" clears it
//   GET  /mock/log                                the last 200 API requests (method, path, body, status)
'use strict';

const http = require('http');
const crypto = require('crypto');
const fs = require('fs');
const path = require('path');

const PORT = Number(process.argv[2] || process.env.PORT || 8080);
const PASSWORD = 'azeltrack';
const WEB_DIR = path.join(__dirname, '..', '..', 'web');
const SPEED_DEG_S = 2.0;
const BANDS = ['50', '70', '144', '222', '432', '902', '1296', '2304', '3400', '5760', '10368',
  '24048', '47088', '76032'];

// ---------------------------------------------------------------- sky (low precision) ----------
const D2R = Math.PI / 180;
const R2D = 180 / Math.PI;
const norm360 = (x) => ((x % 360) + 360) % 360;
const jdOf = (ms) => ms / 86400000 + 2440587.5;
const gmstDeg = (jd) => norm360(280.46061837 + 360.98564736629 * (jd - 2451545.0));
const C_KM_S = 299792.458;

const SOURCES = [
  // name, aliases, RA deg, Dec deg (J2000)
  ['Cassiopeia A', 'casa,cassiopeia,cas a,3c461', 350.85, 58.8150],
  ['Cygnus A', 'cyga,cygnus,cyg a,3c405', 299.8682, 40.7339],
  ['Taurus A', 'taua,taurus,tau a,crab,m1,3c144', 83.6331, 22.0145],
  ['Virgo A', 'vira,virgo,vir a,m87,3c274,leo', 187.7059, 12.3911],
  ['Sagittarius A', 'sgra,sagittarius,sgr a,sgr a*', 266.4167, -29.0078],
  ['Pictor A', 'pica,pictor,pic a', 79.9572, -45.7788],
  ['Orion A', 'oria,orion,ori a,m42', 83.8221, -5.3911],
  ['Hydra A', 'hyda,hydra,hyd a,3c218', 139.5235, -12.0955],
  ['Hercules A', 'hera,hercules,her a,3c348', 252.7839, 4.9926],
  ['Centaurus A', 'cena,centaurus,cen a,ngc5128', 201.365, -43.0192],
  ['M17', 'm17,omega nebula', 275.1963, -16.1717],
  ['3C 273', '3c273', 187.2779, 2.0524],
];

function refract(el) { // Bennett, degrees; enough for a mock
  if (el < -1.5) return el;
  return el + 0.0167 / Math.tan((el + 7.31 / (el + 4.4)) * D2R);
}

function observer(jd, st) {
  const lst = (gmstDeg(jd) + st.lon_deg) * D2R;
  const lat = st.lat_deg * D2R;
  const re = 6378.137 + st.alt_m / 1000;
  return { lst, lat, x: re * Math.cos(lat) * Math.cos(lst), y: re * Math.cos(lat) * Math.sin(lst),
    z: re * Math.sin(lat) };
}

function topo(v, jd, st) { // v: geocentric equatorial vector, km
  const o = observer(jd, st);
  const dx = v.x - o.x; const dy = v.y - o.y; const dz = v.z - o.z;
  const range = Math.hypot(dx, dy, dz);
  const ra = Math.atan2(dy, dx); const dec = Math.asin(dz / range);
  const ha = o.lst - ra;
  const sinEl = Math.sin(dec) * Math.sin(o.lat) + Math.cos(dec) * Math.cos(o.lat) * Math.cos(ha);
  const az = Math.atan2(-Math.cos(dec) * Math.sin(ha),
    Math.sin(dec) * Math.cos(o.lat) - Math.cos(dec) * Math.sin(o.lat) * Math.cos(ha));
  return { az: norm360(az * R2D), el: refract(Math.asin(sinEl) * R2D), range };
}

function radecVec(raDeg, decDeg, dist) {
  const ra = raDeg * D2R; const dec = decDeg * D2R;
  return { x: dist * Math.cos(dec) * Math.cos(ra), y: dist * Math.cos(dec) * Math.sin(ra),
    z: dist * Math.sin(dec) };
}

function sunVec(jd) {
  const d = jd - 2451545;
  const g = (357.529 + 0.98560028 * d) * D2R;
  const l = (280.459 + 0.98564736 * d + 1.915 * Math.sin(g) + 0.020 * Math.sin(2 * g)) * D2R;
  const e = (23.439 - 0.00000036 * d) * D2R;
  const r = 1.496e8;
  return { x: r * Math.cos(l), y: r * Math.cos(e) * Math.sin(l), z: r * Math.sin(e) * Math.sin(l) };
}

function moonVec(jd) {
  const t = (jd - 2451545) / 36525;
  const s = (a, b) => Math.sin((a + b * t) * D2R);
  const c = (a, b) => Math.cos((a + b * t) * D2R);
  const lam = 218.32 + 481267.881 * t + 6.29 * s(135.0, 477198.87) - 1.27 * s(259.3, -413335.36)
    + 0.66 * s(235.7, 890534.22) + 0.21 * s(269.9, 954397.74) - 0.19 * s(357.5, 35999.05)
    - 0.11 * s(186.5, 966404.03);
  const bet = 5.13 * s(93.3, 483202.03) + 0.28 * s(228.2, 960400.87) - 0.28 * s(318.3, 6003.18)
    - 0.17 * s(217.6, -407332.20);
  const par = 0.9508 + 0.0518 * c(135.0, 477198.87) + 0.0095 * c(259.3, -413335.38)
    + 0.0078 * c(235.7, 890534.23) + 0.0028 * c(269.9, 954397.70);
  const r = 6378.14 / Math.sin(par * D2R);
  const l = lam * D2R; const b = bet * D2R; const e = 23.4393 * D2R;
  return {
    x: r * Math.cos(b) * Math.cos(l),
    y: r * (Math.cos(e) * Math.cos(b) * Math.sin(l) - Math.sin(e) * Math.sin(b)),
    z: r * (Math.sin(e) * Math.cos(b) * Math.sin(l) + Math.cos(e) * Math.sin(b)),
  };
}

function gridToLatLon(g) {
  g = g.toUpperCase();
  let lonS = 20; let latS = 10;
  let lon = -180 + (g.charCodeAt(0) - 65) * lonS;
  let lat = -90 + (g.charCodeAt(1) - 65) * latS;
  for (let i = 2; i < g.length; i += 2) {
    if ((i / 2) % 2 === 1) {
      lonS /= 10; latS /= 10;
      lon += Number(g[i]) * lonS; lat += Number(g[i + 1]) * latS;
    } else {
      lonS /= 24; latS /= 24;
      lon += (g.charCodeAt(i) - 65) * lonS; lat += (g.charCodeAt(i + 1) - 65) * latS;
    }
  }
  return { lat: lat + latS / 2, lon: lon + lonS / 2 };
}

function latLonToGrid(lat, lon) {
  let x = Math.min(Math.max(lon + 180, 0), 359.999999);
  let y = Math.min(Math.max(lat + 90, 0), 179.999999);
  let s = String.fromCharCode(65 + Math.floor(x / 20), 65 + Math.floor(y / 10));
  x %= 20; y %= 10;
  s += String(Math.floor(x / 2)) + String(Math.floor(y));
  x %= 2; y %= 1;
  s += String.fromCharCode(65 + Math.floor(x * 12), 65 + Math.floor(y * 24));
  return s;
}

const GRID_RE = /^[A-R]{2}(?:[0-9]{2}(?:[A-X]{2}(?:[0-9]{2}(?:[A-X]{2})?)?)?)?$/i;

// ---------------------------------------------------------------- the simulated station --------
const cfg = {
  station: { grid: 'FN06HE', lat_deg: 46.189, lon_deg: -79.393, alt_m: 300.0 },
  band: '10368',
  dx_grid: '',
  control: { window_deg: 0.1, ramp_s: 1.0, tracking_speed: 0.5 },
  geometry: { az_min_deg: 0, az_max_deg: 360, el_min_deg: 0, el_max_deg: 90 },
  corrections: { az_offset_deg: 0.0, el_offset_deg: 0.0, az_user_deg: 0.0, el_user_deg: 0.0,
    tilt_el_deg: Array.from({ length: 60 }, (_, i) => Math.round(100 * 0.04 * Math.sin(i * 6 * D2R)) / 100) },
  park: [
    { slot: 1, name: 'park', az_deg: 180.0, el_deg: 0.0 },
    { slot: 2, name: 'stow', az_deg: 180.0, el_deg: 90.0 },
    { slot: 3, name: 'north', az_deg: 0.0, el_deg: 0.0 },
    { slot: 4, name: 'service', az_deg: 90.0, el_deg: 0.0 },
  ],
  servers: {
    rotctld: { bind: '127.0.0.1', port: 4533 },
    pstrotator: { bind: '127.0.0.1', port: 12000 },
    serial: [{ protocol: 'gs232b', device: 'pty:gs232b', baud: 9600 }],
    web: { bind: '127.0.0.1', port: PORT },
  },
  restart_needed: [],
};

const sim = {
  mode: 'TRACK',
  who: 'config',
  // goal: {kind: 'sun'|'moon'|'source'|'radec'|'park'|'man'|'ext', name, ra, dec, az, el}
  goal: { kind: 'moon', name: 'Moon' },
  rawAz: 150.0, rawEl: 20.0, // encoder position before offsets
  movingAz: false, movingEl: false,
  faults: [],
  wsRefuseUntil: 0,
};

function sourceByName(name) {
  const n = String(name).trim().toLowerCase();
  return SOURCES.find((s) => s[0].toLowerCase() === n || s[1].split(',').includes(n));
}

function goalPosition(goal, jd) {
  const st = cfg.station;
  switch (goal.kind) {
    case 'sun': return topo(sunVec(jd), jd, st);
    case 'moon': return topo(moonVec(jd), jd, st);
    case 'source': case 'radec': return topo(radecVec(goal.ra, goal.dec, 1e12), jd, st);
    default: return { az: goal.az, el: goal.el };
  }
}

function tiltAt(az) {
  const t = cfg.corrections.tilt_el_deg;
  const x = norm360(az) / 6; const i = Math.floor(x) % 60; const f = x - Math.floor(x);
  return t[i] * (1 - f) + t[(i + 1) % 60] * f;
}

function antennaReading() {
  const c = cfg.corrections;
  return { az: norm360(sim.rawAz + c.az_offset_deg), el: sim.rawEl + c.el_offset_deg };
}

function wrap180(x) { return ((x + 540) % 360) - 180; }

let lastTick = Date.now();
function tick() {
  const now = Date.now();
  const dt = Math.min(0.5, (now - lastTick) / 1000);
  lastTick = now;
  if (sim.mode === 'STOP' || sim.faults.length) { sim.movingAz = sim.movingEl = false; return; }
  const g = goalPosition(sim.goal, jdOf(now));
  const c = cfg.corrections; const geo = cfg.geometry;
  const user = sim.mode === 'TRACK';
  let gAz = norm360(g.az + (user ? c.az_user_deg : 0));
  let gEl = g.el + (user ? c.el_user_deg + tiltAt(g.az) : 0);
  gEl = Math.min(Math.max(gEl, geo.el_min_deg), geo.el_max_deg);
  const r = antennaReading();
  // az cannot cross north on a 0..360 rotator: travel in plain degrees
  const eAz = gAz - r.az; const eEl = gEl - r.el;
  const win = Math.max(cfg.control.window_deg, 0.01);
  if (Math.abs(eAz) > win) sim.movingAz = true;
  if (Math.abs(eEl) > win) sim.movingEl = true;
  const step = SPEED_DEG_S * dt;
  if (sim.movingAz) {
    const m = Math.sign(eAz) * Math.min(step, Math.abs(eAz));
    sim.rawAz += m;
    if (Math.abs(eAz - m) < 0.005) sim.movingAz = false;
  }
  if (sim.movingEl) {
    const m = Math.sign(eEl) * Math.min(step, Math.abs(eEl));
    sim.rawEl += m;
    if (Math.abs(eEl - m) < 0.005) sim.movingEl = false;
  }
}
setInterval(tick, 50);

function round(x, n) { const p = 10 ** n; return Math.round(x * p) / p; }

function moonReport(jd) {
  const st = cfg.station;
  const m = topo(moonVec(jd), jd, st);
  const dtJd = 1 / 86400;
  const rr = (topo(moonVec(jd + dtJd), jd + dtJd, st).range
    - topo(moonVec(jd - dtJd), jd - dtJd, st).range) / 2; // km/s
  const dop = {};
  for (const b of BANDS) dop[b] = Math.round(-2 * Number(b) * 1e6 * rr / C_KM_S);
  let dx = null;
  if (cfg.dx_grid) {
    const p = gridToLatLon(cfg.dx_grid);
    const dxSt = { lat_deg: p.lat, lon_deg: p.lon, alt_m: 0 };
    const rrDx = (topo(moonVec(jd + dtJd), jd + dtJd, dxSt).range
      - topo(moonVec(jd - dtJd), jd - dtJd, dxSt).range) / 2;
    dx = round(-Number(cfg.band) * 1e6 * (rr + rrDx) / C_KM_S, 1);
  }
  return {
    az_deg: round(m.az, 2), el_deg: round(m.el, 2), distance_km: round(m.range, 1),
    echo_delay_s: round(2 * m.range / C_KM_S, 4), band: cfg.band,
    echo_doppler_hz: round(-2 * Number(cfg.band) * 1e6 * rr / C_KM_S, 1),
    dx_echo_doppler_hz: dx, doppler_hz: dop,
  };
}

function goalName(goal) {
  if (goal.kind === 'man' || goal.kind === 'ext') return null;
  return goal.name;
}

function stateObject() {
  const now = Date.now(); const jd = jdOf(now);
  const g = goalPosition(sim.goal, jd);
  const r = antennaReading();
  const c = cfg.corrections;
  const sun = topo(sunVec(jd), jd, cfg.station);
  const user = sim.mode === 'TRACK';
  const cmdAz = norm360(g.az + (user ? c.az_user_deg : 0));
  const cmdEl = g.el + (user ? c.el_user_deg + tiltAt(g.az) : 0);
  return {
    utc: new Date(now).toISOString(),
    mode: sim.mode,
    who: sim.who,
    pc_locked_out: sim.mode === 'STOP' && sim.who === 'console',
    antenna: { known: true, az_deg: round(r.az, 2), el_deg: round(r.el, 2), az_mount_deg: round(r.az, 2),
      moving: sim.movingAz || sim.movingEl },
    target: { name: goalName(sim.goal), az_deg: round(g.az, 2), el_deg: round(g.el, 2) },
    error_deg: { az: round(wrap180(cmdAz - r.az), 2), el: round(cmdEl - r.el, 2) },
    moon: moonReport(jd),
    sun: { az_deg: round(sun.az, 2), el_deg: round(sun.el, 2) },
    corrections: { az_user_deg: c.az_user_deg, el_user_deg: c.el_user_deg,
      az_offset_deg: c.az_offset_deg, el_offset_deg: c.el_offset_deg },
    station: { ...cfg.station },
    clock: { source: 'system' },
    faults: sim.faults.slice(),
    station_io: {
      estop: { wired: false, input: false, latched: false },
      limits: null,
      sequencer: {
        wired: false, ptt: false, inhibited: false, transmitting: false, timed_out: false, hold: false,
        outputs: ['preamp', 'trx_relay', 'amplifier', 'radio'].map((name) => ({ name, on: false })),
      },
    },
    servers: { rotctld: '127.0.0.1:4533', web: `127.0.0.1:${PORT}` },
  };
}

function targetsObject() {
  const jd = jdOf(Date.now()); const st = cfg.station;
  const s = topo(sunVec(jd), jd, st); const m = topo(moonVec(jd), jd, st);
  const targets = [
    { name: 'Sun', kind: 'sun', az_deg: round(s.az, 2), el_deg: round(s.el, 2) },
    { name: 'Moon', kind: 'moon', az_deg: round(m.az, 2), el_deg: round(m.el, 2) },
  ];
  for (const src of SOURCES) {
    const p = topo(radecVec(src[2], src[3], 1e12), jd, st);
    targets.push({ name: src[0], kind: 'source', az_deg: round(p.az, 2), el_deg: round(p.el, 2) });
  }
  // One satellite, as the daemon lists a [satellites] file's entries (the mock does not track it).
  const aos = new Date(Date.now() + 20 * 60000).toISOString();
  const los = new Date(Date.now() + 30 * 60000).toISOString();
  const satellites = [{ name: 'ISS (ZARYA)', norad: '25544', element_age_days: 0.4, az_deg: 300.1, el_deg: -20.5,
    next_pass: { aos, los, max_el_deg: 41.2 },
    passes: [{ aos, tca: aos, los, max_el_deg: 41.2, aos_az_deg: 210, los_az_deg: 40 }] }];
  return { targets, satellites, park: cfg.park.map((p) => ({ ...p })), bands: BANDS.slice() };
}

function skyObject(hours) {
  const now = Date.now(); const st = cfg.station;
  const t = targetsObject().targets;
  const moonPath = []; const sunPath = [];
  for (let k = 0; k <= hours * 6; k++) {
    const ms = now + k * 600000; const jd = jdOf(ms);
    const utc = new Date(ms).toISOString();
    const m = topo(moonVec(jd), jd, st); const s = topo(sunVec(jd), jd, st);
    moonPath.push({ utc, az_deg: round(m.az, 2), el_deg: round(m.el, 2) });
    sunPath.push({ utc, az_deg: round(s.az, 2), el_deg: round(s.el, 2) });
  }
  return { now: t, moon_path: moonPath, sun_path: sunPath };
}

// ---------------------------------------------------------------- HTTP -------------------------
const sessions = new Map(); // sid -> {csrf}
const loginFailures = new Map(); // address -> [times]
const log = [];

function send(res, status, obj, extraHeaders) {
  const body = JSON.stringify(obj);
  res.writeHead(status, { 'Content-Type': 'application/json', 'Cache-Control': 'no-store',
    'Content-Length': Buffer.byteLength(body), ...(extraHeaders || {}) });
  res.end(body);
}

function cookies(req) {
  const out = {};
  for (const part of String(req.headers.cookie || '').split(';')) {
    const i = part.indexOf('=');
    if (i > 0) out[part.slice(0, i).trim()] = part.slice(i + 1).trim();
  }
  return out;
}

function session(req) {
  const sid = cookies(req).azt_session;
  return sid && sessions.has(sid) ? { sid, ...sessions.get(sid) } : null;
}

function originOk(req) {
  const o = req.headers.origin;
  return !o || o === `http://${req.headers.host}`;
}

// null when allowed, else [status, error]
function authError(req) {
  const auth = String(req.headers.authorization || '');
  if (auth.startsWith('Bearer ')) return auth.slice(7) === 'mock-token' ? null : [401, 'bad token'];
  if (!originOk(req)) return [403, 'cross-origin request refused'];
  const s = session(req);
  if (!s) return [401, 'login required'];
  if (req.headers['x-csrf-token'] !== s.csrf) return [403, 'bad or missing CSRF token'];
  return null;
}

function readBody(req) {
  return new Promise((resolve, reject) => {
    const chunks = []; let n = 0;
    req.on('data', (c) => {
      n += c.length;
      if (n > 65536) { reject(Object.assign(new Error('body too large'), { status: 413 })); req.destroy(); return; }
      chunks.push(c);
    });
    req.on('end', () => resolve(Buffer.concat(chunks).toString('utf8')));
    req.on('error', reject);
  });
}

class Bad extends Error {
  constructor(message, field, status) { super(message); this.field = field; this.status = status || 400; }
}

function num(body, key, min, max, label) {
  const v = body[key];
  if (typeof v !== 'number' || !Number.isFinite(v)) throw new Bad(`${label || key}: must be a number`, key);
  if (v < min || v > max) throw new Bad(`${label || key}: ${v} is outside ${min} … ${max}`, key);
  return v;
}

const STATIC = { '/': ['index.html', 'text/html; charset=utf-8'],
  '/app.css': ['app.css', 'text/css; charset=utf-8'],
  '/app.js': ['app.js', 'text/javascript; charset=utf-8'] };

function motionAllowed() {
  if (sim.faults.length) throw new Bad('refused: latched faults; clear them first', 'faults', 409);
}

async function handleApi(req, res, url, bodyText) {
  let body = {};
  if (bodyText.trim()) {
    try { body = JSON.parse(bodyText); } catch { throw new Bad('body: not JSON', 'body'); }
    if (typeof body !== 'object' || body === null || Array.isArray(body)) throw new Bad('body: not a JSON object', 'body');
  }
  const p = url.pathname; const m = req.method;
  const ok = (extra) => send(res, 200, { ok: true, ...(extra || {}) });

  if (p === '/api/login' && m === 'POST') {
    if (!originOk(req)) return send(res, 403, { error: 'cross-origin request refused' });
    const addr = req.socket.remoteAddress; const now = Date.now();
    const fails = (loginFailures.get(addr) || []).filter((t) => now - t < 60000);
    loginFailures.set(addr, fails);
    if (fails.length >= 3) {
      const wait = Math.ceil((60000 - (now - fails[0])) / 1000);
      return send(res, 429, { error: `too many failed logins; try again in ${wait} s` }, { 'Retry-After': String(wait) });
    }
    if (body.password !== PASSWORD) { fails.push(now); return send(res, 401, { error: 'wrong password' }); }
    const sid = crypto.randomBytes(24).toString('hex'); const csrf = crypto.randomBytes(16).toString('hex');
    sessions.set(sid, { csrf });
    return send(res, 200, { ok: true, csrf },
      { 'Set-Cookie': `azt_session=${sid}; HttpOnly; SameSite=Strict; Path=/` });
  }

  const a = authError(req);
  if (a) return send(res, a[0], { error: a[1] });

  if (p === '/api/logout' && m === 'POST') {
    const s = session(req); if (s) sessions.delete(s.sid);
    return send(res, 200, { ok: true }, { 'Set-Cookie': 'azt_session=; HttpOnly; SameSite=Strict; Path=/; Max-Age=0' });
  }
  if (p === '/api/target' && m === 'POST') {
    if ('name' in body) {
      if (typeof body.name !== 'string' || !body.name.trim()) throw new Bad('name: empty', 'name');
      const n = body.name.trim().toLowerCase();
      let goal;
      if (n === 'sun') goal = { kind: 'sun', name: 'Sun' };
      else if (n === 'moon') goal = { kind: 'moon', name: 'Moon' };
      else {
        const src = sourceByName(n);
        if (!src) throw new Bad(`name: unknown target "${body.name}"`, 'name');
        goal = { kind: 'source', name: src[0], ra: src[2], dec: src[3] };
      }
      motionAllowed();
      Object.assign(sim, { goal, mode: 'TRACK', who: 'console' });
      return ok({ mode: 'TRACK', target: goal.name });
    }
    if ('ra_deg' in body || 'dec_deg' in body) {
      const ra = num(body, 'ra_deg', 0, 360, 'ra_deg'); const dec = num(body, 'dec_deg', -90, 90, 'dec_deg');
      motionAllowed();
      Object.assign(sim, { goal: { kind: 'radec', name: `RA ${ra.toFixed(3)} Dec ${dec >= 0 ? '+' : ''}${dec.toFixed(3)}`, ra, dec },
        mode: 'TRACK', who: 'console' });
      return ok({ mode: 'TRACK', target: sim.goal.name });
    }
    if ('park' in body) {
      const slot = body.park;
      if (!Number.isInteger(slot) || slot < 1 || slot > 4) throw new Bad('park: slot must be 1..4', 'park');
      const pk = cfg.park[slot - 1];
      motionAllowed();
      Object.assign(sim, { goal: { kind: 'park', name: pk.name, az: pk.az_deg, el: pk.el_deg }, mode: 'PARK', who: 'console' });
      return ok();
    }
    if ('az_deg' in body || 'el_deg' in body) {
      const g = cfg.geometry;
      const az = num(body, 'az_deg', g.az_min_deg, g.az_max_deg, 'az_deg');
      const el = num(body, 'el_deg', g.el_min_deg, g.el_max_deg, 'el_deg');
      motionAllowed();
      Object.assign(sim, { goal: { kind: 'man', name: null, az, el }, mode: 'MAN', who: 'console' });
      return ok();
    }
    throw new Bad('body: expected name, ra_deg/dec_deg, park or az_deg/el_deg', 'body');
  }
  if (p === '/api/stop' && m === 'POST') {
    sim.mode = 'STOP'; sim.who = 'console';
    return ok();
  }
  if (p === '/api/correction' && m === 'POST') {
    const c = cfg.corrections;
    if (body.reset === true) { c.az_user_deg = 0; c.el_user_deg = 0; return ok({ corrections: { az_user_deg: 0, el_user_deg: 0 } }); }
    if (body.axis !== 'az' && body.axis !== 'el') throw new Bad('axis: must be "az" or "el"', 'axis');
    if (!Number.isInteger(body.steps) || Math.abs(body.steps) > 1000) throw new Bad('steps: must be an integer -1000 … 1000', 'steps');
    const key = `${body.axis}_user_deg`;
    const v = round(c[key] + body.steps * 0.01, 2);
    if (Math.abs(v) > 10) throw new Bad(`${key}: ${v} is outside -10 … 10`, 'steps');
    c[key] = v;
    return ok({ corrections: { az_user_deg: c.az_user_deg, el_user_deg: c.el_user_deg } });
  }
  if (p === '/api/faults/clear' && m === 'POST') { sim.faults = []; return ok(); }

  if (p === '/api/config/station' && m === 'PUT') {
    if ('grid' in body) {
      const gr = String(body.grid || '').trim();
      if (typeof body.grid !== 'string' || gr.length < 4 || gr.length > 10 || gr.length % 2 || !GRID_RE.test(gr)) {
        throw new Bad(`grid: "${body.grid}" is not a Maidenhead locator (4–10 characters, like FN06HE)`, 'grid');
      }
      const ll = gridToLatLon(gr);
      const g = gr.slice(0, 2).toUpperCase() + gr.slice(2, 4) + gr.slice(4, 6).toLowerCase() + gr.slice(6);
      cfg.station = { ...cfg.station, grid: g, lat_deg: round(ll.lat, 6), lon_deg: round(ll.lon, 6) };
      return ok({ station: cfg.station });
    }
    const lat = num(body, 'lat_deg', -90, 90); const lon = num(body, 'lon_deg', -180, 180);
    const alt = 'alt_m' in body ? num(body, 'alt_m', -500, 9000) : cfg.station.alt_m;
    cfg.station = { grid: latLonToGrid(lat, lon), lat_deg: lat, lon_deg: lon, alt_m: alt };
    return ok({ station: cfg.station });
  }
  if (p === '/api/config/band' && m === 'PUT') {
    if (!BANDS.includes(String(body.band))) throw new Bad(`band: "${body.band}" is not one of ${BANDS.join(' ')}`, 'band');
    cfg.band = String(body.band);
    return ok();
  }
  if (p === '/api/config/offsets' && m === 'PUT') {
    const az = 'az_offset_deg' in body ? num(body, 'az_offset_deg', -360, 360) : cfg.corrections.az_offset_deg;
    const el = 'el_offset_deg' in body ? num(body, 'el_offset_deg', -180, 180) : cfg.corrections.el_offset_deg;
    cfg.corrections.az_offset_deg = az; cfg.corrections.el_offset_deg = el;
    return ok();
  }
  if (p === '/api/config/tilt' && m === 'PUT') {
    if ('tilt_el_deg' in body) {
      const t = body.tilt_el_deg;
      if (!Array.isArray(t) || t.length !== 60) throw new Bad('tilt_el_deg: must be 60 numbers', 'tilt_el_deg');
      t.forEach((v, i) => {
        if (typeof v !== 'number' || !Number.isFinite(v) || Math.abs(v) > 5) throw new Bad(`tilt_el_deg[${i}]: must be a number -5 … 5`, 'tilt_el_deg');
      });
      cfg.corrections.tilt_el_deg = t.slice();
      return ok();
    }
    const i = body.index;
    if (!Number.isInteger(i) || i < 0 || i > 59) throw new Bad('index: must be 0 … 59', 'index');
    const v = num(body, 'value', -5, 5, `tilt_el_deg[${i}] (az ${i * 6}°)`);
    cfg.corrections.tilt_el_deg[i] = v;
    return ok();
  }
  if (p === '/api/config/park' && m === 'PUT') {
    const slot = body.slot;
    if (!Number.isInteger(slot) || slot < 1 || slot > 4) throw new Bad('slot: must be 1 … 4', 'slot');
    const cur = cfg.park[slot - 1];
    const name = 'name' in body ? body.name : cur.name;
    if (typeof name !== 'string' || !name.trim() || name.length > 32) throw new Bad('name: 1 to 32 characters', 'name');
    const az = 'az_deg' in body ? num(body, 'az_deg', 0, 360) : cur.az_deg;
    const el = 'el_deg' in body ? num(body, 'el_deg', cfg.geometry.el_min_deg, cfg.geometry.el_max_deg) : cur.el_deg;
    cfg.park[slot - 1] = { slot, name: name.trim(), az_deg: az, el_deg: el };
    return ok();
  }
  if (p === '/api/config/control' && m === 'PUT') {
    const limits = { window_deg: [0, 2], ramp_s: [0, 10], tracking_speed: [0.05, 1] };
    const keys = Object.keys(body);
    if (!keys.length) throw new Bad('body: nothing to change', 'body');
    const next = {};
    for (const k of keys) {
      if (!limits[k]) throw new Bad(`${k}: unknown setting`, k);
      next[k] = num(body, k, limits[k][0], limits[k][1], `control.${k}`);
    }
    for (const k of keys) {
      if (next[k] !== cfg.control[k] && !cfg.restart_needed.includes(`control.${k}`)) cfg.restart_needed.push(`control.${k}`);
      cfg.control[k] = next[k];
    }
    return ok({ restart_needed: cfg.restart_needed.slice() });
  }
  if (p.startsWith('/api/')) {
    const known = ['/api/logout', '/api/target', '/api/stop', '/api/correction', '/api/faults/clear',
      '/api/config/station', '/api/config/band', '/api/config/offsets', '/api/config/tilt',
      '/api/config/park', '/api/config/control'];
    if (known.includes(p)) return send(res, 405, { error: 'method not allowed' });
  }
  return send(res, 404, { error: 'not found' });
}

function handleMock(req, res, url, body) {
  let b = {};
  try { b = body ? JSON.parse(body) : {}; } catch { /* ignore */ }
  if (url.pathname === '/mock/fault' && req.method === 'POST') {
    sim.faults.push(String(b.reason || 'el: stall: driven for 2 s but moved less than 0.5 deg'));
    return send(res, 200, { ok: true });
  }
  if (url.pathname === '/mock/ws-drop' && req.method === 'POST') {
    sim.wsRefuseUntil = Date.now() + 1000 * Number(b.refuse_s || 0);
    for (const c of wsClients) c.destroy();
    wsClients.clear();
    return send(res, 200, { ok: true });
  }
  if (url.pathname === '/mock/mode' && req.method === 'POST') {
    sim.mode = String(b.mode || 'EXT'); sim.who = String(b.who || 'rotctld 127.0.0.1:50412');
    if (typeof b.az_deg === 'number') sim.goal = { kind: 'ext', name: null, az: b.az_deg, el: b.el_deg || 0 };
    return send(res, 200, { ok: true });
  }
  if (url.pathname === '/mock/dx' && req.method === 'POST') {
    const g = String(b.grid || '');
    if (g && !GRID_RE.test(g)) return send(res, 400, { error: 'grid: not a locator', field: 'grid' });
    cfg.dx_grid = g;
    return send(res, 200, { ok: true });
  }
  if (url.pathname === '/mock/log' && req.method === 'GET') return send(res, 200, { requests: log });
  return send(res, 404, { error: 'not found' });
}

const server = http.createServer(async (req, res) => {
  const url = new URL(req.url, 'http://localhost');
  try {
    if (req.method === 'GET' && STATIC[url.pathname]) {
      const [file, type] = STATIC[url.pathname];
      fs.readFile(path.join(WEB_DIR, file), (err, data) => {
        if (err) { send(res, 404, { error: `${file} not found` }); return; }
        res.writeHead(200, { 'Content-Type': type, 'Cache-Control': 'no-store' });
        res.end(data);
      });
      return;
    }
    if (req.method === 'GET') {
      switch (url.pathname) {
        case '/api/state': return send(res, 200, stateObject());
        case '/api/config': return send(res, 200, cfg);
        case '/api/targets': return send(res, 200, targetsObject());
        case '/api/sky': {
          const h = url.searchParams.has('hours') ? Number(url.searchParams.get('hours')) : 12;
          if (!Number.isFinite(h) || h <= 0 || h > 24) return send(res, 400, { error: 'hours: 0 < hours ≤ 24', field: 'hours' });
          return send(res, 200, skyObject(h));
        }
        case '/api/session': {
          const s = session(req);
          return send(res, 200, s ? { logged_in: true, csrf: s.csrf } : { logged_in: false });
        }
        case '/mock/log': return handleMock(req, res, url, '');
        default:
          if (url.pathname.startsWith('/api/')) return send(res, 405, { error: 'method not allowed' });
          return send(res, 404, { error: 'not found' });
      }
    }
    const body = await readBody(req);
    if (url.pathname.startsWith('/mock/')) return handleMock(req, res, url, body);
    const entry = { t: new Date().toISOString(), method: req.method, path: url.pathname, body, status: 0 };
    log.push(entry); if (log.length > 200) log.shift();
    res.on('finish', () => { entry.status = res.statusCode; });
    await handleApi(req, res, url, body);
  } catch (e) {
    if (res.headersSent) return;
    if (e instanceof Bad) return send(res, e.status, { error: e.message, field: e.field });
    if (e.status === 413) return send(res, 413, { error: 'body too large (64 KiB at most)' });
    console.error(e);
    send(res, 500, { error: String(e.message || e) });
  }
});

// ---------------------------------------------------------------- WebSocket (RFC 6455) ---------
const wsClients = new Set();

function wsFrame(opcode, payload) {
  const len = payload.length;
  let head;
  if (len < 126) { head = Buffer.alloc(2); head[1] = len; } else if (len < 65536) {
    head = Buffer.alloc(4); head[1] = 126; head.writeUInt16BE(len, 2);
  } else { head = Buffer.alloc(10); head[1] = 127; head.writeBigUInt64BE(BigInt(len), 2); }
  head[0] = 0x80 | opcode;
  return Buffer.concat([head, payload]);
}

server.on('upgrade', (req, socket) => {
  const url = new URL(req.url, 'http://localhost');
  const key = req.headers['sec-websocket-key'];
  if (url.pathname !== '/ws' || !key || String(req.headers.upgrade).toLowerCase() !== 'websocket') {
    socket.end('HTTP/1.1 400 Bad Request\r\nConnection: close\r\n\r\n'); return;
  }
  if (Date.now() < sim.wsRefuseUntil) {
    socket.end('HTTP/1.1 503 Service Unavailable\r\nConnection: close\r\n\r\n'); return;
  }
  const accept = crypto.createHash('sha1').update(`${key}258EAFA5-E914-47DA-95CA-C5AB0DC85B11`).digest('base64');
  socket.write('HTTP/1.1 101 Switching Protocols\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n'
    + `Sec-WebSocket-Accept: ${accept}\r\n\r\n`);
  socket.setNoDelay(true);
  wsClients.add(socket);
  let buf = Buffer.alloc(0);
  socket.on('data', (chunk) => {
    buf = Buffer.concat([buf, chunk]);
    for (;;) {
      if (buf.length < 2) return;
      const opcode = buf[0] & 0x0f; const masked = (buf[1] & 0x80) !== 0;
      let len = buf[1] & 0x7f; let off = 2;
      if (len === 126) { if (buf.length < 4) return; len = buf.readUInt16BE(2); off = 4; } else if (len === 127) {
        if (buf.length < 10) return; len = Number(buf.readBigUInt64BE(2)); off = 10;
      }
      if (len > 65536) { socket.destroy(); return; }
      const maskOff = off; if (masked) off += 4;
      if (buf.length < off + len) return;
      const payload = Buffer.from(buf.subarray(off, off + len));
      if (masked) for (let i = 0; i < len; i++) payload[i] ^= buf[maskOff + (i & 3)];
      buf = buf.subarray(off + len);
      if (opcode === 0x8) { // close: echo and end
        try { socket.end(wsFrame(0x8, payload.subarray(0, 2))); } catch { /* gone */ }
        wsClients.delete(socket); return;
      }
      if (opcode === 0x9) socket.write(wsFrame(0xA, payload)); // ping -> pong
      // text/binary/pong from the client: ignored
    }
  });
  const drop = () => wsClients.delete(socket);
  socket.on('close', drop); socket.on('error', drop);
  socket.write(wsFrame(0x1, Buffer.from(JSON.stringify(stateObject()))));
});

setInterval(() => {
  if (!wsClients.size) return;
  const frame = wsFrame(0x1, Buffer.from(JSON.stringify(stateObject())));
  for (const s of wsClients) { if (!s.destroyed) s.write(frame); }
}, 200);

server.listen(PORT, () => {
  console.log(`azeltrack mock: http://127.0.0.1:${PORT}/  (password "${PASSWORD}")`);
});
