"""Compact episode records (issue 20, item 5): executed.npz and sensors.npz, as `parksim run
--record-format npz` and sweeps (by default) write them, read by NumPy and pandas with nothing of
parksim, and by `parksim.read_record`; bit for bit the values executed.csv holds, in at most a
third of its bytes for a 240 Hz episode.
"""

import json
import os
import pathlib
import subprocess

import numpy as np
import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("PARKSIM_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[2]))
WORLD = SOURCE_DIR / "worlds" / "head_in.yaml"


def parksim(*args, ok=(0,)):
    exe = os.environ.get("PARKSIM_EXE")
    if not exe:
        pytest.skip("PARKSIM_EXE is not set (run through ctest)")
    p = subprocess.run([exe, *map(str, args)], capture_output=True, text=True, timeout=600)
    assert p.returncode in ok, f"exit {p.returncode}: {p.stderr}"
    return p


def read_csv_exact(path):
    """{column: float64 array}, parsed with Python's float (exact for 17 significant digits)."""
    lines = pathlib.Path(path).read_text(encoding="utf-8").splitlines()
    header = lines[0].split(",")
    rows = [[float(v) for v in line.split(",")] for line in lines[1:] if line]
    values = np.array(rows, dtype=np.float64)
    return {name: values[:, i] for i, name in enumerate(header)}


def same_bits(a, b):
    return a.shape == b.shape and np.array_equal(a.view(np.uint64), b.view(np.uint64))


@pytest.fixture(scope="module", params=["ideal", "lab"])
def runs(request, tmp_path_factory):
    """One episode recorded at 240 Hz (every physics step: run's default) in both formats."""
    tmp = tmp_path_factory.mktemp(f"records-{request.param}")
    for fmt in ("csv", "npz"):
        parksim("run", WORLD, "--realism", request.param, "--record-format", fmt,
                "--out", tmp / fmt)
    return request.param, tmp


def test_npz_reads_back_bit_exact_with_numpy_and_has_the_csvs_columns(runs):
    realism, tmp = runs
    csv = read_csv_exact(tmp / "csv" / "executed.csv")
    with np.load(tmp / "npz" / "executed.npz", allow_pickle=False) as npz:
        assert list(npz.files) == list(csv)
        for name in csv:
            assert npz[name].dtype == np.float64
            assert same_bits(npz[name], csv[name]), name
    metrics = json.loads((tmp / "npz" / "metrics.json").read_text())
    assert len(csv["t"]) == metrics["steps"] + 1  # every physics step: 240 Hz
    assert len(csv) == (26 if realism == "lab" else 13)


def test_npz_is_at_most_a_third_of_the_csv(runs):
    realism, tmp = runs
    csv = (tmp / "csv" / "executed.csv").stat().st_size
    npz = (tmp / "npz" / "executed.npz").stat().st_size
    print(f"{realism}: executed.csv {csv} bytes, executed.npz {npz} bytes ({csv / npz:.2f}x)")
    assert 3 * npz <= csv


def test_sensors_npz_matches_sensors_csv(runs):
    realism, tmp = runs
    if realism != "lab":
        assert not (tmp / "npz" / "sensors.npz").exists()
        return
    csv = read_csv_exact(tmp / "csv" / "sensors.csv")
    with np.load(tmp / "npz" / "sensors.npz") as npz:
        assert list(npz.files) == ["t_received", "t_taken", "x", "y", "theta"]
        for name in csv:
            assert same_bits(npz[name], csv[name]), name


def test_pandas_reads_the_npz_exactly(runs):
    pd = pytest.importorskip("pandas")
    _, tmp = runs
    frame = pd.DataFrame(dict(np.load(tmp / "npz" / "executed.npz")))
    csv = read_csv_exact(tmp / "csv" / "executed.csv")
    assert list(frame.columns) == list(csv)
    for name in csv:
        assert same_bits(frame[name].to_numpy(), csv[name]), name


def test_read_record_reads_both_formats_alike(runs):
    parksim_module = pytest.importorskip("parksim")
    _, tmp = runs
    a = parksim_module.read_record(tmp / "csv" / "executed.csv")
    b = parksim_module.read_record(tmp / "npz" / "executed.npz")
    assert a.dtype.names == b.dtype.names
    for name in a.dtype.names:
        assert same_bits(a[name], b[name]), name


def test_numpy_written_archives_are_read_by_parksim(tmp_path):
    """parksim reads what numpy.savez_compressed writes (e.g. a record edited in Python)."""
    t = np.arange(0.0, 1.0, 1.0 / 240.0)
    np.savez_compressed(tmp_path / "executed.npz", t=t, pos_err=1e-3 * np.sin(t),
                        heading_err=np.zeros_like(t))
    p = parksim("render", WORLD, "--executed", tmp_path / "executed.npz",
                "--figures", "tracking_error", "--out", tmp_path / "render")
    assert (tmp_path / "render" / "figures").is_dir(), p.stdout


def test_a_sweep_records_npz_by_default(tmp_path):
    (tmp_path / "spec.yaml").write_text(
        "format: parksim-sweep/1\nname: rec\n"
        f"worlds: [{WORLD}]\nplanners: [hybrid-a-star]\nseeds: 1\n"
        "realism: lab\nnoise_seeds: {from: 1, to: 2}\n"
        "record: {executed_csv: all, executed_rate_hz: 240}\n", encoding="utf-8")
    parksim("sweep", tmp_path / "spec.yaml", "--out", tmp_path / "out", "--workers", "2")
    dirs = sorted((tmp_path / "out" / "episodes").iterdir())
    assert len(dirs) == 2
    for d in dirs:
        assert (d / "executed.npz").is_file() and not (d / "executed.csv").exists()
        assert (d / "sensors.npz").is_file()
        with np.load(d / "executed.npz") as npz:
            assert len(npz.files) == 26
