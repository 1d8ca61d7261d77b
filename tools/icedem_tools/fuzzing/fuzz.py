"""Fuzz icedem's input handling: mutated scenario and layout files through
`icedem check`, and samples of the accepted scenarios through a short `icedem run`,
through runs whose outputs name their inputs, and through runs stopped by a signal.

    scripts/fuzz [--mutations N] [--runs K] [--guards G] [--signals S] [--outputs O] [--tampers T]
                 [--torn R] [--scenes C] [--walls W] [--seed S] [--icedem PATH] [--out DIR] [--timeout S]

Each mutation takes a shipped scenario (scenarios/**/*.toml) or layout file
(scenarios/examples/*.csv, and a JSON version of it) and changes it the way a user's
mistake or a damaged file would: a number replaced by an extreme (1e308, -1e308, nan,
inf, 0, -1, 1e-300, a 30-digit integer), a value of the wrong type, a key misspelt,
nested thousands of levels deep or megabytes long, a line deleted, duplicated or
truncated, random bytes, brackets nested 100,000 deep, a floe count in the millions.

What counts:
- check: exit 0 (accepted) or 2 (refused) with a message of at most 2 kB that names
  an input file (the mutated one, or the layout file a changed channel no longer
  holds) or the --set; anything else is a finding;
- run (--runs of the accepted scenarios, 2 s of simulated time): exit 0 or 3 (a
  numerical blow-up, named) with the output file readable and not "running"; a
  blow-up (3) of a scene `check` accepted without a warning is a finding;
- guard (--guards of the accepted scenarios): a run whose `-o` or `--summary-json`
  names the scenario, or whose `--summary-json` names its own `-o`, must be refused
  (exit 2) with every input byte for byte as before;
- signal (--signals of the accepted scenarios, 30 s of simulated time): SIGINT, SIGTERM
  or SIGKILL after 0-2 s, during set-up or the run: exit 130 / 143 (or the run's own
  code if it ended first; or death by the signal if it came before icedem started and
  nothing was written), never a 0-byte output file, a file closed with a status
  (SIGINT, SIGTERM) or one `icedem info` reads (SIGKILL);
- outputs (--outputs of the accepted scenarios): every command that writes (run, resume, stl, flow,
  foam-case, calibrate, scripts/layout_from_photo) with an output naming the scenario, its layout file,
  another run's output or checkpoint, a directory or an empty name: refused (exit 2), and every one of
  those files byte for byte as before (tools/icedem_tools/fuzzing/fuzz_files.py);
- tamper (--tampers): a killed run's checkpoint with a digit of its stored scenario changed, a bit of a
  recorded row or of the state's records changed, a bit flipped anywhere or the file cut short:
  `resume` refuses it (exit 2) or, where the change touched nothing the run reads, ends bit for bit as
  the uninterrupted run; continuing to other loads is severe;
- torn (--torn): a killed run's output cut short, zeroed in part or deleted, its checkpoint whole: `info`
  says it is resumable, `run -o` on it is refused touching nothing, and `resume` ends bit for bit as the
  uninterrupted run, the torn file kept aside; a resumable run lost is severe;
- scenes (--scenes): a shipped scenario with one inconsistency (a quoted dotted key, a two-line --set,
  a seed past its range, the structure outside the tank, wider than it, above or under the ice, standing
  still, out of reach of the ice, or its keel below the bottom, an unpackable concentration, elements as
  wide as the floes or not dividing them, unreached floes kept out with sleeping off, intervals below the step, a plate loaded past its
  freeboard): `check` refuses or warns as each class should, naming the key (fuzz_scenes.py);
- wall (--walls): the short tow driven into its channel's end wall: `check` warns, the summary names
  the squeeze and the statistics end before it;
- a crash (a signal), an undocumented exit code, a hang (--timeout), a traceback-like
  message (HDF5 or JSON library text) is a finding. Findings are written to OUT
  (default a temporary directory) with the input that caused them.

Exit code: 0 with no crash and no hang, 1 otherwise (other findings are reported).
"""
import argparse
import glob
import json
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile

