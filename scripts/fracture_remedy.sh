#!/usr/bin/env bash
# Study of the iteration dependence of joint breaks : the
# large-floe breakable scenario (0.15 m elements) with the joint solve and the
# load filter varied, each at the joint softness the plate-deflection test
# calibrates for its joint iterations (60 MPa). Prints, per variant: breaks by
# mode, breaks within 1 m of the cone axis, max and mean surge load, wall time
# and realtime factor, plus the ratio of each wall time to the first variant.
#
#   scripts/fracture_remedy.sh [--duration SECONDS] [--seeds "1 2 3"]
#
# Results also go to bench/results/fracture-remedy-<date>.md. ICEDEM_BIN=path
# runs that binary instead of building the project's.
set -euo pipefail
source "$(dirname "$0")/common.sh"
duration=150
seeds="1"
while [ $# -gt 0 ]; do
  case "$1" in
    --duration) duration="$2"; shift 2 ;;
    --seeds) seeds="$2"; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
ensure_packages
if [ -n "${ICEDEM_BIN:-}" ]; then bin="$ICEDEM_BIN"; else build_project; bin="$ICEDEM_BUILD/dem/icedem"; fi
scenario="$ICEDEM_ROOT/scenarios/paper/large_floes_breakable_015.toml"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# name | --set options. CFM per (ERP, joint iterations) from `icedem calibrate` on
# scenarios/validation/plate_deflection_27_015.toml (2.7 m plate, 60 MPa).
# Lattices everywhere (fracture.lattice_radius = 0) except in the last variant.
common="fracture.lattice_radius=0 fracture.load_filter_time=0"
variants=(
  "10 it, ERP 0.8, paper CFM 1e-10 (12 MPa)|solver.iterations=10 fracture.joint_iterations=0 fracture.erp=0.8 fracture.cfm=1e-10 $common"
  "30 it, ERP 0.8, paper CFM 1e-10 (30 MPa)|solver.iterations=30 fracture.joint_iterations=0 fracture.erp=0.8 fracture.cfm=1e-10 $common"
  "joints 100 it, ERP 0.8, CFM 0.0059|solver.iterations=10 fracture.joint_iterations=100 fracture.erp=0.8 fracture.cfm=0.0059 $common"
  "joints 100 it, ERP 0.8, CFM 0.0059, filter 0.1 s|solver.iterations=10 fracture.joint_iterations=100 fracture.erp=0.8 fracture.cfm=0.0059 fracture.lattice_radius=0 fracture.load_filter_time=0.1"
  "contacts 30 it, joints 100 it, ERP 0.8, CFM 0.0059|solver.iterations=30 fracture.joint_iterations=100 fracture.erp=0.8 fracture.cfm=0.0059 $common"
  "joints 200 it, ERP 0.8, CFM 0.00743 (chosen)|solver.iterations=10 fracture.joint_iterations=200 fracture.erp=0.8 fracture.cfm=0.00743 $common"
  "joints 100 it, ERP 0.5, CFM 0.0022|solver.iterations=10 fracture.joint_iterations=100 fracture.erp=0.5 fracture.cfm=0.0022 $common"
  "joints 200 it, ERP 0.2, CFM 0.00107 (chosen before the island fix)|solver.iterations=10 fracture.joint_iterations=200 fracture.erp=0.2 fracture.cfm=0.00107 $common"
  "chosen, lattice radius 1.5 m (the scenario)|solver.iterations=10 fracture.joint_iterations=200 fracture.erp=0.8 fracture.cfm=0.00743 fracture.lattice_radius=1.5 fracture.load_filter_time=0"
)
if [ -n "${ICEDEM_VARIANTS:-}" ]; then  # e.g. ICEDEM_VARIANTS="8 9": run only those (1-based)
  picked=()
  for i in $ICEDEM_VARIANTS; do picked+=("${variants[$((i - 1))]}"); done
  variants=("${picked[@]}")
fi

report="$ICEDEM_ROOT/bench/results/fracture-remedy-$(date -u +%Y%m%d-%H%M%S).md"
{
  echo "# Joint-break iteration study, $(date -u +%F), $(nproc) cores"
  echo
  echo "\`scripts/fracture_remedy.sh --duration $duration --seeds \"$seeds\"\`: $scenario,"
  echo "${duration} s per run, seeds $seeds. Rocking steps: steps in which an element turned faster"
  echo "than 15 rad/s (/diagnostics/max_angular_speed); a failed run is a numerical blow-up."
  echo
  echo "| variant | seed | breaks | bending | shear | compression | within 1 m | rocking steps | max rad/s | max surge N | mean surge N | wall s | x real time | wall / first |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
} | tee "$report"
first_wall=""
for v in "${variants[@]}"; do
  name="${v%%|*}"
  sets=()
  for kv in ${v#*|}; do sets+=(--set "$kv"); done
  for seed in $seeds; do
    out="$work/run.h5"
    rm -f "$work/s.json"
    if ! "$bin" run "$scenario" -q -o "$out" --summary-json "$work/s.json" --set time.duration="$duration" \
      --set seed="$seed" "${sets[@]}" >/dev/null 2>"$work/err"; then
      echo "| $name | $seed | failed: $(tail -2 "$work/err" | head -1) |||||||||||" | tee -a "$report"
      continue
    fi
    line=$(/usr/bin/python3 - "$work/s.json" "$out" "$ICEDEM_ROOT/scripts" <<'PY'
import json, sys
sys.path.insert(0, sys.argv[3])
from fracture_events import summarise
s = json.load(open(sys.argv[1]))
e = summarise(sys.argv[2])
print(f"{e['breaks']} | {e['bending']} | {e['shear']} | {e['compression']} | {e['within_1m']} | "
      f"{e['rocking_steps']} | {e['max_angular_speed']:.0f} | "
      f"{s['max_fx_N']:.1f} | {s['mean_fx_N']:.1f} | {s['wall_time_s']:.0f} | {s['realtime_factor']:.2f}|{s['wall_time_s']}")
PY
)
    wall="${line##*|}"
    [ -n "$first_wall" ] || first_wall="$wall"
    ratio=$(/usr/bin/python3 -c "print(f'{$wall / $first_wall:.2f}')")
    echo "| $name | $seed | ${line%|*} | $ratio |" | tee -a "$report"
  done
done
echo
echo "report: $report"
