// Browser test of the main screen's cards for the antennas people have (docs/web-api.md): the
// polarisation card on a station with [mount.pol] (docs/eme.md "Polarisation axis"), the beam
// line of a fixed-elevation array ([mount.el] fixed_deg, "Fixed-elevation arrays"), the
// direction test offering only the station's own axes, and the Drives card (docs/web-api.md
// `antenna.axes`): a simulated actuator dish homed from it, and states the simulation cannot be
// brought to on demand added to the daemon's state messages by the test (routeAxes), with Home's
// refusal shown, and an absent game pad's line in the Station I/O card. Debian's Chromium driven by playwright-core
// against a real `azeltrack serve` on the simulated antenna, restarted on each station's file
// (harness.js); the page is loaded afresh for each. Screenshots go to OUT_DIR.
// Usage: node antennas_test.js AZELTRACK OUT_DIR (AZT_WEB_DIR as for console_test.js)
'use strict';
const crypto = require('crypto');
const fs = require('fs');
const {
  setup, freePort, until, useWebPort, api, state, simConfig, setPassword, startDaemon, stopDaemon,
  scenarioWithShots, loggedIn, text, launch, checkPageErrors, shutDown, summarise, run,
} = require('./harness');

const { outDir, config } = setup('antennas_test.js', 'azt-antennas-');
const PASSWORD = 'antennas-test-password';
const TOKEN = crypto.randomBytes(16).toString('hex'); // the test's own requests, to set the scene
const bearer = (method, route, body) => api(method, route, body, TOKEN);
let port = 0;
let base = '';

// The harness's simulated station tracking `target`, edited by `edit`, with the test's token in its
// [web] (which simConfig leaves open at the end) and `more` tables after it.
function writeStation(target, more = '', edit = (s) => s) {
  const tokenHash = crypto.createHash('sha256').update(TOKEN).digest('hex');
  fs.writeFileSync(config, `${edit(simConfig(target, port))}api_token_sha256 = "${tokenHash}"\n${more}`);
  setPassword(PASSWORD);
}
// A fixed-elevation array: the harness's elevation tables replaced by the array's angle and beam.
const fixedElevation = (s) => s
  .replace(/\[mount\.el\]\n(?:[a-z_]+ = [^\n]*\n)+/, '[mount.el]\nfixed_deg = 12.0\nbeam_width_deg = 20.0\n')
  .replace(/\[sim\.el\]\n(?:[a-z_]+ = [^\n]*\n)+/, '');

const scenario = (name, page, body) => scenarioWithShots(name, page, outDir, body);

// The daemon restarted on the file just written (`restart`), the page loaded afresh and logged in;
// `numbers`: once it shows the antenna's position (an unhomed axis has none to show).
async function openStation(page, restart = true, numbers = true) {
  if (restart) {
    await stopDaemon();
    await startDaemon();
  }
  await page.goto('about:blank');
  await page.goto(`${base}/`, { waitUntil: 'load' });
  if (numbers) await until('live numbers', async () => /\d/.test(await text(page, '#ant-az')));
  else await until('the live state', () => page.isVisible('#drives-panel'));
  if (!(await page.isVisible('#password'))) await page.click('#login-state');
  await page.fill('#password', PASSWORD);
  await page.click('#login-btn');
  await until('the session', () => loggedIn(page));
}

// The answer to the request the page makes when `click` runs, with the body it sent.
async function answerTo(page, method, pathname, click) {
  const answer = page.waitForResponse((r) => r.request().method() === method && new URL(r.url()).pathname === pathname, { timeout: 15000 });
  await click();
  const r = await answer;
  return { status: r.status(), json: await r.json().catch(() => null), sent: r.request().postDataJSON() };
}