from ..runs.spec import ROOT
from . import fuzz_files, fuzz_scenes
from ..runs import results
from .fuzz_files import digest, run
EXTREMES = ["1e308", "-1e308", "nan", "inf", "-inf", "0", "-1", "1e-300", "123456789012345678901234567890",
            "1e309", "-0", "0.0000001", "1e6"]
NAMED_INPUT = re.compile(r"\S+\.(toml|csv|json)(:\d+)?: |--set ")
LIBRARY_TEXT = re.compile(r"HDF5-DIAG|json\.exception|terminate called|std::|basic_string|Segmentation")


def numbers(text):
    return list(re.finditer(r"(?<![\w.])-?\d+(\.\d+)?([eE][-+]?\d+)?(?![\w.])", text))


def mutate_scenario(text, rng):
    """One mutation of a TOML scenario."""
    lines = text.split("\n")
    kind = rng.choice(["number", "number", "number", "type", "typo", "deep_key", "deep_header", "long_key",
                       "long_value", "delete", "duplicate", "truncate", "bytes", "brackets", "floes", "section"])
    if kind == "number" and numbers(text):
        m = rng.choice(numbers(text))
        return kind, text[:m.start()] + rng.choice(EXTREMES) + text[m.end():]
    if kind == "type":
        keyed = [i for i, l in enumerate(lines) if "=" in l and not l.lstrip().startswith("#")]
        if keyed:
            i = rng.choice(keyed)
            key = lines[i].split("=")[0]
            lines[i] = key + "= " + rng.choice(['"text"', "[1, 2]", "true", "{a = 1}", "[[1, 2], [3]]", '""'])
            return kind, "\n".join(lines)
    if kind == "typo":
        keyed = [i for i, l in enumerate(lines) if "=" in l and not l.lstrip().startswith("#")]
        if keyed:
            i = rng.choice(keyed)
            key, _, value = lines[i].partition("=")
            k = list(key.strip())
            j = rng.randrange(len(k))
            k[j] = rng.choice("abcdefghijklmnopqrstuvwxyz_")
            lines[i] = "".join(k) + " =" + value
            return kind, "\n".join(lines)
    if kind == "deep_key":
        return kind, text + "\n" + ".".join(["a"] * rng.choice([20, 1000, 31000])) + " = 1\n"
    if kind == "deep_header":
        return kind, "[" + ".".join(["a"] * rng.choice([20, 31000])) + "]\nb = 1\n" + text
    if kind == "long_key":
        return kind, text + "\n" + "k" * rng.choice([1000, 900000]) + " = 1\n"
    if kind == "long_value":
        return kind, text + '\n[ice]\nfloe_size = "' + "x" * rng.choice([1000, 900000]) + '"\n'
    if kind == "delete" and len(lines) > 1:
        del lines[rng.randrange(len(lines))]
        return kind, "\n".join(lines)
    if kind == "duplicate" and lines:
        i = rng.randrange(len(lines))
        lines.insert(i, lines[i])
        return kind, "\n".join(lines)
    if kind == "truncate" and text:
        return kind, text[:rng.randrange(len(text))]
    if kind == "bytes":
        b = bytearray(text.encode())
        for _ in range(rng.randint(1, 10)):
            b[rng.randrange(len(b))] = rng.randrange(256)
        return kind, b.decode("latin-1")
    if kind == "brackets":
        n = rng.choice([50, 100000])
        return kind, text + "\n[structure]\nprofile = " + "[" * n + "]" * n + "\n"
    if kind == "floes":
        return kind, text + "\n[ice]\nfloe_size = " + rng.choice(["1e-6", "0.001", "1e-12"]) + "\n"
    if kind == "section":
        return kind, text + "\n[" + rng.choice(["ice", "tim", "a.b", "solver.x", ""]) + "]\n"
    return "number", text.replace("0", rng.choice(EXTREMES), 1)


