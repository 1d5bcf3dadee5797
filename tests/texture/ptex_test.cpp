// Ptex files (texture/ptex_file.h) written by tests/ptex_writer.h and read back: texels of every encoding
// (constant, zipped, difference-zipped, tiled) and data type, the file's stored reductions and the ones made
// as Ptex makes them; Ptex's B-spline filter (texture/ptex_filter.h) against its closed form at and between
// texel centres, over wider footprints, at the borders, and across edges and corners into adjacent faces; the
// "ptex" texture's encoding and scale (texture/ptex_texture.h); broken files are errors naming the file. (A
// throwaway program linking pbrt-v4's libPtex compared ptex_filter with Ptex's own f_bspline filter:
// docs/verification.md, "Ptex textures".)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "illum/texture/ptex_file.h"
#include "illum/texture/ptex_filter.h"
#include "illum/texture/ptex_texture.h"
#include "illum/util/error.h"
#include "ptex_writer.h"

namespace illum {
namespace {

using test::TestFace;
using test::write_ptex;

// A face of 2^ulog2 x 2^vlog2 texels with distinct values below `max`.
TestFace face(int ulog2, int vlog2, int encoding, int nch, int seed, double max) {
    TestFace f{ulog2, vlog2, encoding, {}};
    int n = (1 << ulog2) * (1 << vlog2) * nch;
    for (int i = 0; i < n; ++i) f.texels.push_back(std::fmod(37.0 * (i + 1) * (seed + 3), max));
    if (encoding == 0) // a constant face: one texel
        f.texels = std::vector<double>(f.texels.begin(), f.texels.begin() + nch);
    return f;
}

TEST(Ptex, EveryEncodingAndDataTypeReadsBack) {
    for (int type : {0, 1, 3}) {
        double max = type == 0 ? 256 : type == 1 ? 65536 : 1000;
        double scale = type == 0 ? 255 : type == 1 ? 65535 : 1;
        std::vector<TestFace> faces = {face(2, 1, 1, 3, 1, max), face(0, 0, 0, 3, 2, max),
                                       face(3, 2, 2, 3, 3, max), face(2, 2, 3, 3, 4, max),
                                       face(1, 3, 1, 3, 5, max)};
        PtexFile f = PtexFile::read(write_ptex("types.ptx", faces, 3, type));
        ASSERT_EQ(f.faces.size(), faces.size());
        EXPECT_EQ(f.channels, 3);
        for (std::size_t i = 0; i < faces.size(); ++i) {
            const PtexFace& got = f.faces[i];
            EXPECT_EQ(got.ures(), 1 << faces[i].ulog2);
            EXPECT_EQ(got.vres(), 1 << faces[i].vlog2);
            for (int v = 0; v < got.vres(); ++v)
                for (int u = 0; u < got.ures(); ++u)
                    for (int c = 0; c < 3; ++c) {
                        std::size_t k = faces[i].encoding == 0 ? std::size_t(c)
                                                               : std::size_t((v * got.ures() + u) * 3 + c);
                        EXPECT_NEAR(f.texel(int(i), u, v, c), faces[i].texels[k] / scale, 1e-6)
                            << "type " << type << " face " << i;
                    }
        }
    }
}

// The file's reduction levels are read (a marker stored in face 1's first reduction comes back), and the
// others are made as Ptex's reader makes them: pairs averaged along u or v in the data type, rounded down.
TEST(Ptex, ReductionsComeFromTheFileOrArePairAveragesRoundedDown) {
    std::vector<TestFace> faces = {face(3, 3, 1, 1, 1, 256), face(4, 3, 1, 1, 2, 256),
                                   face(1, 1, 1, 1, 3, 256)};
    test::PtexOptions o;
    o.reductions = true;
    o.marked_face = 1;
    o.marker = 77;
    PtexFile f = PtexFile::read(write_ptex("reductions.ptx", faces, 1, 0, o));
    // Face 1 (16 x 8): level 1 is 8 x 4, the marker.
    const PtexFace& f1 = f.faces[1];
    for (int i = 0; i < 8 * 4; ++i) EXPECT_EQ(f1.level(3, 2)[i], 77.0f);
    // Face 0 (8 x 8): level 1 is stored (the writer's 2 x 2 average, rounded down, as Ptex's writer).
    const PtexFace& f0 = f.faces[0];
    const std::vector<double>& t = faces[0].texels;
    auto at = [&](int u, int v) { return t[std::size_t(v * 8 + u)]; };
    for (int v = 0; v < 4; ++v)
        for (int u = 0; u < 4; ++u)
            EXPECT_EQ(f0.level(2, 2)[v * 4 + u],
                      std::floor((at(2 * u, 2 * v) + at(2 * u + 1, 2 * v) + at(2 * u, 2 * v + 1) +
                                  at(2 * u + 1, 2 * v + 1)) /
                                 4));
    // (2, 3): from (3, 3) along u; (2, 1): from (2, 2), the stored level, along v.
    for (int v = 0; v < 8; ++v)
        for (int u = 0; u < 4; ++u)
            EXPECT_EQ(f0.level(2, 3)[v * 4 + u], std::floor((at(2 * u, v) + at(2 * u + 1, v)) / 2));
    for (int v = 0; v < 2; ++v)
        for (int u = 0; u < 4; ++u)
            EXPECT_EQ(f0.level(2, 1)[v * 4 + u],
                      std::floor((f0.level(2, 2)[2 * v * 4 + u] + f0.level(2, 2)[(2 * v + 1) * 4 + u]) / 2));
    // Face 2 (2 x 2) has no stored reduction: (1, 1) is the face, (0, 0) the constant data (the mean,
    // rounded down), (1, 0) the v pairs.
    const std::vector<double>& t2 = faces[2].texels;
    EXPECT_EQ(f.faces[2].level(0, 0)[0], std::floor((t2[0] + t2[1] + t2[2] + t2[3]) / 4 + 1e-9));
    EXPECT_EQ(f.faces[2].level(1, 0)[0], std::floor((t2[0] + t2[2]) / 2));
    EXPECT_EQ(f.faces[2].level(1, 0)[1], std::floor((t2[1] + t2[3]) / 2));
}

// The cubic B-spline of Ptex's f_bspline filter, written out: 1/6 of (4 - 6x² + 3|x|³) and (2 - |x|)³.
double bspline(double x) {
    x = std::abs(x);
    return x < 1 ? (4 - 6 * x * x + 3 * x * x * x) / 6 : x < 2 ? std::pow(2 - x, 3) / 6 : 0;
}

// The filter along u on a row of `res` texels t (float data) at u with a footprint of `width` texels (1 to
// 2): the B-spline stretched to the width, taps beyond the edges on the edge texels.
double filtered_row(const std::vector<double>& t, double u, double width) {
    const int res = int(t.size());
    double upix = u * res - 0.5, sum = 0, wsum = 0;
    for (int i = int(std::floor(upix - 2 * width)); i <= int(std::ceil(upix + 2 * width)); ++i) {
        double w = bspline((i - upix) / width);
        sum += w * t[std::size_t(std::clamp(i, 0, res - 1))];
        wsum += w;
    }
    return sum / wsum;
}

TEST(PtexFilter, BSplineAtAndBetweenTexelCentres) {
    TestFace row{3, 0, 1, {0.1, 0.9, 0.3, 0.5, 0.25, 0.75, 1.0, 0.0}}; // 8 x 1, float
    PtexFile f = PtexFile::read(write_ptex("row.ptx", {row}, 1, 3));
    float out = 0;
    // At texel centres with no footprint: 1/6, 2/3, 1/6 of the texel and its neighbours.
    for (int m = 0; m < 8; ++m) {
        ptex_filter(f, 0, (m + 0.5f) / 8, 0.5f, 0, 0, 0, 0, &out);
        double left = row.texels[std::size_t(std::max(m - 1, 0))],
               right = row.texels[std::size_t(std::min(m + 1, 7))];
        EXPECT_NEAR(out, (left + 4 * row.texels[std::size_t(m)] + right) / 6, 1e-6) << "texel " << m;
    }
    // Between centres, and a footprint of 1.5 texels (the ray differentials' |du/dx| + |du/dy|).
    for (float u : {0.0f, 0.03f, 0.3f, 0.47f, 0.71f, 0.98f, 1.0f}) {
        ptex_filter(f, 0, u, 0.5f, 0, 0, 0, 0, &out);
        EXPECT_NEAR(out, filtered_row(row.texels, u, 1), 1e-6) << "u " << u;
        ptex_filter(f, 0, u, 0.5f, 1.0f / 8, 0, -0.5f / 8, 0, &out);
        EXPECT_NEAR(out, filtered_row(row.texels, u, 1.5), 1e-6) << "u " << u;
    }
    // A face index outside the file: 0.
    out = 1;
    ptex_filter(f, 3, 0.5f, 0.5f, 0, 0, 0, 0, &out);
    EXPECT_EQ(out, 0.0f);
}

TEST(PtexFilter, WideFootprintsReadTheReductions) {
    TestFace big = face(3, 3, 1, 1, 1, 256); // 8 x 8, uint8
    test::PtexOptions o;
    o.reductions = true;
    o.marked_face = 0;
    o.marker = 200; // the stored 4 x 4 reduction
    PtexFile f = PtexFile::read(write_ptex("wide.ptx", {big}, 1, 0, o));
    float out = 0;
    // A footprint of two texels: the 4 x 4 level, which is all 200.
    ptex_filter(f, 0, 0.4f, 0.6f, 2.0f / 8, 0, 0, 2.0f / 8, &out);
    EXPECT_NEAR(out, 200.0f / 255, 1e-6);
    // The whole face: its mean (the constant data).
    ptex_filter(f, 0, 0.4f, 0.6f, 1, 0, 0, 1, &out);
    EXPECT_NEAR(out, f.faces[0].level(0, 0)[0] / 255, 1e-6);
    // Constant faces are their value for every footprint.
    PtexFile c = PtexFile::read(write_ptex("constant.ptx", {test::constant_face({10, 20, 30})}, 3, 0));
    float rgb[3];
    for (float w : {0.0f, 0.1f, 0.3f, 0.7f, 2.0f}) {
        ptex_filter(c, 0, 0.2f, 0.9f, w, 0, 0, w, rgb);
        EXPECT_NEAR(rgb[0], 10.0f / 255, 1e-6);
        EXPECT_NEAR(rgb[1], 20.0f / 255, 1e-6);
        EXPECT_NEAR(rgb[2], 30.0f / 255, 1e-6);
    }
}

TEST(PtexFilter, BorderModes) {
    TestFace row{3, 0, 1, {0.1, 0.9, 0.3, 0.5, 0.25, 0.75, 1.0, 0.0}};
    float a, b;
    test::PtexOptions periodic;
    periodic.u_border = 2;
    PtexFile p = PtexFile::read(write_ptex("periodic.ptx", {row}, 1, 3, periodic));
    EXPECT_EQ(p.u_border, PtexBorder::Periodic);
    ptex_filter(p, 0, 1.3f, 0.5f, 0, 0, 0, 0, &a);
    ptex_filter(p, 0, 0.3f, 0.5f, 0, 0, 0, 0, &b);
    EXPECT_NEAR(a, b, 1e-6);
    test::PtexOptions black;
    black.u_border = 1;
    PtexFile k = PtexFile::read(write_ptex("black.ptx", {row}, 1, 3, black));
    for (float u : {1.5f, 2.5f, -1.5f}) {
        ptex_filter(k, 0, u, 0.5f, 0, 0, 0, 0, &a);
        EXPECT_EQ(a, 0.0f) << u;
    }
    // Inside, the taps beyond the edge are dropped but the weight stays: the first texel centre keeps
    // 2/3 + 1/6 of the kernel's weight.
    ptex_filter(k, 0, 0.5f / 8, 0.5f, 0, 0, 0, 0, &a);
    EXPECT_NEAR(a, (4 * 0.1 + 0.9) / 6, 1e-6);
    // Clamp (the default): u beyond the face reads its edge.
    PtexFile c = PtexFile::read(write_ptex("clamp.ptx", {row}, 1, 3));
    ptex_filter(c, 0, 1.7f, 0.5f, 0, 0, 0, 0, &a);
    ptex_filter(c, 0, 1.0f, 0.5f, 0, 0, 0, 0, &b);
    EXPECT_EQ(a, b);
}

// Across edges and corners (Ptex's splitAndApply): 4 x 4 faces of one value each around a corner (a, b, c, d
// in the order lower left, lower right, upper left, upper right); at the corner texel of the first face the
// B-spline's (1/6, 2/3, 1/6) along each axis gives the faces 25/36, 5/36, 5/36 and 1/36 of the weight.
TEST(PtexFilter, KernelsReachAcrossEdgesAndCorners) {
    auto uniform = [](double value) {
        TestFace f{2, 2, 1, std::vector<double>(16, value)};
        return f;
    };
    std::vector<TestFace> grid = {uniform(0.1), uniform(0.3), uniform(0.7), uniform(0.9)};
    auto link = [&](int f, int e, int g, int ge) {
        grid[std::size_t(f)].adjacent[e] = g;
        grid[std::size_t(f)].edges[e] = ge;
        grid[std::size_t(g)].adjacent[ge] = f;
        grid[std::size_t(g)].edges[ge] = e;
    };
    link(0, 1, 1, 3); // right of 0 is left of 1
    link(0, 2, 2, 0); // top of 0 is bottom of 2
    link(1, 2, 3, 0);
    link(2, 1, 3, 3);
    float out = 0;
    const float corner = 3.5f / 4;
    PtexFile four = PtexFile::read(write_ptex("grid.ptx", grid, 1, 3));
    ptex_filter(four, 0, corner, corner, 0, 0, 0, 0, &out);
    EXPECT_NEAR(out, (25 * 0.1 + 5 * 0.3 + 5 * 0.7 + 0.9) / 36, 1e-6);
    // Across the right edge only (v at a texel centre away from the top).
    ptex_filter(four, 0, corner, 1.5f / 4, 0, 0, 0, 0, &out);
    EXPECT_NEAR(out, (5 * 0.1 + 0.3) / 6, 1e-6);
    // Without the corner face (a boundary vertex), its weight is left out of the normalisation.
    grid[1].adjacent[2] = grid[2].adjacent[1] = -1;
    grid.pop_back();
    PtexFile three = PtexFile::read(write_ptex("three.ptx", grid, 1, 3));
    ptex_filter(three, 0, corner, corner, 0, 0, 0, 0, &out);
    EXPECT_NEAR(out, (25 * 0.1 + 5 * 0.3 + 5 * 0.7) / 35, 1e-6);
    // A neighbour turned a quarter: face 1's bottom edge on face 0's right edge, which runs the other way,
    // so face 0's texel row j meets face 1's column 3 - j of its bottom row.
    TestFace turned{2, 2, 1, {}};
    for (int v = 0; v < 4; ++v)
        for (int u = 0; u < 4; ++u) turned.texels.push_back(0.01 * (10 * u + v));
    std::vector<TestFace> pair = {uniform(0.1), turned};
    pair[0].adjacent[1] = 1;
    pair[0].edges[1] = 0;
    pair[1].adjacent[0] = 0;
    pair[1].edges[0] = 1;
    PtexFile rotated = PtexFile::read(write_ptex("turned.ptx", pair, 1, 3));
    ptex_filter(rotated, 0, corner, 1.5f / 4, 0, 0, 0, 0, &out);
    auto t = [&](int u) { return 0.01 * (10 * u); };
    EXPECT_NEAR(out, 5 * 0.1 / 6 + (t(3) / 6 + 2 * t(2) / 3 + t(1) / 6) / 6, 1e-6);
}

TEST(PtexTexture, EncodingQuantisesToEightBitsAndScaleMultiplies) {
    auto file = std::make_shared<const PtexFile>(
        PtexFile::read(write_ptex("encoding.ptx", {test::constant_face({128, 64, 255})}, 3, 0)));
    TextureEvalContext ctx;
    ctx.uv = {0.5f, 0.5f};
    Color3 linear = PtexColorTexture(PtexLookup(file, 1, 1)).evaluate(ctx);
    EXPECT_NEAR(linear.r, 128.0f / 255, 1e-6);
    EXPECT_NEAR(linear.g, 64.0f / 255, 1e-6);
    EXPECT_NEAR(linear.b, 1.0f, 1e-6);
    Color3 gamma = PtexColorTexture(PtexLookup(file, 2.2f, 2)).evaluate(ctx);
    EXPECT_NEAR(gamma.r, 2 * std::pow(128.0 / 255, 2.2), 1e-6);
    EXPECT_NEAR(gamma.g, 2 * std::pow(64.0 / 255, 2.2), 1e-6);
    Color3 srgb = PtexColorTexture(PtexLookup(file, 0, 1)).evaluate(ctx);
    EXPECT_NEAR(srgb.r, std::pow((128.0 / 255 + 0.055) / 1.055, 2.4), 1e-6);
    EXPECT_NEAR(PtexFloatTexture(PtexLookup(file, 1, 3)).evaluate(ctx), (128.0 + 64 + 255) / 255, 1e-5);
    // A float file's 0.5 is quantised to 128 before a gamma decodes it, as pbrt-v4 does.
    auto half = std::make_shared<const PtexFile>(
        PtexFile::read(write_ptex("half.ptx", {test::constant_face({0.5})}, 1, 3)));
    EXPECT_NEAR(PtexFloatTexture(PtexLookup(half, 2.2f, 1)).evaluate(ctx), std::pow(128.0 / 255, 2.2), 1e-6);
    EXPECT_NEAR(PtexFloatTexture(PtexLookup(half, 1, 1)).evaluate(ctx), 0.5, 1e-7);
    // The face comes from the context.
    auto two = std::make_shared<const PtexFile>(
        PtexFile::read(write_ptex("two.ptx", {test::constant_face({10}), test::constant_face({20})}, 1, 0)));
    ctx.face_index = 1;
    EXPECT_NEAR(PtexFloatTexture(PtexLookup(two, 1, 1)).evaluate(ctx), 20.0f / 255, 1e-6);
}

TEST(Ptex, BrokenFilesAreErrorsNamingTheFile) {
    std::string good = test::ptex_bytes({face(2, 2, 1, 3, 1, 256)}, 3, 0);
    std::string path = ::testing::TempDir() + "broken.ptx";
    auto expect = [&](const std::string& bytes, const std::string& needle) {
        std::ofstream(path, std::ios::binary) << bytes;
        try {
            PtexFile::read(path);
            ADD_FAILURE() << "no error for " << needle;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("broken.ptx"), std::string::npos) << e.what();
        }
    };
    expect("Ptxx" + good.substr(4), "does not start with \"Ptex\"");
    expect(good.substr(0, good.size() - 10), "truncated");
    std::string bad_type = good;
    bad_type[12] = 9;
    expect(bad_type, "unknown data type 9");
}

} // namespace
} // namespace illum
