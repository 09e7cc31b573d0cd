// The main screen from each state message: position, target, faults, who moved the antenna,
// station I/O and the Moon panel; the station's GPS, clock and network (station.js); the pol axis
// (pol.js) and each axis's drive hardware (drives.js).

import { S, targetLabel } from './state.js';
import { $, h, setText } from './dom.js';
import { countdown, deg, fix, hz, isNum, pad, sameName, sdeg, utcLocal, waitLine } from './format.js';
import { bandList, wavelength } from './bands.js';
import { drawTrend, TREND_S } from './trend.js';
import { drawSky } from './sky.js';
import { markActiveTarget } from './targets.js';
import { renderStation } from './station.js';
import { renderCorrectionsAndPosition } from './position.js';
import { renderPol } from './pol.js';
import { renderDrives } from './drives.js';

// "AOS 12:34 UTC (18:04 local) · max 83° · 8 s beyond 10° from 12:40:05 · in 4 min 12 s", or the tracker's phase.
function passLine(sat, utc) {
  if (!sat.aos) return sat.problem || sat.phase || '—';
  const hhmm = (iso, secs) => String(iso).slice(11, secs ? 19 : 16);
  const when = sat.phase === 'tracking' ? `LOS ${utcLocal(sat.los)}` : `AOS ${utcLocal(sat.aos)}`;
  const loss = sat.planned_loss || {};
  const lost = loss.seconds > 0
    ? `${Math.round(loss.seconds)} s beyond ${fix(loss.beyond_deg, 0)}° from ${hhmm(loss.from, true)}`
    : 'no loss planned';
  // The countdown from the daemon's clock (the state's utc), not the browser's.
  const toAos = (Date.parse(sat.aos) - Date.parse(utc)) / 1000;
  const soon = sat.phase !== 'tracking' && Number.isFinite(toAos) && toAos > 0 ? ` · ${countdown(toAos)}` : '';
  return `${when} · max ${deg(sat.max_el_deg, 0)}${sat.flip ? ' · flipped' : ''} · ${lost}${soon}`;
}

