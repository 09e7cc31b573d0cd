// The screens, chosen by the URL's #fragment.

import { S } from './state.js';
import { $ } from './dom.js';
import { drawTrend } from './trend.js';
import { drawSky, loadSky } from './sky.js';
import { loadTargets } from './targets.js';
import { drawTilt, loadConfig } from './setup.js';
import { renderStationPage } from './station.js';
import { openPlanner } from './planner.js';
import { openScan } from './scan.js';
import { openSoftware, softwareSummary } from './software.js';
import { toast } from './toast.js';

export const SCREENS = ['main', 'targets', 'sky', 'manual', 'antenna', 'setup'];
// Pages without a tab of their own (the phone's tab bar has no room): reached from the header's
// status icons and from Setup, whose tab stays lit on them; the planner from the Moon panel, the
// pointing scan from the Moon panel, Targets and Sky; the software, settings and account pages
// from Setup.
export const SUBSCREENS = { gps: 'setup', time: 'setup', network: 'setup', planner: 'main', scan: 'targets', software: 'setup',
  settings: 'setup', account: 'setup' };

// The settings and account pages' modules are loaded when first opened: the console's first
// load stays light.
async function openLazy(name) {
  try {
    if (name === 'settings') await (await import('./settings.js')).openSettings();
    else await (await import('./settings_account.js')).openAccount();
  } catch (e) {
    toast(`The ${name} page could not be loaded: ${e.message}`, 'err');
  }
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
  if (name === 'setup') softwareSummary();
  if (name === 'antenna') drawTilt();
  if (name === 'planner') openPlanner();
  else if (name === 'scan') openScan();
  else if (name === 'software') openSoftware();
  else if (name === 'settings' || name === 'account') openLazy(name);
  else if (SUBSCREENS[name]) renderStationPage(name, true);
}
export function go(name) { if (location.hash === `#${name}`) show(name); else location.hash = name; }
