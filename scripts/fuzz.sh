#!/usr/bin/env bash
# Fuzzes one reader with libFuzzer under AddressSanitizer and UndefinedBehaviorSanitizer.
# Usage: scripts/fuzz.sh READER SECONDS [JOBS [LIBFUZZER_FLAGS...]]
#        (READER: a tests/fuzz/fuzz_READER.cpp; extra flags override the defaults below, e.g.
#        -max_len=4096 or -runs=1000000)
# Starts from the reader's corpus (tests/fuzz/corpus/READER) and writes what it learns to a scratch
# corpus in build-fuzz/corpus/READER; a crashing, leaking or hanging input is written to
# build-fuzz/artifacts/READER/. Keep each one as a regression case: copy it into
# tests/fuzz/corpus/READER/ (named for what it exercises) once the reader handles it.
set -euo pipefail
cd "$(dirname "$0")/.."
reader=${1:?usage: scripts/fuzz.sh READER SECONDS [JOBS]}
seconds=${2:?usage: scripts/fuzz.sh READER SECONDS [JOBS]}
jobs=${3:-1}
shift $(($# < 3 ? $# : 3))
[ -f "tests/fuzz/fuzz_${reader}.cpp" ] || {
  echo "fuzz.sh: no harness tests/fuzz/fuzz_${reader}.cpp" >&2
  exit 2
}
build=${NEWTOP_FUZZ_BUILD:-build-fuzz}
cmake -S . -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DNEWTOP_FUZZ=ON -DNEWTOP_BUILD_APP=OFF >/dev/null
cmake --build "$build" --target "fuzz_${reader}"
mkdir -p "$build/corpus/$reader" "$build/artifacts/$reader"
cp -n tests/fuzz/corpus/"$reader"/* "$build/corpus/$reader/" 2>/dev/null || true
# Several jobs run as child processes writing fuzz-N.log: keep those logs in the build folder.
parallel=()
if [ "$jobs" -gt 1 ]; then parallel=(-jobs="$jobs" -workers="$jobs"); fi
build=$(cd "$build" && pwd)
cd "$build"
# -timeout: an input that takes longer is a hang; -rss_limit_mb: one that needs more is a failure.
"$build/tests/fuzz/fuzz_${reader}" "$build/corpus/$reader" -max_total_time="$seconds" -timeout=10 \
  -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 \
  -artifact_prefix="$build/artifacts/$reader/" "${parallel[@]}" "$@"
