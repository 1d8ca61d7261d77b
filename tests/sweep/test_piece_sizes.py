#!/usr/bin/python3
"""scripts/piece_sizes (tools/icedem_tools/runs/pieces.py): the fragments of a lattice over its intact
joints, the pieces broken off (every fragment of a broken floe but its largest) with their true
areas, the breaks up to a time, the element's area from the commonest one, and an unreadable run
named. On hand-made runs: a strip of four 0.15 m squares (floe 0) and a rigid floe (floe 1); a level
sheet of 4 x 3 squares cut through by the channel, whose two sides are the sheet, not pieces."""
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # checks, beside this file
from checks import ROOT, check, finish  # noqa: E402
from icedem_tools.runs import pieces  # noqa: E402


class FakeRun(dict):
    """What pieces reads of a results.load_run object: datasets by path, the events, the scenario
    and the first snapshot's positions."""
    events = None
    scenario = {}
    positions = None

    def first_positions(self):
        return self.positions


def strip_run(breaks):
    """Four squares of 0.15 m in a row (bodies 0-3, floe 0, joints 0-2 between neighbours), the
    last one clipped to half (an element cut at an outline), and a rigid floe (body 4, floe 1);
    `breaks`: (time, joint index) of floe 0."""
    square = np.array([[-0.075, -0.075], [0.075, -0.075], [0.075, 0.075], [-0.075, 0.075]])
    half = np.array([[-0.075, -0.075], [0.0, -0.075], [0.0, 0.075], [-0.075, 0.075]])
    rigid = np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]], dtype=float)
    outlines = [square, square, square, half, rigid]
    run = FakeRun({"/bodies/vertices": np.concatenate(outlines),
                   "/bodies/vertex_offset": np.cumsum([0] + [len(o) for o in outlines]),
                   "/bodies/floe_id": np.array([0, 0, 0, 0, 1]),
                   "/joints/bodies": np.array([[0, 1], [1, 2], [2, 3]]),
                   "/joints/floe": np.array([0, 0, 0]), "/joints/index": np.array([0, 1, 2])})
    ev = np.zeros(len(breaks), dtype=[("time", "f8"), ("floe", "i4"), ("joint", "i4")])
    for i, (t, j) in enumerate(breaks):
        ev[i] = (t, 0, j)
    run.events = ev
    return run


A = 0.15 ** 2
areas = pieces.polygon_areas(np.array([[0, 0], [2, 0], [2, 1], [0, 1.0]]), np.array([0, 4]))
check(abs(areas[0] - 2.0) < 1e-12, f"the shoelace area of a 2 x 1 rectangle is 2: {areas}")

run = strip_run([])
p, element = pieces.piece_areas(run)
check(len(p) == 0 and pieces.summary(p, element) == {"pieces": 0}, "no break: no piece")

run = strip_run([(1.0, 1), (2.0, 2)])
frags = pieces.fragment_areas(run, pieces.body_areas(run))
check(list(frags) == [0] and np.allclose(frags[0], [2 * A, A, A / 2]),
      f"joints 1 and 2 broken: fragments of 2, 1 and a half element, largest first: {frags}")
p, element = pieces.piece_areas(run)
check(abs(element - A) < 1e-12, f"the element's area is the commonest whole one, not the clipped half: {element}")
check(np.allclose(sorted(p), [A / 2, A]), f"the pieces are every fragment but the largest: {p}")
s = pieces.summary(p, element)
check(s["pieces"] == 2 and abs(s["single_element_share"] - 1.0) < 1e-12,
      f"both pieces are no larger than one element: all the area in one-element pieces: {s}")
check(abs(s["diameter_m"][1] - np.median(np.sqrt(4 * p / np.pi))) < 1e-12, "the equivalent diameter is sqrt(4 A / pi)")

p, _ = pieces.piece_areas(run, until=1.5)
check(np.allclose(p, [1.5 * A]), f"until 1.5 s only joint 1 is broken: one piece of 1.5 elements: {p}")


def level_run(broken):
    """A level sheet of 4 x 3 squares of 0.15 m (fracture.element_size) from x = 6 m, the structure
    coming from x = 6 m: body 3 * col + row at column col (along the tow) and row row (across); joints
    between neighbours, `broken` ((col, row), (col, row)) pairs broken at t = 1 s. Its edge (held by the
    ice around): rows 0 and 2 (the sides) and column 3 (the far end)."""
    square = np.array([[-0.075, -0.075], [0.075, -0.075], [0.075, 0.075], [-0.075, 0.075]])
    body = lambda c, r: 3 * c + r  # noqa: E731
    pairs = [((c, r), (c + 1, r)) for c in range(3) for r in range(3)] + \
            [((c, r), (c, r + 1)) for c in range(4) for r in range(2)]
    run = FakeRun({"/bodies/vertices": np.tile(square, (12, 1)), "/bodies/vertex_offset": 4 * np.arange(13),
                   "/bodies/floe_id": np.zeros(12, int),
                   "/joints/bodies": np.array([[body(*a), body(*b)] for a, b in pairs]),
                   "/joints/floe": np.zeros(len(pairs), int), "/joints/index": np.arange(len(pairs))})
    run.scenario = {"ice": {"cover": "level"}, "fracture": {"element_size": 0.15}}
    run.positions = np.array([[6.075 + 0.15 * c, 0.0, -0.15 + 0.15 * r] for c in range(4) for r in range(3)])
    cut = [pairs.index(p) for p in broken]
    run.events = np.array([(1.0, 0, j) for j in cut], dtype=[("time", "f8"), ("floe", "i4"), ("joint", "i4")])
    return run


# the middle row's first three elements broken off (a piece), and the sheet cut through at the far
# end, so that its two sides are fragments of 5 and 4 elements, both held by the ice around
run = level_run([((c, 0), (c, 1)) for c in range(3)] + [((c, 1), (c, 2)) for c in range(4)] + [((2, 1), (3, 1))])
edge = pieces.sheet_edge(run)
check(edge.tolist() == [c == 3 or r != 1 for c in range(4) for r in range(3)],
      f"the sheet's edge: its sides (rows 0 and 2) and its far end (column 3), not its near end: {edge}")
p, _ = pieces.piece_areas(run)
check(np.allclose(p, [3 * A]), f"of a level sheet cut through, the pieces are the fragments the ice around does not "
                               f"hold (the middle row's 3 elements), not the side the channel cut off (4 elements): {p}")
run.scenario = {"ice": {"cover": "floes"}, "fracture": {"element_size": 0.15}}
check(pieces.sheet_edge(run) is None and np.allclose(sorted(pieces.piece_areas(run)[0]), [3 * A, 4 * A]),
      "the same lattice as a floe: every fragment but the largest")

with tempfile.TemporaryDirectory() as tmp:
    bad = os.path.join(tmp, "not_a_run.h5")
    with open(bad, "w") as f:
        f.write("text")
    r = subprocess.run([os.path.join(ROOT, "scripts", "piece_sizes"), bad], capture_output=True, text=True)
    check(r.returncode == 2 and "not_a_run.h5" in r.stderr, f"an unreadable run is named, exit 2: {r.stderr.strip()}")
    r = subprocess.run([os.path.join(ROOT, "scripts", "piece_sizes"), bad, bad, "--label", "one"],
                       capture_output=True, text=True)
    check(r.returncode == 2 and "--label" in r.stderr, f"a --label count that does not match is refused: {r.stderr.strip()}")

finish()
