#!/usr/bin/env bash
# The sanitizer stage of CI, after tools/test.sh (.ci/run): builds everything with
# AddressSanitizer and UndefinedBehaviorSanitizer (GCC, TSTYLES_SANITIZE=ON) into build-asan/, runs
# the tests there, then each fuzz target for FUZZ_SECONDS (default 20; tools/fuzz.sh, clang; 0 leaves
# the fuzzing out, as .ci/run does after its own fuzz stage).
# docs/testing.md, "Sanitizers" says what runs, what is left out and why, and what it costs.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build-asan"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)

start=$SECONDS
# Without the render, window and MPI equivalence test programs (TSTYLES_RENDER_TESTS): the program
# renders under the sanitizers through the cli tests; docs/testing.md says what that leaves out.
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTSTYLES_SANITIZE=ON -DTSTYLES_RENDER_TESTS=OFF \
    "${launcher[@]}" >/dev/null
cmake --build "$build" -j "$(nproc)"
echo "sanitize: build took $((SECONDS - start)) s"

# Any report fails the test that caused it: UBSan stops (-fno-sanitize-recover), ASan and LSan exit
# non-zero. LSan ignores only the Mesa driver's memory at exit (tools/sanitizers/lsan.supp), which
# it can name only while the driver is still loaded: keep_libraries_loaded.so makes dlclose() keep
# it (preloaded ahead of libasan, hence verify_asan_link_order=0).
cc -shared -fPIC -o "$build/keep_libraries_loaded.so" "$root/tools/sanitizers/keep_libraries_loaded.c"
export LD_PRELOAD="$build/keep_libraries_loaded.so"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0:strict_string_checks=1:detect_stack_use_after_return=0:verify_asan_link_order=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS="suppressions=$root/tools/sanitizers/lsan.supp:print_suppressions=0"
# Readers run in-process here: GCC 12's AddressSanitizer allocator is not fork-safe, and a reader
# process forked while a library's thread pool (OpenEXR's, log4cplus's: they start when the libraries
# load) was allocating waited for good on the allocator's lock (cli.check.deterministic_renders, under
# ctest -j2). The isolation itself is tested in tools/test.sh's plain build (docs/testing.md).
export TSTYLES_READ_IN_PROCESS=1
start=$SECONDS
# The Python module is not built here (CMakeLists.txt says why); TSTYLES_SANITIZE_EXCLUDE, a ctest
# regular expression, leaves out more.
cd "$build"
ctest --output-on-failure -j "$(nproc)" ${TSTYLES_SANITIZE_EXCLUDE:+-E "$TSTYLES_SANITIZE_EXCLUDE"}
echo "sanitize: tests took $((SECONDS - start)) s"

unset LD_PRELOAD
if [ "${FUZZ_SECONDS:-20}" != 0 ]; then
  start=$SECONDS
  "$root/tools/fuzz.sh" all "${FUZZ_SECONDS:-20}"
  echo "sanitize: fuzzing took $((SECONDS - start)) s"
fi
