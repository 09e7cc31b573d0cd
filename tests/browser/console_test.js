// Browser tests of the web console (docs/web-api.md): Debian's Chromium driven by playwright-core
// against a real `azeltrack serve` on the simulated antenna. Each scenario checks what a user sees
// and what the daemon did; screenshots at desktop and phone sizes go to OUT_DIR.
// Usage: node console_test.js AZELTRACK OUT_DIR
// AZT_WEB_DIR=web serves the console's files from that directory instead of the copy built into
// AZELTRACK (to try an edit of web/ without a rebuild; the API and the WebSocket stay the daemon's).
'use strict';
const fs = require('fs');
const path = require('path');
const {
  setup, freePort, until, useWebPort, api, simConfig, setPassword, startDaemon, scenario: check, scenarioWithShots,
  loggedIn, text, launch, checkPageErrors, shutDown, summarise, run,
} = require('./harness');
const { useFeeds, stopGpsfake, stopFeeder, tleWithEpochNow } = require('./console_feeds');
const { runTrackingScenarios } = require('./console_tracking_scenarios');
const { runRestartScenarios } = require('./console_restart_scenarios');
const { runClockGpsScenarios } = require('./console_clock_gps_scenarios');
const { runPlannerScenario } = require('./console_planner_scenario');
const { runScanScenarios } = require('./console_scan_scenarios');
const { runPageScenarios } = require('./console_pages_scenarios');
const { measureConsole } = require('./console_measurements');

const { outDir, tmp, config } = setup('console_test.js', 'azt-browser-');
const PASSWORD = 'browser-test-password';
const sourcesFile = path.join(tmp, 'sources.d', 'azeltrack.sources');
let port = 0;
let gpsdPort = 0;
let udpPort = 0;

const apiGet = async (route) => api('GET', route);

function writeConfig() {
  // The harness's fast plant: a quick motor, so that the final approach to each point of a
  // pointing scan takes a second, not four.
  fs.writeFileSync(config, `${simConfig('stop', port)}[satellites]
file = "sats.tle"
[gps]
enabled = true
gpsd = "127.0.0.1:${gpsdPort}"
use_position = false
[time]
chrony_socket = "${path.join(tmp, 'nonexistent.sock')}"
poll_s = 1
manage_chrony = true
sources_file = "${sourcesFile}"
[receiver]
source = "udp"
port = ${udpPort}
stale_s = 2.0
`);
  fs.mkdirSync(path.dirname(sourcesFile), { recursive: true });
  fs.writeFileSync(path.join(path.dirname(config), 'sats.tle'), tleWithEpochNow());
  setPassword(PASSWORD);
}

// Every scenario leaves its screenshots (the harness's scenarioWithShots); check() is one that
// takes its own, or none.
const scenario = (name, page, body) => scenarioWithShots(name, page, outDir, body);

async function login(page) {
  await page.click('#nav-main').catch(() => {});
  if (await loggedIn(page)) return;
  if (!(await page.isVisible('#password'))) await page.click('#login-state');
  await page.fill('#password', PASSWORD);
  await page.click('#login-btn');
  await until('the session', () => loggedIn(page));
}
async function main() {
  port = await freePort();
  gpsdPort = await freePort();
  udpPort = await freePort();
  const base = useWebPort(port);
  useFeeds({ tmp, gpsdPort, udpPort });
  writeConfig();
  await startDaemon();
  // With AZT_WEB_DIR (see the top), the console's page and style sheet come from there.
  const browser = await launch({ '/': 'index.html', '/app.css': 'app.css' }, { viewport: { width: 1280, height: 800 } });
  const { page } = browser;
  try {
    await page.goto(base + '/', { waitUntil: 'load' });
    await until('live numbers', async () => /\d/.test(await text(page, '#ant-az')));
    // What the scenarios share; each group runs its scenarios in order, one group after another,
    // as each builds on what the one before left (a correction, a restart, a scan's feed).
    const t = { page, browser, base, outDir, config, sourcesFile, login, scenario, check, apiGet };
    await runTrackingScenarios(t);
    await runRestartScenarios(t);
    await runClockGpsScenarios(t);
    await runPlannerScenario(t);
    await runScanScenarios(t);
    await runPageScenarios(t);
    await measureConsole(t);
    checkPageErrors(browser.errors);
  } finally {
    stopGpsfake();
    await stopFeeder();
    await shutDown(browser);
  }
  summarise();
}

run(main, stopGpsfake);
