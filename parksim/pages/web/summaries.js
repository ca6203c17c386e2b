// Statistics the sweep and comparison pages compute over the rows they show: a success rate's
// 95 % interval (Wilson's score interval, which stays inside [0, 1] and is honest at 0 and at
// n successes out of n) and quantiles as parksim's reports take them (type 7, the linear
// interpolation of core/stats/Quantile.h's quantile7, NumPy's default).
'use strict';

(function (P) {
  const Z95 = 1.959963984540054;

  // [low, high] of the 95 % Wilson score interval of k successes in n trials.
  P.wilson = function (k, n) {
    if (n <= 0) return [NaN, NaN];
    const p = k / n;
    const z2 = Z95 * Z95;
    const centre = (p + z2 / (2 * n)) / (1 + z2 / n);
    const half = (Z95 / (1 + z2 / n)) * Math.sqrt((p * (1 - p)) / n + z2 / (4 * n * n));
    return [Math.max(0, centre - half), Math.min(1, centre + half)];
  };

  // The q-quantile (0..1) of ascending `sorted` values, type 7; NaN when empty.
  P.quantile7 = function (sorted, q) {
    const n = sorted.length;
    if (n === 0) return NaN;
    const h = (n - 1) * q;
    const lo = Math.floor(h);
    const hi = Math.min(n - 1, lo + 1);
    return sorted[lo] + (h - lo) * (sorted[hi] - sorted[lo]);
  };

  function sortedFinite(values) {
    const out = values.filter((x) => typeof x === 'number' && isFinite(x));
    return out.sort((a, b) => a - b);
  }

  // `bins` edges spaced evenly in log10 from the smallest positive value of `values` to the
  // largest (exactly those two at the ends); one bin [v, v] when they are one value; null when
  // there is no positive value.
  P.logEdges = function (values, bins) {
    const pos = values.filter((x) => typeof x === 'number' && isFinite(x) && x > 0);
    if (pos.length === 0) return null;
    const lo = Math.min(...pos);
    const hi = Math.max(...pos);
    if (lo === hi) return [lo, hi];
    const a = Math.log10(lo);
    const w = (Math.log10(hi) - a) / bins;
    const edges = Array.from({ length: bins + 1 }, (_, k) => Math.pow(10, a + k * w));
    edges[0] = lo;
    edges[bins] = hi;
    return edges;
  };

  // Counts of `values` in the bins of ascending `edges` as NumPy's histogram counts them: bin k
  // holds edges[k] <= x < edges[k + 1], the last one its right edge too; values outside (and
  // missing ones) are not counted.
  P.histogram = function (values, edges) {
    const counts = new Array(edges.length - 1).fill(0);
    const last = edges.length - 1;
    for (const x of values) {
      if (typeof x !== 'number' || !(x >= edges[0] && x <= edges[last])) continue;
      let lo = 0;
      let hi = last - 1;
      while (lo < hi) {
        const mid = (lo + hi + 1) >> 1;
        if (edges[mid] <= x) lo = mid;
        else hi = mid - 1;
      }
      counts[lo]++;
    }
    return counts;
  };

  // Rows grouped by the value of `key`, each group summarised: episodes, met, the met
  // fraction and its interval, and the median, p95 and largest of each error in `errors`
  // (keys of the rows). Groups come in the order of `order` (the axis's values as sorted).
  P.summarise = function (rows, key, order, errors) {
    const groups = new Map(order.map((v) => [v, []]));
    for (const r of rows) {
      const v = r[key];
      if (!groups.has(v)) groups.set(v, []);
      groups.get(v).push(r);
    }
    const out = [];
    for (const [value, members] of groups) {
      if (members.length === 0) continue;
      const met = members.filter((r) => r.met).length;
      const [low, high] = P.wilson(met, members.length);
      const summary = { value, episodes: members.length, met, fraction: met / members.length, low, high };
      for (const e of errors) {
        const s = sortedFinite(members.map((r) => r[e]));
        summary[e] = { median: P.quantile7(s, 0.5), p95: P.quantile7(s, 0.95), max: s.length ? s[s.length - 1] : NaN, n: s.length };
      }
      out.push(summary);
    }
    return out;
  };
})(parksim);