// The axes the Settings page's direction test offers, by their buttons; back to the main screen.
async function testedAxes(page) {
  await page.evaluate(() => { location.hash = 'settings'; });
  await until('the direction test', () => page.isVisible('#sec-direction-test > summary'), 8000);
  if (!(await page.$eval('#sec-direction-test', (d) => d.open))) await page.click('#sec-direction-test > summary');
  const ids = await page.$$eval('#sec-direction-test .dirtest-axes button', (bs) => bs.map((b) => b.id.replace(/^dirtest-/, '')));
  await page.click('#nav-main');
  return ids.join(',');
}

// An angle as the console writes it (format.js deg: no "-0.0").
const deg1 = (v) => `${v.toFixed(1).replace(/^-(0\.0)$/, '$1')}°`;
// The pol card's feed line as pol.js writes it from the state's `pol`.
const polAngle = (p) => `${deg1(p.mount_deg)} / ${p.feed_target_deg === null ? 'holds' : deg1(p.feed_target_deg)}${p.moving ? ' · moving' : ''}`;
// Until the pol axis has settled on `mode`, at `deg` (null: holding, with no target), and the
// card says so. The state's mode changes at once, its target at the loop's next tick.
async function polSettles(page, mode, modeText, deg) {
  let last = null;
  await until(`the feed ${mode}${deg === null ? ', holding' : ` at ${deg}°`} and the card saying so`, async () => {
    const p = (await state()).pol;
    const shown = { mode: await text(page, '#pol-mode'), angle: await text(page, '#pol-angle') };
    last = { p, shown };
    if (!p || p.mode !== mode || p.moving) return false;
    if (deg === null ? p.feed_target_deg !== null : Math.abs(p.mount_deg - deg) > 0.3) return false;
    return shown.mode === modeText && shown.angle === polAngle(p);
  }, 20000, 200).catch((e) => { throw new Error(`${e.message}: ${JSON.stringify(last)}`); });
  return last.p;
}

// The first station: the daemon is already running on it (the browser's launch needs its page).
const writePolStation = () => writeStation('sun', `[mount.pol]
max_rate_deg_s = 10.0
[pol]
mode = "fixed"
fixed_deg = 20.0
`);

