// The Moon planner page (console_test.js runs it): the common windows as the operator types, the
// same as the API's, and a table that fits or says it scrolls at every size.
'use strict';
const { DESKTOP, PHONE, until, text } = require('./harness');
const { plannerCue } = require('./console_probes');

/// The scenarios in order, on the test's page; `t` is what console_test.js shares with them.
async function runPlannerScenario(t) {
  const { page, scenario, apiGet } = t;
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
}

module.exports = { runPlannerScenario };
