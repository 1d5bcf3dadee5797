// Adaptive sampling through the command line: --adaptive renders within the budget and writes its figures to
// --stats; --adaptive-threshold implies it and can end the render early; bad settings and the integrators
// whose work serves every pixel at once (lightpath, sppm, vcm) are refused with one-line errors before
// anything is written.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_support.h"

namespace {

using namespace cli_support;

TEST(AdaptiveCli, RendersWithinTheBudgetAndReportsItsRounds) {
    const fs::path dir = fresh_test_folder("adaptive");
    CliRun a = illum("render --resolution 48x32 --spp 32 --adaptive -o a.exr --stats a.json", dir);
    ASSERT_EQ(a.exit_code, 0) << a.err;
    EXPECT_NE(a.err.find("adaptive: 16-"), std::string::npos) << a.err;
    auto stats = nlohmann::json::parse(read_bytes(dir / "a.json"));
    EXPECT_LE(stats["samples"].get<long long>(), 48LL * 32 * 32);
    EXPECT_EQ(stats["adaptive"]["min_spp"], 16);
    EXPECT_GT(stats["adaptive"]["max_spp"].get<int>(), 32);
    EXPECT_GT(stats["adaptive"]["level"].get<double>(), 0);
    // A threshold no pixel is above: the first two rounds (16 samples a pixel) and no more.
    CliRun t = illum(
        "render --resolution 48x32 --spp 256 --adaptive-threshold 1000 -o t.exr --stats t.json --quiet", dir);
    ASSERT_EQ(t.exit_code, 0) << t.err;
    auto ts = nlohmann::json::parse(read_bytes(dir / "t.json"));
    EXPECT_EQ(ts["samples"].get<long long>(), 48LL * 32 * 16);
    EXPECT_EQ(ts["adaptive"]["rounds"], 2);
    // --adaptive-min-spp implies --adaptive, and sets the first rounds' samples.
    CliRun m =
        illum("render --resolution 48x32 --spp 64 --adaptive-min-spp 4 --adaptive-threshold 1000 -o m.exr "
              "--stats m.json --quiet",
              dir);
    ASSERT_EQ(m.exit_code, 0) << m.err;
    EXPECT_EQ(nlohmann::json::parse(read_bytes(dir / "m.json"))["samples"].get<long long>(), 48LL * 32 * 4);
    // With a time budget the rounds go on until it is spent.
    CliRun u = illum("render --resolution 48x32 --time 0.5 --adaptive -o u.exr --stats u.json --quiet", dir);
    ASSERT_EQ(u.exit_code, 0) << u.err;
    auto us = nlohmann::json::parse(read_bytes(dir / "u.json"));
    EXPECT_GE(us["adaptive"]["rounds"].get<int>(), 3);
    EXPECT_GE(us["seconds"].get<double>(), 0.5);
    EXPECT_GT(us["samples"].get<long long>(), 48LL * 32 * 16);
    fs::remove_all(dir);
}

TEST(AdaptiveCli, BadSettingsAndWholeImageIntegratorsAreRefused) {
    const fs::path dir = fresh_test_folder("adaptive-bad");
    CliRun m = illum("render --resolution 8x8 --spp 4 --adaptive --adaptive-min-spp 12 -o m.exr", dir);
    EXPECT_EQ(m.exit_code, 2);
    EXPECT_NE(m.err.find("power of two"), std::string::npos) << m.err;
    CliRun n = illum("render --resolution 8x8 --spp 4 --adaptive-threshold -1 -o n.exr", dir);
    EXPECT_EQ(n.exit_code, 2) << n.err;
    CliRun b = illum("render --resolution 8x8 --spp 4 --adaptive --integrator sppm -o b.exr", dir);
    EXPECT_EQ(b.exit_code, 2);
    EXPECT_NE(b.err.find("not with lightpath, sppm or vcm"), std::string::npos) << b.err;
    for (const char* f : {"m.exr", "n.exr", "b.exr"}) EXPECT_FALSE(fs::exists(dir / f)) << f;
    fs::remove_all(dir);
}

} // namespace
