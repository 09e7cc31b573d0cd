// Numbers, angles and frequencies as the console shows them, and numbers as operators type them.

export const isNum = (v) => typeof v === 'number' && Number.isFinite(v);
export function fix(v, n) { let t = v.toFixed(n); if (/^-0(\.0*)?$/.test(t)) t = t.slice(1); return t; }
export const deg = (v, n = 2) => (isNum(v) ? `${fix(v, n)}°` : '—');
export function sdeg(v, n = 2) { if (!isNum(v)) return '—'; const t = fix(v, n); return `${t.startsWith('-') ? t : `+${t}`}°`; }
export function hz(v) { if (!isNum(v)) return '—'; const r = Math.round(v); return `${r < 0 ? '-' : '+'}${Math.abs(r)} Hz`; }
// A frequency as radio amateurs read it: MHz, then the Hz in groups of three ("435.297.450").
export function mhzDots(v) {
  if (!isNum(v)) return '—';
  const r = Math.round(Math.abs(v));
  const khzHz = String(r % 1e6).padStart(6, '0');
  return `${v < 0 ? '-' : ''}${Math.floor(r / 1e6)}.${khzHz.slice(0, 3)}.${khzHz.slice(3)}`;
}
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
// A small signed time as chrony gives it (seconds): µs below a millisecond, ms below a second.
export function offset(v, signed = true) {
  if (!isNum(v)) return '—';
  const a = Math.abs(v); const sg = signed ? (v < 0 ? '−' : '+') : '';
  if (a < 1e-3) return `${sg}${fix(a * 1e6, a < 1e-5 ? 1 : 0)} µs`;
  if (a < 1) return `${sg}${fix(a * 1e3, a < 0.01 ? 2 : 1)} ms`;
  return `${sg}${fix(a, 3)} s`;
}
// A duration in seconds as a person reads it: "12 s", "3 min", "2 h".
export function ago(s) {
  if (!isNum(s)) return '—';
  if (s < 120) return `${Math.round(s)} s`;
  if (s < 7200) return `${Math.round(s / 60)} min`;
  if (s < 172800) return `${Math.round(s / 3600)} h`;
  return `${Math.round(s / 86400)} d`;
}
// "in 1 h 05 min", "in 4 min 12 s": the time to an event (AOS, the schedule's next step).
export function countdown(s) {
  const t = Math.max(0, Math.round(s));
  if (t >= 3600) return `in ${Math.floor(t / 3600)} h ${pad(Math.floor((t % 3600) / 60))} min`;
  return `in ${Math.floor(t / 60)} min ${pad(t % 60)} s`;
}
// target.waiting as one line: "up at 00:47 UTC (06:17 local), in 2 h 13 min", or why it will not be.
// The panel's narrow form (480 px, beside the target's numbers; the clock beside it is UTC):
// "↑12:38 · 5h51m" (rises at, in), or why not in a few words. The console's waitLine has the whole sentence.
export function waitShort(w) {
  if (!w.until) return /within two days/.test(w.reason || '') ? 'not up in 2 days' : 'below the limit';
  const s = Math.max(0, isNum(w.in_s) ? w.in_s : 0);
  const h = Math.floor(s / 3600); const m = Math.floor((s % 3600) / 60);
  return `↑${String(w.until).slice(11, 16)} · ${h ? `${h}h` : ''}${String(m).padStart(h ? 2 : 1, '0')}m`;
}

export function waitLine(w) {
  if (!w.until) return w.reason || 'waiting';
  const s = Math.max(0, isNum(w.in_s) ? w.in_s : 0);
  const h = Math.floor(s / 3600); const m = Math.floor((s % 3600) / 60);
  return `up at ${utcLocal(w.until)}, in ${h ? `${h} h ` : ''}${m} min`;
}

// An instant as "18:19 UTC (20:19 local)": the local time is the browser's, left out where it is
// UTC; `secs` adds the seconds. '—' for what is no time.
export function utcLocal(iso, secs = false) {
  const d = new Date(iso);
  if (iso == null || Number.isNaN(d.getTime())) return '—';
  const hm = (h, m, s) => `${pad(h)}:${pad(m)}${secs ? `:${pad(s)}` : ''}`;
  const utc = `${hm(d.getUTCHours(), d.getUTCMinutes(), d.getUTCSeconds())} UTC`;
  return d.getTimezoneOffset() === 0 ? utc : `${utc} (${hm(d.getHours(), d.getMinutes(), d.getSeconds())} local)`;
}
// The local time alone ("20:19"), or '' where local is UTC: for a table's second line.
export function localHm(iso) {
  const d = new Date(iso);
  if (iso == null || Number.isNaN(d.getTime()) || d.getTimezoneOffset() === 0) return '';
  return `${pad(d.getHours())}:${pad(d.getMinutes())}`;
}
