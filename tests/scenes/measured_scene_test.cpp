// pbrt-v4's "measured" material in a scene: a sphere with an RGL table made from a GGX conductor renders
// like the same conductor given analytically (pbrt-v4's "conductor" with "reflectance"), in RGB and
// spectral modes, and reports no unsupported feature; the comparison scene's committed .bsdf file is what
// the generator makes. A missing file is a positioned error.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "illum/bsdf/rgl_tabulate.h"
#include "test_support.h"

namespace illum {
namespace {

namespace fs = std::filesystem;

// The comparison scene's table: GGX α = 0.3, reflectance 0.8 at every wavelength, the RGL database's 32²
// grid with 16 θo nodes.
TensorFile comparison_table() {
    RglTabulation t;
    t.grid = 32;
    t.theta_nodes = 16;
    t.wavelengths = {360, 830};
    t.description = "GGX alpha 0.3, conductor reflectance 0.8 (illum rgl_tabulate)";
    return tabulate_rgl(MicrofacetDistribution(MicrofacetType::GGX, 0.3f, 0.3f),
                        ggx_conductor_brdf(0.3f, [](float) { return 0.8f; }), t);
}

std::string sphere_scene(const std::string& material) {
    return "LookAt 0 0 4  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" [30]\n"
           "Film \"rgb\" \"integer xresolution\" [48] \"integer yresolution\" [48]\n"
           "Integrator \"path\" \"integer maxdepth\" [1]\n"
           "WorldBegin\n"
           "LightSource \"distant\" \"point3 from\" [1 1 1] \"point3 to\" [0 0 0] \"blackbody L\" [5000]\n"
           "LightSource \"infinite\" \"rgb L\" [0.2 0.25 0.3]\n" +
           material + "\nShape \"sphere\" \"float radius\" [1]\n";
}

TEST(MeasuredScene, CommittedComparisonTableIsTheGeneratorsOutput) {
    fs::path committed = fs::path(ILLUM_SOURCE_DIR) / "scenes" / "measured" / "ggx_conductor.bsdf";
    std::string path = ::testing::TempDir() + "ggx_conductor.bsdf";
    comparison_table().write(path);
    auto bytes = [](const fs::path& p) {
        std::ifstream in(p, std::ios::binary);
        return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    };
    std::string a = bytes(committed), b = bytes(path);
    EXPECT_EQ(a.size(), b.size()) << committed;
    EXPECT_TRUE(a == b) << committed << " differs from the generator's output";
}

TEST(MeasuredScene, RendersLikeTheAnalyticConductor) {
    std::string path = ::testing::TempDir() + "sphere_ggx.bsdf";
    comparison_table().write(path);
    std::string measured = sphere_scene("Material \"measured\" \"string filename\" \"" + path + "\"");
    std::string analytic = sphere_scene("Material \"conductor\" \"spectrum reflectance\" [300 0.8 900 0.8] "
                                        "\"float roughness\" [0.3] \"bool remaproughness\" false");
    {
        SceneDesc desc = parse_pbrt_string(measured, "<test>", ".");
        EXPECT_TRUE(build_scene(desc)->unsupported.empty());
    }
    for (bool spectral : {false, true}) {
        test::RenderSetup setup;
        setup.spp = 64;
        setup.spectral = spectral;
        Image a = test::render_pbrt(measured, setup).image, b = test::render_pbrt(analytic, setup).image;
        for (int c = 0; c < 3; ++c) {
            test::MeanEstimate ma = test::pixel_mean(a, c), mb = test::pixel_mean(b, c);
            double sigma = std::hypot(ma.standard_error, mb.standard_error);
            std::printf("%s channel %d: measured %.5f ± %.5f, analytic %.5f ± %.5f\n",
                        spectral ? "spectral" : "rgb", c, ma.mean, ma.standard_error, mb.mean,
                        mb.standard_error);
            // Noise (4σ) plus the tables' interpolation error (1% of f on average, MeasuredTest).
            EXPECT_NEAR(ma.mean, mb.mean, 4 * sigma + 0.01 * mb.mean) << "channel " << c;
        }
    }
}

TEST(MeasuredScene, MissingFileIsAPositionedError) {
    std::string scene = sphere_scene("Material \"measured\" \"string filename\" \"/nonexistent/x.bsdf\"");
    try {
        build_scene(parse_pbrt_string(scene, "m.pbrt", "."));
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("m.pbrt:8:"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("x.bsdf"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace illum