export function onState(st) {
  S.state = st;
  const t = st.target || {};
  // TRACK starts the selected target: the one chosen here last, or the one the controller last
  // switched to (a change of the tracked target, by anyone, becomes the selection).
  if (st.mode === 'TRACK' && t.name && !sameName(t.name, S.lastTracked)) {
    S.lastTracked = t.name;
    const mine = S.sel && (sameName(S.sel.serverName, t.name) || sameName(S.sel.label, t.name) || (S.sel.body.ra_deg !== undefined && !S.sel.serverName));
    if (mine) S.sel.serverName = t.name; else S.sel = { body: { name: t.name }, label: t.name, serverName: t.name };
  }
  // A: target
  setText('target-name', targetLabel(st));
  setText('target-az', deg(t.az_deg));
  setText('target-el', deg(t.el_deg));
  const m = st.moon;
  setText('doppler', m ? hz(m.echo_doppler_hz) : '—');
  setText('doppler-band', m && m.band ? `${m.band} MHz` : '');
  // As on the seed's screen: the echo lines only while the Moon is the target.
  const onMoon = st.mode === 'TRACK' && sameName(t.name, 'moon');
  $('echo-row').hidden = !onMoon;
  const dx = onMoon && m && isNum(m.dx_echo_doppler_hz);
  $('dx-row').hidden = !dx;
  if (dx) setText('dx-doppler', hz(m.dx_echo_doppler_hz));
  // A satellite: its pass and the loss planned before AOS (docs/satellites.md).
  const sat = st.mode === 'TRACK' ? t.satellite : null;
  $('sat-row').hidden = !sat;
  if (sat) setText('sat-pass', passLine(sat, st.utc));
  // Below the horizon limit: when it rises, instead of a pointing error that means nothing.
  const wait = st.mode === 'TRACK' ? t.waiting : null;
  $('wait-row').hidden = !wait;
  if (wait) setText('wait-line', waitLine(wait));
  // B: corrections; C: antenna
  const known = renderCorrectionsAndPosition(st);
  const a = st.antenna || {};
  // A fixed-elevation array: the elevation is not pointed, the target is in its beam or not.
  const fixedEl = isNum(a.el_fixed_deg);
  const inBeam = fixedEl && typeof t.in_beam === 'boolean' && !wait;
  $('beam-row').hidden = !inBeam;
  if (inBeam) setText('beam-line', `${t.in_beam ? 'in' : 'outside'} the beam at ${deg(a.el_fixed_deg)} elevation`);
  const e = st.error_deg;
  setText('err-az', e ? sdeg(e.az) : '—');
  setText('err-el', fixedEl ? 'fixed' : e ? sdeg(e.el) : '—');
  const pe = $('pointing-error');
  if (e && isNum(e.az) && isNum(e.el)) {
    const elErr = fixedEl ? 0 : e.el;
    const tot = Math.hypot(e.az * Math.cos(((isNum(a.el_deg) ? a.el_deg : 0) * Math.PI) / 180), elErr);
    setText(pe, deg(tot));
    const win = S.config && S.config.control ? S.config.control.window_deg : 0.1;
    pe.className = `perr ${tot <= Math.max(win, 0.02) + 0.01 ? 'good' : tot > 3 ? 'far' : ''}`;
  } else { setText(pe, '—'); pe.className = 'perr'; }
  const mv = $('ant-moving');
  setText(mv, !known ? 'position unknown' : a.moving ? 'moving' : 'still');
  mv.className = `moving${known && a.moving ? ' on' : ''}`;
  const showMount = known && isNum(a.az_mount_deg) && Math.abs(a.az_mount_deg - a.az_deg) > 0.005;
  $('mount-row').hidden = !showMount;
  if (showMount) setText('ant-mount', deg(a.az_mount_deg));
  // D: mode, time
  const mode = st.mode || '—';
  setText('mode', mode);
  $('mode').className = `mode m-${mode}`;
  setText('mode-who', st.who ? `by ${st.who}` : '');
  $('pc-locked').hidden = !st.pc_locked_out;
  setText('track-name', S.sel ? S.sel.label : 'choose a target');
  const d = st.utc ? new Date(st.utc) : null;
  if (d && !Number.isNaN(d.getTime())) {
    setText('utc', `${pad(d.getUTCHours())}:${pad(d.getUTCMinutes())}:${pad(d.getUTCSeconds())}`);
    setText('date', `${['Sun', 'Mon', 'Tue', 'Wed', 'Thu', 'Fri', 'Sat'][d.getUTCDay()]}, ${pad(d.getUTCDate())} ${
      ['Jan', 'Feb', 'Mar', 'Apr', 'May', 'Jun', 'Jul', 'Aug', 'Sep', 'Oct', 'Nov', 'Dec'][d.getUTCMonth()]} ${d.getUTCFullYear()}`);
  }
  // header
  setText('mini-az', known ? `${fix(a.az_deg, 2)}°` : '—');
  setText('mini-el', known ? `${fix(a.el_deg, 2)}°` : '—');
  setText('mini-mode', mode);
  $('mini-mode').className = `mini-mode m-${mode}`;
  renderFaults(Array.isArray(st.faults) ? st.faults : []);
  renderIo(st.station_io);
  renderLog('event-list', 'eventsKey', Array.isArray(st.events) ? st.events : [], 10);
  renderLog('command-list', 'commandsKey', Array.isArray(st.commands) ? st.commands : [], 6);
  renderMoon(m);
  renderStation(st);
  renderPol(st);
  renderDrives(st);
  // trend
  const now = performance.now() / 1000;
  S.trend.push([now, e && isNum(e.az) ? e.az : null, e && isNum(e.el) ? e.el : null]);
  while (S.trend.length && S.trend[0][0] < now - TREND_S - 5) S.trend.shift();
  if (S.screen === 'main') drawTrend();
  if (S.screen === 'sky') drawSky();
  if (S.screen === 'manual') {
    setText('man-cur-az', known ? deg(a.az_deg) : '—');
    setText('man-cur-el', known ? deg(a.el_deg) : '—');
    setText('man-cur-mode', `${mode}${st.who ? ` (${st.who})` : ''}`);
  }
  if (S.screen === 'targets') markActiveTarget();
}