async function polStation(page) {
  await openStation(page, false);

  await scenario('pol: the card shows the file\'s mode and the feed as read', page, async () => {
    await until('the pol card', () => page.isVisible('#pol-panel'), 5000);
    const p = await polSettles(page, 'fixed', 'fixed 20.0°', 20);
    if (p.feed_target_deg === null || Math.abs(p.feed_target_deg - 20) > 0.01) throw new Error(`fixed 20: the feed's target ${p.feed_target_deg}`);
    if ((await page.inputValue('#pol-mode-select')) !== 'fixed') throw new Error(`the selector: ${await page.inputValue('#pol-mode-select')}`);
  });

  await scenario('pol: manual 35° from the card is posted, and the feed and the card follow', page, async () => {
    await page.selectOption('#pol-mode-select', 'manual');
    await page.fill('#pol-angle-input', '35');
    const r = await answerTo(page, 'POST', '/api/pol', () => page.click('#pol-set'));
    if (r.status !== 200) throw new Error(`POST /api/pol answered ${r.status} ${JSON.stringify(r.json)}`);
    if (r.sent.mode !== 'manual' || r.sent.angle_deg !== 35) throw new Error(`the page sent ${JSON.stringify(r.sent)}`);
    const p = await polSettles(page, 'manual', 'manual 35.0°', 35);
    if (p.manual_deg !== 35) throw new Error(`manual_deg ${p.manual_deg}`);
  });

  await scenario('pol: a refused angle shows the daemon\'s words and changes nothing', page, async () => {
    await page.selectOption('#pol-mode-select', 'fixed');
    await page.fill('#pol-angle-input', '500');
    const r = await answerTo(page, 'POST', '/api/pol', () => page.click('#pol-set'));
    if (r.status !== 400 || !r.json || !r.json.error) throw new Error(`angle 500 answered ${r.status} ${JSON.stringify(r.json)}`);
    await until('the refusal beside the form', async () => (await text(page, '#pol-error')) === r.json.error, 3000);
    if (!(await page.isVisible('#pol-error'))) throw new Error('the refusal is not visible');
    const p = (await state()).pol;
    if (p.mode !== 'manual' || p.manual_deg !== 35) throw new Error(`after the refusal: ${p.mode} ${p.manual_deg}`);
    if ((await text(page, '#pol-mode')) !== 'manual 35.0°') throw new Error(`the card: ${await text(page, '#pol-mode')}`);
  });

  await scenario('pol: off holds the feed, and the refusal is cleared', page, async () => {
    await page.selectOption('#pol-mode-select', 'off');
    await page.fill('#pol-angle-input', '');
    const r = await answerTo(page, 'POST', '/api/pol', () => page.click('#pol-set'));
    if (r.status !== 200 || r.sent.mode !== 'off' || 'angle_deg' in r.sent) throw new Error(`off: ${r.status}, sent ${JSON.stringify(r.sent)}`);
    const p = await polSettles(page, 'off', 'off', null);
    if (Math.abs(p.mount_deg - 35) > 0.3 || !(await text(page, '#pol-angle')).endsWith('/ holds')) throw new Error(`off: the feed at ${p.mount_deg}, shown ${await text(page, '#pol-angle')}`);
    if ((await text(page, '#pol-error')) !== '' || (await page.isVisible('#pol-error'))) throw new Error(`a refusal still shown: ${await text(page, '#pol-error')}`);
  });

  await scenario('pol: a mode set by a script moves the selector and the card', page, async () => {
    const r = await bearer('POST', '/api/pol', { mode: 'fixed', angle_deg: -10 });
    if (r.status !== 200) throw new Error(`the script's POST /api/pol: ${r.status} ${JSON.stringify(r.json)}`);
    await polSettles(page, 'fixed', 'fixed -10.0°', -10);
    if ((await page.inputValue('#pol-mode-select')) !== 'fixed') throw new Error(`the selector: ${await page.inputValue('#pol-mode-select')}`);
  });

  await scenario('pol: the direction test offers the pol axis', page, async () => {
    const axes = await testedAxes(page);
    if (axes !== 'az,el,pol') throw new Error(`the direction test offers ${axes}`);
    if (await page.isVisible('#beam-row')) throw new Error('a beam line on a steerable elevation');
  });
}

async function plainStation(page) {
  writeStation('stop');
  await openStation(page);
  await scenario('a plain az/el station: no pol card, no beam line, no pol in the direction test', page, async () => {
    const r = await bearer('POST', '/api/target', { az_deg: 190, el_deg: 30 });
    if (r.status !== 200) throw new Error(`MAN: ${r.status} ${JSON.stringify(r.json)}`);
    // The page has drawn a state with the manual target: its elevation is on screen.
    await until('the manual target on screen', async () => (await text(page, '#target-el')) === '30.00°', 5000);
    const s = await state();
    if (s.pol !== null || 'in_beam' in s.target || 'el_fixed_deg' in s.antenna) throw new Error(`the state: pol ${JSON.stringify(s.pol)}, target ${JSON.stringify(s.target)}`);
    if (await page.isVisible('#pol-panel')) throw new Error('the pol card is shown');
    if (await page.isVisible('#beam-row')) throw new Error(`the beam line is shown: ${await text(page, '#beam-line')}`);
    if ((await text(page, '#err-el')) === 'fixed') throw new Error('the elevation error says "fixed"');
    const axes = await testedAxes(page);
    if (axes !== 'az,el') throw new Error(`the direction test offers ${axes}`);
  });
}

