// The direction test (docs/hardware.md): one axis driven at low speed for one second
// (POST /api/hardware/direction-test), and which way its reading moved, said plainly: the classic
// wiring mistake is a motor or a sensor the wrong way round. The controller refuses it while
// tracking or while the sequencer keys the transmitter (409). Beside it, the E-stop, the limit
// switches and PTT as they are now (live.js renders every [data-io] element).

import { S } from './state.js';
import { $, h, setText } from './dom.js';
import { fix, isNum } from './format.js';
import { act } from './actions.js';
import { ask } from './confirm.js';
import { refreshIo } from './live.js';

const AXES = {
  az: { name: 'azimuth', way: 'clockwise' },
  el: { name: 'elevation', way: 'up' },
  pol: { name: 'polarisation', way: 'clockwise, seen from behind the antenna' },
};
const COMMANDS = { cw: 'a clockwise command', ccw: 'an anticlockwise command', up: 'an upward command', down: 'a downward command' };

// The controller's answer in words: "The reading went up 0.8° for a clockwise command: …".
export function verdictText(d) {
  const cmd = COMMANDS[d.commanded] || `the command ${d.commanded || '?'}`;
  const moved = isNum(d.moved_deg) ? d.moved_deg : 0;
  const size = `${fix(Math.abs(moved), 2)}°`;
  const span = isNum(d.before_deg) && isNum(d.after_deg) ? ` (${fix(d.before_deg, 2)}° → ${fix(d.after_deg, 2)}°)` : '';
  if (d.verdict === 'ok') return `The reading went ${moved < 0 ? 'down' : 'up'} ${size}${span} for ${cmd}: the wiring is right.`;
  if (d.verdict === 'reversed') {
    return `The reading went ${moved < 0 ? 'DOWN' : 'UP'} ${size}${span} for ${cmd}: the motor or the sensor is reversed. `
      + 'Swap the motor\'s two wires (or the relay outputs), or reverse the sensor, then test again.';
  }
  if (d.verdict === 'no movement') {
    return `The reading did not move${span} for ${cmd}: check the motor's power, its drive and the sensor's wiring.`;
  }
  return `${d.verdict || 'No verdict'}: the reading moved ${fix(moved, 2)}°${span} for ${cmd}.`;
}

async function run(axis, btn) {
  const a = AXES[axis];
  const yes = await ask({
    title: `Test the ${a.name} direction?`,
    text: `The ${a.name} axis will turn at low speed for one second (${a.way}), then stop. Make sure nobody is near the antenna and nothing is in its way.`,
    ok: `Turn the ${a.name} axis`, danger: true,
  });
  if (!yes) return;
  const out = $(`dirtest-${axis}-result`);
  out.className = 'dirtest-result';
  setText(out, `Testing the ${a.name} axis…`);
  const r = await act(`test the ${a.name} direction`, 'POST', '/api/hardware/direction-test', { axis }, { btn, quiet: true });
  if (!r.ok) {
    out.className = 'dirtest-result io-bad';
    if (r.status === 401) setText(out, 'Not tested: log in first.');
    else if (r.status === 404) setText(out, 'This controller has no direction test (it answered 404).');
    else setText(out, `Not tested: ${r.data.error || (r.status ? `HTTP ${r.status}` : 'no answer from the controller')}`);
    return;
  }
  out.className = `dirtest-result ${r.data.verdict === 'ok' ? 'ok-txt' : 'io-bad'}`;
  setText(out, verdictText(r.data));
}

function axisBox(axis) {
  const a = AXES[axis];
  const btn = h('button', { type: 'button', class: 'btn', id: `dirtest-${axis}`, text: `Test the ${a.name} direction…` });
  btn.addEventListener('click', () => run(axis, btn));
  return h('div', { class: 'dirtest-axis' }, btn,
    h('p', { class: 'dirtest-result', id: `dirtest-${axis}-result`, role: 'status', 'aria-live': 'polite' }));
}
// The station's own axes: no elevation on a fixed-elevation array, pol with [mount.pol].
function testedAxes() {
  const st = S.state || {};
  const a = st.antenna || {};
  return ['az', isNum(a.el_fixed_deg) ? null : 'el', st.pol ? 'pol' : null].filter(Boolean);
}
const ioRow = (label, what) => h('div', {}, h('span', { class: 'lbl', text: label }), h('span', { 'data-io': what, text: '—' }));

// The card, a <details> like the sections around it.
export function hardwareCard() {
  const tracking = S.state && S.state.mode === 'TRACK';
  const d = h('details', { class: 'sset dirtest', id: 'sec-direction-test', 'data-section': 'direction-test' },
    h('summary', {}, h('span', { class: 'sset-t', text: 'Direction test and the station\'s inputs' }),
      h('span', { class: 'sset-s' }, 'E-stop ', h('span', { 'data-io': 'estop', text: '—' }), ' · limits ', h('span', { 'data-io': 'limits', text: '—' }))),
    h('p', { class: 'hint', text: 'Runs one axis at low speed for one second and says which way its reading moved: a motor or a sensor wired the wrong way round shows at once. Refused while tracking (STOP first) and while the transmitter is keyed.' }),
    tracking ? h('p', { class: 'hint warn-txt', text: 'The antenna is tracking now: STOP it before a test.' }) : null,
    h('div', { class: 'kv' }, ioRow('E-stop', 'estop'), ioRow('Limit switches', 'limits'), ioRow('PTT', 'ptt')),
    h('div', { class: 'dirtest-axes' }, ...testedAxes().map(axisBox)));
  queueMicrotask(refreshIo); // once it is on the page
  return d;
}