def mutate_csv(text, rng):
    lines = text.split("\n")
    data = [i for i, l in enumerate(lines) if l and not l.startswith("#") and not l.startswith("x,")]
    kind = rng.choice(["number", "number", "yaw", "polygon", "fields", "quote", "delete", "bytes", "header"])
    if kind in ("number", "yaw") and data:
        i = rng.choice(data)
        fields = lines[i].split(",", 3)
        j = 2 if kind == "yaw" else rng.randrange(2)
        fields[j] = rng.choice(EXTREMES)
        lines[i] = ",".join(fields)
    elif kind == "polygon" and data:
        i = rng.choice(data)
        fields = lines[i].split(",", 3)
        fields[3] = rng.choice(['"0 0; 1 1"', '"0 0; 1 0; 2 0"', '"0 0; 1 0; 0 1; 1 1"', '""', '"a b; c d; e f"',
                                '"' + "; ".join(["0 0"] * 1000) + '"'])
        lines[i] = ",".join(fields)
    elif kind == "fields" and data:
        i = rng.choice(data)
        lines[i] = lines[i] + ",extra" if rng.random() < 0.5 else lines[i].split(",")[0]
    elif kind == "quote" and data:
        i = rng.choice(data)
        lines[i] = lines[i].replace('"', "", 1)
    elif kind == "delete" and data:
        del lines[rng.choice(data)]
    elif kind == "header":
        lines = [l.replace("yaw_deg", rng.choice(["yaw", "", "x"])) for l in lines]
    else:
        b = bytearray(text.encode())
        for _ in range(rng.randint(1, 10)):
            b[rng.randrange(len(b))] = rng.randrange(256)
        return "bytes", b.decode("latin-1")
    return kind, "\n".join(lines)


def mutate_json(text, rng):
    kind = rng.choice(["number", "number", "deep", "type", "missing", "truncate", "overflow"])
    if kind == "number" and numbers(text):
        m = rng.choice(numbers(text))
        return kind, text[:m.start()] + rng.choice([e for e in EXTREMES if e not in ("nan", "inf", "-inf")]) + text[m.end():]
    if kind == "deep":
        n = rng.choice([100, 100000])
        return kind, '{"floes": ' + "[" * n + "]" * n + "}"
    if kind == "type":
        return kind, text.replace('"yaw_deg": ', '"yaw_deg": "x" ,"_": ', 1)
    if kind == "missing":
        return kind, text.replace('"centre"', '"center"', 1)
    if kind == "truncate":
        return kind, text[:rng.randrange(max(1, len(text)))]
    return "overflow", text.replace("0", "1e309", 1)


def csv_to_json(text):
    floes = []
    for line in text.split("\n"):
        if not line or line.startswith("#") or line.startswith("x,"):
            continue
        x, z, yaw, poly = line.split(",", 3)
        pts = [[float(a) for a in v.split()] for v in poly.strip('"').split(";") if v.strip()]
        floes.append({"centre": [float(x), float(z)], "yaw_deg": float(yaw), "polygon": pts})
    return json.dumps({"floes": floes})


def judge_check(code, out, names):
    """(problem or None, is a crash or hang)"""
    if code is None:
        return "hang", True
    if code < 0 or code >= 128 and code != 130:
        return f"crash (exit {code}, signal {signal.Signals(-code).name if code < 0 else code - 128})", True
    if code not in (0, 2):
        return f"exit {code} from check (expected 0 or 2)", False
    if code == 2:
        if len(out) > 2048:
            return f"a {len(out)}-character message", False
        # the mutated file or --set, or the input file it led to (a layout outside a changed channel)
        if not any(n in out for n in names) and not NAMED_INPUT.search(out):
            return "a refusal that names no input file and no --set", False
    if LIBRARY_TEXT.search(out):
        return "library text in the message", False
    return None, False


def remove_run(h5):
    """Remove a run's output and its checkpoint, where they exist."""
    for p in (h5, h5 + ".checkpoint"):
        if os.path.exists(p):
            os.remove(p)