async function fixedElStation(page) {
  writeStation('stop', '', fixedElevation);
  await openStation(page);
  // A manual target's elevation is the target's (the array ignores it): 15° is within ±10° of
  // 12°, 60° is not.
  for (const [el, words, inBeam] of [[15, 'in the beam at 12.00° elevation', true], [60, 'outside the beam at 12.00° elevation', false]]) {
    await scenario(`a fixed-elevation array: a target at ${el}° is ${inBeam ? 'in' : 'outside'} the beam`, page, async () => {
      const r = await bearer('POST', '/api/target', { az_deg: 200, el_deg: el });
      if (r.status !== 200) throw new Error(`MAN: ${r.status} ${JSON.stringify(r.json)}`);
      await until('the target in the state', async () => (await state()).target.el_deg === el, 5000);
      const s = await state();
      if (s.antenna.el_fixed_deg !== 12 || s.target.in_beam !== inBeam) throw new Error(`the state: el_fixed_deg ${s.antenna.el_fixed_deg}, in_beam ${s.target.in_beam}`);
      await until(`"${words}"`, async () => (await page.isVisible('#beam-row')) && (await text(page, '#beam-line')) === words, 5000);
      if ((await text(page, '#err-el')) !== 'fixed') throw new Error(`the elevation error: ${await text(page, '#err-el')}`);
    });
  }
  await scenario('a fixed-elevation array: the direction test offers azimuth only', page, async () => {
    const axes = await testedAxes(page);
    if (axes !== 'az') throw new Error(`the direction test offers ${axes}`);
  });
}

// A dish whose elevation is a pulse-counted linear actuator (examples/actuator_dish.toml's
// [hardware.el], flown by the simulated actuator), waiting for the operator to home it: the
// daemon's own `antenna.axes`, Home posted and followed to "homed".
const DISH = `[geometry]
el_min_deg = 5.3
el_max_deg = 87.0
[hardware.el]
sensor = "pulses"
pulse_line = 20
home_switch = 16
counts_per_mm = 1.0
home_mm = 525.0
actuator_pivot_to_fixed_mm = 650.0
actuator_pivot_to_moving_mm = 400.0
actuator_offset_deg = 48.0
actuator_retracted_mm = 520.0
actuator_extended_mm = 977.2
home_seek_duty = -0.8
home_at_start = false
`;
async function dishStation(page) {
  // The actuator's rate (8 mm/s at 0.14–0.31°/mm), so the supervisor expects what it does.
  writeStation('stop', DISH, (s) => s.replace('[sim.el]\nstart_deg = 20.0\n', '[sim.el]\nstart_deg = 9.0\n')
    .replace('[mount.el]\nmax_rate_deg_s = 10.0\n', '[mount.el]\nmax_rate_deg_s = 1.2\n'));
  await openStation(page, true, false);
  await scenario('drives: the daemon\'s pulse-counted elevation waits for Home, then homes', page, async () => {
    await until('the Drives card', () => page.isVisible('#drives-panel'), 5000);
    const shown = await drivesShown(page);
    if (shown !== 'el+home') throw new Error(`the card has ${shown}`);
    if ((await text(page, '#drive-el-held')) !== 'not homed: homing has not run') throw new Error(`held: "${await text(page, '#drive-el-held')}"`);
    await page.click('#drive-el-home');
    await until('the confirmation', () => page.isVisible('#confirm-dialog'), 3000);
    const r = await answerTo(page, 'POST', '/api/hardware/home', () => page.click('#confirm-ok'));
    if (r.status !== 200 || r.json.axis !== 'el') throw new Error(`POST /api/hardware/home: ${r.status} ${JSON.stringify(r.json)}`);
    await until('homed, in the card', async () => /^homed · -?\d+ counts$/.test(await text(page, '#drive-el-homing')), 45000)
      .catch(async (e) => { throw new Error(`${e.message}: ${JSON.stringify((await state()).antenna.axes)} ${JSON.stringify((await state()).faults)}`); });
    const s = await state();
    if (s.antenna.axes.el.homing !== 'homed' || s.antenna.axes.el.held !== null) throw new Error(`the state: ${JSON.stringify(s.antenna.axes)}`);
    if (await page.isVisible('#drive-el-held-row')) throw new Error('the held words still shown once homed');
    await until('the position, once homed', async () => (await state()).antenna.known && /\d/.test(await text(page, '#ant-el')), 5000);
  });
}

