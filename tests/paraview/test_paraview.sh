#!/usr/bin/env bash
# "Opens in ParaView", tested: a short run's snapshots written as XDMF
# (scripts/xdmf_snapshots.py) and read by ParaView's own XDMF reader (pvpython, in
# Debian's python3-paraview package, which scripts/test.sh installs). Two runs: rigid
# floes (one grid per snapshot), breakable floes whose joints break (a floes and a
# joints block per snapshot: the cracks), and a cone moored by four catenary lines (a mooring block).
# Usage: test_paraview.sh ICEDEM_BINARY SOURCE_DIR WORK_DIR
set -euo pipefail
icedem="$1"; src="$2"; work="$3"
command -v pvpython >/dev/null || { echo "no pvpython: install Debian's python3-paraview (scripts/test.sh does)"; exit 1; }
mkdir -p "$work" && cd "$work"

# what a file holds: snapshots, two polygons (top, bottom) per body, floes; joints, and those
# broken by the first and the last snapshot
counts() {
  /usr/bin/python3 -c "
import h5py
with h5py.File('$1', 'r') as h:
    t = h['/snapshots/time'][:]
    e = h['/fracture/events'][:]
    broken = lambda s: len({(int(f), int(j)) for f, j, b in zip(e['floe'], e['joint'], e['time']) if b <= s})
    print(len(t), 2 * len(h['/bodies/floe_id']), int(h['/bodies/floe_id'][:].max()) + 1,
          len(h['/joints/floe']), broken(t[0]), broken(t[-1]))"
}

# 1. rigid floes
"$icedem" run "$src/scenarios/examples/short_tow.toml" -o rigid.h5 -q --set time.duration=10 \
  --set output.snapshot_interval=2 >/dev/null
/usr/bin/python3 "$src/scripts/xdmf_snapshots.py" rigid.h5
read -r steps cells floes joints _ _ < <(counts rigid.h5)
[ "$joints" -eq 0 ] || { echo "rigid run: $joints joints in /joints, expected none"; exit 1; }
# ParaView's offscreen build needs no display
pvpython --force-offscreen-rendering "$src/tests/paraview/check_xdmf.py" rigid.xdmf "$steps" "$cells" "$floes"

# 2. breakable floes, as the golden breakable case: 0.15 m elements with weak joints (6 kPa)
#    hit at 0.2 m/s, so that joints break within the 4 s
"$icedem" run "$src/scenarios/paper/large_floes_breakable_015.toml" -o lattice.h5 -q \
  --set time.duration=4 --set channel.start_x=3.0 --set channel.length=3.6 --set channel.width=3.0 \
  --set ice.concentration=0.6 --set structure.start_x=2.2 --set structure.speed=0.2 \
  --set ice.bending_strength=6e3 --set output.snapshot_interval=0.5 >/dev/null
/usr/bin/python3 "$src/scripts/xdmf_snapshots.py" lattice.h5
read -r steps cells floes joints first last < <(counts lattice.h5)
[ "$last" -gt 0 ] || { echo "breakable run: no joint broke, so the cracks are not tested"; exit 1; }
# the faces drawn are the glued ones: at t = 0 every joint's face on its first element
# coincides with the nearest edge of its second element (1 mm: the joints' initial gap is
# zero; a wrong edge is a whole element side, 0.15 m, away)
/usr/bin/python3 - "$src" <<'PY'
import sys
import h5py
import numpy as np
sys.path.insert(0, sys.argv[1] + "/tools")
from icedem_tools.runs.xdmf import nearest_edge, quat_to_matrix
from icedem_tools.runs.results import snapshot_field
with h5py.File("lattice.h5", "r") as h, h5py.File("lattice_views.h5", "r") as v:
    off, verts = h["/bodies/vertex_offset"][:], h["/bodies/vertices"][:]
    positions, orientations, _ = snapshot_field(h)
    pos, q = positions[0], orientations[0]
    faces = v["joint_points/0"][:].reshape(-1, 4, 3)
    worst = 0.0
    for r, (a, b) in enumerate(h["/joints/bodies"][:]):
        # b's edge nearest a's face centre, in the tank frame, at the face's height
        R = quat_to_matrix(q[b])
        centre = faces[r].mean(axis=0)
        local = R.T @ (centre - pos[b])
        p, s = nearest_edge(verts[off[b]:off[b + 1]], local[[0, 2]])
        edge = np.array([[p[0], 0, p[1]], [s[0], 0, s[1]]]) @ R.T + pos[b]
        top = faces[r][:2]
        d = min(np.abs(top[:, [0, 2]] - edge[:, [0, 2]]).max(), np.abs(top[::-1][:, [0, 2]] - edge[:, [0, 2]]).max())
        worst = max(worst, d)
    assert worst < 1e-3, f"a joint's face is {worst:.4f} m from its neighbour's edge"
    print(f"{len(faces)} joint faces on their neighbours' edges (worst {worst * 1e3:.3g} mm)")
PY
pvpython --force-offscreen-rendering "$src/tests/paraview/check_xdmf.py" lattice.xdmf "$steps" "$cells" "$floes" \
  "$joints" "$first" "$last"

# 3. the cone moored by four catenary lines: the lines as polylines with their tensions
"$icedem" run "$src/scenarios/moored/small_floes_moored.toml" -o moored.h5 -q --set time.duration=2 \
  --set 'mooring.model="catenary"' --set output.snapshot_interval=0.5 >/dev/null
/usr/bin/python3 "$src/scripts/xdmf_snapshots.py" moored.h5
read -r steps cells floes _ _ _ < <(counts moored.h5)
pvpython --force-offscreen-rendering "$src/tests/paraview/check_xdmf.py" moored.xdmf "$steps" "$cells" "$floes" lines=4
