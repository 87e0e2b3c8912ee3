#!/usr/bin/env bash
# Builds the .vtree libFuzzer target with clang (ASan + UBSan) in build-fuzz/ and runs it.
#   scripts/fuzz.sh [SECONDS]   (default 60; CI runs 60)
set -euo pipefail
seconds="${1:-60}"
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${VOLTREE_FUZZ_BUILD:-$root/build-fuzz}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DVOLTREE_BUILD_FUZZERS=ON -DVOLTREE_BUILD_TESTS=OFF >/dev/null
nice cmake --build "$build" -j2 --target vtree_fuzzer vtree_fuzz_seeds
corpus="$build/vtree_corpus"
mkdir -p "$corpus"
"$build/fuzz/vtree_fuzz_seeds" "$corpus"
# -rss_limit_mb / -malloc_limit_mb catch allocations driven by corrupt counts.
"$build/fuzz/vtree_fuzzer" "$corpus" -max_total_time="$seconds" -max_len=65536 -rss_limit_mb=2048 \
  -malloc_limit_mb=1100 -timeout=10 -print_final_stats=1
