#include "illum/image/hdr.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "illum/image/image_io.h"
#include "illum/util/error.h"
#include "image/test_util.h"

namespace illum {
namespace {

using test::ScratchDir;

// RGBE shares one 8-bit exponent: each channel is within one mantissa step (2^-8 of the largest channel,
// i.e. ~0.4-0.8% of it) of the original.
void expect_rgbe_close(const Image& got, const Image& want) {
    ASSERT_EQ(got.width(), want.width());
    ASSERT_EQ(got.height(), want.height());
    for (int y = 0; y < want.height(); ++y)
        for (int x = 0; x < want.width(); ++x) {
            const Color3 w = want(x, y), g = got(x, y);
            const float tolerance = 0.01f * w.max_component();
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(g[c], w[c], tolerance) << x << "," << y << " channel " << c;
        }
}

TEST(Hdr, RoundTripWithinRgbePrecision) {
    ScratchDir dir;
    for (int width : {5, 64}) { // stb writes flat scanlines below width 8 and run-length ones above
        const Image img = test::test_image(width, 9);
        // (Built with append: GCC 12 gives a false -Wrestrict for "a" + std::string.)
        std::string name = std::to_string(width);
        name.append(".hdr");
        const std::string path = dir.file(name);
        write_image(img, path);
        const Image back = read_image(path);
        expect_rgbe_close(back, img);
        EXPECT_NE(back, img); // it is lossy: something must have changed
    }
    // Runs: a constant image compresses into run-length spans and still reads back.
    const Image flat(100, 3, Color3(0.75f, 2.0f, 1e-3f));
    write_image(flat, dir.file("flat.hdr"));
    expect_rgbe_close(read_image(dir.file("flat.hdr")), flat);
    EXPECT_LT(test::file_contents(dir.file("flat.hdr")).size(), 100u * 3u * 4u / 4u);
}

TEST(Hdr, UnrepresentableValuesAreSanitised) {
    Image img(2, 1);
    img(0, 0) = Color3(-1.0f, std::numeric_limits<float>::quiet_NaN(), 2.0f);
    img(1, 0) = Color3(std::numeric_limits<float>::infinity(), 1.0f, 0.0f);
    const std::string bytes = encode_hdr(img);
    const Image back =
        decode_hdr({reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()}, "x.hdr");
    EXPECT_EQ(back(0, 0).r, 0.0f);
    EXPECT_EQ(back(0, 0).g, 0.0f);
    EXPECT_NEAR(back(0, 0).b, 2.0f, 0.02f);
    EXPECT_TRUE(std::isfinite(back(1, 0).r));
    EXPECT_GT(back(1, 0).r, 1e37f);
}

TEST(Hdr, TruncatedFilesThrow) {
    ScratchDir dir;
    const std::string path = dir.file("bad.hdr");
    for (int width : {5, 64}) {
        const std::string good = dir.file("good.hdr");
        write_image(test::test_image(width, 9), good);
        const std::string bytes = test::file_contents(good);
        for (std::size_t cut :
             {std::size_t(3), std::size_t(20), bytes.size() / 2, bytes.size() - 5, bytes.size() - 1}) {
            test::write_contents(path, bytes.substr(0, cut));
            EXPECT_THROW(read_image(path), Error) << "width " << width << ", cut at " << cut;
        }
    }
    // A zero-length literal run (stb alone would loop forever on it) and a run longer than the scanline.
    const std::string good = dir.file("good.hdr");
    write_image(Image(64, 2, Color3(0.5f)), good);
    const std::string bytes = test::file_contents(good);
    const std::size_t marker = bytes.find(std::string("\x02\x02\x00\x40", 4));
    ASSERT_NE(marker, std::string::npos);
    for (unsigned char count : {0, 128 + 65, 65}) {
        std::string corrupt = bytes;
        corrupt[marker + 4] = char(count);
        test::write_contents(path, corrupt);
        EXPECT_THROW(read_image(path), Error) << int(count);
    }
    // Orientation stb cannot read.
    std::string rotated = bytes;
    rotated.replace(rotated.find("-Y 2 +X 64"), 10, "+X 64 -Y 2");
    test::write_contents(path, rotated);
    EXPECT_THROW(read_image(path), Error);
    test::write_contents(path, "not an hdr file at all");
    EXPECT_THROW(read_image(path), Error);
}

} // namespace
} // namespace illum
