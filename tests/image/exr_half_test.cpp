// EXR output as pbrt-v4 writes its film: half channels when asked (values rounded to the nearest half,
// those above the largest half clamped to it), and a crop as the data window of the full display window.
#include <gtest/gtest.h>

#include <ImfChannelList.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <half.h>

#include "illum/image/exr.h"
#include "illum/image/image_io.h"
#include "illum/util/error.h"
#include "image/test_util.h"

namespace illum {
namespace {

using test::ScratchDir;

TEST(ExrHalf, WritesHalfChannelsRoundedFromFloat) {
    ScratchDir dir;
    Image img = test::test_image(19, 11);
    img(2, 3) = Color3(70000.0f, 65504.0f, -3.25f); // above the largest half, the largest, negative
    img(4, 5) = Color3(1.0f / 3, 1e-6f, 12345.678f);
    const std::string path = dir.file("h.exr");
    WriteOptions opts;
    opts.exr.half = true;
    write_image(img, path, opts);

    Imf::InputFile file(path.c_str());
    for (const char* name : {"R", "G", "B"}) {
        ASSERT_NE(file.header().channels().findChannel(name), nullptr) << name;
        EXPECT_EQ(file.header().channels().findChannel(name)->type, Imf::HALF) << name;
    }
    Image back = read_image(path);
    ASSERT_EQ(back.width(), img.width());
    ASSERT_EQ(back.height(), img.height());
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x)
            for (int c = 0; c < 3; ++c) {
                float v = std::min(img(x, y)[c], 65504.0f);
                EXPECT_EQ(back(x, y)[c], float(half(v))) << x << "," << y << " " << c;
            }
    EXPECT_EQ(back(2, 3).r, 65504.0f);
    // Half keeps 11 significant bits: a relative error of at most 2^-11 for normal values.
    EXPECT_NEAR(back(4, 5).r, 1.0f / 3, (1.0f / 3) * 0x1p-11f);
    EXPECT_NE(back(4, 5).r, 1.0f / 3);
}

TEST(ExrHalf, ACropIsTheDataWindowOfTheFullDisplayWindow) {
    ScratchDir dir;
    Image crop = test::test_image(5, 3);
    const std::string path = dir.file("c.exr");
    WriteOptions opts;
    opts.exr.display_width = 12;
    opts.exr.display_height = 9;
    opts.exr.x0 = 4;
    opts.exr.y0 = 6;
    write_image(crop, path, opts);
    Imf::InputFile file(path.c_str());
    const Imath::Box2i& dw = file.header().dataWindow();
    const Imath::Box2i& disp = file.header().displayWindow();
    EXPECT_EQ(disp.max.x, 11);
    EXPECT_EQ(disp.max.y, 8);
    EXPECT_EQ(dw.min.x, 4);
    EXPECT_EQ(dw.min.y, 6);
    EXPECT_EQ(dw.max.x, 8);
    EXPECT_EQ(dw.max.y, 8);
    // Read back over the display window: the crop in place, black elsewhere.
    Image back = read_image(path);
    ASSERT_EQ(back.width(), 12);
    ASSERT_EQ(back.height(), 9);
    for (int y = 0; y < 9; ++y)
        for (int x = 0; x < 12; ++x) {
            bool inside = x >= 4 && x < 9 && y >= 6;
            EXPECT_EQ(back(x, y), inside ? crop(x - 4, y - 6) : Color3(0.0f)) << x << "," << y;
        }
    opts.exr.x0 = 8; // 8 + 5 > 12
    EXPECT_THROW(write_image(crop, dir.file("bad.exr"), opts), Error);
}

} // namespace
} // namespace illum
