#!/usr/bin/env bash
# Install the Debian packages icedem needs and build it. Safe to re-run.
set -euo pipefail
source "$(dirname "$0")/common.sh"
start=$(date +%s)
ensure_packages
build_project
log "ready: $ICEDEM_BUILD/dem/icedem ($(( $(date +%s) - start )) s)"
