// What the browser tests (console_test.js, panel_test.js) share: the command line, a real
// `azeltrack serve` in a temporary directory and its HTTP API, polling, Debian's Chromium (with
// AZT_WEB_DIR's files in place of the daemon's copy), the scenarios' results and the exit status.
// One test runs per process, so the harness holds its one daemon, address and list of results.
'use strict';
const { chromium } = require('playwright-core');
const { spawn, spawnSync } = require('child_process');
const fs = require('fs');
const net = require('net');
const os = require('os');
const path = require('path');

let bin = '';
let tmp = '';
let config = '';
let base = '';
let daemon = null;
const results = [];
// The sizes every page is seen at (docs/web-api.md): a desktop and a phone.
const DESKTOP = { width: 1280, height: 800 };
const PHONE = { width: 390, height: 844 };

/// Reads `node SCRIPT AZELTRACK OUT_DIR`, makes OUT_DIR and a temporary directory (TMP_PREFIX…)
/// for the daemon's settings and log.
function setup(script, tmpPrefix) {
  const [program, outDir] = process.argv.slice(2);
  if (!program || !outDir) {
    console.error(`usage: node ${script} AZELTRACK OUT_DIR`);
    process.exit(2);
  }
  fs.mkdirSync(outDir, { recursive: true });
  bin = program;
  tmp = fs.mkdtempSync(path.join(os.tmpdir(), tmpPrefix));
  config = path.join(tmp, 'azeltrack.toml');
  return { bin, outDir, tmp, config };
}

const freePort = () => new Promise((resolve, reject) => {
  const s = net.createServer();
  s.once('error', reject);
  s.listen(0, '127.0.0.1', () => { const p = s.address().port; s.close(() => resolve(p)); });
});
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

/// Polls `probe` (an async function returning a truthy value when done) until `ms` pass.
async function until(what, probe, ms = 10000, every = 100) {
  const end = Date.now() + ms;
  let last;
  while (Date.now() < end) {
    try { last = await probe(); if (last) return last; } catch (e) { last = e.message; }
    await sleep(every);
  }
  throw new Error(`timed out after ${ms} ms waiting for ${what} (last: ${JSON.stringify(last)})`);
}

/// The daemon's address once its [web] port is chosen: what api() and the browser talk to.
function useWebPort(port) {
  base = `http://127.0.0.1:${port}`;
  return base;
}

async function api(method, route, body, token) {
  const headers = { 'Content-Type': 'application/json' };
  if (token) headers.Authorization = `Bearer ${token}`;
  const res = await fetch(base + route, { method, headers, body: body ? JSON.stringify(body) : undefined });
  return { status: res.status, json: await res.json().catch(() => null) };
}
const state = async () => (await api('GET', '/api/state')).json;

/// The settings both tests start from: the simulated antenna with 16-bit encoders and no movement
/// window, so that 0.01° steps are visible, and a fast plant; tracking `target` from the start; the
/// console on `port`. The [web] section comes last, so that a test can add its own keys to it.
function simConfig(target, port) {
  return `schema_version = 2
[station]
grid = "FN06HE"
alt_m = 300.0
[control]
window_deg = 0.0
[target]
name = "${target}"
[mount.az]
max_rate_deg_s = 10.0
encoder_bits = 16
time_constant_s = 0.1
[mount.el]
max_rate_deg_s = 10.0
encoder_bits = 16
time_constant_s = 0.1
[sim.az]
start_deg = 180.0
[sim.el]
start_deg = 20.0
[rotctld]
port = 0
[pstrotator]
port = 0
[web]
port = ${port}
`;
}

/// An ISS element set (or one under NORAD and NAME, its orbit turned to RAAN_DEG) whose epoch is
/// now, so that its next pass is within hours.
function tleWithEpochNow(norad = '25544', name = 'ISS (ZARYA)', raanDeg = 247.4627) {
  const checksum = (l) => l.slice(0, 68) + String([...l.slice(0, 68)].reduce((a, c) =>
    a + (c >= '0' && c <= '9' ? Number(c) : c === '-' ? 1 : 0), 0) % 10);
  const now = new Date();
  const day = (now - Date.UTC(now.getUTCFullYear(), 0, 1)) / 86400000 + 1;
  const epoch = `${String(now.getUTCFullYear() % 100).padStart(2, '0')}${day.toFixed(8).padStart(12, '0')}`;
  const l1 = `1 ${norad}U 98067A   ${epoch}  .00016717  00000-0  30119-3 0  999`;
  const l2 = `2 ${norad}  51.6416 ${raanDeg.toFixed(4).padStart(8, ' ')} 0006703 130.5360 325.0288 15.49815488441110`;
  return `${name}\n${checksum(l1)}\n${checksum(l2)}\n`;
}

