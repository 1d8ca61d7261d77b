#!/usr/bin/python3
"""The OpenFOAM side of the probe-mode exchange (coupling/PROTOCOL.md).

    foam_partner.py --exchange DIR --case SOLVED_CASE [--idle-timeout S]
    foam_partner.py --exchange DIR --still-water [--case-hash H]   (no OpenFOAM: tests)

It waits for the DEM's dem.hello in DIR, answers with partner.hello, then for
every request of that run samples the water velocity at the floes with
OpenFOAM's own sampling (postProcess with the probes function object, cellPoint
interpolation, on a private copy of the solved case: U = -grad(Phi) per unit
tow speed in the structure frame), turns it into the tank frame, computes the
drag of the water on each floe, 1/2 rho (C_d frontal + C_f bottom) |u - v| (u - v)
with the horizontal relative velocity, and writes the response. It exits when
the DEM writes `stop`, or after --idle-timeout seconds without a request.

The DEM starts it (coupling.partner = "spawn"), or it runs separately, e.g. on
another host sharing the exchange directory (coupling.partner = "external").
A restarted partner picks up the current run and answers its pending request.
"""
import argparse
import glob
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

VERSION = "icedem-exchange 1"


class ProtocolError(Exception):
    pass


def read_record(path, kind):
    with open(path) as f:
        lines = f.read().splitlines()
    if not lines or lines[0] != VERSION:
        raise ProtocolError(f"{path}:1: expected the header '{VERSION}', found {lines[:1]}")
    if lines[-1] != "end":
        raise ProtocolError(f"{path}:{len(lines)}: no final 'end': truncated or half-written")
    if lines[1] != f"kind {kind}":
        raise ProtocolError(f"{path}:2: '{lines[1]}', expected 'kind {kind}'")
    return lines[2:-1]


def field(lines, i, name):
    if not lines[i].startswith(name + " "):
        raise ProtocolError(f"line {i + 3}: expected '{name} ...', found '{lines[i]}'")
    return lines[i][len(name) + 1:]


def parse_request(path):
    lines = read_record(path, "request")
    r = {"run": field(lines, 0, "run"), "step": int(field(lines, 1, "step")),
         "time": float(field(lines, 2, "time"))}
    s = [float(x) for x in field(lines, 3, "structure").split()]
    r["structure"], r["speed"] = s[0:3], s[3]
    r["rho"], r["cd"], r["cf"] = (float(x) for x in field(lines, 4, "water").split())
    n = int(field(lines, 5, "floes"))
    r["floes"] = []
    for line in lines[6:6 + n]:
        v = line.split()
        if len(v) != 9:
            raise ProtocolError(f"{path}: floe line '{line}' has {len(v)} fields, expected 9")
        r["floes"].append({"id": int(v[0]), "x": [float(a) for a in v[1:4]], "v": [float(a) for a in v[4:7]],
                           "frontal": float(v[7]), "bottom": float(v[8])})
    if len(lines) != 6 + n:
        raise ProtocolError(f"{path}: {len(lines) - 6} floe lines for 'floes {n}'")
    return r


def write_atomic(path, text):
    with open(path + ".tmp", "w") as f:
        f.write(text)
    os.replace(path + ".tmp", path)


def g17(x):
    return f"{x:.17g}"


class OpenFoamSampler:
    """Samples U = -grad(Phi) (per unit tow speed, structure frame) at points."""

    def __init__(self, case):
        self.work = tempfile.mkdtemp(prefix="icedem-partner-")
        for part in ("system", "constant", "0"):
            shutil.copytree(os.path.join(case, part), os.path.join(self.work, part))
        self.env = dict(os.environ, WM_PROJECT_DIR=os.environ.get("WM_PROJECT_DIR", "/usr/share/openfoam"))

    def close(self):
        """Removes the private copy of the case (a mesh per run would fill /tmp in a sweep)."""
        shutil.rmtree(self.work, ignore_errors=True)

    def sample(self, points):
        body = "\n".join(f"            ({p[0]:.9g} {min(p[1], -1e-3):.9g} {p[2]:.9g})" for p in points)
        with open(os.path.join(self.work, "system", "exchangeProbes"), "w") as f:
            f.write("FoamFile { version 2.0; format ascii; class dictionary; object exchangeProbes; }\n"
                    "functions\n{\n    exchange\n    {\n        type probes;\n        libs (\"libsampling.so\");\n"
                    "        fields (gradPhi);\n        writeControl writeTime;\n"
                    "        interpolationScheme cellPoint;\n        probeLocations\n        (\n"
                    f"{body}\n        );\n    }}\n}}\n")
        shutil.rmtree(os.path.join(self.work, "postProcessing"), ignore_errors=True)
        proc = subprocess.run(["postProcess", "-case", self.work, "-dict", "system/exchangeProbes",
                               "-fields", "(gradPhi)", "-latestTime"], capture_output=True, text=True, env=self.env)
        out = os.path.join(self.work, "postProcessing", "exchange", "0", "gradPhi")
        if proc.returncode != 0 or not os.path.exists(out):
            raise RuntimeError(f"OpenFOAM sampling failed: {(proc.stdout + proc.stderr)[-800:]}")
        last = [l for l in open(out).read().splitlines() if l and not l.startswith("#")][-1]
        vecs = re.findall(r"\(([^)]*)\)", last)
        result = []
        for v in vecs:
            g = [float(a) for a in v.split()]
            # -1e300: the point is in no cell (inside the hull, or outside the domain)
            result.append(None if max(abs(a) for a in g) > 1e100 else [-a for a in g])
        return result


