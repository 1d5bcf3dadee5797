#include "illum/texture/ptex_file.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <zlib.h>

#include "illum/image/file_bytes.h"
#include "illum/util/error.h"

namespace illum {

namespace {

enum class DataType : std::uint32_t { UInt8 = 0, UInt16 = 1, Half = 2, Float = 3 };
enum Encoding : std::uint32_t { kConstant = 0, kZipped = 1, kDiffZipped = 2, kTiled = 3 };
constexpr std::uint32_t kMagic = 'P' | ('t' << 8) | ('e' << 16) | ('x' << 24);
constexpr std::size_t kHeaderSize = 64, kFaceInfoSize = 20, kLevelInfoSize = 16;

std::size_t data_size(DataType t) {
    switch (t) {
    case DataType::UInt8:
        return 1;
    case DataType::UInt16:
    case DataType::Half:
        return 2;
    case DataType::Float:
        return 4;
    }
    return 0;
}

// IEEE 754 binary16 to float.
float half_to_float(std::uint16_t h) {
    std::uint32_t sign = std::uint32_t(h & 0x8000) << 16, exp = (h >> 10) & 0x1f, mant = h & 0x3ff;
    float f;
    if (exp == 0)
        f = std::ldexp(float(mant), -24); // subnormal (or zero)
    else if (exp == 31)
        f = mant ? std::nanf("") : INFINITY;
    else
        f = std::ldexp(float(mant | 0x400), int(exp) - 25);
    return sign ? -f : f;
}

class Reader {
public:
    Reader(const std::string& path) : path_(path), bytes_(read_file_bytes(path)) {}