function renderFaults(list) {
  const key = JSON.stringify(list);
  if (key === S.faultsKey) return;
  S.faultsKey = key;
  $('faults').hidden = list.length === 0;
  $('faults-plural').hidden = list.length === 1;
  $('fault-list').replaceChildren(...list.map((f) => h('li', { text: String(f) })));
}

// A newest-first list of {utc, text, count}: the refusals any source was given ("events") and
// the accepted motion commands with their sources ("commands"), docs/web-api.md.
function renderLog(listId, keyName, list, max) {
  const key = JSON.stringify(list);
  if (key === S[keyName]) return;
  S[keyName] = key;
  if (!list.length) { $(listId).replaceChildren(h('li', { class: 'dimtxt', text: 'none yet' })); return; }
  $(listId).replaceChildren(...list.slice(0, max).map((e) => h('li', {
    text: `${String(e.utc || '').slice(11, 19)}  ${String(e.text)}${e.count > 1 ? ` (×${e.count})` : ''}`,
  })));
}

// E-stop, limit switches and the T/R chain (docs/web-api.md "station_io"), wherever the page
// shows them: the main screen's Station I/O and the Settings page's hardware card (data-io).
function showIo(what, txt, bad) {
  document.querySelectorAll(`[data-io="${what}"]`).forEach((e) => { setText(e, txt); e.classList.toggle('io-bad', bad); });
}
export function renderIo(io) {
  const key = JSON.stringify(io || null);
  if (key === S.ioKey) return;
  S.ioKey = key;
  const es = io && io.estop ? io.estop : null;
  if (!es || (!es.wired && !es.latched)) showIo('estop', 'not wired', false); else {
    showIo('estop', es.latched ? (es.input ? 'PRESSED · latched' : 'latched · clear faults to resume') : 'ready', !!es.latched);
  }
  const lim = io && io.limits ? io.limits : null;
  const names = { az_ccw: 'AZ CCW', az_cw: 'AZ CW', el_down: 'EL DOWN', el_up: 'EL UP' };
  const tripped = lim ? Object.keys(names).filter((k) => lim[k]).map((k) => names[k]) : [];
  showIo('limits', !lim ? 'not wired' : tripped.length ? `tripped: ${tripped.join(', ')}` : 'all clear', tripped.length > 0);
  const seq = io && io.sequencer ? io.sequencer : null;
  let ptt = '—';
  if (seq) {
    ptt = seq.timed_out ? 'time-out: release PTT' : seq.inhibited ? 'inhibited' : seq.transmitting ? 'TRANSMIT'
      : seq.ptt ? 'keying…' : 'receive';
    if (!seq.wired) ptt += ' (no GPIO lines)';
  }
  showIo('ptt', ptt, !!(seq && (seq.transmitting || seq.timed_out)));
  // A pad absent is no fault (it is looked for every 2 s), so never shown as one.
  const pad = io && io.gamepad ? io.gamepad : null;
  showIo('pad', !pad ? 'none set' : pad.connected ? `connected: ${pad.name}`
    : pad.error ? `not found: ${pad.error}` : 'looking for it…', false);
  const outs = seq && Array.isArray(seq.outputs) ? seq.outputs : [];
  $('io-seq').replaceChildren(...outs.map((o) => h('span', { class: `out${o.on ? ' on' : ''}`, text: String(o.name) })));
}
// A view of the inputs just built: drawn at once from the last state.
export function refreshIo() { S.ioKey = ''; if (S.state) renderIo(S.state.station_io); }

