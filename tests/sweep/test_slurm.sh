#!/usr/bin/env bash
# The sweep's Slurm path against a real single-node Slurm cluster started here
# (scripts/slurm_local.sh): a tiny sweep as a job array finishes every run, and
# a failing configuration is reported with its error. Skipped (77) without root.
#   tests/sweep/test_slurm.sh ICEDEM SOURCE_DIR WORKDIR
set -euo pipefail
icedem="$1"; src="$2"; work="$3"
[ "$(id -u)" -eq 0 ] || { echo "not root: skipping the Slurm test"; exit 77; }
rm -rf "$work" && mkdir -p "$work"
trap '"$src/scripts/slurm_local.sh" stop "$work/cluster"' EXIT
eval "export $("$src/scripts/slurm_local.sh" start "$work/cluster")"

out="$("$src/scripts/sweep" slurm "$src/sweeps/ci_tiny.toml" --out "$work/ok" --icedem "$icedem" --submit)"
echo "$out"
grep -q "4 runs: 4 finished, 0 failed, 0 pending" <<<"$out"
[ "$(ls "$work/ok/slurm"/task-*.out | wc -l)" -eq 4 ]

sed 's/\[0.1, 0.3\]/[0.1, 7.0]/' "$src/sweeps/ci_tiny.toml" >"$work/bad.toml"
set +e
out="$("$src/scripts/sweep" slurm "$work/bad.toml" --out "$work/bad" --icedem "$icedem" --submit)"
rc=$?
set -e
echo "$out"
[ "$rc" -eq 1 ]
grep -q "2 finished, 2 failed" <<<"$out"
[ "$(grep -c "FAILED .*friction.ice_structure=7.0.*expected a number" <<<"$out")" -eq 2 ]
echo "slurm sweep test passed"