def water_velocity(sample, speed, point_struct, half_length):
    """Tank-frame water velocity from a per-unit-speed structure-frame sample."""
    if sample is None:
        # outside the domain: undisturbed; inside the hull: moving with it
        return [0.0, 0.0, 0.0] if abs(point_struct[0]) >= half_length else [speed, 0.0, 0.0]
    return [speed * (sample[0] + 1.0), speed * sample[1], speed * sample[2]]


def drag(rho, cd, cf, floe, u):
    rel = [u[0] - floe["v"][0], 0.0, u[2] - floe["v"][2]]  # horizontal relative velocity
    mag = math.hypot(rel[0], rel[2])
    k = 0.5 * rho * (cd * floe["frontal"] + cf * floe["bottom"]) * mag
    return [k * rel[0], 0.0, k * rel[2]]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--exchange", required=True, help="the exchange directory")
    ap.add_argument("--case", help="the solved OpenFOAM case (a coupling.cache_dir entry)")
    ap.add_argument("--still-water", action="store_true", help="no OpenFOAM: the water is at rest (tests)")
    ap.add_argument("--case-hash", help="with --still-water: the hash to announce")
    ap.add_argument("--idle-timeout", type=float, default=600.0)
    a = ap.parse_args()
    if not a.still_water and not a.case:
        sys.exit("foam_partner: --case SOLVED_CASE or --still-water")
    case_hash = a.case_hash or ""
    sampler, half_length = None, float("inf")
    if a.case:
        case_hash = open(os.path.join(a.case, "case.hash")).read().strip()
        sampler = OpenFoamSampler(a.case)
        m = re.search(r"^length (\S+)$", open(os.path.join(a.case, "case.inputs")).read(), re.M)
        half_length = float(m.group(1)) / 2
    # icedem stops a partner that does not see `stop` in time with SIGTERM: leave through finally
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(143))
    try:
        return serve(a, sampler, case_hash, half_length)
    finally:
        if sampler:
            sampler.close()


def serve(a, sampler, case_hash, half_length):
    """Answers the DEM's requests until `stop` or the idle timeout; the exit code."""
    d = a.exchange
    run, answered, idle_since = None, set(), time.monotonic()
    while True:
        if os.path.exists(os.path.join(d, "stop")):
            return 0
        hello = os.path.join(d, "dem.hello")
        if os.path.exists(hello):
            lines = read_record(hello, "hello")
            dem_run = field(lines, 1, "run")
            if dem_run != run:  # a new run (or our restart): announce ourselves for it
                run, answered = dem_run, set()
                write_atomic(os.path.join(d, "partner.hello"),
                             f"{VERSION}\nkind hello\nrole partner\nrun {run}\ncase {case_hash}\nend\n")
        requests = sorted(p for p in glob.glob(os.path.join(d, "request.*")) if not p.endswith(".tmp"))
        pending = [p for p in requests if p not in answered]
        if not pending:
            if time.monotonic() - idle_since > a.idle_timeout:
                print(f"foam_partner: no request in {a.idle_timeout:.0f} s; exiting", file=sys.stderr)
                return 1
            time.sleep(0.002)
            continue
        path = pending[0]
        answered.add(path)
        idle_since = time.monotonic()
        try:
            r = parse_request(path)
        except (ProtocolError, FileNotFoundError, ValueError) as e:
            print(f"foam_partner: refused {path}: {e}", file=sys.stderr)
            continue
        if r["run"] != run:
            print(f"foam_partner: refused {path}: stale (run {r['run']}, current {run})", file=sys.stderr)
            continue
        sx, speed = r["structure"], r["speed"]
        points = [[f["x"][0] - sx[0], f["x"][1], f["x"][2] - sx[2]] for f in r["floes"]]
        samples = sampler.sample(points) if sampler and points else [[-1.0, 0.0, 0.0]] * len(points)
        out = [f"{VERSION}", "kind response", f"run {run}", f"step {r['step']}", f"floes {len(r['floes'])}"]
        for f, p, s in zip(r["floes"], points, samples):
            u = [0.0, 0.0, 0.0] if a.still_water else water_velocity(s, speed, p, half_length)
            F = drag(r["rho"], r["cd"], r["cf"], f, u)
            out.append(f"{f['id']} " + " ".join(g17(x) for x in F + u))
        out.append("end")
        write_atomic(os.path.join(d, f"response.{r['step']:010d}"), "\n".join(out) + "\n")


if __name__ == "__main__":
    sys.exit(main())
