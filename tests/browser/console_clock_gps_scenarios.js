// The station's clock and GPS in the console's header and on their pages (console_test.js runs
// it): the banner and the Time page with NTP servers saved, the GPS icon's colours fed by gpsfake,
// its page and sky plot.
'use strict';
const fs = require('fs');
const path = require('path');
const { until, state, text } = require('./harness');
const { startGpsfake, stopGpsfake, hasProgram } = require('./console_feeds');
const { colourIs } = require('./console_probes');

/// The scenarios in order, on the test's page; `t` is what console_test.js shares with them.
async function runClockGpsScenarios(t) {
  const { page, scenario, login, sourcesFile } = t;
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
}

module.exports = { runClockGpsScenarios };
