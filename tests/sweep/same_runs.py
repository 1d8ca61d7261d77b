#!/usr/bin/python3
"""Whether two sweep directories hold the same runs, every dataset byte for byte: the Slurm
tests compare a faulted sweep with the same sweep run without faults.

    same_runs.py WHOLE OTHER COUNT      exit 0 if WHOLE's COUNT runs are all equal in OTHER
"""
import glob
import os
import sys

import h5py
import numpy as np


def datasets(path):
    """Every dataset of an HDF5 file, as bytes, by path."""
    out = {}
    with h5py.File(path, "r") as f:
        f.visititems(lambda n, o: out.__setitem__(n, np.asarray(o[()]).tobytes()) if isinstance(o, h5py.Dataset) else None)
    return out


def main(whole, other, count):
    runs = sorted(os.path.relpath(p, whole) for p in glob.glob(os.path.join(whole, "*", "*", "*", "run.h5")))
    assert len(runs) == count, runs
    for r in runs:
        assert datasets(os.path.join(whole, r)) == datasets(os.path.join(other, r)), r
    print(f"{count} runs of {other} equal those of {whole}, bit for bit")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], int(sys.argv[3]))
