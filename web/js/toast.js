// Short notices at the bottom of the page; errors stay longer and are announced.

import { $, h } from './dom.js';

export function toast(msg, kind = 'ok', action = null, ms = 0) {
  const t = h('div', { class: `toast${kind === 'err' ? ' err' : ''}`, role: kind === 'err' ? 'alert' : 'status' }, h('span', { text: msg }));
  const close = () => t.remove();
  if (action) t.append(h('button', { type: 'button', class: 'btn small', text: action.label, onclick: () => { close(); action.fn(); } }));
  $('toasts').append(t);
  while ($('toasts').children.length > 4) $('toasts').firstChild.remove();
  setTimeout(close, ms || (kind === 'err' ? 8000 : action ? 8000 : 3000));
}
