"""An episode's record as a NumPy structured array, from either format parksim writes.

    import parksim
    rows = parksim.read_record("out/study/episodes/<id>/executed.npz")   # or executed.csv
    rows["pos_err"].max()

executed.npz and sensors.npz are NumPy archives (one float64 array per column, in the CSV's
column order), so `numpy.load(path)` reads them without parksim, and pandas with
`pd.DataFrame(dict(numpy.load(path)))`. Values are the simulation's doubles, bit for bit, in
both formats (the CSV's 17 significant digits read back exactly). docs/simulation.md,
"Recorded rows".
"""

import os as _os

import numpy as _np


def read_record(path):
    """executed.npz / executed.csv / sensors.npz / sensors.csv as a structured array whose
    fields are the file's columns (float64), in the file's order."""
    path = _os.fspath(path)
    if path.endswith(".npz"):
        with _np.load(path, allow_pickle=False) as archive:
            names = list(archive.files)
            columns = [_np.asarray(archive[name], dtype=_np.float64) for name in names]
        lengths = {len(c) for c in columns}
        if len(lengths) > 1:
            raise ValueError(f"{path}: columns differ in length")
        out = _np.empty(lengths.pop() if lengths else 0,
                        dtype=[(name, _np.float64) for name in names])
        for name, column in zip(names, columns):
            out[name] = column
        return out
    # Python's float() reads the 17 digits exactly (NumPy's text parsers are not guaranteed to).
    with open(path, encoding="utf-8") as f:
        header = f.readline().strip().split(",")
        rows = [tuple(float(v) for v in line.split(",")) for line in f if line.strip()]
    return _np.array(rows, dtype=[(name, _np.float64) for name in header])
