// The targets screen: sources, spacecraft, satellites and their passes, RA/Dec.

import { parkSlotAt, S } from './state.js';
import { $, h, setText } from './dom.js';
import { deg, fix, isNum, localHm, pad, parseNum, sameName } from './format.js';
import { toast } from './toast.js';
import { loadJSON } from './api.js';
import { act } from './actions.js';
import { fillBands } from './bands.js';

export async function loadTargets() {
  const j = await loadJSON('/api/targets');
  if (!j) { setText('targets-error', S.targets ? '' : 'Could not read the target list.'); return; }
  setText('targets-error', '');
  S.targets = j;
  renderTargets();
  fillBands();
}
const posText = (o) => (isNum(o.el_deg) ? `az ${deg(o.az_deg, 1)} · el ${deg(o.el_deg, 1)}${o.el_deg < 0 ? ' · below' : ''}` : '');
function renderTargets() {
  const list = (S.targets && S.targets.targets) || [];
  for (const kind of ['sun', 'moon']) {
    const o = list.find((x) => x.kind === kind);
    const b = $(`tgt-${kind}`);
    if (o) { b.dataset.tname = o.name; setText(`tgt-${kind}-pos`, posText(o)); b.classList.toggle('down', o.el_deg < 0); }
  }
  const box = $('sources');
  const srcs = list.filter((x) => x.kind === 'source');
  const names = srcs.map((x) => x.name).join('\n');
  if (box.dataset.names !== names) {
    box.dataset.names = names;
    box.replaceChildren(...srcs.map((o) => h('button', { type: 'button', class: 'tgt src', 'data-name': o.name },
      h('span', { class: 'tn', text: o.name }), h('span', { class: 'tp' }))));
    if (!srcs.length) box.append(h('p', { class: 'dimtxt', text: 'No radio sources configured.' }));
  }
  for (const o of srcs) {
    const b = [...box.children].find((x) => x.dataset.name === o.name);
    if (b) { setText(b.lastChild, posText(o)); b.classList.toggle('down', o.el_deg < 0); }
  }
  renderSatellites();
  renderSpacecraft(list.filter((x) => x.kind === 'spacecraft'));
  const park = (S.targets && S.targets.park) || [];
  for (let n = 1; n <= 4; n++) {
    const p = park.find((x) => x.slot === n);
    const b = $(`park-${n}`);
    setText(b.firstChild, p ? `${n} · ${p.name}` : `Park ${n}`);
    setText(b.lastChild, p ? `az ${deg(p.az_deg, 1)} · el ${deg(p.el_deg, 1)}` : 'not set');
  }
  markActiveTarget();
}
function renderSpacecraft(crafts) {
  const box = $('spacecraft');
  const key = JSON.stringify(crafts.map((o) => [o.name, o.description, o.frequency_mhz, o.error || '',
    isNum(o.el_deg) ? Math.round(o.el_deg * 10) : null]));
  if (box.dataset.key === key) return;
  box.dataset.key = key;
  if (!crafts.length) { box.replaceChildren(h('p', { class: 'dimtxt', text: 'None configured.' })); return; }
  box.replaceChildren(...crafts.map((o) => {
    const f = isNum(o.frequency_mhz) && o.frequency_mhz > 0 ? ` · ${o.frequency_mhz} MHz` : '';
    const where = o.error ? 'outside its table' : posText(o);
    return h('button', { type: 'button', class: 'tgt src', 'data-name': o.name, title: o.description || '' },
      h('span', { class: 'tn', text: o.name }),
      h('span', { class: 'tp', text: `${o.description ? `${o.description}${f} · ` : f ? `${f.slice(3)} · ` : ''}${where}` }));
  }));
}
// Every satellite's passes in the next 24 h, merged in time order (the first 15).
function renderPasses(sats) {
  const rows = [];
  for (const o of sats) for (const p of (Array.isArray(o.passes) ? o.passes : [])) rows.push({ name: o.name, ...p });
  rows.sort((a, b) => (a.aos < b.aos ? -1 : a.aos > b.aos ? 1 : 0));
  // UTC, and the browser's local time below it where that is not UTC.
  const when = (iso) => h('td', {}, utcHm(iso), localHm(iso) ? h('small', { class: 'loc', text: `${localHm(iso)} local` }) : null);
  const table = $('sat-passes');
  table.hidden = rows.length === 0;
  table.tBodies[0].replaceChildren(...rows.slice(0, 15).map((r) => h('tr', { class: r.stale ? 'stale' : '' },
    h('td', { text: r.stale ? `${r.name} (stale elements)` : r.name }), when(r.aos), h('td', { text: deg(r.aos_az_deg, 0) }),
    h('td', { text: deg(r.max_el_deg, 0) }), when(r.los), h('td', { text: deg(r.los_az_deg, 0) }))));
}
function utcHm(iso) { const t = new Date(iso); return Number.isNaN(t.getTime()) ? '—' : `${pad(t.getUTCHours())}:${pad(t.getUTCMinutes())}`; }
// The search box's words: a name's part (any case) or a NORAD number (leading zeros or not).
export function matches(o, query) {
  const q = query.trim().toLowerCase();
  if (!q) return true;
  if (/^\d+$/.test(q)) return String(o.norad).replace(/^0+/, '') === q.replace(/^0+/, '') || String(o.name).toLowerCase().includes(q);
  return String(o.name).toLowerCase().includes(q);
}
function renderSatellites() {
  const all = (S.targets && Array.isArray(S.targets.satellites)) ? S.targets.satellites : [];
  const query = $('sat-search') ? $('sat-search').value : '';
  const sats = all.filter((o) => matches(o, query));
  const box = $('satellites');
  const key = JSON.stringify([query, sats.map((o) => [o.norad, o.name, o.next_pass, o.el_deg && Math.round(o.el_deg), o.stale, o.refused])]);
  if (box.dataset.key === key) return;
  box.dataset.key = key;
  renderPasses(sats);
  if (!sats.length) {
    box.replaceChildren(h('p', { class: 'dimtxt', text: all.length ? `No satellite matches “${query}”.` : 'No satellite catalogue ([satellites] sources or file).' }));
    return;
  }
  box.replaceChildren(...sats.map((o) => {
    const np = o.next_pass;
    const t = np ? new Date(np.aos) : null;
    const local = np ? localHm(np.aos) : '';
    let info = np && t && !Number.isNaN(t.getTime())
      ? `AOS ${utcHm(np.aos)} UTC${local ? ` (${local} local)` : ''} · max ${deg(np.max_el_deg, 0)}` : 'no pass in 24 h';
    if (isNum(o.el_deg) && o.el_deg >= 0) info = `up now · el ${deg(o.el_deg, 1)}`;
    // The daemon's verdict ([satellites] stale_days, refuse_days): stale passes are marked, and
    // a refused satellite says why it will not be tracked.
    const stale = !!o.stale || !!o.refused;
    if (o.refused) info = `not tracked: elements ${Math.round(o.element_age_days)} d old`;
    else if (stale) info = `${info} · elements ${Math.round(o.element_age_days)} d old`;
    return h('button', { type: 'button', class: 'tgt sat', 'data-name': `sat:${o.name}`, 'data-norad': o.norad, title: o.refused || '' },
      h('span', { class: 'tn', text: o.name }),
      h('span', { class: `tp${stale ? ' stale' : ''}`, text: info }));
  }));
}
export function wireSatelliteSearch() {
  $('sat-search').addEventListener('input', renderSatellites);
}
export function markActiveTarget() {
  const st = S.state || {};
  const tn = st.mode === 'TRACK' && st.target ? st.target.name : null;
  document.querySelectorAll('#screen-targets .tgt[data-name], #screen-targets .tgt[data-tname]').forEach((b) => b.classList.toggle('active', sameName(b.dataset.name || b.dataset.tname, tn)));
  const pk = st.mode === 'PARK' && st.target ? parkSlotAt(st.target.az_deg, st.target.el_deg) : null;
  for (let n = 1; n <= 4; n++) $(`park-${n}`).classList.toggle('active', !!pk && pk.slot === n);
}
// TRACK a target (body as POST /api/target takes it); opts as act()'s (errEl, form).
export async function track(body, label, btn, opts = {}) {
  const r = await act(`track ${label}`, 'POST', '/api/target', body, { ...opts, btn });
  if (r.ok || r.status === 401) { // chosen: TRACK starts it after logging in
    S.sel = { body, label, serverName: r.data.target || null };
    setText('track-name', label);
  }
  if (r.ok) toast(`TRACK ${label}`);
  return r;
}

