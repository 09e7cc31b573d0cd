// What the Settings tests (settings_test.js, settings_account_test.js's scenarios) share: the
// daemon's file read from disk by the program's own TOML reader, the Settings page driven as a
// person does (a section opened by its summary, a field typed into, Save clicked), and the two
// checks every section gets: a change that lands in the file and is applied or waits for a
// restart, and a refusal that names its key and leaves the file as it was.
'use strict';
const { spawnSync } = require('child_process');
const fs = require('fs');
const { until, api, state, loggedIn, text } = require('./harness');

// Filled by settings_test.js: the program, its file, the test's temporary directory, the operator
// password, a bearer token, and every PUT /api/config/SECTION the page sent ({route, body}).
const ctx = { bin: '', config: '', tmp: '', password: '', token: '', puts: [] };

const fileText = () => fs.readFileSync(ctx.config, 'utf8');
// One key as the file on disk has it (`azeltrack config get`); null when absent.
function fromFile(key) {
  const r = spawnSync(ctx.bin, ['config', 'get', key, '--config', ctx.config], { encoding: 'utf8' });
  if (r.status !== 0) return null;
  return JSON.parse(r.stdout.trim());
}
const schema = async () => (await api('GET', '/api/config/schema')).json;
const slug = (s) => String(s).replace(/[^a-z0-9_]+/gi, '-');
const fieldSel = (route, key) => `#cfg-${slug(route)}-${key}`;
const sameJson = (a, b) => JSON.stringify(a) === JSON.stringify(b);
const bearer = (method, route, body) => api(method, route, body, ctx.token);

async function login(page) {
  if (await loggedIn(page)) return;
  await page.evaluate(() => { location.hash = 'setup'; });
  if (!(await page.isVisible('#password'))) await page.click('#login-state');
  await page.fill('#password', ctx.password);
  await page.click('#login-btn');
  await until('the session', () => loggedIn(page));
}

async function openSettings(page) {
  await page.evaluate(() => { location.hash = 'settings'; });
  await until('the settings forms', () => page.isVisible('#sec-control > summary'), 5000);
}
// Opens a section's <details> by its summary, as a person does.
async function openSection(page, name) {
  const sel = `#sec-${slug(name)}`;
  if (!(await page.$eval(sel, (d) => d.open))) await page.click(`${sel} > summary`);
}
async function setField(page, route, key, value) {
  const sel = fieldSel(route, key);
  const kind = await page.$eval(sel, (e) => (e.type === 'checkbox' ? 'checkbox' : e.tagName.toLowerCase()));
  if (kind === 'checkbox') await page.setChecked(sel, value);
  else if (kind === 'select') await page.selectOption(sel, String(value));
  else await page.fill(sel, String(value));
}
// Clicks the form's Save and returns the daemon's answer to its PUT: {status, json}.
async function save(page, route) {
  const answer = page.waitForResponse((r) => r.request().method() === 'PUT'
    && new URL(r.url()).pathname === `/api/config/${route}`, { timeout: 10000 });
  await page.click(`form[data-route="${route}"] button[type=submit]`);
  const r = await answer;
  return { status: r.status(), json: await r.json().catch(() => null) };
}

// The restart banner lists `dotted` (or, with `gone`, none of them).
async function bannerLists(page, dotted) {
  const listed = await page.$$eval('#restart-keys li', (ls) => ls.map((l) => l.textContent));
  return (await page.isVisible('#restart-banner')) && dotted.every((d) => listed.includes(d));
}

