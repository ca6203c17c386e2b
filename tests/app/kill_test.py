#!/usr/bin/env python3
"""Kill and concurrency test of parksim's output directory (docs/limits.md, "Output directory").

Kill: `parksim run --frames --video` is SIGKILLed or SIGINTed at seeded random moments. After
each kill, --out must hold exactly the earlier run's files (same names, same bytes) or a
complete new run's (the new run's names, every PNG whole, metrics.json readable), never a mix
and never a partial file; no ffmpeg may outlive parksim; after SIGINT no staging directory may
remain. Concurrency: a second command into an --out that another command is writing must fail
at once (exit 2, "another parksim command"), and of two commands started together never both
succeed.

Usage: kill_test.py PARKSIM WORLD [--kills N] [--seed S]
"""

import argparse
import fcntl
import hashlib
import json
import os
import random
import shutil
import signal
import subprocess
import sys
import tempfile
import time

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL: " + message, flush=True)


def snapshot(directory):
    """Relative path -> sha256 of every file under directory (None when it does not exist)."""
    if not os.path.isdir(directory):
        return None
    files = {}
    for root, _, names in os.walk(directory):
        for name in names:
            path = os.path.join(root, name)
            with open(path, "rb") as f:
                files[os.path.relpath(path, directory)] = hashlib.sha256(f.read()).hexdigest()
    return files


def complete_run(directory, expected_names):
    """True when directory holds exactly expected_names, every PNG whole, metrics.json valid."""
    snap = snapshot(directory)
    if snap is None or set(snap) != expected_names:
        return False
    for name in snap:
        path = os.path.join(directory, name)
        if name.endswith(".png"):
            with open(path, "rb") as f:
                data = f.read()
            if not data.startswith(b"\x89PNG") or b"IEND" not in data[-12:]:
                return False
    with open(os.path.join(directory, "metrics.json")) as f:
        json.load(f)
    return True


