// What the Calibration page's parts share: a part's message line, an answer's refusal in words,
// and a route that is not on this controller (404) said plainly rather than faked.

import { $, setText } from './dom.js';

export function say(id, msg, bad = false) {
  const m = $(id);
  setText(m, msg);
  m.className = bad ? 'error' : 'dimtxt';
}

/// An action's refusal as a sentence's end: "log in first", the controller's reason, the status.
export function why(r) {
  if (r.status === 401) return 'log in first';
  if (r.status === 404) return 'not available on this controller';
  return r.data.error || r.data.refused || (r.status ? `HTTP ${r.status}` : 'no answer from the controller');
}

/// A number typed in a form: '' is none (the controller's default), NaN is a mistake.
export function typed(id) {
  const raw = $(id).value.trim().replace(',', '.');
  if (raw === '') return undefined;
  return /^[-+]?(\d+\.?\d*|\.\d+)(e[-+]?\d+)?$/i.test(raw) ? Number(raw) : NaN;
}

/// Reads the form's numbers into `body` ([input id, body key]); returns the ids that are not numbers.
export function readNumbers(body, fields) {
  const bad = [];
  for (const [id, key] of fields) {
    const v = typed(id);
    if (v === undefined) continue;
    if (Number.isNaN(v)) bad.push(id); else body[key] = v;
  }
  return bad;
}

export function markBad(form, ids) {
  form.querySelectorAll('.bad').forEach((e) => e.classList.remove('bad'));
  ids.forEach((id) => $(id).classList.add('bad'));
}

/// A number to `n` places, or '—' for what is none.
export const num = (v, n) => (typeof v === 'number' && Number.isFinite(v) ? (Math.abs(v) < 0.5 * 10 ** -n ? 0 : v).toFixed(n) : '—');
