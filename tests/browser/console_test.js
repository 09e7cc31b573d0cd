// Browser tests of the web console (issue 5 §3): Debian's Chromium driven by playwright-core
// against a real `azeltrack serve` on the simulated antenna. Each scenario checks what a user sees
// and what the daemon did; screenshots at desktop and phone sizes go to OUT_DIR.
// Usage: node console_test.js AZELTRACK OUT_DIR
'use strict';
const { chromium } = require('playwright-core');
const { spawn, spawnSync } = require('child_process');
const fs = require('fs');
const net = require('net');
const os = require('os');
const path = require('path');

const [bin, outDir] = process.argv.slice(2);
if (!bin || !outDir) {
  console.error('usage: node console_test.js AZELTRACK OUT_DIR');
  process.exit(2);
}
fs.mkdirSync(outDir, { recursive: true });
const PASSWORD = 'browser-test-password';
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'azt-browser-'));
const config = path.join(tmp, 'azeltrack.toml');
let daemon = null;
let port = 0;
let base = '';

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

async function api(method, route, body, token) {
  const headers = { 'Content-Type': 'application/json' };
  if (token) headers.Authorization = `Bearer ${token}`;
  const res = await fetch(base + route, { method, headers, body: body ? JSON.stringify(body) : undefined });
  return { status: res.status, json: await res.json().catch(() => null) };
}
const state = async () => (await api('GET', '/api/state')).json;

