// Numbers, angles and frequencies as the console shows them, and numbers as operators type them.

export const isNum = (v) => typeof v === 'number' && Number.isFinite(v);
export function fix(v, n) { let t = v.toFixed(n); if (/^-0(\.0*)?$/.test(t)) t = t.slice(1); return t; }
export const deg = (v, n = 2) => (isNum(v) ? `${fix(v, n)}°` : '—');
export function sdeg(v, n = 2) { if (!isNum(v)) return '—'; const t = fix(v, n); return `${t.startsWith('-') ? t : `+${t}`}°`; }
export function hz(v) { if (!isNum(v)) return '—'; const r = Math.round(v); return `${r < 0 ? '-' : '+'}${Math.abs(r)} Hz`; }
export function parseNum(s) {
  const t = String(s).trim().replace(',', '.');
  if (t === '' || !/^[-+]?(\d+\.?\d*|\.\d+)(e[-+]?\d+)?$/i.test(t)) return NaN;
  return Number(t);
}
export const pad = (n, w = 2) => String(n).padStart(w, '0');
export const upper1 = (s) => (s ? s[0].toUpperCase() + s.slice(1) : s);
export const fmtLatLon = (lat, lon) => `${fix(Math.abs(lat), 4)}° ${lat < 0 ? 'S' : 'N'}, ${fix(Math.abs(lon), 4)}° ${lon < 0 ? 'W' : 'E'}`;
// Names as the operator and the controller write them compare case-blind ("moon", "Moon").
export const sameName = (a, b) => a != null && b != null && String(a).toLowerCase() === String(b).toLowerCase();
