// The Settings page (#settings, reached from Setup): every table of the configuration file as a
// form built from GET /api/config/schema, grouped by the schema's chapters, one <details> per
// table. Each form saves only the keys changed (PUT /api/config/SECTION, or SECTION/N for an
// item of an array of tables); a refusal is shown beside the key it names and nothing is saved;
// the keys waiting for a restart are listed with the Restart button (settings_restart.js).
// Loaded when the page is first opened (navigation.js), so the console's first load stays light.

import { S } from './state.js';
import { $, h, setText } from './dom.js';
import { toast } from './toast.js';
import { loadJSON } from './api.js';
import { act } from './actions.js';
import { loadConfig } from './setup.js';
import { changes, helpNodes, keyRow, markKey, savedWords } from './settings_forms.js';
import { renderRestart, wireRestart } from './settings_restart.js';
import { wireFile } from './settings_file.js';
import { hardwareCard } from './settings_hardware.js';

const OPEN = 'azt.settings.open'; // the tables left open, for this tab
const opened = new Set(JSON.parse(sessionStorage.getItem(OPEN) || '[]'));
let wired = false;

export async function openSettings() {
  if (!wired) {
    wired = true;
    wireRestart(() => reload());
    wireFile(() => reload());
  }
  // Edits not saved yet stay as they are; otherwise the page shows the file as it is now.
  if (!document.querySelector('#settings-body form[data-dirty]')) await reload();
}

// Reads the schema again and shows it: every table, or only `only` (the one just saved: the
// others keep what the operator is typing there).
async function reload(only) {
  const j = await loadJSON('/api/config/schema');
  if (!j || !Array.isArray(j.sections)) {
    setText('settings-msg', 'The controller did not give its settings (GET /api/config/schema): the page shows them when it answers.');
    return false;
  }
  S.schema = j;
  setText('settings-msg', '');
  const old = only && $(`sec-${slug(only)}`);
  const sec = only && j.sections.find((s) => s.name === only);
  if (old && sec) old.replaceWith(sectionEl(sec)); else render();
  renderRestart(j.restart_needed);
  return true;
}

const slug = (s) => String(s).replace(/[^a-z0-9_]+/gi, '-');
const dotted = (route) => route.replace('/', '.');
const waiting = () => (S.schema && Array.isArray(S.schema.restart_needed) ? S.schema.restart_needed : []);

function chaptersOf(sections) {
  const out = [];
  for (const sec of sections) {
    let c = out.find((x) => x.title === sec.chapter);
    if (!c) out.push((c = { title: sec.chapter || 'Other', sections: [] }));
    c.sections.push(sec);
  }
  return out;
}

function render() {
  const chapters = chaptersOf(S.schema.sections);
  $('settings-jump').replaceChildren(...chapters.map((c, i) => h('button', {
    type: 'button', class: 'chip', text: c.title,
    onclick: () => { $(`chapter-${i}`).scrollIntoView({ block: 'start' }); $(`chapter-${i}-t`).focus({ preventScroll: true }); },
  })));
  $('settings-body').replaceChildren(...chapters.map((c, i) => h('section', { class: 'card chapter', id: `chapter-${i}`, 'aria-labelledby': `chapter-${i}-t` },
    h('h2', { id: `chapter-${i}-t`, tabindex: '-1', text: c.title }),
    c.sections.some((s) => s.name.startsWith('hardware.')) ? remember(hardwareCard(), 'direction-test') : null,
    ...c.sections.map(sectionEl))));
}

// A <details> that stays open or closed as the operator left it.
function remember(d, name) {
  d.open = opened.has(name);
  d.addEventListener('toggle', () => {
    if (d.open) opened.add(name); else opened.delete(name);
    sessionStorage.setItem(OPEN, JSON.stringify([...opened]));
  });
  return d;
}

// "3 set in the file · 1 waits for a restart", for the table's summary line.
function summary(sec) {
  const prefix = `${sec.name}.`;
  const mine = waiting().filter((e) => {
    if (!e.startsWith(prefix)) return false; // "sim.az.x" is not [sim]'s: its key is no [sim] key
    const rest = e.slice(prefix.length);
    const key = sec.array_of_tables ? (rest.match(/^\d+\.(.+)$/) || [])[1] : rest;
    return !!key && sec.keys.some((k) => k.key === key);
  });
  const parts = [];
  if (sec.array_of_tables) {
    const n = Array.isArray(sec.items) ? sec.items.length : 0;
    parts.push(n ? `${n} in the file` : 'none in the file');
  } else {
    const set = sec.keys.filter((k) => k.value != null).length;
    parts.push(set ? `${set} set in the file` : 'all defaults');
  }
  if (mine.length) parts.push(`${mine.length} wait${mine.length === 1 ? 's' : ''} for a restart`);
  return parts.join(' · ');
}

