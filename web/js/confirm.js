// A question before an action that cannot be taken back (a restart, a revoke, a motor test): a
// modal dialog with the action's own words on its button. Esc or Cancel answers no; Cancel has
// the focus, so that Enter alone never confirms.

import { $, setText } from './dom.js';

let pending = null;
let wired = false;

// ask({title, text, ok, danger}) -> Promise<boolean>
export function ask({ title, text, ok = 'OK', danger = false }) {
  const d = $('confirm-dialog');
  if (!wired) wire(d);
  if (pending) pending(false);
  setText('confirm-title', title);
  setText('confirm-text', text);
  setText('confirm-ok', ok);
  d.classList.toggle('bad', danger);
  return new Promise((resolve) => {
    pending = (v) => { pending = null; if (d.open) d.close(); resolve(v); };
    d.showModal();
    $('confirm-cancel').focus();
  });
}

function wire(d) {
  wired = true;
  $('confirm-ok').addEventListener('click', () => { if (pending) pending(true); });
  $('confirm-cancel').addEventListener('click', () => { if (pending) pending(false); });
  d.addEventListener('cancel', (ev) => { ev.preventDefault(); if (pending) pending(false); });
  d.addEventListener('close', () => { if (pending) pending(false); });
}
