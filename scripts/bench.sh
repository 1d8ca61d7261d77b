#!/usr/bin/env bash
# Benchmark: run time of the full small-floe scenario (seed paper, 300 s) with the
# defaults and with each "skip" or solver choice switched, and print steps per
# second, the times real time in CPU, awake floes, contact points and the surge
# load, with the ratio of each run's CPU time to the default's in the same session.
#
#   scripts/bench.sh [--duration SECONDS] [--quick]
#   scripts/bench.sh --level-ice [--duration SECONDS]
#                                 the level tow cut by closed forms (scenarios/level_ice/level_ice_analytic.toml,
#                                 default 120 s) at both frictions, rigid and crushing at the cone, with every
#                                 contact crushing and with the channel left behind at 3 m, the first row the
#                                 baseline: its cost grows with the broken channel behind the cone, so the
#                                 duration is part of the figure
#   scripts/bench.sh --micro      the Google Benchmark microbenchmarks of the hot paths
#
# --quick runs 100 s of simulated time (CI uses it). Results also go to
# bench/results/bench-<date>.md. Set ICEDEM_BENCH_FLOAT=0 to skip the float build.
set -euo pipefail
source "$(dirname "$0")/common.sh"
duration=300
while [ $# -gt 0 ]; do
  case "$1" in
    --duration) duration="$2"; shift 2 ;;
    --quick) duration=100; shift ;;
    --micro) micro=1; shift ;;
    --level-ice) level_ice=1; shift ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
ensure_packages
build_project
if [ "${micro:-0}" = 1 ]; then
  exec "$ICEDEM_BUILD/bench/micro/icedem_micro"
fi
scenario="$ICEDEM_ROOT/scenarios/paper/small_floes.toml"
if [ "${level_ice:-0}" = 1 ]; then
  scenario="$ICEDEM_ROOT/scenarios/level_ice/level_ice_analytic.toml"
  [ "$duration" = 300 ] && duration=120
  ICEDEM_BENCH_FLOAT=0
fi
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# the float build, for the precision comparison
float_bin=""
if [ "${ICEDEM_BENCH_FLOAT:-1}" = 1 ]; then
  fbuild="$ICEDEM_BUILD-float"
  [ -f "$fbuild/CMakeCache.txt" ] || cmake -S "$ICEDEM_ROOT" -B "$fbuild" -DICEDEM_DOUBLE_PRECISION=OFF \
    -DICEDEM_BUILD_TESTS=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
  cmake --build "$fbuild" --target icedem -j "$(nproc)" -- --no-print-directory >/dev/null
  float_bin="$fbuild/dem/icedem"
fi

# name | binary | extra --set options
variants=(
  "default (double, dbvt, contact islands, sleeping, split impulse)|$ICEDEM_BUILD/dem/icedem|"
  "freeze resting floes outside the activation region|$ICEDEM_BUILD/dem/icedem|activation.freeze_outside_region=true"
  "sweep-and-prune broadphase|$ICEDEM_BUILD/dem/icedem|solver.broadphase=sap"
  "Bullet islands (bounding-box overlap)|$ICEDEM_BUILD/dem/icedem|activation.islands=bullet"
  "no sleeping (every floe solved)|$ICEDEM_BUILD/dem/icedem|activation.sleeping=false"
  "no split impulse (Baumgarte)|$ICEDEM_BUILD/dem/icedem|solver.split_impulse=false"
)
[ -n "$float_bin" ] && variants+=("float precision|$float_bin|")
if [ "${level_ice:-0}" = 1 ]; then
  variants=(
    "analytic level tow, mu 0.2, rigid contacts|$ICEDEM_BUILD/dem/icedem|friction.ice_structure=0.2 contact.model=rigid"
    "analytic level tow, mu 0.3, rigid contacts|$ICEDEM_BUILD/dem/icedem|friction.ice_structure=0.3 contact.model=rigid"
    "analytic level tow, mu 0.2, crushing at the cone (the scenario's)|$ICEDEM_BUILD/dem/icedem|friction.ice_structure=0.2 contact.model=crushing"
    "analytic level tow, mu 0.3, crushing at the cone (the scenario's)|$ICEDEM_BUILD/dem/icedem|friction.ice_structure=0.3 contact.model=crushing"
    "analytic level tow, mu 0.2, every ice contact crushing|$ICEDEM_BUILD/dem/icedem|friction.ice_structure=0.2 contact.model=crushing contact.crushing_contacts=all"
    "analytic level tow, mu 0.2, rigid, pieces 3 m behind the axis leave|$ICEDEM_BUILD/dem/icedem|friction.ice_structure=0.2 contact.model=rigid activation.leave_behind=3.0"
  )
fi

out="$ICEDEM_ROOT/bench/results"
mkdir -p "$out"
report="$out/bench-$(date -u +%Y%m%d-%H%M%S).md"
{
  echo "# icedem benchmark, $(date -u '+%Y-%m-%d %H:%M UTC')"
  echo
  echo "Command: \`scripts/bench.sh${level_ice:+ --level-ice} --duration $duration\`; scenario ${scenario#"$ICEDEM_ROOT/"},"
  echo "$duration s simulated, one core ($(nproc) on the machine), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)."
  echo
  echo "| variant | wall s | CPU s | steps/s | x real time (CPU) | CPU / first row's | mean awake | contact points (mean) | mean Fx N | max Fx N |"
  echo "|---|---|---|---|---|---|---|---|---|---|"
} > "$report"

base_wall=""
for v in "${variants[@]}"; do
  IFS='|' read -r name bin sets <<<"$v"
  args=(run "$scenario" -o "$work/run.h5" --summary-json "$work/run.json" -q --set "time.duration=$duration")
  [ -n "$sets" ] && args+=(--set $sets)  # one or more key=value, split on spaces
  log "bench: $name"
  "$bin" "${args[@]}" >/dev/null
  row=$(ICEDEM_ROOT="$ICEDEM_ROOT" /usr/bin/python3 - "$work/run.json" "$work/run.h5" "${base_wall:-0}" "$name" <<'PY'
import json, os, sys
sys.path.insert(0, os.path.join(os.environ["ICEDEM_ROOT"], "tools"))
from icedem_tools.runs import results
s = json.load(open(sys.argv[1])); base = float(sys.argv[3])
pts = results.load_run(sys.argv[2])["/diagnostics/contact_points"].mean()
ratio = s["cpu_time_s"] / base if base > 0 else 1.0
fmt = lambda v: "n/a" if v is None else f"{v:.2f}"
print(f"| {sys.argv[4]} | {s['wall_time_s']:.1f} | {s['cpu_time_s']:.1f} | {s['steps_per_second']:.0f} | {s['sim_time_s'] / s['cpu_time_s']:.2f} | "
      f"{ratio:.2f} | {s['mean_awake']:.0f} | {pts:.0f} | {fmt(s['mean_fx_N'])} | {fmt(s['max_fx_N'])} |")
print(s["cpu_time_s"])
PY
)
  echo "$row" | head -1 | tee -a "$report"
  [ -z "$base_wall" ] && base_wall=$(echo "$row" | tail -1)
done
log "report: $report"