def ffmpeg_writing_into(parent):
    """Pids of ffmpeg processes whose command line names a path under parent."""
    pids = []
    for pid in os.listdir("/proc"):
        if not pid.isdigit():
            continue
        try:
            with open("/proc/%s/cmdline" % pid, "rb") as f:
                argv = f.read().split(b"\0")
        except OSError:
            continue
        if argv and os.path.basename(argv[0]) == b"ffmpeg" and any(
                parent.encode() in a for a in argv):
            pids.append(int(pid))
    return pids


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("parksim")
    ap.add_argument("world")
    ap.add_argument("--kills", type=int, default=10)
    ap.add_argument("--seed", type=int, default=13)
    args = ap.parse_args()
    rng = random.Random(args.seed)
    tmp = tempfile.mkdtemp(prefix="parksim_kill_")
    out = os.path.join(tmp, "out")
    # Two runs with different frame counts, so their file sets differ.
    base = [args.parksim, "run", args.world, "--frames", "--video", "--size", "32x24",
            "--out", out]
    old_cmd = base + ["--fps", "1"]
    new_cmd = base + ["--fps", "2"]
    try:
        t0 = time.monotonic()
        r = subprocess.run(new_cmd, capture_output=True)
        full_s = time.monotonic() - t0
        check(r.returncode == 0, "reference run failed: %s" % r.stderr.decode(errors="replace"))
        new_names = set(snapshot(out))
        check(any(n.startswith("frames/") for n in new_names), "the reference run wrote no frames")
        r = subprocess.run(old_cmd, capture_output=True)
        check(r.returncode == 0, "earlier run failed: %s" % r.stderr.decode(errors="replace"))
        print("full run %.2f s; %d files new, %d earlier" % (full_s, len(new_names),
                                                            len(snapshot(out))), flush=True)

        for i in range(args.kills):
            sig = signal.SIGKILL if i % 2 == 0 else signal.SIGINT
            before = snapshot(out)
            delay = rng.uniform(0.0, full_s * 1.1)
            p = subprocess.Popen(new_cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
            time.sleep(delay)
            p.send_signal(sig)
            _, err = p.communicate()
            after = snapshot(out)
            kept = after == before
            whole_new = complete_run(out, new_names)
            print("kill %d: %s after %.2f s -> exit %d, %s" %
                  (i, sig.name, delay, p.returncode,
                   "earlier run" if kept else ("new run" if whole_new else "MIXED")), flush=True)
            check(kept or whole_new,
                  "kill %d (%s at %.2f s): --out is neither the earlier run nor the new one" %
                  (i, sig.name, delay))
            check(p.returncode in (0, -sig, 2) or (p.returncode == 1 and whole_new),
                  "kill %d: unexpected exit %d: %s" % (i, p.returncode, err.decode(errors="replace")))
            # PR_SET_PDEATHSIG is delivered as the parent dies; give the kernel a moment.
            for _ in range(50):
                if not ffmpeg_writing_into(tmp):
                    break
                time.sleep(0.02)
            check(not ffmpeg_writing_into(tmp), "kill %d: ffmpeg outlived parksim" % i)
            if sig == signal.SIGINT:
                # (a SIGKILLed run's staging stays until the next run gets past its checks)
                left = [n for n in os.listdir(tmp) if n.endswith("staging-%d" % p.pid)]
                check(not left, "kill %d: SIGINT left %s" % (i, left))

        # Directed (issue 22): SIGINT while planning with --progress ends the progress line,
        # so the shell's prompt does not run into it. rrt-star plans until its budget.
        plan_cmd = [args.parksim, "plan", args.world, "--planner", "rrt-star", "--progress",
                    "--max-iterations", "1000000", "--out", os.path.join(tmp, "plan")]
        p = subprocess.Popen(plan_cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        err = b""
        while p.poll() is None and b"\r" not in err:
            chunk = os.read(p.stderr.fileno(), 4096)
            if not chunk:
                break
            err += chunk
        check(b"\r" in err, "plan --progress drew no progress line: %r" % err[-200:])
        p.send_signal(signal.SIGINT)
        err += p.stderr.read()
        p.wait()
        print("SIGINT during planning: exit %d, stderr ends %r" % (p.returncode, err[-40:]),
              flush=True)
        check(p.returncode == -signal.SIGINT, "plan: exit %d after SIGINT" % p.returncode)
        check(err.endswith(b"\n"), "SIGINT left the progress line open: %r" % err[-80:])

        # Directed: SIGKILL while ffmpeg is encoding; ffmpeg must die with parksim.
        before = snapshot(out)
        p = subprocess.Popen(new_cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        seen = False
        while p.poll() is None and not seen:
            seen = bool(ffmpeg_writing_into(tmp))
            time.sleep(0.002)
        p.kill()
        p.wait()
        print("kill during ffmpeg: %s" % ("ffmpeg was running" if seen else "ffmpeg not caught"),
              flush=True)
        for _ in range(50):
            if not ffmpeg_writing_into(tmp):
                break
            time.sleep(0.02)
        check(not ffmpeg_writing_into(tmp), "ffmpeg outlived a SIGKILLed parksim")
        if seen:
            check(snapshot(out) == before, "a kill during ffmpeg changed --out")

        # The next run into the same --out cleans up what SIGKILL left and succeeds.
        r = subprocess.run(old_cmd, capture_output=True)
        check(r.returncode == 0, "run after the kills failed: %s" % r.stderr.decode(errors="replace"))
        left = [n for n in os.listdir(tmp) if ".parksim-" in n]
        check(not left, "staging directories left after a complete run: %s" % left)

        # Concurrency, deterministic: once the first command holds the lock, a second fails.
        lock = os.path.join(tmp, ".out.lock")
        for attempt in range(2):
            first = subprocess.Popen(new_cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
            held = False
            for _ in range(500):
                with open(lock, "a") as f:
                    try:
                        fcntl.flock(f, fcntl.LOCK_EX | fcntl.LOCK_NB)
                        fcntl.flock(f, fcntl.LOCK_UN)
                    except BlockingIOError:
                        held = True
                if held or first.poll() is not None:
                    break
                time.sleep(0.005)
            second = subprocess.run(old_cmd, capture_output=True)
            first.communicate()
            if held:
                check(second.returncode == 2 and b"another parksim command" in second.stderr,
                      "concurrency %d: second run while the first held the lock: exit %d: %s" %
                      (attempt, second.returncode, second.stderr.decode(errors="replace")))
            check(first.returncode == 0, "concurrency %d: first run exit %d" %
                  (attempt, first.returncode))
            check(complete_run(out, new_names) or held is False,
                  "concurrency %d: --out is not the first run's whole output" % attempt)
        # Two started together: never both succeed.
        for attempt in range(1):
            a = subprocess.Popen(new_cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
            b = subprocess.Popen(old_cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
            a.communicate()
            b.communicate()
            print("together %d: exits %d and %d" % (attempt, a.returncode, b.returncode),
                  flush=True)
            check(not (a.returncode == 0 and b.returncode == 0),
                  "together %d: both runs into one --out succeeded" % attempt)
            check(sorted([a.returncode, b.returncode])[1] == 2,
                  "together %d: the loser did not exit 2" % attempt)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    if failures:
        print("%d failure(s)" % len(failures))
        return 1
    print("all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
