#include "illum/image/exr.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfRgbaFile.h>
#include <ImfThreading.h>
#include <ImfVersion.h>
#include <algorithm>
#include <cstring>
#include <exception>
#include <half.h>
#include <thread>
#include <vector>

#include "illum/util/error.h"

namespace illum {

namespace {

// Refuse headers that claim absurd sizes before allocating for them (2^28 pixels = 16k x 16k).
constexpr std::int64_t kMaxPixels = std::int64_t(1) << 28;

// Reads from a byte buffer; a read past the end throws, which OpenEXR reports as a truncated file.
class MemoryIStream : public Imf::IStream {
public:
    MemoryIStream(std::span<const unsigned char> bytes, const std::string& name)
        : Imf::IStream(name.c_str()), bytes_(bytes) {}

    bool read(char c[], int n) override {
        if (n < 0 || pos_ > bytes_.size() || std::size_t(n) > bytes_.size() - pos_)
            throw std::runtime_error("unexpected end of file");
        std::memcpy(c, bytes_.data() + pos_, std::size_t(n));
        pos_ += std::size_t(n);
        return pos_ < bytes_.size();
    }
    uint64_t tellg() override { return pos_; }
    void seekg(uint64_t pos) override { pos_ = std::size_t(pos); }

private:
    std::span<const unsigned char> bytes_;
    std::size_t pos_ = 0;
};

// Writes into a growing string; OpenEXR seeks back to fill in the line offset table.
class StringOStream : public Imf::OStream {
public:
    explicit StringOStream(std::string& out) : Imf::OStream("memory"), out_(out) {}

    void write(const char c[], int n) override {
        if (pos_ + std::size_t(n) > out_.size()) out_.resize(pos_ + std::size_t(n));
        std::memcpy(out_.data() + pos_, c, std::size_t(n));
        pos_ += std::size_t(n);
    }
    uint64_t tellp() override { return pos_; }
    void seekp(uint64_t pos) override { pos_ = std::size_t(pos); }

private:
    std::string& out_;
    std::size_t pos_ = 0;
};

std::string quoted(const std::string& s) { return "\"" + s + "\""; }

std::int64_t box_width(const Imath::Box2i& b) { return std::int64_t(b.max.x) - b.min.x + 1; }
std::int64_t box_height(const Imath::Box2i& b) { return std::int64_t(b.max.y) - b.min.y + 1; }

// Copies the data-window pixels (given as planar r, g, b arrays over `dw`) into an image covering `disp`.
Image place(const std::vector<float> (&planes)[3], const Imath::Box2i& dw, const Imath::Box2i& disp) {
    Image image(int(box_width(disp)), int(box_height(disp)));
    const std::int64_t w = box_width(dw);
    for (int y = std::max(dw.min.y, disp.min.y); y <= std::min(dw.max.y, disp.max.y); ++y)
        for (int x = std::max(dw.min.x, disp.min.x); x <= std::min(dw.max.x, disp.max.x); ++x) {
            const std::size_t i =
                std::size_t((std::int64_t(y) - dw.min.y) * w + (std::int64_t(x) - dw.min.x));
            image(x - disp.min.x, y - disp.min.y) = {planes[0][i], planes[1][i], planes[2][i]};
        }
    return image;
}

Image read_luminance_chroma(std::span<const unsigned char> bytes, const std::string& name,
                            const Imath::Box2i& dw, const Imath::Box2i& disp) {
    MemoryIStream stream(bytes, name);
    Imf::RgbaInputFile file(stream);
    const std::size_t n = std::size_t(box_width(dw) * box_height(dw));
    std::vector<Imf::Rgba> pixels(n);
    file.setFrameBuffer(pixels.data() - dw.min.x - std::ptrdiff_t(dw.min.y) * box_width(dw), 1,
                        std::size_t(box_width(dw)));
    file.readPixels(dw.min.y, dw.max.y);
    std::vector<float> planes[3];
    for (auto& p : planes) p.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        planes[0][i] = pixels[i].r;
        planes[1][i] = pixels[i].g;
        planes[2][i] = pixels[i].b;
    }
    return place(planes, dw, disp);
}

Image read_exr(std::span<const unsigned char> bytes, const std::string& name) {
    MemoryIStream stream(bytes, name);
    Imf::InputFile file(stream);
    const Imf::Header& header = file.header();
    const Imath::Box2i dw = header.dataWindow();
    Imath::Box2i disp = header.displayWindow();
    if (box_width(disp) <= 0 || box_height(disp) <= 0) disp = dw;
    if (box_width(dw) <= 0 || box_height(dw) <= 0 || box_width(dw) * box_height(dw) > kMaxPixels ||
        box_width(disp) * box_height(disp) > kMaxPixels)
        throw Error(quoted(name) + " has an unsupported image size");
    if (!file.isComplete()) throw Error(quoted(name) + " is truncated or incomplete");

    const Imf::ChannelList& channels = header.channels();
    const char* sources[3] = {nullptr, nullptr, nullptr};
    if (channels.findChannel("R") || channels.findChannel("G") || channels.findChannel("B")) {
        sources[0] = "R";
        sources[1] = "G";
        sources[2] = "B";
    } else if (channels.findChannel("Y")) {
        if (channels.findChannel("RY") || channels.findChannel("BY"))
            return read_luminance_chroma(bytes, name, dw, disp);
        sources[0] = sources[1] = sources[2] = "Y";
    } else {
        int count = 0;
        std::string list;
        for (auto c = channels.begin(); c != channels.end(); ++c, ++count)
            list += std::string(list.empty() ? "" : ", ") + c.name();
        if (count != 1)
            throw Error(quoted(name) +
                        " has no R, G, B or Y channel (channels: " + (list.empty() ? "none" : list) + ")");
        auto it = channels.begin();
        sources[0] = sources[1] = sources[2] = it.name();
    }

    const std::size_t n = std::size_t(box_width(dw) * box_height(dw));
    std::vector<float> planes[3];
    Imf::FrameBuffer fb;
    for (int c = 0; c < 3; ++c) {
        planes[c].assign(n, 0.0f);
        // A channel that is used twice (grey) is read once and copied below.
        if (c > 0 && std::strcmp(sources[c], sources[0]) == 0) continue;
        if (const Imf::Channel* ch = channels.findChannel(sources[c]))
            if (ch->xSampling != 1 || ch->ySampling != 1)
                throw Error(quoted(name) + ": subsampled channel " + sources[c] + " is not supported");
        // A missing channel is filled with the slice's fill value, 0.
        fb.insert(sources[c], Imf::Slice::Make(Imf::FLOAT, planes[c].data(), dw));
    }
    file.setFrameBuffer(fb);
    file.readPixels(dw.min.y, dw.max.y);
    if (std::strcmp(sources[1], sources[0]) == 0) planes[1] = planes[0];
    if (std::strcmp(sources[2], sources[0]) == 0) planes[2] = planes[0];
    return place(planes, dw, disp);
}

} // namespace

