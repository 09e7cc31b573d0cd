// Browser tests of the web console (docs/web-api.md): Debian's Chromium driven by playwright-core
// against a real `azeltrack serve` on the simulated antenna. Each scenario checks what a user sees
// and what the daemon did; screenshots at desktop and phone sizes go to OUT_DIR.
// Usage: node console_test.js AZELTRACK OUT_DIR
// AZT_WEB_DIR=web serves the console's files from that directory instead of the copy built into
// AZELTRACK (to try an edit of web/ without a rebuild; the API and the WebSocket stay the daemon's).
'use strict';
const { spawn, spawnSync } = require('child_process');
const dgram = require('dgram');
const fs = require('fs');
const path = require('path');
const {
  DESKTOP, PHONE, setup, freePort, sleep, until, useWebPort, api, state, simConfig, setPassword, startDaemon,
  stopDaemon, scenario: check, scenarioWithShots, loggedIn, text, launch, pageWeight, checkPageErrors, shutDown,
  summarise, run, tleWithEpochNow,
} = require('./harness');

const { outDir, tmp, config } = setup('console_test.js', 'azt-browser-');
const PASSWORD = 'browser-test-password';
const WEIGHT_BUDGET = 200 * 1000; // the console's first load, uncompressed (docs/web-api.md)
// The pages' modules loaded when the page is first opened (navigation.js), not at start.
const LAZY_MODULES = ['/js/planner.js', '/js/scan.js', '/js/software.js', '/js/settings.js', '/js/settings_account.js'];
const sourcesFile = path.join(tmp, 'sources.d', 'azeltrack.sources');
let port = 0;
let gpsdPort = 0;
let gpsfake = null;
let udpPort = 0;
let feeder = null;

const apiGet = async (route) => api('GET', route);

// gpsd fed once with a recorded fix by gpsfake, in a process group of its own (gpsfake waits on
// its gpsd otherwise), as tests/integration/gps_test.py does.
function startGpsfake(log) {
  gpsfake = spawn('gpsfake', ['-q', '-1', '-c', '0.02', '-P', String(gpsdPort), log],
    { stdio: 'ignore', detached: true, env: { ...process.env, TMPDIR: tmp } });
}
function stopGpsfake() {
  if (!gpsfake) return;
  try { process.kill(-gpsfake.pid, 'SIGKILL'); } catch (e) { /* gone */ }
  gpsfake = null;
  // gpsd killed leaves its shared-memory export (key 0x4770 then the port in hex) behind.
  spawnSync('ipcrm', ['-M', `0x4770${gpsdPort.toString(16).padStart(4, '0')}`], { stdio: 'ignore' });
}
// The receiver for the pointing scans (docs/calibration.md), as tests/integration/scan_test.py is
// one: a Gaussian beam of BEAM_DEG on a source TRUE_AZ_DEG / TRUE_EL_DEG away from where the
// ephemeris puts it (the target in /api/state), seen from where the encoders read, sent as dB lines
// over UDP ([receiver] udp) every 100 ms.
const BEAM_DEG = 1.0;
const TRUE_AZ_DEG = 0.4;
const TRUE_EL_DEG = -0.25;
function beamPowerDb(s) {
  const a = s.antenna || {}; const t = s.target || {};
  if (!a.known || typeof t.az_deg !== 'number' || typeof t.el_deg !== 'number') return 0;
  const srcAz = t.az_deg + TRUE_AZ_DEG; const srcEl = t.el_deg + TRUE_EL_DEG;
  const dAz = ((a.encoder_az_deg - srcAz + 540) % 360) - 180;
  const d2 = (dAz * Math.cos((srcEl * Math.PI) / 180)) ** 2 + (a.encoder_el_deg - srcEl) ** 2;
  return 10 * Math.log10(1 + 3 * Math.exp((-4 * Math.LN2 * d2) / BEAM_DEG ** 2));
}
function startFeeder() {
  const sock = dgram.createSocket('udp4');
  let on = true;
  const done = (async () => {
    while (on) {
      try {
        const s = await state();
        if (s) sock.send(`${beamPowerDb(s).toFixed(4)} dB\n`, udpPort, '127.0.0.1');
      } catch (e) { /* the daemon restarting */ }
      await sleep(100);
    }
    sock.close();
  })();
  feeder = { stop: async () => { on = false; await done; } };
}
async function stopFeeder() {
  if (!feeder) return;
  const f = feeder;
  feeder = null;
  await f.stop();
}

const hasProgram = (name) => spawnSync('sh', ['-c', `command -v ${name}`], { stdio: 'ignore' }).status === 0;

function writeConfig() {
  // The harness's fast plant: a quick motor, so that the final approach to each point of a
  // pointing scan takes a second, not four.
  fs.writeFileSync(config, `${simConfig('stop', port)}[satellites]
file = "sats.tle"
[gps]
enabled = true
gpsd = "127.0.0.1:${gpsdPort}"
use_position = false
[time]
chrony_socket = "${path.join(tmp, 'nonexistent.sock')}"
poll_s = 1
manage_chrony = true
sources_file = "${sourcesFile}"
[receiver]
source = "udp"
port = ${udpPort}
stale_s = 2.0
`);
  fs.mkdirSync(path.dirname(sourcesFile), { recursive: true });
  fs.writeFileSync(path.join(path.dirname(config), 'sats.tle'), tleWithEpochNow());
  setPassword(PASSWORD);
}

// Every scenario leaves its screenshots (the harness's scenarioWithShots); check() is one that
// takes its own, or none.
const scenario = (name, page, body) => scenarioWithShots(name, page, outDir, body);

async function login(page) {
  await page.click('#nav-main').catch(() => {});
  if (await loggedIn(page)) return;
  if (!(await page.isVisible('#password'))) await page.click('#login-state');
  await page.fill('#password', PASSWORD);
  await page.click('#login-btn');
  await until('the session', () => loggedIn(page));
}

