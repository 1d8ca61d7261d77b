#!/usr/bin/env bash
# The `icedem` command as users and sweeps call it: exit codes, error messages,
# the summary JSON keys, the HDF5 layout, and a Ctrl-C that keeps a readable file.
# Usage: test_cli.sh ICEDEM_BINARY SOURCE_DIR WORK_DIR
set -u
icedem="$1"; src="$2"; work="$3"
py=/usr/bin/python3
mkdir -p "$work" && cd "$work" || exit 1
passed=0; failed=0
ok()   { echo "ok: $1"; passed=$((passed + 1)); }
fail() { echo "FAILED: $1"; failed=$((failed + 1)); }

# 1. a typo in a scenario: exit 2, file:line, key and a suggestion; no output written
printf '[ice]\nfloe_size = 0.3\nconcentraton = 0.7\n' > bad.toml
rm -f bad.h5
msg=$("$icedem" run bad.toml -o bad.h5 2>&1); code=$?
[ $code -eq 2 ] && ok "bad input exits 2" || fail "bad input exit code $code"
echo "$msg" | grep -q "bad.toml:3" && echo "$msg" | grep -q "did you mean 'ice.concentration'" \
  && ok "error names file:line and suggests the key" || fail "error message: $msg"
[ ! -e bad.h5 ] && ok "nothing written on bad input" || fail "bad.h5 was written"

# 2. an existing output survives a bad --set
echo keep > keep.h5
"$icedem" run "$src/scenarios/examples/short_tow.toml" -o keep.h5 --set time.dt=-1 >/dev/null 2>&1
[ "$(cat keep.h5)" = keep ] && ok "existing file kept on bad --set" || fail "existing file clobbered"

# 2b. an output in a missing directory is bad input too
"$icedem" run "$src/scenarios/examples/short_tow.toml" -o no/such/dir/x.h5 >/dev/null 2>&1; code=$?
[ $code -eq 2 ] && ok "missing output directory exits 2" || fail "missing output directory exit code $code"

# 2c. a field too large for the sweep-and-prune broadphase: exit 2 naming the key (was a
# crash: Bullet's sweep and prune writes past its fixed number of handles), nothing written
rm -f sap.h5
msg=$("$icedem" run "$src/scenarios/paper/small_floes.toml" -o sap.h5 -q --set channel.length=2400 \
      --set solver.broadphase=sap 2>&1); code=$?
[ $code -eq 2 ] && echo "$msg" | grep -q 'solver.broadphase = "sap" holds at most 65535 bodies' && [ ! -e sap.h5 ] \
  && ok "96000 floes with the sweep and prune: exit 2 naming solver.broadphase" || fail "sap limit: exit $code: $msg"

# 3. check validates only
"$icedem" check "$src/scenarios/paper/small_floes.toml" >/dev/null && ok "check accepts the paper scenario" \
  || fail "check rejected the paper scenario"

# 3b. the hull as STL for the OpenFOAM case: one facet per triangle, closed
"$icedem" stl "$src/scenarios/paper/small_floes.toml" -o hull.stl >/dev/null \
  && [ "$(grep -c 'facet normal' hull.stl)" -eq "$(grep -c 'endfacet' hull.stl)" ] \
  && [ "$(grep -c 'facet normal' hull.stl)" -gt 100 ] && ok "stl writes the hull" || fail "stl"

# 3c. calibrate writes a scenario with the calibrated joint CFM that check accepts
"$icedem" calibrate "$src/scenarios/validation/plate_deflection_27_015.toml" --set validation.plate_size=1.5 \
  --set time.duration=6 --set solver.iterations=30 --target-modulus 20e6 --write cal.toml >/dev/null 2>&1 \
  && grep -q "^cfm = " cal.toml && "$icedem" check cal.toml >/dev/null 2>&1 \
  && ok "calibrate writes a valid calibrated scenario" || fail "calibrate"

# 4. a short run: summary JSON keys of docs/user/output.md and the HDF5 layout
"$icedem" run "$src/scenarios/examples/short_tow.toml" -o run.h5 --summary-json run.json -q \
  --set time.duration=20 >/dev/null 2>&1 && ok "short run exits 0" || fail "short run failed"
$py - <<'PY' && ok "summary JSON and HDF5 layout" || fail "summary JSON or HDF5 layout"
import json, h5py, math
s = json.load(open("run.json"))
for k in ["mean_fx_N", "max_fx_N", "std_fx_N", "window_s", "breaks", "steps", "sim_time_s", "wall_time_s"]:
    assert k in s, k
assert s["steps"] == 1000 and abs(s["sim_time_s"] - 20) < 1e-9, s
assert math.isfinite(s["mean_fx_N"]) and s["window_s"] > 0, s
with h5py.File("run.h5", "r") as f:
    n = s["steps"]
    assert f["/load/time"].shape == (n,) and f["/load/force"].shape == (n, 3)
    assert f["/load/moment"].shape == (n, 3) and f["/structure/position"].shape == (n, 3)
    assert f["/meta"].attrs["status"] == "complete"
    assert f["/fracture/events"].shape == (0,)
    assert abs(f["/stats"].attrs["mean_fx_N"] - s["mean_fx_N"]) < 1e-12
    # surge load = -Fx: resisting the tow is positive
    assert abs(f["/load/surge"][:] + f["/load/force"][:, 0]).max() == 0
