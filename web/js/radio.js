// The Radio page (#radio, from Setup): what the daemon's radio does (docs/radio.md "In the daemon",
// /api/state `radio` and `wsjtx`): the rig's link, the frequencies it acknowledged and their
// Doppler corrections, WSJT-X as heard; and, plainly, that only one program may do Doppler.
// Loaded when the page is first opened (navigation.js).

import { S } from './state.js';
import { $, setText } from './dom.js';
import { ago, hz, isNum, mhzDots, utcLocal } from './format.js';

// WSJT-X sends a Heartbeat every 15 s: heard within two of them is heard now.
const HEARD_S = 30;

const EME = {
  dx: 'full Doppler to the DX grid', self: 'own echo', constant: 'constant frequency on the Moon',
  on_dx: 'on DX echo', call_dx: 'call DX',
};

// Everything shown comes with /api/state `radio`: the rigs' addresses, the EME mode and the
// transmitter followed too.
export function openRadio() {
  renderRadio();
}

export function renderRadio() {
  const st = S.state;
  if (!st || !$('radio-rx')) return;
  const r = st.radio || { doppler: 'off', link: 'off' };
  const w = st.wsjtx || { listening: false };
  const heard = heardAgo(w, st.utc);
  renderLink(r);
  renderFrequencies(r, st);
  renderWsjtx(w, heard);
  renderOwner(r, heard);
}

// Seconds since WSJT-X was last heard, by the daemon's clock; null if never or not listening.
function heardAgo(w, utc) {
  if (!w.listening || !w.last_heard) return null;
  const s = (Date.parse(utc) - Date.parse(w.last_heard)) / 1000;
  return Number.isFinite(s) ? Math.max(0, s) : null;
}

function badge(id, cls, word) {
  const b = $(id);
  if (b.className !== `badge ${cls}`) b.className = `badge ${cls}`;
  setText(b, word);
}

// "up", "connecting", "down: why" or "off" (no rig in the file).
function linkWords(link) {
  const l = String(link || 'off');
  if (l === 'up') return ['b-fix', 'LINK UP', 'the rig answers'];
  if (l === 'connecting') return ['', 'CONNECTING', 'connecting to the rig…'];
  if (l.startsWith('down')) return ['b-bad', 'LINK DOWN', l.replace(/^down:?\s*/, '') || 'no reason given'];
  return ['b-off', 'NO RIG', 'no rig: [radio] rigctld and model are empty'];
}


function renderLink(r) {
  const [cls, word, why] = linkWords(r.link);
  badge('radio-badge', cls, word);
  setText('radio-link-text', r.link && String(r.link).startsWith('down') ? `${why} (retrying)` : why);
  setText('radio-rigctld', r.rig || 'none');
  $('radio-tx-link-row').hidden = !r.tx_link;
  if (r.tx_link) setText('radio-tx-link', `${r.tx_rig || ''} ${linkWords(r.tx_link)[2]}`.trim());
  const mode = r.eme_mode;
  const words = { off: 'off: azeltrack writes nothing to the rig', satellite: 'the tracked satellite’s transmitter',
    eme: `the Moon’s echo${EME[mode] ? `: ${EME[mode]}` : ''}` };
  setText('radio-doppler', words[r.doppler] || String(r.doppler || 'off'));
  const problem = $('radio-problem');
  problem.hidden = !r.problem;
  if (r.problem) setText(problem, `Nothing written: ${r.problem}.`);
}

// A leg's frequency, and its correction ("+2592 Hz Doppler").
function leg(id, f, corr) {
  setText(id, mhzDots(f));
  setText(`${id}-corr`, isNum(f) && isNum(corr) ? `${hz(corr)} Doppler` : '');
}

