#include "illum/image/pfm.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

#include "illum/image/image_io.h"
#include "illum/util/error.h"
#include "image/test_util.h"

namespace illum {
namespace {

using test::ScratchDir;

std::string big_endian(std::initializer_list<float> values) {
    std::string out;
    for (float f : values) {
        std::uint32_t u;
        std::memcpy(&u, &f, 4);
        for (int i = 3; i >= 0; --i) out.push_back(char((u >> (8 * i)) & 0xff));
    }
    return out;
}

TEST(Pfm, ColourRoundTripIsExact) {
    ScratchDir dir;
    Image img = test::test_image(13, 7);
    img(0, 0) = Color3(-1.5f, 0.0f, 6e-39f); // negative and subnormal values survive
    const std::string path = dir.file("a.pfm");
    write_image(img, path);
    EXPECT_EQ(read_image(path), img);
    // Little-endian colour header; 12 bytes per pixel follow it.
    const std::string bytes = test::file_contents(path);
    EXPECT_EQ(bytes.substr(0, 13), "PF\n13 7\n-1.0\n");
    EXPECT_EQ(bytes.size(), 13 + 13u * 7u * 12u);
}

TEST(Pfm, GreyRoundTripIsExact) {
    Image img(5, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 5; ++x) img(x, y) = Color3(0.1f * float(x) + 3.7f * float(y));
    const std::string bytes = encode_pfm_grey(img);
    EXPECT_EQ(bytes.substr(0, 3), "Pf\n");
    const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
    EXPECT_EQ(decode_pfm({p, bytes.size()}, "grey.pfm"), img);
}

TEST(Pfm, ReadsBigEndianBottomToTop) {
    ScratchDir dir;
    const std::string path = dir.file("be.pfm");
    // 2x2, positive scale = big-endian; the first row in the file is the bottom row (y = 1).
    test::write_contents(path, "PF\n2 2\n1.0\n" + big_endian({1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}));
    const Image img = read_image(path);
    ASSERT_EQ(img.width(), 2);
    ASSERT_EQ(img.height(), 2);
    EXPECT_EQ(img(0, 1), Color3(1, 2, 3));
    EXPECT_EQ(img(1, 1), Color3(4, 5, 6));
    EXPECT_EQ(img(0, 0), Color3(7, 8, 9));
    EXPECT_EQ(img(1, 0), Color3(10, 11, 12));

    // Greyscale, big-endian, with a scale of 2 that multiplies the values; header tokens separated by
    // arbitrary whitespace.
    test::write_contents(path, "Pf 3\t1\n  2.0\n" + big_endian({0.5f, -1.0f, 1e10f}));
    const Image grey = read_image(path);
    ASSERT_EQ(grey.width(), 3);
    ASSERT_EQ(grey.height(), 1);
    EXPECT_EQ(grey(0, 0), Color3(1.0f));
    EXPECT_EQ(grey(1, 0), Color3(-2.0f));
    EXPECT_EQ(grey(2, 0), Color3(2e10f));
}

TEST(Pfm, TruncatedAndMalformedFilesThrow) {
    ScratchDir dir;
    const std::string good = dir.file("good.pfm");
    write_image(test::test_image(6, 5), good);
    const std::string bytes = test::file_contents(good);
    const std::string path = dir.file("bad.pfm");
    for (std::size_t cut : {std::size_t(0), std::size_t(1), std::size_t(4), std::size_t(9), std::size_t(12),
                            bytes.size() / 2, bytes.size() - 1}) {
        test::write_contents(path, bytes.substr(0, cut));
        EXPECT_THROW(read_image(path), Error) << "cut at " << cut;
    }
    for (const char* header : {"P6\n1 1\n-1\n", "PF\n0 1\n-1\n", "PF\n-2 1\n-1\n", "PF\nx 1\n-1\n",
                               "PF\n1 1\n0\n", "PF\n1 1\nnan\n", "PF\n99999999999 99999999999\n-1\n"}) {
        test::write_contents(path, header + std::string(12, '\0'));
        EXPECT_THROW(read_image(path), Error) << header;
    }
    try {
        test::write_contents(path, bytes.substr(0, bytes.size() - 4));
        read_image(path);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace illum
