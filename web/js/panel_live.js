// The panel from each state message (docs/web-api.md /api/state): A the target, B the
// corrections, C the antenna, D (the bar, on every screen) the time and status; the status
// screen's details, each axis's drives among them. The verdicts on GPS, network and clock are the
// console's (gps.js, network.js, time.js), so both pages say the same.

import { S, targetLabel } from './state.js';
import { $, setText } from './dom.js';
import { deg, fix, hz, isNum, pad, sameName, sdeg, waitLine, waitShort } from './format.js';
import { gpsLevel, gpsSummary } from './gps.js';
import { linkOf, netSummary } from './network.js';
import { timeLine } from './time.js';
import { markActive } from './panel_targets.js';
import { renderCorrectionsAndPosition } from './position.js';

// One indicator for the links, as the AnTrack-Pro has: lit when Ethernet or WiFi is up.
function renderIndicators(st) {
  const gps = $('ind-gps');
  const lvl = gpsLevel(st.gps);
  if (gps.dataset.state !== lvl) gps.dataset.state = lvl;
  gps.title = `GPS: ${gpsSummary(st.gps)}`;
  const eth = linkOf(st.network, 'ethernet');
  const wifi = linkOf(st.network, 'wifi');
  const states = [eth.state, wifi.state];
  const net = states.includes('up') ? 'up' : states.includes('down') ? 'down' : states.includes('unknown') ? 'unknown' : 'off';
  const ind = $('ind-net');
  if (ind.dataset.state !== net) ind.dataset.state = net;
  ind.title = `Ethernet: ${eth.text} · WiFi: ${wifi.text}`;
}

// D: the UTC time and a line of status (mode, faults, clock), on the bar of every screen.
function renderBar(st, faults) {
  const d = st.utc ? new Date(st.utc) : null;
  if (d && !Number.isNaN(d.getTime())) setText('utc', `${pad(d.getUTCHours())}:${pad(d.getUTCMinutes())}:${pad(d.getUTCSeconds())}`);
  const synced = !!st.time && st.time.synced === true;
  const parts = [st.mode || '—'];
  if (faults.length) parts.push(`${faults.length} FAULT${faults.length > 1 ? 'S' : ''}`);
  parts.push(synced ? 'clock synced' : 'clock NOT synced');
  setText('status-line', parts.join(' · '));
  const cls = `sline${faults.length || !synced ? ' bad' : ''}`;
  if ($('status-line').className !== cls) $('status-line').className = cls;
}

// Each axis's own hardware in one line ("EL homed · brake released; AZ 1.2 A"), as the console's
// Drives card has it in full; empty when `antenna.axes` is absent. Homing is the console's.
function drivesLine(axes) {
  if (!axes || typeof axes !== 'object') return '';
  return ['az', 'el', 'pol'].filter((k) => axes[k]).map((k) => {
    const a = axes[k];
    const parts = [a.homing, a.brake ? `brake ${a.brake}` : null, isNum(a.current_a) ? `${fix(a.current_a, 1)} A` : null,
      isNum(a.temperature_c) ? `${fix(a.temperature_c, 0)} °C` : null, a.reset_refused ? 'trip latched' : null];
    return `${k.toUpperCase()} ${parts.filter(Boolean).join(' · ')}`;
  }).join('; ');
}

function renderStatus(st, faults) {
  setText('st-mode', `${st.mode || '—'}${st.who ? ` by ${st.who}` : ''}${st.pc_locked_out ? ' · PC programs locked out' : ''}`);
  const [word, detail] = timeLine(st.time || null);
  setText('st-clock', detail ? `${word}: ${detail}` : word);
  setText('st-gps', gpsSummary(st.gps));
  setText('st-net', netSummary(st.network));
  setText('st-faults', faults.length ? faults.join('; ') : 'none');
  const drives = drivesLine(st.antenna && st.antenna.axes);
  $('st-drives-t').hidden = !drives;
  $('st-drives').hidden = !drives;
  setText('st-drives', drives || '—');
  $('faults-clear').hidden = !faults.length;
  $('allow-pc').hidden = !st.pc_locked_out;
}

export function renderPanel(st) {
  S.state = st;
  const t = st.target || {};
  // A: the target, and the Moon's echo Doppler while the Moon is the target (as on the seed)
  setText('target-name', targetLabel(st));
  setText('target-az', deg(t.az_deg));
  setText('target-el', deg(t.el_deg));
  const onMoon = st.mode === 'TRACK' && sameName(t.name, 'moon');
  $('echo-row').hidden = !onMoon;
  if (onMoon) setText('doppler', hz(st.moon ? st.moon.echo_doppler_hz : null));
  const wait = st.mode === 'TRACK' ? t.waiting : null;
  $('wait-row').hidden = !wait;
  if (wait) {
    setText('wait-line', waitShort(wait));
    $('wait-row').title = `Waiting: ${waitLine(wait)}. The antenna holds until the target is up.`;
  }
  renderIndicators(st);
  // B: the operator's corrections; C: where the antenna points
  const known = renderCorrectionsAndPosition(st);
  const a = st.antenna || {};
  setText('ant-moving', !known ? 'position unknown' : a.moving ? 'moving' : 'still');
  const e = st.error_deg;
  setText('err-az', e ? sdeg(e.az) : '—');
  // The polarisation axis, when the station has one: its angle as read and its mode.
  $('pol-row').hidden = !st.pol;
  if (st.pol) setText('pol-angle', `${deg(st.pol.mount_deg, 1)} ${st.pol.mode}`);
  setText('err-el', e ? sdeg(e.el) : '—');
  const faults = Array.isArray(st.faults) ? st.faults.map(String) : [];
  renderBar(st, faults);
  if (S.screen === 'status') renderStatus(st, faults);
  if (S.screen === 'targets' || S.screen === 'park') markActive();
}
export function renderStatusScreen() {
  if (S.state) renderStatus(S.state, Array.isArray(S.state.faults) ? S.state.faults.map(String) : []);
}
