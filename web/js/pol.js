// The polarisation axis on the main screen (docs/eme.md, "Polarisation axis"): its angle, target,
// mode, Dpol and the transmitter's key from the state's `pol` (null: no pol axis, the card hidden),
// and the mode and angle set through POST /api/pol.

import { $, setText } from './dom.js';
import { deg, parseNum } from './format.js';
import { toast } from './toast.js';
import { act } from './actions.js';

let shownMode = null; // the mode the selector was last set to from the state

export function renderPol(st) {
  const p = st.pol;
  $('pol-panel').hidden = !p;
  if (!p) return;
  // The selector follows the station's mode when it changes (from here, a script or the file),
  // and is left alone between, while the operator chooses.
  if (p.mode !== shownMode) {
    $('pol-mode-select').value = p.mode;
    shownMode = p.mode;
  }
  const target = p.feed_target_deg === null ? 'holds' : deg(p.feed_target_deg, 1);
  setText('pol-angle', `${deg(p.mount_deg, 1)} / ${target}${p.moving ? ' · moving' : ''}`);
  const angle = p.mode === 'manual' ? deg(p.manual_deg, 1) : p.mode === 'fixed' ? deg(p.fixed_deg, 1) : '';
  setText('pol-mode', `${p.mode}${angle ? ` ${angle}` : ''}${p.faults.length ? ` · ${p.faults[0]}` : ''}`);
  setText('pol-dpol', `${deg(p.dpol_deg, 1)} / ${p.transmitting ? 'TX' : 'RX'}`);
}

export function wirePol() {
  $('pol-form').addEventListener('submit', async (ev) => {
    ev.preventDefault();
    const body = { mode: $('pol-mode-select').value };
    const text = $('pol-angle-input').value.trim();
    if (text !== '' && (body.mode === 'fixed' || body.mode === 'manual')) body.angle_deg = parseNum(text);
    const r = await act('set the polarisation', 'POST', '/api/pol', body,
      { btn: $('pol-set'), errEl: $('pol-error'), form: $('pol-form') });
    if (r.ok) toast(`Polarisation: ${body.mode}${body.angle_deg !== undefined ? ` ${deg(body.angle_deg, 1)}` : ''}`);
  });
}
