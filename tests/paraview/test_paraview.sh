#!/usr/bin/env bash
# "Opens in ParaView", tested: a short run's snapshots written as XDMF
# (scripts/xdmf_snapshots.py) and read by ParaView's own XDMF reader (pvpython, in
# Debian's python3-paraview package). Skipped (exit 77) without pvpython.
# Usage: test_paraview.sh ICEDEM_BINARY SOURCE_DIR WORK_DIR
set -euo pipefail
icedem="$1"; src="$2"; work="$3"
command -v pvpython >/dev/null || { echo "skipped: no pvpython (Debian package python3-paraview)"; exit 77; }
mkdir -p "$work" && cd "$work"
"$icedem" run "$src/scenarios/examples/short_tow.toml" -o run.h5 -q --set time.duration=10 \
  --set output.snapshot_interval=2 >/dev/null
/usr/bin/python3 "$src/scripts/xdmf_snapshots.py" run.h5
# what the file holds: snapshots, and two polygons (top, bottom) per body
read -r steps bodies floes < <(/usr/bin/python3 -c "
import h5py
with h5py.File('run.h5', 'r') as h:
    print(len(h['/snapshots/time']), len(h['/bodies/floe_id']), int(h['/bodies/floe_id'][:].max()) + 1)")
# ParaView's offscreen build needs no display
pvpython --force-offscreen-rendering "$src/tests/paraview/check_xdmf.py" run.xdmf "$steps" "$((2 * bodies))" "$floes"
