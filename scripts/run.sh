#!/usr/bin/env bash
# Set up (packages, build) and run one scenario:
#   scripts/run.sh [SCENARIO.toml] [icedem run options...]
# Default: the seed paper's small-floe test; writes small_floes.h5 and
# small_floes.summary.json in the current directory. Run again after a kill or Ctrl-C (a checkpoint
# small_floes.h5.checkpoint beside it), it resumes the run (options given: it is refused, naming
# `icedem resume` and `--restart`).
set -euo pipefail
source "$(dirname "$0")/common.sh"
ensure_packages
build_project
scenario="${1:-$ICEDEM_ROOT/scenarios/paper/small_floes.toml}"
[ $# -gt 0 ] && shift
name="$(basename "$scenario" .toml)"
# a run of this script killed or stopped (Ctrl-C) before: continue it from its checkpoint
if [ $# -eq 0 ] && [ -f "$name.h5.checkpoint" ]; then
  log "resuming $name.h5 from its checkpoint"
  exec "$ICEDEM_BUILD/dem/icedem" resume "$name.h5" --summary-json "$name.summary.json"
fi
log "running $scenario"
exec "$ICEDEM_BUILD/dem/icedem" run "$scenario" -o "$name.h5" --summary-json "$name.summary.json" "$@"
