#!/usr/bin/env bash
# Set up (packages, build) and run one scenario:
#   scripts/run.sh [SCENARIO.toml] [icedem run options...]
# Default: the seed paper's small-floe test; writes small_floes.h5 and
# small_floes.summary.json in the current directory.
set -euo pipefail
source "$(dirname "$0")/common.sh"
ensure_packages
build_project
scenario="${1:-$ICEDEM_ROOT/scenarios/paper/small_floes.toml}"
[ $# -gt 0 ] && shift
name="$(basename "$scenario" .toml)"
log "running $scenario"
exec "$ICEDEM_BUILD/dem/icedem" run "$scenario" -o "$name.h5" --summary-json "$name.summary.json" "$@"
