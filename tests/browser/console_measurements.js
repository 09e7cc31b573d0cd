// The console's closing measurements (console_test.js runs them): the first load's weight, a
// pass/fail budget, and how long a state change takes to reach the page (printed, not judged).
'use strict';
const { until, text, pageWeight, scenario: check } = require('./harness');

const WEIGHT_BUDGET = 200 * 1000; // the console's first load, uncompressed (docs/web-api.md)
// The pages' modules loaded when the page is first opened (navigation.js), not at start.
const LAZY_MODULES = ['/js/planner.js', '/js/scan.js', '/js/software.js', '/js/settings.js', '/js/settings_account.js'];

/// The measurements on the test's browser and page; `t` is what console_test.js shares.
async function measureConsole(t) {
  const { browser, base, page } = t;
  // Measurements (not pass/fail): page weight and state-change -> DOM latency. Sessions live in
  // the daemon's memory, so the restarts earlier logged the page out (login() is a no-op if not).
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
}

module.exports = { measureConsole };
