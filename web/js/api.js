// The JSON API (docs/web-api.md): one request, its answer always an object.

import { S } from './state.js';

// `type`: a body sent as it is (a string) with that Content-Type, instead of as JSON.
export async function request(method, path, body, type) {
  const headers = { Accept: 'application/json' };
  if (body !== undefined) headers['Content-Type'] = type || 'application/json';
  // The kiosk acts with its bearer token (no cookie, so no CSRF token); a person with a session,
  // whose token goes with reads too: some need the login (GET /api/tokens).
  if (S.token) headers.Authorization = `Bearer ${S.token}`;
  else if (S.csrf) headers['X-CSRF-Token'] = S.csrf;
  let r;
  try {
    r = await fetch(path, { method, headers, credentials: 'same-origin', cache: 'no-store',
      body: body === undefined ? undefined : type ? body : JSON.stringify(body) });
  } catch (e) {
    return { ok: false, status: 0, data: { error: 'no answer from the controller' } };
  }
  let data = {};
  try { data = await r.json(); } catch (e) { /* not JSON */ }
  if (!data || typeof data !== 'object') data = {};
  return { ok: r.ok, status: r.status, data, headers: r.headers };
}

export async function loadJSON(path) {
  const r = await request('GET', path);
  return r.ok ? r.data : null;
}
