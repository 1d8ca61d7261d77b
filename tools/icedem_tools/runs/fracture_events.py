"""Summarise the joint breaks of one icedem run: count by mode, and where they
happened relative to the structure (distance ahead of its axis and sideways).

    fracture_events.py RUN.h5 [--json]

Prints one line (or a JSON object): breaks, by mode, breaks within 1 m of the
structure axis, median and max distance from the axis at the time of the break,
and the steps in which some element turned faster than 15 rad/s (a rocking
element; /diagnostics/max_angular_speed) with the fastest turn of the run.
"""
import json
import sys

import numpy as np

from . import results


# rad/s, as kRockingAngularSpeed in dem/core/constants.hpp: a 0.15 m element turning
# this fast moves its edge at over 1 m/s, 15 times the tow speed; floes in the
# channel turn at a few rad/s at most
ROCKING_RAD_S = 15.0


def summarise(path):
    run = results.load_run(path)
    events, t, pos = run.events, run["/load/time"], run["/structure/position"]
    w = run["/diagnostics/max_angular_speed"] if "/diagnostics/max_angular_speed" in run else np.zeros(0)
    out = {"breaks": int(len(events))}
    out["rocking_steps"] = int(np.sum(w > ROCKING_RAD_S))
    out["max_angular_speed"] = float(np.max(w)) if len(w) else float("nan")
    # by mode, every mode the file names (spaces and hyphens as "_")
    for name in run.modes.values():
        out[results.mode_key(name)] = int(np.sum(events["mode_name"] == name)) if len(events) else 0
    if len(events) == 0:
        out.update(within_1m=0, median_distance_m=float("nan"), max_distance_m=float("nan"))
        return out
    # structure axis at each break time (nearest recorded step)
    i = np.clip(np.searchsorted(t, events["time"]), 0, len(t) - 1)
    dx = events["x"] - pos[i, 0]
    dz = events["z"] - pos[i, 2]
    r = np.hypot(dx, dz)
    out.update(within_1m=int(np.sum(r <= 1.0)), median_distance_m=float(np.median(r)),
               max_distance_m=float(np.max(r)))
    return out


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    files = [x for x in argv if x != "--json"]
    if len(files) != 1:
        sys.exit(__doc__)
    s = summarise(files[0])
    if "--json" in argv:
        print(json.dumps(s))
    else:
        print(" ".join(f"{k}={v:.3g}" if isinstance(v, float) else f"{k}={v}" for k, v in s.items()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