/// Sets the console's password in the settings as an operator does, by the program itself.
function setPassword(password) {
  const r = spawnSync(bin, ['web', 'password', '--config', config], { input: `${password}\n` });
  if (r.status !== 0) throw new Error(`web password: ${r.stderr}`);
}

// The log is appended to, so that it covers every restart a test makes; `args` are more of
// serve's options (the software test's --update-inbox).
async function startDaemon(args = []) {
  const log = fs.openSync(path.join(tmp, 'daemon.log'), 'a');
  daemon = spawn(bin, ['serve', '--config', config, ...args], { stdio: ['ignore', log, log] });
  // Served once the position is known, or once an axis says why it is not (a pulse-counted axis
  // waiting to be homed: antenna.axes).
  await until('the daemon to serve /api/state', async () => {
    const s = await state();
    return s && s.antenna && (s.antenna.known || s.antenna.axes !== undefined);
  });
}
async function stopDaemon() {
  if (!daemon) return;
  const d = daemon;
  daemon = null;
  const exited = new Promise((r) => d.once('exit', r));
  d.kill('SIGTERM');
  await exited;
}

/// Thrown by a scenario that cannot run here (skip()): recorded as skipped with its reason,
/// neither passed nor failed.
class Skipped extends Error {}
function skip(reason) { throw new Skipped(reason); }

/// Runs one scenario and records its result; a failure is reported and the next one runs.
async function scenario(name, body) {
  const started = Date.now();
  try {
    await body();
    results.push({ name, ok: true });
    console.log(`ok   ${name} (${Date.now() - started} ms)`);
  } catch (e) {
    if (e instanceof Skipped) {
      results.push({ name, ok: true, skipped: e.message });
      console.log(`skip ${name}: ${e.message}`);
      return;
    }
    results.push({ name, ok: false, error: e.message });
    console.log(`FAIL ${name}: ${e.message}`);
  }
}

/// A scenario, then what it left on screen at desktop and at phone size in OUT_DIR, passed or not.
async function scenarioWithShots(name, page, outDir, body) {
  await scenario(name, body);
  const slug = name.replace(/[^a-z0-9]+/gi, '-').toLowerCase().replace(/-+$/, '');
  for (const [size, vp] of [['desktop', DESKTOP], ['phone', PHONE]]) {
    try {
      await page.setViewportSize(vp);
      await sleep(150);
      await page.screenshot({ path: path.join(outDir, `${slug}-${size}.png`), fullPage: true });
    } catch (e) { console.log(`     (screenshot ${size}: ${e.message})`); }
  }
  await page.setViewportSize(DESKTOP);
}

const loggedIn = (page) => page.evaluate(async () => (await (await fetch('/api/session')).json()).logged_in);
async function text(page, sel) { return (await page.textContent(sel) || '').trim(); }

// Serves web/ from disk in place of the daemon's built-in copy (AZT_WEB_DIR): `pages` maps the
// page's own paths to its files; the modules under js/, the page fragments under pages/ and the
// style sheets under css/ (the pages loaded when first opened) are common to every page. Each file goes
// with the daemon's Content-Security-Policy, so that a violation shows here as it would there.
async function serveWebDir(ctx, dir, pages) {
  const types = { '.html': 'text/html; charset=utf-8', '.css': 'text/css; charset=utf-8', '.js': 'text/javascript; charset=utf-8' };
  const csp = (await fetch(base + '/')).headers.get('content-security-policy');
  if (!csp) throw new Error('the daemon sent no Content-Security-Policy');
  await ctx.route(`${base}/**`, (route) => {
    const p = new URL(route.request().url()).pathname;
    const file = pages[p] || (/^\/(js\/[a-z_]+\.js|pages\/[a-z_]+\.html|css\/[a-z_]+\.css)$/.test(p) ? p.slice(1) : null);
    if (!file) return route.continue();
    return route.fulfill({ status: 200, contentType: types[path.extname(file)], headers: { 'Content-Security-Policy': csp },
      body: fs.readFileSync(path.join(dir, file)) });
  });
}

