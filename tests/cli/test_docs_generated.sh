#!/usr/bin/env bash
# The generated reference pages are what the program prints today: docs/user/scenario_keys.md
# (`icedem keys`) and docs/user/output.md (`icedem schema`). After changing a key or an output,
# regenerate them with the commands in each page's second line.
set -u
icedem="$1"; root="$2"
status=0
check() {  # check PAGE COMMAND...
  local page="$1"; shift
  if ! diff -u "$root/$page" <("$icedem" "$@") > /dev/null; then
    echo "$page is out of date: run build/dem/icedem $* > $page"
    diff -u "$root/$page" <("$icedem" "$@") | head -20
    status=1
  fi
}
check docs/user/scenario_keys.md keys
check docs/user/output.md schema
exit $status
