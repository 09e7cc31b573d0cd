// Browser tests of the console's Settings (docs/web-api.md "The console's screens"):
// Debian's Chromium driven by playwright-core against a real `azeltrack serve` on the simulated
// antenna. Every section of the configuration file is a form built from GET /api/config/schema;
// one value changed in a form is read back from the file on disk (`azeltrack config get`) and is
// either applied (the live state) or listed as waiting for a restart; an invalid value is refused
// beside the key it names and the file is left byte for byte as it was. The parts whose API may
// not be in the daemon yet (restart, the whole file, password, tokens, the direction test) first
// ask the daemon (settings_backend.js): a 404 records the scenario as skipped with the reason.
// Screenshots at 1280×800 and 390×844 go to OUT_DIR.
// Usage: node settings_test.js AZELTRACK OUT_DIR (AZT_WEB_DIR=web: the console's files from disk)
'use strict';
const { spawnSync } = require('child_process');
const fs = require('fs');
const path = require('path');
const {
  setup, freePort, sleep, until, useWebPort, api, simConfig, setPassword, startDaemon, scenario, text,
  launch, checkPageErrors, shutDown, summarise, run,
} = require('./harness');
const {
  ctx, schema, slug, login, openSettings, openSection, changeAndCheck, refuseAndCheck,
} = require('./settings_lib');
const backend = require('./settings_backend');

const { bin, outDir, tmp, config } = setup('settings_test.js', 'azt-settings-');
Object.assign(ctx, { bin, config, tmp, password: 'settings-test-password' });
const DESKTOP = { width: 1280, height: 800 };
const PHONE = { width: 390, height: 844 };

function writeConfig(port) {
  fs.writeFileSync(config, simConfig('stop', port));
  setPassword(ctx.password);
  const r = spawnSync(bin, ['web', 'token', '--config', config], { encoding: 'utf8' });
  ctx.token = (r.stdout || '').trim().split('\n')[0];
  if (r.status !== 0 || !/^[0-9a-f]{64}$/.test(ctx.token)) throw new Error(`web token: ${r.stderr}`);
}

// One value changed in each of these sections' forms. `live`: applied at once, seen in the state.
function changes(rotctldPort) {
  return [
    { name: '[control] window_deg', section: 'control', route: 'control', set: { window_deg: '0.25' }, expect: { window_deg: 0.25 } },
    { name: '[rotctld] port', section: 'rotctld', route: 'rotctld', set: { port: rotctldPort }, expect: { port: rotctldPort } },
    { name: '[gps] enabled and min_sats', section: 'gps', route: 'gps', set: { enabled: true, min_sats: '6' }, expect: { enabled: true, min_sats: 6 } },
    { name: '[log] level', section: 'log', route: 'log', set: { level: 'debug' }, expect: { level: 'debug' } },
    { name: '[sequencer] tx_timeout_s and hold_motion', section: 'sequencer', route: 'sequencer', set: { tx_timeout_s: '300', hold_motion: false }, expect: { tx_timeout_s: 300, hold_motion: false } },
    { name: '[sequencer] outputs, one a line', section: 'sequencer', route: 'sequencer', set: { outputs: 'preamp\nradio' }, expect: { outputs: ['preamp', 'radio'] } },
    { name: '[hardware.az] window_deg with the sim backend', section: 'hardware.az', route: 'hardware.az', set: { window_deg: '0.8' }, expect: { window_deg: 0.8 } },
    { name: '[sim.az] fault', section: 'sim.az', route: 'sim.az', set: { fault: 'reversed_motor' }, expect: { fault: 'reversed_motor' } },
    { name: '[station] grid, live', section: 'station', route: 'station', set: { grid: 'FN06HF' }, expect: { grid: 'FN06HF' }, live: (s) => s.station.grid === 'FN06HF' },
    { name: '[corrections] az_offset_deg, live', section: 'corrections', route: 'corrections', set: { az_offset_deg: '0.12' }, expect: { az_offset_deg: 0.12 }, live: (s) => Math.abs(s.corrections.az_offset_deg - 0.12) < 1e-9 },
    { name: '[sky] band, live', section: 'sky', route: 'sky', set: { band: '1296' }, expect: { band: '1296' }, live: (s) => s.moon.band === '1296' },
    { name: '[[park]] #1 added, live', section: 'park', route: 'park/1', add: true, set: { name: 'dish south', az_deg: '175', el_deg: '5' }, expect: { name: 'dish south', az_deg: 175, el_deg: 5 },
      live: async () => { const t = (await api('GET', '/api/targets')).json; return t.park[0].name === 'dish south' && t.park[0].az_deg === 175; } },
    // An array of tables inside a table: saved in [satellites], read back from the file.
    { name: '[[satellites.transmitter]] #1 added', section: 'satellites.transmitter', route: 'satellites.transmitter/1', add: true, set: { norad: '43017', downlink_mhz: '145.96', mode: 'linear_inverting', uplink_mhz: '435.65' }, expect: { norad: '43017', downlink_mhz: 145.96, mode: 'linear_inverting', uplink_mhz: 435.65 } },
  ];
}
// Refused: by the daemon, naming the key, or (`local`) by the page before anything is sent.
const REFUSALS = [
  { name: '[control] window_deg 5 (0 to 2)', section: 'control', route: 'control', set: { window_deg: '5' }, field: 'window_deg', words: 'window_deg must be 0 to 2' },
  { name: '[gps] min_sats 2 (3 to 64)', section: 'gps', route: 'gps', set: { min_sats: '2' }, field: 'min_sats', words: 'min_sats' },
  { name: '[station] lat_deg without lon_deg', section: 'station', route: 'station', set: { grid: '', lat_deg: '45' }, field: 'lat_deg', words: 'lon_deg' },
  { name: '[sequencer] delays_ms not numbers (the page)', section: 'sequencer', route: 'sequencer', set: { delays_ms: '20, x' }, field: 'delays_ms', words: 'not a list of numbers', local: true },
];

