"""What a run wrote, read into numpy arrays with their units: the HDF5 file (`load_run`) and the
summary (`load_summary`). Every path and key is listed in docs/user/output.md, which icedem
generates from its output schema. For a notebook:

    import sys; sys.path.insert(0, "tools")
    from icedem_tools.runs import results
    run = results.load_run("run.h5")
    t, surge = run["/load/time"], run["/load/surge"]      # arrays, with .unit and .description
    run.events["mode_name"]                                # breaks, modes by name
"""
import dataclasses
import json
import tomllib

import h5py
import numpy as np


class Quantity(np.ndarray):
    """A numpy array that carries the unit and description of the dataset it was read from."""

    def __new__(cls, values, unit="", description=""):
        q = np.asarray(values).view(cls)
        q.unit, q.description = unit, description
        return q

    def __array_finalize__(self, obj):
        self.unit = getattr(obj, "unit", "")
        self.description = getattr(obj, "description", "")


def code_names(attribute):
    """{code: name} from an attribute like "0 compression, 1 shear" (/fracture/events mode_names
    and mechanism_names): icedem names its codes in the file, the tools do not repeat them."""
    out = {}
    for part in str(attribute or "").split(","):
        code, _, name = part.strip().partition(" ")
        if code.lstrip("-").isdigit():
            out[int(code)] = name
    return out


def mode_key(name):
    """icedem names failure modes and mechanisms like "in-plane bending"; tables and keys use
    in_plane_bending."""
    return name.replace("-", "_").replace(" ", "_")


def _text(value):
    return value.decode() if isinstance(value, bytes) else value


@dataclasses.dataclass
class RunFile:
    path: str
    meta: dict       # /meta attributes: status, scenario (resolved TOML), seed, version, ...
    stats: dict      # /stats attributes: the summary's statistics
    layout: dict     # /layout attributes
    datasets: dict   # path -> Quantity, every dataset read
    events: np.ndarray  # /fracture/events rows, with mode_name and mechanism_name added
    modes: dict         # failure mode code -> name, every mode icedem has
    mechanisms: dict    # break mechanism code -> name

    def __getitem__(self, path):
        return self.datasets[path]

    def __contains__(self, path):
        return path in self.datasets

    @property
    def scenario(self):
        """The resolved scenario the run was made from (every key with its value), as a dict."""
        return tomllib.loads(self.meta.get("scenario", ""))

    def first_positions(self):
        """Every body's position (nb x 3, m) at the first snapshot, which stores every body in the
        run then (snapshot_field), or None when the file holds no snapshot."""
        with h5py.File(self.path, "r") as f:
            if "/snapshots/end_row" not in f or len(f["/snapshots/end_row"]) == 0:
                return None
            rows = int(f["/snapshots/end_row"][0])
            position = np.full((len(f["/bodies/floe_id"]), 3), np.nan)
            position[f["/snapshots/rows/body"][:rows]] = f["/snapshots/rows/position"][:rows]
            return position

    @property
    def snapshot_count(self):
        """How many snapshots the file holds."""
        return len(self.datasets.get("/snapshots/time", ()))


ABSENT = 2  # /snapshots/rows/awake of a body not in the run: gone (split), or born later
LEFT = 3  # /snapshots/rows/awake of a floe left behind the structure (activation.leave_behind): ice still there


def snapshot_field(f):
    """The snapshots of an open output file `f` (h5py) as full fields: position (k x nb x 3, m),
    orientation (k x nb x 4, w x y z) and awake (k x nb). The file stores, per snapshot, only the
    bodies whose pose or awake flag changed since the snapshot before (the first stores every
    body): each body keeps its latest row. A body not in the run at a snapshot has awake 2: one
    born later (a piece of a floe that splits, /bodies/born) with no row yet, at the origin
    unrotated, or one gone (split into pieces), at its last pose; a floe left behind the structure
    (activation.leave_behind) has awake 3 where it left the run."""
    k = len(f["/snapshots/time"])
    nb = len(f["/bodies/floe_id"])
    end = f["/snapshots/end_row"][:k]
    rows = int(end[-1]) if k else 0
    body = f["/snapshots/rows/body"][:rows]
    pos, ori, awk = f["/snapshots/rows/position"][:rows], f["/snapshots/rows/orientation"][:rows], f["/snapshots/rows/awake"][:rows]
    position, orientation, awake = np.zeros((k, nb, 3)), np.zeros((k, nb, 4)), np.zeros((k, nb), dtype=np.uint8)
    p, o, a = np.zeros((nb, 3)), np.tile([1.0, 0.0, 0.0, 0.0], (nb, 1)), np.full(nb, ABSENT, dtype=np.uint8)
    start = 0
    for i in range(k):
        r = slice(start, int(end[i]))
        p[body[r]], o[body[r]], a[body[r]] = pos[r], ori[r], awk[r]
        position[i], orientation[i], awake[i] = p, o, a
        start = int(end[i])
    return position, orientation, awake


def load_run(path, snapshots=False):
    """Every dataset of the run's HDF5 file as a Quantity (the snapshots' full fields as
    /snapshots/position, orientation and awake, k x nb, only if `snapshots`: they are the large
    part; their times always), its attributes, and its breaks with their names."""
    datasets = {}
    with h5py.File(path, "r") as f:
        def visit(name, obj):
            if not isinstance(obj, h5py.Dataset) or name == "fracture/events":
                return
            if name.startswith("snapshots/") and name != "snapshots/time" and not snapshots:
                return
            datasets["/" + name] = Quantity(obj[()], _text(obj.attrs.get("units", "")),
                                            _text(obj.attrs.get("description", "")))
        f.visititems(visit)
        if snapshots and "/snapshots/end_row" in f:
            position, orientation, awake = snapshot_field(f)
            rows = {n: f["/snapshots/rows/" + n] for n in ("position", "orientation", "awake")}
            for name, value in (("position", position), ("orientation", orientation), ("awake", awake)):
                datasets["/snapshots/" + name] = Quantity(value, _text(rows[name].attrs.get("units", "")),
                                                          _text(rows[name].attrs.get("description", "")))
        attrs = {g: {k: _text(v) for k, v in f[g].attrs.items()} if g in f else {} for g in ("/meta", "/stats", "/layout")}
        events, modes, mechanisms = np.zeros(0), {}, {}
        if "/fracture/events" in f:
            ev = f["/fracture/events"]
            rows = ev[()]
            modes, mechanisms = code_names(_text(ev.attrs.get("mode_names"))), code_names(_text(ev.attrs.get("mechanism_names")))
            names = [(n, rows.dtype[n]) for n in rows.dtype.names] + [("mode_name", "U32"), ("mechanism_name", "U32")]
            events = np.zeros(len(rows), dtype=names)
            for n in rows.dtype.names:
                events[n] = rows[n]
            events["mode_name"] = [modes.get(int(c), "") for c in rows["mode"]] if len(rows) else []
            if "mechanism" in rows.dtype.names and len(rows):
                events["mechanism_name"] = [mechanisms.get(int(c), "") for c in rows["mechanism"]]
    return RunFile(path, attrs["/meta"], attrs["/stats"], attrs["/layout"], datasets, events, modes, mechanisms)


def status(path):
    """The run's /meta status ("complete", "running", "failed", ...), or None when the file is
    missing or unreadable: cheap, it reads no dataset."""
    try:
        with h5py.File(path, "r") as f:
            return _text(f["/meta"].attrs["status"])
    except (OSError, KeyError):
        return None


def load_summary(path):
    """The summary JSON of a run (keys in docs/user/output.md; null statistics as None)."""
    with open(path) as f:
        return json.load(f)
