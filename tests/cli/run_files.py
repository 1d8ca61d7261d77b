"""What the resume tests compare of a run's files: every dataset (as bytes) with the /stats
attributes and the status, and the time of its checkpoint."""
import h5py
import numpy as np


def contents(path):
    """Every dataset (as bytes) and the /stats attributes of an output file."""
    out = {}
    with h5py.File(path, "r") as f:
        f.visititems(lambda n, o: out.__setitem__(n, np.asarray(o[()]).tobytes()) if isinstance(o, h5py.Dataset) else None)
        # the run's statistics, all but its own run time
        # (a number, or what a run without them says instead: "the structure never touched the ice")
        out["/stats"] = sorted((k, v.decode() if isinstance(v, bytes) else v if isinstance(v, str) else float(v))
                               for k, v in f["stats"].attrs.items() if not k.endswith("time_s"))
        out["/meta/status"] = f["meta"].attrs["status"]
    return out


def checkpoint_time(path):
    """The simulated time of a checkpoint file, -1 if there is none (or it is torn)."""
    try:
        with h5py.File(path, "r") as f:
            # the State's time, a record of one double as the build holds it (dem/output/checkpoint.cpp)
            return float(np.frombuffer(f["checkpoint/state/time"][()].tobytes(), dtype=np.float64)[0])
    except (OSError, KeyError):
        return -1.0
