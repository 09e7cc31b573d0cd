// The sky plot: the Sun, the Moon, the sources and the tracked pass, with their paths.

import { S } from './state.js';
import { $, h, setText, sv } from './dom.js';
import { deg, isNum, pad, sameName } from './format.js';
import { loadJSON } from './api.js';
import { drawPolarGrid, polarXY } from './polar.js';

let skyEls = null;
function drawSkyStatic() {
  const svg = $('sky-plot');
  drawPolarGrid(svg);
  skyEls = { paths: sv('g'), srcs: sv('g'), bodies: sv('g'), marks: sv('g') };
  svg.append(skyEls.paths, skyEls.srcs, skyEls.bodies, skyEls.marks);
  skyEls.sun = sv('g', { class: 'sunm', id: 'sky-sun' }); skyEls.sun.append(sv('circle', { r: 5.5 }), sv('text', { class: 'bodyl', x: 11, y: 3 }, 'Sun'));
  skyEls.moon = sv('g', { class: 'moonm', id: 'sky-moon' }); skyEls.moon.append(sv('circle', { r: 5 }), sv('text', { class: 'bodyl', x: 11, y: 3 }, 'Moon'));
  skyEls.bodies.append(skyEls.sun, skyEls.moon);
  skyEls.tgt = sv('g', { class: 'tgtm', id: 'sky-target' });
  skyEls.tgt.append(sv('circle', { r: 8 }), sv('title', {}, 'target'));
  skyEls.ant = sv('g', { class: 'antm', id: 'sky-antenna' });
  skyEls.ant.append(sv('circle', { r: 4.5 }), sv('path', { d: 'M-10 0H-5M5 0H10M0 -10V-5M0 5V10' }), sv('title', {}, 'antenna'));
  skyEls.marks.append(skyEls.tgt, skyEls.ant);
}
function place(g, az, el) {
  const ok = isNum(az) && isNum(el) && el >= -0.5;
  g.style.display = ok ? '' : 'none';
  if (ok) { const [x, y] = polarXY(az, el); g.setAttribute('transform', `translate(${x.toFixed(2)} ${y.toFixed(2)})`); }
}
function drawSkyPaths() {
  if (!skyEls) drawSkyStatic();
  const out = [];
  const sky = S.sky || {};
  for (const [list, cls, labels] of [[sky.sun_path, 'spath', false], [sky.moon_path, 'mpath', true]]) {
    if (!Array.isArray(list)) continue;
    let d = ''; let up = false;
    list.forEach((p, i) => {
      if (!isNum(p.el_deg) || p.el_deg < 0) { up = false; return; }
      const [x, y] = polarXY(p.az_deg, p.el_deg);
      d += `${up ? 'L' : 'M'}${x.toFixed(1)} ${y.toFixed(1)}`; up = true;
      if (labels && i % 6 === 0 && i > 0) {
        const dt = new Date(p.utc);
        out.push(sv('circle', { class: 'ptick', cx: x.toFixed(1), cy: y.toFixed(1), r: 1.6 }));
        if (i % 12 === 0 && !Number.isNaN(dt.getTime())) out.push(sv('text', { class: 'plbl', x: (x + 3).toFixed(1), y: (y - 3).toFixed(1) }, `${pad(dt.getUTCHours())}h`));
      }
    });
    out.unshift(sv('path', { class: cls, d, id: labels ? 'sky-moon-path' : 'sky-sun-path' }));
  }
  if (Array.isArray(sky.pass_path) && sky.pass_path.length) out.push(...passPath(sky.pass_path));
  skyEls.paths.replaceChildren(...out);
  const srcs = [];
  for (const o of (Array.isArray(sky.now) ? sky.now : [])) {
    if (o.kind !== 'source' || !isNum(o.el_deg) || o.el_deg < 0) continue;
    const [x, y] = polarXY(o.az_deg, o.el_deg);
    const g = sv('g', { transform: `translate(${x.toFixed(1)} ${y.toFixed(1)})` });
    g.append(sv('circle', { class: 'src', r: 2.2 }), sv('text', { class: 'srcl', x: 3.5, y: 2.5 }, String(o.name)), sv('title', {}, String(o.name)));
    srcs.push(g);
  }
  skyEls.srcs.replaceChildren(...srcs);
}
// The tracked satellite's planned pass (before AOS too): its track, and its AOS and LOS marked
// with their UTC times.
function passPath(list) {
  let d = ''; let up = false;
  const seen = list.filter((p) => isNum(p.el_deg) && p.el_deg >= 0);
  for (const p of list) {
    if (!isNum(p.el_deg) || p.el_deg < 0) { up = false; continue; }
    const [x, y] = polarXY(p.az_deg, p.el_deg);
    d += `${up ? 'L' : 'M'}${x.toFixed(1)} ${y.toFixed(1)}`; up = true;
  }
  const out = [sv('path', { class: 'ppath', d, id: 'sky-pass-path' })];
  if (!seen.length) return out;
  for (const [p, word, id] of [[seen[0], 'AOS', 'sky-pass-aos'], [seen[seen.length - 1], 'LOS', 'sky-pass-los']]) {
    const [x, y] = polarXY(p.az_deg, p.el_deg);
    const g = sv('g', { class: 'pend', id, transform: `translate(${x.toFixed(1)} ${y.toFixed(1)})` });
    g.append(sv('circle', { r: 2.4 }), sv('text', { x: 4, y: word === 'AOS' ? -3 : 8 }, `${word} ${String(p.utc).slice(11, 16)}`));
    out.push(g);
  }
  return out;
}
export function drawSky(force) {
  const nowMs = performance.now();
  if (!skyEls) { drawSkyStatic(); drawSkyPaths(); }
  if (!force && nowMs - S.skyDrawn < 300) return;
  S.skyDrawn = nowMs;
  const st = S.state || {};
  const nowList = (S.sky && S.sky.now) || [];
  const sun = st.sun || nowList.find((o) => o.kind === 'sun') || {};
  const moon = st.moon || nowList.find((o) => o.kind === 'moon') || {};
  place(skyEls.sun, sun.az_deg, sun.el_deg);
  place(skyEls.moon, moon.az_deg, moon.el_deg);
  const t = st.target || {};
  place(skyEls.tgt, t.az_deg, t.el_deg);
  const a = st.antenna || {};
  place(skyEls.ant, a.known !== false ? a.az_deg : null, a.el_deg);
  const key = `${st.mode}|${t.name}`;
  if (force || key !== S.skyListKey || nowMs - S.skyListDrawn > 5000) { S.skyListDrawn = nowMs; S.skyListKey = key; drawSkyList(); }
}
function drawSkyList() {
  const st = S.state || {};
  const rows = [];
  const nowList = (S.sky && S.sky.now) || [];
  for (const o of nowList) {
    let p = o;
    if (o.kind === 'sun' && st.sun) p = { ...o, ...st.sun };
    if (o.kind === 'moon' && st.moon) p = { ...o, az_deg: st.moon.az_deg, el_deg: st.moon.el_deg };
    rows.push(p);
  }
  if (!rows.length) {
    if (st.sun) rows.push({ name: 'Sun', ...st.sun });
    if (st.moon) rows.push({ name: 'Moon', az_deg: st.moon.az_deg, el_deg: st.moon.el_deg });
  }
  rows.sort((x, y) => (y.el_deg ?? -99) - (x.el_deg ?? -99));
  const tn = st.mode === 'TRACK' && st.target ? st.target.name : null;
  $('sky-list').replaceChildren(...rows.map((o) => h('tr', { class: sameName(o.name, tn) ? 'sel' : isNum(o.el_deg) && o.el_deg < 0 ? 'below' : null },
    h('td', { text: String(o.name) }), h('td', { text: deg(o.az_deg, 1) }), h('td', { text: deg(o.el_deg, 1) }))));
}
export async function loadSky() {
  const hours = $('sky-hours').value;
  const j = await loadJSON(`/api/sky?hours=${encodeURIComponent(hours)}`);
  if (!j) { setText('sky-error', 'Could not read /api/sky.'); return; }
  setText('sky-error', '');
  S.sky = j; drawSkyPaths(); drawSky(true);
}
