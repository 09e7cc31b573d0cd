// Browser test of the console's Schedule page (docs/satellites.md "The schedule", docs/web-api.md):
// Debian's Chromium driven by playwright-core against a real `azeltrack serve` on the simulated
// antenna, with three satellites whose element sets are from now and two of them in [[schedule]].
// The page must draw what GET /api/schedule plans (a row per scheduled satellite with its passes,
// the plan's steps on a lane, "now" inside the step the state says runs), say when the schedule
// is held and hand it back with Resume, and save the priority list as edited (a satellite found
// with the search, moved, one removed; a refusal shown beside its row, nothing saved). The
// browser runs in Asia/Kolkata (UTC+05:30), so that the local times differ from UTC.
// Usage: node schedule_page_test.js AZELTRACK OUT_DIR (AZT_WEB_DIR as for console_test.js)
'use strict';
const fs = require('fs');
const path = require('path');
const {
  setup, tleWithEpochNow, freePort, until, useWebPort, api, state, simConfig, setPassword, startDaemon,
  scenarioWithShots, loggedIn, text, launch, checkPageErrors, shutDown, summarise, run,
} = require('./harness');

const { outDir, config } = setup('schedule_page_test.js', 'azt-schedule-page-');
const PASSWORD = 'schedule-test-password';
const LOCAL_MS = 5.5 * 3600e3; // Asia/Kolkata

const schedule = async () => (await api('GET', '/api/schedule')).json;
const scenario = (name, page, body) => scenarioWithShots(name, page, outDir, body);
const hm = (ms) => new Date(ms).toISOString().slice(11, 16);

function writeConfig(port) {
  fs.writeFileSync(path.join(path.dirname(config), 'sats.tle'), tleWithEpochNow()
    + tleWithEpochNow('43017', 'AO-91 TEST', 120.0) + tleWithEpochNow('27607', 'SO-50 TEST', 20.0));
  fs.writeFileSync(config, `${simConfig('stop', port)}[satellites]
file = "sats.tle"
[[schedule]]
sat = "ISS"
min_el_deg = 10.0
[[schedule]]
sat = "AO-91"
preempt = "finish"
`);
  setPassword(PASSWORD);
}

async function login(page) {
  if (await loggedIn(page)) return;
  if (!(await page.isVisible('#password'))) await page.click('#login-state');
  await page.fill('#password', PASSWORD);
  await page.click('#login-btn');
  await until('the session', () => loggedIn(page));
}

// What the timeline shows: its rows' labels and bars, the lane's steps, and where "now" is, as
// boxes on the screen.
const drawn = (page) => page.evaluate(() => {
  const svg = document.getElementById('sch-timeline');
  const box = (e) => { const r = e.getBoundingClientRect(); return { left: r.left, right: r.right }; };
  return {
    rows: [...svg.querySelectorAll('.srow')].map((g) => ({ label: g.querySelector('.rowl').textContent, bars: g.querySelectorAll('rect.pass').length })),
    steps: [...svg.querySelectorAll('.lane rect')].map((r) => ({ cls: r.getAttribute('class'), ...box(r) })),
    now: svg.querySelector('#sch-now line') && svg.querySelector('#sch-now').style.display !== 'none' ? box(svg.querySelector('#sch-now line')) : null,
    ticks: [...svg.querySelectorAll('text.tick')].map((t) => t.textContent),
  };
});

async function openSchedule(page) {
  await page.click('#nav-targets');
  await page.click('#schedule-link-sats');
  await until('the Schedule page', () => page.isVisible('#sch-timeline'), 5000);
}

