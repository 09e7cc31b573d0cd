// The console's one state object: what the controller last said, and what the page is doing.

export const S = {
  state: null, config: null, targets: null, sky: null, screen: 'main',
  schema: null, // GET /api/config/schema, on the Settings page
  loggedIn: false, csrf: null, passwordSet: true,
  token: null, // the kiosk's bearer token (panel only): acts without a password or CSRF token
  loginDismissed: localStorage.getItem('azt.loginbar') === 'hidden',
  sel: null, // what TRACK starts: {body, label, serverName}
  ws: null, connected: false, links: 0, backoff: 250, attempts: 0, lastMsg: 0, openedAt: 0, retryTimer: 0,
  trend: [], trendDrawn: 0, skyDrawn: 0, skyListDrawn: 0, faultsKey: '', eventsKey: '', commandsKey: '', ioKey: '', dopKey: '',
};

// The park slot at this position, if one is (the target line says "Park 2 · Stow").
export function parkSlotAt(az, el) {
  const park = (S.config && S.config.park) || (S.targets && S.targets.park) || [];
  return park.find((p) => Number.isFinite(az) && Math.abs(p.az_deg - az) < 0.01 && Math.abs(p.el_deg - el) < 0.01);
}

// What the controller is pointing at, in words: the target, the park slot, or who moves it.
export function targetLabel(st) {
  const t = st.target || {};
  switch (st.mode) {
    // A satellite by its catalogue name, not the request's "sat:" form.
    case 'TRACK': return (t.satellite && t.satellite.sat) || t.name || '—';
    case 'PARK': { const p = parkSlotAt(t.az_deg, t.el_deg); return p ? `Park ${p.slot} · ${p.name}` : 'Park'; }
    case 'MAN': return 'Manual position';
    case 'EXT': return 'PC program';
    default: return t.name || (S.sel ? S.sel.label : '—');
  }
}
