#include "illum/image/exr.h"

#include <gtest/gtest.h>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfThreading.h>
#include <cstdint>
#include <cstring>
#include <half.h>
#include <vector>

#include "illum/image/image_io.h"
#include "illum/util/error.h"
#include "image/test_util.h"

namespace illum {
namespace {

using test::ScratchDir;

TEST(Exr, FloatRoundTripIsExact) {
    ScratchDir dir;
    Image img = test::test_image(37, 23);
    img(3, 4) = Color3(1e-30f, 3e37f, -2.5f); // denormal-ish, huge and negative values survive float
    const std::string path = dir.file("a.exr");
    write_image(img, path);
    EXPECT_EQ(read_image(path), img);

    // The file stores 32-bit float R, G, B channels.
    Imf::InputFile file(path.c_str());
    const Imf::ChannelList& ch = file.header().channels();
    for (const char* name : {"R", "G", "B"}) {
        ASSERT_NE(ch.findChannel(name), nullptr) << name;
        EXPECT_EQ(ch.findChannel(name)->type, Imf::FLOAT) << name;
    }
}

// Writes a half-float EXR the way pbrt-v4 does, with the given channels (each value = f(channel, x, y)).
template <class F>
void write_half_exr(const std::string& path, int w, int h, const std::vector<std::string>& names, F value,
                    Imath::Box2i data_window = {}) {
    Imf::Header header(w, h);
    if (!data_window.isEmpty()) header.dataWindow() = data_window;
    const Imath::Box2i dw = header.dataWindow();
    const int dw_w = dw.max.x - dw.min.x + 1, dw_h = dw.max.y - dw.min.y + 1;
    std::vector<std::vector<half>> planes(names.size(), std::vector<half>(std::size_t(dw_w * dw_h)));
    Imf::FrameBuffer fb;
    for (std::size_t c = 0; c < names.size(); ++c) {
        header.channels().insert(names[c], Imf::Channel(Imf::HALF));
        for (int y = 0; y < dw_h; ++y)
            for (int x = 0; x < dw_w; ++x)
                planes[c][std::size_t(y * dw_w + x)] = half(value(int(c), x + dw.min.x, y + dw.min.y));
        fb.insert(names[c], Imf::Slice::Make(Imf::HALF, planes[c].data(), dw));
    }
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(fb);
    file.writePixels(dw_h);
}

// Blocks of scanlines are compressed in OpenEXR's thread pool; the file's bytes do not depend on it.
TEST(Exr, SameBytesWithAnyCompressionThreadCount) {
    Image img = test::test_image(301, 97); // several 16-line blocks, the last one partial
    for (bool half : {false, true}) {
        const std::string threaded = encode_exr(img, {.half = half});
        const int threads = Imf::globalThreadCount();
        Imf::setGlobalThreadCount(0);
        const std::string serial = encode_exr(img, {.half = half});
        Imf::setGlobalThreadCount(3);
        const std::string three = encode_exr(img, {.half = half});
        Imf::setGlobalThreadCount(threads);
        EXPECT_EQ(threaded, serial) << half;
        EXPECT_EQ(three, serial) << half;
    }
}

TEST(Exr, ReadsHalfRgba) {
    ScratchDir dir;
    const std::string path = dir.file("half.exr");
    // Values exactly representable in half precision, so the comparison can be exact.
    auto value = [](int c, int x, int y) { return float(c + 1) * 0.25f + float(x) * 0.5f + float(y) * 8.0f; };
    write_half_exr(path, 5, 3, {"R", "G", "B", "A"}, value);
    const Image img = read_image(path);
    ASSERT_EQ(img.width(), 5);
    ASSERT_EQ(img.height(), 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x)
            EXPECT_EQ(img(x, y), Color3(value(0, x, y), value(1, x, y), value(2, x, y))) << x << "," << y;
}

TEST(Exr, ReadsHalfRoundingToNearestHalf) {
    ScratchDir dir;
    const std::string path = dir.file("half.exr");
    write_half_exr(path, 2, 1, {"R", "G", "B"}, [](int, int x, int) { return x == 0 ? 0.1f : 1000.3f; });
    const Image img = read_image(path);
    EXPECT_EQ(img(0, 0).r, float(half(0.1f)));
    EXPECT_NEAR(img(0, 0).g, 0.1f, 1e-4f);
    EXPECT_NEAR(img(1, 0).b, 1000.3f, 0.5f);
}

TEST(Exr, ReadsLuminanceOnlyAsGrey) {
    ScratchDir dir;
    const std::string path = dir.file("y.exr");
    write_half_exr(path, 3, 2, {"Y"}, [](int, int x, int y) { return float(x + 3 * y) * 0.125f; });
    const Image img = read_image(path);
    ASSERT_EQ(img.width(), 3);
    EXPECT_EQ(img(2, 1), Color3(5 * 0.125f));
    EXPECT_EQ(img(1, 0), Color3(0.125f));
}

TEST(Exr, DataWindowInsideDisplayWindow) {
    ScratchDir dir;
    const std::string path = dir.file("crop.exr");
    write_half_exr(
        path, 4, 4, {"R", "G", "B"}, [](int, int, int) { return 2.0f; }, Imath::Box2i({1, 2}, {2, 3}));
    const Image img = read_image(path);
    ASSERT_EQ(img.width(), 4);
    ASSERT_EQ(img.height(), 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            const bool inside = x >= 1 && x <= 2 && y >= 2 && y <= 3;
            EXPECT_EQ(img(x, y), Color3(inside ? 2.0f : 0.0f)) << x << "," << y;
        }
}

TEST(Exr, MissingColourChannelsReadAsZeroAndOtherChannelsAreRejected) {
    ScratchDir dir;
    const std::string rg = dir.file("rg.exr");
    write_half_exr(rg, 2, 2, {"R", "G"}, [](int c, int, int) { return float(c + 1); });
    EXPECT_EQ(read_image(rg)(1, 1), Color3(1, 2, 0));

    const std::string two = dir.file("two.exr");
    write_half_exr(two, 2, 2, {"depth", "normal.x"}, [](int, int, int) { return 1.0f; });
    try {
        read_image(two);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("no R, G, B or Y channel"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("depth"), std::string::npos) << e.what();
    }
}

TEST(Exr, NotAnExrFile) {
    ScratchDir dir;
    const std::string path = dir.file("foo.exr");
    test::write_contents(path, "P6\n1 1\n255\nabc");
    try {
        read_image(path);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), "\"" + path + "\" is not an OpenEXR file");
    }
}

