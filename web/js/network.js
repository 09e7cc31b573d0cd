// The Network page (docs/web-api.md "network"): one card per interface the controller has
// (loopback left out), and the header's Ethernet and WiFi icons' verdicts.

import { $, h, setText } from './dom.js';
import { isNum } from './format.js';

const ifaces = (net) => (net && Array.isArray(net.interfaces) ? net.interfaces : []);
const linkUp = (i) => !!i.up && i.carrier !== false;

// WiFi signal as a share of full: the driver's percentage, or from dBm (−100 → 0 %, −50 → 100 %).
export function signalPercent(w) {
  if (!w) return null;
  if (isNum(w.signal_percent)) return Math.max(0, Math.min(100, w.signal_percent));
  if (isNum(w.signal_dbm)) return Math.max(0, Math.min(100, 2 * (w.signal_dbm + 100)));
  return null;
}
const barsOf = (pct) => (pct == null ? 4 : pct >= 75 ? 4 : pct >= 50 ? 3 : pct >= 25 ? 2 : 1);
function signalText(w) {
  const pct = signalPercent(w);
  const parts = [];
  if (w && isNum(w.signal_dbm)) parts.push(`${Math.round(w.signal_dbm)} dBm`.replace('-', '−'));
  if (pct != null) parts.push(`${Math.round(pct)} %`);
  return parts.join(' · ');
}

// The header icon for one kind: unknown (no report), none (no such interface), up or down; for
// WiFi the bars of the best link that is up.
export function linkOf(net, kind) {
  if (!net || !Array.isArray(net.interfaces)) return { state: 'unknown', bars: 0, text: 'not reported by the controller' };
  const list = ifaces(net).filter((i) => i.kind === kind);
  if (!list.length) return { state: 'none', bars: 0, text: `no ${kind === 'wifi' ? 'WiFi' : 'Ethernet'} interface` };
  const up = list.filter(linkUp);
  if (!up.length) return { state: 'down', bars: 0, text: `${list.map((i) => i.name).join(', ')} down` };
  if (kind !== 'wifi') return { state: 'up', bars: 0, text: `${up.map((i) => i.name).join(', ')} up` };
  const best = up.map((i) => ({ i, pct: signalPercent(i.wifi) })).sort((a, b) => (b.pct ?? 101) - (a.pct ?? 101))[0];
  const w = best.i.wifi || {};
  const sig = signalText(w);
  return { state: 'up', bars: barsOf(best.pct), text: `${best.i.name} up${w.ssid ? ` · ${w.ssid}` : ''}${sig ? ` · ${sig}` : ''}` };
}

export function netSummary(net) {
  if (!net || !Array.isArray(net.interfaces)) return 'not reported';
  const list = ifaces(net);
  if (!list.length) return 'no interfaces';
  return list.map((i) => `${i.name} ${linkUp(i) ? 'up' : 'down'}`).join(' · ');
}

const KINDS = { ethernet: 'Ethernet', wifi: 'WiFi', other: 'other' };
function row(label, value, cls) {
  return h('div', {}, h('span', { class: 'lbl', text: label }), value instanceof Node ? value : h('span', { class: cls || null, text: value }));
}
function linkText(i) {
  if (linkUp(i)) return 'up';
  const why = i.carrier === false ? 'no carrier' : i.operstate && i.operstate !== 'down' ? String(i.operstate) : '';
  return why ? `down (${why})` : 'down';
}
function wifiBars(pct) {
  const n = barsOf(pct);
  return h('span', { class: 'wbars', 'aria-hidden': 'true' }, ...[1, 2, 3, 4].map((k) => h('i', { class: k <= n ? 'on' : null })));
}
function card(i, nm) {
  const up = linkUp(i);
  const addrs = Array.isArray(i.addresses) ? i.addresses : [];
  const rows = [
    row('Link', linkText(i), up ? 'ok-txt' : i.kind === 'other' ? 'dimtxt' : 'io-bad'),
    row('Addresses', addrs.length ? h('span', { class: 'addrs' }, ...addrs.map((a) => h('span', { class: 'addr', text: String(a) }))) : 'none'),
    row('MAC', i.mac ? String(i.mac) : '—'),
    row('Speed', isNum(i.speed_mbps) && i.speed_mbps > 0 ? (i.speed_mbps >= 1000 ? `${i.speed_mbps / 1000} Gb/s` : `${i.speed_mbps} Mb/s`) : '—'),
  ];
  if (i.kind === 'wifi') {
    const w = i.wifi || {};
    rows.push(row('SSID', w.ssid ? String(w.ssid) : nm ? 'not connected' : 'SSID not known (NetworkManager not running)', w.ssid ? null : 'dimtxt'));
    const pct = signalPercent(w);
    const sig = signalText(w);
    rows.push(row('Signal', sig ? h('span', {}, wifiBars(pct), ' ', sig) : 'not known'));
  }
  return h('div', { class: `card netcard${up ? ' up' : ''}`, 'data-iface': i.name },
    h('h2', {}, h('span', { class: `linkdot${up ? ' on' : ''}` }), h('span', { class: 'ifname', text: String(i.name) }), ' ',
      h('span', { class: 'h-note', text: KINDS[i.kind] || String(i.kind || '') })),
    h('div', { class: 'kv' }, ...rows));
}

let lastKey = null;
export function renderNetwork(net, force) {
  const key = JSON.stringify(net);
  if (!force && key === lastKey) return;
  lastKey = key;
  if (!net || !Array.isArray(net.interfaces)) {
    setText('net-summary', 'The controller does not report its network interfaces (yet).');
    $('net-list').replaceChildren();
    return;
  }
  const list = ifaces(net);
  setText('net-summary', `${list.length} interface${list.length === 1 ? '' : 's'} (loopback not listed). NetworkManager ${net.networkmanager ? 'is running' : 'is not running: WiFi network names are not known'}.`);
  $('net-list').replaceChildren(...(list.length ? list.map((i) => card(i, !!net.networkmanager))
    : [h('div', { class: 'card' }, h('p', { class: 'hint', text: 'No network interface besides loopback.' }))]));
}
