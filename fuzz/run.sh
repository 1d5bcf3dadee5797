#!/usr/bin/env bash
# Builds the pbrt parser fuzzer with clang (libFuzzer, ASan, UBSan) and runs it for a while.
#   fuzz/run.sh BUILD_DIR [SECONDS=60] [SHARED_DIR]
# Seeds the corpus with the shared scenes' .pbrt files and tests/pbrt's malformed inputs when present.
# Exits non-zero when the fuzzer finds a crash, a sanitizer report or a timeout.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:?usage: fuzz/run.sh BUILD_DIR [SECONDS] [SHARED_DIR]}"
seconds="${2:-60}"
shared="${3:-$root/../shared}"
cxx="${CLANGXX:-clang++}"
mkdir -p "$out/corpus"
bin="$out/pbrt_parser_fuzz"
srcs=(fuzz/pbrt_parser_fuzz.cpp src/illum/scene/pbrt/tokenizer.cpp src/illum/scene/pbrt/parser.cpp
      src/illum/geometry/ply.cpp src/illum/param/param_set.cpp src/illum/math/transform.cpp)
newest=$(cd "$root" && ls -t "${srcs[@]}" src/illum/scene/pbrt/*.h src/illum/scene/*.h | head -1)
if [ ! -x "$bin" ] || [ "$root/$newest" -nt "$bin" ]; then
    echo "fuzz: building $bin"
    (cd "$root" && "$cxx" -std=c++20 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
        -Isrc "${srcs[@]}" -lfmt -lz -o "$bin")
fi
if [ -d "$shared/scenes" ]; then
    for f in "$shared"/scenes/*/*.pbrt; do cp -f "$f" "$out/corpus/$(basename "$(dirname "$f")")-$(basename "$f")"; done
fi
for d in "$root"/tests/pbrt/corpus "$root"/tests/pbrt/malformed; do
    [ -d "$d" ] && cp -f "$d"/* "$out/corpus/" 2>/dev/null || true
done
echo "fuzz: running for ${seconds}s"
cd "$out"
exec "./pbrt_parser_fuzz" -max_total_time="$seconds" -max_len=65536 -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 corpus
