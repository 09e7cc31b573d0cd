// The panel's on-screen keys (docs/panel.md): a kiosk's touch screen has no keyboard of its own,
// so the password and RA/Dec are typed on these. Keys are buttons carrying data-k (the character)
// or data-do (what they do), 44 px or more at 480×320.

import { h } from './dom.js';

// Three layers of ten columns, every printable ASCII character on one of them; the fourth row
// (layer key, space, OK) is shared. ⇧ shifts the letters until pressed again.
const LAYERS = {
  abc: ['qwertyuiop', 'asdfghjkl-', ['⇧', ...'zxcvbnm.', '⌫']],
  num: ['1234567890', '@#$%&*()_+', ['#+=', ...'!?,;:\'"/', '⌫']],
  sym: ['[]{}<>^~`|', '\\=-_+.,:;/', ['123', ...'!?@#$%&*', '⌫']],
};
const DOES = { '⇧': 'shift', '⌫': 'back', '#+=': 'layer:sym', '123': 'layer:num' };

function key(ch) {
  const does = DOES[ch];
  return h('button', { type: 'button', 'data-k': does ? null : ch, 'data-do': does || null,
    'aria-label': does === 'back' ? 'Delete' : does === 'shift' ? 'Shift' : null, text: ch });
}

// Fills `box` with the keyboard; `ok` is the form's submit button (session.js knows it by id).
// type(ch) gets each character, back() each ⌫.
export function buildKeyboard(box, ok, { type, back }) {
  for (const [name, rows] of Object.entries(LAYERS)) {
    box.append(h('div', { class: `layer${name === 'abc' ? ' on' : ''}`, 'data-layer': name },
      ...rows.flatMap((r) => [...r].map(key))));
  }
  const layerKey = h('button', { type: 'button', class: 'w2', 'data-do': 'layer:num', text: '123' });
  box.append(layerKey, h('button', { type: 'button', class: 'w5', 'data-k': ' ', 'aria-label': 'Space', text: 'space' }), ok);
  ok.classList.add('w3');
  const show = (name) => {
    box.dataset.layer = name;
    for (const l of box.querySelectorAll('.layer')) l.classList.toggle('on', l.dataset.layer === name);
    layerKey.dataset.do = name === 'abc' ? 'layer:num' : 'layer:abc';
    layerKey.textContent = name === 'abc' ? '123' : 'abc';
  };
  const shift = (on) => {
    box.querySelector('[data-do="shift"]').classList.toggle('lit', on);
    for (const b of box.querySelectorAll('[data-layer="abc"] [data-k]')) {
      if (/[a-z]/i.test(b.dataset.k)) b.dataset.k = b.textContent = on ? b.dataset.k.toUpperCase() : b.dataset.k.toLowerCase();
    }
  };
  box.addEventListener('click', (ev) => {
    const b = ev.target.closest('button');
    if (!b || b === ok) return;
    const does = b.dataset.do || '';
    if (b.dataset.k !== undefined) type(b.dataset.k);
    else if (does === 'back') back();
    else if (does === 'shift') shift(!b.classList.contains('lit'));
    else if (does.startsWith('layer:')) show(does.slice(6));
  });
  return { reset: () => { show('abc'); shift(false); } };
}

// Four by four number keys for angles: digits, the point, the colon of h:m:s, the sign, ⌫, C
// (clear) and → (the next field). press(k) gets '0'…'9', '.', ':', '-', 'back', 'clear', 'next'.
export function buildNumberPad(box, press) {
  const keys = ['7', '8', '9', '⌫', '4', '5', '6', 'C', '1', '2', '3', ':', '−', '0', '.', '→'];
  const what = { '⌫': 'back', C: 'clear', '→': 'next', '−': '-' };
  const label = { '⌫': 'Delete', C: 'Clear the field', '→': 'Next field', '−': 'Minus' };
  box.replaceChildren(...keys.map((k) => h('button', { type: 'button', 'data-k': what[k] || k, 'aria-label': label[k] || null, text: k })));
  box.addEventListener('click', (ev) => {
    const b = ev.target.closest('button[data-k]');
    if (b) press(b.dataset.k);
  });
}