/// WSJT-X's Astronomical Data fields (docs/eme.md).
function renderMoonEme(m) {
  const tsky = isNum(m.tsky_k) ? `${Math.round(m.tsky_k)} K` : '—';
  setText('moon-tsky', isNum(m.dgrd_db) ? `${tsky} / ${m.dgrd_db.toFixed(1)} dB` : tsky);
  const width = isNum(m.width_hz) ? `${m.width_hz.toFixed(1)} Hz` : '—';
  setText('moon-width', isNum(m.dx_width_hz) ? `${width} · DX ${m.dx_width_hz.toFixed(1)} Hz` : width);
  setText('moon-sunsep', isNum(m.sun_sep_deg) ? `${m.sun_sep_deg.toFixed(1)}°` : '—');
  setText('moon-illum', isNum(m.illumination) ? `${Math.round(100 * m.illumination)} %` : '—');
  setText('moon-par', isNum(m.parallactic_deg) ? `${m.parallactic_deg.toFixed(1)}°` : '—');
  const dx = isNum(m.dpol_deg);
  $('moon-dpol-row').hidden = !dx;
  if (dx) setText('moon-dpol', `${m.dpol_deg > 0 ? '+' : ''}${m.dpol_deg.toFixed(1)}° / ${m.mnr_db.toFixed(1)} dB`);
  setText('moon-dec', isNum(m.dec_deg) ? `${m.dec_deg.toFixed(1)}°` : '—');
  const rate = (hz) => `${hz > 0 ? '+' : ''}${hz.toFixed(1)} Hz/min`;
  const dfdt = isNum(m.echo_doppler_rate_hz_min) ? rate(m.echo_doppler_rate_hz_min) : '—';
  setText('moon-dfdt', isNum(m.dx_echo_doppler_rate_hz_min) ? `${dfdt} · DX ${rate(m.dx_echo_doppler_rate_hz_min)}` : dfdt);
  const there = m.dx && isNum(m.dx.az_deg) ? m.dx : null;
  $('moon-dx-row').hidden = !there;
  if (there) setText('moon-dx', `${deg(there.az_deg)} / ${deg(there.el_deg)} / ${there.dec_deg.toFixed(1)}°`);
}

function renderMoon(m) {
  if (!m) {
    setText('moon-azel', 'not available'); setText('moon-dist', '—'); setText('moon-delay', '—');
    for (const id of ['moon-tsky', 'moon-width', 'moon-sunsep', 'moon-illum', 'moon-par', 'moon-dec', 'moon-dfdt']) setText(id, '—');
    $('moon-dpol-row').hidden = true;
    $('moon-dx-row').hidden = true;
    if (S.dopKey) { $('moon-doppler').replaceChildren(); S.dopKey = ''; }
    return;
  }
  setText('moon-azel', `${deg(m.az_deg)} / ${deg(m.el_deg)}${isNum(m.el_deg) && m.el_deg < 0 ? ' (below horizon)' : ''}`);
  setText('moon-dist', isNum(m.distance_km) ? `${Math.round(m.distance_km).toLocaleString('en-US')} km` : '—');
  setText('moon-delay', isNum(m.echo_delay_s) ? `${m.echo_delay_s.toFixed(3)} s` : '—');
  renderMoonEme(m);
  const dop = m.doppler_hz && typeof m.doppler_hz === 'object' ? m.doppler_hz : {};
  const bands = Object.keys(dop).sort((x, y) => Number(x) - Number(y));
  const key = `${bands.join(',')}|${m.band}|${bandList().length}`;  // names once /api/targets is in
  if (key !== S.dopKey) {
    S.dopKey = key;
    $('moon-doppler').replaceChildren(h('div', { class: 'dophead', text: 'Self-echo Doppler by band (MHz)' }),
      ...bands.map((b) => h('div', { class: `dop${String(b) === String(m.band) ? ' sel' : ''}` },
        h('span', {}, String(b), ' ', h('small', { text: wavelength(b) })), h('b', { 'data-band': b }))));
  }
  for (const el of $('moon-doppler').querySelectorAll('b[data-band]')) setText(el, hz(dop[el.dataset.band]));
}
