#!/usr/bin/env bash
# Records what every subcommand prints and writes on every example: stdout, stderr, the exit code
# and the CSV it writes, one file per run, so that two builds can be compared byte for byte
# (`diff -r BEFORE AFTER`). Run it before and after a change to the program's structure. Known to
# vary from run to run: the sweep's points per second (stderr) and analytic's seconds_per_sample.
# Usage: scripts/snapshot_outputs.sh NEWTOP_BINARY OUT_DIR
set -uo pipefail
newtop=$(realpath "$1")
out=$(realpath -m "$2")
cd "$(dirname "$0")/.."
mkdir -p "$out"
# A fixed working folder, so that the paths the program prints ("written to ...") compare equal.
tmp=/tmp/newtop-snapshot-work
rm -rf "$tmp" && mkdir -p "$tmp"
trap 'rm -rf "$tmp"' EXIT
run() {  # run NAME ARGS...: the program's stdout, stderr and exit code under OUT/NAME.*
  local name=$1
  shift
  (cd "$tmp" && timeout 120 "$newtop" "$@" >"$out/$name.out" 2>"$out/$name.err")
  echo $? >"$out/$name.rc"
  for f in "$tmp"/*; do
    [ -e "$f" ] && mv "$f" "$out/$name.file.$(basename "$f")"
  done
}
commands=(simulate integrals equilibria rotations stability analytic field section chaos
          libration find-integrals)
for f in examples/*.toml; do
  e=$(basename "$f" .toml)
  ex=$(realpath "$f")
  if [[ $e == sweep_* ]]; then
    run "sweep.$e.json" sweep "$ex" --json --out "$tmp/sweep.csv"
    continue
  fi
  for c in "${commands[@]}"; do
    run "$c.$e" "$c" "$ex"
    run "$c.$e.json" "$c" "$ex" --json
  done
  run "simulate.$e.csv" simulate "$ex" --out "$tmp/run.csv"
done