async function startDaemon() {
  const log = fs.openSync(path.join(tmp, 'daemon.log'), 'a');
  daemon = spawn(bin, ['serve', '--config', config], { stdio: ['ignore', log, log] });
  await until('the daemon to serve /api/state', async () => {
    const s = await state();
    return s && s.antenna && s.antenna.known;
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

// An ISS element set whose epoch is now, so that its next pass is within hours (issue 7).
function tleWithEpochNow() {
  const checksum = (l) => l.slice(0, 68) + String([...l.slice(0, 68)].reduce((a, c) =>
    a + (c >= '0' && c <= '9' ? Number(c) : c === '-' ? 1 : 0), 0) % 10);
  const now = new Date();
  const day = (now - Date.UTC(now.getUTCFullYear(), 0, 1)) / 86400000 + 1;
  const epoch = `${String(now.getUTCFullYear() % 100).padStart(2, '0')}${day.toFixed(8).padStart(12, '0')}`;
  const l1 = `1 25544U 98067A   ${epoch}  .00016717  00000-0  30119-3 0  999`;
  const l2 = '2 25544  51.6416 247.4627 0006703 130.5360 325.0288 15.49815488441110';
  return `ISS (ZARYA)\n${checksum(l1)}\n${checksum(l2)}\n`;
}

function writeConfig() {
  // 16-bit encoders and no movement window, so 0.01° steps are visible; a fast plant.
  fs.writeFileSync(config, `schema_version = 2
[station]
grid = "FN06HE"
alt_m = 300.0
[control]
window_deg = 0.0
[target]
name = "stop"
[mount.az]
max_rate_deg_s = 10.0
encoder_bits = 16
[mount.el]
max_rate_deg_s = 10.0
encoder_bits = 16
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
[satellites]
file = "sats.tle"
`);
  fs.writeFileSync(path.join(path.dirname(config), 'sats.tle'), tleWithEpochNow());
  const r = spawnSync(bin, ['web', 'password', '--config', config], { input: `${PASSWORD}\n` });
  if (r.status !== 0) throw new Error(`web password: ${r.stderr}`);
}

const results = [];
async function scenario(name, page, body) {
  const started = Date.now();
  try {
    await body();
    results.push({ name, ok: true });
    console.log(`ok   ${name} (${Date.now() - started} ms)`);
  } catch (e) {
    results.push({ name, ok: false, error: e.message });
    console.log(`FAIL ${name}: ${e.message}`);
  }
  const slug = name.replace(/[^a-z0-9]+/gi, '-').toLowerCase();
  for (const [size, vp] of [['desktop', { width: 1280, height: 800 }], ['phone', { width: 375, height: 740 }]]) {
    try {
      await page.setViewportSize(vp);
      await sleep(150);
      await page.screenshot({ path: path.join(outDir, `${slug}-${size}.png`), fullPage: true });
    } catch (e) { console.log(`     (screenshot ${size}: ${e.message})`); }
  }
  await page.setViewportSize({ width: 1280, height: 800 });
}

async function login(page) {
  await page.click('#nav-main').catch(() => {});
  if (!(await page.isVisible('#password'))) await page.click('#login-state');
  await page.fill('#password', PASSWORD);
  await page.click('#login-btn');
  await until('the session', () => page.evaluate(async () => (await (await fetch('/api/session')).json()).logged_in));
}

async function text(page, sel) { return (await page.textContent(sel) || '').trim(); }

async function main() {
  port = await freePort();
  base = `http://127.0.0.1:${port}`;
  writeConfig();
  await startDaemon();
  const userDataDir = fs.mkdtempSync(path.join(os.tmpdir(), 'azt-chromium-'));
  const ctx = await chromium.launchPersistentContext(userDataDir, {
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    headless: true,
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync',
      '--disable-dev-shm-usage'],
    viewport: { width: 1280, height: 800 },
  });
  const page = ctx.pages()[0] || await ctx.newPage();
  const consoleErrors = [];
  page.on('pageerror', (e) => consoleErrors.push(e.message));
  try {
    await page.goto(base + '/', { waitUntil: 'load' });
    await until('live numbers', async () => /\d/.test(await text(page, '#ant-az')));

    await scenario('actions are refused without login', page, async () => {
      const before = (await state()).mode;
      await page.click('#btn-stop');
      await until('the login form', () => page.isVisible('#password'), 3000);
      const direct = await page.evaluate(async () => (await fetch('/api/stop', { method: 'POST' })).status);
      if (direct !== 401) throw new Error(`POST /api/stop without login answered ${direct}`);
      const after = (await state()).mode;
      if (after !== before) throw new Error(`mode changed from ${before} to ${after}`);
    });

    await scenario('login and the antenna moves on screen while tracking', page, async () => {
      await login(page);
      const targets = (await api('GET', '/api/targets')).json.targets;
      const up = targets.filter((t) => t.kind === 'source' && t.el_deg > 25 && t.el_deg < 80)
        .sort((a, b) => b.el_deg - a.el_deg)[0];
      if (!up) throw new Error('no radio source between 25° and 80° of elevation right now');
      await page.click('#nav-targets');
      await page.click(`[data-name="${up.name}"]`);
      await until(`TRACK ${up.name}`, async () => (await text(page, '#mode')).includes('TRACK'));
      const first = await text(page, '#ant-az') + ' ' + await text(page, '#ant-el');
      await page.click('#nav-main');
      await until('the antenna numbers to change', async () =>
        (await text(page, '#ant-az') + ' ' + await text(page, '#ant-el')) !== first, 8000);
      const s = await state();
      if (s.target.name !== up.name) throw new Error(`daemon target is ${s.target.name}`);
    });

    await scenario('choosing the Moon changes the target', page, async () => {
      await page.click('#nav-targets');
      await page.click('#tgt-moon');
      await page.click('#nav-main');
      await until('Moon on screen', async () => (await text(page, '#target-name')).includes('Moon'), 3000);
      const s = await state();
      if (s.target.name !== 'Moon' || s.mode !== 'TRACK') throw new Error(`daemon: ${s.mode} ${s.target.name}`);
      // Who moved the antenna (issue 13 §1): the console's choice, with its address.
      await until('the command in the list', async () =>
        (await text(page, '#command-list')).includes('console 127.0.0.1: track Moon'), 3000);
    });

    await scenario('the station I/O panel shows the T/R chain and what is wired', page, async () => {
      await page.click('#nav-main');
      await until('the T/R chain', async () => (await text(page, '#io-seq')).includes('amplifier'), 3000);
      const io = (await state()).station_io;
      const names = io.sequencer.outputs.map((o) => o.name).join(',');
      if (names !== 'preamp,trx_relay,amplifier,radio') throw new Error(`sequencer outputs: ${names}`);
      if (io.sequencer.outputs.some((o) => o.on)) throw new Error('an output is keyed with no PTT');
      if ((await text(page, '#io-estop')) !== 'not wired') throw new Error(`E-stop: ${await text(page, '#io-estop')}`);
      if ((await page.$$('#io-seq .out.on')).length !== 0) throw new Error('an output is lit');
    });

    await scenario('a satellite is listed with its next pass, and tracking it plots the pass', page, async () => {
      await page.click('#nav-targets');
      await until('the satellite button', () => page.isVisible('#satellites button[data-norad="25544"]'), 5000);
      const label = await text(page, '#satellites button[data-norad="25544"]');
      if (!/ISS/.test(label) || !/(AOS|up now)/.test(label)) throw new Error(`satellite button: ${label}`);
      await until('the upcoming passes', () => page.isVisible('#sat-passes tbody tr'), 5000);
      if ((await page.$$('#sat-passes tbody tr')).length < 2) throw new Error('fewer than 2 ISS passes in 24 h');
      await page.click('#satellites button[data-norad="25544"]');
      await until('TRACK of the satellite', async () => (await state()).target.name === 'sat:ISS (ZARYA)', 5000);
      const sat = (await state()).target.satellite;
      if (!sat || !sat.aos || !['waiting for AOS', 'tracking'].includes(sat.phase)) {
        throw new Error(`satellite status: ${JSON.stringify(sat)}`);
      }
      await page.click('#nav-sky');
      await until('the planned pass on the sky plot', async () => (await page.$('#sky-pass-path')) !== null, 8000);
      await page.click('#nav-main');
    });

    await scenario('+0.01° changes the running total and the antenna follows', page, async () => {
      await page.click('#nav-manual');
      await page.fill('#man-az', '200');
      await page.fill('#man-el', '30');
      await page.click('#man-go');
      await until('the antenna at 200/30', async () => {
        const s = await state();
        return s.mode === 'MAN' && !s.antenna.moving && Math.abs(s.antenna.el_deg - 30) < 0.01 &&
          Math.abs(s.antenna.az_deg - 200) < 0.01;
      }, 30000, 200);
      const before = (await state()).antenna.encoder_el_deg;
      await page.click('#nav-main');
      for (let i = 0; i < 5; ++i) await page.click('#el-up');
      await until('+0.05 on screen', async () => (await text(page, '#el-corr')).includes('0.05'), 3000);
      const s = await until('the encoder 0.05° higher', async () => {
        const now = await state();
        return Math.abs(now.antenna.encoder_el_deg - before - 0.05) < 0.012 && !now.antenna.moving && now;
      }, 10000, 100);
      if (Math.abs(s.corrections.el_user_deg - 0.05) > 1e-9) throw new Error(`daemon total ${s.corrections.el_user_deg}`);
    });

    await scenario('a bad locator shows an error and changes nothing', page, async () => {
      const before = (await api('GET', '/api/config')).json.station.grid;
      await page.click('#nav-setup');
      // The other representation comes from the controller's Maidenhead (GET /api/locator).
      await page.fill('#grid', 'FN06HE');
      await until('the square of FN06HE', async () =>
        (await text(page, '#grid-other')).includes('46.1875° N, 79.3750° W'), 3000);
      await page.fill('#lat', '46.189');
      await page.fill('#lon', '-79.393');
      await until('the locator of the position', async () =>
        (await text(page, '#latlon-other')) === 'Locator FN06he', 3000);
      const band2m = await page.$eval('#band option[value="144"]', (o) => o.textContent);
      if (band2m !== '144 MHz (2 m)') throw new Error(`band label: ${band2m}`);
      await page.fill('#grid', 'ZZ99');
      await until('the hint that ZZ99 is not a locator', async () =>
        (await text(page, '#grid-other')).startsWith('Not a valid locator'), 3000);
      await page.click('#grid-save');
      await until('the error next to the field', async () =>
        (await page.isVisible('#grid-error')) && (await text(page, '#grid-error')).length > 5, 3000);
      const after = (await api('GET', '/api/config')).json.station.grid;
      if (after !== before) throw new Error(`grid changed from ${before} to ${after}`);
      if (!fs.readFileSync(config, 'utf8').includes(`grid = "${before}"`)) throw new Error('the file changed');
    });

    await scenario('a tilt-table edit survives a daemon restart', page, async () => {
      await page.click('#nav-antenna');
      await page.fill('#tilt-5', '0.25');
      await page.press('#tilt-5', 'Enter');
      await page.locator('#tilt-6').focus();
      await until('the daemon to save it', async () => (await api('GET', '/api/config')).json.corrections.tilt_el_deg[5] === 0.25, 3000);
      await stopDaemon();
      await startDaemon();
      await page.reload({ waitUntil: 'load' });
      await page.click('#nav-antenna');
      await until('0.25 in the grid after the restart', async () => parseFloat(await page.inputValue('#tilt-5')) === 0.25, 5000);
    });

    await scenario('the WebSocket reconnects after a daemon restart', page, async () => {
      await page.click('#nav-main');
      await until('connected', async () => !(await page.isVisible('#disconnected')), 5000);
      await stopDaemon();
      await until('the disconnected banner', () => page.isVisible('#disconnected'), 5000);
      await startDaemon();
      await until('the banner to go', async () => !(await page.isVisible('#disconnected')), 8000);
      const t1 = await text(page, '#utc');
      await until('the clock to tick again', async () => (await text(page, '#utc')) !== t1, 3000);
    });

    // Measurements (not pass/fail): page weight and state-change -> DOM latency. Sessions live in
    // the daemon's memory, so the restarts above logged the page out.
    await login(page);
    await page.click('#nav-main');
    let bytes = 0;
    const files = await page.evaluate(() => performance.getEntriesByType('resource')
      .map((e) => new URL(e.name).pathname).filter((p) => p.endsWith('.js') || p.endsWith('.css')));
    for (const f of ['/', ...new Set(files)]) bytes += (await (await fetch(base + f)).arrayBuffer()).byteLength;
    const latencies = await page.evaluate(async () => {
      const csrf = (await (await fetch('/api/session')).json()).csrf;
      const el = document.getElementById('target-name');
      const out = [];
      for (let i = 0; i < 10; ++i) {
        const want = i % 2 === 0 ? 'Sun' : 'Moon';
        const seen = new Promise((resolve) => {
          const obs = new MutationObserver(() => {
            if (el.textContent.includes(want)) { obs.disconnect(); resolve(performance.now()); }
          });
          obs.observe(el, { childList: true, characterData: true, subtree: true });
          setTimeout(() => { obs.disconnect(); resolve(NaN); }, 3000);
        });
        const t0 = performance.now();
        await fetch('/api/target', { method: 'POST', headers: { 'Content-Type': 'application/json', 'X-CSRF-Token': csrf }, body: JSON.stringify({ name: want.toLowerCase() }) });
        out.push((await seen) - t0);
        await new Promise((r) => setTimeout(r, 300));
      }
      return out;
    });
    latencies.sort((a, b) => a - b);
    const seenAll = latencies.every((x) => Number.isFinite(x));
    console.log(`measure: page weight ${bytes} bytes; state change -> DOM median ${latencies[5].toFixed(1)} ms, max ${latencies[9].toFixed(1)} ms (10 target changes${seenAll ? '' : ', some never shown'})`);
    if (consoleErrors.length) {
      results.push({ name: 'no JavaScript errors', ok: false, error: consoleErrors.join('; ') });
      console.log(`FAIL no JavaScript errors: ${consoleErrors.join('; ')}`);
    }
  } finally {
    await ctx.close();
    await stopDaemon();
    fs.rmSync(userDataDir, { recursive: true, force: true });
  }
  const failed = results.filter((r) => !r.ok).length;
  if (failed) console.log(fs.readFileSync(path.join(tmp, 'daemon.log'), 'utf8').split('\n').slice(-20).join('\n'));
  fs.rmSync(tmp, { recursive: true, force: true });
  console.log(`${results.length - failed} passed, ${failed} failed`);
  process.exit(failed ? 1 : 0);
}

main().catch(async (e) => {
  console.error(e);
  await stopDaemon().catch(() => {});
  process.exit(1);
});
