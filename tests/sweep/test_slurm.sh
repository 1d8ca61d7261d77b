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
# preemption: the array's tasks requeued mid-run (scontrol requeue: SIGTERM, then back in the
# queue) resume their runs from their checkpoints, and every run ends as in a sweep without faults
sed 's/"output.snapshot_interval=0"\]/"output.snapshot_interval=0", "output.checkpoint_interval=5"]/' \
  "$src/sweeps/ci_tiny.toml" >"$work/ck.toml"
grep -q checkpoint_interval "$work/ck.toml"
"$src/scripts/sweep" run "$work/ck.toml" --out "$work/whole" --icedem "$icedem" --jobs 2 >/dev/null
"$src/scripts/sweep" slurm "$work/ck.toml" --out "$work/requeued" --icedem "$icedem" >/dev/null
job="$(sbatch --parsable "$work/requeued/slurm/array.sh")"
for _ in $(seq 600); do   # until a task has checkpointed (at most a minute)
  ls "$work"/requeued/*/*/*/run.h5.checkpoint >/dev/null 2>&1 && break
  sleep 0.1
done
ls "$work"/requeued/*/*/*/run.h5.checkpoint
for task in $(squeue -h -j "$job" -t R -o %i); do scontrol requeue "$task"; done  # the running ones
sleep 1
# Slurm holds a requeued job back for a while (its begin time); let it start again now
for task in $(squeue -h -j "$job" -t PD -o %i); do scontrol update JobId="$task" StartTime=now || true; done
for _ in $(seq 1200); do  # until the array is done (at most two minutes)
  [ -z "$(squeue -h -j "$job" 2>/dev/null)" ] && break
  sleep 0.1
done
out="$("$src/scripts/sweep" status "$work/ck.toml" --out "$work/requeued")"
echo "$out"
grep -q "4 runs: 4 finished, 0 failed, 0 pending" <<<"$out"
grep -l "resuming" "$work"/requeued/*/*/*/log.txt
/usr/bin/python3 "$src/tests/sweep/same_runs.py" "$work/whole" "$work/requeued" 4
echo "slurm sweep test passed"
