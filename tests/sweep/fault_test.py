#!/usr/bin/env python3
"""Full disks and read-only output directories (issue 22, item 2), as root on small tmpfs
mounts (`mount -t tmpfs -o size=...`): `sweep`, `merge`, `report` and `run --frames --video`
run out of space at seeded points (a seeded file-system size and a seeded filler file), and
each must stop with a clean one-line error (exit 2), leave whole tables (`parksim verify`
finds no problem) or its earlier output untouched, and leave no temporary file; once the file
system is grown (`mount -o remount,size=...`) the same command completes, and the table equals
a sweep that never ran out of space (timing columns aside). A read-only --out is refused with a
clean error by every writing command and still verified by `verify`.

No wall-clock timing is asserted; every process is bounded by a timeout only so that a hang
fails instead of blocking CI. Without root (or without mount) the test is skipped (exit 77).

Usage: fault_test.py PARKSIM_EXE SOURCE_DIR WORK_DIR [SEED]
"""
import json
import os
import random
import shutil
import subprocess
import sys

EXE, SRC, WORK = (os.path.realpath(a) for a in sys.argv[1:4])
SEED = int(sys.argv[4]) if len(sys.argv) > 4 else 22
rng = random.Random(SEED)
TIMING = {"plan_time_s", "plan_first_solution_s", "sim_wall_s", "episode_wall_s",
          "plan_cost_history", "plan_phase_times_s", "row_checksum", "host"}
mounts = []


def skip(why):
    print(f"skipped: {why}")
    sys.exit(77)


def run(*args, timeout=300):
    p = subprocess.run([EXE, *args], capture_output=True, text=True, timeout=timeout)
    return p.returncode, p.stdout, p.stderr


def mount(name, size):
    path = os.path.join(WORK, name)
    os.makedirs(path, exist_ok=True)
    subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={size}", "tmpfs", path], check=True)
    mounts.append(path)
    return path


def remount(path, options):
    subprocess.run(["mount", "-o", f"remount,{options}", path], check=True)


def unmount_all():
    for path in reversed(mounts):
        subprocess.run(["umount", path], check=False)
        if os.path.ismount(path):
            subprocess.run(["umount", "-l", path], check=False)


def fill(path, nbytes):
    """A filler file of nbytes (or as much as fits: nothing, when the mount is full already)."""
    try:
        with open(os.path.join(path, "filler"), "wb") as f:
            f.write(b"\0" * nbytes)
    except OSError:
        # ENOSPC: creating the file or writing it. The tables' sizes vary from run to run (their
        # wall-clock columns), and a tmpfs counts whole pages, so the copied shards can take
        # the whole mount: then there is nothing left to fill.
        pass


def table(directory):
    rows = {}
    with open(os.path.join(directory, "results.jsonl")) as f:
        for line in f:
            r = json.loads(line)
            rows[r["episode_id"]] = {k: v for k, v in r.items() if k not in TIMING}
    return rows


def leftovers(path):
    """Temporary files and staging directories left anywhere under path."""
    found = []
    for root, dirs, files in os.walk(path):
        for n in files + dirs:
            if n.endswith(".tmp") or ".parksim-staging" in n or n.endswith(".removing"):
                found.append(os.path.join(root, n))
    return found


def expect_clean_failure(what, rc, err):
    """Exit 2 and one error line naming the full disk (or the read-only file system)."""
    lines = [l for l in err.splitlines() if l.startswith("parksim: error:")]
    assert rc == 2, f"{what}: exit {rc}, expected 2:\n{err}"
    assert len(lines) == 1, f"{what}: expected one error line:\n{err}"
    assert ("No space left on device" in lines[0] or "Read-only file system" in lines[0]
            or "File too large" in lines[0]), f"{what}: {lines[0]}"
    return lines[0]


def check_whole(what, directory):
    rc, out, err = run("verify", directory)
    assert rc == 0, f"{what}: verify found problems in {directory}:\n{out}{err}"


