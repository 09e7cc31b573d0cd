// The screens, chosen by the URL's #fragment.

import { S } from './state.js';
import { $ } from './dom.js';
import { drawTrend } from './trend.js';
import { drawSky, loadSky } from './sky.js';
import { loadTargets } from './targets.js';
import { drawTilt, loadConfig, softwareLine } from './setup.js';
import { renderStationPage } from './station.js';
import { toast } from './toast.js';

export const SCREENS = ['main', 'targets', 'sky', 'manual', 'antenna', 'setup'];
// Pages without a tab of their own (the phone's tab bar has no room): reached from the header's
// status icons and from Setup, whose tab stays lit on them; the planner from the Moon panel, the
// pointing scan from the Moon panel, Targets and Sky; the software, settings and account pages
// from Setup.
export const SUBSCREENS = { gps: 'setup', time: 'setup', network: 'setup', planner: 'main', scan: 'targets', software: 'setup',
  settings: 'setup', account: 'setup' };

// The pages whose modules are loaded when first opened, so that the console's first load stays
// light (docs/web-api.md "Measured"): each module's open() and, for those that follow the live
// state, its render(force), called with every state message while the page is shown.
const LAZY = {
  planner: [() => import('./planner.js'), 'openPlanner'],
  scan: [() => import('./scan.js'), 'openScan', 'renderScan'],
  software: [() => import('./software.js'), 'openSoftware', 'renderForm'],
  settings: [() => import('./settings.js'), 'openSettings'],
  account: [() => import('./settings_account.js'), 'openAccount'],
};
const loaded = {};
async function openLazy(name) {
  const [load, open] = LAZY[name];
  try {
    loaded[name] = loaded[name] || await load();
    if (S.screen === name) await loaded[name][open]();
  } catch (e) {
    toast(`The ${name} page could not be loaded: ${e.message}`, 'err');
  }
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
  else if (SUBSCREENS[name]) renderStationPage(name, true);
}
export function go(name) { if (location.hash === `#${name}`) show(name); else location.hash = name; }
