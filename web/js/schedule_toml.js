// The settings file's text with its [[schedule]] tables replaced by a new list, for the saves the
// section route cannot make (PUT /api/config/schedule/N changes or adds an item, but removes or
// moves none): the whole file goes back through PUT /api/config/file, which checks it whole before
// one save. Everything else in the file, comments included, is kept as written.

// A table header line: [name] or [[name]], with an optional comment after it.
const HEADER = /^\s*(\[\[?)\s*([A-Za-z0-9_."' -]+?)\s*(\]\]?)\s*(#.*)?$/;

// The header's table name without quotes around its parts ("schedule", "satellites.transmitter").
function tableName(raw) {
  return raw.split('.').map((p) => p.trim().replace(/^"(.*)"$|^'(.*)'$/, '$1$2')).join('.');
}

// Whether a line opens or closes a multi-line string ("""…""" or '''…'''), in which a line that
// looks like a header is text.
function togglesMultiline(line, open) {
  let state = open;
  const re = /"""|'''/g;
  let m;
  while ((m = re.exec(line))) {
    if (!state) state = m[0];
    else if (state === m[0]) state = null;
  }
  return state;
}

// A TOML basic string: JSON's escapes are TOML's, except DEL, which TOML wants escaped too.
export const tomlString = (s) => JSON.stringify(String(s)).replace(/\x7f/g, '\\u007F');
// A number as TOML reads a float (the schema's number keys): 10 -> 10.0.
const tomlNumber = (v) => (Number.isInteger(v) ? v.toFixed(1) : String(v));

/// One [[schedule]] table's text: `sat`, and `min_el_deg` and `preempt` where set.
export function scheduleTable(row) {
  const lines = ['[[schedule]]', `sat = ${tomlString(row.sat)}`];
  if (row.min_el_deg != null) lines.push(`min_el_deg = ${tomlNumber(row.min_el_deg)}`);
  if (row.preempt) lines.push(`preempt = ${tomlString(row.preempt)}`);
  return lines.join('\n');
}

/// `text` without its [[name]] tables (and their sub-tables), with `tables` (their text) at the end.
export function replaceTables(text, name, tables) {
  const out = [];
  let skipping = false;
  let multiline = null;
  let comments = []; // at the end of a table left out: they introduce the next table, kept
  for (const line of String(text).split('\n')) {
    const m = multiline ? null : line.match(HEADER);
    if (m && (m[1].length === m[3].length)) {
      const t = tableName(m[2]);
      const was = skipping;
      skipping = t === name || t.startsWith(`${name}.`);
      if (was && !skipping) {
        while (comments.length && !comments[0].trim() && (!out.length || !out[out.length - 1].trim())) comments.shift();
        out.push(...comments);
      }
      comments = [];
    }
    const quiet = !multiline && /^\s*(#.*)?$/.test(line);
    multiline = togglesMultiline(line, multiline);
    if (!skipping) out.push(line);
    else if (quiet) comments.push(line);
    else comments = [];
  }
  while (out.length && out[out.length - 1].trim() === '') out.pop();
  const body = out.join('\n');
  return `${body}${tables.length ? `\n\n${tables.join('\n\n')}` : ''}\n`;
}