// The axes' hardware added to every state message the daemon sends the page (its WebSocket routed
// through the test): the states a simulated station cannot be brought to on demand (a brake's
// words, a refused reset, a lost position). `axes` is what the next messages carry; null leaves
// the state as the daemon sent it.
const injected = { axes: null };
async function routeAxes(page) {
  await page.routeWebSocket(/\/ws$/, (ws) => {
    const server = ws.connectToServer();
    server.onMessage((m) => {
      if (injected.axes === null || typeof m !== 'string') { ws.send(m); return; }
      const st = JSON.parse(m);
      st.antenna = { ...st.antenna, axes: injected.axes };
      ws.send(JSON.stringify(st));
    });
  });
}

// The Drives card's axes as drawn, and whether each has Home.
const drivesShown = (page) => page.$$eval('#drives-list .drive', (ds) => ds.map((d) => `${d.id.replace(/^drive-/, '')}${d.querySelector('button') ? '+home' : ''}`).join(','));

async function drivesStation(page) {
  writeStation('stop');
  await routeAxes(page);
  await openStation(page);

  await scenario('drives: hidden while the state has no antenna.axes', page, async () => {
    const s = await state();
    if ('axes' in s.antenna) throw new Error(`the daemon sends antenna.axes: ${JSON.stringify(s.antenna.axes)}`);
    if (await page.isVisible('#drives-panel')) throw new Error('the Drives card is shown');
  });

  await scenario('drives: each axis\'s brake, motor, trip and homing, in words; Home only where it homes', page, async () => {
    injected.axes = {
      az: { brake: 'released, idle', brake_released: false, current_a: 1.234, temperature_c: 41.26, reset_refused: 'az: over-temperature: 81 °C is above 80 °C' },
      el: { homing: 'not homed', held: 'not homed: homing has not run', pulse_count: 0 },
    };
    await until('the Drives card', () => page.isVisible('#drives-panel'), 5000);
    const shown = await drivesShown(page);
    if (shown !== 'az,el+home') throw new Error(`the card has ${shown}`);
    const want = {
      '#drive-az-brake': 'released, idle', '#drive-az-motor': '1.23 A · 41.3 °C',
      '#drive-az-trip': 'az: over-temperature: 81 °C is above 80 °C',
      '#drive-el-homing': 'not homed · 0 counts', '#drive-el-held': 'not homed: homing has not run',
    };
    for (const [sel, words] of Object.entries(want)) if ((await text(page, sel)) !== words) throw new Error(`${sel}: "${await text(page, sel)}", not "${words}"`);
    if (!(await page.isVisible('#drive-el-held-row'))) throw new Error('the held words are hidden');
  });

  await scenario('drives: Home asks first, posts /api/hardware/home, and shows the daemon\'s refusal', page, async () => {
    let sent = false;
    const seen = (r) => { if (r.url().endsWith('/api/hardware/home')) sent = true; };
    page.on('request', seen);
    await page.click('#drive-el-home');
    await until('the confirmation', () => page.isVisible('#confirm-dialog'), 3000);
    await page.keyboard.press('Escape');
    await until('the dialog closed', async () => !(await page.isVisible('#confirm-dialog')), 3000);
    page.off('request', seen);
    if (sent) throw new Error('Escape did not cancel the homing');
    await page.click('#drive-el-home');
    await until('the confirmation', () => page.isVisible('#confirm-dialog'), 3000);
    if (!/elevation/.test(await text(page, '#confirm-title'))) throw new Error(`the confirmation asked "${await text(page, '#confirm-title')}"`);
    const r = await answerTo(page, 'POST', '/api/hardware/home', () => page.click('#confirm-ok'));
    if (r.sent.axis !== 'el') throw new Error(`the page sent ${JSON.stringify(r.sent)}`);
    // This daemon has no pulse-counted axis: it refuses, and the card says its words.
    if (r.status !== 409 || !r.json || !r.json.error) throw new Error(`POST /api/hardware/home: ${r.status} ${JSON.stringify(r.json)}`);
    await until('the refusal beside Home', async () => (await text(page, '#drive-el-error')) === r.json.error, 3000);
  });

  await scenario('drives: the card follows the homing, and hides again without axes', page, async () => {
    injected.axes = { el: { homing: 'seeking', held: 'not homed: homing in progress (seeking the home switch)', pulse_count: -12 } };
    await until('seeking, azimuth gone', async () => (await text(page, '#drive-el-homing')) === 'seeking · -12 counts' && (await drivesShown(page)) === 'el+home', 5000);
    injected.axes = { el: { homing: 'homed', held: null, pulse_count: 160 } };
    await until('homed, the held line gone', async () => (await text(page, '#drive-el-homing')) === 'homed · 160 counts' && !(await page.isVisible('#drive-el-held-row')), 5000);
    injected.axes = { el: { homing: 'position lost', held: 'position lost: 3 counts lost', pulse_count: 157 } };
    await until('position lost, marked', async () => (await page.$eval('#drive-el-homing', (e) => e.classList.contains('io-bad'))), 5000);
    injected.axes = null;
    await until('the card hidden', async () => !(await page.isVisible('#drives-panel')), 5000);
  });

  await scenario('drives: the panel\'s status screen has the Drives line', page, async () => {
    injected.axes = { az: { brake: 'engaged', brake_released: false, current_a: 0.5 }, el: { homing: 'homed', held: null, pulse_count: 160 } };
    await page.goto(`${base}/panel`, { waitUntil: 'load' });
    await page.click('#status-btn');
    await until('the Drives line', async () => (await page.isVisible('#st-drives')) && (await text(page, '#st-drives')) === 'AZ brake engaged · 0.5 A; EL homed', 5000);
    injected.axes = null;
    await until('the Drives line hidden', async () => !(await page.isVisible('#st-drives')) && !(await page.isVisible('#st-drives-t')), 5000);
  });
}

