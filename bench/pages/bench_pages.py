#!/usr/bin/python3
"""The pages in headless Chromium (docs/pages.md, "Speed"), through scripts/page_browser.py's
session (Debian's chromium and chromedriver, python3-selenium):

  bench/pages/bench_pages.py ready PAGE... [--runs 5]
      each page opened from file:// RUNS times (after one warm-up); the time from navigation
      start to document.body.dataset.ready (the page's own clock), min / median / max, and the
      page's size on disk
  bench/pages/bench_pages.py scrub PAGE [--steps 600]
      an episode page's scrubber moved across the whole episode in STEPS steps, one per
      animation frame, each an input event as a drag of the scrubber makes: frames per second
      over the whole drag, and the time each step took from the event to the replay's canvas
      drawn (its pixels read back), median and p95

Prints one Markdown table row per page."""
import argparse
import os
import pathlib
import statistics
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "scripts"))
from page_browser import PageBrowser  # noqa: E402

SCRUB = """
const done = arguments[arguments.length - 1];
const steps = arguments[0];
const s = document.getElementById('scrubber');
const canvas = document.getElementById('lot');
const rows = Number(s.max) + 1;
const work = [];
let k = 0;
const t0 = performance.now();
function step() {
  const a = performance.now();
  s.value = Math.round(k * (rows - 1) / (steps - 1));
  s.dispatchEvent(new Event('input'));
  canvas.getContext('2d').getImageData(0, 0, 1, 1);  // the drawing done, not only queued
  work.push(performance.now() - a);
  if (++k < steps) requestAnimationFrame(step);
  else requestAnimationFrame(() => done({ms: performance.now() - t0, work, rows}));
}
requestAnimationFrame(step);
"""


def ready(args):
    print("| page | size (MB) | ready median (s) | min | max |")
    print("|---|---:|---:|---:|---:|")
    with PageBrowser() as b:
        for page in args.pages:
            b.open(page)  # warm-up: the browser's caches
            times = [b.open(page) for _ in range(args.runs)]
            errors = b.console_errors()
            if errors:
                raise SystemExit("%s: console errors %s" % (page, errors))
            size = os.path.getsize(page) / 1e6
            print("| %s | %.2f | %.3f | %.3f | %.3f |" % (
                page, size, statistics.median(times), min(times), max(times)))


def scrub(args):
    print("| page | rows | steps | frames/s | step median (ms) | step p95 (ms) |")
    print("|---|---:|---:|---:|---:|---:|")
    with PageBrowser() as b:
        for page in args.pages:
            b.open(page)
            b.driver.set_script_timeout(300)
            r = b.driver.execute_async_script(SCRUB, args.steps)
            work = sorted(r["work"])
            fps = args.steps / (r["ms"] / 1000.0)
            print("| %s | %d | %d | %.1f | %.2f | %.2f |" % (
                page, r["rows"], args.steps, fps, statistics.median(work),
                work[int(0.95 * (len(work) - 1))]))
            if b.console_errors():
                raise SystemExit("%s: console errors %s" % (page, b.console_errors()))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = parser.add_subparsers(dest="command", required=True)
    r = sub.add_parser("ready")
    r.add_argument("pages", nargs="+")
    r.add_argument("--runs", type=int, default=5)
    s = sub.add_parser("scrub")
    s.add_argument("pages", nargs="+")
    s.add_argument("--steps", type=int, default=600)
    args = parser.parse_args()
    {"ready": ready, "scrub": scrub}[args.command](args)


if __name__ == "__main__":
    main()
