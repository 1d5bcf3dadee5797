// The render command's EXR output as pbrt-v4 writes its film (half unless "savefp16" is false; a crop as
// the data window of the full image) and the scene's Option "seed" (the command line's --seed wins).
#include <gtest/gtest.h>

#include <ImfChannelList.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <filesystem>

#include "cli_support.h"
#include "illum/image/image_io.h"

namespace {

namespace fs = std::filesystem;
using cli_support::CliRun;
using cli_support::illum;
using cli_support::read_bytes;
using cli_support::write_text;

class FilmOutputCli : public testing::Test {
protected:
    void SetUp() override { dir_ = cli_support::fresh_test_folder("film"); }
    void TearDown() override { fs::remove_all(dir_); }

    // Renders `film` and `options` of a small lit scene to out.exr and returns the file's R channel type.
    CliRun render(const std::string& film, const std::string& options = "", const std::string& args = "") {
        write_text(dir_ / "s.pbrt", options + R"(
LookAt 0 0 -3  0 0 0  0 1 0
Camera "perspective" "float fov" 40
Film "rgb" "integer xresolution" 12 "integer yresolution" 10 )" +
                                        film + R"(
Sampler "sobol" "integer pixelsamples" 2
WorldBegin
LightSource "infinite" "rgb L" [0.3 0.6 0.9]
Material "diffuse" "rgb reflectance" [0.8 0.4 0.2]
Shape "sphere"
)");
        return illum("render s.pbrt -q -o out.exr " + args, dir_);
    }
    Imf::PixelType channel_type() {
        Imf::InputFile file((dir_ / "out.exr").c_str());
        return file.header().channels().findChannel("R")->type;
    }
    fs::path dir_;
};

TEST_F(FilmOutputCli, ExrIsHalfUnlessTheFilmSaysOtherwise) {
    ASSERT_EQ(render("").exit_code, 0);
    EXPECT_EQ(channel_type(), Imf::HALF);
    illum::Image half_image = illum::read_image((dir_ / "out.exr").string());
    ASSERT_EQ(render("\"bool savefp16\" false").exit_code, 0);
    EXPECT_EQ(channel_type(), Imf::FLOAT);
    illum::Image float_image = illum::read_image((dir_ / "out.exr").string());
    // The same render, its values rounded to half.
    for (int y = 0; y < float_image.height(); ++y)
        for (int x = 0; x < float_image.width(); ++x)
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(half_image(x, y)[c], float_image(x, y)[c], float_image(x, y)[c] * 0x1p-11f);
}

TEST_F(FilmOutputCli, ACropIsWrittenInPlaceInTheFullImage) {
    ASSERT_EQ(render("\"bool savefp16\" false").exit_code, 0);
    illum::Image full = illum::read_image((dir_ / "out.exr").string());
    ASSERT_EQ(render("\"bool savefp16\" false \"integer pixelbounds\" [3 9 2 7]").exit_code, 0);
    Imf::InputFile file((dir_ / "out.exr").c_str());
    EXPECT_EQ(file.header().dataWindow().min.x, 3);
    EXPECT_EQ(file.header().dataWindow().max.y, 6);
    illum::Image cropped = illum::read_image((dir_ / "out.exr").string());
    ASSERT_EQ(cropped.width(), 12);
    for (int y = 0; y < 10; ++y)
        for (int x = 0; x < 12; ++x) {
            bool inside = x >= 3 && x < 9 && y >= 2 && y < 7;
            EXPECT_EQ(cropped(x, y), inside ? full(x, y) : illum::Color3(0.0f)) << x << "," << y;
        }
    // A PNG of a crop holds the kept pixels only.
    ASSERT_EQ(illum("render s.pbrt -q -o crop.png", dir_).exit_code, 0);
    EXPECT_EQ(illum::read_image((dir_ / "crop.png").string()).width(), 6);
}

TEST_F(FilmOutputCli, TheScenesSeedIsUsedUnlessTheCommandLineGivesOne) {
    ASSERT_EQ(render("", "", "--seed 5").exit_code, 0);
    std::string seed5 = read_bytes(dir_ / "out.exr");
    ASSERT_EQ(render("", "", "--seed 0").exit_code, 0);
    std::string seed0 = read_bytes(dir_ / "out.exr");
    ASSERT_NE(seed5, seed0);
    ASSERT_EQ(render("", "Option \"integer seed\" 5\n").exit_code, 0);
    EXPECT_EQ(read_bytes(dir_ / "out.exr"), seed5);
    ASSERT_EQ(render("", "Option \"integer seed\" 5\n", "--seed 0").exit_code, 0);
    EXPECT_EQ(read_bytes(dir_ / "out.exr"), seed0);
}

} // namespace
