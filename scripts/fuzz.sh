#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (ASan + UBSan) in build-fuzz/ and runs each of them:
# the .vtree asset reader and the COLMAP model readers (text and binary).
#   scripts/fuzz.sh [SECONDS per target]   (default 60; CI runs 40 for the asset reader, 20 for COLMAP)
# Installs clang and its sanitizer runtimes from Debian when they are missing.
set -euo pipefail
seconds="${1:-60}"
colmap_seconds="${2:-$seconds}"
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${VOLTREE_FUZZ_BUILD:-$root/build-fuzz}"

missing=()
for package in clang libclang-rt-14-dev; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if ((${#missing[@]})); then
  echo "fuzz: installing ${missing[*]}"
  sudo_cmd=()
  [[ $(id -u) -ne 0 ]] && sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends \
    "${missing[@]}" >/dev/null
fi

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DVOLTREE_BUILD_FUZZERS=ON -DVOLTREE_BUILD_TESTS=OFF >/dev/null
nice cmake --build "$build" -j2 --target vtree_fuzzer vtree_fuzz_seeds colmap_fuzzer >/dev/null

# The same sanitizer-runtime flaw as in scripts/sanitize.sh (clang 14 has it too): the leak check's
# tracer can crash on a dynamic TLS block that merely looks like an old glibc header.
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}intercept_tls_get_addr=0"
# -rss_limit_mb / -malloc_limit_mb catch allocations driven by corrupt counts.
limits=(-max_len=65536 -rss_limit_mb=2048 -malloc_limit_mb=1100 -timeout=10 -print_final_stats=1)
vtree_corpus="$build/vtree_corpus"
mkdir -p "$vtree_corpus"
"$build/fuzz/vtree_fuzz_seeds" "$vtree_corpus"
echo "fuzz: .vtree reader for ${seconds}s"
"$build/fuzz/vtree_fuzzer" "$vtree_corpus" -max_total_time="$seconds" "${limits[@]}" 2>&1 | tail -n 12

# COLMAP seed: a small text model in the fuzzer's input layout (byte 0 even = text; bytes 1, 2 =
# where the rest is cut into cameras.txt / images.txt / points3D.txt).
colmap_corpus="$build/colmap_corpus"
mkdir -p "$colmap_corpus"
cameras=$'1 PINHOLE 64 48 50 50 32 24\n2 OPENCV 64 48 50 51 32 24 0.01 0 0 0\n'
images=$'# comment\n1 0.7 0.1 0.1 0.7 0.1 0.2 3 1 a.png\n10 20 -1 30 40 1\n2 1 0 0 0 0 0 1 2 b.png\n\n'
points=$'1 0.1 0.2 3 255 0 0 0.5 1 1 2 0\n'
total=$((${#cameras} + ${#images} + ${#points}))
cut() { printf "\\x$(printf %02x $(($1 * 255 / total)))"; }
{ printf '\x00'; printf "$(cut ${#cameras})"; printf "$(cut $((${#cameras} + ${#images})))";
  printf '%s%s%s' "$cameras" "$images" "$points"; } >"$colmap_corpus/text_model"
echo "fuzz: COLMAP readers for ${colmap_seconds}s"
"$build/fuzz/colmap_fuzzer" "$colmap_corpus" -max_total_time="$colmap_seconds" "${limits[@]}" 2>&1 | tail -n 12
