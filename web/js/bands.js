// The amateur bands the controller knows (from /api/targets: band, EME frequency, wavelength),
// so the page names them as the core does, with no table of its own.

import { S } from './state.js';
import { $, h } from './dom.js';

export function bandList() {
  return S.targets && Array.isArray(S.targets.bands) ? S.targets.bands : [];
}
export function wavelength(band) {
  const b = bandList().find((x) => String(x.band) === String(band));
  return b ? b.wavelength : '';
}
export function bandLabel(band) {
  const w = wavelength(band);
  return `${band} MHz${w ? ` (${w})` : ''}`;
}

// The band choice on the Setup page: the controller's bands, and the configured one if it is
// not among them.
export function fillBands() {
  const sel = $('band');
  if (document.activeElement === sel) return;
  const bands = bandList().map((b) => String(b.band));
  const cur = S.config ? String(S.config.band) : (S.state && S.state.moon ? String(S.state.moon.band) : '');
  const all = cur && !bands.includes(cur) ? [...bands, cur] : bands;
  if (sel.dataset.bands !== all.join(',')) {
    sel.dataset.bands = all.join(',');
    sel.replaceChildren(...all.map((b) => h('option', { value: b, text: bandLabel(b) })));
  }
  if (cur) sel.value = cur;
}
