#!/usr/bin/env bash
# AddressSanitizer + UndefinedBehaviorSanitizer: builds voltree and its tests in their own build
# folder (default build-sanitize/, GCC, -O1 -g1: line tables name a report's file and line, and
# compile a fifth faster than full -g) and runs the unit tests that take seconds, not minutes. Any
# report fails the run (UBSan does not recover; ASan aborts on its first error).
#   scripts/sanitize.sh            environment: BUILD_DIR, JOBS, SANITIZE_TESTS (a ctest -R regex),
#                                  SANITIZE_TARGETS (only these test executables, run directly: what CI does)
# Left out, each for a reason: the end-to-end tests through the binary (*Cli*, BadInput,
# Interrupt: they fork the sanitized binary over whole pipelines), COLMAP runs, and the
# benchmark-sized suites below, which take minutes under ASan's 2-3x slow-down.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${BUILD_DIR:-build-sanitize}
jobs=${JOBS:-$(nproc)}
sanitizers="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
mkdir -p "$build_dir"
echo "sanitize: building in $build_dir with $jobs jobs (log: $build_dir/build.log)"
if ! { cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
         -DCMAKE_CXX_FLAGS="$sanitizers" -DCMAKE_EXE_LINKER_FLAGS="$sanitizers" &&
       cmake --build "$build_dir" -j "$jobs" ${SANITIZE_TARGETS:+--target $SANITIZE_TARGETS}; } >"$build_dir/build.log" 2>&1; then
  grep -E "error|Error" "$build_dir/build.log" | head -40 >&2
  echo "sanitize: build failed; full log: $build_dir/build.log" >&2
  exit 1
fi
# Leaks: Mesa's llvmpipe and TBB's worker pools keep allocations until exit by design, and
# OpenCV's RGB->Lab conversion builds lookup tables once per process and never frees them. OpenCV
# has no frame pointers, so with ASan's fast unwinder its leaks show only cv::fastMalloc: that is
# what is suppressed (our code holds OpenCV memory only in cv::Mat, which frees itself). Full
# unwinding on malloc would name the function but deadlocks in libgcc's unwinder under Mesa.
suppressions="$(cd "$build_dir" && pwd)/lsan.supp"  # absolute: ctest runs each suite in its own folder
printf '%s\n' "leak:libLLVM" "leak:libgallium" "leak:mesa" "leak:libEGL_mesa" "leak:libtbb" \
  "leak:libOpenImageIO" "leak:libfontconfig" "leak:cv::fastMalloc" >"$suppressions"
# intercept_tls_get_addr=0: GCC 12's runtime mistakes a malloc'd dynamic TLS block that happens to
# sit at a particular page offset for a pre-2.25 glibc header and reads past it, so the leak check
# at exit died at random ("Tracer caught signal 11") after every test had passed.
export ASAN_OPTIONS="detect_leaks=1:strict_init_order=1:check_initialization_order=1:intercept_tls_get_addr=0"
export LSAN_OPTIONS="suppressions=$suppressions:print_suppressions=0:intercept_tls_get_addr=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
slow='Cli|BadInput|Interrupt|Colmap|Calibrat|Bench|PhantomTomography|SartCeres|Studio.*Oak|Demo'
if [[ -n ${SANITIZE_TARGETS:-} ]]; then
  for target in $SANITIZE_TARGETS; do
    echo "sanitize: $target"
    (cd "$build_dir/tests" && "./$target" --gtest_brief=1 --gtest_filter="-*Cli*:*BadInput*:*Interrupt*:*Bench*")
  done
else
  ctest --test-dir "$build_dir" --output-on-failure -j "$jobs" --timeout 600 \
    ${SANITIZE_TESTS:+-R "$SANITIZE_TESTS"} -E "$slow"
fi
echo "sanitize: no AddressSanitizer or UndefinedBehaviorSanitizer report"
