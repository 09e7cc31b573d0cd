// The Time page (docs/web-api.md "time"): chrony's verdict on the clock and its sources, the
// kernel's and the RTC's, and the upstream NTP servers when the console manages them.

import { $, h, setText } from './dom.js';
import { ago, fix, isNum, offset } from './format.js';
import { toast } from './toast.js';
import { act } from './actions.js';

const refText = (t) => [t.ref, t.ref_id && t.ref_id !== t.ref ? `(${t.ref_id})` : ''].filter(Boolean).join(' ');

// The main screen's clock line: a word, then the details.
export function timeLine(t) {
  if (!t) return ['unknown', 'not reported by the controller'];
  if (!t.synced) return ['not synchronised', t.chrony_error ? 'chronyd does not answer' : (t.reason || '')];
  return ['synchronised', [refText(t), isNum(t.stratum) ? `stratum ${t.stratum}` : '', isNum(t.offset_s) ? `offset ${offset(t.offset_s)}` : '']
    .filter(Boolean).join(' · ')];
}

const yesNo = (v, yes, no) => (v === true ? yes : v === false ? no : 'unknown');

let sourcesKey = '';
let serversKey = '';
export function renderTime(t, force) {
  const badge = $('time-badge');
  const lvl = !t ? 'off' : t.synced ? 'fix' : 'bad';
  setText(badge, !t ? 'NOT WATCHED' : t.synced ? 'SYNCHRONISED' : 'NOT SYNCHRONISED');
  if (badge.className !== `badge b-${lvl}`) badge.className = `badge b-${lvl}`;
  setText('time-reason', !t ? 'The controller does not report its clock.' : t.synced ? '' : String(t.reason || 'no reason given'));
  t = t || {};
  const ce = $('time-chrony');
  setText(ce, t.chrony_error ? `does not answer: ${t.chrony_error}` : t.chrony_synced === true ? 'synchronised'
    : t.chrony_synced === false ? 'not synchronised' : '—');
  const cc = t.chrony_error ? 'io-bad' : '';
  if (ce.className !== cc) ce.className = cc;
  setText('time-ref', refText(t) || '—');
  setText('time-stratum', isNum(t.stratum) ? String(t.stratum) : '—');
  setText('time-offset', offset(t.offset_s));
  setText('time-rms', isNum(t.last_offset_s) || isNum(t.rms_offset_s) ? `${offset(t.last_offset_s)} / ${offset(t.rms_offset_s, false)}` : '—');
  setText('time-freq', isNum(t.frequency_ppm) ? `${t.frequency_ppm >= 0 ? '+' : '−'}${fix(Math.abs(t.frequency_ppm), 3)} ppm` : '—');
  setText('time-root', isNum(t.root_delay_s) || isNum(t.root_dispersion_s) ? `${offset(t.root_delay_s, false)} / ${offset(t.root_dispersion_s, false)}` : '—');
  setText('time-interval', isNum(t.update_interval_s) ? `${fix(t.update_interval_s, 1)} s` : '—');
  setText('time-leap', t.leap ? String(t.leap) : '—');
  setText('time-kernel', yesNo(t.kernel_synced, 'synchronised', 'not synchronised'));
  setText('time-rtc', yesNo(t.rtc, 'present (/dev/rtc0)', 'none'));
  setText('time-checked', isNum(t.checked_s_ago) ? `${ago(t.checked_s_ago)} ago` : '—');
  const sources = Array.isArray(t.sources) ? t.sources : [];
  const sk = JSON.stringify(sources);
  if (force || sk !== sourcesKey) {
    sourcesKey = sk;
    $('time-source-list').replaceChildren(...(sources.length ? sources.map(sourceRow)
      : [h('tr', {}, h('td', { colspan: 7, class: 'dimtxt', text: t.chrony_error ? 'None: chronyd does not answer.' : 'None.' }))]));
  }
  renderServers(t, force);
}

const STATE_WORDS = { selected: 'selected', combined: 'combined', not_combined: 'not combined', unusable: 'unusable',
  falseticker: 'falseticker', too_variable: 'too variable', unknown: 'unknown' };
function sourceRow(s) {
  const good = s.state === 'selected' || s.state === 'combined';
  const bad = s.state === 'unusable' || s.state === 'falseticker';
  return h('tr', { class: s.state === 'selected' ? 'sel' : null, 'data-source': s.name },
    h('td', { text: String(s.name) }), h('td', { text: String(s.mode || '—') }),
    h('td', { class: good ? 'ok-txt' : bad ? 'io-bad' : null, text: STATE_WORDS[s.state] || String(s.state || '—') }),
    h('td', { text: isNum(s.stratum) ? String(s.stratum) : '—' }),
    h('td', { title: isNum(s.reach) ? `the last 8 polls, newest last: ${s.reach.toString(2).padStart(8, '0')}` : null,
      text: isNum(s.reach) ? s.reach.toString(8) : '—' }),
    h('td', { text: isNum(s.last_rx_s) ? `${ago(s.last_rx_s)} ago` : '—' }),
    h('td', { text: isNum(s.offset_s) ? `${offset(s.offset_s)}${isNum(s.error_s) ? ` ± ${offset(s.error_s, false)}` : ''}` : '—' }));
}

function renderServers(t, force) {
  const managed = !!t.managed;
  $('ntp-form').hidden = !managed;
  $('ntp-unmanaged').hidden = managed;
  if (!managed) return;
  setText('ntp-file', t.sources_file ? `Written to ${t.sources_file}; chronyd reloads it at once.` : '');
  const list = Array.isArray(t.servers) ? t.servers : [];
  const key = list.join('\n');
  const ta = $('ntp-servers');
  if ((force || key !== serversKey) && !ta.dataset.dirty && document.activeElement !== ta) ta.value = key;
  serversKey = key;
}

async function saveServers(ev) {
  ev.preventDefault();
  const ta = $('ntp-servers');
  const servers = ta.value.split(/[\n,]+/).map((x) => x.trim()).filter(Boolean);
  const r = await act('save the NTP servers', 'POST', '/api/time/servers', { servers },
    { btn: $('ntp-save'), errEl: $('ntp-error'), form: $('ntp-form') });
  if (r.ok) {
    delete ta.dataset.dirty; ta.classList.remove('bad');
    toast(servers.length ? `NTP servers saved: ${servers.join(', ')}.` : 'NTP servers cleared.');
    if (r.data.time) renderTime(r.data.time, true);
    return;
  }
  if (r.status === 409) setText('ntp-error', `Not saved: the console does not manage chrony's servers ([time] manage_chrony is off). ${r.data.error || ''}`.trim());
  else if (r.status === 503) setText('ntp-error', `Not applied: ${r.data.error || 'the sources file or chronyd failed'}`);
  else if (r.status === 400) setText('ntp-error', `Not saved: ${r.data.error || 'a server name is not valid'}`);
}

export function wireTime() {
  $('ntp-form').addEventListener('submit', saveServers);
  $('ntp-servers').addEventListener('input', () => { $('ntp-servers').dataset.dirty = '1'; });
}
