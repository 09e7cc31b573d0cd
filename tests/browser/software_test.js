// Browser test of the console's Software page (the AnTrack-Pro manual's "Software Updating";
// docs/web-api.md "software"): Debian's Chromium driven by playwright-core against a real
// `azeltrack serve` started with --update-inbox and --update-status in a temporary directory. The
// test plays the root update helper: it takes the inbox's request.deb and writes the status file
// (key=value lines, atomically) as packaging/azeltrack-update does. Screenshots go to OUT_DIR.
// Usage: node software_test.js AZELTRACK OUT_DIR (AZT_WEB_DIR as for console_test.js)
'use strict';
const crypto = require('crypto');
const { spawnSync } = require('child_process');
const fs = require('fs');
const path = require('path');
const {
  setup, freePort, sleep, until, useWebPort, api, simConfig, setPassword, startDaemon, stopDaemon,
  scenarioWithShots, loggedIn, text, launch, checkPageErrors, shutDown, summarise, run,
} = require('./harness');

const { outDir, tmp, config } = setup('software_test.js', 'azt-software-');
const PASSWORD = 'software-test-password';
const inbox = path.join(tmp, 'update');
const request = path.join(inbox, 'request.deb');
const statusFile = path.join(tmp, 'update-status');
const UPDATES = ['--update-inbox', inbox, '--update-status', statusFile];

const sha256 = (bytes) => crypto.createHash('sha256').update(bytes).digest('hex');

// A throwaway package built as Debian builds one: what the daemon checks is that it is a Debian
// archive; the name, architecture and version are the helper's to check.
function buildDeb(version, arch) {
  const root = fs.mkdtempSync(path.join(tmp, 'pkg-'));
  fs.mkdirSync(path.join(root, 'DEBIAN'));
  fs.writeFileSync(path.join(root, 'DEBIAN', 'control'), `Package: azeltrack
Version: ${version}
Architecture: ${arch}
Maintainer: azeltrack tests <tests@example.invalid>
Description: throwaway package for the Software page's browser test
`);
  const doc = path.join(root, 'usr', 'share', 'doc', 'azeltrack');
  fs.mkdirSync(doc, { recursive: true });
  fs.writeFileSync(path.join(doc, 'README'), `azeltrack ${version} (${arch}): not a real package.\n`);
  const out = path.join(tmp, `azeltrack_${version}_${arch}.deb`);
  const r = spawnSync('dpkg-deb', ['--root-owner-group', '--build', root, out]);
  if (r.status !== 0) throw new Error(`dpkg-deb --build: ${r.stderr}`);
  return out;
}

// The helper's report, written whole (a temporary file renamed over the old one).
function report(fields) {
  const all = { ...fields, at: Math.floor(Date.now() / 1000) };
  const tmpFile = `${statusFile}.new`;
  fs.writeFileSync(tmpFile, Object.entries(all).map(([k, v]) => `${k}=${v}\n`).join(''));
  fs.renameSync(tmpFile, statusFile);
}
// The helper takes the package out of the inbox before it checks it.
function take() { fs.rmSync(request); }

const software = async () => (await api('GET', '/api/software')).json;

// Every scenario leaves its screenshots (the harness's scenarioWithShots).
const scenario = (name, page, body) => scenarioWithShots(name, page, outDir, body);

// Logs in from the header, staying on the page shown.
async function login(page) {
  if (await loggedIn(page)) return;
  if (!(await page.isVisible('#password'))) await page.click('#login-state');
  await page.fill('#password', PASSWORD);
  await page.click('#login-btn');
  await until('the session', () => loggedIn(page));
}
async function openSoftware(page) {
  await page.click('#nav-setup');
  await page.click('#go-software');
  await until('the Software page', () => page.isVisible('#screen-software'), 3000);
}
async function closePopup(page) {
  if (await page.isVisible('#sw-popup')) await page.click('#sw-popup-ok');
  await until('the popup closed', async () => !(await page.isVisible('#sw-popup')), 3000);
}
const stage = (page) => text(page, '#sw-stage');
const percent = (page) => text(page, '#sw-percent');
// The "Last update" rows as shown: {Result: …, Versions: …, …}.
const lastUpdate = (page) => page.$$eval('#sw-last > div', (rows) => Object.fromEntries(rows.map((r) =>
  [r.firstChild.textContent.trim(), r.lastChild.textContent.trim()])));