// A game pad configured but not plugged in (docs/hardware.md "Buttons and a game pad"): the
// daemon's own reason shown in the Station I/O card, and no fault made of it.
async function gamepadStation(page) {
  writeStation('stop', '[gamepad]\ndevice = "/dev/input/by-id/azt-absent-pad-event-joystick"\n');
  await openStation(page);
  await scenario('game pad: an absent pad shows why it is not found, as no fault', page, async () => {
    const pad = (await state()).station_io.gamepad;
    if (!pad || pad.connected || pad.device !== '/dev/input/by-id/azt-absent-pad-event-joystick' || !/No such file/.test(pad.error || '')) {
      throw new Error(`station_io.gamepad: ${JSON.stringify(pad)}`);
    }
    await until('the pad line', async () => (await text(page, '#io-pad')) === `not found: ${pad.error}`, 5000);
    if (await page.$eval('#io-pad', (e) => e.classList.contains('io-bad'))) throw new Error('an absent pad is marked as a fault');
    if ((await state()).faults.length) throw new Error(`faults: ${JSON.stringify((await state()).faults)}`);
  });
}

async function main() {
  port = await freePort();
  base = useWebPort(port);
  writePolStation();
  await startDaemon();
  const browser = await launch({ '/': 'index.html', '/app.css': 'app.css', '/panel': 'panel.html', '/panel.css': 'panel.css' }, { viewport: { width: 1280, height: 800 } });
  const { page } = browser;
  try {
    await polStation(page);
    await plainStation(page);
    await fixedElStation(page);
    await dishStation(page);
    await drivesStation(page);
    await gamepadStation(page);
    checkPageErrors(browser.errors);
  } finally {
    await shutDown(browser);
  }
  summarise();
}

run(main);
