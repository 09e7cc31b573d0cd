// Building and updating the page: elements, SVG, text (server text only ever goes into
// textContent and attributes, never into markup).

export const $ = (id) => document.getElementById(id);
const SVGNS = 'http://www.w3.org/2000/svg';

export function h(tag, props, ...kids) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(props || {})) {
    if (v == null || v === false) continue;
    if (k === 'class') e.className = v;
    else if (k === 'text') e.textContent = v;
    else if (k.startsWith('on')) e.addEventListener(k.slice(2), v);
    else e.setAttribute(k, v === true ? '' : String(v));
  }
  for (const kid of kids) if (kid != null) e.append(kid instanceof Node ? kid : String(kid));
  return e;
}
export function sv(tag, attrs, text) {
  const e = document.createElementNS(SVGNS, tag);
  for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, String(v));
  if (text != null) e.textContent = text;
  return e;
}
export function setText(el, txt) { if (typeof el === 'string') el = $(el); if (el && el.textContent !== txt) el.textContent = txt; }
