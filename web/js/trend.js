// The pointing error trend of the last five minutes on the main screen.

import { S } from './state.js';
import { $, sv } from './dom.js';
import { isNum } from './format.js';

export const TREND_S = 300;

export function niceScale(m) {
  for (const s of [0.05, 0.1, 0.2, 0.5, 1, 2, 5]) if (m <= s) return s;
  return 5;
}
export function drawTrend(force) {
  const nowMs = performance.now();
  if (!force && nowMs - S.trendDrawn < 400) return;
  S.trendDrawn = nowMs;
  const svg = $('trend');
  const W = fitWidth(svg, 190);
  const TR = { L: 48, R: W - 8, T: 10, B: 166 };
  const kids = [];
  const now = nowMs / 1000;
  let m = 0;
  for (const [t, az, el] of S.trend) if (t >= now - TREND_S) m = Math.max(m, Math.abs(az || 0), Math.abs(el || 0));
  const win = S.config && S.config.control && isNum(S.config.control.window_deg) ? S.config.control.window_deg : 0;
  const sc = niceScale(Math.max(m, win * 1.25));
  const mid = (TR.T + TR.B) / 2; const half = (TR.B - TR.T) / 2;
  const y = (v) => mid - (Math.max(-sc, Math.min(sc, v)) / sc) * half;
  const x = (t) => TR.R - ((now - t) / TREND_S) * (TR.R - TR.L);
  if (win > 0) kids.push(sv('rect', { class: 'winband', x: TR.L, width: TR.R - TR.L, y: y(win), height: Math.max(0, y(-win) - y(win)) }));
  for (const v of [sc, sc / 2, 0, -sc / 2, -sc]) {
    kids.push(sv('line', { class: v === 0 ? 'zero' : 'gl', x1: TR.L, x2: TR.R, y1: y(v), y2: y(v) }),
      sv('text', { x: TR.L - 6, y: y(v), 'text-anchor': 'end', 'dominant-baseline': 'middle' }, v === 0 ? '0°' : `${v > 0 ? '+' : '−'}${Math.abs(v)}°`));
  }
  const step = W < 420 ? 2 : 1;
  for (let k = 0; k <= 5; k += 1) {
    const xx = TR.L + ((TR.R - TR.L) * k) / 5;
    kids.push(sv('line', { class: 'gl', x1: xx, x2: xx, y1: TR.T, y2: TR.B, 'stroke-dasharray': '2 4' }));
    if (k === 5 || (5 - k) % step === 0) kids.push(sv('text', { x: xx, y: TR.B + 17, 'text-anchor': k === 5 ? 'end' : 'middle' }, k === 5 ? 'now' : `−${5 - k} min`));
  }
  for (const [idx, cls] of [[1, 'laz'], [2, 'lel']]) {
    let d = ''; let prev = null;
    for (const p of S.trend) {
      if (p[0] < now - TREND_S || p[idx] === null) { prev = null; continue; }
      const gap = !prev || p[0] - prev[0] > 2;
      d += `${gap ? 'M' : 'L'}${x(p[0]).toFixed(1)} ${y(p[idx]).toFixed(1)}`;
      prev = p;
    }
    kids.push(sv('path', { class: cls, d }));
  }
  svg.replaceChildren(...kids);
}
// Charts are drawn in CSS pixels (viewBox = the element's width), so text keeps its size on a phone.
export function fitWidth(svg, height) {
  const W = Math.max(260, Math.round(svg.clientWidth || (svg.parentElement && svg.parentElement.clientWidth) || 600));
  const vb = `0 0 ${W} ${height}`;
  if (svg.getAttribute('viewBox') !== vb) svg.setAttribute('viewBox', vb);
  return W;
}
