// Browser test of the touch panel (/panel, docs/panel.md): Debian's Chromium driven by
// playwright-core at the 4" display's 480×320 with touch (every action a tap), against a real
// `azeltrack serve` on the simulated antenna, started by harness.js as for console_test.js. Each
// scenario checks what the operator sees and what the daemon did; a screenshot of each screen goes
// to OUT_DIR.
// Usage: node panel_test.js AZELTRACK OUT_DIR
// AZT_WEB_DIR=web serves the page's files from that directory instead of the copy built into
// AZELTRACK (to try an edit of web/ without a rebuild; the API and the WebSocket stay the daemon's).
'use strict';
const crypto = require('crypto');
const fs = require('fs');
const path = require('path');
const {
  setup, freePort, until, useWebPort, api, state, simConfig, setPassword, startDaemon,
  scenario, loggedIn, text, launch, pageWeight, checkPageErrors, shutDown, summarise, run,
} = require('./harness');

const { outDir, tmp, config } = setup('panel_test.js', 'azt-panel-');
const W = 480;
const H = 320;
const MIN_PX = 44; // the smallest control a finger hits reliably
const WEIGHT_BUDGET = 100 * 1024; // html + css + every module the panel loads, uncompressed
// A capital and digits, so that the keyboard's ⇧ and its 123 layer are used.
const PASSWORD = 'Panel-test-17';
const TOKEN = crypto.randomBytes(16).toString('hex'); // a script's bearer token, to set the scene

function writeConfig(port) {
  // The token's hash belongs in [web], which simConfig leaves open at the end.
  const tokenHash = crypto.createHash('sha256').update(TOKEN).digest('hex');
  fs.writeFileSync(config, `${simConfig('sun', port)}api_token_sha256 = "${tokenHash}"
[mount.pol]
max_rate_deg_s = 10.0
[pol]
mode = "fixed"
fixed_deg = 20.0
[time]
chrony_socket = "${path.join(tmp, 'nonexistent.sock')}"
poll_s = 1
`);
  setPassword(PASSWORD);
}

const num = (t) => parseFloat(String(t).replace('−', '-'));
const visible = (page, sel) => page.isVisible(sel);

// The rules of a screen at 480×320 (docs/panel.md): nothing scrolls, the document or any box in it;
// every visible control is 44×44 px or more and wholly on the screen; STOP is on the screen and
// not covered. Returns the problems found.
async function screenProblems(page) {
  return page.evaluate(([minPx]) => {
    const out = [];
    const vw = window.innerWidth; const vh = window.innerHeight;
    const de = document.documentElement;
    if (de.scrollWidth > vw) out.push(`the page scrolls sideways (${de.scrollWidth} px wide)`);
    if (de.scrollHeight > vh) out.push(`the page scrolls (${de.scrollHeight} px high)`);
    for (const e of document.querySelectorAll('body *')) {
      if (!e.checkVisibility()) continue;
      const cs = getComputedStyle(e);
      const scrolls = (o) => o === 'auto' || o === 'scroll';
      if ((scrolls(cs.overflowY) && e.scrollHeight > e.clientHeight) || (scrolls(cs.overflowX) && e.scrollWidth > e.clientWidth)) {
        out.push(`#${e.id || e.className} scrolls`);
      }
    }
    const name = (e) => `${e.tagName.toLowerCase()}${e.id ? `#${e.id}` : ''}${e.dataset.k !== undefined ? `[data-k="${e.dataset.k}"]` : ''} “${(e.textContent || e.placeholder || '').trim().slice(0, 20)}”`;
    for (const e of document.querySelectorAll('button, input, select, textarea, a[href], [role="button"]')) {
      if (!e.checkVisibility({ visibilityProperty: true })) continue;
      const r = e.getBoundingClientRect();
      if (r.width < minPx || r.height < minPx) out.push(`${name(e)} is ${r.width.toFixed(1)}×${r.height.toFixed(1)} px`);
      if (r.left < 0 || r.top < 0 || r.right > vw + 0.5 || r.bottom > vh + 0.5) out.push(`${name(e)} is off the screen`);
    }
    // Text held on one line must fit its box: a line running off the 480 px screen is cut off.
    for (const e of document.querySelectorAll('body *')) {
      if (!e.checkVisibility() || getComputedStyle(e).whiteSpace !== 'nowrap' || !e.textContent.trim()) continue;
      const r = e.getBoundingClientRect();
      if (e.scrollWidth > e.clientWidth + 1 || r.right > vw + 0.5 || r.left < -0.5) out.push(`${name(e)} runs out of its box`);
    }
    const stop = document.getElementById('btn-stop');
    const r = stop.getBoundingClientRect();
    const hit = document.elementFromPoint(r.left + r.width / 2, r.top + r.height / 2);
    if (!stop.checkVisibility() || r.left < 0 || r.top < 0 || r.right > vw || r.bottom > vh || hit !== stop) {
      out.push('STOP is not on the screen');
    }
    return out;
  }, [MIN_PX]);
}
async function checkScreen(page, shot) {
  const problems = await screenProblems(page);
  await page.screenshot({ path: path.join(outDir, `${shot}.png`) });
  if (problems.length) throw new Error(`${shot}: ${problems.join('; ')}`);
}