TEST(Exr, TruncatedOrCorruptFilesThrow) {
    ScratchDir dir;
    const std::string good = dir.file("good.exr");
    write_image(test::test_image(40, 40), good);
    const std::string bytes = test::file_contents(good);
    ASSERT_GT(bytes.size(), 200u);
    const std::string path = dir.file("bad.exr");
    // Cut inside the magic number, the header, the offset table and the pixel data.
    for (std::size_t cut : {std::size_t(2), std::size_t(10), std::size_t(100), bytes.size() / 3,
                            bytes.size() / 2, bytes.size() - 20, bytes.size() - 1}) {
        test::write_contents(path, bytes.substr(0, cut));
        EXPECT_THROW(read_image(path), Error) << "cut at " << cut << " of " << bytes.size();
    }
    // Garbage after a valid magic number and version.
    test::write_contents(path, bytes.substr(0, 8) + std::string(300, '\x7f'));
    EXPECT_THROW(read_image(path), Error);
    // Corrupt compressed pixel data, header and offsets intact. (The test image above is incompressible, so
    // OpenEXR stored it raw; a smooth image is stored compressed.)
    Image smooth(40, 40);
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 40; ++x) smooth(x, y) = Color3(float(x / 8), 1.0f, 0.5f);
    write_image(smooth, good);
    std::string corrupt = test::file_contents(good);
    ASSERT_LT(corrupt.size(), 40u * 40u * 12u / 4u) << "expected a compressed file";
    for (std::size_t i = corrupt.size() - 20; i < corrupt.size(); ++i) corrupt[i] = char(i * 37);
    test::write_contents(path, corrupt);
    EXPECT_THROW(read_image(path), Error);
    // An offset table whose last entry points past the end of the file. The table (3 chunks of 16 lines for
    // 40 ZIP-compressed rows) starts where its first entry minus 24 says. OpenEXR rebuilds a broken table
    // from the chunk headers, so the read may succeed, but then only with the right pixels.
    corrupt = test::file_contents(good);
    std::size_t table = 0;
    for (std::size_t p = 8; p + 8 <= corrupt.size() && table == 0; ++p) {
        std::uint64_t v = 0;
        std::memcpy(&v, corrupt.data() + p, 8);
        if (v == p + 24) table = p;
    }
    ASSERT_NE(table, 0u);
    const std::uint64_t beyond = corrupt.size() + 1000;
    std::memcpy(corrupt.data() + table + 16, &beyond, 8);
    test::write_contents(path, corrupt);
    try {
        EXPECT_EQ(read_image(path), smooth);
    } catch (const Error&) {
    }
    // Both a broken table and a missing last chunk: nothing to recover from.
    test::write_contents(path, corrupt.substr(0, corrupt.size() - 30));
    EXPECT_THROW(read_image(path), Error);
}

} // namespace
} // namespace illum
