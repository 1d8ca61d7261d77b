#!/usr/bin/env bash
# A sweep of 20 runs through a real single-node Slurm cluster (scripts/slurm_local.sh),
# faulted while it runs: rounds of preemption (scontrol requeue of the running tasks:
# SIGTERM, then back in the queue) and of lost nodes (SIGKILL of running icedem
# processes: the task fails, and the documented recovery is to submit the sweep again).
# Every run must end complete and equal, dataset by dataset, to the same sweep run
# without faults. Its own label (slurm_faults, a few minutes); skipped (77) without root.
#   tests/sweep/test_slurm_faults.sh ICEDEM SOURCE_DIR WORKDIR
set -euo pipefail
icedem="$1"; src="$2"; work="$3"
[ "$(id -u)" -eq 0 ] || { echo "not root: skipping the Slurm test"; exit 77; }
rm -rf "$work" && mkdir -p "$work"
trap '"$src/scripts/slurm_local.sh" stop "$work/cluster"' EXIT
eval "export $("$src/scripts/slurm_local.sh" start "$work/cluster")"

# 2 configurations x 10 seeds of the short tow, 40 s each, a checkpoint every 5 s
sed -e 's/^seeds = .*/seeds = 10/' -e 's/"time.duration=20"/"time.duration=40"/' \
    -e 's/"output.snapshot_interval=0"\]/"output.snapshot_interval=0", "output.checkpoint_interval=5"]/' \
    "$src/sweeps/ci_tiny.toml" >"$work/faults.toml"
grep -q "seeds = 10" "$work/faults.toml" && grep -q checkpoint_interval "$work/faults.toml"
"$src/scripts/sweep" run "$work/faults.toml" --out "$work/whole" --icedem "$icedem" --jobs 2 >/dev/null

"$src/scripts/sweep" slurm "$work/faults.toml" --out "$work/faulted" --icedem "$icedem" >/dev/null
job="$(sbatch --parsable "$work/faulted/slurm/array.sh")"
requeued=0; killed=0
for round in $(seq 8); do
  sleep 2
  [ -z "$(squeue -h -j "$job" 2>/dev/null)" ] && break
  if [ $((round % 2)) -eq 1 ]; then  # preemption: every running task requeued
    for task in $(squeue -h -j "$job" -t R -o %i); do scontrol requeue "$task" && requeued=$((requeued + 1)) || true; done
    sleep 1
    for task in $(squeue -h -j "$job" -t PD -o %i); do scontrol update JobId="$task" StartTime=now || true; done
  else  # a lost node: one running run killed outright
    pid=""
    for p in $(pgrep -f "^$icedem (run|resume) " || true); do  # a run of this sweep (its directory)
      case "$(readlink "/proc/$p/cwd" 2>/dev/null)" in "$work/faulted/"*) pid=$p; break ;; esac
    done
    [ -n "$pid" ] && kill -KILL "$pid" && killed=$((killed + 1)) || true
  fi
done
for _ in $(seq 1800); do  # until the array is done (at most three minutes)
  [ -z "$(squeue -h -j "$job" 2>/dev/null)" ] && break
  sleep 0.1
done
echo "faults: $requeued tasks requeued, $killed runs killed"
[ "$requeued" -gt 0 ] && [ "$killed" -gt 0 ]
# what the kills left failed is submitted again (docs/user/slurm.md): resumed, not restarted
"$src/scripts/sweep" slurm "$work/faults.toml" --out "$work/faulted" --icedem "$icedem" --submit >/dev/null || true
out="$("$src/scripts/sweep" status "$work/faults.toml" --out "$work/faulted")"
echo "$out"
grep -q "20 runs: 20 finished, 0 failed, 0 pending" <<<"$out"
echo "runs that resumed from a checkpoint: $(grep -l "resuming" "$work"/faulted/*/*/*/log.txt | wc -l)"
/usr/bin/python3 "$src/tests/sweep/same_runs.py" "$work/whole" "$work/faulted" 20
echo "slurm fault test passed"
