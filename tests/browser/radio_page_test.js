// Browser test of the console's Radio page (docs/radio.md "In the daemon"): Debian's Chromium
// driven by playwright-core against a real `azeltrack serve` that tracks a satellite with its
// [[satellites.transmitter]] and keeps Hamlib's own dummy rig (`rigctld -m 1`, Debian's
// libhamlib-utils) on frequency, as tests/integration/radio_test.py starts it. The page must show
// what the rig itself reads back, WSJT-X as heard (datagrams built here as
// Network/NetworkMessage.hpp writes them), the link's failure with its reason, and why only one
// program may do Doppler. The browser runs in Asia/Kolkata (UTC+05:30, no summer time), so
// that the local time shown beside UTC differs from it. Screenshots go to OUT_DIR.
// Usage: node radio_page_test.js AZELTRACK OUT_DIR (AZT_WEB_DIR as for console_test.js)
'use strict';
const { spawn, spawnSync } = require('child_process');
const dgram = require('dgram');
const fs = require('fs');
const net = require('net');
const path = require('path');
const {
  setup, tleWithEpochNow, freePort, until, useWebPort, state, simConfig, startDaemon, stopDaemon,
  scenarioWithShots, text, launch, checkPageErrors, shutDown, summarise, run,
} = require('./harness');

const { outDir, config } = setup('radio_page_test.js', 'azt-radio-page-');
const DOWNLINK_MHZ = 437.8;
const UPLINK_MHZ = 145.99;
let rigPort = 0;
let rigctld = null;

const hasProgram = (name) => spawnSync('sh', ['-c', `command -v ${name}`], { stdio: 'ignore' }).status === 0;

function startRigctld() {
  rigctld = spawn('rigctld', ['-m', '1', '-T', '127.0.0.1', '-t', String(rigPort)], { stdio: 'ignore' });
  return until('rigctld to listen', () => new Promise((resolve) => {
    const s = net.connect(rigPort, '127.0.0.1', () => { s.destroy(); resolve(true); });
    s.on('error', () => resolve(false));
  }), 5000, 50);
}
function stopRigctld() {
  if (!rigctld) return Promise.resolve();
  const r = rigctld;
  rigctld = null;
  const gone = new Promise((resolve) => r.once('exit', resolve));
  r.kill('SIGTERM');
  return gone;
}

// The main VFO as Hamlib's own client reads it back.
function rigRx() {
  const r = spawnSync('rigctl', ['-m', '2', '-r', `127.0.0.1:${rigPort}`, 'f'], { encoding: 'utf8', timeout: 5000 });
  if (r.status !== 0) throw new Error(`rigctl f: ${r.stderr}`);
  return Number(r.stdout.split('\n')[0]);
}
// The split (TX) frequency, asked in rigctld's own protocol: Hamlib 4.5's `rigctl -m 2 … i`
// answers the main VFO against a rigctld without VFO mode (its vfo_fixup takes VFOA as the TX VFO).
function rigTx() {
  return new Promise((resolve, reject) => {
    const s = net.connect(rigPort, '127.0.0.1', () => s.write('i\n'));
    let got = '';
    s.setTimeout(3000, () => { s.destroy(); reject(new Error('rigctld did not answer i')); });
    s.on('data', (d) => { got += d; if (got.includes('\n')) { s.destroy(); resolve(Number(got.split('\n')[0])); } });
    s.on('error', reject);
  });
}

// The frequency as the page must write it: MHz, then the Hz in groups of three.
function dots(hz) {
  const r = String(Math.round(hz));
  return `${r.slice(0, -6)}.${r.slice(-6, -3)}.${r.slice(-3)}`;
}

// A WSJT-X Status (schema 2, ending after the DX grid as WSJT-X 1.7's does; QDataStream,
// big-endian): id, dial, mode, DX call, report, Tx mode, Tx enabled, transmitting, decoding,
// Rx/Tx df, own call and grid, DX grid.
function wsjtxStatus(dxCall, dxGrid) {
  const utf8 = (s) => { const b = Buffer.from(s); const n = Buffer.alloc(4); n.writeUInt32BE(b.length); return Buffer.concat([n, b]); };
  const u32 = (...v) => { const b = Buffer.alloc(4 * v.length); v.forEach((x, i) => b.writeUInt32BE(x, 4 * i)); return b; };
  const dial = Buffer.alloc(8);
  dial.writeBigUInt64BE(435000000n);
  return Buffer.concat([u32(0xadbccbda, 2, 1), utf8('WSJT-X'), dial, utf8('FT8'), utf8(dxCall), utf8('-10'), utf8('FT8'),
    Buffer.from([1, 0, 0]), u32(1500, 1500), utf8('W1AW'), utf8('FN31'), utf8(dxGrid)]);
}
function sendUdp(port, body) {
  const sock = dgram.createSocket('udp4');
  return new Promise((resolve, reject) => sock.send(body, port, '127.0.0.1', (e) => { sock.close(); if (e) reject(e); else resolve(); }));
}

