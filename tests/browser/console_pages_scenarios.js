// Every page of the console at desktop and phone sizes (console_test.js runs it): the Network page,
// the phone's header, notices that never cover STOP, the Setup footer, and each page shown and
// screenshot without an error.
'use strict';
const fs = require('fs');
const path = require('path');
const { DESKTOP, PHONE, sleep, until, state } = require('./harness');
const { someToasts, toastProblems } = require('./console_probes');

/// The scenarios in order, on the test's page; `t` is what console_test.js shares with them.
async function runPageScenarios(t) {
  const { page, scenario, check, login, outDir } = t;
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
}

module.exports = { runPageScenarios };