// RA as degrees or h:m:s (also "5h34m31.9s"); Dec as degrees or d:m:s.
export function parseAngle(str, hours) {
  const s = String(str).trim().replace(/,/g, '.');
  if (!s) return NaN;
  const sign = s.startsWith('-') || s.startsWith('−') ? -1 : 1;
  const body = s.replace(/^[-+−]/, '').trim();
  if (/[:hms°'"\s]/i.test(body)) {
    const parts = body.split(/[:hms°'"\s]+/i).filter(Boolean).map(parseNum);
    if (!parts.length || parts.length > 3 || parts.some(Number.isNaN)) return NaN;
    const v = parts[0] + (parts[1] || 0) / 60 + (parts[2] || 0) / 3600;
    return sign * v * (hours ? 15 : 1);
  }
  const v = parseNum(body);
  return sign * v;
}
// RA and Dec as typed -> {ra, dec} (NaN where not a number) and, when both are, the target's
// body for POST /api/target and its label.
export function radecTarget(raText, decText) {
  const ra = parseAngle(raText, true); const dec = parseAngle(decText, false);
  if (Number.isNaN(ra) || Number.isNaN(dec)) return { ra, dec, body: null, label: '' };
  return { ra, dec, body: { ra_deg: ra, dec_deg: dec }, label: `RA ${fix(ra, 3)}° Dec ${dec >= 0 ? '+' : ''}${fix(dec, 3)}°` };
}
export function radecHint() {
  const ra = parseAngle($('ra').value, true); const dec = parseAngle($('dec').value, false);
  const parts = [];
  if (isNum(ra)) { const hh = ra / 15; const H = Math.floor(hh); const M = Math.floor((hh - H) * 60); parts.push(`RA ${fix(ra, 4)}° = ${pad(H)}h${pad(M)}m${fix(((hh - H) * 60 - M) * 60, 1).padStart(4, '0')}s`); }
  if (isNum(dec)) parts.push(`Dec ${dec >= 0 ? '+' : ''}${fix(dec, 4)}°`);
  setText('radec-hint', parts.join(' · '));
}