function writeConfig(webPort, udpPort, doppler) {
  fs.writeFileSync(config, `${simConfig('sat:25544', webPort)}[satellites]
file = "sats.tle"
[[satellites.transmitter]]
norad = "25544"
downlink_mhz = ${DOWNLINK_MHZ}
uplink_mhz = ${UPLINK_MHZ}
mode = "fm"
[radio]
rigctld = "127.0.0.1:${rigPort}"
doppler = "${doppler}"
[wsjtx]
listen = "127.0.0.1:${udpPort}"
`);
}

const scenario = (name, page, body) => scenarioWithShots(name, page, outDir, body);
const owner = async (page) => ((await page.isVisible('#radio-owner')) ? text(page, '#radio-owner') : '');

async function main() {
  if (!hasProgram('rigctld') || !hasProgram('rigctl')) {
    console.log('skip: Hamlib\'s rigctld and rigctl are not installed (libhamlib-utils)');
    process.exit(77); // ctest's SKIP_RETURN_CODE
  }
  rigPort = await freePort();
  const webPort = await freePort();
  const udpPort = await freePort();
  const base = useWebPort(webPort);
  fs.writeFileSync(path.join(path.dirname(config), 'sats.tle'), tleWithEpochNow());
  writeConfig(webPort, udpPort, 'satellite');
  await startRigctld();
  await startDaemon();
  const browser = await launch({ '/': 'index.html', '/app.css': 'app.css' }, { viewport: { width: 1280, height: 800 }, timezoneId: 'Asia/Kolkata' });
  const { page } = browser;
  try {
    await page.goto(base + '/', { waitUntil: 'load' });
    await until('live numbers', async () => /\d/.test(await text(page, '#ant-az')));

    await scenario('the Radio page from Setup shows the frequencies the rig reads back', page, async () => {
      await page.click('#nav-setup');
      await until('Setup\'s radio line', async () => /rig up · satellite Doppler/.test(await text(page, '#setup-radio')), 8000);
      await page.click('#go-radio');
      await until('the Radio page', () => page.isVisible('#radio-rx'), 5000);
      if ((await page.getAttribute('#nav-setup', 'aria-selected')) !== 'true') throw new Error('the Setup tab is not lit on the Radio page');
      await until('the link up', async () => (await text(page, '#radio-badge')) === 'LINK UP', 5000);
      // Hamlib's rig moves at most once a second: the page must catch up with what it reads back.
      await until('the RX the rig reads back', async () => (await text(page, '#radio-rx')) === dots(rigRx()), 8000, 200);
      await until('the TX the rig reads back', async () => (await text(page, '#radio-tx')) === dots(await rigTx()), 8000, 200);
      const r = (await state()).radio;
      // The downlink heard within the Doppler of a low orbit (under 8 km/s: 12 kHz at 437.8 MHz).
      if (Math.abs(rigRx() - DOWNLINK_MHZ * 1e6) > 12e3) throw new Error(`the rig's RX ${rigRx()} is no Doppler-corrected ${DOWNLINK_MHZ} MHz`);
      const nominal = await text(page, '#radio-nominal');
      if (nominal !== `${dots(DOWNLINK_MHZ * 1e6)} / ${dots(UPLINK_MHZ * 1e6)}`) throw new Error(`nominal: ${nominal}`);
      if (!/^[+-]\d+ Hz Doppler$/.test(await text(page, '#radio-rx-corr'))) throw new Error(`RX correction: ${await text(page, '#radio-rx-corr')}`);
      if (!(await text(page, '#radio-sat')).includes('NORAD 25544')) throw new Error(`satellite: ${await text(page, '#radio-sat')}`);
      // The rig's address and the transmitter followed, from /api/state `radio` itself.
      if (r.rigctld !== `127.0.0.1:${rigPort}` || (await text(page, '#radio-rigctld')) !== r.rigctld) throw new Error(`rigctld: ${await text(page, '#radio-rigctld')} (state: ${r.rigctld})`);
      const t = r.transmitter || {};
      if (t.norad !== '25544' || t.downlink_mhz !== DOWNLINK_MHZ || t.uplink_mhz !== UPLINK_MHZ || t.mode !== 'fm') throw new Error(`the state's transmitter: ${JSON.stringify(r.transmitter)}`);
      const followed = await text(page, '#radio-transmitter');
      if (followed !== `${dots(DOWNLINK_MHZ * 1e6)} / ${dots(UPLINK_MHZ * 1e6)} MHz · fm`) throw new Error(`transmitter: ${followed}`);
      // The instant in UTC and, beside it, in the browser's zone (UTC+05:30).
      // The page and the state are read moments apart and the instant moves on each cycle: the
      // time shown is within a few seconds of the state's (a minute may turn between the reads),
      // and the local time is exactly 5 h 30 min after the UTC shown.
      const shown = await text(page, '#radio-at');
      const m = /(\d\d):(\d\d):(\d\d) UTC \((\d\d):(\d\d):(\d\d) local\)/.exec(shown);
      if (!m) throw new Error(`computed for: ${shown} (at ${r.at})`);
      const day = 86400;
      const secs = (h, mi, se) => (Number(h) * 3600 + Number(mi) * 60 + Number(se)) % day;
      const shownUtc = secs(m[1], m[2], m[3]);
      const at = new Date(r.at);
      const apart = Math.abs(((shownUtc - secs(at.getUTCHours(), at.getUTCMinutes(), at.getUTCSeconds()) + day * 1.5) % day) - day / 2);
      if (apart > 5 || secs(m[4], m[5], m[6]) !== (shownUtc + 5.5 * 3600) % day) throw new Error(`computed for: ${shown} (at ${r.at})`);
      if (await page.isVisible('#radio-owner')) throw new Error(`a Doppler note with WSJT-X silent: ${await owner(page)}`);
      if (!/SILENT/.test(await text(page, '#wsjtx-badge'))) throw new Error(`WSJT-X: ${await text(page, '#wsjtx-badge')}`);
    });

    await scenario('WSJT-X heard while azeltrack does Doppler: only one program may', page, async () => {
      await sendUdp(udpPort, wsjtxStatus('OZ1ABC', 'JO65MR'));
      await until('WSJT-X heard', async () => (await text(page, '#wsjtx-badge')) === 'HEARD', 5000);
      const said = await owner(page);
      if (!said.includes('WSJT-X is heard and azeltrack’s Doppler is on') || !said.includes('Only one program may do Doppler')) throw new Error(`note: ${said}`);
      if ((await text(page, '#wsjtx-dx')) !== 'OZ1ABC · JO65MR') throw new Error(`DX: ${await text(page, '#wsjtx-dx')}`);
    });

    await scenario('the rig gone: the link down with its reason', page, async () => {
      await stopRigctld();
      await until('the link down', async () => (await text(page, '#radio-badge')) === 'LINK DOWN', 8000);
      const why = String((await state()).radio.link).replace(/^down:\s*/, '');
      if (!why || !(await text(page, '#radio-link-text')).includes(why)) throw new Error(`reason: ${await text(page, '#radio-link-text')} (state: ${why})`);
    });

    await scenario('with doppler = "off" the page says why azeltrack writes nothing', page, async () => {
      await startRigctld();
      await stopDaemon();
      writeConfig(webPort, udpPort, 'off');
      await startDaemon();
      await until('the daemon without Doppler', async () => (await text(page, '#radio-doppler')).startsWith('off'), 10000);
      const said = await owner(page);
      if (!said.includes('azeltrack’s Doppler is off ([radio] doppler = "off")') || !said.includes('Only one program may do Doppler')) throw new Error(`note: ${said}`);
      if ((await text(page, '#radio-rx')) !== '—') throw new Error(`an RX with Doppler off: ${await text(page, '#radio-rx')}`);
    });
  } finally {
    checkPageErrors(browser.errors);
    await shutDown(browser);
    await stopRigctld();
  }
  summarise();
}

run(main, () => { if (rigctld) rigctld.kill('SIGKILL'); });
