"""The pieces a run's breakable ice broke into: the fragments of each lattice at the run's end, from
its elements' outlines (/bodies), its joints (/joints) and the joints it broke (/fracture/events).

A floe's fragments are the connected parts of its elements over the joints still intact. The piece
sizes a run reports are those of the fragments broken off: every fragment of a floe that broke but
its largest, which is what is left of the floe; of a level sheet, every fragment but those the ice
around the sheet holds (sheet_edge: once the structure's channel has cut the sheet through, the
sheet is two fragments, one either side of it). Areas are the
elements' true areas (a hexagonal or outline-clipped element keeps its own), so square and
hexagonal lattices compare on the same footing; the equivalent diameter is sqrt(4 A / pi).

    scripts/piece_sizes RUN.h5 [RUN.h5 ...] [--label NAME ...] [--until T]

prints, per run, the number of pieces, their area's quartiles, the equivalent diameter's quartiles
and the share of the broken-off area in pieces of one element (the lattice's own grain), so that a
distribution set by the elements' size shows as such."""
import argparse
import sys

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

from . import results
from .polygons import polygon_area


def polygon_areas(vertices, offsets):
    """The area (m^2) of each outline vertices[offsets[i]:offsets[i+1]]."""
    return np.array([polygon_area(vertices[offsets[i]:offsets[i + 1]]) for i in range(len(offsets) - 1)])


def body_areas(run):
    """The area (m^2) of every body of a results.load_run object, from its outline (/bodies)."""
    return polygon_areas(np.asarray(run["/bodies/vertices"]), np.asarray(run["/bodies/vertex_offset"]))


def lattice_joints(run):
    """The bodies each joint of a breakable floe glues (/joints/bodies, nj x 2; empty without)."""
    return np.asarray(run["/joints/bodies"]) if "/joints/bodies" in run else np.empty((0, 2), int)


def sheet_edge(run):
    """Of a level-ice run (ice.cover = "level"), which bodies are the sheet's elements that the ice
    around it holds, as icedem marks them (dem/fracture/level_ice.cpp, add_level_sheet): a centre
    within one element (fracture.element_size) of the sheet's sides or of its far end (the structure
    comes from the near end), where the sheet lay at the start (the first snapshot). A fragment
    with one of them is the sheet, not a piece broken off. None for any other ice cover, or a run
    without snapshots (its pieces are then every fragment but the largest)."""
    scenario = run.scenario
    if scenario.get("ice", {}).get("cover") != "level":
        return None
    position = run.first_positions()
    if position is None:
        return None
    vertices, offsets = np.asarray(run["/bodies/vertices"]), np.asarray(run["/bodies/vertex_offset"])
    sheet = np.unique(lattice_joints(run).ravel())
    xs = np.concatenate([position[b, 0] + vertices[offsets[b]:offsets[b + 1], 0] for b in sheet])
    zs = np.concatenate([position[b, 2] + vertices[offsets[b]:offsets[b + 1], 1] for b in sheet])
    near = float(scenario["fracture"]["element_size"])
    x, z = position[:, 0], position[:, 2]
    edge = np.zeros(len(position), bool)
    edge[sheet] = (z[sheet] - zs.min() < near) | (zs.max() - z[sheet] < near) | (xs.max() - x[sheet] < near)
    return edge


def fragments(run, areas, until=None):
    """{floe id: (areas (m^2) of its fragments, largest first; for each, whether it holds an element
    of a level sheet's edge (sheet_edge), or None when the run is not of level ice)} for every
    lattice floe that broke, from a results.load_run object and its bodies' areas (body_areas),
    after the breaks up to time `until` (s; None: all of them). Rigid floes (no joints) and lattices
    that never broke are left out."""
    joints = lattice_joints(run)
    if len(joints) == 0:
        return {}
    floe_of_joint, index = np.asarray(run["/joints/floe"]), np.asarray(run["/joints/index"])
    ev = run.events
    if until is not None and len(ev):
        ev = ev[ev["time"] <= until]
    broken_keys = {(int(f), int(j)) for f, j in zip(ev["floe"], ev["joint"]) if j >= 0} if len(ev) else set()
    if not broken_keys:
        return {}
    intact = np.array([(int(f), int(j)) not in broken_keys for f, j in zip(floe_of_joint, index)])
    n = len(areas)
    a, b = joints[intact, 0], joints[intact, 1]
    graph = coo_matrix((np.ones(len(a)), (a, b)), shape=(n, n))
    _, label = connected_components(graph, directed=False)
    edge = sheet_edge(run)
    broken_floes = {f for f, _ in broken_keys}
    lattice_bodies = np.unique(joints.ravel())
    floe_id = np.asarray(run["/bodies/floe_id"])
    out = {}
    for f in sorted(broken_floes):
        bodies = lattice_bodies[floe_id[lattice_bodies] == f]
        labels, inverse = np.unique(label[bodies], return_inverse=True)
        sums = np.bincount(inverse, weights=areas[bodies], minlength=len(labels))
        order = np.argsort(sums, kind="stable")[::-1]
        held = None if edge is None else np.bincount(inverse, weights=edge[bodies], minlength=len(labels))[order] > 0
        out[f] = (sums[order], held)
    return out


