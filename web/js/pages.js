// The pages without a tab whose markup and style come when first opened: web/pages/NAME.html goes
// into the page's empty <section id="screen-NAME"> of index.html, and web/css/NAME.css (or the
// style sheet it shares) is linked, so that the console's first load stays light (docs/web-api.md
// "Measured"). The fragments are the console's own files, never server data: they hold no script
// (the Content-Security-Policy allows none inline) and no style attribute.

import { $, h } from './dom.js';

// Each page's style sheet under css/, if it has one.
const STYLE = {
  gps: 'station', time: 'station', network: 'station', planner: 'planner', scan: 'scan', calibration: 'calibration',
  software: 'software', settings: 'settings', account: 'settings', radio: 'radio', schedule: 'schedule',
};
export const FRAGMENTS = Object.keys(STYLE);

const filled = new Set();
const loading = {};
const styles = {};

async function text(path) {
  const r = await fetch(path, { credentials: 'same-origin', cache: 'no-store' });
  if (!r.ok) throw new Error(`${path}: HTTP ${r.status}`);
  return r.text();
}

// Resolves once the sheet applies, so that a page is never shown unstyled.
function linkStyle(name) {
  styles[name] = styles[name] || new Promise((resolve, reject) => {
    const link = h('link', { rel: 'stylesheet', href: `/css/${name}.css` });
    link.addEventListener('load', resolve);
    link.addEventListener('error', () => { delete styles[name]; link.remove(); reject(new Error(`/css/${name}.css did not load`)); });
    document.head.append(link);
  });
  return styles[name];
}

/// Whether the page's markup is in place.
export const pageReady = (name) => !FRAGMENTS.includes(name) || filled.has(name);

/// Puts the page's markup and style in place once; `first` runs after the markup first arrives
/// (to wire its forms). A failure is thrown, and the next call tries again.
export function loadPage(name, first) {
  if (pageReady(name)) return Promise.resolve();
  loading[name] = loading[name] || (async () => {
    const [markup] = await Promise.all([text(`/pages/${name}.html`), linkStyle(STYLE[name])]);
    const t = document.createElement('template');
    t.innerHTML = markup; // inert: our own file, parsed without running anything
    $(`screen-${name}`).replaceChildren(t.content);
    filled.add(name);
    if (first) first();
  })().finally(() => { delete loading[name]; });
  return loading[name];
}