    Error fail(const std::string& why) const {
        return Error("\"" + path_ + "\" is not a valid Ptex file: " + why);
    }
    void need(std::uint64_t at, std::uint64_t n, const char* what) const {
        if (at > bytes_.size() || bytes_.size() - at < n)
            throw fail(std::string(what) + " lies beyond the end of the file (truncated?)");
    }
    template <class T>
    T get(std::uint64_t at) const {
        need(at, sizeof(T), "the header");
        T v;
        std::memcpy(&v, bytes_.data() + at, sizeof(T));
        return v;
    }
    // The zlib stream of `zipped` bytes at `at`, which must inflate to exactly `size` bytes.
    std::vector<unsigned char> unzip(std::uint64_t at, std::uint64_t zipped, std::uint64_t size,
                                     const char* what) const {
        need(at, zipped, what);
        std::vector<unsigned char> out(size);
        uLongf n = uLongf(size);
        int rc = size == 0 ? Z_OK : uncompress(out.data(), &n, bytes_.data() + at, uLong(zipped));
        if (rc != Z_OK || n != size)
            throw fail(std::string("its ") + what + " does not inflate to " + std::to_string(size) +
                       " bytes");
        return out;
    }
    const unsigned char* at(std::uint64_t pos) const { return bytes_.data() + pos; }

private:
    std::string path_;
    std::vector<unsigned char> bytes_;
};

} // namespace

PtexFile PtexFile::read(const std::string& path) {
    Reader r(path);
    if (r.get<std::uint32_t>(0) != kMagic) throw r.fail("it does not start with \"Ptex\"");
    if (r.get<std::uint32_t>(4) != 1)
        throw r.fail("version " + std::to_string(r.get<std::uint32_t>(4)) + " (1 expected)");
    PtexFile f;
    f.triangles = r.get<std::uint32_t>(8) == 0;
    std::uint32_t dt = r.get<std::uint32_t>(12);
    if (dt > 3) throw r.fail("unknown data type " + std::to_string(dt));
    DataType type = DataType(dt);
    f.alpha_channel = r.get<std::int32_t>(16);
    f.channels = r.get<std::uint16_t>(20);
    const int levels = r.get<std::uint16_t>(22);
    const std::uint32_t nfaces = r.get<std::uint32_t>(24), ext_size = r.get<std::uint32_t>(28),
                        faceinfo_size = r.get<std::uint32_t>(32), constdata_size = r.get<std::uint32_t>(36),
                        levelinfo_size = r.get<std::uint32_t>(40);
    if (f.channels < 1 || levels < 1) throw r.fail("no channels or no levels");
    if (nfaces > (1u << 28)) throw r.fail("too many faces");
    const std::size_t texel = data_size(type) * std::size_t(f.channels);

    std::uint64_t pos = kHeaderSize + ext_size;
    std::vector<unsigned char> info =
        r.unzip(pos, faceinfo_size, std::uint64_t(nfaces) * kFaceInfoSize, "face info");
    pos += faceinfo_size + constdata_size; // the constant data (face means) are not needed
    std::vector<unsigned char> level_info =
        r.unzip(pos, levelinfo_size, std::uint64_t(levels) * kLevelInfoSize, "level info");
    pos += levelinfo_size;

    std::uint64_t level0_size = 0;
    std::uint32_t level0_header = 0, level0_faces = 0;
    std::memcpy(&level0_size, level_info.data(), 8);
    std::memcpy(&level0_header, level_info.data() + 8, 4);
    std::memcpy(&level0_faces, level_info.data() + 12, 4);
    if (level0_faces != nfaces) throw r.fail("level 0 does not hold every face");
    std::vector<unsigned char> fdh = r.unzip(pos, level0_header, std::uint64_t(nfaces) * 4, "level 0 header");
    std::uint64_t block = pos + level0_header;

    // Decodes one block of ures x vres texels into `out` (row-major, channels interleaved).
    auto decode = [&](std::uint64_t at, std::uint32_t word, int ures, int vres, float* out, int row_stride,
                      auto& self) -> void {
        const std::uint32_t size = word & 0x3fffffff, enc = word >> 30;
        auto convert = [&](const unsigned char* src, std::size_t i) -> float {
            switch (type) {
            case DataType::UInt8:
                return float(src[i]) / 255.0f;
            case DataType::UInt16: {
                std::uint16_t v;
                std::memcpy(&v, src + 2 * i, 2);
                return float(v) / 65535.0f;
            }
            case DataType::Half: {
                std::uint16_t v;
                std::memcpy(&v, src + 2 * i, 2);
                return half_to_float(v);
            }
            case DataType::Float: {
                float v;
                std::memcpy(&v, src + 4 * i, 4);
                return v;
            }
            }
            return 0;
        };
        if (enc == kConstant) {
            r.need(at, texel, "a constant face");
            for (int v = 0; v < vres; ++v)
                for (int u = 0; u < ures; ++u)
                    for (int c = 0; c < f.channels; ++c)
                        out[std::size_t(v) * row_stride + std::size_t(u * f.channels + c)] =
                            convert(r.at(at), std::size_t(c));
        } else if (enc == kZipped || enc == kDiffZipped) {
            const std::size_t n = std::size_t(ures) * std::size_t(vres);
            std::vector<unsigned char> planes = r.unzip(at, size, n * texel, "face data");
            if (enc == kDiffZipped) { // running sums, wrapping, over the whole block (integer types only)
                if (type == DataType::UInt8) {
                    unsigned char prev = 0;
                    for (unsigned char& b : planes) prev = b = static_cast<unsigned char>(b + prev);
                } else if (type == DataType::UInt16) {
                    std::uint16_t prev = 0;
                    for (std::size_t i = 0; i + 1 < planes.size(); i += 2) {
                        std::uint16_t v;
                        std::memcpy(&v, &planes[i], 2);
                        prev = v = static_cast<std::uint16_t>(v + prev);
                        std::memcpy(&planes[i], &v, 2);
                    }
                }
            }
            // Channel planes of vres rows of ures values each.
            for (int c = 0; c < f.channels; ++c)
                for (int v = 0; v < vres; ++v)
                    for (int u = 0; u < ures; ++u)
                        out[std::size_t(v) * row_stride + std::size_t(u * f.channels + c)] = convert(
                            planes.data(), std::size_t(c) * n + std::size_t(v) * ures + std::size_t(u));
        } else { // tiled
            r.need(at, 6, "a tiled face");
            const int tu = 1 << std::clamp<int>(std::int8_t(*r.at(at)), 0, 20),
                      tv = 1 << std::clamp<int>(std::int8_t(*r.at(at + 1)), 0, 20);
            std::uint32_t tile_header = r.get<std::uint32_t>(at + 2);
            if (tu > ures || tv > vres) throw r.fail("a tile is larger than its face");
            const int ntu = ures / tu, ntv = vres / tv;
            std::vector<unsigned char> th =
                r.unzip(at + 6, tile_header, std::uint64_t(ntu) * ntv * 4, "tile headers");
            std::uint64_t tile_at = at + 6 + tile_header;
            for (int t = 0; t < ntu * ntv; ++t) {
                std::uint32_t w;
                std::memcpy(&w, &th[std::size_t(t) * 4], 4);
                if ((w >> 30) == kTiled) throw r.fail("a tile is itself tiled");
                int ut = t % ntu, vt = t / ntu;
                self(tile_at, w, tu, tv,
                     out + std::size_t(vt * tv) * row_stride + std::size_t(ut * tu * f.channels), row_stride,
                     self);
                tile_at += w & 0x3fffffff;
            }
        }
    };

    f.faces.resize(nfaces);
    for (std::uint32_t i = 0; i < nfaces; ++i) {
        const unsigned char* fi = info.data() + std::size_t(i) * kFaceInfoSize;
        int ulog2 = std::int8_t(fi[0]), vlog2 = std::int8_t(fi[1]);
        if (ulog2 < 0 || vlog2 < 0 || ulog2 > 15 || vlog2 > 15 || ulog2 + vlog2 > 24)
            throw r.fail("face " + std::to_string(i) + " has resolution 2^" + std::to_string(ulog2) +
                         " x 2^" + std::to_string(vlog2));
        PtexFace& face = f.faces[i];
        face.ures = 1 << ulog2;
        face.vres = 1 << vlog2;
        face.texels.resize(std::size_t(face.ures) * std::size_t(face.vres) * std::size_t(f.channels));
        std::uint32_t word;
        std::memcpy(&word, &fdh[std::size_t(i) * 4], 4);
        decode(block, word, face.ures, face.vres, face.texels.data(), face.ures * f.channels, decode);
        block += word & 0x3fffffff;
    }
    if (block > pos + level0_header + level0_size) throw r.fail("the faces' blocks overrun level 0");
    return f;
}

void PtexFile::lookup(int face, Point2f uv, float* out) const {
    if (face < 0 || std::size_t(face) >= faces.size()) {
        std::fill(out, out + channels, 0.0f);
        return;
    }
    const PtexFace& f = faces[std::size_t(face)];
    // Texel centres at (i + 1/2) / res; clamped at the face's edges.
    float x = std::clamp(uv.x, 0.0f, 1.0f) * float(f.ures) - 0.5f,
          y = std::clamp(uv.y, 0.0f, 1.0f) * float(f.vres) - 0.5f;
    int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    float sx = x - float(x0), sy = y - float(y0);
    auto at = [&](int u, int v, int c) {
        u = std::clamp(u, 0, f.ures - 1);
        v = std::clamp(v, 0, f.vres - 1);
        return f.texels[(std::size_t(v) * std::size_t(f.ures) + std::size_t(u)) * std::size_t(channels) +
                        std::size_t(c)];
    };
    for (int c = 0; c < channels; ++c)
        out[c] = (1 - sy) * ((1 - sx) * at(x0, y0, c) + sx * at(x0 + 1, y0, c)) +
                 sy * ((1 - sx) * at(x0, y0 + 1, c) + sx * at(x0 + 1, y0 + 1, c));
}

} // namespace illum
