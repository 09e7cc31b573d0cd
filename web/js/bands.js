// The amateur bands the controller knows (from /api/targets: band, EME frequency, wavelength),
// so the page names them as the core does, with no table of its own.

import { S } from './state.js';

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
