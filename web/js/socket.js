// The live state over /ws: reconnecting with back-off, a silent socket abandoned. The page says
// what a state message and a new connection mean (useSocket): the console and the panel share it.

import { S } from './state.js';
import { $, setText } from './dom.js';
import { fix } from './format.js';
import { refreshSession } from './session.js';

const on = { state: () => {}, connected: () => {} };
// state(st): each state message; connected(): the socket is up again (re-read what may be stale).
export function useSocket(handlers) { Object.assign(on, handlers); }

export function connect() {
  clearTimeout(S.retryTimer);
  S.attempts += 1;
  let ws;
  try {
    ws = new WebSocket(`${location.protocol === 'https:' ? 'wss:' : 'ws:'}//${location.host}/ws`);
  } catch (e) { retry(); return; }
  S.ws = ws; S.openedAt = performance.now();
  ws.onopen = () => { if (S.ws === ws) { S.lastMsg = performance.now(); setConnected(true); } };
  ws.onmessage = (ev) => {
    if (S.ws !== ws) return;
    S.lastMsg = performance.now(); S.backoff = 250; S.attempts = 0;
    if (!S.connected) setConnected(true);
    let st;
    try { st = JSON.parse(ev.data); } catch (e) { return; }
    if (st && typeof st === 'object') on.state(st);
  };
  ws.onclose = () => { if (S.ws === ws) { S.ws = null; setConnected(false); retry(); } };
  ws.onerror = () => { try { ws.close(); } catch (e) { /* closed */ } };
}
function retry() {
  clearTimeout(S.retryTimer);
  const wait = S.backoff;
  S.backoff = Math.min(2000, S.backoff * 2);
  setText('disc-detail', `Reconnecting in ${fix(wait / 1000, 1)} s${S.attempts > 1 ? ` (attempt ${S.attempts})` : ''}…`);
  S.retryTimer = setTimeout(connect, wait);
}
function dropSocket() { // a silent or stuck socket: abandon it and start again
  const ws = S.ws; S.ws = null;
  if (ws) { ws.onclose = ws.onmessage = ws.onopen = ws.onerror = null; try { ws.close(); } catch (e) { /* */ } }
  setConnected(false); retry();
}
export function setConnected(v) {
  const was = S.connected;
  S.connected = v;
  $('disconnected').hidden = v;
  $('conn-dot').className = `dot${v ? ' on' : ''}`;
  $('conn-dot').title = v ? 'Live: connected to the controller' : 'Not connected';
  document.body.classList.toggle('stale', !v);
  if (v && !was) {
    S.links += 1; // a new connection: after a restart, the controller is back
    on.connected();
    refreshSession(); // a restarted daemon has forgotten every session
  }
}
// A socket that says nothing for 3 s (the daemon sends state at least every second), or does not
// open in 4 s, is abandoned; a page coming back into view reconnects at once.
export function watchSocket() {
  setInterval(() => {
    const now = performance.now();
    if (S.ws && S.ws.readyState === WebSocket.OPEN && now - S.lastMsg > 3000) dropSocket();
    else if (S.ws && S.ws.readyState === WebSocket.CONNECTING && now - S.openedAt > 4000) dropSocket();
  }, 500);
  document.addEventListener('visibilitychange', () => {
    if (!document.hidden && !S.ws) { S.backoff = 250; connect(); }
  });
}
