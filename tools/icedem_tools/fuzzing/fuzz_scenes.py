"""The fuzzer's classes of scenes (scripts/fuzz): scenarios whose keys are each legal but which cannot
run as meant, and structures driven into the channel's end wall.

- scenes: a shipped scenario given one inconsistency: a quoted dotted key, a --set value of two lines,
  a seed past its range, the structure outside the tank, wider than it or wholly above the ice, its keel
  below the tank's bottom, standing still, too far back to reach the ice or past every floe, a
  concentration a whole number of floes cannot make, breakable floes no wider than an element or
  elements that do not divide them, unreached floes kept out with sleeping off, snapshot or checkpoint
  intervals below the step, a plate case loaded past its freeboard. `icedem check` must refuse it (exit 2, naming the key)
  or accept it with a warning naming the key, as each class says.
- wall: the short tow in a channel of random length, towed into its end wall within the run. `check`
  must warn, and the run's summary must name the squeeze (`squeeze`) and end its statistics before it.
"""
import json
import os

from .fuzz_files import run
from ..runs.spec import ROOT

TOW = os.path.join(ROOT, "scenarios", "examples", "short_tow.toml")
PLATE = os.path.join(ROOT, "scenarios", "validation", "plate_deflection_27_015.toml")


def scene_cases(rng, scenarios):
    """(what, base scenario, text to append or None, --set values, expected "refused"/"warned", a word
    the message must hold)"""
    tows = [s for s in scenarios if "/validation/" not in s and "/stress/" not in s]
    base = rng.choice(tows)
    dt = rng.choice(["0.01", "0.02"])
    return rng.choice([
        ("a quoted dotted key", base, f'\n"time.dt" = {dt}\n', [], "refused", "time.dt"),
        ("a quoted dotted key at the top", base, '"solver.tolerance" = 1e-3\n', [], "refused", "solver.tolerance"),
        ("a --set of two lines", base, None, [f"time.dt={dt}\ntime.duration=5"], "refused", "more than one line"),
        ("a seed past 9e18", base, None, [f"seed={rng.choice([9000000000000000001, 9223372036854775807])}"],
         "refused", "seed"),
        ("the structure outside the tank", base, None, [f"structure.start_z={rng.choice([2.8, -3.5, 50.0])}"],
         "refused", "structure.start_z"),
        ("the hull above the ice", base, None, ["structure.profile=[[0.1, 0.2], [0.5, 0.6]]"], "refused",
         "structure.profile"),
        ("the hull under the ice", base, None, ["structure.profile=[[-0.9, 0.2], [-0.2, 0.6]]"], "refused",
         "structure.profile"),
        ("the keel below the bottom", base, None, ["tank.depth=0.2"], "warned", "tank.depth"),
        ("unreached floes kept out with sleeping off", base, None,
         ["activation.sleeping=false", "activation.unreached_out_of_world=true"], "warned",
         "activation.unreached_out_of_world"),
        ("snapshots more often than the step", base, None, ["output.snapshot_interval=0.001"], "warned",
         "output.snapshot_interval"),
        ("checkpoints more often than the step", base, None, ["output.checkpoint_interval=0.005"], "warned",
         "output.checkpoint_interval"),
        ("the structure standing still", base, None, ["structure.speed=0"], "warned", "structure.speed"),
        ("the structure too far back to reach the ice", base, None, ["structure.start_x=-60"], "warned",
         "structure.start_x"),
        ("the structure past every floe", base, None, ["structure.start_x=500"], "warned", "structure.start_x"),
        ("a hull wider than the tank", base, None, ["structure.profile=[[-0.443, 0.171], [0.0, 0.614], [0.3, 3.5]]"],
         "refused", "structure.profile"),
        ("a concentration a whole number of floes cannot make", TOW, None,
         ["ice.floe_size=1", "channel.length=2", "channel.width=2.1", "ice.concentration=0.9",
          "layout.size_spread=0.1"], "warned", "ice.concentration"),
        ("breakable floes no wider than an element", TOW, None,
         ["fracture.mode=on"] + rng.choice([["fracture.element_size=0.3"],
                                            ["fracture.element_shape=hexagon", "fracture.element_size=0.5"]]),
         "warned", "fracture.element_size"),
        ("square elements that do not divide the floe", TOW, None, ["fracture.mode=on", "fracture.element_size=0.25"],
         "refused", "fracture.element_size"),
        ("a plate loaded past its freeboard", PLATE, None, [f"validation.load={rng.choice([100, 1000, 10000])}"],
         "warned", "validation.load"),
    ])


