// libFuzzer target for the whole scene front end: the pbrt-v4 tokenizer and parser, the scene builder
// (shapes, materials, textures, lights, camera, film, Embree BVH) and one 1-spp render of an 8x8 film, plus
// the PLY decoder. Any input must either work or throw illum::Error; a crash, a sanitizer report, a hang
// or any other exception is a bug.
//
// Built by CMake in the sanitizer build (cmake/sanitize.cmake sets ILLUM_FUZZ with clang), linked against
// the whole library; run it with `make fuzz` (fuzz/run.sh seeds the corpus with fuzz/seeds and the shared
// scenes). The CTest `pbrt_scene_fuzz_60s` (label sanitize) runs it for 60 s in `make test-sanitize`.
//
// Relative Include/Import, plymesh, imagemap and environment-map names resolve against a folder that does
// not exist, so a scene's files are always missing, which must be an illum::Error too; only absolute paths
// can reach real files (the parser reads only regular files, so /dev/zero and the like are refused).
// Inputs starting with "ply" go to the PLY decoder as well.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "illum/geometry/ply.h"
#include "illum/render/renderer.h"
#include "illum/scene/build.h"
#include "illum/scene/pbrt/parser.h"
#include "illum/util/error.h"

namespace {

[[noreturn]] void unexpected(const char* stage, const char* what) {
    std::fprintf(stderr, "pbrt_scene_fuzz: %s threw a non-illum::Error exception: %s\n", stage, what);
    std::abort();
}

void parse_build_render(const std::string& text) {
    illum::SceneDesc desc = illum::parse_pbrt_string(text, "fuzz.pbrt", "/nonexistent-fuzz-dir");
    desc.set_film_resolution(8, 8);
    auto scene = illum::build_scene(desc);
    // Bounded work per input: at most 4 bounces (the scene may ask for unbounded depth), 1 spp, 1 thread.
    int depth = scene->request.max_depth < 0 ? 4 : std::min(scene->request.max_depth, 4);
    auto integrator = illum::make_integrator(scene->request.integrator, *scene, depth);
    illum::RenderOptions opt;
    opt.spp = 1;
    opt.threads = 1;
    opt.sampler = scene->request.sampler;
    opt.quiet = true;
    illum::RenderResult r = illum::render(*scene, *integrator, opt);
    (void)r;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string text(reinterpret_cast<const char*>(data), size);
    try {
        parse_build_render(text);
    } catch (const illum::Error&) {
    } catch (const std::exception& e) {
        unexpected("parse/build/render", e.what());
    } catch (...) {
        unexpected("parse/build/render", "(not a std::exception)");
    }
    if (size >= 3 && text.compare(0, 3, "ply") == 0) {
        try {
            illum::TriangleMeshData m = illum::parse_ply(text.data(), text.size(), "fuzz.ply");
            (void)m;
        } catch (const illum::Error&) {
        } catch (const std::exception& e) {
            unexpected("parse_ply", e.what());
        } catch (...) {
            unexpected("parse_ply", "(not a std::exception)");
        }
    }
    return 0;
}
