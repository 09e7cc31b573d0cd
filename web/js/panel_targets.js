// The panel's target screens (docs/panel.md): SUN and MOON, the radio sources of /api/targets six
// at a time (no screen scrolls), PARKING's four slots and RA/Dec typed on number keys. A choice
// starts TRACK or PARK at once, as on the console's Targets screen, and returns to the main screen.

import { parkSlotAt, S } from './state.js';
import { $, h, setText } from './dom.js';
import { deg, isNum, sameName } from './format.js';
import { toast } from './toast.js';
import { loadJSON } from './api.js';
import { act } from './actions.js';
import { radecHint, radecTarget, track } from './targets.js';
import { perform } from './panel_login.js';
import { buildNumberPad } from './panel_keys.js';

const PAGE = 6; // sources on one page: two columns of three
let page = 0;
let go = () => {};
let field = 'ra'; // the RA/Dec field the number keys type into

export async function loadPanelTargets() {
  const j = await loadJSON('/api/targets');
  if (!j) return;
  S.targets = j;
  renderTargets();
}

const where = (o) => (isNum(o.el_deg) ? `az ${deg(o.az_deg, 1)} el ${deg(o.el_deg, 1)}` : '');

function renderSources() {
  const srcs = ((S.targets && S.targets.targets) || []).filter((x) => x.kind === 'source');
  const pages = Math.max(1, Math.ceil(srcs.length / PAGE));
  page = (page + pages) % pages; // ‹ and › go round
  $('src-pager').hidden = pages < 2;
  setText('src-page', `${page + 1} / ${pages}`);
  const shown = srcs.slice(page * PAGE, (page + 1) * PAGE);
  const box = $('sources');
  const names = shown.map((o) => o.name).join('\n');
  if (box.dataset.names !== names) {
    box.dataset.names = names;
    box.replaceChildren(...shown.map((o) => h('button', { type: 'button', class: 'tgt src', 'data-name': o.name, title: o.name },
      h('span', { class: 'tn', text: o.name }), h('span', { class: 'tp' }))));
    if (!srcs.length) box.append(h('p', { class: 'lbl', text: 'No radio sources configured.' }));
  }
  for (const b of box.querySelectorAll('button[data-name]')) {
    const o = shown.find((x) => x.name === b.dataset.name);
    setText(b.lastChild, where(o));
    b.classList.toggle('down', o.el_deg < 0);
  }
}

function renderTargets() {
  const list = (S.targets && S.targets.targets) || [];
  for (const kind of ['sun', 'moon']) {
    const o = list.find((x) => x.kind === kind);
    if (o) { setText(`tgt-${kind}-pos`, where(o)); $(`tgt-${kind}`).classList.toggle('down', o.el_deg < 0); }
  }
  renderSources();
  const park = (S.targets && S.targets.park) || [];
  for (let n = 1; n <= 4; n++) {
    const p = park.find((x) => x.slot === n);
    const b = $(`park-${n}`);
    setText(b.firstChild, p ? `${n} · ${p.name}` : `Park ${n}`);
    setText(b.lastChild, p ? `az ${deg(p.az_deg)} el ${deg(p.el_deg)}` : 'not set');
  }
  markActive();
}

// The tracked target's button, or the park slot's, lit.
export function markActive() {
  const st = S.state || {};
  const t = st.target || {};
  const tn = st.mode === 'TRACK' ? t.name : null;
  document.querySelectorAll('#screen-targets .tgt[data-name], #screen-targets .tgt[data-tname]')
    .forEach((b) => b.classList.toggle('active', sameName(b.dataset.name || b.dataset.tname, tn)));
  const pk = st.mode === 'PARK' ? parkSlotAt(t.az_deg, t.el_deg) : null;
  for (let n = 1; n <= 4; n++) $(`park-${n}`).classList.toggle('active', !!pk && pk.slot === n);
}

// TRACK a target (asking for the password first if need be), then back to the main screen.
function choose(body, label, btn, opts) {
  return perform(async () => {
    const r = await track(body, label, btn, opts);
    if (r.ok) go('main');
    return r;
  });
}
function park(n) {
  return perform(async () => {
    const r = await act(`park at slot ${n}`, 'POST', '/api/target', { park: n }, { btn: $(`park-${n}`) });
    if (r.ok) { toast(`PARK at slot ${n}.`); go('main'); }
    return r;
  });
}

function setField(name) {
  field = name;
  $('ra').classList.toggle('on', name === 'ra');
  $('dec').classList.toggle('on', name === 'dec');
}
function press(k) {
  const inp = $(field);
  const v = inp.value;
  if (k === 'next') { setField(field === 'ra' ? 'dec' : 'ra'); return; }
  if (k === 'back') inp.value = v.slice(0, -1);
  else if (k === 'clear') inp.value = '';
  else if (k === '-') inp.value = v.startsWith('-') ? v.slice(1) : `-${v}`; // the sign, wherever the finger is
  else if (v.length < 16) inp.value = v + k;
  inp.classList.remove('bad');
  setText('radec-error', '');
  radecHint();
}
function submitRadec(ev) {
  ev.preventDefault();
  const t = radecTarget($('ra').value, $('dec').value);
  $('ra').classList.toggle('bad', Number.isNaN(t.ra));
  $('dec').classList.toggle('bad', Number.isNaN(t.dec));
  if (!t.body) { setText('radec-error', 'Type RA and Dec: degrees, or h:m:s and d:m:s.'); return; }
  choose(t.body, t.label, $('radec-go'), { errEl: $('radec-error'), form: $('radec-form') });
}
// A keyboard plugged into the kiosk types RA/Dec too.
function radecKeys(ev) {
  if (S.screen !== 'radec' || !$('login-form').hidden || ev.ctrlKey || ev.metaKey || ev.altKey) return;
  const k = { Backspace: 'back', Tab: 'next', Delete: 'clear' }[ev.key] || (/^[0-9.:-]$/.test(ev.key) ? ev.key : '');
  if (ev.key === 'Enter') { ev.preventDefault(); $('radec-form').requestSubmit($('radec-go')); } else if (k) { ev.preventDefault(); press(k); }
}

export function wireTargets(goTo) {
  go = goTo;
  $('tgt-sun').addEventListener('click', () => choose({ name: 'sun' }, 'Sun', $('tgt-sun')));
  $('tgt-moon').addEventListener('click', () => choose({ name: 'moon' }, 'Moon', $('tgt-moon')));
  $('sources').addEventListener('click', (ev) => {
    const b = ev.target.closest('button[data-name]');
    if (b) choose({ name: b.dataset.name }, b.dataset.name, b);
  });
  $('src-prev').addEventListener('click', () => { page -= 1; renderSources(); markActive(); });
  $('src-next').addEventListener('click', () => { page += 1; renderSources(); markActive(); });
  $('go-park').addEventListener('click', () => go('park'));
  $('go-radec').addEventListener('click', () => go('radec'));
  for (let n = 1; n <= 4; n++) $(`park-${n}`).addEventListener('click', () => park(n));
  buildNumberPad($('numpad'), press);
  $('ra').addEventListener('click', () => setField('ra'));
  $('dec').addEventListener('click', () => setField('dec'));
  setField('ra');
  $('radec-form').addEventListener('submit', submitRadec);
  document.addEventListener('keydown', radecKeys);
}