def fragment_areas(run, areas, until=None):
    """{floe id: areas (m^2) of its fragments, largest first} (fragments, without the edge)."""
    return {f: a for f, (a, _) in fragments(run, areas, until).items()}


def piece_areas(run, until=None):
    """(areas (m^2) of the pieces broken off by time `until` (s; None: the run's end), the lattices'
    whole element's area (m^2)): every fragment of a floe that broke but its largest; of a level
    sheet, every fragment the ice around it does not hold (sheet_edge)."""
    joints = lattice_joints(run)
    if len(joints) == 0:  # rigid floes only: no outline read
        return np.empty(0), 0.0
    areas = body_areas(run)
    frags = fragments(run, areas, until)
    off = [a[1:] if held is None else a[~held] for a, held in frags.values()]
    pieces = np.concatenate(off) if off else np.empty(0)
    # the whole elements' area: the commonest, to the round-off (clipped ones at an outline are smaller)
    values, counts = np.unique(np.round(areas[np.unique(joints.ravel())], 9), return_counts=True)
    return pieces, float(values[np.argmax(counts)])


def summary(pieces, element):
    """The figures of one run's pieces: count, area and equivalent-diameter quartiles, elements a
    piece (median) and the share of broken-off area in pieces no larger than one element."""
    if len(pieces) == 0:
        return {"pieces": 0}  # (a record's pieces: None when kept before they were)
    d = np.sqrt(4 * pieces / np.pi)
    q = lambda x: [float(v) for v in np.quantile(x, [0.25, 0.5, 0.75])]  # noqa: E731
    single = pieces <= element * 1.001 if element > 0 else np.zeros(len(pieces), bool)
    return {"pieces": int(len(pieces)), "area_m2": q(pieces), "diameter_m": q(d),
            "area_weighted_diameter_m": float(np.sum(d * pieces) / np.sum(pieces)),
            "elements_median": float(np.median(pieces) / element) if element > 0 else None,
            "single_element_share": float(pieces[single].sum() / pieces.sum()),
            "element_area_m2": element}


def fmt(v, digits):
    """A number for the table, n/a for none."""
    return "n/a" if v is None else f"{v:.{digits}f}"


def table(rows):
    """Markdown lines: one row per (label, summary); a summary of None (a record kept before pieces
    were) is n/a."""
    L = ["| run | pieces | area, m^2: median (quartiles) | equivalent diameter, m: median (quartiles) | "
         "area-weighted diameter, m | elements a piece (median) | area in one-element pieces |",
         "|---|---|---|---|---|---|---|"]
    for label, s in rows:
        if not s or s.get("pieces") is None:  # a record kept before pieces were
            L.append(f"| {label} | n/a | | | | | |")
            continue
        if s["pieces"] == 0:
            L.append(f"| {label} | 0 | | | | | |")
            continue
        a, d = s["area_m2"], s["diameter_m"]
        L.append(f"| {label} | {s['pieces']} | {fmt(a[1], 4)} ({fmt(a[0], 4)}-{fmt(a[2], 4)}) | "
                 f"{fmt(d[1], 3)} ({fmt(d[0], 3)}-{fmt(d[2], 3)}) | {fmt(s['area_weighted_diameter_m'], 3)} | "
                 f"{fmt(s['elements_median'], 2)} | {fmt(100 * s['single_element_share'], 1)} % |")
    return L


def main(argv=None):
    ap = argparse.ArgumentParser(prog="scripts/piece_sizes", description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("runs", nargs="+", help="run outputs (OUT.h5) of scenarios with breakable ice")
    ap.add_argument("--label", action="append", default=[], help="a name for each run, in order (default: its path)")
    ap.add_argument("--until", type=float, help="the pieces after the breaks up to this time, s (default: the "
                                                "run's end; a run still going is read as far as it got)")
    a = ap.parse_args(argv)
    if a.label and len(a.label) != len(a.runs):
        ap.error(f"{len(a.label)} --label for {len(a.runs)} runs: give one for each or none")
    rows = []
    for i, path in enumerate(a.runs):
        try:
            run = results.load_run(path)
        except OSError as e:
            print(f"scripts/piece_sizes: {path}: cannot read it as a run's output ({e})", file=sys.stderr)
            return 2
        rows.append((a.label[i] if a.label else path, summary(*piece_areas(run, a.until))))
    print("\n".join(table(rows)))
    return 0