def main():
    if os.geteuid() != 0:
        skip("the file-system fault tests mount tmpfs file systems: they need root")
    if shutil.which("mount") is None:
        skip("mount not installed")
    shutil.rmtree(WORK, ignore_errors=True)
    os.makedirs(WORK)
    try:
        probe = mount("probe", "64k")
    except subprocess.CalledProcessError:
        skip("cannot mount a tmpfs here (no CAP_SYS_ADMIN?)")
    try:
        spec = os.path.join(WORK, "spec.yaml")
        with open(spec, "w") as f:
            f.write(f"format: parksim-sweep/1\nname: faults\n"
                    f"worlds: [{SRC}/bench/scale/tiny.yaml]\nplanners: hybrid-a-star\n"
                    f"tracking: [open, closed]\nseeds: {{from: 1, to: 12}}\n"
                    f"record: {{executed_csv: all}}\n")
        ref = os.path.join(WORK, "reference")
        rc, _, err = run("sweep", spec, "--out", ref, "--workers", "2")
        assert rc in (0, 1), f"reference sweep: {rc}\n{err}"
        reference = table(ref)
        assert len(reference) == 24
        ref_bytes = sum(os.path.getsize(os.path.join(r, f))
                        for r, _, fs in os.walk(ref) for f in fs)
        sweep_faults(spec, reference, ref_bytes)
        merge_faults(spec, reference)
        report_faults(ref)
        run_faults()
        read_only(spec, ref)
    finally:
        unmount_all()
    print("fault_test: every fault ended in a clean error, whole tables, and a completed re-run")


