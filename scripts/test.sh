#!/usr/bin/env bash
# Builds newtop with warnings as errors, runs every test and example (ctest), checks formatting,
# and proves the installed CMake package works by building a small consumer project against it.
# Usage: scripts/test.sh [BUILD_DIR]   (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
jobs=$(nproc 2>/dev/null || echo 2)

scripts/install-deps.sh

echo "== format check (clang-format, .clang-format)"
mapfile -t sources < <(git ls-files '*.cpp' '*.hpp' 2>/dev/null || find include src apps tests bench -name '*.[ch]pp')
clang-format --dry-run --Werror "${sources[@]}"

echo "== build"
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DNEWTOP_WERROR=ON -DNEWTOP_BUILD_BENCH=ON
cmake --build "$build" -j "$jobs"

echo "== tests and examples"
ctest --test-dir "$build" --output-on-failure -j "$jobs"

echo "== installed package: find_package(newtop) from a consumer project"
rm -rf "$build/stage" "$build/consumer"
cmake --install "$build" --prefix "$build/stage" >/dev/null
cmake -S tests/consumer -B "$build/consumer" -G Ninja -DCMAKE_PREFIX_PATH="$PWD/$build/stage"
cmake --build "$build/consumer"
"$build/consumer/newtop_consumer"
echo "all checks passed"
