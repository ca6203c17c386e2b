// Statistics the sweep and comparison pages compute over the rows they show: a success rate's
// 95 % interval (Wilson's score interval, which stays inside [0, 1] and is honest at 0 and at
// n successes out of n) and quantiles as parksim's reports take them (type 7, the linear
// interpolation of compare/Quantile.h's quantile7, NumPy's default).
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