async function main() {
  const port = await freePort();
  const base = useWebPort(port);
  writeConfig(port);
  await startDaemon();
  const browser = await launch({ '/': 'index.html', '/app.css': 'app.css' }, { viewport: { width: 1280, height: 800 }, timezoneId: 'Asia/Kolkata' });
  const { page } = browser;
  try {
    await page.goto(base + '/', { waitUntil: 'load' });
    await until('live numbers', async () => /\d/.test(await text(page, '#ant-az')));
    const plan = await until('the first plan', async () => { const s = await schedule(); return s && s.from && s.plan.length && s; }, 15000, 200);

    await scenario('the next 24 hours: a row per satellite with its passes, the plan on its lane, now', page, async () => {
      await openSchedule(page);
      if ((await page.getAttribute('#nav-targets', 'aria-selected')) !== 'true') throw new Error('the Targets tab is not lit on the Schedule page');
      await until('the timeline drawn', async () => (await drawn(page)).rows.length === 2, 5000);
      const d = await drawn(page);
      const t0 = Date.parse(plan.from); const t1 = t0 + plan.hours * 3600e3;
      const inside = (a, b) => Date.parse(b) > t0 && Date.parse(a) < t1;
      const want = [['1. ISS', 'ISS (ZARYA)'], ['2. AO-91', 'AO-91 TEST']].map(([label, sat]) =>
        ({ label, bars: plan.passes.filter((p) => p.sat === sat && inside(p.aos, p.los)).length }));
      if (JSON.stringify(d.rows) !== JSON.stringify(want)) throw new Error(`rows ${JSON.stringify(d.rows)}, the plan's passes ${JSON.stringify(want)}`);
      if (!want[0].bars || !want[1].bars) throw new Error(`a satellite without passes in 24 h: ${JSON.stringify(want)}`);
      const steps = plan.plan.filter((s) => inside(s.from, s.to));
      if (d.steps.length !== steps.length || d.steps.some((s, i) => s.cls !== `seg seg-${steps[i].kind}`)) {
        throw new Error(`lane ${JSON.stringify(d.steps.map((s) => s.cls))}, plan ${JSON.stringify(steps.map((s) => s.kind))}`);
      }
      // Hours in UTC with the local time under them.
      const tick = d.ticks.findIndex((t) => /^\d\d:00$/.test(t));
      const utcMs = Date.parse(`${new Date(t0).toISOString().slice(0, 10)}T${d.ticks[tick]}:00Z`);
      if (d.ticks[tick + 1] !== hm(utcMs + LOCAL_MS)) throw new Error(`ticks ${d.ticks.slice(0, 6)}: no local time under ${d.ticks[tick]}`);
      // "Now" within the step the plan has at the daemon's now, or before the next one.
      const nowMs = Date.parse((await state()).utc);
      const at = steps.findIndex((s) => Date.parse(s.from) <= nowMs && nowMs < Date.parse(s.to));
      const next = steps.findIndex((s) => Date.parse(s.from) > nowMs);
      if (!d.now) throw new Error('no "now" line');
      if (at >= 0 ? !(d.now.left >= d.steps[at].left - 1.5 && d.now.right <= d.steps[at].right + 1.5)
        : next >= 0 && d.now.right > d.steps[next].left + 1.5) throw new Error(`now at ${JSON.stringify(d.now)}, step ${at}/${next}: ${JSON.stringify(d.steps)}`);
      // The next step in words, with its start in UTC, local and a countdown.
      const s = (await state()).schedule;
      if (s && s.next) {
        await until('the next step', async () => (await text(page, '#sch-next')).includes(s.next.sat || ''), 3000);
        const at2 = await text(page, '#sch-next-at');
        const start = Date.parse(s.next.from);
        if (!at2.startsWith(`${hm(start)} UTC (${hm(start + LOCAL_MS)} local), in `)) throw new Error(`next at: ${at2} (${s.next.from})`);
      }
      if ((await page.$$('#sch-plan-rows tr')).length !== plan.plan.length) throw new Error('the plan table has not every step');
    });

    await scenario('held by another command: said, and Resume hands the antenna back', page, async () => {
      await login(page);
      await page.click('#nav-targets');
      await page.click('#tgt-moon');
      await until('the schedule held', async () => { const s = (await state()).schedule; return s && s.held_by; }, 5000);
      await openSchedule(page);
      await until('HELD on the page', async () => (await text(page, '#sch-badge')) === 'HELD' && page.isVisible('#sch-held'), 5000);
      const who = (await state()).schedule.held_by;
      if (!(await text(page, '#sch-held-text')).includes(`Held by ${who}`)) throw new Error(`held: ${await text(page, '#sch-held-text')}`);
      await page.click('#sch-resume');
      await until('the schedule running again', async () => { const s = (await state()).schedule; return s && s.running && !s.held_by; }, 5000);
      await until('RUNNING on the page', async () => (await text(page, '#sch-badge')) === 'RUNNING' && !(await page.isVisible('#sch-held')), 5000);
    });

    await scenario('the priority list edited: found by the search, moved up, one removed, saved and followed', page, async () => {
      await page.click('#sch-add');
      const row3 = '#sch-rows .sch-row:nth-child(3)';
      await page.fill(`${row3} .sat-in`, '27607');
      await until('the search\'s answer', () => page.isVisible(`${row3} .sugg`), 3000);
      const offered = await text(page, `${row3} .sugg`);
      if (offered !== 'SO-50 TEST · 27607') throw new Error(`offered: ${offered}`);
      await page.click(`${row3} .sugg`);
      await page.fill(`${row3} [data-field="min_el_deg"]`, '15');
      await page.click(`${row3} .up`);
      await page.click('#sch-rows .sch-row:nth-child(3) .rm');
      if ((await text(page, '#sch-count')) === '') throw new Error('the edit is not marked as not saved');
      await page.click('#sch-save');
      await until('the list followed', async () => JSON.stringify((await schedule()).entries.map((e) => [e.sat, e.min_el_deg])) === '[["ISS",10],["SO-50 TEST",15]]', 5000);
      const file = fs.readFileSync(config, 'utf8');
      if (!/\[\[schedule\]\]\s*\nsat = "ISS"[^[]*\[\[schedule\]\]\s*\nsat = "SO-50 TEST"/.test(file) || file.includes('AO-91')) throw new Error(`the file's [[schedule]]: ${file.slice(file.indexOf('[[schedule'))}`);
      await until('the new rows on the timeline', async () => JSON.stringify((await drawn(page)).rows.map((r) => r.label)) === '["1. ISS","2. SO-50 TEST"]', 8000);
      if (!(await page.isDisabled('#sch-save'))) throw new Error('Save still enabled after the save');
    });

    await scenario('a refusal names its row and saves nothing', page, async () => {
      await page.fill('#sch-rows .sch-row:nth-child(2) .sat-in', 'ISS');
      await page.click('#sch-save');
      await until('the refusal', async () => (await text(page, '#sch-save-error')).startsWith('Nothing was saved'), 5000);
      const beside = await text(page, '#sch-rows .sch-row:nth-child(2) .sch-err');
      if (!beside) throw new Error(`no word beside row 2 (${await text(page, '#sch-save-error')})`);
      if ((await schedule()).entries.length !== 2 || (await schedule()).entries[1].sat !== 'SO-50 TEST') throw new Error('a refused list was saved');
      await page.click('#sch-undo');
      if ((await page.inputValue('#sch-rows .sch-row:nth-child(2) .sat-in')) !== 'SO-50 TEST') throw new Error('Undo did not bring the list back');
    });
  } finally {
    checkPageErrors(browser.errors);
    await shutDown(browser);
  }
  summarise();
}

run(main);
