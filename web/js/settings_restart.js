// "Restart needed": the saved keys the controller runs without until its next start
// (restart_needed), and the Restart button. POST /api/restart (202) stops the motors; the
// controller exits and comes back (restarted by systemd, or re-executing itself under
// scripts/run). The page then waits for its live connection to come back (socket.js counts the
// connections in S.links) and reads the settings again: the banner goes when nothing waits.

import { S } from './state.js';
import { $, h, setText } from './dom.js';
import { toast } from './toast.js';
import { act } from './actions.js';
import { ask } from './confirm.js';
import { refreshSession } from './session.js';

const BACK_WITHIN_MS = 90000;
let restarting = false;
let reload = async () => true;
let waiting = [];

export function renderRestart(list) {
  waiting = Array.isArray(list) ? list : [];
  $('restart-banner').hidden = !waiting.length && !restarting;
  const n = waiting.length;
  setText('restart-count', n === 1 ? '1 saved setting applies' : `${n} saved settings apply`);
  $('restart-keys').replaceChildren(...waiting.map((k) => h('li', {}, h('code', { text: k }))));
}

export function wireRestart(reloadSettings) {
  reload = reloadSettings;
  $('restart-btn').addEventListener('click', restart);
}

const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

async function restart() {
  if (restarting) return;
  const yes = await ask({
    title: 'Restart the controller?',
    text: 'The motors stop now. The controller exits and starts again with the saved settings, which takes a few seconds; PC programs and this page lose their connection meanwhile, and everyone logged in is logged out.',
    ok: 'Stop the motors and restart', danger: true,
  });
  if (!yes) return;
  const btn = $('restart-btn');
  const links = S.links;
  const r = await act('restart the controller', 'POST', '/api/restart', undefined, { btn, quiet: true });
  if (!r.ok) {
    if (r.status === 401) setText('restart-msg', 'Not restarted: log in first.');
    else if (r.status === 404) setText('restart-msg', 'This controller cannot restart from the console (it answered 404): restart it by hand (sudo systemctl restart azeltrack).');
    else setText('restart-msg', `Not restarted: ${r.data.error || (r.status ? `HTTP ${r.status}` : 'no answer from the controller')}`);
    return;
  }
  restarting = true;
  btn.disabled = true;
  $('restart-banner').classList.add('busy-banner');
  setText('restart-msg', 'Restarting… the motors are stopped; waiting for the controller to answer again.');
  const started = Date.now();
  while (!(S.connected && S.links > links) && Date.now() - started < BACK_WITHIN_MS) await sleep(250);
  const back = S.connected && S.links > links;
  restarting = false;
  btn.disabled = false;
  $('restart-banner').classList.remove('busy-banner');
  if (!back) {
    setText('restart-msg', `The controller has not answered for ${BACK_WITHIN_MS / 1000} s. Under systemd, see journalctl -u azeltrack; the page reconnects by itself when it is back.`);
    renderRestart(waiting);
    return;
  }
  setText('restart-msg', '');
  await refreshSession();
  await reload();
  toast(`The controller has restarted with the saved settings.${S.loggedIn ? '' : ' Log in again to act.'}`);
}