// Every stage the page shows from now on, as it shows it.
const recordStages = (page) => page.evaluate(() => {
  window.aztStages = [];
  const el = document.getElementById('sw-stage');
  new MutationObserver((records) => {
    for (const r of records) for (const n of r.addedNodes) window.aztStages.push(n.textContent);
  }).observe(el, { childList: true });
});

async function sendPackage(page, file) {
  await page.setInputFiles('#sw-file', file);
  await until('Update enabled', async () => !(await page.isDisabled('#sw-update')), 3000);
  await recordStages(page);
  await page.click('#sw-update');
}

async function main() {
  const port = await freePort();
  const base = useWebPort(port);
  fs.writeFileSync(config, simConfig('stop', port));
  setPassword(PASSWORD);
  await startDaemon(UPDATES);
  const browser = await launch({ '/': 'index.html', '/app.css': 'app.css' }, { viewport: { width: 1280, height: 800 } });
  const { page } = browser;
  const first = await software();
  const version = first && first.version;
  try {
    await page.goto(base + '/', { waitUntil: 'load' });
    await until('live numbers', async () => /\d/.test(await text(page, '#ant-az')));

    await scenario('the Software page from Setup: the version; Update disabled without login', page, async () => {
      if (!first || typeof version !== 'string') throw new Error(`GET /api/software: ${JSON.stringify(first)}`);
      if (first.updates !== true) throw new Error(`updates are off with --update-inbox: ${first.updates_reason}`);
      await page.click('#nav-setup');
      await until('the version on Setup', async () => (await text(page, '#setup-software')).includes(`version ${version}`), 5000);
      await page.click('#go-software');
      await until('the Software page', () => page.isVisible('#screen-software'), 3000);
      if ((await page.getAttribute('#nav-setup', 'aria-selected')) !== 'true') throw new Error('the Setup tab is not lit on the Software page');
      await until('the version', async () => (await text(page, '#sw-version')) === version, 5000);
      const arch = await text(page, '#sw-arch');
      if (arch !== (first.architecture || 'not known')) throw new Error(`architecture: ${arch} (the API: ${first.architecture})`);
      if (!(await page.isVisible('#sw-form')) || (await page.isVisible('#sw-no-updates'))) throw new Error('the upload form is not shown');
      if ((await page.getAttribute('#sw-file', 'accept')) !== '.deb') throw new Error('the file input does not ask for .deb');
      if (!(await page.isDisabled('#sw-update')) || !(await page.isDisabled('#sw-file'))) throw new Error('the form is enabled without login');
      if (!/^Log in to update/.test(await text(page, '#sw-hint')) || !(await page.isVisible('#sw-login'))) throw new Error(`hint: ${await text(page, '#sw-hint')}`);
      if (!(await text(page, '#screen-software')).includes('Updating the software will not change any configuration parameters.')) throw new Error('the settings note is missing');
      if (await page.isVisible('#sw-progress')) throw new Error('a progress bar with no update');
      // The controller refuses it too.
      const direct = await page.evaluate(async () => (await fetch('/api/software/update', { method: 'POST',
        headers: { 'Content-Type': 'application/vnd.debian.binary-package' }, body: '!<arch>\n' })).status);
      if (direct !== 401) throw new Error(`POST /api/software/update without login answered ${direct}`);
    });

    await scenario('a file that is not a Debian package is refused with the controller\'s reason', page, async () => {
      await login(page);
      await until('the form to follow the login', async () => !(await page.isDisabled('#sw-file')) && !(await page.isVisible('#sw-login')), 3000);
      if (!(await page.isDisabled('#sw-update'))) throw new Error('Update is enabled with no file chosen');
      // Named .deb: the controller looks at what the file is, not at its name.
      await page.setInputFiles('#sw-file', { name: 'notes.deb', mimeType: 'application/octet-stream', buffer: Buffer.from('not a package\n') });
      await until('Update enabled', async () => !(await page.isDisabled('#sw-update')), 3000);
      if (!(await text(page, '#sw-hint')).startsWith('notes.deb, 14 bytes')) throw new Error(`hint: ${await text(page, '#sw-hint')}`);
      await page.click('#sw-update');
      await until('the refusal', async () => /^Not sent: not a Debian package\b/.test(await text(page, '#sw-error')), 5000);
      if (fs.existsSync(request)) throw new Error('a refused file reached the inbox');
      if ((await software()).upload !== null) throw new Error('the controller remembers a refused upload');
      if (await page.isVisible('#sw-progress')) throw new Error('a progress bar after a refusal');
    });

    const deb = buildDeb('0.1.0+1', 'amd64');
    const bytes = fs.readFileSync(deb);
    const sha = sha256(bytes);

    await scenario('a package is sent: 100 %, waiting for the update helper, the same bytes in the inbox', page, async () => {
      await sendPackage(page, deb);
      await until('100 % sent and waiting for the helper', async () => (await stage(page)) === 'Waiting for the update helper' &&
        (await percent(page)) === 'Percent complete: 100%', 5000);
      const seen = await page.evaluate(() => window.aztStages);
      if (seen[0] !== 'Sending') throw new Error(`stages shown: ${JSON.stringify(seen)}`);
      if (!fs.existsSync(request)) throw new Error('no request.deb in the inbox');
      const stored = fs.readFileSync(request);
      if (stored.length !== bytes.length || sha256(stored) !== sha) throw new Error(`request.deb: ${stored.length} bytes, sha256 ${sha256(stored)}; sent ${bytes.length}, ${sha}`);
      const said = await text(page, '#sw-sha');
      if (said !== sha) throw new Error(`the page's sha256 ${said}, the package's ${sha}`);
      const s = await software();
      if (!s.upload || s.upload.sha256 !== sha || s.upload.bytes !== bytes.length) throw new Error(`upload: ${JSON.stringify(s.upload)}`);
      if (!(await page.isDisabled('#sw-update')) || (await text(page, '#sw-hint')) !== 'An update is under way.') throw new Error('Update is enabled while an update waits');
      if (await page.inputValue('#sw-file')) throw new Error('the file is still chosen after it was sent');
      // On a phone: nothing wider than the screen, and the controls big enough for a finger.
      await page.setViewportSize({ width: 375, height: 740 });
      await sleep(100);
      const wide = await page.evaluate(() => document.documentElement.scrollWidth);
      if (wide > 375) throw new Error(`the page is ${wide} px wide on a 375 px phone`);
      for (const id of ['#sw-file', '#sw-update']) {
        const box = await page.$eval(id, (e) => e.getBoundingClientRect().height);
        if (box < 44) throw new Error(`${id} is ${box} px high`);
      }
      await page.setViewportSize({ width: 1280, height: 800 });
    });

    await scenario('the helper checks, then installs: the bar shows its percent', page, async () => {
      take();
      report({ phase: 'checking', percent: 0, message: 'Checking azeltrack_0.1.0+1_amd64.deb', from: version, to: '0.1.0+1', sha256: sha });
      await until('Checking', async () => (await stage(page)) === 'Checking', 5000);
      report({ phase: 'installing', percent: 40, message: `Unpacking azeltrack (0.1.0+1) over (${version})`, from: version, to: '0.1.0+1', sha256: sha });
      await until('Installing at 40 %', async () => (await stage(page)) === 'Installing' && (await percent(page)) === 'Percent complete: 40%', 5000);
      if ((await page.getAttribute('#sw-bar', 'aria-valuenow')) !== '40') throw new Error(`bar: ${await page.getAttribute('#sw-bar', 'aria-valuenow')}`);
      await until('the bar drawn 40 % full', async () => Math.abs(await page.$eval('#sw-bar', (b) =>
        b.firstElementChild.getBoundingClientRect().width / b.clientWidth) - 0.4) < 0.02, 3000);
      if (!(await text(page, '#sw-detail')).includes('Unpacking azeltrack (0.1.0+1)')) throw new Error(`detail: ${await text(page, '#sw-detail')}`);
      if (await page.isVisible('#sw-popup')) throw new Error('a popup before the end');
    });

    await scenario('the package restarts the controller: Restarting…, then the update succeeded', page, async () => {
      await stopDaemon();
      await until('Restarting…', async () => (await stage(page)) === 'Restarting…', 5000);
      if ((await percent(page)) !== 'Percent complete: 40%') throw new Error(`while restarting: ${await percent(page)}`);
      if (await page.isVisible('#sw-problem')) throw new Error(`an error while restarting: ${await text(page, '#sw-problem')}`);
      // apt finishes after the postinst restarted the daemon; the helper says so.
      report({ phase: 'installed', percent: 100, message: `azeltrack ${version} installed`, from: version, to: version, sha256: sha });
      await startDaemon(UPDATES);
      await until('the success popup', () => page.isVisible('#sw-popup'), 10000);
      if ((await text(page, '#sw-popup-title')) !== 'Update installed') throw new Error(`popup: ${await text(page, '#sw-popup')}`);
      const said = await text(page, '#sw-popup-text');
      if (!said.includes(`from ${version} to ${version}`) || !said.includes('configuration parameters are unchanged')) throw new Error(`popup: ${said}`);
      if ((await stage(page)) !== 'Installed' || (await percent(page)) !== 'Percent complete: 100%') throw new Error(`${await stage(page)}, ${await percent(page)}`);
      const last = await lastUpdate(page);
      if (last.Result !== 'installed' || last.Versions !== `${version} → ${version}`) throw new Error(`last update: ${JSON.stringify(last)}`);
      // The popup is no modal: STOP stays within reach (a trial click fails on a covered button).
      await page.click('#btn-stop', { trial: true, timeout: 2000 });
    });

    await scenario('a reload shows the result without announcing it again', page, async () => {
      await closePopup(page);
      await page.reload({ waitUntil: 'load' });
      await until('the Software page', () => page.isVisible('#screen-software'), 3000);
      await until('the last update', async () => (await lastUpdate(page).catch(() => ({}))).Result === 'installed', 5000);
      await sleep(1200); // one fast poll's time: the popup must not come back
      if (await page.isVisible('#sw-popup')) throw new Error('the result was announced twice');
    });

    const deb2 = buildDeb('0.1.0+2', 'arm64');
    const sha2 = sha256(fs.readFileSync(deb2));
    const refusal = "architecture arm64 is not this machine's amd64";

    await scenario('a package the helper refuses: the popup and the page say why', page, async () => {
      await login(page); // the restart ended the session
      await sendPackage(page, deb2);
      await until('waiting for the helper', async () => (await stage(page)) === 'Waiting for the update helper' && (await text(page, '#sw-sha')) === sha2, 5000);
      take();
      report({ phase: 'checking', percent: 0, message: 'Checking azeltrack_0.1.0+2_arm64.deb', from: version, to: '0.1.0+2', sha256: sha2 });
      await until('Checking', async () => (await stage(page)) === 'Checking', 5000);
      report({ phase: 'refused', percent: 0, message: refusal, from: version, to: '0.1.0+2', sha256: sha2 });
      await until('the refusal popup', () => page.isVisible('#sw-popup'), 5000);
      if ((await text(page, '#sw-popup-title')) !== 'Update refused') throw new Error(`popup: ${await text(page, '#sw-popup')}`);
      const said = await text(page, '#sw-popup-text');
      if (!said.includes(refusal) || !said.includes(`Version ${version} is running`)) throw new Error(`popup: ${said}`);
      if ((await stage(page)) !== 'Refused') throw new Error(`stage: ${await stage(page)}`);
      const last = await lastUpdate(page);
      if (last.Result !== 'refused' || last.Message !== refusal) throw new Error(`last update: ${JSON.stringify(last)}`);
      if ((await text(page, '#sw-version')) !== version) throw new Error(`version: ${await text(page, '#sw-version')}`);
      // Done: another package may be sent.
      await until('Update ready again', async () => !(await page.isDisabled('#sw-file')), 3000);
    });

    await scenario('without the update helper the page says why and offers no upload', page, async () => {
      await closePopup(page);
      await stopDaemon();
      await startDaemon();
      const s = await software();
      if (s.updates !== false || !s.updates_reason) throw new Error(`GET /api/software: ${JSON.stringify(s)}`);
      await page.reload({ waitUntil: 'load' });
      await until('the Software page', () => page.isVisible('#screen-software'), 3000);
      await until('the reason', async () => (await page.isVisible('#sw-no-updates')) &&
        (await text(page, '#sw-no-reason')) === s.updates_reason.replace(/\.+$/, ''), 5000);
      if (await page.isVisible('#sw-form')) throw new Error('the upload form is shown');
    });

    checkPageErrors(browser.errors);
  } finally {
    await shutDown(browser);
  }
  summarise();
}

run(main);