// An element's colour against a theme variable's, both as the browser computes them.
async function colourIs(page, sel, variable) {
  return page.evaluate(([s, v]) => {
    const probe = document.createElement('span');
    probe.style.color = `var(${v})`;
    document.body.append(probe);
    const want = getComputedStyle(probe).color;
    probe.remove();
    return getComputedStyle(document.querySelector(s)).color === want;
  }, [sel, variable]);
}

// The planner's table at this size: every column shown, and either all of it within the card or
// a scroller whose hint and right-hand fade show while there is more to the right, gone at the
// end. Returns true, or (with `why`) what is wrong.
async function plannerCue(page, why = false) {
  const r = await page.evaluate(async () => {
    const s = document.getElementById('planner-scroll');
    const box = document.getElementById('planner-box');
    const table = document.getElementById('planner-table');
    if (!s || !box) return { ok: false, missing: 'the scroller #planner-scroll in #planner-box' };
    const fade = () => getComputedStyle(box.querySelector('.scroll-edge'), '::after').opacity;
    const hint = () => document.getElementById('planner-more').checkVisibility();
    const hidden = [...table.querySelectorAll('th')].filter((th) => !th.checkVisibility()).map((th) => th.textContent);
    const card = box.closest('.card').getBoundingClientRect();
    const out = { hidden, over: s.scrollWidth - s.clientWidth, right: s.getBoundingClientRect().right, card: card.right };
    if (hidden.length || out.right > card.right + 0.5 || out.right > window.innerWidth) return { ...out, ok: false };
    if (out.over <= 1) return { ...out, ok: !hint() && fade() === '0' };
    const frames = () => new Promise((res) => requestAnimationFrame(() => requestAnimationFrame(res)));
    s.scrollLeft = 0;
    await frames();
    const start = { hint: hint(), fade: fade() };
    s.scrollLeft = s.scrollWidth;
    await frames();
    const end = { fade: fade() };
    s.scrollLeft = 0;
    return { ...out, start, end, ok: start.hint && start.fade === '1' && end.fade === '0' };
  });
  return why ? r : r.ok;
}

// Notices (toast.js) made as the page makes them, one of them an error and one long.
const someToasts = (page) => page.evaluate(async () => {
  const { toast } = await import('/js/toast.js');
  toast('Station locator saved.');
  toast('TRACK Taurus A');
  toast('start the scan: the receiver has no readings (a scan needs them); check [receiver] and the feed', 'err');
});
// Where the notices are now: none covers STOP, and a tap on any visible control under one reaches
// that control. Returns the problems found and how many controls lie under a notice.
const toastProblems = (page) => page.evaluate(() => {
  const out = [];
  const toasts = [...document.querySelectorAll('#toasts > .toast')].map((t) => t.getBoundingClientRect());
  if (!toasts.length) return { out: ['no notice shown'], under: 0 };
  const meets = (a, b) => a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;
  const stop = document.getElementById('btn-stop');
  const rs = stop.getBoundingClientRect();
  if (toasts.some((t) => meets(t, rs))) out.push('a notice covers STOP');
  if (document.elementFromPoint(rs.left + rs.width / 2, rs.top + rs.height / 2) !== stop) out.push('STOP is not what a tap on it reaches');
  let under = 0;
  for (const c of document.querySelectorAll('button, a[href], input, select, textarea, summary')) {
    if (c.closest('#toasts') || !c.checkVisibility({ visibilityProperty: true })) continue;
    const r = c.getBoundingClientRect();
    for (const t of toasts) {
      if (!meets(t, r)) continue;
      const x = (Math.max(t.left, r.left) + Math.min(t.right, r.right)) / 2;
      const y = (Math.max(t.top, r.top) + Math.min(t.bottom, r.bottom)) / 2;
      const hit = document.elementFromPoint(x, y);
      ++under;
      if (!hit || !(hit === c || c.contains(hit))) out.push(`a notice stands over ${c.id || c.textContent.trim().slice(0, 20)} (a tap reaches ${!hit ? 'nothing' : hit.closest('.toast') ? 'the notice' : hit.id || hit.className})`);
    }
  }
  return { out, under };
});