def guard_problems(icedem, scenario, timeout):
    """Runs of `scenario` whose outputs name an input or each other: each must be refused
    (exit 2) and leave the scenario as it was. Yields (problem, is severe, output)."""
    before = digest(scenario)
    h5 = scenario + ".guard.h5"
    attempts = {
        "-o names the scenario": ["-o", scenario],
        "--summary-json names the scenario": ["-o", h5, "--summary-json", scenario],
        "--summary-json names -o": ["-o", h5, "--summary-json", h5],
    }
    for what, args in attempts.items():
        code, text = run([icedem, "run", scenario, "-q", "--set", "time.duration=0.1"] + args, timeout)
        if code is None or code < 0 or code >= 128:
            yield f"{what}: crash or hang (exit {code})", True, text
        elif code != 2:
            yield f"{what}: exit {code}, expected 2 (refused)", False, text
        if digest(scenario) != before:
            yield f"{what}: the scenario was overwritten", True, text
            return
        remove_run(h5)


def signal_problem(icedem, scenario, sig, delay, timeout):
    """A 30 s run of `scenario` to a new output, sent `sig` after `delay` s.
    Returns (problem or None, is severe, output)."""
    h5 = scenario + ".signal.h5"
    remove_run(h5)
    proc = subprocess.Popen([icedem, "run", scenario, "-q", "-o", h5, "--set", "time.duration=30"],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, errors="replace")
    try:
        proc.wait(timeout=delay)
    except subprocess.TimeoutExpired:
        proc.send_signal(sig)
    try:
        text, _ = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        proc.kill()
        return "hang after the signal", True, ""
    code = proc.returncode
    expected = {signal.SIGINT: 130, signal.SIGTERM: 143, signal.SIGKILL: -signal.SIGKILL}[sig]
    problem, bad = None, False
    if code == -sig and not os.path.exists(h5):
        pass  # the signal came before icedem could answer it (starting up): it wrote nothing
    elif code == -sig and os.path.getsize(h5) > 0 and results.status(h5) == "complete":
        pass  # the signal came after the run had ended and released its file (a run of a few steps)
    elif code not in (0, 2, 3, expected):
        problem, bad = f"exit {code}, expected {expected} (or the run's own 0, 2, 3)", code < 0 and code != expected
    elif os.path.exists(h5) and os.path.getsize(h5) == 0:
        problem = "a 0-byte output file"
    elif os.path.exists(h5) and sig != signal.SIGKILL and code != 2:
        status = results.status(h5)
        if status not in ("complete", "failed", "interrupted"):
            problem = f"output file status '{status}' after the signal"
    elif os.path.exists(h5):
        info, info_text = run([icedem, "info", h5], timeout)
        if info not in (0, 2):  # 2: a file killed before its layout was written, named as unreadable
            problem, bad = f"icedem info on the killed run's file: exit {info}", info is None or info < 0
        text = info_text
    remove_run(h5)
    return problem, bad, text


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--mutations", type=int, default=1000)
    ap.add_argument("--runs", type=int, default=20, help="accepted scenarios run for 2 s")
    ap.add_argument("--guards", type=int, default=0, help="accepted scenarios run with outputs naming inputs")
    ap.add_argument("--signals", type=int, default=0, help="accepted scenarios run and stopped by a signal")
    ap.add_argument("--outputs", type=int, default=0,
                    help="accepted scenarios whose commands aim outputs at inputs and other runs' files")
    ap.add_argument("--tampers", type=int, default=0, help="checkpoints tampered with, then resumed")
    ap.add_argument("--torn", type=int, default=0, help="killed runs' outputs torn, then resumed")
    ap.add_argument("--scenes", type=int, default=0, help="inconsistent scenes through check")
    ap.add_argument("--walls", type=int, default=0, help="tows driven into the channel's end wall")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--icedem", default=os.path.join(ROOT, "build", "dem", "icedem"))
    ap.add_argument("--out", help="where findings and their inputs go (default: a temporary directory)")
    ap.add_argument("--timeout", type=float, default=30.0, help="s per check; a run gets four times this")
    a = ap.parse_args(argv)
    rng = random.Random(a.seed)
    out = a.out or tempfile.mkdtemp(prefix="icedem-fuzz-")
    work = os.path.join(out, "work")
    os.makedirs(work, exist_ok=True)
    scenarios = sorted(glob.glob(os.path.join(ROOT, "scenarios", "**", "*.toml"), recursive=True))
    csv_file = os.path.join(ROOT, "scenarios", "examples", "floes_small.csv")
    csv_text = open(csv_file).read()
    json_text = csv_to_json(csv_text)
    layout_scenario = os.path.join(ROOT, "scenarios", "examples", "floes_from_file.toml")

    findings, severe, accepted, check_text = [], 0, [], {}
    counts = {"scenario": 0, "csv": 0, "json": 0, "accepted": 0, "refused": 0}
    for i in range(a.mutations):
        target = rng.choices(["scenario", "csv", "json"], weights=[6, 2, 2])[0]
        counts[target] += 1
        if target == "scenario":
            base = rng.choice(scenarios)
            kind, text = mutate_scenario(open(base).read(), rng)
            path = os.path.join(work, f"m{i}.toml")
            # layout files and caches are found relative to the scenario: keep them reachable
            text = text.replace('file = "floes_small.csv"', f'file = "{csv_file}"')
            cmd, names = [a.icedem, "check", path], [path]
        else:
            kind, text = (mutate_csv(csv_text, rng) if target == "csv" else mutate_json(json_text, rng))
            path = os.path.join(work, f"m{i}.{target}")
            cmd = [a.icedem, "check", layout_scenario, "--set", f'layout.file="{path}"']
            names = [path, "layout.file"]
        with open(path, "w", encoding="latin-1", errors="replace") as f:
            f.write(text)
        code, text_out = run(cmd, a.timeout)
        problem, bad = judge_check(code, text_out, names)
        if code == 0:
            counts["accepted"] += 1
            if target == "scenario":
                accepted.append(path)
                check_text[path] = text_out
        elif code == 2:
            counts["refused"] += 1
        if problem:
            severe += bad
            keep = os.path.join(out, f"finding_{len(findings)}_{os.path.basename(path)}")
            shutil.copy(path, keep)
            findings.append((f"check {target} ({kind})", problem, keep, text_out.strip()[-300:]))
        if not bad and path not in check_text:  # accepted scenarios are run below
            os.remove(path)

    for path in rng.sample(accepted, min(a.runs, len(accepted))):
        h5 = path + ".h5"
        code, text_out = run([a.icedem, "run", path, "-q", "-o", h5, "--set", "time.duration=2",
                              "--set", "output.snapshot_interval=1"], 4 * a.timeout)
        problem = None
        if code is None:
            problem, bad = "hang", True
        elif code < 0 or (code >= 128 and code != 130):
            problem, bad = f"crash (exit {code})", True
        elif code not in (0, 3):
            problem, bad = f"exit {code} from run of a scene check accepted", False
        elif os.path.exists(h5):
            status = results.status(h5)
            if status not in ("complete", "failed"):
                problem, bad = f"output file status '{status}'", False
            elif code == 3 and "warning" not in check_text[path]:
                problem, bad = "a blow-up of a scene check accepted without a warning", False
        if problem:
            severe += bad
            keep = os.path.join(out, f"finding_{len(findings)}_{os.path.basename(path)}")
            shutil.copy(path, keep)
            findings.append(("run", problem, keep, text_out.strip()[-300:]))
        remove_run(h5)

    def keep_finding(what, problem, path, tail, bad):
        nonlocal severe
        severe += bad
        keep = os.path.join(out, f"finding_{len(findings)}_{os.path.basename(path)}")
        shutil.copy(path, keep)
        findings.append((what, problem, keep, tail.strip()[-300:]))

    guards = rng.sample(accepted, min(a.guards, len(accepted)))
    for path in guards:
        for problem, bad, tail in guard_problems(a.icedem, path, a.timeout):
            keep_finding("guard", problem, path, tail, bad)

    signals = rng.sample(accepted, min(a.signals, len(accepted)))
    for path in signals:
        sig = rng.choice([signal.SIGINT, signal.SIGTERM, signal.SIGKILL])
        delay = rng.uniform(0.0, 2.0)
        problem, bad, tail = signal_problem(a.icedem, path, sig, delay, 4 * a.timeout)
        if problem:
            keep_finding(f"signal {sig.name} after {delay:.2f} s", problem, path, tail, bad)
    # the file classes (tools/icedem_tools/fuzzing/fuzz_files.py) and the scene classes (fuzz_scenes.py)
    outputs_tried = tampered = refused_tampers = torn_tried = scenes_tried = walls_tried = 0
    if a.outputs or a.tampers or a.torn:
        fx = fuzz_files.Fixture(a.icedem, os.path.join(out, "files"), a.timeout)
        for path in rng.sample(accepted, min(a.outputs, len(accepted))):
            outputs_tried += 1
            for problem, bad, tail in fuzz_files.output_problems(fx, path, rng, 4):
                keep_finding("outputs", problem, path, tail, bad)
        for i in range(a.tampers):
            problem, code, how = fuzz_files.tamper_problem(fx, rng, i)
            tampered += 1
            refused_tampers += code == 2
            if problem:
                text, bad, tail = problem[0], problem[1], problem[2]
                findings.append(("tamper", text, fx.killed + ".checkpoint", tail.strip()[-300:]))
                severe += bad
        for i in range(a.torn):
            problem, how = fuzz_files.torn_problem(fx, rng, i)
            torn_tried += 1
            if problem:
                text, bad, tail = problem
                findings.append(("torn", text, fx.killed, tail.strip()[-300:]))
                severe += bad
        fuzz_files.cleanup(fx)
    for i in range(a.scenes):
        problem, bad, what, tail = fuzz_scenes.scene_problem(a.icedem, work, rng, scenarios, i, a.timeout)
        scenes_tried += 1
        if problem:
            findings.append(("scene", problem, what, tail.strip()[-300:]))
            severe += bad
    for i in range(a.walls):
        problem, bad, tail = fuzz_scenes.wall_problem(a.icedem, work, rng, i, a.timeout)
        walls_tried += 1
        if problem:
            findings.append(("wall", problem, "short_tow into its end wall", tail.strip()[-300:]))
            severe += bad

    for path in accepted:
        os.remove(path)

    cases = a.mutations + min(a.runs, len(accepted)) + len(guards) + len(signals) + outputs_tried + tampered + \
        torn_tried + scenes_tried + walls_tried
    print(f"fuzz: {cases} cases. {a.mutations} mutations (scenario {counts['scenario']}, layout CSV {counts['csv']}, "
          f"layout JSON {counts['json']}): {counts['accepted']} accepted, {counts['refused']} refused; "
          f"{min(a.runs, len(accepted))} accepted scenarios run, {len(guards)} with outputs naming inputs, "
          f"{len(signals)} stopped by a signal; {outputs_tried} with every command's outputs aimed at what a user "
          f"has; {tampered} checkpoints tampered with ({refused_tampers} refused, the others changed nothing the "
          f"run reads); {torn_tried} killed runs' outputs torn and resumed; {scenes_tried} inconsistent scenes; {walls_tried} tows into the end wall; "
          f"{severe} crashes, hangs, files overwritten, tampered checkpoints continued or resumable runs lost, "
          f"{len(findings) - severe} other findings (seed {a.seed})")
    for what, problem, keep, tail in findings:
        print(f"  {what}: {problem}: {keep}\n    {tail[:300]!r}")
    if not findings:
        shutil.rmtree(out, ignore_errors=True) if not a.out else None
    return 1 if severe else 0


if __name__ == "__main__":
    sys.exit(main())
