// A comparison's page (parksim/pages/ComparisonPage.h): the headline, then every group's tests
// in one Tabulator table, regressed groups first, each metric with both sides, their
// intervals and the Holm-adjusted p-value; then, per group, its paired episodes whose pages
// both sweeps kept, the worst changes first, linked side by side.
'use strict';

(function (P) {
  const el = P.el;

  function pct(x) {
    return (100 * x).toFixed(1) + ' %';
  }

  function signedPct(x) {
    return (x >= 0 ? '+' : '') + (100 * x).toFixed(1) + ' %';
  }

  // One side of a metric: a rate with its Wilson interval, or a quantile in mm.
  function sideText(m, which) {
    if (!m.tested) return '-';
    if (m.q < 0) {
      const k = m[which + '_met'];
      const n = m[which + '_n'];
      const [lo, hi] = P.wilson(k, n);
      return k + '/' + n + ' = ' + pct(k / n) + ' (' + pct(lo) + ' .. ' + pct(hi) + ')';
    }
    return P.mm(m[which]);
  }

  function changeText(m) {
    if (!m.tested) return '-';
    if (m.q < 0) {
      const pp = 100 * (m.candidate - m.baseline);
      return (pp >= 0 ? '+' : '') + pp.toFixed(1) + ' pp';
    }
    if (!(m.baseline > 0)) return '-';
    return signedPct(m.candidate / m.baseline - 1) +
      (m.ci_low !== null ? ' (' + signedPct(m.ci_low) + ' .. ' + signedPct(m.ci_high) + ')' : '');
  }

  function pText(p) {
    if (p === null || p === undefined) return '-';
    return p < 1e-4 ? '<0.0001' : String(Number(p.toPrecision(2)));
  }

  // A group's name, then, compared across columns, what each side held in them:
  // "head_in / * / world (planner: time-a-star vs example)".
  function groupTitle(group) {
    if (!group.across) return group.name;
    return group.name + ' (' + group.across.map((a) => a.column + ': ' + a.baseline + ' vs ' + a.candidate).join('; ') + ')';
  }

  function episodesOf(group) {
    const box = el('div', { class: 'pairs', 'data-group': group.name },
      el('h3', {}, group.regression ? P.badge('regression') : null, ' ', groupTitle(group)));
    if (group.linked_episodes === 0) {
      box.append(el('p', { class: 'note', text: group.paired_episodes + ' episodes in both tables; ' +
        'neither sweep kept pages for the same ones (record: executed_csv: all or failures keeps them).' }));
      return box;
    }
    box.append(el('p', { class: 'note', text: group.linked_episodes + ' of ' + group.paired_episodes +
      ' paired episodes linked, the worst changes first.' }));
    const side = (s, href, label) => el('td', {}, P.badge(s.status), ' ',
      s.max_pos_err_m === null ? '' : 'max ' + P.mm(s.max_pos_err_m) + ' ', el('a', { href, text: label }));
    box.append(el('table', { class: 'summary pairs-table' },
      el('thead', {}, el('tr', {}, el('th', { text: 'episode' }), el('th', { text: 'baseline' }), el('th', { text: 'candidate' }))),
      el('tbody', {}, group.episodes.map((e) => el('tr', {}, el('td', { text: e.candidate_id ? e.id + ' / ' + e.candidate_id : e.id }),
        side(e.baseline, e.baseline_href, 'baseline page'),
        side(e.candidate, e.candidate_href, 'candidate page'))))));
    return box;
  }

  function main(data, root) {
    const groups = [...data.groups].sort((a, b) => (b.regression - a.regression) || a.name.localeCompare(b.name));
    const s = data.settings;
    root.append(el('header', {},
      el('h1', {}, 'Comparison ', P.badge(data.regression ? 'regression' : 'met')),
      el('p', { class: 'verdict ' + (data.regression ? 'failed' : 'met'), id: 'verdict',
        text: data.regression
          ? data.regressions + ' of ' + data.tests + ' tests found a regression'
          : 'no regression in ' + data.tests + ' tests' }),
      el('dl', { class: 'facts' },
        el('dt', { text: 'baseline' }), el('dd', { text: data.baseline.path + ' (' + data.baseline.rows + ' episodes)' }),
        el('dt', { text: 'candidate' }), el('dd', { text: data.candidate.path + ' (' + data.candidate.rows + ' episodes)' }),
        el('dt', { text: 'method' }), el('dd', { text: 'success rate: exact test (McNemar paired, Fisher unpaired); ' +
          'error quantiles: bootstrap (' + s.resamples + ' resamples), a regression when grown by more than ' +
          pct(s.max_increase) + ' and ' + P.mm(s.min_increase_m) + '; Holm-adjusted over every test at ' +
          pct(s.confidence) + ' family-wise confidence. Intervals: a rate\'s 95 % Wilson interval, a ' +
          'quantile\'s change at the same confidence (not adjusted).' }),
        data.across ? [el('dt', { text: 'compared across' }), el('dd', { text: data.across.join(', ') +
          ': rows pair when every other parameter is equal' })] : []),
      [...data.only_baseline.map((g) => el('p', { class: 'warning', text: 'only in the baseline: ' + g })),
        ...data.only_candidate.map((g) => el('p', { class: 'warning', text: 'only in the candidate: ' + g }))]));
    // What differs between the two configurations: the columns whose values differ, the
    // lines of the spec files only one has (compare/ConfigurationDiff.h).
    if (data.differences) {
      const diff = el('section', { class: 'differences', id: 'differences' },
        el('h2', { text: 'What differs between the configurations' }));
      if (data.differences.length === 0) {
        diff.append(el('p', { class: 'note', text: 'Nothing: the same parameters, build, worlds and spec lines.' }));
      } else {
        diff.append(el('table', { class: 'summary' },
          el('thead', {}, el('tr', {}, el('th', { text: 'what' }), el('th', { text: 'baseline' }), el('th', { text: 'candidate' }))),
          el('tbody', {}, data.differences.map((d) => el('tr', {}, el('td', { text: d.what }),
            el('td', { text: d.baseline }), el('td', { text: d.candidate }))))));
      }
      root.append(diff);
    }
    const rows = [];
    for (const g of groups) {
      for (const m of g.metrics) {
        rows.push({
          group: groupTitle(g), regressed_group: g.regression, metric: m.name,
          baseline: sideText(m, 'baseline'), candidate: sideText(m, 'candidate'),
          change: changeText(m), p: m.tested ? m.p : null, p_adjusted: m.tested ? m.p_adjusted : null,
          verdict: !m.tested ? 'not tested: ' + m.note : (m.regression ? 'regression' : 'ok'),
          line: m.line, pairing: g.paired ? 'paired' : 'unpaired',
        });
      }
    }
    const tableBox = el('div', { id: 'metrics' });
    root.append(el('section', { class: 'table' }, el('h2', { text: 'Every group and test, regressions first' }), tableBox));
    const verdictCell = (cell) => {
      const v = cell.getValue();
      return v === 'regression' ? P.badge('regression') : P.text(v);
    };
    const tab = new Tabulator(tableBox, {
      data: rows,
      layout: 'fitDataStretch',
      // Cells as text nodes (P.text): a group's name holds world names.
      columnDefaults: { formatter: (c) => P.text(c.getValue()) },
      groupBy: 'group',
      groupHeader: (value, count, data) => el('span', {},
        data.some((r) => r.verdict === 'regression') ? P.badge('regression') : null, ' ', value,
        ' ', el('small', { text: '(' + data[0].pairing + ', ' + count + ' tests)' })),
      columns: [
        { title: 'metric', field: 'metric', headerFilter: 'input', tooltip: (e, cell) => el('span', { text: cell.getRow().getData().line }) },
        { title: 'baseline', field: 'baseline' },
        { title: 'candidate', field: 'candidate' },
        { title: 'change (interval)', field: 'change' },
        { title: 'p', field: 'p', sorter: 'number', formatter: (c) => P.text(pText(c.getValue())), hozAlign: 'right' },
        { title: 'p, Holm-adjusted', field: 'p_adjusted', sorter: 'number', formatter: (c) => P.text(pText(c.getValue())), hozAlign: 'right' },
        { title: 'verdict', field: 'verdict', formatter: verdictCell, headerFilter: 'input' },
      ],
    });
    window.parksimTable = tab;
    document.body.dataset.rows = String(rows.length);
    document.body.dataset.groups = String(groups.length);
    const pairs = el('section', { class: 'pairs-list', id: 'pairs' }, el('h2', { text: 'Paired episodes' }));
    for (const g of groups) pairs.append(episodesOf(g));
    root.append(pairs);
    return new Promise((resolve) => tab.on('tableBuilt', resolve));
  }

  P.start(main);
})(parksim);
