// Each motor axis's own hardware on the main screen (docs/hardware.md; docs/web-api.md
// `antenna.axes`): its brake, the motor's current and temperature, a motor trip the last clear
// left latched, and a pulse-counted axis's homing with the words it holds by, with Home
// (POST /api/hardware/home). The daemon sends only what an axis has and leaves `antenna.axes`
// out when no axis has anything: the card is hidden then.

import { $, h, setText } from './dom.js';
import { fix, isNum } from './format.js';
import { toast } from './toast.js';
import { act } from './actions.js';
import { ask } from './confirm.js';

const NAMES = { az: 'azimuth', el: 'elevation', pol: 'polarisation' };
const ORDER = ['az', 'el', 'pol'];
let shapeKey = ''; // which axes, and which rows each has: the rows are rebuilt only when it changes

const row = (axis, what, label, title) => h('div', { id: `drive-${axis}-${what}-row`, title },
  h('span', { class: 'lbl', text: label }), h('span', { id: `drive-${axis}-${what}`, class: 'num', text: '—' }));

// One axis's rows, for the fields it has; Home with its refusal's span for a pulse-counted one.
function axisBlock(axis, ax) {
  const rows = [];
  if ('brake' in ax) rows.push(row(axis, 'brake', 'Brake', 'The brake as the controller drives it (its line energised: released or being released)'));
  if ('current_a' in ax || 'temperature_c' in ax) rows.push(row(axis, 'motor', 'Motor', 'The motor\'s last current and temperature readings'));
  if ('reset_refused' in ax) rows.push(row(axis, 'trip', 'Trip', 'Why the last Clear faults left a motor trip latched: its cause is still there'));
  if ('homing' in ax) {
    rows.push(row(axis, 'homing', 'Homing', 'A pulse-counted axis: its homing, and the count since the controller started'));
    rows.push(row(axis, 'held', 'Held', 'Why the axis holds rather than tracks'));
  }
  const block = h('div', { class: 'drive', id: `drive-${axis}` },
    h('h3', { text: `${axis.toUpperCase()} · ${NAMES[axis]}` }), h('div', { class: 'kv' }, ...rows));
  if ('homing' in ax) {
    const btn = h('button', { type: 'button', class: 'btn small', id: `drive-${axis}-home`, text: 'Home' });
    const err = h('span', { class: 'error', id: `drive-${axis}-error`, role: 'status', 'aria-live': 'polite' });
    btn.addEventListener('click', () => home(axis, btn, err));
    block.append(h('div', { class: 'pol-form drive-act' }, btn, err));
  }
  return block;
}

async function home(axis, btn, err) {
  const name = NAMES[axis];
  const yes = await ask({
    title: `Home the ${name} axis?`,
    text: `The ${name} axis will drive towards its home switch, without a position until it finds it. Make sure nobody is near the antenna and nothing is in its way. STOP ends it.`,
    ok: `Home the ${name} axis`, danger: true,
  });
  if (!yes) return;
  const r = await act(`home the ${name} axis`, 'POST', '/api/hardware/home', { axis }, { btn, errEl: err });
  if (r.status === 401) setText(err, 'Not homed: log in first.'); // act's words are a form's ("Not saved")
  if (r.ok) toast(`Homing the ${name} axis: follow it on this card`);
}

function fill(axis, ax) {
  if ('brake' in ax) {
    setText(`drive-${axis}-brake`, String(ax.brake));
    $(`drive-${axis}-brake`).classList.toggle('ok-txt', ax.brake_released === true);
  }
  if ('current_a' in ax || 'temperature_c' in ax) {
    const parts = [isNum(ax.current_a) ? `${fix(ax.current_a, 2)} A` : null, isNum(ax.temperature_c) ? `${fix(ax.temperature_c, 1)} °C` : null];
    setText(`drive-${axis}-motor`, parts.filter(Boolean).join(' · ') || '—');
  }
  if ('reset_refused' in ax) setText(`drive-${axis}-trip`, String(ax.reset_refused));
  if ('homing' in ax) {
    const count = Number.isInteger(ax.pulse_count) ? ` · ${ax.pulse_count} counts` : '';
    setText(`drive-${axis}-homing`, `${ax.homing}${count}`);
    $(`drive-${axis}-homing`).classList.toggle('io-bad', /failed|lost/.test(ax.homing));
    $(`drive-${axis}-held-row`).hidden = !ax.held;
    setText(`drive-${axis}-held`, ax.held ? String(ax.held) : '—');
  }
}

export function renderDrives(st) {
  const all = st.antenna && st.antenna.axes && typeof st.antenna.axes === 'object' ? st.antenna.axes : null;
  const axes = all ? ORDER.filter((k) => all[k] && typeof all[k] === 'object') : [];
  $('drives-panel').hidden = !axes.length;
  const key = axes.map((k) => `${k}:${['brake', 'current_a', 'temperature_c', 'reset_refused', 'homing'].filter((f) => f in all[k]).join(',')}`).join('|');
  if (key !== shapeKey) {
    shapeKey = key;
    $('drives-list').replaceChildren(...axes.map((k) => axisBlock(k, all[k])));
  }
  for (const k of axes) fill(k, all[k]);
}
