#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz with clang (TSTYLES_FUZZ=ON, into build-fuzz/) and
# runs TARGET, or every target, for SECONDS each; prints the executions of each target.
#   tools/fuzz.sh TARGET|all SECONDS
# Each run starts from the seed corpus in tests/fuzz/corpus/<target> plus what earlier runs found
# (build-fuzz/corpus/<target>); a finding (crash, sanitizer report, an exception other than
# InputError, a run over -timeout seconds, more than -rss_limit_mb of memory or one allocation over
# -malloc_limit_mb) is written to build-fuzz/findings/<target>/ and the script exits 1.
# Runs under nice: the machine is shared. docs/testing.md, "Fuzzing".
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
targets_all=(manifest scene nrrd netcdf netcdf_header nifti isabel plot3d style_image zarr vtk vtk_legacy vtk_parallel tiff dicom
             dicomdir)
if [[ $# -ne 2 || ! $2 =~ ^[0-9]+$ ]]; then
    echo "usage: tools/fuzz.sh TARGET|all SECONDS   (targets: ${targets_all[*]})" >&2
    exit 2
fi
if [[ $1 == all ]]; then targets=("${targets_all[@]}"); else targets=("$1"); fi
for target in "${targets[@]}"; do
    [[ " ${targets_all[*]} " == *" $target "* ]] || { echo "tools/fuzz.sh: no fuzz target '$target'" >&2; exit 2; }
done
seconds=$2
# FUZZ_RUNS=N (CI): N inputs from a fixed seed instead of SECONDS of time, so that a run finds the
# same things on every machine, whatever its speed.
# The targets that read through a reader process, as the program reads NetCDF-4 and DICOM (a fork
# for each input, tests/fuzz/fuzz_series_file.h), run a tenth of the N inputs: 20 000 forks of an
# instrumented fuzzer took 262 s for NetCDF and over 13 minutes for DICOM on 2 cores.
forking_targets=" netcdf dicom dicomdir "
build="$root/build-fuzz"

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
      -DTSTYLES_FUZZ=ON "${launcher[@]}" >/dev/null
nice cmake --build "$build" -j "$(nproc)" --target "${targets[@]/#/fuzz_}" >/dev/null

# Each fuzzer's scratch files (fuzz_support.h) go under a folder of this run, removed at the end
# even when a finding stopped a fuzzer before its own clean-up.
scratch=$(mktemp -d "$build/scratch.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
status=0
for target in "${targets[@]}"; do
    corpus="$build/corpus/$target" findings="$build/findings/$target"
    mkdir -p "$corpus" "$findings"
    dictionary=()
    [[ $target == manifest || $target == scene ]] && dictionary=(-dict="$root/tests/fuzz/json.dict")
    log="$build/findings/$target.log"
    if [[ -z ${FUZZ_RUNS:-} ]]; then
        length=(-max_total_time="$seconds")
    elif [[ $forking_targets == *" $target "* ]]; then
        length=(-runs="$((FUZZ_RUNS / 10))" -seed=1)
    else
        length=(-runs="$FUZZ_RUNS" -seed=1)
    fi
    # Memory: 16 MiB is the parsers' cap (fuzz_support.h); one allocation over 256 MiB, or 1 GiB in
    # all, means a size from the input got past the checks (OpenImageIO's read_image takes a fixed
    # 64 MiB conversion buffer whatever the image, so the single-allocation limit sits above it).
    # -close_fd_mask=2: the libraries' chatter is dropped, and libFuzzer and the sanitizers report
    # on a copy of stderr, which StderrCapture cannot swallow.
    # Leaks are findings, but for the library leaks tools/sanitizers/lsan.supp explains.
    # From the scratch folder: a reader process that a sanitizer or libFuzzer's malloc limit stops
    # writes its report to ./.PID (the report file of a forked child), which must not litter the tree.
    if (cd "$scratch" && TMPDIR="$scratch" ASAN_OPTIONS=detect_leaks=1 \
           LSAN_OPTIONS="suppressions=$root/tools/sanitizers/lsan.supp:print_suppressions=0" nice "$build/tests/fuzz/fuzz_$target" \
           "${dictionary[@]}" "${length[@]}" -timeout=10 -rss_limit_mb=1024 -malloc_limit_mb=256 -close_fd_mask=2 \
           -max_len=16384 -print_final_stats=1 -artifact_prefix="$findings/" \
           "$corpus" "$root/tests/fuzz/corpus/$target") >"$log" 2>&1; then
        result=ok
    else
        result="FINDING (see $log and $findings/)"
        status=1
    fi
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    time=$(sed -n 's/^Done \([0-9]*\) runs in \([0-9]*\) second.*/\2/p' "$log" | tail -1)
    printf '%-14s %10s executions in %4s s  %s\n' "$target" "${runs:-?}" "${time:-$seconds}" "$result"
done
exit $status
