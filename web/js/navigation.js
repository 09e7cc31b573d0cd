// The screens, chosen by the URL's #fragment.

import { S } from './state.js';
import { $ } from './dom.js';
import { drawTrend } from './trend.js';
import { drawSky, loadSky } from './sky.js';
import { loadTargets } from './targets.js';
import { drawTilt, loadConfig } from './setup.js';

export const SCREENS = ['main', 'targets', 'sky', 'manual', 'antenna', 'setup'];

export function show(name) {
  if (!SCREENS.includes(name)) name = 'main';
  const changed = S.screen !== name;
  S.screen = name;
  for (const n of SCREENS) {
    $(`screen-${n}`).hidden = n !== name;
    $(`nav-${n}`).setAttribute('aria-selected', String(n === name));
  }
  if (changed) window.scrollTo({ top: 0 });
  if (name === 'main') { drawTrend(true); }
  if (name === 'targets') loadTargets();
  if (name === 'sky') { loadSky(); drawSky(true); }
  if (name === 'setup' || name === 'antenna' || name === 'manual') loadConfig();
  if (name === 'antenna') drawTilt();
}
export function go(name) { if (location.hash === `#${name}`) show(name); else location.hash = name; }
