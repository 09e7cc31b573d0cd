// Sections B and C of the seed's main screen, the same on the console and the panel (the same
// element ids on both pages): the operator's corrections and where the antenna points.

import { setText } from './dom.js';
import { deg, isNum, sdeg } from './format.js';

// Whether the antenna's position is known (no readings: shown as —).
export function renderCorrectionsAndPosition(st) {
  const c = st.corrections || {};
  setText('az-corr', sdeg(c.az_user_deg));
  setText('el-corr', sdeg(c.el_user_deg));
  const a = st.antenna || {};
  const known = a.known !== false && isNum(a.az_deg);
  setText('ant-az', known ? deg(a.az_deg) : '—');
  setText('ant-el', known ? deg(a.el_deg) : '—');
  return known;
}