/// Debian's Chromium (CHROMIUM to use another) in a profile of its own, with `options` (the
/// viewport, touch) for the page; the page's uncaught errors are kept in `errors`.
async function launch(pages, options) {
  const userDataDir = fs.mkdtempSync(path.join(os.tmpdir(), 'azt-chromium-'));
  const ctx = await chromium.launchPersistentContext(userDataDir, {
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    headless: true,
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync',
      '--disable-dev-shm-usage',
      // a page fulfilled by the test (AZT_WEB_DIR) counts as public: let it reach the daemon
      ...(process.env.AZT_WEB_DIR ? ['--disable-features=LocalNetworkAccessChecks'] : [])],
    ...options,
  });
  if (process.env.AZT_WEB_DIR) await serveWebDir(ctx, path.resolve(process.env.AZT_WEB_DIR), pages);
  const page = ctx.pages()[0] || await ctx.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  // Console errors too, Content-Security-Policy violations among them ("Refused to apply inline
  // style…"); a request the daemon answered with an error status is the test's own doing, and
  // so is a live connection refused while a test restarts the daemon (the page retries it).
  page.on('console', (m) => {
    if (m.type() === 'error' && !/^Failed to load resource|^WebSocket connection to .* failed: .*ERR_CONNECTION_REFUSED/.test(m.text())) errors.push(`console: ${m.text()}`);
  });
  return { ctx, page, errors, userDataDir };
}

/// What the page weighs: `first` (its HTML) and every script and style sheet it loaded, each
/// counted once, fetched again by the page for its size uncompressed (so that AZT_WEB_DIR's files
/// are the ones measured).
async function pageWeight(page, first) {
  return page.evaluate(async (html) => {
    const files = performance.getEntriesByType('resource')
      .map((e) => new URL(e.name).pathname).filter((p) => p.endsWith('.js') || p.endsWith('.css'));
    const all = [html, ...new Set(files)];
    let bytes = 0;
    for (const f of all) bytes += (await (await fetch(f, { cache: 'no-store' })).arrayBuffer()).byteLength;
    return { bytes, all };
  }, first);
}

// An uncaught error on the page fails the test even when every scenario passed.
function checkPageErrors(errors) {
  if (!errors.length) return;
  results.push({ name: 'no JavaScript errors', ok: false, error: errors.join('; ') });
  console.log(`FAIL no JavaScript errors: ${errors.join('; ')}`);
}

/// Closes the browser and stops the daemon (for the test's `finally`).
async function shutDown(browser) {
  await browser.ctx.close();
  await stopDaemon();
  fs.rmSync(browser.userDataDir, { recursive: true, force: true });
}

/// The count and the exit status ctest reads; on a failure the daemon's last words, to see why.
function summarise() {
  const failed = results.filter((r) => !r.ok).length;
  const skipped = results.filter((r) => r.skipped).length;
  if (failed) console.log(fs.readFileSync(path.join(tmp, 'daemon.log'), 'utf8').split('\n').slice(-20).join('\n'));
  fs.rmSync(tmp, { recursive: true, force: true });
  console.log(`${results.length - failed - skipped} passed, ${failed} failed${skipped ? `, ${skipped} skipped` : ''}`);
  process.exit(failed ? 1 : 0);
}

/// Runs the test's main: a throw outside any scenario fails the test, with `cleanUp` run and the
/// daemon stopped so that neither outlives it.
function run(main, cleanUp = () => {}) {
  main().catch(async (e) => {
    console.error(e);
    cleanUp();
    await stopDaemon().catch(() => {});
    process.exit(1);
  });
}

module.exports = {
  DESKTOP, PHONE,
  setup, tleWithEpochNow, freePort, sleep, until, useWebPort, api, state, simConfig, setPassword, startDaemon,
  stopDaemon, scenario, scenarioWithShots, skip, loggedIn, text, launch, pageWeight, checkPageErrors, shutDown, summarise, run,
};
