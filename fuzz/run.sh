#!/usr/bin/env bash
# Runs the libFuzzer target that CMake builds in the sanitizer build (cmake/sanitize.cmake, ILLUM_FUZZ):
#   fuzz/run.sh FUZZER WORK_DIR [SECONDS=60] [SHARED_DIR] [more libFuzzer options...]
# e.g. make fuzz, or bash fuzz/run.sh build-sanitize/fuzz-target/pbrt_scene_fuzz build-sanitize/fuzz 600
# Seeds WORK_DIR/corpus with fuzz/seeds (valid scenes, scenes whose files are missing, the malformed
# inputs of tests/pbrt/parser_errors_test.cpp, a PLY) and the shared scenes' .pbrt files when present; new
# inputs that libFuzzer finds stay in WORK_DIR/corpus, crashes go to WORK_DIR/crash-* (or leak-*,
# timeout-*, oom-*). Exits non-zero when the fuzzer finds a crash, a sanitizer report, a non-illum::Error
# exception (the target aborts), a leak or a hang (an input taking over 10 s).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
usage="usage: fuzz/run.sh FUZZER WORK_DIR [SECONDS] [SHARED_DIR] [libFuzzer options]"
bin="$(realpath "${1:?$usage}")"
out="${2:?$usage}"
seconds="${3:-60}"
shared="${4:-$root/../shared}"
shift $(($# < 4 ? $# : 4))
[ -x "$bin" ] || { echo "fuzz: $bin is not built (make sanitize-build)" >&2; exit 2; }
mkdir -p "$out/corpus"
cp -f "$root"/fuzz/seeds/* "$out/corpus/"
if [ -d "$shared/scenes" ]; then
    for f in "$shared"/scenes/*/*.pbrt; do
        [ -f "$f" ] && cp -f "$f" "$out/corpus/$(basename "$(dirname "$f")")-$(basename "$f")"
    done
fi
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=1:print_stacktrace=1"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:+$UBSAN_OPTIONS:}halt_on_error=1:print_stacktrace=1"
export LSAN_OPTIONS="${LSAN_OPTIONS:+$LSAN_OPTIONS:}suppressions=$root/cmake/lsan.supp:print_suppressions=0"
echo "fuzz: $bin for ${seconds}s on $out/corpus ($(ls "$out/corpus" | wc -l) inputs)"
cd "$out"
exec "$bin" -max_total_time="$seconds" -max_len=65536 -timeout=10 -rss_limit_mb=4096 -print_final_stats=1 \
    -artifact_prefix="$PWD/" "$@" corpus
