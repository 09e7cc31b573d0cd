// Short notices at the bottom of the page; errors stay longer and are announced. A notice never
// stands between the operator and a control: a tap goes through it to what is underneath (the
// style sheet), the first tap anywhere clears those that ask nothing, and STOP's header is above
// them all.

import { $, h } from './dom.js';

let wired = false;
function clearOnTap() {
  wired = true;
  document.addEventListener('pointerdown', (e) => {
    if (e.target instanceof Element && e.target.closest('#toasts')) return; // an Undo in a notice
    for (const t of [...$('toasts').children]) if (!t.querySelector('button')) t.remove();
  }, true);
}

export function toast(msg, kind = 'ok', action = null, ms = 0) {
  if (!wired) clearOnTap();
  const t = h('div', { class: `toast${kind === 'err' ? ' err' : ''}`, role: kind === 'err' ? 'alert' : 'status' }, h('span', { text: msg }));
  const close = () => t.remove();
  if (action) t.append(h('button', { type: 'button', class: 'btn small', text: action.label, onclick: () => { close(); action.fn(); } }));
  $('toasts').append(t);
  while ($('toasts').children.length > 4) $('toasts').firstChild.remove();
  setTimeout(close, ms || (kind === 'err' ? 8000 : action ? 8000 : 3000));
}