async function main() {
  port = await freePort();
  gpsdPort = await freePort();
  udpPort = await freePort();
  const base = useWebPort(port);
  writeConfig();
  await startDaemon();
  // With AZT_WEB_DIR (see the top), the console's page and style sheet come from there.
  const browser = await launch({ '/': 'index.html', '/app.css': 'app.css' }, { viewport: { width: 1280, height: 800 } });
  const { page } = browser;
  try {
    await page.goto(base + '/', { waitUntil: 'load' });
    await until('live numbers', async () => /\d/.test(await text(page, '#ant-az')));

    await scenario('actions are refused without login; STOP from this machine is not', page, async () => {
      const before = (await state()).mode;
      const direct = await page.evaluate(async () => (await fetch('/api/target', { method: 'POST',
        headers: { 'Content-Type': 'application/json' }, body: '{"name":"moon"}' })).status);
      if (direct !== 401) throw new Error(`POST /api/target without login answered ${direct}`);
      const after = (await state()).mode;
      if (after !== before) throw new Error(`mode changed from ${before} to ${after}`);
      // A stop never waits for a password on the controller's own machine (loopback).
      await page.click('#btn-stop');
      await until('STOP by the console without a login', async () => {
        const s = await state();
        return s.mode === 'STOP' && /^console\b/.test(s.who);
      }, 3000);
      const said = await text(page, '#login-error');
      if (/STOP was refused/.test(said)) throw new Error(`STOP was refused: ${said}`);
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
      // The echo line is the Moon's alone (as on the seed's screen).
      if ((await state()).target.name !== 'Moon' && await page.isVisible('#echo-row')) {
        throw new Error('the echo line is shown while the Moon is not the target');
      }
      await page.click('#nav-targets');
      await page.click('#tgt-moon');
      await page.click('#nav-main');
      await until('Moon on screen', async () => (await text(page, '#target-name')).includes('Moon'), 3000);
      const s = await state();
      if (s.target.name !== 'Moon' || s.mode !== 'TRACK') throw new Error(`daemon: ${s.mode} ${s.target.name}`);
      // Who moved the antenna: the console's choice, with its address.
      await until('the command in the list', async () =>
        (await text(page, '#command-list')).includes('console 127.0.0.1: track Moon'), 3000);
      await until('the echo line', () => page.isVisible('#echo-row'), 3000);
      // WSJT-X's Astronomical Data in the Moon panel, as the daemon computed them, with a DX
      // station (its Moon, Dpol) and without.
      const setDx = async (grid) => {
        await page.click('#nav-setup');
        await page.fill('#dx-input', grid);
        await page.click('#dx-save');
        await until(`DX ${grid || 'none'} saved`, async () => (await apiGet('/api/config')).json.dx_grid === grid, 3000);
        await page.click('#nav-main');
      };
      await setDx('JO62QM');
      await until('the DX Moon', () => page.isVisible('#moon-dx-row'), 3000);
      const withDx = (await state()).moon;
      if (withDx.dpol_deg === null || withDx.dpol_deg !== withDx.dx_dpol_deg) throw new Error(`Dpol ${withDx.dpol_deg} / alias ${withDx.dx_dpol_deg}`);
      const dxText = await text(page, '#moon-dx');
      if (Math.abs(parseFloat(dxText) - withDx.dx.az_deg) > 0.2) throw new Error(`DX Moon ${dxText} vs ${withDx.dx.az_deg}`);
      await setDx('');
      await until('no DX Moon', async () => !(await page.isVisible('#moon-dx-row')), 3000);
      const m = (await state()).moon;
      await until('Tsky and Dgrd', async () => (await text(page, '#moon-tsky')).includes(' K / '), 3000);
      await until('the echo width', async () => / Hz/.test(await text(page, '#moon-width')), 3000);
      const sep = await text(page, '#moon-sunsep');
      if (Math.abs(parseFloat(sep) - m.sun_sep_deg) > 0.2) throw new Error(`Sun separation ${sep} vs ${m.sun_sep_deg}`);
      const illum = await text(page, '#moon-illum');
      if (Math.abs(parseFloat(illum) - 100 * m.illumination) > 1.5) throw new Error(`illuminated ${illum} vs ${m.illumination}`);
      if (await page.isVisible('#moon-dpol-row') !== (m.dpol_deg !== null)) throw new Error('Dpol to DX shown without a DX');
      if (await page.isVisible('#moon-dx-row') !== (m.dx !== null)) throw new Error('the DX Moon shown without a DX');
      const dec = await text(page, '#moon-dec');
      if (Math.abs(parseFloat(dec) - m.dec_deg) > 0.2) throw new Error(`Dec ${dec} vs ${m.dec_deg}`);
      if (!/Hz\/min/.test(await text(page, '#moon-dfdt'))) throw new Error(`Df/dt: ${await text(page, '#moon-dfdt')}`);
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
      // The pass on the main screen, with the loss the plan reports before AOS.
      await page.click('#nav-main');
      await until('the pass line on the main screen', () => page.isVisible('#sat-row'), 5000);
      const line = await text(page, '#sat-pass');
      const loss = (await state()).target.satellite.planned_loss;
      const said = loss.seconds > 0 ? `${Math.round(loss.seconds)} s beyond` : 'no loss planned';
      if (!/^(AOS|LOS) \d\d:\d\d UTC( \(\d\d:\d\d local\))? · max \d+°/.test(line) || !line.includes(said)) {
        throw new Error(`pass line: ${line} (planned loss ${JSON.stringify(loss)})`);
      }
      await page.click('#nav-sky');
      await until('the planned pass on the sky plot', async () => (await page.$('#sky-pass-path')) !== null, 8000);
      // Its AOS marked with the time the tracker plans (the path's first point above the horizon:
      // AOS, or 10 s later should AOS itself come out a hair below).
      const aos = Date.parse((await state()).target.satellite.aos);
      const marked = await text(page, '#sky-pass-aos');
      const could = [aos, aos + 10e3].map((t) => `AOS ${new Date(t).toISOString().slice(11, 16)}`);
      if (sat.phase === 'waiting for AOS' && !could.includes(marked)) throw new Error(`AOS mark: ${marked} (AOS ${new Date(aos).toISOString()})`);
      await page.click('#nav-main');
    });

    await scenario('the satellites: a search, where their elements come from, an upload', page, async () => {
      await page.click('#nav-targets');
      await page.fill('#sat-search', '25544');
      await until('the ISS found by its number', () => page.isVisible('#satellites button[data-norad="25544"]'), 3000);
      await page.fill('#sat-search', 'no such satellite');
      await until('nothing found, said so', async () => (await text(page, '#satellites')).includes('No satellite matches'), 3000);
      await page.fill('#sat-search', '');
      await until('the file as a source', async () => (await text(page, '#sat-sources')).includes('sats.tle'), 5000);
      await login(page);
      await page.click('#nav-targets');
      const upload = async (name, body) => {
        await page.setInputFiles('#elements-file', { name, mimeType: 'text/plain', buffer: Buffer.from(body) });
        await page.click('#elements-upload');
      };
      await upload('junk.tle', 'not an element set\n');
      await until('the refusal beside the form', async () => (await text(page, '#elements-error')).includes('does not parse'), 5000);
      await upload('mine.tle', tleWithEpochNow('43017', 'AO-91 TEST'));
      await until('the uploaded satellite listed', async () => page.isVisible('#satellites button[data-norad="43017"]'), 8000);
      await until('the upload as a source', async () => (await text(page, '#sat-sources')).includes('uploaded in the console'), 5000);
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

    // The station's clock, GPS and network, in the header and on their pages.
    await scenario('the clock: the banner, the Time page, NTP servers saved from the console', page, async () => {
      await login(page);
      await until('the clock banner with a reason', async () => (await page.isVisible('#clock-banner')) &&
        (await text(page, '#clock-reason')).length > 5, 5000);
      const banner = await text(page, '#clock-banner');
      if (!/^Clock not synchronised: .+\. Tracking carries on\./.test(banner)) throw new Error(`banner: ${banner}`);
      const t = (await state()).time;
      if (t.synced !== false || !t.chrony_error) throw new Error(`daemon time: ${JSON.stringify(t)}`);
      if (!banner.includes(t.reason.replace(/\.+$/, ''))) throw new Error(`the banner does not give the reason “${t.reason}”`);
      // Dismissed, it stays hidden through the next updates while the reason is the same.
      await page.click('#clock-dismiss');
      await until('the banner hidden', async () => !(await page.isVisible('#clock-banner')), 2000);
      const tick = await text(page, '#utc');
      await until('two more updates', async () => (await text(page, '#utc')) !== tick, 3000);
      if (await page.isVisible('#clock-banner')) throw new Error('the dismissed clock banner came back with the same reason');
      await page.click('#nav-setup');
      await page.click('#go-time');
      await until('the Time page', () => page.isVisible('#screen-time'), 3000);
      if ((await page.getAttribute('#nav-setup', 'aria-selected')) !== 'true') throw new Error('the Setup tab is not lit on the Time page');
      if ((await text(page, '#time-badge')) !== 'NOT SYNCHRONISED') throw new Error(`badge: ${await text(page, '#time-badge')}`);
      await until('the chrony error', async () => (await text(page, '#time-chrony')).includes(t.chrony_error), 3000);
      if (!(await page.isVisible('#ntp-form')) || (await page.isVisible('#ntp-unmanaged'))) throw new Error('the managed servers form is not shown');
      // chronyd is not running: the file is written, then `chronyc reload sources` fails (503).
      await page.fill('#ntp-servers', '192.168.1.10');
      await page.click('#ntp-save');
      await until('the reload error', async () => /^Not applied: .*chronyc reload sources/.test(await text(page, '#ntp-error')), 5000);
      const written = fs.readFileSync(sourcesFile, 'utf8');
      if (!/^server 192\.168\.1\.10 iburst$/m.test(written)) throw new Error(`sources file: ${written}`);
      await until('the servers in the state', async () => JSON.stringify((await state()).time.servers) === '["192.168.1.10"]', 3000);
      await page.fill('#ntp-servers', 'bad name');
      await page.click('#ntp-save');
      await until('the field error', async () => /^Not saved: .*bad name/.test(await text(page, '#ntp-error')), 3000);
      if (!(await page.$eval('#ntp-servers', (e) => e.classList.contains('bad')))) throw new Error('the servers field is not marked');
      if (fs.readFileSync(sourcesFile, 'utf8') !== written) throw new Error('a refused name changed the sources file');
    });

    await scenario('the GPS: red without a fix, yellow with one, its page and sky plot', page, async () => {
      if (!hasProgram('gpsfake')) { console.log('     (skipped: no gpsfake; install gpsd-clients)'); return; }
      await page.click('#nav-main');
      await until('the GPS icon red with no gpsd', async () => (await page.getAttribute('#ico-gps', 'data-state')) === 'bad' &&
        (await state()).gps.state === 'no_gpsd', 5000);
      if (!(await colourIs(page, '#ico-gps', '--bad'))) throw new Error('the GPS icon is not red');
      if (!(await page.getAttribute('#ico-gps', 'title')).includes('gpsd not reachable')) throw new Error(`title: ${await page.getAttribute('#ico-gps', 'title')}`);
      startGpsfake(path.join(__dirname, '..', 'data', 'gps', 'good_fix.nmea'));
      // The log opens with ~5 s (played) of no fix; the daemon tries gpsd every 2 s.
      const seen = await until('no fix, red', async () => {
        const g = (await state()).gps.state;
        if (g === 'fix2d' || g === 'fix3d') return 'missed';
        return g === 'no_fix' && (await page.getAttribute('#ico-gps', 'data-state')) === 'bad' && 'seen';
      }, 15000);
      if (seen === 'missed') console.log('     (the daemon reached gpsd after the no-fix part of the log)');
      await page.click('#ico-gps');
      await until('the GPS page', () => page.isVisible('#screen-gps'), 3000);
      await until('a 3D fix, yellow', async () => (await state()).gps.state === 'fix3d' &&
        (await page.getAttribute('#ico-gps', 'data-state')) === 'fix', 15000);
      if (!(await colourIs(page, '#ico-gps', '--gps'))) throw new Error('the GPS icon is not yellow');
      await until('8 of 12 satellites', async () => (await text(page, '#gps-sats')) === '8 used of 12 seen', 3000);
      await until('the locator FN06he', async () => (await text(page, '#gps-locator')).toUpperCase() === 'FN06HE', 3000);
      const marks = await page.$$eval('#gps-sats-marks .gsat', (l) => [l.length, l.filter((g) => g.classList.contains('used')).length]);
      if (marks[0] !== 12 || marks[1] !== 8) throw new Error(`sky plot: ${marks[0]} satellites, ${marks[1]} used`);
      if ((await text(page, '#gps-badge')) !== '3D FIX') throw new Error(`badge: ${await text(page, '#gps-badge')}`);
      if (!/46\.189\d° N, 79\.393\d° W/.test(await text(page, '#gps-pos'))) throw new Error(`position: ${await text(page, '#gps-pos')}`);
      // Back and the tabs still work from a page without a tab.
      await page.click('#nav-sky');
      await until('the Sky screen', () => page.isVisible('#screen-sky'), 3000);
      await page.goBack();
      await until('the GPS page again', () => page.isVisible('#screen-gps'), 3000);
    });
    stopGpsfake();

    await scenario('the Moon planner finds the common windows as the operator types', page, async () => {
      await page.click('#nav-main');
      await page.click('#planner-link');
      await until('the planner', () => page.isVisible('#screen-planner'), 3000);
      await page.fill('#planner-days', '5');
      await page.fill('#planner-dx', 'JO62QM');
      await until('the windows', async () => (await page.$$('#planner-rows tr')).length > 0
        && (await text(page, '#planner-msg')).includes('JO62QM'), 10000);
      // The same question to the API (after the page's: one search runs at a time).
      const api = (await apiGet('/api/moon-windows?dx_grid=JO62QM&days=5&min_el=0&dx_min_el=0')).json;
      const rows = (await page.$$('#planner-rows tr')).length;
      if (rows !== api.windows.length) throw new Error(`${rows} rows, the API ${api.windows.length} windows`);
      if (api.windows.length < 3) throw new Error(`5 days, ${api.windows.length} windows`);
      const first = await text(page, '#planner-rows tr:first-child td:first-child');
      if (!first.includes(api.windows[0].start.slice(11, 16))) throw new Error(`first window ${first} vs ${api.windows[0].start}`);
      // Every column at every size: it fits, or it scrolls sideways with the hint and the fade.
      for (const vp of [PHONE, { width: 320, height: 700 }, DESKTOP]) {
        await page.setViewportSize(vp);
        await until(`the table at ${vp.width} px: fits, or scrolls and says so`, () => plannerCue(page), 2000)
          .catch(async (e) => { throw new Error(`${e.message}: ${JSON.stringify(await plannerCue(page, true))}`); });
      }
      await page.fill('#planner-dx', 'ZZ99');
      await until('the refusal', async () => (await text(page, '#planner-msg')).startsWith('Not found:'), 10000);
      if ((await page.$$('#planner-rows tr')).length !== 0) throw new Error('rows kept after a refusal');
    });

    // The pointing-scan page (docs/calibration.md). The test is the receiver (startFeeder, above).
    const sd3 = (v) => { const t = v.toFixed(3); return `${t.startsWith('-') ? t : `+${t}`}°`; };
    // The plot as drawn: each circle's sample index, position and title; each curve's points.
    const plotted = () => page.evaluate(() => {
      const one = (id) => {
        const svg = document.getElementById(id);
        const curve = svg.querySelector('path.fitc');
        const centre = svg.querySelector('line.fitx');
        return {
          circles: [...svg.querySelectorAll('circle.spt')].map((c) => ({ i: Number(c.dataset.i), shared: c.classList.contains('shared'),
            x: Number(c.getAttribute('cx')), y: Number(c.getAttribute('cy')), title: c.textContent })),
          curve: curve ? (curve.getAttribute('d').match(/-?[\d.]+ -?[\d.]+/g) || []).map((p) => p.split(' ').map(Number)) : [],
          centre: centre ? { deg: Number(centre.dataset.deg), x: Number(centre.getAttribute('x1')) } : null,
        };
      };
      return { xel: one('scan-plot-xel'), el: one('scan-plot-el') };
    });
    const scanSource = (targets) => targets.filter((t) => ['sun', 'moon', 'source'].includes(t.kind) && t.el_deg >= 20 && t.el_deg <= 70)
      .sort((a, b) => (b.kind === 'source') - (a.kind === 'source') || b.el_deg - a.el_deg)[0];

    await scenario('the pointing scan: refused without readings, a five-point scan plotted and fitted, its offsets applied', page, async () => {
      await login(page);
      await page.click('#nav-main');
      await page.click('#scan-link-moon');
      await until('the scan page', () => page.isVisible('#screen-scan'), 3000);
      if ((await page.getAttribute('#nav-targets', 'aria-selected')) !== 'true') throw new Error('the Targets tab is not lit on the scan page');
      // The form: Sun, Moon and the daemon's radio sources; the three kinds; Stop and Apply idle.
      const targets = (await api('GET', '/api/targets')).json.targets;
      const names = JSON.stringify(targets.filter((t) => ['sun', 'moon', 'source'].includes(t.kind)).map((t) => t.name));
      await until('the sources in the form', async () => JSON.stringify(await page.$$eval('#scan-source option', (o) => o.map((x) => x.value))) === names, 5000);
      if (!names.includes('"Sun"') || !names.includes('"Moon"')) throw new Error(`sources: ${names}`);
      const kinds = await page.$$eval('#scan-kind option', (o) => o.map((x) => x.value));
      if (kinds.join(',') !== 'cross,five-point,raster') throw new Error(`kinds: ${kinds}`);
      for (const id of ['#scan-beam', '#scan-start', '#scan-stop', '#scan-apply']) if (!(await page.isVisible(id))) throw new Error(`${id} is not shown`);
      if (!(await page.isDisabled('#scan-stop')) || !(await page.isDisabled('#scan-apply'))) throw new Error('Stop or Apply is enabled with no scan');
      // No readings yet: said plainly, and a scan is refused naming the receiver; nothing moves.
      await until('the receiver line to say there are no readings', async () => /no readings — a scan needs them/.test(await text(page, '#scan-receiver')), 5000);
      const src = scanSource(targets);
      if (!src) { console.log('     (no source between 20° and 70° now: the scan itself is not tested)'); return; }
      await page.selectOption('#scan-source', src.name);
      await page.selectOption('#scan-kind', 'five-point');
      await page.click('#scan-more summary');
      await page.fill('#scan-ref', '2.5');
      await page.fill('#scan-settle', '0');
      await page.fill('#scan-dwell', '0.4');
      await page.fill('#scan-beam', '40');  // the plan refuses it before the receiver is asked
      await page.click('#scan-start');
      await until('the beamwidth refused', async () => /^Not started: beamwidth_deg /.test(await text(page, '#scan-msg')), 5000);
      if (!(await page.$eval('#scan-beam', (e) => e.classList.contains('bad')))) throw new Error('the beamwidth field is not marked');
      await page.fill('#scan-beam', String(BEAM_DEG));
      const before = await state();
      await page.click('#scan-start');
      await until('the refusal naming the receiver', async () => /^Not started: .*receiver/.test(await text(page, '#scan-msg')), 5000);
      if (!(await page.$eval('#scan-msg', (e) => e.classList.contains('error')))) throw new Error('the refusal is not shown as an error');
      const after = await state();
      if (after.mode !== before.mode || after.scan.state === 'running') throw new Error(`a refused scan changed ${before.mode} to ${after.mode}, scan ${after.scan.state}`);
      // Readings: the receiver line shows the latest and the counts.
      startFeeder();
      await until('a reading on the receiver line', async () => {
        const r = (await state()).receiver;
        return r.state === 'receiving' && new RegExp(`: -?\\d+\\.\\d\\d dB, .*good [1-9]\\d*, malformed ${r.malformed}`).test(await text(page, '#scan-receiver'));
      }, 5000);
      const t0 = Date.now();
      await page.click('#scan-start');
      await until('the scan running', async () => (await state()).scan.state === 'running' && /^Scanning /.test(await text(page, '#scan-state')), 5000);
      if (await page.isDisabled('#scan-stop')) throw new Error('Stop is disabled while scanning');
      // The points plotted as they come, each once (the point on the source in both plots).
      await until('the points read so far plotted', async () => {
        const s = (await state()).scan;
        if (s.state !== 'running' || s.samples.length < 2) return false;
        const p = await plotted();
        return p.xel.circles.length + p.el.circles.filter((c) => !c.shared).length === s.samples.length;
      }, 90000, 200);
      await until('the end of the scan', async () => (await state()).scan.state !== 'running', 120000, 500);
      const sc = (await state()).scan;
      console.log(`     (five-point scan of ${src.name} at el ${src.el_deg.toFixed(0)}°: ${sc.state} after ${((Date.now() - t0) / 1000).toFixed(1)} s)`);
      if (sc.state !== 'done') throw new Error(`the scan ended ${sc.state}: ${sc.reason}`);
      const p = await until('every sample plotted once, with the fitted curves', async () => {
        const q = await plotted();
        const ids = [...q.xel.circles, ...q.el.circles.filter((c) => !c.shared)].map((c) => c.i).sort((a, b) => a - b);
        return JSON.stringify(ids) === JSON.stringify(sc.samples.map((_, i) => i)) && q.xel.curve.length > 100 && q.el.curve.length > 100 && q;
      }, 3000);
      for (const c of [...p.xel.circles, ...p.el.circles]) {
        if (!c.title.includes(`${sc.samples[c.i].power_db.toFixed(2)} dB`)) throw new Error(`circle ${c.i}: “${c.title}”, the sample ${JSON.stringify(sc.samples[c.i])}`);
      }
      const shared = p.el.circles.filter((c) => c.shared).map((c) => c.i);
      const onSource = sc.samples.map((s, i) => [s, i]).filter(([s]) => Math.hypot(s.xel_deg, s.el_deg) < 0.1).map(([, i]) => i);
      if (JSON.stringify(shared) !== JSON.stringify(onSource)) throw new Error(`the point on the source in the elevation plot: ${shared} (on the source: ${onSource})`);
      // Each curve peaks at the fitted centre and passes through the readings (a five-point fit is exact).
      for (const [axis, q, centre] of [['xel', p.xel, sc.fit.xel_offset_deg], ['el', p.el, sc.fit.el_offset_deg]]) {
        if (!q.centre || Math.abs(q.centre.deg - centre) > 1e-9) throw new Error(`${axis}: the centre line at ${JSON.stringify(q.centre)}, the fit ${centre}`);
        const topY = Math.min(...q.curve.map((c) => c[1]));
        const top = q.curve.filter((c) => c[1] < topY + 0.5).map((c) => c[0]);  // the flat top, to the pixel
        const topX = (Math.min(...top) + Math.max(...top)) / 2;
        if (Math.abs(topX - q.centre.x) > 4) throw new Error(`${axis}: the curve peaks at x ${topX}, the centre is at ${q.centre.x}`);
        for (const c of q.circles) {
          const k = q.curve.findIndex((pt) => pt[0] >= c.x);
          if (k < 1) throw new Error(`${axis}: circle ${c.i} outside the curve`);
          const [a, b] = [q.curve[k - 1], q.curve[k]];
          const y = a[1] + ((b[1] - a[1]) * (c.x - a[0])) / (b[0] - a[0] || 1);
          if (Math.abs(y - c.y) > 4) throw new Error(`${axis}: circle ${c.i} at y ${c.y}, the curve at ${y.toFixed(1)}`);
        }
      }
      // The result: the offsets found, shown; then applied, once. The beam was on the source where
      // the encoders read source + TRUE, and the controller's reading is the encoders' less the
      // operator's corrections (+0.05° of elevation from the scenario above).
      const found = sc.found;
      const was = (await state()).corrections;
      if (Math.abs(found.az_offset_deg - (TRUE_AZ_DEG - was.az_user_deg)) > 0.03 ||
          Math.abs(found.el_offset_deg - (TRUE_EL_DEG - was.el_user_deg)) > 0.03) throw new Error(`found ${JSON.stringify(found)} with corrections ${JSON.stringify(was)}`);
      await until('the found offsets on the page', async () => (await text(page, '#scan-found')) === `az ${sd3(found.az_offset_deg)} · el ${sd3(found.el_offset_deg)}`, 3000);
      if (!(await text(page, '#scan-width')).includes(`${sc.fit.width_xel_deg.toFixed(3)}°`)) throw new Error(`width: ${await text(page, '#scan-width')}`);
      if (!(await text(page, '#scan-peak')).startsWith(`${sc.fit.peak_db.toFixed(2)} dB`)) throw new Error(`peak: ${await text(page, '#scan-peak')}`);
      if (await page.isDisabled('#scan-apply')) throw new Error('Apply is disabled with a result to apply');
      await page.click('#scan-apply');
      const want = [was.az_offset_deg - found.az_offset_deg, was.el_offset_deg - found.el_offset_deg];
      await until('the new offsets in the controller', async () => {
        const c = (await state()).corrections;
        return Math.abs(c.az_offset_deg - want[0]) < 1e-9 && Math.abs(c.el_offset_deg - want[1]) < 1e-9;
      }, 5000);
      const saved = (await api('GET', '/api/config')).json.corrections;
      if (Math.abs(saved.az_offset_deg - want[0]) > 1e-9 || Math.abs(saved.el_offset_deg - want[1]) > 1e-9) throw new Error(`saved: ${JSON.stringify(saved)}`);
      await until('the new offsets on the page', async () => (await text(page, '#scan-msg')).startsWith(`Applied and saved: encoder offsets az ${sd3(want[0])}, el ${sd3(want[1])}`), 5000);
      await until('Apply disabled: applied once', () => page.isDisabled('#scan-apply'), 3000);
    });

    await scenario('a running scan stops from the page', page, async () => {
      if (!feeder) { console.log('     (skipped: no scan above)'); return; }
      await page.click('#nav-targets');
      await page.click('#scan-link-targets');
      await until('the scan page', () => page.isVisible('#screen-scan'), 3000);
      await page.selectOption('#scan-kind', 'cross');
      await page.fill('#scan-points', '5');
      await page.click('#scan-start');
      await until('the scan running', async () => (await state()).scan.state === 'running' && !(await page.isDisabled('#scan-stop')), 5000);
      await page.click('#scan-stop');
      await until('the scan stopped', async () => (await state()).scan.state === 'stopped' && /^Stopped: /.test(await text(page, '#scan-state')), 5000);
      if (!(await text(page, '#scan-msg')).startsWith('Scan stopped')) throw new Error(`message: ${await text(page, '#scan-msg')}`);
      const s = await state();
      if (s.mode !== 'TRACK') throw new Error(`after the stop: ${s.mode}`);
      if (!(await page.isDisabled('#scan-stop')) || (await page.isDisabled('#scan-start'))) throw new Error('Stop still enabled, or Start not');
    });
    await stopFeeder();

    await scenario('the Network page lists the interfaces', page, async () => {
      await page.click('#ico-eth');
      await until('the Network page', () => page.isVisible('#screen-network'), 3000);
      const names = fs.readdirSync('/sys/class/net').filter((n) => n !== 'lo');
      const net = await until('network in the state', async () => { const s = await state(); return s.network; }, 5000);
      if (!Array.isArray(net.interfaces)) throw new Error(`network: ${JSON.stringify(net)}`);
      const shown = await until('an interface card', async () => {
        const l = await page.$$eval('#net-list [data-iface]', (c) => c.map((e) => e.dataset.iface));
        return l.some((n) => names.includes(n)) && l;
      }, 3000);
      if (shown.includes('lo')) throw new Error('loopback listed');
    });

    await scenario('on a phone the header keeps STOP, the status icons and the antenna\'s az/el on screen', page, async () => {
      await page.click('#nav-main');
      for (const width of [320, 375, 390]) {
        await page.setViewportSize({ width, height: 844 });
        const problems = await page.evaluate((vw) => {
          const out = [];
          const ids = ['btn-stop', 'ico-gps', 'ico-eth', 'ico-wifi', 'conn-dot', 'mini-az', 'mini-el', 'login-state', 'logout-btn', 'theme-btn'];
          const boxes = ids.map((id) => [id, document.getElementById(id).getBoundingClientRect()]);
          for (const [id, r] of boxes) {
            const e = document.getElementById(id);
            if (!e.checkVisibility({ visibilityProperty: true, opacityProperty: true }) || r.width <= 0 || r.left < 0 || r.right > vw || r.top < 0) out.push(`${id} is off the screen (${r.left.toFixed(1)}…${r.right.toFixed(1)})`);
            // what a tap or an eye reaches there is the control itself, nothing drawn over it
            const hit = document.elementFromPoint(r.left + r.width / 2, r.top + r.height / 2);
            if (!hit || !(hit === e || e.contains(hit))) out.push(`${id} is covered by ${hit ? hit.id || hit.className : 'nothing'}`);
          }
          for (const [a, ra] of boxes) {
            for (const [b, rb] of boxes) {
              if (a < b && ra.left < rb.right - 0.5 && rb.left < ra.right - 0.5 && ra.top < rb.bottom - 0.5 && rb.top < ra.bottom - 0.5) out.push(`${a} overlaps ${b}`);
            }
          }
          for (const id of ['mini-az', 'mini-el']) if (!/^\d+\.\d\d°$/.test(document.getElementById(id).textContent)) out.push(`${id} reads “${document.getElementById(id).textContent}”`);
          return out;
        }, width);
        if (problems.length) throw new Error(`at ${width} px: ${problems.join('; ')}`);
      }
      for (const s of ['gps', 'time', 'network', 'scan']) {
        await page.evaluate((n) => { location.hash = n; }, s);
        await until(`the ${s} page`, () => page.isVisible(`#screen-${s}`), 3000);
        const w = await page.evaluate(() => document.documentElement.scrollWidth);
        if (w > 390) throw new Error(`the ${s} page is ${w} px wide on a 390 px phone`);
      }
      await page.setViewportSize({ width: 1280, height: 800 });
    });

    await check('notices never cover STOP, a tap goes through them to the control underneath and clears them', async () => {
      for (const [vp, screen] of [[PHONE, 'main'], [PHONE, 'setup'], [DESKTOP, 'setup']]) {
        await page.setViewportSize(vp);
        await page.evaluate((n) => { location.hash = n; window.scrollTo(0, document.documentElement.scrollHeight); }, screen);
        await until(`the ${screen} page`, () => page.isVisible(`#screen-${screen}`), 3000);
        await someToasts(page);
        // On the phone's main screen, TRACK right under the notices: the case to prove.
        if (vp === PHONE && screen === 'main') {
          await page.evaluate(() => {
            const t = document.querySelector('#toasts > .toast:last-child').getBoundingClientRect();
            const b = document.getElementById('btn-track').getBoundingClientRect();
            window.scrollBy(0, (b.top + b.bottom) / 2 - (t.top + t.bottom) / 2);
          });
        }
        const { out, under } = await toastProblems(page);
        if (out.length) throw new Error(`${screen} at ${vp.width} px: ${out.join('; ')}`);
        if (vp === PHONE && screen === 'main' && !under) throw new Error('no control under the notices: the check saw nothing');
        if (vp === PHONE && screen === 'main') await page.screenshot({ path: path.join(outDir, 'toasts-phone.png') });
        // A tap through a notice (where no control is under it: the check above covers those)
        // reaches the page, and the notices step aside.
        const spot = await page.evaluate(() => {
          const r = document.querySelector('#toasts > .toast').getBoundingClientRect();
          for (const f of [0.5, 0.2, 0.8]) {
            const x = r.left + r.width * f; const y = r.top + r.height / 2;
            const hit = document.elementFromPoint(x, y);
            if (hit && !hit.closest('button, a, input, select, textarea, summary, label, .toast')) return { x, y };
          }
          const m = document.getElementById('mini').getBoundingClientRect();
          return { x: m.left + m.width / 2, y: m.top + m.height / 2 };
        });
        await page.mouse.click(spot.x, spot.y);
        await until('the notices cleared by the tap', async () => (await page.$$('#toasts > .toast')).length === 0, 2000);
      }
      await page.setViewportSize(DESKTOP);
    });

    await check('the Setup page\'s footer stands below its cards, clear of the Software card', async () => {
      await page.click('#nav-setup');
      for (const vp of [DESKTOP, PHONE]) {
        await page.setViewportSize(vp);
        const bad = await page.evaluate(() => {
          const foot = document.getElementById('setup-foot');
          if (!foot) return 'no footer (#setup-foot)';
          const f = foot.getBoundingClientRect();
          if (!foot.checkVisibility() || f.height <= 0) return 'the footer is not shown';
          const cards = [...document.querySelectorAll('#screen-setup > .card')];
          const hit = cards.find((c) => { const r = c.getBoundingClientRect(); return f.left < r.right && r.left < f.right && f.top < r.bottom && r.top < f.bottom; });
          if (hit) return `the footer runs into the ${hit.querySelector('h2').textContent} card`;
          if (cards.some((c) => c.getBoundingClientRect().bottom > f.top)) return 'a card ends below the footer\'s top';
          return '';
        });
        if (bad) throw new Error(`${vp.width} px: ${bad}`);
      }
      await page.setViewportSize(DESKTOP);
    });

    // Every page at both sizes, screenshot and all: a console error or a Content-Security-Policy
    // violation on any of them fails the test (checkPageErrors), and none is wider than a phone.
    await login(page);
    await check('every page is shown, at 1280×800 and 390×844', async () => {
      const ready = {
        main: '#ant-az', targets: '#sources .tgt', sky: '#sky-plot circle', manual: '#man-az', antenna: '#tilt-grid input',
        setup: '#setup-software', gps: '#gps-badge', time: '#time-badge', network: '#net-list [data-iface]',
        planner: '#planner-msg', scan: '#scan-source option', software: '#sw-version', settings: '#settings-body details',
        account: '#token-list tr',
      };
      const REDRAWN = { main: true, antenna: true, scan: true };
      const wide = [];
      for (const [name, sel] of Object.entries(ready)) {
        await page.evaluate((n) => { location.hash = n; }, name);
        await until(`the ${name} page`, async () => (await page.isVisible(`#screen-${name}`)) &&
          page.$eval(sel, (e) => e.textContent.trim() !== '—').catch(() => false), 5000);
        for (const [size, vp] of [['desktop', DESKTOP], ['phone', PHONE]]) {
          await page.setViewportSize(vp);
          await sleep(REDRAWN[name] ? 200 : 30); // main.js redraws these charts 150 ms after a resize
          await page.screenshot({ path: path.join(outDir, `page-${name}-${size}.png`), fullPage: name !== 'settings' });
          if (size === 'phone') {
            const w = await page.evaluate(() => document.documentElement.scrollWidth);
            if (w > PHONE.width) wide.push(`${name} ${w} px`);
          }
        }
      }
      await page.setViewportSize(DESKTOP);
      if (wide.length) throw new Error(`wider than a ${PHONE.width} px phone: ${wide.join(', ')}`);
    });

    // Measurements (not pass/fail): page weight and state-change -> DOM latency. Sessions live in
    // the daemon's memory, so the restarts above logged the page out (login() is a no-op if not).
    await page.click('#nav-main');
    // The console's first load, in a page of its own: the page, its style sheet and the modules it
    // loads at start (the pages' own modules come when they are first opened).
    const fresh = await browser.ctx.newPage();
    fresh.on('console', (m) => { if (m.type() === 'error') browser.errors.push(`console (first load): ${m.text()}`); });
    await fresh.goto(base + '/', { waitUntil: 'load' });
    await until('live numbers on the first load', async () => /\d/.test(await text(fresh, '#ant-az')));
    const { bytes, all } = await pageWeight(fresh, '/');
    await fresh.close();
    console.log(`measure: page weight ${bytes} bytes (${(bytes / 1000).toFixed(1)} KB) in ${all.length} files`);
    await check(`the console's first load weighs less than ${WEIGHT_BUDGET / 1000} KB`, async () => {
      if (bytes >= WEIGHT_BUDGET) throw new Error(`${bytes} bytes: ${all.join(' ')}`);
      const early = all.filter((f) => LAZY_MODULES.includes(f));
      if (early.length) throw new Error(`loaded at start: ${early.join(' ')}`);
    });
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
    console.log(`measure: state change -> DOM median ${latencies[5].toFixed(1)} ms, max ${latencies[9].toFixed(1)} ms (10 target changes${seenAll ? '' : ', some never shown'})`);
    checkPageErrors(browser.errors);
  } finally {
    stopGpsfake();
    await stopFeeder();
    await shutDown(browser);
  }
  summarise();
}

run(main, stopGpsfake);
