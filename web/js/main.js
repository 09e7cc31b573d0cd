// azeltrack web console: live state over /ws, actions over the JSON API (docs/web-api.md).
// Plain ES2020 modules, no build step and no dependencies; each module holds one part of the page.

import { S } from './state.js';
import { $, setText } from './dom.js';
import { refreshSession, setLoggedIn } from './session.js';
import { renderPage, show } from './navigation.js';
import { connect, setConnected, useSocket, watchSocket } from './socket.js';
import { onState } from './live.js';
import { drawTrend } from './trend.js';
import { loadSky } from './sky.js';
import { loadTargets, wireSatelliteSearch } from './targets.js';
import { renderElementSources, wireElements } from './elements.js';
import { buildPark, buildTilt, drawTilt, loadConfig } from './setup.js';
import { applyTheme, wire } from './wire.js';

function start() {
  // The pages loaded on demand that follow the live state (the pointing scan; the software page's
  // form, which follows the login that any screen can change) and the Targets page's element
  // sources are brought up to date by each state message.
  const state = (st) => {
    onState(st);
    renderPage();
    if (S.screen === 'targets') renderElementSources();
  };
  useSocket({ state, connected: () => { if (!S.config) loadConfig(); if (!S.targets) loadTargets(); } });
  applyTheme(localStorage.getItem('azt.theme') || 'dark');
  buildPark();
  buildTilt();
  wire();
  wireElements();
  wireSatelliteSearch();
  setLoggedIn(false, null);
  $('login-form').hidden = true; // until /api/session has answered
  setConnected(false);
  setText('disc-detail', 'Connecting…');
  show(location.hash.slice(1) || 'main');
  refreshSession();
  loadConfig();
  loadTargets();
  connect();
  watchSocket();
  setInterval(() => {
    if (document.hidden) return;
    if (S.screen === 'targets') loadTargets();
  }, 30000);
  setInterval(() => { if (!document.hidden && S.screen === 'sky') loadSky(); }, 60000);
  setInterval(() => { if (S.screen === 'main' && !S.connected) drawTrend(true); }, 1000);
  let rt = 0;
  window.addEventListener('resize', () => { clearTimeout(rt); rt = setTimeout(() => { if (S.screen === 'main') drawTrend(true); if (S.screen === 'antenna') drawTilt(); if (S.screen === 'scan') renderPage(true); }, 150); });
}
if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', start); else start();