function sectionEl(sec) {
  const name = sec.array_of_tables ? `[[${sec.name}]]` : `[${sec.name}]`;
  const d = h('details', { class: 'sset', id: `sec-${slug(sec.name)}`, 'data-section': sec.name },
    h('summary', {}, h('span', { class: 'sset-t', text: sec.title || name }), h('code', { class: 'sset-n', text: name }),
      h('span', { class: 'sset-s', text: summary(sec) })),
    sec.help ? h('p', { class: 'hint sset-help' }, ...helpNodes(sec.help)) : null,
    ...(sec.array_of_tables ? itemForms(sec) : [tableForm(sec, sec.name, Object.fromEntries(sec.keys.map((k) => [k.key, k.value])))]));
  return remember(d, sec.name);
}

// An array of tables ([[park]], [[serial]]): a form per item, and one to add the next.
function itemForms(sec) {
  const items = Array.isArray(sec.items) ? sec.items : [];
  const forms = items.map((it, i) => tableForm(sec, `${sec.name}/${i + 1}`, it || {},
    `[[${sec.name}]] #${i + 1}${it && it.name ? ` · ${it.name}` : ''}`));
  if (!items.length) forms.push(h('p', { class: 'hint', text: 'None in the file.' }));
  if (!sec.keys.some((k) => k.access === 'editable')) return forms; // made elsewhere ([[token]]: Login and tokens)
  const n = items.length + 1;
  const add = tableForm(sec, `${sec.name}/${n}`, {}, `New [[${sec.name}]] #${n}`);
  add.hidden = true;
  const btn = h('button', { type: 'button', class: 'btn small', id: `add-${slug(sec.name)}`, text: `Add [[${sec.name}]] #${n}` });
  btn.addEventListener('click', () => {
    add.hidden = false; btn.hidden = true;
    const first = add.querySelector('[data-field]');
    if (first) first.focus();
  });
  return [...forms, btn, add];
}

function tableForm(sec, route, values, legend) {
  const rn = waiting();
  const submit = h('button', { type: 'submit', class: 'btn primary', text: 'Save' });
  const undo = h('button', { type: 'button', class: 'btn ghost', text: 'Undo changes' });
  const f = h('form', { class: 'sform', novalidate: true, 'data-route': route, 'aria-label': legend || `[${sec.name}]` },
    legend ? h('h3', { text: legend }) : null,
    ...sec.keys.map((k) => keyRow(k, route, values[k.key] == null ? null : values[k.key], rn.includes(`${dotted(route)}.${k.key}`))),
    sec.keys.some((k) => k.access === 'editable')
      ? h('div', { class: 'row sform-foot' }, submit, undo, h('span', { class: 'hint sform-count', 'aria-live': 'polite' }))
      : h('p', { class: 'hint', text: 'Read-only here.' }),
    h('p', { class: 'error sform-err', role: 'alert' }));
  const count = () => {
    const { body, errors } = changes(f, sec.keys);
    const n = Object.keys(body).length + errors.length;
    if (n) f.dataset.dirty = '1'; else delete f.dataset.dirty;
    setText(f.querySelector('.sform-count'), n ? `${n} changed, not saved` : '');
  };
  f.addEventListener('input', count);
  f.addEventListener('change', count);
  undo.addEventListener('click', () => {
    const fresh = tableForm(sec, route, values, legend);
    fresh.hidden = f.hidden;
    f.replaceWith(fresh);
  });
  f.addEventListener('submit', (ev) => { ev.preventDefault(); save(f, sec, route, submit); });
  return f;
}

async function save(f, sec, route, btn) {
  const { body, errors } = changes(f, sec.keys);
  const err = f.querySelector('.sform-err');
  if (errors.length) {
    markKey(f, errors[0][0], `${errors[0][1]}`);
    setText(err, `Not saved: ${errors.map(([k, e]) => `${k} is ${e}`).join('; ')}.`);
    return;
  }
  if (!Object.keys(body).length) { markKey(f, null, ''); setText(err, ''); toast('Nothing changed.'); return; }
  const what = route.includes('/') ? `[[${route.replace('/', ']] #')}` : `[${route}]`;
  const r = await act(`save ${what}`, 'PUT', `/api/config/${route}`, body, { btn, form: f, quiet: true });
  if (!r.ok) {
    if (r.status === 401) { setText(err, 'Not saved: log in first.'); return; }
    const msg = r.data.error || (r.status ? `HTTP ${r.status}` : 'no answer from the controller');
    const beside = r.data.field ? markKey(f, r.data.field, msg) : false;
    setText(err, `Nothing was saved${beside ? ` (${r.data.field}, above)` : `: ${msg}`}.`);
    return;
  }
  markKey(f, null, '');
  setText(err, '');
  toast(savedWords(what, r.data), 'ok', null, 6000);
  await reload(sec.name);
  loadConfig(true); // the other screens' forms show what was saved
}
