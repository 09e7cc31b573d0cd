// What the console's browser test (console_test.js) reads off a page beyond text: colours as the
// browser computes them, the planner table's scroll cue, notices over controls, the scan's plots.
'use strict';

// An element's colour against a theme variable's, both as the browser computes them.
async function colourIs(page, sel, variable) {
  return page.evaluate(([s, v]) => {
    const probe = document.createElement('span');
    probe.style.color = `var(${v})`;
    document.body.append(probe);
    const want = getComputedStyle(probe).color;
    probe.remove();
    return getComputedStyle(document.querySelector(s)).color === want;
  }, [sel, variable]);
}

// The planner's table at this size: every column shown, and either all of it within the card or
// a scroller whose hint and right-hand fade show while there is more to the right, gone at the
// end. Returns true, or (with `why`) what is wrong.
async function plannerCue(page, why = false) {
  const r = await page.evaluate(async () => {
    const s = document.getElementById('planner-scroll');
    const box = document.getElementById('planner-box');
    const table = document.getElementById('planner-table');
    if (!s || !box) return { ok: false, missing: 'the scroller #planner-scroll in #planner-box' };
    const fade = () => getComputedStyle(box.querySelector('.scroll-edge'), '::after').opacity;
    const hint = () => document.getElementById('planner-more').checkVisibility();
    const hidden = [...table.querySelectorAll('th')].filter((th) => !th.checkVisibility()).map((th) => th.textContent);
    const card = box.closest('.card').getBoundingClientRect();
    const out = { hidden, over: s.scrollWidth - s.clientWidth, right: s.getBoundingClientRect().right, card: card.right };
    if (hidden.length || out.right > card.right + 0.5 || out.right > window.innerWidth) return { ...out, ok: false };
    if (out.over <= 1) return { ...out, ok: !hint() && fade() === '0' };
    const frames = () => new Promise((res) => requestAnimationFrame(() => requestAnimationFrame(res)));
    s.scrollLeft = 0;
    await frames();
    const start = { hint: hint(), fade: fade() };
    s.scrollLeft = s.scrollWidth;
    await frames();
    const end = { fade: fade() };
    s.scrollLeft = 0;
    return { ...out, start, end, ok: start.hint && start.fade === '1' && end.fade === '0' };
  });
  return why ? r : r.ok;
}

// Notices (toast.js) made as the page makes them, one of them an error and one long.
const someToasts = (page) => page.evaluate(async () => {
  const { toast } = await import('/js/toast.js');
  toast('Station locator saved.');
  toast('TRACK Taurus A');
  toast('start the scan: the receiver has no readings (a scan needs them); check [receiver] and the feed', 'err');
});
// Where the notices are now: none covers STOP, and a tap on any visible control under one reaches
// that control. Returns the problems found and how many controls lie under a notice.
const toastProblems = (page) => page.evaluate(() => {
  const out = [];
  const toasts = [...document.querySelectorAll('#toasts > .toast')].map((t) => t.getBoundingClientRect());
  if (!toasts.length) return { out: ['no notice shown'], under: 0 };
  const meets = (a, b) => a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;
  const stop = document.getElementById('btn-stop');
  const rs = stop.getBoundingClientRect();
  if (toasts.some((t) => meets(t, rs))) out.push('a notice covers STOP');
  if (document.elementFromPoint(rs.left + rs.width / 2, rs.top + rs.height / 2) !== stop) out.push('STOP is not what a tap on it reaches');
  let under = 0;
  for (const c of document.querySelectorAll('button, a[href], input, select, textarea, summary')) {
    if (c.closest('#toasts') || !c.checkVisibility({ visibilityProperty: true })) continue;
    const r = c.getBoundingClientRect();
    for (const t of toasts) {
      if (!meets(t, r)) continue;
      const x = (Math.max(t.left, r.left) + Math.min(t.right, r.right)) / 2;
      const y = (Math.max(t.top, r.top) + Math.min(t.bottom, r.bottom)) / 2;
      const hit = document.elementFromPoint(x, y);
      ++under;
      if (!hit || !(hit === c || c.contains(hit))) out.push(`a notice stands over ${c.id || c.textContent.trim().slice(0, 20)} (a tap reaches ${!hit ? 'nothing' : hit.closest('.toast') ? 'the notice' : hit.id || hit.className})`);
    }
  }
  return { out, under };
});

// The pointing-scan page (docs/calibration.md): an offset as the page writes it ("+0.123°").
const sd3 = (v) => { const t = v.toFixed(3); return `${t.startsWith('-') ? t : `+${t}`}°`; };
// The plot as drawn: each circle's sample index, position and title; each curve's points.
const plotted = (page) => page.evaluate(() => {
  const one = (id) => {
    const svg = document.getElementById(id);
    const curve = svg.querySelector('path.fitc');
    const centre = svg.querySelector('line.fitx');
    return {
      circles: [...svg.querySelectorAll('circle.spt')].map((c) => ({ i: Number(c.dataset.i), shared: c.classList.contains('shared'),
        x: Number(c.getAttribute('cx')), y: Number(c.getAttribute('cy')), title: c.textContent })),
      curve: curve ? (curve.getAttribute('d').match(/-?[\d.]+ -?[\d.]+/g) || []).map((p) => p.split(' ').map(Number)) : [],
      centre: centre ? { deg: Number(centre.dataset.deg), x: Number(centre.getAttribute('x1')) } : null,
    };
  };
  return { xel: one('scan-plot-xel'), el: one('scan-plot-el') };
});
// The source to scan: a radio source (else the Sun or the Moon) between 20° and 70° of elevation.
const scanSource = (targets) => targets.filter((t) => ['sun', 'moon', 'source'].includes(t.kind) && t.el_deg >= 20 && t.el_deg <= 70)
  .sort((a, b) => (b.kind === 'source') - (a.kind === 'source') || b.el_deg - a.el_deg)[0];

module.exports = { colourIs, plannerCue, someToasts, toastProblems, sd3, plotted, scanSource };