// One character on the on-screen keyboard: the layer it is on (the shared key switches abc and
// 123), ⇧ for capitals, then its key. Covers what PASSWORD holds.
async function tapKey(page, ch) {
  const want = /[0-9]/.test(ch) ? 'num' : /[a-zA-Z.-]/.test(ch) ? 'abc' : null;
  if (!want) throw new Error(`the test does not type “${ch}”`);
  if ((await page.getAttribute('#keys', 'data-layer')) !== want) await page.tap('#keys > [data-do^="layer:"]');
  if (/[a-zA-Z]/.test(ch)) {
    const lit = await page.$eval('#keys [data-do="shift"]', (b) => b.classList.contains('lit'));
    if (lit !== /[A-Z]/.test(ch)) await page.tap('#keys [data-do="shift"]');
  }
  await page.locator(`#keys [data-k=${JSON.stringify(ch)}]`).locator('visible=true').first().tap();
}
async function typePassword(page) {
  for (const ch of PASSWORD) await tapKey(page, ch);
  const typed = await page.inputValue('#password');
  if (typed !== PASSWORD) throw new Error(`the keyboard typed “${typed}”`);
  await page.tap('#login-btn');
}

// Taps and waits for the screen it leads to.
async function tapTo(page, sel, screen) {
  await page.tap(sel);
  await until(`the ${screen} screen`, () => visible(page, `#screen-${screen}`), 3000);
}
async function toMain(page) {
  for (let i = 0; i < 3 && await visible(page, '#back'); i++) await page.tap('#back');
  await until('the main screen', () => visible(page, '#screen-main'), 3000);
}
// A manual move by a script (bearer token), so that a STOP has something to stop.
async function moving() {
  const r = await api('POST', '/api/target', { az_deg: 100, el_deg: 30 }, TOKEN);
  if (r.status !== 200) throw new Error(`manual move: ${r.status} ${JSON.stringify(r.json)}`);
  await until('MAN', async () => (await state()).mode === 'MAN', 3000);
}

