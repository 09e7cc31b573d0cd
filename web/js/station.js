// The station's own health on every screen (docs/web-api.md "gps", "time", "network"): the
// header's GPS, Ethernet and WiFi icons, the banner of an unsynchronised clock, the main screen's
// clock line and Setup's summaries; and, while one is shown, the GPS, Time or Network page.

import { S } from './state.js';
import { $, setText } from './dom.js';
import { gpsLevel, gpsSummary, renderGps } from './gps.js';
import { renderTime, timeLine } from './time.js';
import { linkOf, netSummary, renderNetwork } from './network.js';
import { pageReady } from './pages.js';

function setIcon(id, cls, state, title) {
  const b = $(id);
  const c = `sico ${cls}${b.classList.contains('here') ? ' here' : ''}`;
  if (b.className !== c) b.className = c;
  if (b.dataset.state !== state) b.dataset.state = state;
  if (b.title !== title) { b.title = title; b.setAttribute('aria-label', title); }
}

function renderIcons(st) {
  const g = st.gps;
  const lvl = gpsLevel(g);
  setIcon('ico-gps', lvl, lvl, `GPS: ${gpsSummary(g)}`);
  const net = st.network;
  const eth = linkOf(net, 'ethernet');
  setIcon('ico-eth', eth.state === 'up' ? 'up' : eth.state === 'down' ? 'down' : 'off', eth.state, `Ethernet: ${eth.text}`);
  const wifi = linkOf(net, 'wifi');
  setIcon('ico-wifi', wifi.state === 'up' ? 'up' : wifi.state === 'down' ? 'down' : 'off', wifi.state, `WiFi: ${wifi.text}`);
  const bars = String(wifi.bars);
  if ($('ico-wifi').dataset.bars !== bars) $('ico-wifi').dataset.bars = bars;
}

/// The clock banner can be hidden until its reason changes: a station that runs without NTP on
/// purpose should not carry a warning over its screen all night.
function dismissClockBanner() {
  sessionStorage.setItem('azt-clock-dismissed', $('clock-reason').textContent);
  $('clock-banner').hidden = true;
}

function renderClock(t) {
  const bad = !!t && t.synced === false;
  const reason = bad ? String(t.reason || 'no reason given').replace(/\.+$/, '') : '';
  $('clock-banner').hidden = !bad || sessionStorage.getItem('azt-clock-dismissed') === reason;
  if (bad) setText('clock-reason', reason);
  const [word, detail] = timeLine(t);
  setText('clock-source', word);
  const cs = $('clock-source');
  const cls = bad ? 'io-bad' : '';
  if (cs.className !== cls) cs.className = cls;
  setText('clock-status', detail);
  setText('setup-clock', detail ? `${word} · ${detail}` : word);
}

// Setup's Radio line: the rig's link, whose Doppler, WSJT-X (the Radio page has the rest).
function radioLine(r, w) {
  const link = String((r && r.link) || 'off');
  const rig = link === 'off' ? 'no rig' : link === 'up' ? 'rig up' : link === 'connecting' ? 'rig connecting' : 'rig down';
  const dop = r && r.doppler && r.doppler !== 'off' ? `${r.doppler} Doppler` : 'Doppler off';
  return [rig, dop, w && w.listening ? 'WSJT-X listened to' : ''].filter(Boolean).join(' · ');
}

export function renderStation(st) {
  renderIcons(st);
  renderClock(st.time || null);
  setText('setup-gps', gpsSummary(st.gps));
  setText('setup-net', netSummary(st.network));
  setText('setup-radio', radioLine(st.radio, st.wsjtx));
  if (['gps', 'time', 'network'].includes(S.screen) && pageReady(S.screen)) renderStationPage(S.screen, false);
}

// The page `name` from the latest state; `force` redraws what is otherwise redrawn on change only.
export function renderStationPage(name, force) {
  const st = S.state;
  if (!st) return;
  if (name === 'gps') renderGps(st.gps || null, force);
  if (name === 'time') renderTime(st.time || null, force);
  if (name === 'network') renderNetwork(st.network || null, force);
}

export function wireStation(go) {
  document.querySelectorAll('.sico').forEach((b) => b.addEventListener('click', () => go(b.dataset.go)));
  $('clock-dismiss').addEventListener('click', dismissClockBanner);
}