// Every section of the schema on the page, by chapter, each key with the input its type calls
// for, its badge, default and range; secrets never on the page. Reading needs no login.
async function everySection(page) {
  await openSettings(page);
  const sch = await schema();
  const shown = await page.$$eval('details.sset[data-section]', (ds) => ds.map((d) => d.dataset.section).filter((n) => n !== 'direction-test'));
  const want = sch.sections.map((s) => s.name);
  if (JSON.stringify(shown) !== JSON.stringify(want)) throw new Error(`sections shown ${shown.length}, schema ${want.length}: ${want.filter((n) => !shown.includes(n))}`);
  const chapters = [...new Set(sch.sections.map((s) => s.chapter))];
  const headings = await page.$$eval('#settings-body .chapter > h2', (hs) => hs.map((x) => x.textContent));
  if (JSON.stringify(headings) !== JSON.stringify(chapters)) throw new Error(`chapters ${headings}`);
  let badges = 0;
  for (const s of sch.sections) badges += (s.array_of_tables ? (s.items || []).length + 1 : 1) * s.keys.filter((k) => k.applies === 'restart').length;
  const shownBadges = await page.$$eval('#settings-body .skey .t-restart', (b) => b.length);
  if (shownBadges !== badges) throw new Error(`${shownBadges} restart badges for ${badges} keys applied at restart`);
  const kinds = await page.evaluate(() => {
    const q = (s) => document.querySelector(s);
    const w = q('#cfg-control-window_deg');
    return { lead: q('#cfg-control-lead').type, level: [...q('#cfg-log-level').options].map((o) => o.value),
      window: [w.type, w.min, w.max, w.step], outputs: q('#cfg-sequencer-outputs').tagName,
      tilt: q('#cfg-corrections-tilt_el_deg').tagName, help: q('[data-key="window_deg"] .skey-help').textContent,
      secret: !!q('input#cfg-web-password_hash, #cfg-web-password_hash[data-field]'), unit: q('[data-key="window_deg"] .unit').textContent };
  });
  const expect = { lead: 'checkbox', level: ['', 'debug', 'info', 'warn'], window: ['number', '0', '2', 'any'], outputs: 'TEXTAREA', tilt: 'TEXTAREA', secret: false, unit: '°' };
  for (const [k, v] of Object.entries(expect)) if (JSON.stringify(kinds[k]) !== JSON.stringify(v)) throw new Error(`${k}: ${JSON.stringify(kinds[k])}`);
  if (!/Default 0°.*0 to 2/.test(kinds.help)) throw new Error(`window_deg's help: ${kinds.help}`);
  const hash = /password_hash = "([^"]+)"/.exec(fs.readFileSync(config, 'utf8'))[1];
  if ((await page.content()).includes(hash.slice(-20))) throw new Error('the password hash is on the page');
  // Read-only keys (a token's label) cannot be edited, in every item of an array of tables.
  for (const s of sch.sections) for (const k of s.keys.filter((x) => x.access === 'read_only')) {
    const sel = s.array_of_tables ? `form[data-route^="${s.name}/"] [data-field="${k.key}"]` : `#cfg-${slug(s.name)}-${k.key}`;
    const states = await page.$$eval(sel, (es) => es.map((e) => e.disabled));
    if (!s.array_of_tables && states.length !== 1) throw new Error(`${s.name}.${k.key} is not shown`);
    if (states.some((d) => !d)) throw new Error(`${s.name}.${k.key} is read-only but editable`);
  }
}