PY

# 4b. nothing written is lost or mixed: a second run on the same -o is refused while the
# first runs (the first completes); -o onto the scenario is refused; an unwritable
# --summary-json is refused before the run
# (the first run is long enough, 200 s simulated, to be still running on a loaded machine)
rm -f same.h5  # a file left by an earlier run of this test would let the second start first
"$icedem" run "$src/scenarios/examples/short_tow.toml" -o same.h5 -q --set time.duration=200 >first.log 2>&1 &
first=$!
for _ in $(seq 300); do [ -s same.h5 ] && break; sleep 0.1; done
msg=$("$icedem" run "$src/scenarios/examples/short_tow.toml" -o same.h5 -q 2>&1); code=$?
wait $first; first_code=$?
[ $code -eq 2 ] && echo "$msg" | grep -q "another icedem run is writing" && [ $first_code -eq 0 ] \
  && ok "a second writer of one file is refused, the first completes" || fail "second writer: $code $first_code $msg"
cp "$src/scenarios/examples/short_tow.toml" input.toml
"$icedem" run input.toml -o input.toml -q >/dev/null 2>&1; code=$?
[ $code -eq 2 ] && cmp -s input.toml "$src/scenarios/examples/short_tow.toml" \
  && ok "-o onto the scenario is refused, the scenario kept" || fail "-o onto the scenario: exit $code"
rm -f nosum.h5
"$icedem" run "$src/scenarios/examples/short_tow.toml" -o nosum.h5 -q --summary-json no/such/dir/s.json >/dev/null 2>&1; code=$?
[ $code -eq 2 ] && [ ! -e nosum.h5 ] && ok "unwritable --summary-json refused before the run" \
  || fail "unwritable --summary-json: exit $code"

# 4c. a full disk (a small tmpfs; needs root, skipped otherwise): exit 5 with one message,
# the file closed, readable and marked failed
mkdir -p full
if mount -t tmpfs -o size=1400k tmpfs full 2>/dev/null; then
  msg=$("$icedem" run "$src/scenarios/examples/short_tow.toml" -o full/out.h5 -q 2>&1); code=$?
  $py -c "
import h5py, sys
with h5py.File('full/out.h5', 'r') as h:
    assert h['/meta'].attrs['status'] == 'failed', h['/meta'].attrs['status']
    assert 'did not fit' in h['/meta'].attrs['message']
    assert len(h['/load/time']) > 0
" && [ $code -eq 5 ] && [ "$(echo "$msg" | grep -c .)" -le 2 ] && echo "$msg" | grep -q "disk full" \
    && ok "full disk: exit 5, one message, file closed and marked failed" || fail "full disk: exit $code: $msg"
  umount full
else
  echo "skipped: full disk (cannot mount a tmpfs here)"
fi

# 5. Ctrl-C (exit 130) and SIGTERM (kill, a Slurm preemption: 143): the file is readable and
#    marked interrupted
for sig in INT TERM; do
  rm -f int.h5 int.h5.checkpoint  # the last one's: an interrupted run's output is resumed, not run over
  "$icedem" run "$src/scenarios/paper/small_floes.toml" -o int.h5 -q --set time.duration=100000 >/dev/null 2>&1 &
  pid=$!
  # interrupt once the file holds some steps (polled: set-up takes longer on a loaded machine)
  for _ in $(seq 120); do
    sleep 0.5
    $py -c "import h5py, sys; sys.exit(0 if h5py.File('int.h5', 'r')['/load/time'].shape[0] > 10 else 1)" 2>/dev/null && break
  done
  kill -$sig $pid
  wait $pid; code=$?
  want=$([ $sig = INT ] && echo 130 || echo 143)
  [ $code -eq $want ] && ok "SIG$sig exits $want" || fail "SIG$sig exit code $code"
  $py -c "
import h5py
f = h5py.File('int.h5', 'r')
assert f['/meta'].attrs['status'] == 'interrupted', f['/meta'].attrs['status']
assert f['/load/time'].shape[0] > 10
" && ok "interrupted file readable and marked (SIG$sig)" || fail "interrupted file (SIG$sig)"
done

# 6. a numerical blow-up: a time step far beyond the buoyancy's stability limit
#    (omega dt = 17.9 rad/s x 0.5 s >> 2): exit 3, a message naming step, floe and
#    quantity, and the file holds the steps before it, marked failed
msg=$("$icedem" run "$src/scenarios/examples/short_tow.toml" -o blow.h5 -q --set time.dt=0.5 \
      --set activation.sleeping=false 2>&1); code=$?
[ $code -eq 3 ] && ok "blow-up exits 3" || fail "blow-up exit code $code: $msg"
echo "$msg" | grep -q "step [0-9]* (t = " && echo "$msg" | grep -q "floe [0-9]*" \
  && ok "blow-up message names step and floe" || fail "blow-up message: $msg"
