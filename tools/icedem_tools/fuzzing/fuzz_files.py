"""The fuzzer's classes on files (scripts/fuzz): the outputs of every command aimed at what a user has,
checkpoints tampered with or damaged before a resume, and killed runs whose output was torn.

- outputs: every command that writes (run, resume, stl, flow, foam-case, calibrate --write,
  scripts/layout_from_photo) with an output naming its scenario, the layout file, another run's output,
  another run's checkpoint, a killed run's output (without --restart), a directory or an empty name.
  Each must be refused (exit 2), and every one of those files must be byte for byte as before.
- tamper: a killed run's checkpoint changed the way an accident would (a number of the stored scenario
  edited, a value of a recorded row or of the state's records changed, a bit flipped anywhere, the file
  cut short). `icedem resume` must refuse it (exit 2), or, where the change touched nothing the run reads
  (a flip in bytes HDF5 leaves unused), end bit for bit as the uninterrupted run. `icedem info` must not
  crash on it.

- torn: a killed run's output cut short (inside HDF5's signature or anywhere), zeroed in part or lost,
  its checkpoint whole. `icedem info` must say it is resumable (exit 0), `icedem run -o` on it must be
  refused (exit 2) touching nothing, and `icedem resume` must end bit for bit as the uninterrupted run,
  the torn file kept aside (OUT.damaged) byte for byte.

Each yields (problem, is severe, output tail); severe: a crash, a hang, a file overwritten, a tampered
checkpoint continued, a resumable run lost.
"""
import hashlib
import os
import random
import shutil
import signal
import subprocess
import time

import h5py
import numpy as np

from ..runs.spec import ROOT

# the exit codes docs/user/commands.md lists (dem/core/errors.hpp); any other is a finding
DOCUMENTED_EXITS = {0, 2, 3, 4, 5, 130, 143}


def run(cmd, timeout):
    """(exit code or None for a hang, output text): the fuzzer's one way of running a command"""
    try:
        p = subprocess.run(cmd, capture_output=True, timeout=timeout, text=True, errors="replace")
        return p.returncode, p.stdout + p.stderr
    except subprocess.TimeoutExpired as e:
        return None, (e.stdout or b"").decode(errors="replace") if isinstance(e.stdout, bytes) else (e.stdout or "")


def digest(path):
    """A file's SHA-256, or what stands in its place (a directory's listing, "missing")."""
    if os.path.isdir(path):
        return "directory " + ",".join(sorted(os.listdir(path)))
    if not os.path.exists(path):
        return "missing"
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def surge(path):
    with h5py.File(path, "r") as f:
        return f["load/surge"][:].tobytes(), f["load/time"][:].tobytes()


