// What the console's browser test (console_test.js) plays besides the browser: gpsd fed by
// gpsfake, a receiver sending a beam's power over UDP, and an element set whose epoch is now.
'use strict';
const { spawn, spawnSync } = require('child_process');
const dgram = require('dgram');
// The element set whose epoch is now is the harness's (tleWithEpochNow), passed on from here.
const { sleep, state, tleWithEpochNow } = require('./harness');

let tmp = '';
let gpsdPort = 0;
let gpsfake = null;
let udpPort = 0;
let feeder = null;

/// Where the feeds go: gpsd's port, the receiver's UDP port, and the test's temporary directory.
function useFeeds(ports) {
  ({ tmp, gpsdPort, udpPort } = ports);
}

// gpsd fed once with a recorded fix by gpsfake, in a process group of its own (gpsfake waits on
// its gpsd otherwise), as tests/integration/gps_test.py does.
function startGpsfake(log) {
  gpsfake = spawn('gpsfake', ['-q', '-1', '-c', '0.02', '-P', String(gpsdPort), log],
    { stdio: 'ignore', detached: true, env: { ...process.env, TMPDIR: tmp } });
}
function stopGpsfake() {
  if (!gpsfake) return;
  try { process.kill(-gpsfake.pid, 'SIGKILL'); } catch (e) { /* gone */ }
  gpsfake = null;
  // gpsd killed leaves its shared-memory export (key 0x4770 then the port in hex) behind.
  spawnSync('ipcrm', ['-M', `0x4770${gpsdPort.toString(16).padStart(4, '0')}`], { stdio: 'ignore' });
}
// The receiver for the pointing scans (docs/calibration.md), as tests/integration/scan_test.py is
// one: a Gaussian beam of BEAM_DEG on a source TRUE_AZ_DEG / TRUE_EL_DEG away from where the
// ephemeris puts it (the target in /api/state), seen from where the encoders read, sent as dB lines
// over UDP ([receiver] udp) every 100 ms.
const BEAM_DEG = 1.0;
const TRUE_AZ_DEG = 0.4;
const TRUE_EL_DEG = -0.25;
function beamPowerDb(s) {
  const a = s.antenna || {}; const t = s.target || {};
  if (!a.known || typeof t.az_deg !== 'number' || typeof t.el_deg !== 'number') return 0;
  const srcAz = t.az_deg + TRUE_AZ_DEG; const srcEl = t.el_deg + TRUE_EL_DEG;
  const dAz = ((a.encoder_az_deg - srcAz + 540) % 360) - 180;
  const d2 = (dAz * Math.cos((srcEl * Math.PI) / 180)) ** 2 + (a.encoder_el_deg - srcEl) ** 2;
  return 10 * Math.log10(1 + 3 * Math.exp((-4 * Math.LN2 * d2) / BEAM_DEG ** 2));
}
function startFeeder() {
  const sock = dgram.createSocket('udp4');
  let on = true;
  const done = (async () => {
    while (on) {
      try {
        const s = await state();
        if (s) sock.send(`${beamPowerDb(s).toFixed(4)} dB\n`, udpPort, '127.0.0.1');
      } catch (e) { /* the daemon restarting */ }
      await sleep(100);
    }
    sock.close();
  })();
  feeder = { stop: async () => { on = false; await done; } };
}
async function stopFeeder() {
  if (!feeder) return;
  const f = feeder;
  feeder = null;
  await f.stop();
}

/// Whether the receiver feed is running (a scan was started with it).
const feeding = () => feeder !== null;

const hasProgram = (name) => spawnSync('sh', ['-c', `command -v ${name}`], { stdio: 'ignore' }).status === 0;

module.exports = {
  BEAM_DEG, TRUE_AZ_DEG, TRUE_EL_DEG, useFeeds, startGpsfake, stopGpsfake, startFeeder, stopFeeder, feeding,
  hasProgram, tleWithEpochNow,
};