async function main() {
  const port = await freePort();
  const base = useWebPort(port);
  writeConfig(port);
  await startDaemon();
  // With AZT_WEB_DIR (see the top), the panel's page and style sheet come from there.
  const browser = await launch({ '/panel': 'panel.html', '/panel.css': 'panel.css' },
    { viewport: { width: W, height: H }, hasTouch: true });
  const { page } = browser;
  try {
    await page.goto(`${base}/panel`, { waitUntil: 'load' });
    await until('live numbers', async () => /\d/.test(await text(page, '#ant-az')));

    await scenario('reading is open: A–D agree with /api/state without a login', async () => {
      if (await loggedIn(page)) throw new Error('logged in before any login');
      if (await visible(page, '#login-form')) throw new Error('the keyboard is shown before any action');
      // Read a moment apart, page and state agree (to the 0.01° shown) once the antenna is still.
      let diff = null;
      await until('the page to show the state', async () => {
        const shown = {};
        for (const id of ['target-name', 'target-az', 'target-el', 'ant-az', 'ant-el', 'az-corr', 'el-corr', 'utc', 'status-line']) shown[id] = await text(page, `#${id}`);
        const s = await state();
        const near = (t, v, tol) => Math.abs(num(t) - v) <= tol;
        const ok = shown['target-name'].toLowerCase() === 'sun' &&
          near(shown['target-az'], s.target.az_deg, 0.011) && near(shown['target-el'], s.target.el_deg, 0.011) &&
          near(shown['ant-az'], s.antenna.az_deg, 0.011) && near(shown['ant-el'], s.antenna.el_deg, 0.011) &&
          near(shown['az-corr'], s.corrections.az_user_deg, 1e-9) && near(shown['el-corr'], s.corrections.el_user_deg, 1e-9) &&
          shown['status-line'].startsWith(`${s.mode} · `) && /^\d\d:\d\d:\d\d$/.test(shown.utc) &&
          shown.utc.slice(0, 5) === s.utc.slice(11, 16);
        diff = { shown, state: { mode: s.mode, utc: s.utc, target: s.target, antenna: s.antenna, corrections: s.corrections } };
        return ok;
      }, 15000, 200).catch(() => { throw new Error(`page and state differ: ${JSON.stringify(diff)}`); });
      if (await visible(page, '#echo-row')) throw new Error('the Echo line is shown with the Sun as the target');
      await checkScreen(page, 'main');
    });

    await scenario('the polarisation axis shows its angle as read and its mode', async () => {
      let last = null;
      await until('the pol line to show the state', async () => {
        const s = await state();
        const shown = await visible(page, '#pol-row') ? await text(page, '#pol-angle') : null;
        last = { shown, pol: s.pol };
        return shown !== null && s.pol !== null && shown.endsWith(' fixed') &&
          Math.abs(num(shown) - s.pol.mount_deg) <= 0.06 && Math.abs(s.pol.mount_deg - 20) < 1;
      }, 15000, 200).catch(() => { throw new Error(`pol line: ${JSON.stringify(last)}`); });
      await checkScreen(page, 'main-pol');
    });

    await scenario('MOON asks for the password on the keyboard, then tracks the Moon and shows its echo', async () => {
      await tapTo(page, '#target-pick', 'targets');
      // Sun, Moon and the daemon's radio sources, six a page.
      const targets = (await api('GET', '/api/targets')).json;
      const want = targets.targets.filter((t) => t.kind === 'source').map((t) => t.name);
      await until('the sources', async () => (await page.$$('#sources [data-name]')).length === Math.min(6, want.length), 3000);
      await checkScreen(page, 'targets');
      const seen = [];
      for (let p = 0; p < Math.ceil(want.length / 6); p++) {
        seen.push(...await page.$$eval('#sources [data-name]', (b) => b.map((x) => x.dataset.name)));
        if (want.length > 6) await page.tap('#src-next');
      }
      if (JSON.stringify(seen) !== JSON.stringify(want)) throw new Error(`sources shown ${JSON.stringify(seen)}, the daemon's ${JSON.stringify(want)}`);
      const before = await state();
      await page.tap('#tgt-moon');
      await until('the keyboard', () => visible(page, '#login-form'), 3000);
      await checkScreen(page, 'login');
      const still = await state();
      if (still.mode !== before.mode || still.target.name !== before.target.name) throw new Error('the target changed without a login');
      await typePassword(page);
      await until('the Moon tracked, with no second tap', async () => {
        const s = await state();
        return s.mode === 'TRACK' && s.target.name === 'Moon';
      }, 8000);
      await until('the main screen', () => visible(page, '#screen-main'), 3000);
      if (await visible(page, '#login-form')) throw new Error('the keyboard stayed open');
      if ((await text(page, '#login-state')) !== 'Logged in') throw new Error(`login pill: ${await text(page, '#login-state')}`);
      await until('the Echo line with the Moon\'s Doppler', async () => {
        if (!(await visible(page, '#echo-row'))) return false;
        const hz = (await state()).moon.echo_doppler_hz;
        return Math.abs(num(await text(page, '#doppler')) - hz) <= 2;
      }, 3000);
      if ((await text(page, '#target-name')).toLowerCase() !== 'moon') throw new Error(`target button: ${await text(page, '#target-name')}`);
      await checkScreen(page, 'main-moon');
    });

    await scenario('SUN hides the Echo line', async () => {
      await tapTo(page, '#target-pick', 'targets');
      await page.tap('#tgt-sun');
      await until('the Sun tracked', async () => (await state()).target.name === 'Sun', 5000);
      await until('the Echo line to go', async () => !(await visible(page, '#echo-row')), 3000);
      if (await visible(page, '#login-form')) throw new Error('asked for the password again');
    });

    await scenario('the session outlives a reload; ± and UP/DWN change the offsets by 0.01°', async () => {
      await page.reload({ waitUntil: 'load' });
      await until('logged in after the reload', async () => (await text(page, '#login-state')) === 'Logged in', 5000);
      for (const [id, axis, d] of [['#az-plus', 'az', 0.01], ['#az-minus', 'az', -0.01], ['#el-up', 'el', 0.01], ['#el-down', 'el', -0.01], ['#el-down', 'el', -0.01]]) {
        const key = `${axis}_user_deg`;
        const was = (await state()).corrections[key];
        await page.tap(id);
        const now = await until(`${id}: ${key} ${was} + ${d}`, async () => {
          const c = (await state()).corrections[key];
          return Math.abs(c - (was + d)) < 1e-9 && { c };
        }, 3000);
        await until(`${id}: the total on the page`, async () => Math.abs(num(await text(page, `#${axis}-corr`)) - now.c) < 1e-9, 3000);
        if (await visible(page, '#login-form')) throw new Error('asked for the password');
      }
    });

    await scenario('PARKING: a slot parks the antenna', async () => {
      await tapTo(page, '#target-pick', 'targets');
      await tapTo(page, '#go-park', 'park');
      const park = (await api('GET', '/api/targets')).json.park;
      await until('the slots named', async () => (await text(page, '#park-3 .tn')) === `3 · ${park[2].name}`, 3000);
      await checkScreen(page, 'parking');
      await page.tap('#park-3');
      await until(`PARK at ${park[2].name}`, async () => {
        const s = await state();
        return s.mode === 'PARK' && s.target.name === park[2].name;
      }, 5000);
      await until('the main screen naming the slot', async () => (await visible(page, '#screen-main')) &&
        (await text(page, '#target-name')).toLowerCase() === `park 3 · ${park[2].name}`.toLowerCase(), 3000);
    });

    await scenario('RA/Dec typed on the number keys sets the target', async () => {
      await tapTo(page, '#target-pick', 'targets');
      await tapTo(page, '#go-radec', 'radec');
      await checkScreen(page, 'radec');
      await page.tap('#ra');
      for (const k of '83.633') await page.tap(`#numpad [data-k="${k}"]`);
      await page.tap('#numpad [data-k="next"]');
      for (const k of '22.0145') await page.tap(`#numpad [data-k="${k}"]`);
      if ((await page.inputValue('#ra')) !== '83.633' || (await page.inputValue('#dec')) !== '22.0145') throw new Error('the keys typed something else');
      await until('the hint', async () => (await text(page, '#radec-hint')).includes('Dec +22.0145°'), 3000);
      await page.tap('#radec-go');
      await until('TRACK RA/Dec', async () => {
        const s = await state();
        return s.mode === 'TRACK' && /^RA 83\.633 Dec 22\.0145/.test(s.target.name);
      }, 5000);
      await until('the main screen', () => visible(page, '#screen-main'), 3000);
      await checkScreen(page, 'main-radec');
    });

    await scenario('STOP is on every screen and stops in one tap', async () => {
      const ways = {
        main: [], targets: ['#target-pick'], park: ['#target-pick', '#go-park'],
        radec: ['#target-pick', '#go-radec'], status: ['#status-btn'],
      };
      for (const [screen, taps] of Object.entries(ways)) {
        await toMain(page);
        for (const sel of taps) await page.tap(sel);
        await until(`the ${screen} screen`, () => visible(page, `#screen-${screen}`), 3000);
        if (screen === 'status') await checkScreen(page, 'status');
        await moving();
        const problems = await screenProblems(page);
        if (problems.length) throw new Error(`${screen}: ${problems.join('; ')}`);
        await page.tap('#btn-stop');
        await until(`STOP from the ${screen} screen`, async () => {
          const s = await state();
          return s.mode === 'STOP' && /^console\b/.test(s.who) && s.pc_locked_out;
        }, 3000).catch(async (e) => { const s = await state(); throw new Error(`${e.message}: ${s.mode} by ${s.who}, PC locked out ${s.pc_locked_out}`); });
      }
    });

    await scenario('logged out, STOP still stops in one tap (loopback needs no login for STOP)', async () => {
      await toMain(page);
      await page.tap('#login-state');
      await until('logged out', async () => !(await loggedIn(page)) && (await text(page, '#login-state')) === 'Read-only', 3000);
      const refused = await api('POST', '/api/correction', { axis: 'az', steps: 1 });
      if (refused.status !== 401) throw new Error(`POST /api/correction without a login answered ${refused.status}`);
      await moving();
      await page.tap('#btn-stop');
      await until('STOP without a login, in one tap', async () => (await state()).mode === 'STOP', 3000);
      if (await visible(page, '#login-form')) throw new Error('STOP asked for the password');
    });

    await scenario('the kiosk\'s token: target, park, corrections and STOP with no keyboard', async () => {
      // What azeltrack-panel-token makes at install (docs/panel.md), and the address the kiosk opens.
      const made = await api('POST', '/api/tokens', { label: 'panel' }, TOKEN);
      if (made.status !== 200 || !/^[0-9a-f]{64}$/.test(made.json.token || '')) throw new Error(`token: ${made.status} ${JSON.stringify(made.json)}`);
      await page.goto('about:blank');  // a load, not a move within the page: the token is read at load
      await page.goto(`${base}/panel#token=${made.json.token}`, { waitUntil: 'load' });
      await until('acting with the token', async () => (await text(page, '#login-state')) === 'Kiosk', 5000);
      const keyboard = () => visible(page, '#login-form').then((v) => { if (v) throw new Error('the keyboard was asked for'); });
      await tapTo(page, '#target-pick', 'targets');
      await page.tap('#tgt-moon');
      await until('the Moon tracked', async () => (await state()).target.name === 'Moon', 5000);
      await keyboard();
      await tapTo(page, '#target-pick', 'targets');
      await tapTo(page, '#go-park', 'park');
      await page.tap('#park-2');
      await until('PARK', async () => (await state()).mode === 'PARK', 5000);
      await keyboard();
      const was = (await state()).corrections.az_user_deg;
      await page.tap('#az-plus');
      await until('the correction', async () => Math.abs((await state()).corrections.az_user_deg - (was + 0.01)) < 1e-9, 3000);
      await page.tap('#btn-stop');
      await until('STOP', async () => (await state()).mode === 'STOP', 3000);
      await keyboard();
      if (page.url().includes(made.json.token)) throw new Error('the token stays in the address bar');
      // Revoked from the console: the panel is read-only again, and says so.
      const gone = await api('DELETE', '/api/tokens/panel', undefined, TOKEN);
      if (gone.status !== 200) throw new Error(`revoke: ${gone.status}`);
      await page.tap('#az-plus');
      await until('read-only after the revoke', async () => (await text(page, '#login-state')) === 'Read-only', 5000);
      await until('the keyboard, saying why', async () => (await visible(page, '#login-form')) && /token was revoked/.test(await text(page, '#login-error')), 3000);
      await checkScreen(page, 'login-revoked');
      await page.tap('#login-cancel');
    });

    await scenario('a target that never rises is shown waiting, in words that fit the screen', async () => {
      // Dec −89° never rises at 46° N: the wait line is the "not within two days" form, whatever the hour.
      const r = await api('POST', '/api/target', { ra_deg: 0, dec_deg: -89 }, TOKEN);
      if (r.status !== 200) throw new Error(`RA/Dec: ${r.status} ${JSON.stringify(r.json)}`);
      await toMain(page);
      await until('the wait line', async () => (await visible(page, '#wait-row')) && (await text(page, '#wait-line')) === 'not up in 2 days', 8000);
      await checkScreen(page, 'main-waiting');
      await api('POST', '/api/stop', {}, TOKEN);
    });

    // Measured: the panel's weight (the page, its CSS and every module it loaded).
    const { bytes, all } = await pageWeight(page, '/panel');
    console.log(`measure: panel page weight ${bytes} bytes in ${all.length} files (${all.join(' ')})`);
    await scenario(`the panel weighs less than ${WEIGHT_BUDGET} bytes`, async () => {
      if (bytes >= WEIGHT_BUDGET) throw new Error(`${bytes} bytes`);
      if (!all.includes('/js/socket.js') || !all.includes('/js/session.js') || !all.includes('/js/api.js')) throw new Error('the console\'s modules are not the ones used');
    });
    checkPageErrors(browser.errors);
  } finally {
    await shutDown(browser);
  }
  summarise();
}

run(main);
