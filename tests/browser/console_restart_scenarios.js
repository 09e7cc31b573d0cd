// The console across daemon restarts (console_test.js runs it): a saved tilt-table edit is there
// after one, and the live view reconnects by itself.
'use strict';
const { until, api, startDaemon, stopDaemon, text } = require('./harness');

/// The scenarios in order, on the test's page; `t` is what console_test.js shares with them.
async function runRestartScenarios(t) {
  const { page, scenario } = t;
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
}

module.exports = { runRestartScenarios };
