// The pointing-scan page (docs/calibration.md; console_test.js runs it), the test being the
// receiver: refused without readings, a five-point scan plotted and fitted, its offsets applied
// once, and a running scan stopped from the page.
'use strict';
const { until, api, state, text } = require('./harness');
const { startFeeder, stopFeeder, feeding, BEAM_DEG, TRUE_AZ_DEG, TRUE_EL_DEG } = require('./console_feeds');
const { plotted, scanSource, sd3 } = require('./console_probes');

/// The scenarios in order, on the test's page; `t` is what console_test.js shares with them.
async function runScanScenarios(t) {
  const { page, scenario, login } = t;
  await scenario('the pointing scan: refused without readings, a five-point scan plotted and fitted, its offsets applied', page, async () => {
    await login(page);
    await page.click('#nav-main');
    await page.click('#scan-link-moon');
    await until('the scan page', () => page.isVisible('#screen-scan'), 3000);
    if ((await page.getAttribute('#nav-targets', 'aria-selected')) !== 'true') throw new Error('the Targets tab is not lit on the scan page');
    // The form: Sun, Moon and the daemon's radio sources; the three kinds; Stop and Apply idle.
    const targets = (await api('GET', '/api/targets')).json.targets;
    const names = JSON.stringify(targets.filter((t) => ['sun', 'moon', 'source'].includes(t.kind)).map((t) => t.name));
    await until('the sources in the form', async () => JSON.stringify(await page.$$eval('#scan-source option', (o) => o.map((x) => x.value))) === names, 5000);
    if (!names.includes('"Sun"') || !names.includes('"Moon"')) throw new Error(`sources: ${names}`);
    const kinds = await page.$$eval('#scan-kind option', (o) => o.map((x) => x.value));
    if (kinds.join(',') !== 'cross,five-point,raster') throw new Error(`kinds: ${kinds}`);
    for (const id of ['#scan-beam', '#scan-start', '#scan-stop', '#scan-apply']) if (!(await page.isVisible(id))) throw new Error(`${id} is not shown`);
    if (!(await page.isDisabled('#scan-stop')) || !(await page.isDisabled('#scan-apply'))) throw new Error('Stop or Apply is enabled with no scan');
    // No readings yet: said plainly, and a scan is refused naming the receiver; nothing moves.
    await until('the receiver line to say there are no readings', async () => /no readings — a scan needs them/.test(await text(page, '#scan-receiver')), 5000);
    const src = scanSource(targets);
    if (!src) { console.log('     (no source between 20° and 70° now: the scan itself is not tested)'); return; }
    await page.selectOption('#scan-source', src.name);
    await page.selectOption('#scan-kind', 'five-point');
    await page.click('#scan-more summary');
    await page.fill('#scan-ref', '2.5');
    await page.fill('#scan-settle', '0');
    await page.fill('#scan-dwell', '0.4');
    await page.fill('#scan-beam', '40');  // the plan refuses it before the receiver is asked
    await page.click('#scan-start');
    await until('the beamwidth refused', async () => /^Not started: beamwidth_deg /.test(await text(page, '#scan-msg')), 5000);
    if (!(await page.$eval('#scan-beam', (e) => e.classList.contains('bad')))) throw new Error('the beamwidth field is not marked');
    await page.fill('#scan-beam', String(BEAM_DEG));
    const before = await state();
    await page.click('#scan-start');
    await until('the refusal naming the receiver', async () => /^Not started: .*receiver/.test(await text(page, '#scan-msg')), 5000);
    if (!(await page.$eval('#scan-msg', (e) => e.classList.contains('error')))) throw new Error('the refusal is not shown as an error');
    const after = await state();
    if (after.mode !== before.mode || after.scan.state === 'running') throw new Error(`a refused scan changed ${before.mode} to ${after.mode}, scan ${after.scan.state}`);
    // Readings: the receiver line shows the latest and the counts.
    startFeeder();
    await until('a reading on the receiver line', async () => {
      const r = (await state()).receiver;
      return r.state === 'receiving' && new RegExp(`: -?\\d+\\.\\d\\d dB, .*good [1-9]\\d*, malformed ${r.malformed}`).test(await text(page, '#scan-receiver'));
    }, 5000);
    const t0 = Date.now();
    await page.click('#scan-start');
    await until('the scan running', async () => (await state()).scan.state === 'running' && /^Scanning /.test(await text(page, '#scan-state')), 5000);
    if (await page.isDisabled('#scan-stop')) throw new Error('Stop is disabled while scanning');
    // The points plotted as they come, each once (the point on the source in both plots).
    await until('the points read so far plotted', async () => {
      const s = (await state()).scan;
      if (s.state !== 'running' || s.samples.length < 2) return false;
      const p = await plotted(page);
      return p.xel.circles.length + p.el.circles.filter((c) => !c.shared).length === s.samples.length;
    }, 90000, 200);
    await until('the end of the scan', async () => (await state()).scan.state !== 'running', 120000, 500);
    const sc = (await state()).scan;
    console.log(`     (five-point scan of ${src.name} at el ${src.el_deg.toFixed(0)}°: ${sc.state} after ${((Date.now() - t0) / 1000).toFixed(1)} s)`);
    if (sc.state !== 'done') throw new Error(`the scan ended ${sc.state}: ${sc.reason}`);
    const p = await until('every sample plotted once, with the fitted curves', async () => {
      const q = await plotted(page);
      const ids = [...q.xel.circles, ...q.el.circles.filter((c) => !c.shared)].map((c) => c.i).sort((a, b) => a - b);
      return JSON.stringify(ids) === JSON.stringify(sc.samples.map((_, i) => i)) && q.xel.curve.length > 100 && q.el.curve.length > 100 && q;
    }, 3000);
    for (const c of [...p.xel.circles, ...p.el.circles]) {
      if (!c.title.includes(`${sc.samples[c.i].power_db.toFixed(2)} dB`)) throw new Error(`circle ${c.i}: “${c.title}”, the sample ${JSON.stringify(sc.samples[c.i])}`);
    }
    const shared = p.el.circles.filter((c) => c.shared).map((c) => c.i);
    const onSource = sc.samples.map((s, i) => [s, i]).filter(([s]) => Math.hypot(s.xel_deg, s.el_deg) < 0.1).map(([, i]) => i);
    if (JSON.stringify(shared) !== JSON.stringify(onSource)) throw new Error(`the point on the source in the elevation plot: ${shared} (on the source: ${onSource})`);
    // Each curve peaks at the fitted centre and passes through the readings (a five-point fit is exact).
    for (const [axis, q, centre] of [['xel', p.xel, sc.fit.xel_offset_deg], ['el', p.el, sc.fit.el_offset_deg]]) {
      if (!q.centre || Math.abs(q.centre.deg - centre) > 1e-9) throw new Error(`${axis}: the centre line at ${JSON.stringify(q.centre)}, the fit ${centre}`);
      const topY = Math.min(...q.curve.map((c) => c[1]));
      const top = q.curve.filter((c) => c[1] < topY + 0.5).map((c) => c[0]);  // the flat top, to the pixel
      const topX = (Math.min(...top) + Math.max(...top)) / 2;
      if (Math.abs(topX - q.centre.x) > 4) throw new Error(`${axis}: the curve peaks at x ${topX}, the centre is at ${q.centre.x}`);
      for (const c of q.circles) {
        const k = q.curve.findIndex((pt) => pt[0] >= c.x);
        if (k < 1) throw new Error(`${axis}: circle ${c.i} outside the curve`);
        const [a, b] = [q.curve[k - 1], q.curve[k]];
        const y = a[1] + ((b[1] - a[1]) * (c.x - a[0])) / (b[0] - a[0] || 1);
        if (Math.abs(y - c.y) > 4) throw new Error(`${axis}: circle ${c.i} at y ${c.y}, the curve at ${y.toFixed(1)}`);
      }
    }
    // The result: the offsets found, shown; then applied, once. The beam was on the source where
    // the encoders read source + TRUE, and the controller's reading is the encoders' less the
    // operator's corrections (+0.05° of elevation from the tracking scenarios' +0.01° steps).
    const found = sc.found;
    const was = (await state()).corrections;
    if (Math.abs(found.az_offset_deg - (TRUE_AZ_DEG - was.az_user_deg)) > 0.03 ||
        Math.abs(found.el_offset_deg - (TRUE_EL_DEG - was.el_user_deg)) > 0.03) throw new Error(`found ${JSON.stringify(found)} with corrections ${JSON.stringify(was)}`);
    await until('the found offsets on the page', async () => (await text(page, '#scan-found')) === `az ${sd3(found.az_offset_deg)} · el ${sd3(found.el_offset_deg)}`, 3000);
    if (!(await text(page, '#scan-width')).includes(`${sc.fit.width_xel_deg.toFixed(3)}°`)) throw new Error(`width: ${await text(page, '#scan-width')}`);
    if (!(await text(page, '#scan-peak')).startsWith(`${sc.fit.peak_db.toFixed(2)} dB`)) throw new Error(`peak: ${await text(page, '#scan-peak')}`);
    if (await page.isDisabled('#scan-apply')) throw new Error('Apply is disabled with a result to apply');
    await page.click('#scan-apply');
    const want = [was.az_offset_deg - found.az_offset_deg, was.el_offset_deg - found.el_offset_deg];
    await until('the new offsets in the controller', async () => {
      const c = (await state()).corrections;
      return Math.abs(c.az_offset_deg - want[0]) < 1e-9 && Math.abs(c.el_offset_deg - want[1]) < 1e-9;
    }, 5000);
    const saved = (await api('GET', '/api/config')).json.corrections;
    if (Math.abs(saved.az_offset_deg - want[0]) > 1e-9 || Math.abs(saved.el_offset_deg - want[1]) > 1e-9) throw new Error(`saved: ${JSON.stringify(saved)}`);
    await until('the new offsets on the page', async () => (await text(page, '#scan-msg')).startsWith(`Applied and saved: encoder offsets az ${sd3(want[0])}, el ${sd3(want[1])}`), 5000);
    await until('Apply disabled: applied once', () => page.isDisabled('#scan-apply'), 3000);
  });

  await scenario('a running scan stops from the page', page, async () => {
    if (!feeding()) { console.log('     (skipped: no scan above)'); return; }
    await page.click('#nav-targets');
    await page.click('#scan-link-targets');
    await until('the scan page', () => page.isVisible('#screen-scan'), 3000);
    await page.selectOption('#scan-kind', 'cross');
    await page.fill('#scan-points', '5');
    await page.click('#scan-start');
    await until('the scan running', async () => (await state()).scan.state === 'running' && !(await page.isDisabled('#scan-stop')), 5000);
    await page.click('#scan-stop');
    await until('the scan stopped', async () => (await state()).scan.state === 'stopped' && /^Stopped: /.test(await text(page, '#scan-state')), 5000);
    if (!(await text(page, '#scan-msg')).startsWith('Scan stopped')) throw new Error(`message: ${await text(page, '#scan-msg')}`);
    const s = await state();
    if (s.mode !== 'TRACK') throw new Error(`after the stop: ${s.mode}`);
    if (!(await page.isDisabled('#scan-stop')) || (await page.isDisabled('#scan-start'))) throw new Error('Stop still enabled, or Start not');
  });
  await stopFeeder();
}

module.exports = { runScanScenarios };