def scene_problem(icedem, work, rng, scenarios, index, timeout):
    """One inconsistent scene through check. (problem or None, is severe, what, output)"""
    what, base, extra, sets, expected, word = scene_cases(rng, scenarios)
    path = base
    if extra is not None:
        path = os.path.join(os.path.dirname(base), f".fuzz_scene_{os.getpid()}_{index}.toml")
        with open(path, "w") as f:  # at the top: a key of no section; appended: of the last one
            text = open(base).read()
            f.write(extra + text if extra.startswith('"') else text + extra)
    try:
        code, text = run([icedem, "check", path] + [x for s in sets for x in ("--set", s)], timeout)
    finally:
        if path != base:
            os.remove(path)
    if code is None or code < 0:
        return f"{what}: crash or hang (exit {code})", True, what, text
    if expected == "refused" and not (code == 2 and word in text):
        return f"{what}: exit {code}, expected a refusal naming {word}", False, what, text
    if expected == "warned" and not (code == 0 and "warning:" in text and word in text):
        return f"{what}: exit {code}, expected a warning naming {word}", False, what, text
    return None, False, what, text


def wall_problem(icedem, work, rng, index, timeout):
    """The short tow driven into its channel's end wall. (problem or None, is severe, output)"""
    length = round(rng.uniform(1.5, 2.5), 3)
    # the rim (0.736 m) within one ice thickness (0.033 m) of the wall at 6 + length, from x = 5 m at
    # 0.07 m/s, and the run a few seconds beyond
    meeting = (6.0 + length - 0.736 - 0.033 - 5.0) / 0.07
    duration = meeting + rng.uniform(1.0, 8.0)
    sets = ["--set", f"channel.length={length}", "--set", f"time.duration={duration:.2f}",
            "--set", "ice.concentration=0.6",  # a short channel holds fewer floes on its grid
            "--set", f"seed={rng.randint(1, 1000)}", "--set", "output.snapshot_interval=0"]
    code, text = run([icedem, "check", TOW, *sets], timeout)
    if code != 0 or "end wall" not in text:
        return f"check of a tow into the end wall: exit {code}, no warning", code is None or code < 0, text
    h5, js = os.path.join(work, f"wall{index}.h5"), os.path.join(work, f"wall{index}.json")
    code, text = run([icedem, "run", TOW, "-q", "-o", h5, "--summary-json", js, *sets], 4 * timeout)
    problem = None
    if code is None or code < 0:
        problem = (f"run into the end wall: crash or hang (exit {code})", True, text)
    elif code not in (0, 3):
        problem = (f"run into the end wall: exit {code}", False, text)
    elif code == 0:
        s = json.load(open(js))
        sq = s.get("squeeze")
        if not sq or abs(sq["start_s"] - meeting) > 1e-6 or not sq["excluded_from_statistics"]:
            problem = (f"run into the end wall: the summary does not name the squeeze at {meeting:.2f} s ({sq})",
                       False, text)
        elif s.get("window_end_s") is not None and s["window_end_s"] >= sq["start_s"]:
            problem = (f"run into the end wall: the statistics run to {s['window_end_s']} s, past the squeeze",
                       False, text)
    for p in (h5, h5 + ".checkpoint", js):
        if os.path.exists(p):
            os.remove(p)
    return problem if problem else (None, False, text)
