// A sweep's page (parksim/pages/SweepPage.h): every episode in a Tabulator table (sorted by a
// click on any header, filtered by status chips and by a filter under any header), per axis
// that varies a summary of the episodes the filters leave (summaries.js), and each kept
// episode linked to its own page. The columns are the table's own (pages/TableColumns.h):
// nothing here names a column but to choose which are shown at first.
'use strict';

(function (P) {
  const el = P.el;
  // Shown at first besides the id and the axes that vary; every other column is one click away.
  const firstShown = ['status', 'failure', 'max_pos_err_m', 'goal_pos_err_m',
    'goal_heading_err_deg', 'contacts', 'plan_duration_s', 'sim_time_s', 'plan_time_s'];
  const errorKeys = ['max_pos_err_m', 'goal_pos_err_m'];
  // An axis with more distinct numbers than this is summarised in this many equal bins.
  const maxValues = 24;
  const bins = 10;

  // Lengths in mm, as on every page (P.mmKey): a number column whose key names metres is
  // shown times 1000 and titled with "_mm".
  const isLength = (col) => col.kind === 'number' && P.isMetresKey(col.name);
  const shownName = (col) => (isLength(col) ? P.mmKey(col.name) : col.name);

  // A column's values as a plain array (lengths in mm): numbers, text, booleans, or null where a
  // row has none (which the table sorts last).
  function values(col, n) {
    const k = isLength(col) ? 1e3 : 1;
    const scale = (v) => (typeof v === 'number' ? v * k : v);
    if (col.encoding === 'const') return new Array(n).fill(scale(col.value));
    if (col.encoding === 'levels') {
      const codes = P.column(col);
      const levels = col.levels.map(scale);
      return Array.from(codes, (c) => levels[c]);
    }
    const a = P.column(col);
    return a.length === n ? Array.from(a, (x) => (isNaN(x) ? null : x * k)) : new Array(n).fill(null);
  }

  // A header filter for numbers: "0.002", ">0.001", "<= 5", "!=0", "1..3" (inclusive).
  function numberFilter(expr, value) {
    const text = String(expr).trim();
    if (text === '') return true;
    if (typeof value !== 'number') return false;
    const range = text.match(/^(-?[\d.]+(?:e[-+]?\d+)?)\s*\.\.\s*(-?[\d.]+(?:e[-+]?\d+)?)$/i);
    if (range) return value >= Number(range[1]) && value <= Number(range[2]);
    const m = text.match(/^(<=|>=|!=|<|>|=)?\s*(-?[\d.]+(?:e[-+]?\d+)?)$/i);
    if (!m) return P.fmt(value).includes(text);
    const x = Number(m[2]);
    switch (m[1]) {
      case '<': return value < x;
      case '<=': return value <= x;
      case '>': return value > x;
      case '>=': return value >= x;
      case '!=': return value !== x;
      default: return value === x || Number(value.toPrecision(4)) === Number(x.toPrecision(4));
    }
  }

  function statusRank(statuses) {
    // Failures first, in judging order; met last.
    return (s) => (s === 'met' ? statuses.length + 1 : (statuses.indexOf(s) + 1 || statuses.length));
  }

  // A column of the table. Its width is set from its name's length rather than measured from
  // its cells, which took most of a 120-row page's start-up.
  function columnDef(col, field, state) {
    const name = shownName(col);
    let chars = Math.max(name.length, col.kind === 'number' ? 8 : 12);
    if (col.encoding === 'levels' && col.kind !== 'number') {
      for (const v of col.levels.slice(0, 500)) chars = Math.max(chars, Math.min(40, String(v).length));
    }
    // Every title, cell and list item is a text node (P.text): names from input files are
    // column titles (parked_displacement_m.<robot>) and values (world), shown as text.
    const def = { title: name, field, headerSortTristate: true, width: Math.min(380, 34 + 8.5 * chars),
      titleFormatter: () => P.text(name) };
    if (col.name === 'status') {
      const rank = statusRank(state.statuses);
      def.sorter = (a, b) => rank(a) - rank(b);
      def.formatter = (cell) => P.badge(String(cell.getValue()));
    } else if (col.kind === 'number') {
      def.sorter = 'number';
      def.sorterParams = { alignEmptyValues: 'bottom' };
      def.hozAlign = 'right';
      def.formatter = (cell) => P.text(P.fmt(cell.getValue(), 4));
    } else {
      def.sorter = (a, b) => String(a).localeCompare(String(b), undefined, { numeric: true });
      def.formatter = (cell) => P.text(cell.getValue());
    }
    if (col.name === 'episode_id') {
      def.frozen = true;
      def.formatter = (cell) => {
        const row = cell.getRow().getData();
        const id = String(cell.getValue());
        if (!state.kept[row._i]) return P.text(id);
        return el('a', { href: state.href + '/' + encodeURIComponent(id) + '/report.html', text: id });
      };
    }
    // A list of values for text and booleans with few; numbers, however few their values, get
    // the typed filter (a list of raw floats is no way to ask for ">0.0001").
    const few = col.encoding === 'levels' && col.levels.length <= 64 && col.kind !== 'number';
    if (few && col.name !== 'episode_id') {
      def.headerFilter = 'list';
      const labels = {};
      for (const v of col.levels) labels[String(v)] = v === null ? '(none)' : String(v);
      def.headerFilterParams = { values: labels, clearable: true,
        itemFormatter: (label) => el('span', { text: label }) };
      def.headerFilterFunc = (wanted, value) => wanted === '' || wanted === undefined || String(value) === wanted;
    } else if (col.kind === 'number') {
      def.headerFilter = 'input';
      def.headerFilterPlaceholder = '>0.001, 1..3';
      def.headerFilterFunc = numberFilter;
    } else {
      def.headerFilter = 'input';
      def.headerFilterFunc = 'like';
    }
    return def;
  }

  function statusChips(state, counts, onChange) {
    const chips = state.statuses.map((s) => {
      const chip = el('button', { class: 'chip on', 'data-status': s, title: 'show or hide ' + s });
      chip.append(P.badge(s), ' ', el('span', { class: 'count', text: String(counts.get(s) || 0) }));
      if (!counts.get(s)) chip.classList.add('none');
      chip.addEventListener('click', () => {
        if (state.hidden.has(s)) state.hidden.delete(s);
        else state.hidden.add(s);
        chip.classList.toggle('on', !state.hidden.has(s));
        onChange();
      });
      return chip;
    });
    return el('div', { class: 'chips', id: 'status-filter' }, chips);
  }

  // An axis's groups: its values, or for many distinct numbers equal-width bins.
  function axisGroups(col, rows, field) {
    const distinct = col.encoding === 'levels' ? col.levels : [...new Set(rows.map((r) => r[field]))];
    const numeric = col.kind === 'number';
    if (!numeric || distinct.length <= maxValues) {
      return { key: field, order: distinct, label: (v) => (v === null ? '(none)' : String(v)), numeric };
    }
    const finite = distinct.filter((v) => typeof v === 'number' && isFinite(v));
    const lo = Math.min(...finite);
    const hi = Math.max(...finite);
    const width = (hi - lo) / bins || 1;
    const key = field + '#bin';
    for (const r of rows) {
      const v = r[field];
      r[key] = typeof v === 'number' && isFinite(v) ? Math.min(bins - 1, Math.floor((v - lo) / width)) : null;
    }
    const order = [...Array(bins).keys()];
    return {
      key, order, numeric,
      label: (b) => (b === null ? '(none)' : P.fmt(lo + b * width) + ' .. ' + P.fmt(lo + (b + 1) * width)),
      centre: (b) => lo + (b + 0.5) * width,
    };
  }

  function summaryTable(name, groups, summary, errorFields) {
    const head = el('tr', {}, el('th', { text: name }), el('th', { text: 'episodes' }),
      el('th', { text: 'met' }), el('th', { text: 'met fraction (95 % interval)' }),
      el('th', { text: 'max tracking error median / p95 / max' }), el('th', { text: 'goal error median / p95' }));
    const mm = (x) => (isNaN(x) ? '-' : x.toFixed(3));  // the table's lengths are in mm
    const body = summary.map((s) => {
      const te = s[errorFields[0]] || {};
      const ge = s[errorFields[1]] || {};
      return el('tr', {}, el('td', { text: groups.label(s.value) }), el('td', { text: s.episodes }),
        el('td', { text: s.met }),
        el('td', { text: (100 * s.fraction).toFixed(1) + ' % (' + (100 * s.low).toFixed(1) + ' .. ' + (100 * s.high).toFixed(1) + ' %)' }),
        el('td', { text: te.n ? mm(te.median) + ' / ' + mm(te.p95) + ' / ' + mm(te.max) + ' mm' : '-' }),
        el('td', { text: ge.n ? mm(ge.median) + ' / ' + mm(ge.p95) + ' mm' : '-' }));
    });
    return el('table', { class: 'summary' }, el('thead', {}, head), el('tbody', {}, body));
  }

  function summaryPlot(name, groups, summary, errorField, box) {
    const points = summary.filter((s) => s.value !== null);
    if (!groups.numeric || points.length < 3) return;
    const x = points.map((s) => (groups.centre ? groups.centre(s.value) : Number(s.value)));
    const pct = (f) => points.map((s) => 100 * s[f]);
    const err = points.map((s) => (s[errorField] ? s[errorField].p95 : NaN));
    new uPlot({
      title: 'Met fraction (95 % interval) and p95 of the max tracking error against ' + name,
      width: Math.min(720, Math.max(320, box.clientWidth - 8)),
      height: 200,
      scales: { x: { time: false }, '%': { range: [0, 100] } },
      axes: [{ label: name }, { scale: '%', label: 'met %' }, { scale: 'mm', side: 1, grid: { show: false }, label: 'mm' }],
      series: [{ label: name },
        { label: 'met %', scale: '%', stroke: '#1a7f37', width: 2, points: { show: true } },
        { label: 'interval low', scale: '%', stroke: 'rgba(26,127,55,0.4)' },
        { label: 'interval high', scale: '%', stroke: 'rgba(26,127,55,0.4)' },
        { label: 'max error p95 (mm)', scale: 'mm', stroke: '#cf222e', dash: [5, 3], points: { show: true } }],
      bands: [{ series: [3, 2], fill: 'rgba(26,127,55,0.12)' }],
    }, [x, pct('fraction'), pct('low'), pct('high'), err], box);
  }

  // The distribution of the max tracking error in each group of an axis: counts in 12 bins
  // spaced evenly in log10 over the errors shown (a step line per group, at most 12 groups,
  // the largest); what parksimHistograms[axis] holds for tests and readers of the page.
  function errorHistogram(name, axis, groups, rows, errorField, box) {
    const all = rows.map((r) => r[errorField]);
    const edges = P.logEdges(all, 12);
    window.parksimHistograms[axis] = null;
    if (!edges || edges.length < 3) return;
    const members = new Map();
    for (const r of rows) {
      const v = r[groups.key];
      if (!members.has(v)) members.set(v, []);
      members.get(v).push(r[errorField]);
    }
    const order = groups.order.filter((v) => members.has(v));
    for (const v of members.keys()) if (!order.includes(v)) order.push(v);
    const shown = order.map((v) => ({ value: v, label: groups.label(v), counts: P.histogram(members.get(v), edges) }))
      .sort((a, b) => b.counts.reduce((x, y) => x + y, 0) - a.counts.reduce((x, y) => x + y, 0))
      .slice(0, 12);
    window.parksimHistograms[axis] = { edges, groups: shown };
    const centres = edges.slice(0, -1).map((e, k) => Math.sqrt(e * edges[k + 1]));
    const colors = ['#0969da', '#cf222e', '#1a7f37', '#8250df', '#d4610b', '#0b7285', '#b08800',
      '#a40e26', '#6e4aa8', '#57606a', '#1f6feb', '#c2185b'];
    new uPlot({
      title: 'Max tracking error per ' + name + ': episodes per bin (log-spaced)',
      width: Math.min(720, Math.max(320, box.clientWidth - 8)),
      height: 200,
      scales: { x: { time: false, distr: 3 } },
      axes: [{ label: 'max tracking error (mm)', values: (u, splits) => splits.map((v) => P.fmt(v, 3)) },
        { label: 'episodes' }],
      series: [{ label: 'error (mm)', value: (u, v) => (v === null || v === undefined ? '--' : P.fmt(v, 3) + ' mm') },
        ...shown.map((g, k) => ({ label: g.label, stroke: colors[k % colors.length], width: 1.5,
          points: { show: true } }))],
    }, [centres, ...shown.map((g) => g.counts)], box);
  }

  function main(data, root) {
    const table = data.table;
    const n = table.rows;
    // The same in every row: listed once below the table, but for the columns the page reads
    // (the verdict) and the id, which stay columns whatever their values.
    const always = new Set(['episode_id', 'status', 'met_tolerance', 'failure']);
    const cols = table.columns.filter((c) => c.encoding !== 'const' || always.has(c.name));
    const constants = table.columns.filter((c) => !cols.includes(c));
    const field = new Map(cols.map((c, j) => [c.name, 'c' + j]));
    const varying = data.axes.filter((a) => field.has(a));
    const state = {
      statuses: data.statuses,
      hidden: new Set(),
      shown: new Set(['episode_id', ...varying, ...firstShown]),
      kept: P.column(data.episodes.kept),
      href: data.episodes.href,
    };
    // Rows as objects: c<j> per column, _i the row's place in the file, met for the summaries.
    const rows = Array.from({ length: n }, (_, i) => ({ _i: i }));
    cols.forEach((c, j) => {
      const vs = values(c, n);
      const f = 'c' + j;
      for (let i = 0; i < n; i++) rows[i][f] = vs[i];
    });
    const statusField = field.get('status');
    const metField = field.get('met_tolerance');
    for (const r of rows) r.met = metField ? r[metField] === true : r[statusField] === 'met';
    const counts = new Map();
    for (const r of rows) counts.set(r[statusField], (counts.get(r[statusField]) || 0) + 1);
    for (const s of counts.keys()) if (!state.statuses.includes(s)) state.statuses.push(s);
    // The failures first (by status in judging order, met last; file order within a status) as
    // the table's own order, not a sort: what a third click on a header, which clears the
    // sort, comes back to.
    const rank = statusRank(state.statuses);
    rows.sort((a, b) => rank(a[statusField]) - rank(b[statusField]) || a._i - b._i);
    const met = rows.filter((r) => r.met).length;
    const [low, high] = P.wilson(met, n);
    const kept = state.kept.reduce((a, b) => a + b, 0);
    root.append(el('header', {},
      el('h1', {}, 'Sweep ', el('span', { text: data.title })),
      el('p', { class: 'lead', text: n + ' episodes in ' + data.source + ': ' + met + ' met their tolerance (' +
        (100 * met / n).toFixed(1) + ' %, 95 % interval ' + (100 * low).toFixed(1) + ' .. ' + (100 * high).toFixed(1) +
        ' %); ' + kept + ' kept their files, linked from their ids.' }),
      data.warnings.length ? el('p', { class: 'warning', id: 'warning-count',
        text: data.warnings.length + (data.warnings.length === 1 ? ' warning' : ' warnings') + ':' }) : null,
      data.warnings.map((w) => el('p', { class: 'warning', text: w }))));
    const shownCount = el('span', { id: 'shown' });
    const chooser = el('details', { class: 'chooser' }, el('summary', { text: 'Columns' }));
    const tableBox = el('div', { id: 'episodes' });
    const help = el('p', { class: 'note', text: 'Click a header to sort (again to reverse, a third time back to failures first). ' +
      'Filters under the headers: a value from the list, text to look for, or for numbers ">0.001", "<=5", "1..3". ' +
      'Numbers show 4 significant digits, lengths in mm (a column "_mm"; results.jsonl has them exact, in m).' });
    const chips = statusChips(state, counts, () => tab.refreshFilter());
    root.append(el('section', { class: 'table' }, el('h2', { text: 'Episodes' }),
      el('div', { class: 'toolbar' }, chips, shownCount, chooser), help, tableBox));
    const axesBox = el('section', { class: 'axes', id: 'axes' }, el('h2', { text: 'Per axis, over the episodes shown' }));
    root.append(axesBox);
    if (constants.length) {
      root.append(el('details', { class: 'constants' },
        el('summary', { text: 'The same in every episode (' + constants.length + ' columns)' }),
        el('table', {}, el('tbody', {}, constants.map((c) => el('tr', {}, el('th', { text: shownName(c) }),
          el('td', { text: c.value === null ? '(none)' : P.fmt(values(c, 1)[0], 8) })))))));
    }
    if (table.omitted.length) {
      root.append(el('p', { class: 'note', text: 'Lists of lists, in results.jsonl only: ' + table.omitted.join(', ') }));
    }
    // An axis that groups the episodes exactly as an earlier one (world_file beside world) says
    // nothing new: it keeps its column but gets no summary.
    const same = (a, b) => {
      const fa = field.get(a);
      const fb = field.get(b);
      const pairs = new Set(rows.map((r) => String(r[fa]) + '\u0000' + String(r[fb])));
      const count = (f) => new Set(rows.map((r) => r[f])).size;
      return pairs.size === count(fa) && pairs.size === count(fb);
    };
    const summarised = varying.filter((a, k) => !varying.slice(0, k).some((b) => same(a, b)));
    const groups = new Map(summarised.map((a) => {
      const col = cols.find((c) => c.name === a);
      return [a, axisGroups(col, rows, field.get(a))];
    }));
    const errorFields = errorKeys.map((k) => field.get(k));
    window.parksimHistograms = {};
    const drawAxes = (shown) => {
      axesBox.replaceChildren(axesBox.firstChild);
      if (summarised.length === 0) axesBox.append(el('p', { class: 'note', text: 'No axis varies in this table.' }));
      for (const a of summarised) {
        const g = groups.get(a);
        const summary = P.summarise(shown, g.key, g.order, errorFields.filter(Boolean));
        const title = shownName(cols.find((c) => c.name === a));
        const box = el('div', { class: 'axis', 'data-axis': a }, el('h3', { text: title }));
        axesBox.append(box);
        box.append(summaryTable(title, g, summary, errorFields));
        summaryPlot(title, g, summary, errorFields[0], box);
        if (errorFields[0]) errorHistogram(title, a, g, shown, errorFields[0], box);
      }
    };
    const tab = new Tabulator(tableBox, {
      data: rows,
      index: '_i',
      height: '560px',
      layout: 'fitData',
      renderHorizontal: cols.length > 40 ? 'virtual' : 'basic',
      placeholder: 'No episode matches the filters',
      // Only the columns shown: each column costs start-up time whether shown or not; the
      // others are added when chosen.
      columns: cols.filter((c) => state.shown.has(c.name)).map((c) => columnDef(c, field.get(c.name), state)),
    });
    window.parksimTable = tab;
    document.body.dataset.rows = String(n);
    const defined = new Set([...state.shown].filter((n) => field.has(n)));
    const showColumn = (c, show) => {
      const f = field.get(c.name);
      if (!show) {
        tab.hideColumn(f);
      } else if (defined.has(c.name)) {
        tab.showColumn(f);
      } else {
        defined.add(c.name);
        tab.addColumn(columnDef(c, f, state));
      }
    };
    let pending = false;
    const onFiltered = () => {
      if (pending) return;
      pending = true;
      requestAnimationFrame(() => {
        pending = false;
        const shown = tab.getData('active');
        shownCount.textContent = shown.length + ' of ' + n + ' shown';
        document.body.dataset.shown = String(shown.length);
        drawAxes(shown);
      });
    };
    return new Promise((resolve) => {
      tab.on('tableBuilt', () => {
        tab.setFilter((row) => !state.hidden.has(row[statusField]));
        chooser.append(el('div', { class: 'choices' }, cols.map((c) => el('label', {},
          el('input', { type: 'checkbox', checked: state.shown.has(c.name),
            onchange: (e) => showColumn(c, e.target.checked) }),
          ' ' + shownName(c)))));
        tab.on('dataFiltered', onFiltered);
        const shown = tab.getData('active');
        shownCount.textContent = shown.length + ' of ' + n + ' shown';
        document.body.dataset.shown = String(shown.length);
        drawAxes(shown);
        resolve();
      });
    });
  }

  P.start(main);
})(parksim);