Image decode_exr(std::span<const unsigned char> bytes, const std::string& name) {
    if (bytes.size() < 4 || !Imf::isImfMagic(reinterpret_cast<const char*>(bytes.data())))
        throw Error(quoted(name) + " is not an OpenEXR file");
    try {
        return read_exr(bytes, name);
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        throw Error("cannot read " + quoted(name) + ": " + e.what());
    }
}

std::string encode_exr(const Image& image, const ExrLayout& layout) {
    if (image.empty()) throw Error("cannot encode an empty image as OpenEXR");
    const int w = image.width(), h = image.height();
    const int dw = layout.display_width > 0 ? layout.display_width : w;
    const int dh = layout.display_height > 0 ? layout.display_height : h;
    if (layout.x0 < 0 || layout.y0 < 0 || layout.x0 + w > dw || layout.y0 + h > dh)
        throw Error("cannot encode OpenEXR: the data window lies outside the display window");
    std::string out;
    try {
        // Windows are inclusive in OpenEXR.
        Imath::Box2i display(Imath::V2i(0, 0), Imath::V2i(dw - 1, dh - 1));
        Imath::Box2i data(Imath::V2i(layout.x0, layout.y0), Imath::V2i(layout.x0 + w - 1, layout.y0 + h - 1));
        Imf::Header header(display, data);
        header.compression() = Imf::ZIP_COMPRESSION;
        const Imf::PixelType type = layout.half ? Imf::HALF : Imf::FLOAT;
        for (const char* c : {"R", "G", "B"}) header.channels().insert(c, Imf::Channel(type));
        StringOStream stream(out);
        // OpenEXR compresses blocks of scanlines in its own thread pool when it has one (the bytes do not
        // depend on it: each block is compressed alone and written in order).
        static const bool pool = [] {
            Imf::setGlobalThreadCount(int(std::max(1u, std::thread::hardware_concurrency())));
            return true;
        }();
        (void)pool;
        Imf::OutputFile file(stream, header, Imf::globalThreadCount());
        Imf::FrameBuffer fb;
        // OpenEXR addresses a slice by the data window's absolute coordinates: the base pointer is moved
        // back by the window's origin (Slice::Make does that arithmetic without forming the pointer early).
        std::vector<half> halves;
        if (layout.half) {
            halves.resize(std::size_t(w) * h * 3);
            constexpr float kHalfMax = 65504.0f;
            for (std::size_t i = 0; i < std::size_t(w) * h; ++i)
                for (int c = 0; c < 3; ++c) halves[3 * i + c] = half(std::min(image.data()[i][c], kHalfMax));
            const std::size_t xs = 3 * sizeof(half), ys = xs * std::size_t(w);
            for (int c = 0; c < 3; ++c)
                fb.insert(c == 0   ? "R"
                          : c == 1 ? "G"
                                   : "B",
                          Imf::Slice::Make(Imf::HALF, &halves[std::size_t(c)], data, xs, ys));
        } else {
            Color3* pixels = const_cast<Color3*>(image.data()); // OpenEXR only reads through these pointers
            const std::size_t xs = sizeof(Color3), ys = sizeof(Color3) * std::size_t(w);
            fb.insert("R", Imf::Slice::Make(Imf::FLOAT, &pixels->r, data, xs, ys));
            fb.insert("G", Imf::Slice::Make(Imf::FLOAT, &pixels->g, data, xs, ys));
            fb.insert("B", Imf::Slice::Make(Imf::FLOAT, &pixels->b, data, xs, ys));
        }
        file.setFrameBuffer(fb);
        file.writePixels(h);
    } catch (const std::exception& e) {
        throw Error(std::string("OpenEXR: ") + e.what());
    }
    return out;
}

} // namespace illum