def sweep_faults(spec, reference, ref_bytes):
    hit = 0
    for trial in range(6):
        # A file system smaller than the sweep's output, at a seeded size, partly filled.
        size = rng.randrange(ref_bytes // 4, ref_bytes)
        size = max(size, 48 * 1024)
        mnt = mount(f"sweep{trial}", size)
        fill(mnt, rng.randrange(0, size // 3))
        out = os.path.join(mnt, "out")
        rc, _, err = run("sweep", spec, "--out", out, "--workers", "2")
        if rc == 2:
            hit += 1
            line = expect_clean_failure(f"sweep trial {trial} ({size} bytes)", rc, err)
            print(f"sweep trial {trial}: {size} bytes: {line}")
            if os.path.exists(os.path.join(out, "results.jsonl")):
                check_whole(f"sweep trial {trial}", out)
        else:
            assert rc in (0, 1), f"sweep trial {trial}: exit {rc}\n{err}"
        assert not leftovers(mnt), f"sweep trial {trial}: left {leftovers(mnt)}"
        # Room again: the same command resumes and completes.
        remount(mnt, "size=64m")
        rc, _, err = run("sweep", spec, "--out", out, "--workers", "2")
        assert rc in (0, 1), f"sweep trial {trial} after growing: exit {rc}\n{err}"
        check_whole(f"sweep trial {trial} completed", out)
        assert table(out) == reference, f"sweep trial {trial}: table differs from the reference"
    assert hit >= 4, f"only {hit} of 6 sweep trials ran out of space: sizes too generous"


def merge_faults(spec, reference):
    shards = os.path.join(WORK, "shards-src")
    for i in range(3):
        rc, _, err = run("sweep", spec, "--out", f"{shards}/shards/{i}", "--shard", f"{i}/3",
                         "--workers", "2")
        assert rc in (0, 1), err
    tables = sum(os.path.getsize(f"{shards}/shards/{i}/{n}") for i in range(3)
                 for n in ("results.jsonl", "results.csv"))
    for trial in range(3):
        # Room for the shards and part of the merged table.
        size = tables + rng.randrange(8 * 1024, tables // 2)
        mnt = mount(f"merge{trial}", size + 64 * 1024)
        sweep = os.path.join(mnt, "sweep")
        os.makedirs(os.path.join(sweep, "shards"))
        for i in range(3):
            shutil.copytree(f"{shards}/shards/{i}", f"{sweep}/shards/{i}",
                            ignore=shutil.ignore_patterns("episodes"))
        fill(mnt, max(0, 64 * 1024 - rng.randrange(0, 16 * 1024)))
        before = {i: open(f"{sweep}/shards/{i}/results.jsonl", "rb").read() for i in range(3)}
        rc, _, err = run("merge", sweep)
        if rc == 2:
            line = expect_clean_failure(f"merge trial {trial}", rc, err)
            print(f"merge trial {trial}: {line}")
            assert not os.path.exists(os.path.join(sweep, "results.jsonl")), "partial merge"
        for i in range(3):
            assert open(f"{sweep}/shards/{i}/results.jsonl", "rb").read() == before[i]
        assert not leftovers(mnt), f"merge trial {trial}: left {leftovers(mnt)}"
        remount(mnt, "size=64m")
        rc, _, err = run("merge", sweep)
        assert rc == 0, f"merge trial {trial} after growing: exit {rc}\n{err}"
        check_whole(f"merge trial {trial}", sweep)
        assert table(sweep) == reference


def report_faults(ref):
    for trial, size in enumerate(sorted(rng.sample(range(16, 160, 8), 3))):
        mnt = mount(f"report{trial}", f"{size}k")
        out = os.path.join(mnt, "report")
        rc, _, err = run("report", ref, "--out", out)
        if rc == 2:
            line = expect_clean_failure(f"report trial {trial}", rc, err)
            print(f"report trial {trial} ({size} KiB): {line}")
            assert not os.path.exists(out), "report: a partial report directory"
        assert not leftovers(mnt), f"report trial {trial}: left {leftovers(mnt)}"
        remount(mnt, "size=64m")
        rc, _, err = run("report", ref, "--out", out)
        assert rc == 0, f"report trial {trial} after growing: {rc}\n{err}"
        assert os.path.exists(os.path.join(out, "summary.md"))


def run_faults():
    video = ["--video"] if shutil.which("ffmpeg") else []
    args = ["run", f"{SRC}/worlds/head_in.yaml", "--frames", "--fps", "4", "--size", "160x120",
            *video]
    for trial, size in enumerate(sorted(rng.sample(range(64, 1024, 32), 3))):
        mnt = mount(f"run{trial}", f"{size}k")
        out = os.path.join(mnt, "film")
        rc, _, err = run(*args, "--out", out)
        if rc == 2:
            line = expect_clean_failure(f"run trial {trial}", rc, err)
            print(f"run --frames{' --video' if video else ''} trial {trial} ({size} KiB): {line}")
            assert not os.path.exists(out), "run: a partial --out"
        assert not leftovers(mnt), f"run trial {trial}: left {leftovers(mnt)}"
        remount(mnt, "size=256m")
        rc, _, err = run(*args, "--out", out)
        assert rc == 0, f"run trial {trial} after growing: {rc}\n{err}"
        assert os.listdir(os.path.join(out, "frames"))


def read_only(spec, ref):
    mnt = mount("readonly", "64m")
    shutil.copytree(ref, os.path.join(mnt, "sweep"), ignore=shutil.ignore_patterns("episodes"))
    remount(mnt, "ro")
    sweep = os.path.join(mnt, "sweep")
    for what, args in (("sweep", ["sweep", spec, "--out", sweep]),
                       ("merge", ["merge", ref, "--out", os.path.join(mnt, "merged")]),
                       ("report", ["report", sweep]),
                       ("run", ["run", f"{SRC}/worlds/head_in.yaml", "--out",
                                os.path.join(mnt, "run")])):
        rc, _, err = run(*args)
        line = expect_clean_failure(f"{what} into a read-only --out", rc, err)
        print(f"read-only --out, {what}: {line}")
    check_whole("verify of a read-only table", sweep)


if __name__ == "__main__":
    main()
