// azeltrack's touch panel (/panel, docs/panel.md): the AnTrack-Pro's screens for a 4" 480×320
// display, on the console's modules: the live state over /ws (socket.js), the JSON API and its
// actions (api.js, actions.js), the login session (session.js) and the targets (targets.js).

import { S } from './state.js';
import { $, setText } from './dom.js';
import { toast } from './toast.js';
import { act } from './actions.js';
import { adoptToken, refreshSession, setLoggedIn } from './session.js';
import { connect, setConnected, useSocket, watchSocket } from './socket.js';
import { renderPanel, renderStatusScreen } from './panel_live.js';
import { loadPanelTargets, markActive, wireTargets } from './panel_targets.js';
import { cancelLogin, perform, wireLogin } from './panel_login.js';

// Each screen and the one its Back returns to; STOP and the bar stay on all of them.
const SCREENS = { main: null, targets: 'main', park: 'targets', radec: 'targets', status: 'main' };
const BACK = { main: 'Main', targets: 'Targets' };

function go(name) {
  if (!(name in SCREENS)) name = 'main';
  S.screen = name;
  for (const n of Object.keys(SCREENS)) $(`screen-${n}`).hidden = n !== name;
  const up = SCREENS[name];
  $('back').hidden = !up;
  if (up) setText('back', `‹ ${BACK[up]}`);
  if (!$('login-form').hidden) cancelLogin(); // leaving the screen drops the action it was for
  if (name === 'targets' || name === 'park') { loadPanelTargets(); markActive(); }
  if (name === 'status') renderStatusScreen();
}

function stop() {
  return perform(async () => {
    const r = await act('STOP', 'POST', '/api/stop', undefined, { btn: $('btn-stop') });
    if (r.ok) toast('STOP: motors stopped, PC programs locked out.');
    return r;
  });
}

function wire() {
  $('btn-stop').addEventListener('click', stop);
  $('back').addEventListener('click', () => go(SCREENS[S.screen] || 'main'));
  $('target-pick').addEventListener('click', () => go('targets'));
  $('status-btn').addEventListener('click', () => go(S.screen === 'status' ? 'main' : 'status'));
  const step = (axis, n, id) => $(id).addEventListener('click', () =>
    perform(() => act(`correct ${axis.toUpperCase()}`, 'POST', '/api/correction', { axis, steps: n }, { btn: $(id) })));
  step('az', -1, 'az-minus'); step('az', 1, 'az-plus'); step('el', -1, 'el-down'); step('el', 1, 'el-up');
  $('faults-clear').addEventListener('click', () => perform(async () => {
    const r = await act('clear the faults', 'POST', '/api/faults/clear', undefined, { btn: $('faults-clear') });
    if (r.ok) toast('Faults cleared. Choose a target to move again.');
    return r;
  }));
  // After a console STOP: hands the antenna to PC programs without moving it (EXT, no target).
  $('allow-pc').addEventListener('click', () => perform(async () => {
    const r = await act('allow PC control', 'POST', '/api/control/pc', undefined, { btn: $('allow-pc') });
    if (r.ok) toast('PC programs may move the antenna; nothing moved.');
    return r;
  }));
  wireLogin();
  wireTargets(go);
}

function start() {
  adoptToken();
  useSocket({ state: renderPanel, connected: loadPanelTargets });
  wire();
  setLoggedIn(false, null);
  setConnected(false);
  go('main');
  refreshSession();
  loadPanelTargets();
  connect();
  watchSocket();
  // The sources' positions for the target screen; the state itself comes over /ws.
  setInterval(() => { if (!document.hidden && (S.screen === 'targets' || S.screen === 'park')) loadPanelTargets(); }, 30000);
}
if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', start); else start();
