#!/usr/bin/env bash
# Set up (packages, build) and run the default test suite: ctest labels unit,
# physics, regression, coupling and paraview. Long validations and benchmarks have their own labels
# and scripts and are not run here.
set -euo pipefail
source "$(dirname "$0")/common.sh"
start=$(date +%s)
ensure_packages
build_project
cd "$ICEDEM_BUILD"
ctest -L 'unit|physics|regression|coupling|paraview' --output-on-failure -j "$(nproc)" "$@"
log "tests done ($(( $(date +%s) - start )) s)"
