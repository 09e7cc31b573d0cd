// The polar sky plots (the Sky screen, the GPS page's satellites): north up, east right, the
// zenith in the middle and the horizon at radius 100, in an SVG whose viewBox is centred on 0.

import { sv } from './dom.js';

/// SVG x, y of an az/el (degrees); below the horizon sits on it.
export function polarXY(az, el) {
  const r = (100 * (90 - Math.min(90, Math.max(0, el)))) / 90; const a = (az * Math.PI) / 180;
  return [r * Math.sin(a), -r * Math.cos(a)];
}

/// The horizon, the 30° and 60° rings, the cross and N E S W.
export function drawPolarGrid(svg) {
  svg.append(sv('circle', { class: 'horizon', r: 100 }));
  for (const el of [30, 60]) {
    const r = (100 * (90 - el)) / 90;
    svg.append(sv('circle', { class: 'gl', r }), sv('text', { class: 'ringl', x: 1.5, y: -r - 1.5 }, `${el}°`));
  }
  svg.append(sv('line', { class: 'gl', x1: -100, x2: 100, y1: 0, y2: 0 }), sv('line', { class: 'gl', y1: -100, y2: 100, x1: 0, x2: 0 }));
  for (const [t, x, y] of [['N', 0, -109], ['E', 110, 0], ['S', 0, 110], ['W', -110, 0]]) {
    svg.append(sv('text', { class: 'card-l', x, y, 'text-anchor': 'middle', 'dominant-baseline': 'middle' }, t));
  }
}