$py -c "
import h5py
f = h5py.File('blow.h5', 'r')
assert f['/meta'].attrs['status'] == 'failed'
assert 'blow-up' in f['/meta'].attrs['message']
assert f['/load/time'].shape[0] >= 1
" && ok "failed run's file readable and marked" || fail "failed run's file"

# 7. every output goes through one guard: never an input, never another output, never a directory
cp "$src/scenarios/examples/short_tow.toml" guard.toml
before=$(md5sum guard.toml)
mkdir -p a_directory
for args in "-o guard.h5 --summary-json guard.toml" "-o guard.h5 --summary-json guard.h5" \
            "-o guard.h5 --summary-json guard.h5.checkpoint" "-o guard.toml" "-o a_directory"; do
  msg=$("$icedem" run guard.toml $args -q --set time.duration=1 2>&1); code=$?
  [ $code -eq 2 ] && ok "refused with exit 2: run $args" || fail "run $args: exit $code: $msg"
done
[ "$before" = "$(md5sum guard.toml)" ] && ok "the scenario was never overwritten" || fail "guard.toml changed"

# 8. a section given a value, and a NUL in a string: messages that say what is wrong, whole
printf 'structure = 3\n' > section.toml
msg=$("$icedem" check section.toml 2>&1); code=$?
[ $code -eq 2 ] && echo "$msg" | grep -q "'structure' is a section" && ! echo "$msg" | grep -q "did you mean" \
  && ok "a section given a value is named a section" || fail "section given a value: $msg"
printf '[layout]\nfile = "a\\u0000b.csv"\n' > nul.toml
msg=$("$icedem" check nul.toml 2>&1); code=$?
[ $code -eq 2 ] && echo "$msg" | grep -q 'a\\x00b.csv": no such file' \
  && ok "a NUL in a string is shown escaped, the message whole" || fail "NUL in a string: $msg"

# 9. scenes that cannot run right are refused or warned about by check (and run)
tow="$src/scenarios/examples/short_tow.toml"
msg=$("$icedem" check "$tow" --set structure.start_x=7 2>&1); code=$?
[ $code -eq 2 ] && echo "$msg" | grep -q "overlaps the structure at t = 0" \
  && ok "check refuses a floe inside the structure at t = 0" || fail "floe in the structure (check): $code $msg"
rm -f overlap.h5
"$icedem" run "$tow" --set structure.start_x=7 -o overlap.h5 -q >/dev/null 2>&1; code=$?
[ $code -eq 2 ] && [ ! -e overlap.h5 ] && ok "run refuses it too, writing nothing" || fail "floe in the structure (run): $code"
"$icedem" check "$tow" --set water.roll_pitch_damping_ratio=10 | grep -q "water damping cannot be integrated" \
  && ok "check warns of water damping the step cannot integrate" || fail "no warning for damping ratio 10"
"$icedem" check "$tow" --set ice.floe_size=0.02 --set channel.length=0.5 --set channel.width=0.5 \
  | grep -q "narrower than 0.0206 m" && ok "check warns of floes too narrow to float flat" \
  || fail "no warning for 0.02 m floes of 33 mm ice"

# 9b. a layout that would take minutes to relax is refused at once, with its cost
msg=$(timeout 20 "$icedem" check "$tow" --set layout.sweeps=100000 --set ice.floe_size=0.1 --set channel.length=3 2>&1); code=$?
[ $code -eq 2 ] && echo "$msg" | grep -q "Monte-Carlo moves, about 34 s of set-up" \
  && ok "a layout beyond the set-up bound is refused with its cost" || fail "layout bound: $code $msg"

# 10. a signal during set-up (675,000 floes to lay out: seconds) ends the run with a message,
#     exit 128 + the signal, and no empty file left at a new output path
for sig in INT TERM; do
  rm -f setup.h5
  "$icedem" run "$tow" --set channel.length=3000 --set ice.floe_size=0.1 -o setup.h5 -q >setup.log 2>&1 &
  pid=$!
  sleep 1
  kill -$sig $pid
  wait $pid; code=$?
  want=$([ $sig = INT ] && echo 130 || echo 143)
  [ $code -eq $want ] && [ ! -e setup.h5 ] && grep -q "interrupted before the run started" setup.log \
    && ok "SIG$sig during set-up: exit $want, a message, no file" || fail "SIG$sig during set-up: exit $code, $(cat setup.log)"
done

# 10b. a set-up of more than a few seconds says how far it is (not with -q): the same
#      675,000 floes, stopped once the line is seen (or after 30 s)
rm -f setup.h5
"$icedem" run "$tow" --set channel.length=3000 --set ice.floe_size=0.1 -o setup.h5 >setup.log 2>&1 &
pid=$!
for _ in $(seq 60); do
  sleep 0.5
  grep -q "setting up: floe layout .* %" setup.log && break
done
kill -INT $pid; wait $pid
grep -q "setting up: floe layout .* %  ETA" setup.log && ok "a long set-up shows its progress"   || fail "no set-up progress: $(head -c 300 setup.log)"

echo "$passed passed, $failed failed"
[ $failed -eq 0 ]