class Fixture:
    """What the file classes work on, made once in `work`: a complete run's output (another run's),
    a killed run's output and checkpoint, and the uninterrupted run the killed one should become."""

    def __init__(self, icedem, work, timeout):
        self.icedem, self.work, self.timeout = icedem, work, timeout
        self.scenario = os.path.join(ROOT, "scenarios", "examples", "short_tow.toml")
        self.options = ["--set", "output.checkpoint_interval=2", "--set", "time.duration=20"]
        os.makedirs(work, exist_ok=True)
        self.other = os.path.join(work, "other.h5")
        code, text = run([icedem, "run", self.scenario, "-q", "-o", self.other, "--set", "time.duration=1"], timeout)
        if code != 0:
            raise RuntimeError(f"fuzz: the fixture's run failed (exit {code}): {text[-300:]}")
        self.full = os.path.join(work, "full.h5")
        code, text = run([icedem, "run", self.scenario, "-q", "-o", self.full, *self.options], 4 * timeout)
        if code != 0:
            raise RuntimeError(f"fuzz: the fixture's full run failed (exit {code}): {text[-300:]}")
        self.full_surge = surge(self.full)
        self.killed = os.path.join(work, "killed.h5")
        self._kill_after_checkpoint(self.killed, 6.0)
        self.checkpoint_bytes = open(self.killed + ".checkpoint", "rb").read()
        self.output_bytes = open(self.killed, "rb").read()
        self.directory = os.path.join(work, "a_directory")
        os.makedirs(self.directory, exist_ok=True)

    def _kill_after_checkpoint(self, name, t):
        proc = subprocess.Popen([self.icedem, "run", self.scenario, "-q", "-o", name, *self.options],
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        checkpoint, deadline = name + ".checkpoint", time.time() + 4 * self.timeout
        while proc.poll() is None and time.time() < deadline:
            try:
                with h5py.File(checkpoint, "r") as f:
                    if f["load/time"][-1] >= t - 1e-9:
                        break
            except (OSError, KeyError, IndexError):
                pass
            time.sleep(0.01)
        proc.send_signal(signal.SIGKILL)
        proc.wait()
        if not os.path.exists(checkpoint):
            raise RuntimeError("fuzz: the fixture's killed run left no checkpoint")


def output_attempts(fx, scenario, layout):
    """(what, command) of outputs that must be refused, for an accepted `scenario`."""
    icedem, other, chk, d = fx.icedem, fx.other, fx.killed + ".checkpoint", fx.directory
    short = ["--set", "time.duration=0.1"]
    attempts = [
        ("run -o the scenario", [icedem, "run", scenario, "-q", "-o", scenario, *short]),
        ("run -o another run's checkpoint", [icedem, "run", scenario, "-q", "-o", chk, *short]),
        ("run -o a killed run's output", [icedem, "run", scenario, "-q", "-o", fx.killed, *short]),
        ("run --summary-json another run's output", [icedem, "run", scenario, "-q", "-o",
                                                      os.path.join(fx.work, "new.h5"), "--summary-json", other, *short]),
        ("run -o a directory", [icedem, "run", scenario, "-q", "-o", d, *short]),
        ("run -o ''", [icedem, "run", scenario, "-q", "-o", "", *short]),
        ("resume --summary-json the checkpoint", [icedem, "resume", fx.killed, "-q", "--summary-json", chk]),
        ("resume --summary-json another run's output", [icedem, "resume", fx.killed, "-q", "--summary-json", other]),
        ("stl -o the scenario", [icedem, "stl", scenario, "-o", scenario]),
        ("stl -o another run's output", [icedem, "stl", scenario, "-o", other]),
        ("stl -o another run's checkpoint", [icedem, "stl", scenario, "-o", chk]),
        ("stl -o a directory", [icedem, "stl", scenario, "-o", d]),
        ("stl -o ''", [icedem, "stl", scenario, "-o", ""]),
        ("flow -o the scenario", [icedem, "flow", scenario, "-o", scenario]),
        ("flow -o another run's output", [icedem, "flow", scenario, "-o", other]),
        ("foam-case -o the scenario", [icedem, "foam-case", scenario, "-o", scenario]),
        ("foam-case -o another run's output", [icedem, "foam-case", scenario, "-o", other]),
        ("calibrate --write the scenario", [icedem, "calibrate", scenario, "--write", scenario]),
    ]
    if layout:
        attempts += [("stl -o the layout file", [icedem, "stl", scenario, "-o", layout]),
                     ("flow -o the layout file", [icedem, "flow", scenario, "-o", layout]),
                     ("run -o the layout file", [icedem, "run", scenario, "-q", "-o", layout, *short])]
    tool = os.path.join(ROOT, "scripts", "layout_from_photo")
    photo = os.path.join(ROOT, "docs", "photo_layout", "angled_overlay.jpg")
    attempts += [("layout_from_photo -o another run's output", [tool, photo, "-o", other, "--metres-per-pixel", "0.01"]),
                 ("layout_from_photo --overlay the scenario",
                  [tool, photo, "-o", os.path.join(fx.work, "l.csv"), "--overlay", scenario,
                   "--metres-per-pixel", "0.01"])]
    return attempts


def layout_of(scenario):
    """The layout file a scenario names, absolute, or None."""
    for line in open(scenario, encoding="latin-1"):
        s = line.split("#")[0].strip()
        if s.startswith("file") and "=" in s:
            name = s.split("=", 1)[1].strip().strip('"')
            return name if os.path.isabs(name) else os.path.join(os.path.dirname(scenario), name)
    return None


def output_problems(fx, scenario, rng, count):
    """`count` attempts of output_attempts on `scenario`: each refused, nothing a user has touched."""
    layout = layout_of(scenario)
    layout = layout if layout and os.path.isfile(layout) else None
    kept = [scenario, fx.other, fx.killed, fx.killed + ".checkpoint", fx.directory] + ([layout] if layout else [])
    attempts = output_attempts(fx, scenario, layout)
    for what, cmd in rng.sample(attempts, min(count, len(attempts))):
        before = {p: digest(p) for p in kept}
        code, text = run(cmd, 4 * fx.timeout)
        changed = [os.path.basename(p) for p in kept if digest(p) != before[p]]
        if changed:
            yield f"{what}: overwrote {', '.join(changed)} (exit {code})", True, text
            return
        if code is None or code < 0:
            yield f"{what}: crash or hang (exit {code})", True, text
        elif code not in DOCUMENTED_EXITS:
            yield f"{what}: undocumented exit {code}", False, text
        elif code != 2:
            yield f"{what}: exit {code}, expected 2 (refused)", False, text
        for extra in ("new.h5", "new.h5.checkpoint", "l.csv", "l.png"):
            p = os.path.join(fx.work, extra)
            if os.path.exists(p):
                os.remove(p)


# --- checkpoints tampered with ---------------------------------------------------------------------

def _edit_scenario(path, rng):
    with h5py.File(path, "r+") as f:
        text = f["meta"].attrs["scenario"]
        spots = [i for i, c in enumerate(text) if c.isdigit()]
        i = rng.choice(spots)
        f["meta"].attrs["scenario"] = text[:i] + str((int(text[i]) + rng.randint(1, 9)) % 10) + text[i + 1:]
    return "a digit of the stored scenario changed"


def _edit_value(path, rng):
    with h5py.File(path, "r+") as f:
        sets = []
        f.visititems(lambda n, o: sets.append(n) if isinstance(o, h5py.Dataset) and o.size > 0
                     and (n.startswith("load/") or n.startswith("checkpoint/")) else None)
        name = rng.choice(sets)
        d = f[name]
        flat = d[...].reshape(-1).view(np.uint8).copy() if d.dtype.kind not in "V" else None
        if flat is None or flat.size == 0:
            return "nothing (a compound dataset)"
        i = rng.randrange(flat.size)
        flat[i] ^= 1 << rng.randrange(8)
        d[...] = flat.view(d.dtype).reshape(d.shape)
    return f"a bit of {name} changed"


def _flip_bit(path, rng):
    data = bytearray(open(path, "rb").read())
    i = rng.randrange(len(data))
    data[i] ^= 1 << rng.randrange(8)
    open(path, "wb").write(data)
    return f"a bit flipped at byte {i}"


def _truncate(path, rng):
    data = open(path, "rb").read()
    n = rng.randrange(len(data))
    open(path, "wb").write(data[:n])
    return f"cut to {n} bytes"


TAMPERS = [_edit_scenario, _edit_value, _flip_bit, _flip_bit, _truncate]


def tamper_problem(fx, rng, index):
    """One checkpoint of the killed run tampered with and resumed."""
    name = os.path.join(fx.work, f"tampered{index}.h5")
    for p in (name, name + ".checkpoint"):
        if os.path.exists(p):
            os.remove(p)
    open(name + ".checkpoint", "wb").write(fx.checkpoint_bytes)
    open(name, "wb").write(fx.output_bytes)
    how = rng.choice(TAMPERS)(name + ".checkpoint", rng)
    tampered = open(name + ".checkpoint", "rb").read()
    changed = tampered != fx.checkpoint_bytes
    code, info_text = run([fx.icedem, "info", name], fx.timeout)
    problem = None
    if code is None or code < 0 or code not in (0, 2):
        problem = (f"{how}: icedem info exit {code}", code is None or code < 0, info_text)
    code, text = run([fx.icedem, "resume", name, "-q"], 4 * fx.timeout)
    if code is None or code < 0:
        problem = (f"{how}: resume crashed or hung (exit {code})", True, text)
    elif code not in DOCUMENTED_EXITS:
        problem = (f"{how}: resume exit {code}, undocumented", False, text)
    elif code == 0:
        same = os.path.exists(name) and surge(name) == fx.full_surge
        if not same:
            problem = (f"{how}: a tampered checkpoint was continued (exit 0) to other loads", True, text)
    elif code == 2 and changed and open(name + ".checkpoint", "rb").read() != tampered:
        problem = (f"{how}: the refused checkpoint was changed", True, text)
    for p in (name, name + ".checkpoint"):
        if os.path.exists(p):
            os.remove(p)
    return problem, code, how


# --- a killed run's output torn, its checkpoint whole -------------------------------------------------

def _tear(path, rng):
    data = open(path, "rb").read()
    how = rng.choice(["cut", "cut in the signature", "zeroed", "lost"])
    if how == "lost":
        os.remove(path)
        return "the output deleted"
    if how == "cut in the signature":
        n = rng.randrange(1, 8)
        open(path, "wb").write(data[:n])
        return f"the output cut to {n} bytes (inside HDF5's signature)"
    if how == "cut":
        n = rng.randrange(len(data))
        open(path, "wb").write(data[:n])
        return f"the output cut to {n} bytes"
    i = rng.randrange(len(data))
    n = rng.randint(1, 65536)
    open(path, "wb").write(data[:i] + bytes(min(n, len(data) - i)) + data[i + n:])
    return f"{n} bytes of the output zeroed from byte {i}"


def torn_problem(fx, rng, index):
    """The killed run's output torn (cut short, zeroed in part, or lost), its checkpoint whole: `icedem
    info` says it is resumable (exit 0), `run -o` on it is refused (exit 2) touching nothing, and `icedem
    resume` ends bit for bit as the uninterrupted run, the torn file kept aside byte for byte.
    (problem or None, is severe, output), how it was torn."""
    name = os.path.join(fx.work, f"torn{index}.h5")
    for p in (name, name + ".checkpoint", name + ".damaged"):
        if os.path.exists(p):
            os.remove(p)
    open(name + ".checkpoint", "wb").write(fx.checkpoint_bytes)
    open(name, "wb").write(fx.output_bytes)
    how = _tear(name, rng)
    torn = open(name, "rb").read() if os.path.exists(name) else None
    problem = None
    code, text = run([fx.icedem, "info", name], fx.timeout)
    said_torn = code == 0 and ": torn, it cannot be read" in text  # else still readable (zeroed where nothing is read) or lost
    if code is None or code < 0:
        problem = (f"{how}: icedem info crashed or hung (exit {code})", True, text)
    elif code != 0 or "resumable from" not in text:
        problem = (f"{how}: icedem info exit {code}, not saying it is resumable", False, text)
    if not problem:
        code, text = run([fx.icedem, "run", fx.scenario, "-q", "-o", name, *fx.options], 4 * fx.timeout)
        now = open(name, "rb").read() if os.path.exists(name) else None
        if code != 2 or now != torn or open(name + ".checkpoint", "rb").read() != fx.checkpoint_bytes:
            problem = (f"{how}: run -o on the killed run: exit {code}, expected 2 touching nothing",
                       code is None or code < 0 or now != torn, text)
    if not problem:
        code, text = run([fx.icedem, "resume", name, "-q"], 4 * fx.timeout)
        kept = name + ".damaged"
        if code is None or code < 0:
            problem = (f"{how}: resume crashed or hung (exit {code})", True, text)
        elif code != 0:
            problem = (f"{how}: resume exit {code}: a resumable run lost", True, text)
        elif surge(name) != fx.full_surge:
            problem = (f"{how}: resumed to other loads than the uninterrupted run's", True, text)
        elif said_torn and (not os.path.exists(kept) or open(kept, "rb").read() != torn):
            problem = (f"{how}: the torn output was not kept aside as it was", True, text)
    for p in (name, name + ".checkpoint", name + ".damaged"):
        if os.path.exists(p):
            os.remove(p)
    return problem, how


def cleanup(fx):
    shutil.rmtree(fx.work, ignore_errors=True)


if __name__ == "__main__":  # a quick look: python3 -m icedem_tools.fuzzing.fuzz_files
    import sys
    import tempfile
    fx = Fixture(os.path.join(ROOT, "build", "dem", "icedem"), tempfile.mkdtemp(), 30.0)
    r = random.Random(1)
    for i in range(int(sys.argv[1]) if len(sys.argv) > 1 else 10):
        print(tamper_problem(fx, r, i))
