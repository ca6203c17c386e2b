#!/usr/bin/env python3
"""Samples a running sweep for bench/sweep_scale.sh, and fits the samples.

sample.py PID RESULTS_JSONL OUT_CSV   every 0.5 s until PID ends: rows written (newlines of
                                      results.jsonl, counted incrementally), resident memory
                                      (VmRSS, bytes) and CPU time (utime + stime, s) of PID
sample.py --fit OUT_CSV               memory growth per row after the first 1,000 rows (least
                                      squares), and CPU time per row in each tenth of the rows
"""
import os
import sys
import time


def sample(pid, path, out):
    tick = os.sysconf("SC_CLK_TCK")
    rows, pos = 0, 0
    with open(out, "w") as f:
        f.write("rows,rss_bytes,cpu_s,wall_s\n")
        t0 = time.monotonic()
        while True:
            try:
                with open(f"/proc/{pid}/status") as s:
                    rss = next(int(l.split()[1]) * 1024 for l in s if l.startswith("VmRSS:"))
                with open(f"/proc/{pid}/stat") as s:
                    fields = s.read().rsplit(")", 1)[1].split()
                cpu = (int(fields[11]) + int(fields[12])) / tick
            except (FileNotFoundError, ProcessLookupError, StopIteration):
                break
            try:
                with open(path, "rb") as r:
                    r.seek(pos)
                    data = r.read()
                    rows += data.count(b"\n")
                    pos += len(data)
            except FileNotFoundError:
                pass
            f.write(f"{rows},{rss},{cpu:.2f},{time.monotonic() - t0:.2f}\n")
            f.flush()
            time.sleep(0.5)


def fit(path):
    samples = []
    with open(path) as f:
        next(f)
        for line in f:
            r, rss, cpu, wall = line.split(",")
            samples.append((int(r), int(rss), float(cpu), float(wall)))
    total = max(s[0] for s in samples)
    after = [s for s in samples if s[0] >= 1000]
    n = len(after)
    mx = sum(s[0] for s in after) / n
    my = sum(s[1] for s in after) / n
    sxy = sum((s[0] - mx) * (s[1] - my) for s in after)
    sxx = sum((s[0] - mx) ** 2 for s in after)
    slope = sxy / sxx if sxx > 0 else float("nan")
    first = next(s for s in samples if s[0] >= 1000)
    last = samples[-1]
    print(f"rows {total}; RSS {first[1] / 2**20:.1f} MB at row {first[0]}, "
          f"{last[1] / 2**20:.1f} MB at row {last[0]}; "
          f"memory growth after the first 1,000 rows: {slope:.1f} bytes/row (least squares, "
          f"{n} samples)")
    # CPU time per row in tenths of the rows: the sample nearest each boundary.
    per_row = []
    for k in range(10):
        lo, hi = total * k // 10, total * (k + 1) // 10
        a = min(samples, key=lambda s: abs(s[0] - lo))
        b = min(samples, key=lambda s: abs(s[0] - hi))
        if b[0] > a[0]:
            per_row.append((b[2] - a[2]) / (b[0] - a[0]))
    print("CPU ms per row, by tenth of the rows: " +
          " ".join(f"{1000 * x:.2f}" for x in per_row))
    base = sorted(per_row[1:4])[1] if len(per_row) >= 4 else per_row[0]
    print(f"last tenth / median of tenths 2-4: {per_row[-1] / base:.3f}; "
          f"max tenth / min tenth (2-10): {max(per_row[1:]) / min(per_row[1:]):.3f}")
    print(f"sweep wall {last[3]:.0f} s, CPU {last[2]:.0f} s")


if __name__ == "__main__":
    if sys.argv[1] == "--fit":
        fit(sys.argv[2])
    else:
        sample(int(sys.argv[1]), sys.argv[2], sys.argv[3])
