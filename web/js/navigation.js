// The screens, chosen by the URL's #fragment.

import { S } from './state.js';
import { $ } from './dom.js';
import { drawTrend } from './trend.js';
import { drawSky, loadSky } from './sky.js';
import { loadTargets } from './targets.js';
import { drawTilt, loadConfig, softwareLine } from './setup.js';
import { renderStationPage } from './station.js';
import { wireTime } from './time.js';
import { loadPage } from './pages.js';
import { toast } from './toast.js';

export const SCREENS = ['main', 'targets', 'sky', 'manual', 'antenna', 'setup'];
// Pages without a tab of their own (the phone's tab bar has no room): reached from the header's
// status icons and from Setup, whose tab stays lit on them; the planner from the Moon panel, the
// pointing scan from the Moon panel, Targets and Sky, the calibration page from Targets and the scan; the software, settings, account and radio
// pages from Setup; the satellite schedule from Targets.
export const SUBSCREENS = { gps: 'setup', time: 'setup', network: 'setup', planner: 'main', scan: 'targets', calibration: 'targets', software: 'setup',
  settings: 'setup', account: 'setup', radio: 'setup', schedule: 'targets' };

// The pages whose modules are loaded when first opened (their markup and style too: pages.js), so
// that the console's first load stays light (docs/web-api.md "Measured"): each module's open()
// and, for those that follow the live state, its render(force), called with every state message
// while the page is shown.
const LAZY = {
  planner: [() => import('./planner.js'), 'openPlanner'],
  scan: [() => import('./scan.js'), 'openScan', 'renderScan'],
  calibration: [() => import('./calibration.js'), 'openCalibration', 'renderCalibration'],
  software: [() => import('./software.js'), 'openSoftware', 'renderForm'],
  settings: [() => import('./settings.js'), 'openSettings'],
  account: [() => import('./settings_account.js'), 'openAccount'],
  radio: [() => import('./radio.js'), 'openRadio', 'renderRadio'],
  schedule: [() => import('./schedule.js'), 'openSchedule', 'renderSchedule'],
};
const loaded = {};
async function openLazy(name) {
  const [load, open] = LAZY[name];
  try {
    await loadPage(name);
    loaded[name] = loaded[name] || await load();
    if (S.screen === name) await loaded[name][open]();
  } catch (e) {
    toast(`The ${name} page could not be loaded: ${e.message}`, 'err');
  }
}
// The GPS, Time and Network pages: their modules are loaded at start (the header's icons and
// Setup's lines need them), their markup when first opened.
async function openStation(name) {
  try {
    await loadPage(name, name === 'time' ? wireTime : null);
  } catch (e) {
    toast(`The ${name} page could not be loaded: ${e.message}`, 'err');
    return;
  }
  if (S.screen === name) renderStationPage(name, true);
}
// The shown page's render(force), if it has one and its module is loaded.
export function renderPage(force) {
  const m = loaded[S.screen];
  const render = m && LAZY[S.screen][2];
  if (render) m[render](force);
}

export function show(name) {
  if (!SCREENS.includes(name) && !SUBSCREENS[name]) name = 'main';
  const changed = S.screen !== name;
  S.screen = name;
  const tab = SUBSCREENS[name] || name;
  for (const n of [...SCREENS, ...Object.keys(SUBSCREENS)]) $(`screen-${n}`).hidden = n !== name;
  for (const n of SCREENS) $(`nav-${n}`).setAttribute('aria-selected', String(n === tab));
  document.querySelectorAll('.sico').forEach((b) => b.classList.toggle('here', b.dataset.go === name));
  if (changed) window.scrollTo({ top: 0 });
  if (name === 'main') { drawTrend(true); }
  if (name === 'targets') loadTargets();
  if (name === 'sky') { loadSky(); drawSky(true); }
  if (name === 'setup' || name === 'antenna' || name === 'manual') loadConfig();
  if (name === 'setup') softwareLine();
  if (name === 'antenna') drawTilt();
  if (LAZY[name]) openLazy(name);
  else if (SUBSCREENS[name]) openStation(name);
}
export function go(name) { if (location.hash === `#${name}`) show(name); else location.hash = name; }
