// What every parksim page shares (parksim/pages/PageDocument.h inlines this first): reading the
// page's data, unpacking its packed columns (pages/ColumnCodec.h), numbers as text, the
// statuses' colours, small DOM helpers, and the signal tests and benchmarks wait for:
// document.body.dataset.ready = "true" once the page is drawn.
'use strict';

const parksim = {};

(function (P) {
  // The data parksim wrote into the page.
  P.data = function () {
    return JSON.parse(document.getElementById('parksim-data').textContent);
  };

  const arrayTypes = {
    f64: Float64Array,
    f32: Float32Array,
    u8: Uint8Array,
    u16: Uint16Array,
    u32: Uint32Array,
  };

  function bytesOf(base64) {
    const text = atob(base64);
    const bytes = new Uint8Array(text.length);
    for (let i = 0; i < text.length; i++) bytes[i] = text.charCodeAt(i);
    return bytes;
  }

  // A packed column as a typed array. Integer columns with an offset come back as a
  // Float64Array with the offset added and NaN where a value is missing; codes and floats as
  // they were stored (little-endian, as every browser's typed arrays on x86 and ARM). The
  // base64 text is the column's "data", or the text of its blob element (PageDocument.h).
  P.column = function (packed) {
    const Type = arrayTypes[packed.type];
    if (!Type) throw new Error('unknown column type ' + packed.type);
    const text = packed.data !== undefined ? packed.data
      : document.getElementById('parksim-blob-' + packed.blob).textContent;
    const bytes = bytesOf(text);
    const stored = new Type(bytes.buffer, 0, bytes.length / Type.BYTES_PER_ELEMENT);
    if (packed.offset === undefined) return stored;
    const values = new Float64Array(stored.length);
    for (let i = 0; i < stored.length; i++) {
      values[i] = stored[i] === packed.missing ? NaN : stored[i] + packed.offset;
    }
    return values;
  };

  // A number as short text: integers whole, others with `digits` significant digits; empty
  // for a missing value.
  P.fmt = function (x, digits) {
    if (x === null || x === undefined || (typeof x === 'number' && isNaN(x))) return '';
    if (typeof x !== 'number') return String(x);
    if (Number.isInteger(x)) return String(x);
    const d = digits || 4;
    const a = Math.abs(x);
    if (a !== 0 && (a < 1e-4 || a >= 1e7)) return x.toExponential(d - 1);
    return String(Number(x.toPrecision(d)));
  };

  // One length unit on every page, mm: a number under a key that names metres (its unit
  // suffix "_m", at the end or before a name: max_pos_err_m, parked_displacement_m.robot_5,
  // set.robot.width_m) is shown times 1000 under the key with "_mm" (P.mmKey).
  const metres = /_m(?=$|\.)/;
  P.isMetresKey = (key) => metres.test(key);
  P.mmKey = (key) => key.replace(metres, '_mm');

  // Metres as millimetres with three decimals ("0.063 mm"), as the command line prints them.
  P.mm = function (m) {
    if (m === null || m === undefined || isNaN(m)) return '-';
    return (1e3 * m).toFixed(3) + ' mm';
  };

  // One colour per status (pipeline/Verdict.h's EpisodeStatus); a status a later parksim adds
  // gets the failure colour until it is named here.
  const statusColors = {
    met: '#1a7f37',
    plan_failed: '#6e4aa8',
    plan_invalid: '#8a5cc7',
    planner_error: '#b0186a',
    controller_error: '#c2185b',
    contact: '#cf222e',
    goal_missed: '#d4610b',
    tolerance_missed: '#b08800',
  };
  P.statusColor = function (status) {
    return statusColors[status] || '#8c1d18';
  };

  // <tag attrs...>children</tag>; attributes starting with "on" are listeners.
  P.el = function (tag, attrs, ...children) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs || {})) {
      if (v === undefined || v === null || v === false) continue;
      if (k.startsWith('on')) e.addEventListener(k.slice(2), v);
      else if (k === 'text') e.textContent = v;
      else e.setAttribute(k, v === true ? '' : v);
    }
    for (const c of children.flat()) {
      if (c === null || c === undefined || c === false) continue;
      e.append(c instanceof Node ? c : document.createTextNode(String(c)));
    }
    return e;
  };

  // A value as a text node: what a table cell, a column title or a list item returns, so that
  // a name from an input file is shown as the text it is, never read as markup (Tabulator
  // takes a string a formatter returns as HTML).
  P.text = function (v) {
    return document.createTextNode(v === null || v === undefined ? '' : String(v));
  };

  // A status as a coloured badge.
  P.badge = function (status) {
    const b = P.el('span', { class: 'badge', text: status });
    b.style.background = P.statusColor(status);
    return b;
  };

  // Runs the page's main(data, root) and then marks the page ready for tests (after the next
  // frame, so what it drew is on screen), with window.parksimReadyMs the milliseconds since
  // the navigation started (what the page benchmark reports). An exception is shown on the page and logged as a
  // console error, which the browser tests fail on.
  P.start = function (main) {
    const root = document.getElementById('page');
    try {
      Promise.resolve(main(P.data(), root))
        .then(() => requestAnimationFrame(() => {
          window.parksimReadyMs = performance.now();
          document.body.dataset.ready = 'true';
        }))
        .catch(fail);
    } catch (e) {
      fail(e);
    }
    function fail(e) {
      root.prepend(P.el('p', { class: 'error', text: 'This page could not be drawn: ' + e }));
      document.body.dataset.failed = String(e);
      console.error(e);
    }
  };
})(parksim);
