// libFuzzer target for the pbrt-v4 tokenizer and parser, and the PLY decoder: any input must either parse
// or throw illum::Error; a crash, a sanitizer report, a hang or any other exception is a bug.
//
// It lives outside tests/ so the normal build (which compiles every tests/<folder>/*.cpp into a gtest
// binary) skips it. Build and run with clang (from the repository root):
//
//   mkdir -p build-fuzz && clang++ -std=c++20 -g -O1 -fsanitize=fuzzer,address,undefined -Isrc \
//       fuzz/pbrt_parser_fuzz.cpp src/illum/scene/pbrt/tokenizer.cpp src/illum/scene/pbrt/parser.cpp \
//       src/illum/scene/pbrt/ply.cpp src/illum/scene/param_set.cpp src/illum/math/transform.cpp \
//       -lfmt -lz -o build-fuzz/pbrt_parser_fuzz
//   mkdir -p build-fuzz/corpus && cp ../shared/scenes/*/*.pbrt build-fuzz/corpus/
//   build-fuzz/pbrt_parser_fuzz -max_total_time=300 -max_len=65536 -timeout=10 build-fuzz/corpus
//
// Inputs starting with "ply" go to the PLY decoder as well. Relative Include/Import names resolve against
// a folder that does not exist, so only absolute paths can reach real files (the parser reads only regular
// files, so /dev/zero and the like are refused).
#include <cstddef>
#include <cstdint>
#include <string>

#include "illum/geometry/ply.h"
#include "illum/scene/pbrt/parser.h"
#include "illum/util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string text(reinterpret_cast<const char*>(data), size);
    try {
        illum::SceneDesc s = illum::parse_pbrt_string(text, "fuzz.pbrt", "/nonexistent-fuzz-dir");
        (void)s;
    } catch (const illum::Error&) {
    }
    if (size >= 3 && text.compare(0, 3, "ply") == 0) {
        try {
            illum::TriangleMeshData m = illum::parse_ply(text.data(), text.size(), "fuzz.ply");
            (void)m;
        } catch (const illum::Error&) {
        }
    }
    return 0;
}
