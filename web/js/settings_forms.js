// One table of the configuration file as a form built from its schema (GET /api/config/schema,
// docs/web-api.md): the input each key's type calls for, with its unit, help, default and range,
// a "restart" badge on the keys applied at the next start; a secret's value is never shown and
// a read-only key cannot be edited. changes() reads back only the keys the operator changed, as
// the JSON values PUT /api/config/SECTION takes (null: removed from the file, its default applies).

import { h } from './dom.js';
import { parseNum } from './format.js';

// The help is Markdown: `code`, and links to pages of docs/, which the controller does not
// serve: their words are kept, the page named in a tooltip.
export function helpNodes(md) {
  const out = [];
  const re = /`([^`]+)`|\[([^\]]+)\]\(([^)]+)\)/g;
  let last = 0;
  let m;
  while ((m = re.exec(md || ''))) {
    if (m.index > last) out.push(md.slice(last, m.index));
    if (m[1] != null) out.push(h('code', { text: m[1] }));
    else out.push(h('span', { class: 'docref', title: `docs/${m[3]}`, text: m[2] }));
    last = re.lastIndex;
  }
  if (md && last < md.length) out.push(md.slice(last));
  return out;
}

const slug = (s) => String(s).replace(/[^a-z0-9_]+/gi, '-');
const isList = (t) => t === 'text_list' || t === 'number_list' || t === 'integer_list';
const long = (k) => k.type === 'text_list' || (isList(k.type) && (!k.items || k.items.max == null || k.items.max > 8));

// A value as the operator types it in the key's input ('' when absent).
function asText(k, v) {
  if (v == null) return '';
  if (Array.isArray(v)) return v.join(k.type === 'text_list' ? '\n' : ', ');
  return String(v);
}
// A value in words, for the default.
function words(k, v) {
  if (typeof v === 'boolean') return v ? 'on' : 'off';
  if (Array.isArray(v)) return v.length ? v.join(', ') : 'none';
  if (v === '') return '""';
  const unit = k.unit && typeof v === 'number' ? k.unit : '';
  return `${v}${unit && unit !== '°' ? ' ' : ''}${unit}`;
}
function defaultText(k) {
  if (k.default != null) return `Default ${words(k, k.default)}${k.default_note ? ` (${k.default_note})` : ''}.`;
  return k.default_note ? `Default: ${k.default_note}.` : 'No default.';
}
const rangeText = (k) => (k.range && k.range.text ? ` ${k.range.text[0].toUpperCase()}${k.range.text.slice(1)}.` : '');
function itemsText(k) {
  if (!k.items) return '';
  const { min, max } = k.items;
  const n = min === max ? `${min}` : max == null ? (min ? `at least ${min}` : '') : `${min} to ${max}`;
  const how = k.type === 'text_list' ? 'one a line' : 'separated by commas';
  return ` ${n ? `${n} values, ` : ''}${how}.`.replace(/^ ([a-z])/, (x, c) => ` ${c.toUpperCase()}`);
}

// The control for key `k` holding `value` (null: absent from the file).
function control(k, id, value, describedBy) {
  const attrs = { id, name: k.key, 'data-field': k.key, 'aria-describedby': describedBy, disabled: k.access === 'read_only' };
  if (k.type === 'boolean') {
    const on = value != null ? value : k.default;
    const c = h('input', { ...attrs, type: 'checkbox', checked: !!on });
    c.dataset.was = on ? '1' : '';
    return c;
  }
  let c;
  if (Array.isArray(k.choices) && k.choices.length) {
    const none = k.default != null ? `default (${words(k, k.default)})` : k.default_note ? `default (${k.default_note})` : '— choose —';
    c = h('select', attrs, h('option', { value: '', text: none }),
      ...k.choices.map((x) => h('option', { value: String(x), text: String(x) })));
    c.value = value == null ? '' : String(value);
  } else if (long(k)) {
    c = h('textarea', { ...attrs, rows: k.type === 'text_list' ? 3 : 4, spellcheck: 'false', autocomplete: 'off' });
    c.value = asText(k, value);
  } else {
    const num = k.type === 'integer' || k.type === 'number';
    const r = k.range || {};
    c = h('input', { ...attrs, type: num ? 'number' : 'text', autocomplete: 'off', spellcheck: 'false',
      inputmode: num ? (k.type === 'integer' ? 'numeric' : 'decimal') : null,
      step: num ? (k.type === 'integer' ? '1' : 'any') : null,
      min: num && r.min != null && !r.min_exclusive ? r.min : null,
      max: num && r.max != null && !r.max_exclusive ? r.max : null,
      placeholder: k.default != null && !isList(k.type) ? String(k.default) : k.default_note || null });
    c.value = asText(k, value);
  }
  c.dataset.was = c.value;
  return c;
}

// A secret is never sent to the page: whether it is set, when the controller says.
function secretText(k) {
  if (k.set === true) return 'set (not shown)';
  if (k.set === false) return 'not set';
  return 'secret: never shown';
}

// One key's row. `route` names the table ("control", "park/2"); `pending`: saved, not yet
// running (restart_needed).
export function keyRow(k, route, value, pending) {
  const id = `cfg-${slug(route)}-${k.key}`;
  const help = h('p', { class: 'hint skey-help', id: `${id}-help` }, ...helpNodes(k.help),
    k.help && !/[.:]$/.test(k.help) ? '. ' : ' ', defaultText(k), rangeText(k), itemsText(k));
  const tags = h('span', { class: 'skey-tags' },
    k.applies === 'restart' ? h('span', { class: 'tag t-restart', title: 'Applied when the controller next starts', text: 'restart' }) : null,
    k.access === 'read_only' ? h('span', { class: 'tag', text: 'read-only' }) : null,
    pending ? h('span', { class: 'tag t-pending', title: 'Saved; the controller runs without it until its next start', text: 'saved · waits for restart' }) : null);
  const head = h('div', { class: 'skey-l' }, h('label', { for: id }, h('code', { text: k.key })), tags);
  let input;
  if (k.access === 'secret') {
    input = h('div', { class: 'skey-in' }, h('span', { class: 'secret', id, text: secretText(k) }),
      h('a', { href: '#account', class: 'h-link', text: 'Login and tokens ›' }));
  } else {
    const c = control(k, id, value, `${id}-help`);
    input = h('div', { class: `skey-in${k.type === 'boolean' ? ' check' : ''}` }, c, k.unit ? h('span', { class: 'unit', text: k.unit }) : null);
  }
  return h('div', { class: `skey${pending ? ' pending' : ''}`, 'data-key': k.key }, head, input, help,
    h('p', { class: 'error skey-err', role: 'alert' }));
}

// What the operator typed, as the key's JSON value: {value} or {error}; null when unchanged.
function readKey(k, c) {
  if (k.type === 'boolean') return c.checked === (c.dataset.was === '1') ? null : { value: c.checked };
  if (c.value === c.dataset.was && !(c.validity && c.validity.badInput)) return null;
  if (c.validity && c.validity.badInput) return { error: 'not a number' };
  const raw = c.value.trim();
  if (raw === '') return { value: null };
  if (k.type === 'integer' || k.type === 'number') {
    const n = parseNum(raw);
    if (Number.isNaN(n)) return { error: 'not a number' };
    if (k.type === 'integer' && !Number.isInteger(n)) return { error: 'not a whole number' };
    return { value: n };
  }
  if (k.type === 'gpio_line') return { value: /^\d+$/.test(raw) ? Number(raw) : raw };
  if (k.type === 'text_list') return { value: raw.split('\n').map((x) => x.trim()).filter(Boolean) };
  if (isList(k.type)) {
    const ns = raw.split(/[\s,;]+/).filter(Boolean).map(parseNum);
    if (ns.some(Number.isNaN)) return { error: 'not a list of numbers' };
    if (k.type === 'integer_list' && !ns.every(Number.isInteger)) return { error: 'not a list of whole numbers' };
    return { value: ns };
  }
  return { value: raw };
}

// The changed keys of a form built by keyRow: {body: {key: value}, errors: [[key, words]]}.
export function changes(form, keys) {
  const body = {};
  const errors = [];
  for (const k of keys) {
    if (k.access !== 'editable') continue;
    const c = form.querySelector(`[data-field="${k.key}"]`);
    const r = c ? readKey(k, c) : null;
    if (!r) continue;
    if (r.error) errors.push([k.key, r.error]); else body[k.key] = r.value;
  }
  return { body, errors };
}

// A refusal or a local error beside the key it names; the others cleared.
export function markKey(form, key, message) {
  form.querySelectorAll('.skey').forEach((row) => {
    const mine = row.dataset.key === key;
    row.classList.toggle('bad', mine);
    const c = row.querySelector('[data-field]');
    if (c) c.classList.toggle('bad', mine);
    row.querySelector('.skey-err').textContent = mine ? message : '';
  });
  const row = [...form.querySelectorAll('.skey')].find((r) => r.dataset.key === key);
  const c = row && row.querySelector('[data-field]');
  if (c) c.focus({ preventScroll: false });
  return !!row;
}

// A save's answer in words, for the toast: which keys apply now and which at the next start.
export function savedWords(what, reply, verb = 'Saved') {
  const list = (a) => (Array.isArray(a) ? a : []);
  const applied = list(reply.applied); const restart = list(reply.restart);
  const parts = [];
  if (applied.length) parts.push(`applied now: ${applied.join(', ')}`);
  if (restart.length) parts.push(`at the next start: ${restart.join(', ')}`);
  const waiting = list(reply.restart_needed);
  if (!reply.applied && !reply.restart && waiting.length) parts.push(`waiting for a restart: ${waiting.join(', ')}`);
  return `${verb} ${what}${parts.length ? ` — ${parts.join('; ')}` : ''}.`;
}
