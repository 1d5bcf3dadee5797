#include "illum/image/ldr.h"

#include <gtest/gtest.h>

#include <cmath>

#include "illum/image/image_io.h"
#include "illum/util/error.h"
#include "image/test_util.h"

namespace illum {
namespace {

using test::ScratchDir;

TEST(Png, RoundTripWithinQuantisation) {
    ScratchDir dir;
    Image img(16, 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) img(x, y) = {float(x) / 15.0f, float(y) / 15.0f, float(x * y) / 225.0f};
    img(0, 0) = Color3(0.0005f, 0.002f, 0.01f); // the linear segment near black
    const std::string path = dir.file("a.png");
    write_image(img, path);
    const Image back = read_image(path);
    ASSERT_EQ(back.width(), 16);
    ASSERT_EQ(back.height(), 16);
    // 8-bit quantisation happens in sRGB space: within half a code value there.
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x)
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(srgb_encode(back(x, y)[c]), srgb_encode(img(x, y)[c]), 0.5f / 255.0f + 1e-6f)
                    << x << "," << y << " channel " << c;
    EXPECT_EQ(back(15, 15), Color3(1.0f));
    EXPECT_EQ(back(0, 15).r, 0.0f);
}

TEST(Png, ExposureAndToneMapApply) {
    ScratchDir dir;
    const std::string path = dir.file("t.png");
    const Image img(2, 2, Color3(0.25f, 2.0f, 0.0f));
    write_image(img, path, {.exposure_stops = 2.0f, .exr = {}}); // 0.25 * 4 = 1 -> white; 8 -> clamped
    Image back = read_image(path);
    EXPECT_EQ(back(1, 1), Color3(1.0f, 1.0f, 0.0f));

    write_image(img, path, {.exposure_stops = 0.0f, .tonemap = ToneMap::Reinhard, .exr = {}});
    back = read_image(path);
    // 0.25 -> 0.2, 2 -> 2/3, each quantised to 8-bit sRGB.
    EXPECT_EQ(back(0, 0).r, srgb8_decode(srgb8_encode(0.2f)));
    EXPECT_EQ(back(0, 0).g, srgb8_decode(srgb8_encode(2.0f / 3.0f)));
    EXPECT_NEAR(back(0, 0).g, 2.0f / 3.0f, 0.005f);

    // The bytes of the PNG itself: 8-bit code values.
    const std::string bytes = encode_png(Image(1, 1, Color3(0.5f)), ToneMap::Clamp, 0.0f);
    const Image decoded =
        decode_ldr({reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()}, "x");
    EXPECT_EQ(decoded(0, 0), Color3(srgb8_decode(188)));
}

TEST(Png, CorruptFilesThrow) {
    ScratchDir dir;
    const std::string good = dir.file("good.png");
    write_image(test::test_image(32, 32), good);
    const std::string bytes = test::file_contents(good);
    const std::string path = dir.file("bad.png");
    for (std::size_t cut : {std::size_t(4), std::size_t(30), bytes.size() / 2}) {
        test::write_contents(path, bytes.substr(0, cut));
        EXPECT_THROW(read_image(path), Error) << "cut at " << cut;
    }
    test::write_contents(dir.file("bad.jpg"), "definitely not a jpeg");
    EXPECT_THROW(read_image(dir.file("bad.jpg")), Error);
}

} // namespace
} // namespace illum
