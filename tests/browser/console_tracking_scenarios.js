// The console's main work in the browser (console_test.js runs it): STOP and refusals without a
// login, tracking on screen, the Moon and its data, the station I/O panel, satellites (their
// passes, a search, an upload), a manual +0.01° and a refused locator.
'use strict';
const fs = require('fs');
const { until, api, state, text } = require('./harness');
const { tleWithEpochNow } = require('./console_feeds');

/// The scenarios in order, on the test's page; `t` is what console_test.js shares with them.
async function runTrackingScenarios(t) {
  const { page, scenario, login, config, apiGet } = t;
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
    if ((await text(page, '#io-pad')) !== 'none set' || io.gamepad !== null) throw new Error(`game pad: ${await text(page, '#io-pad')}, ${JSON.stringify(io.gamepad)}`);
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
    const planned = (await state()).target.satellite;
    const aos = Date.parse(planned.aos);
    const marked = await text(page, '#sky-pass-aos');
    const could = [aos, aos + 10e3].map((t) => `AOS ${new Date(t).toISOString().slice(11, 16)}`);
    if (planned.phase === 'waiting for AOS' && !could.includes(marked)) {
      throw new Error(`AOS mark: ${marked} (AOS ${new Date(aos).toISOString()})`);
    }
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
}

module.exports = { runTrackingScenarios };