function renderFrequencies(r, st) {
  leg('radio-rx', r.rx_hz, r.rx_correction_hz);
  leg('radio-tx', r.tx_hz, r.tx_correction_hz);
  // What the rig would be on without Doppler: the dial (EME), the satellite-frame frequencies.
  const nominal = (f, c) => (isNum(f) && isNum(c) ? mhzDots(f - c) : '—');
  setText('radio-nominal', `${nominal(r.rx_hz, r.rx_correction_hz)} / ${nominal(r.tx_hz, r.tx_correction_hz)}`);
  const sat = st.mode === 'TRACK' && st.target ? st.target.satellite : null;
  $('radio-sat-row').hidden = r.doppler !== 'satellite';
  $('radio-transmitter-row').hidden = r.doppler !== 'satellite';
  if (r.doppler === 'satellite') {
    setText('radio-sat', sat ? `${sat.sat} (NORAD ${sat.norad})` : 'none tracked');
    setText('radio-transmitter', transmitterWords(r.transmitter));
  }
  const behind = isNum(r.at_unix_s) ? (Date.parse(st.utc) / 1000) - r.at_unix_s : NaN;
  setText('radio-at', r.at ? `${utcLocal(r.at, true)}${Number.isFinite(behind) ? ` · ${ago(Math.max(0, behind))} ago` : ''}` : 'nothing written yet');
}

// The [[satellites.transmitter]] followed, downlink / uplink in the satellite's frame:
// "437.800.000 / 145.990.000 MHz · fm".
function transmitterWords(t) {
  if (!t) return 'none for this satellite';
  const mhz = (f) => mhzDots(f * 1e6);
  const up = isNum(t.uplink_mhz) ? ` / ${mhz(t.uplink_mhz)} MHz` : ' MHz, receive only';
  return `${mhz(t.downlink_mhz)}${up} · ${t.mode}`;
}

function renderWsjtx(w, heard) {
  if (!w.listening) {
    badge('wsjtx-badge', 'b-off', 'OFF');
    setText('wsjtx-state', 'not listening: [wsjtx] listen is empty');
  } else if (heard != null && heard <= HEARD_S) {
    badge('wsjtx-badge', 'b-fix', 'HEARD');
    setText('wsjtx-state', `WSJT-X heard ${ago(heard)} ago`);
  } else {
    badge('wsjtx-badge', '', 'SILENT');
    setText('wsjtx-state', heard == null ? 'listening; nothing from WSJT-X yet' : `nothing from WSJT-X for ${ago(heard)}`);
  }
  setText('wsjtx-address', w.address || '—');
  setText('wsjtx-heard', w.last_heard ? utcLocal(w.last_heard, true) : 'never');
  setText('wsjtx-id', w.id || '—');
  setText('wsjtx-dx', [w.dx_call, w.dx_grid].filter(Boolean).join(' · ') || '—');
  const tx = $('wsjtx-tx');
  setText(tx, w.transmitting ? 'TRANSMITTING' : 'no');
  tx.classList.toggle('io-bad', !!w.transmitting);
  setText('wsjtx-hold', w.hold ? 'held while WSJT-X transmits' : 'free to move');
  setText('wsjtx-period', isNum(w.tr_period_s) ? `${w.tr_period_s} s` : '—');
  setText('wsjtx-malformed', w.malformed ? `${w.malformed}${w.last_malformed ? ` · last: ${w.last_malformed}` : ''}` : '0');
}

// Two programs writing one rig undo each other's correction every second (docs/radio.md "Beside
// WSJT-X, Gpredict and SDR programs"): said whenever it may be happening or be meant.
function renderOwner(r, heard) {
  const box = $('radio-owner');
  let title = '';
  let words = '';
  if (r.doppler === 'off' || !r.doppler) {
    title = 'azeltrack’s Doppler is off ([radio] doppler = "off"): it writes nothing to the rig.';
    words = 'Only one program may do Doppler. If WSJT-X does its own (Doppler tracking on, through its own CAT), or Gpredict or an SDR program keeps the rig on frequency, azeltrack’s must stay off. For azeltrack to do it, set [radio] doppler to "satellite" or "eme" under Settings and switch the other program’s Doppler off.';
  } else if (heard != null && heard <= HEARD_S) {
    title = `WSJT-X is heard and azeltrack’s Doppler is on (${r.doppler}).`;
    words = 'Only one program may do Doppler. If WSJT-X does its own (Doppler tracking in its Astronomical Data window, through its own CAT), azeltrack’s must be off: set [radio] doppler = "off" under Settings. Otherwise switch WSJT-X’s Doppler tracking off and leave its split at “None”.';
  }
  box.hidden = !title;
  box.classList.toggle('warn-owner', r.doppler !== 'off' && !!title);
  setText('radio-owner-title', title);
  setText('radio-owner-text', words);
}