// One change through the form (c: {section, route, add, set, expect, live}): only those keys
// sent, in the file on re-read, then applied (c.live checks the state) or waiting for a restart
// (the answer, restart_needed, the banner and the key's row say so); the toast names them.
async function changeAndCheck(page, c) {
  await login(page);
  await openSettings(page);
  await openSection(page, c.section);
  if (c.add) await page.click(`#add-${slug(c.section)}`);
  const before = fileText();
  for (const [key, value] of Object.entries(c.set)) await setField(page, c.route, key, value);
  const sent = ctx.puts.length;
  const r = await save(page, c.route);
  if (r.status !== 200) throw new Error(`PUT /api/config/${c.route} answered ${r.status}: ${JSON.stringify(r.json)}`);
  const body = ctx.puts[sent] && ctx.puts[sent].body;
  if (!body || !sameJson(Object.keys(body).sort(), Object.keys(c.expect).sort())) {
    throw new Error(`the page sent ${JSON.stringify(body)}, not only ${Object.keys(c.expect)}`);
  }
  if (fileText() === before) throw new Error('the file did not change');
  const prefix = c.route.replace('/', '.');
  for (const [key, want] of Object.entries(c.expect)) {
    const got = fromFile(`${prefix}.${key}`);
    if (!sameJson(got, want)) throw new Error(`${prefix}.${key} in the file is ${JSON.stringify(got)}, not ${JSON.stringify(want)}`);
  }
  const dotted = Object.keys(c.expect).map((k) => `${prefix}.${k}`);
  const waiting = (await schema()).restart_needed;
  if (c.live) {
    if (!sameJson([...r.json.applied].sort(), [...dotted].sort())) throw new Error(`applied: ${JSON.stringify(r.json.applied)}`);
    if (dotted.some((d) => waiting.includes(d))) throw new Error(`a live key is listed as waiting for a restart: ${waiting}`);
    await until(`the state to show ${dotted}`, async () => c.live(await state()), 5000);
  } else {
    for (const d of dotted) {
      if (!r.json.restart.includes(d)) throw new Error(`the answer's restart list lacks ${d}: ${JSON.stringify(r.json)}`);
      if (!waiting.includes(d)) throw new Error(`restart_needed lacks ${d}: ${waiting}`);
    }
    await until('the banner to list the keys', () => bannerLists(page, dotted), 5000);
    const row = `form[data-route="${c.route}"] .skey[data-key="${Object.keys(c.expect)[0]}"]`;
    if (!(await page.isVisible(`${row} .t-pending`))) throw new Error(`${row} does not say it waits for a restart`);
  }
  const toast = await text(page, '#toasts');
  if (!dotted.every((d) => toast.includes(d))) throw new Error(`the toast does not name ${dotted}: ${toast}`);
}

// A refusal (c: {section, route, set, field, words, local}): the words beside the key named, the
// field marked and focused, the file byte for byte as it was; `local`: the page refuses it
// itself and sends nothing.
async function refuseAndCheck(page, c) {
  await login(page);
  await openSettings(page);
  await openSection(page, c.section);
  const before = fileText();
  for (const [key, value] of Object.entries(c.set)) await setField(page, c.route, key, value);
  const sent = ctx.puts.length;
  const row = `form[data-route="${c.route}"] .skey[data-key="${c.field}"]`;
  if (c.local) {
    await page.click(`form[data-route="${c.route}"] button[type=submit]`);
    await until('the page\'s refusal', async () => (await text(page, `${row} .skey-err`)) !== '', 3000);
    if (ctx.puts.length !== sent) throw new Error('a value the page could not read was sent');
  } else {
    const r = await save(page, c.route);
    if (r.status !== 400 || !r.json || r.json.field !== c.field) throw new Error(`answered ${r.status} ${JSON.stringify(r.json)}`);
  }
  const said = await text(page, `${row} .skey-err`);
  if (!said.includes(c.words)) throw new Error(`beside ${c.field}: "${said}", not "${c.words}"`);
  if (!(await page.$eval(`${row} [data-field]`, (e) => e.classList.contains('bad')))) throw new Error(`${c.field} is not marked`);
  if (!(await page.$eval(`${row} [data-field]`, (e) => e === document.activeElement))) throw new Error(`${c.field} does not have the focus`);
  if (!/Nothing was saved|Not saved/.test(await text(page, `form[data-route="${c.route}"] .sform-err`))) throw new Error('the form does not say nothing was saved');
  if (fileText() !== before) throw new Error('the file changed');
  await page.click(`form[data-route="${c.route}"] .sform-foot .ghost`); // Undo changes
  if (await page.$(`form[data-route="${c.route}"][data-dirty]`)) throw new Error('Undo left the form changed');
}

// Confirms the page's dialog (confirm.js) and returns its title.
async function confirmDialog(page) {
  await until('the confirmation', () => page.isVisible('#confirm-dialog'), 3000);
  const title = await text(page, '#confirm-title');
  await page.click('#confirm-ok');
  return title;
}

module.exports = {
  ctx, fileText, fromFile, schema, slug, fieldSel, sameJson, bearer, login, openSettings, openSection,
  setField, save, bannerLists, changeAndCheck, refuseAndCheck, confirmDialog,
};