// The keyboard alone: a section opened from its summary, Tab to its first field.
async function keyboard(page) {
  await openSettings(page);
  await page.focus('#sec-log > summary');
  await page.keyboard.press('Enter');
  if (!(await page.$eval('#sec-log', (d) => d.open))) throw new Error('Enter did not open [log]');
  await page.keyboard.press('Tab');
  const focused = await page.evaluate(() => document.activeElement.id);
  if (focused !== 'cfg-log-level') throw new Error(`Tab went to ${focused}`);
  await page.keyboard.press('Shift+Tab');
  await page.keyboard.press('Enter');
  if (await page.$eval('#sec-log', (d) => d.open)) throw new Error('Enter did not close [log]');
}

// Screenshots, and at phone size every section open with nothing wider than the screen and
// each key's field below its name.
async function shots(page) {
  await openSettings(page);
  await page.evaluate(() => {
    document.querySelectorAll('#settings-body details[open]').forEach((d) => { d.open = false; });
    document.querySelectorAll('#toasts > *').forEach((t) => t.remove());
  });
  if (await page.isVisible('#clock-dismiss')) await page.click('#clock-dismiss');
  await openSection(page, 'control');
  await openSection(page, 'direction-test');
  await page.setViewportSize(DESKTOP);
  await page.evaluate(() => window.scrollTo(0, 0));
  await sleep(200);
  await page.screenshot({ path: path.join(outDir, 'settings-desktop.png') });
  await page.screenshot({ path: path.join(outDir, 'settings-desktop-full.png'), fullPage: true });
  await page.setViewportSize(PHONE);
  await page.evaluate(() => window.scrollTo(0, 0));
  await sleep(200);
  await page.screenshot({ path: path.join(outDir, 'settings-phone.png') });
  await page.screenshot({ path: path.join(outDir, 'settings-phone-full.png'), fullPage: true });
  await page.evaluate(() => document.querySelectorAll('#settings-body details').forEach((d) => { d.open = true; }));
  await sleep(200);
  const wide = await page.evaluate(() => ({ page: document.documentElement.scrollWidth, view: window.innerWidth,
    over: [...document.querySelectorAll('#screen-settings *')].filter((e) => e.getBoundingClientRect().right > window.innerWidth + 0.5).map((e) => e.id || e.className).slice(0, 5) }));
  if (wide.page > wide.view || wide.over.length) throw new Error(`wider than the phone: ${JSON.stringify(wide)}`);
  const stacked = await page.$eval('#cfg-control-window_deg', (i) => {
    const row = i.closest('.skey');
    return i.getBoundingClientRect().top >= row.querySelector('.skey-l').getBoundingClientRect().bottom - 1;
  });
  if (!stacked) throw new Error('at phone size the field is not below its name');
  await page.evaluate(() => document.querySelectorAll('#settings-body details').forEach((d) => { d.open = false; }));
  await page.setViewportSize(DESKTOP);
}

async function main() {
  const port = await freePort();
  const rotctldPort = await freePort();
  const base = useWebPort(port);
  writeConfig(port);
  await startDaemon();
  const browser = await launch({ '/': 'index.html', '/app.css': 'app.css' }, { viewport: DESKTOP });
  const { page, errors } = browser;
  page.on('request', (r) => {
    const p = new URL(r.url()).pathname;
    if (r.method() === 'PUT' && p.startsWith('/api/config/') && p !== '/api/config/file') ctx.puts.push({ route: p.slice(12), body: r.postDataJSON() });
  });
  try {
    await page.goto(base + '/', { waitUntil: 'load' });
    await until('live numbers', async () => /\d/.test(await text(page, '#ant-az')));
    await scenario('every section of the schema, by chapter, with the input its type calls for', () => everySection(page));
    await scenario('the settings by keyboard alone', () => keyboard(page));
    for (const c of changes(rotctldPort)) await scenario(`changed in the form: ${c.name}`, () => changeAndCheck(page, c));
    for (const c of REFUSALS) await scenario(`refused, nothing saved: ${c.name}`, () => refuseAndCheck(page, c));
    await scenario('screenshots at 1280×800 and 390×844; nothing wider than a phone', () => shots(page));
    await backend.run(page, { outDir, rotctldPort, DESKTOP, PHONE });
  } finally {
    checkPageErrors(errors);
    await shutDown(browser);
  }
  summarise();
}

run(main);
