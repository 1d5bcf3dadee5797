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
    std::uint64_t size() const { return bytes_.size(); }

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
    const DataType type = DataType(dt);
    f.one_value = type == DataType::UInt8 ? 255.0f : type == DataType::UInt16 ? 65535.0f : 1.0f;
    f.alpha_channel = r.get<std::int32_t>(16);
    f.channels = r.get<std::uint16_t>(20);
    const int levels = r.get<std::uint16_t>(22);
    const std::uint32_t nfaces = r.get<std::uint32_t>(24), ext_size = r.get<std::uint32_t>(28),
                        faceinfo_size = r.get<std::uint32_t>(32), constdata_size = r.get<std::uint32_t>(36),
                        levelinfo_size = r.get<std::uint32_t>(40);
    if (f.channels < 1 || levels < 1) throw r.fail("no channels or no levels");
    if (nfaces > (1u << 28)) throw r.fail("too many faces");
    const int nch = f.channels;
    const std::size_t texel = data_size(type) * std::size_t(nch);
    if (ext_size >= 4) { // the extended header's border modes (0 clamp, 1 black, 2 periodic)
        auto border = [&](std::uint16_t m) { return m <= 2 ? PtexBorder(m) : PtexBorder::Clamp; };
        f.u_border = border(r.get<std::uint16_t>(kHeaderSize));
        if (ext_size >= 6) f.v_border = border(r.get<std::uint16_t>(kHeaderSize + 4));
        if (ext_size >= 8) f.tangent_vectors = r.get<std::uint16_t>(kHeaderSize + 6) == 1;
    }

    std::uint64_t pos = kHeaderSize + ext_size;
    std::vector<unsigned char> info =
        r.unzip(pos, faceinfo_size, std::uint64_t(nfaces) * kFaceInfoSize, "face info");
    pos += faceinfo_size;
    std::vector<unsigned char> constant = r.unzip(pos, constdata_size, nfaces * texel, "constant data");
    pos += constdata_size;
    // The level info is not zipped (PtexReader::readLevelInfo reads it as it is).
    r.need(pos, std::uint64_t(levels) * kLevelInfoSize, "the level info");
    std::vector<unsigned char> level_info(r.at(pos), r.at(pos) + std::size_t(levels) * kLevelInfoSize);
    pos += levelinfo_size;

    // One stored value as a float in the data type's units.
    auto convert = [&](const unsigned char* src, std::size_t i) -> float {
        switch (type) {
        case DataType::UInt8:
            return float(src[i]);
        case DataType::UInt16: {
            std::uint16_t v;
            std::memcpy(&v, src + 2 * i, 2);
            return float(v);
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

    // Decodes one block of ures x vres texels into `out` (row-major, channels interleaved).
    auto decode = [&](std::uint64_t at, std::uint32_t word, int ures, int vres, float* out, int row_stride,
                      auto& self) -> void {
        const std::uint32_t size = word & 0x3fffffff, enc = word >> 30;
        if (enc == kConstant) {
            r.need(at, texel, "a constant face");
            for (int v = 0; v < vres; ++v)
                for (int u = 0; u < ures; ++u)
                    for (int c = 0; c < nch; ++c)
                        out[std::size_t(v) * row_stride + std::size_t(u * nch + c)] =
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
            for (int c = 0; c < nch; ++c)
                for (int v = 0; v < vres; ++v)
                    for (int u = 0; u < ures; ++u)
                        out[std::size_t(v) * row_stride + std::size_t(u * nch + c)] = convert(
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
                self(tile_at, w, tu, tv, out + std::size_t(vt * tv) * row_stride + std::size_t(ut * tu * nch),
                     row_stride, self);
                tile_at += w & 0x3fffffff;
            }
        }
    };

    // Face info, and room for every reduction of each face.
    f.faces.resize(nfaces);
    std::vector<std::vector<char>> have(nfaces); // which reductions are filled
    for (std::uint32_t i = 0; i < nfaces; ++i) {
        const unsigned char* fi = info.data() + std::size_t(i) * kFaceInfoSize;
        PtexFace& face = f.faces[i];
        face.ulog2 = std::int8_t(fi[0]);
        face.vlog2 = std::int8_t(fi[1]);
        if (face.ulog2 < 0 || face.vlog2 < 0 || face.ulog2 > 15 || face.vlog2 > 15 ||
            face.ulog2 + face.vlog2 > 24)
            throw r.fail("face " + std::to_string(i) + " has resolution 2^" + std::to_string(face.ulog2) +
                         " x 2^" + std::to_string(face.vlog2));
        for (int e = 0; e < 4; ++e) face.adjacent_edges[std::size_t(e)] = (fi[2] >> (2 * e)) & 3;
        face.flags = fi[3];
        for (int e = 0; e < 4; ++e) {
            std::int32_t a;
            std::memcpy(&a, fi + 4 + 4 * e, 4);
            face.adjacent_faces[std::size_t(e)] = a >= 0 && std::uint32_t(a) < nfaces ? a : -1;
        }
        std::size_t total = 0;
        for (int ru = 0; ru <= face.ulog2; ++ru)
            for (int rv = 0; rv <= face.vlog2; ++rv) {
                face.offsets.push_back(std::uint32_t(total));
                total += (std::size_t(1) << (ru + rv)) * std::size_t(nch);
            }
        face.texels.resize(total);
        have[i].assign(face.offsets.size(), 0);
        // 1 x 1: the constant data (the face's mean), which is the whole face when it is constant.
        float* one = face.texels.data();
        for (int c = 0; c < nch; ++c) one[c] = convert(constant.data() + i * texel, std::size_t(c));
        have[i][0] = 1;
        if (face.constant()) {
            for (std::size_t k = 0; k < total; ++k) face.texels[k] = one[k % std::size_t(nch)];
            std::fill(have[i].begin(), have[i].end(), 1);
        }
    }
    // The reduction faces' order: decreasing smaller side, stable (a constant face counts as 2).
    std::vector<std::uint32_t> by_size(nfaces);
    for (std::uint32_t i = 0; i < nfaces; ++i) by_size[i] = i;
    auto smaller = [&](std::uint32_t i) {
        const PtexFace& face = f.faces[i];
        return face.constant() ? 1 : std::min(face.ulog2, face.vlog2);
    };
    std::stable_sort(by_size.begin(), by_size.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return smaller(a) > smaller(b); });

    std::uint64_t level_at = pos;
    for (int l = 0; l < levels; ++l) {
        std::uint64_t level_size = 0;
        std::uint32_t header_size = 0, level_faces = 0;
        std::memcpy(&level_size, level_info.data() + l * kLevelInfoSize, 8);
        std::memcpy(&header_size, level_info.data() + l * kLevelInfoSize + 8, 4);
        std::memcpy(&level_faces, level_info.data() + l * kLevelInfoSize + 12, 4);
        if (l == 0 && level_faces != nfaces) throw r.fail("level 0 does not hold every face");
        if (level_faces > nfaces) throw r.fail("level " + std::to_string(l) + " holds too many faces");
        std::vector<unsigned char> fdh =
            r.unzip(level_at, header_size, std::uint64_t(level_faces) * 4, "level header");
        std::uint64_t block = level_at + header_size;
        for (std::uint32_t k = 0; k < level_faces; ++k) {
            std::uint32_t word;
            std::memcpy(&word, &fdh[std::size_t(k) * 4], 4);
            const std::uint32_t id = l == 0 ? k : by_size[k];
            PtexFace& face = f.faces[id];
            const int ru = face.ulog2 - l, rv = face.vlog2 - l;
            if (!face.constant() && ru >= 0 && rv >= 0) {
                const std::size_t slot = std::size_t(ru * (face.vlog2 + 1) + rv);
                decode(block, word, 1 << ru, 1 << rv, face.texels.data() + face.offsets[slot],
                       (1 << ru) * nch, decode);
                have[id][slot] = 1;
            }
            block += word & 0x3fffffff;
        }
        if (block > level_at + header_size + level_size)
            throw r.fail("the faces' blocks overrun level " + std::to_string(l));
        level_at += level_size;
    }

    // The reductions the file does not hold, as Ptex makes them.
    const bool integer = type == DataType::UInt8 || type == DataType::UInt16;
    for (std::uint32_t i = 0; i < nfaces; ++i) {
        PtexFace& face = f.faces[i];
        auto slot = [&](int ru, int rv) { return std::size_t(ru * (face.vlog2 + 1) + rv); };
        auto make = [&](int ru, int rv, auto& self) -> void {
            if (have[i][slot(ru, rv)]) return;
            const int redu = face.ulog2 - ru, redv = face.vlog2 - rv;
            const bool along_u = redu == redv ? (ru & 1) != 0 : redu > redv;
            const int su = along_u ? ru + 1 : ru, sv = along_u ? rv : rv + 1;
            self(su, sv, self);
            const float* src = face.texels.data() + face.offsets[slot(su, sv)];
            float* dst = face.texels.data() + face.offsets[slot(ru, rv)];
            const int uw = 1 << ru, vw = 1 << rv, src_row = (1 << su) * nch;
            for (int v = 0; v < vw; ++v)
                for (int u = 0; u < uw; ++u)
                    for (int c = 0; c < nch; ++c) {
                        const float* a = along_u
                                             ? src + std::size_t(v) * src_row + std::size_t(2 * u * nch + c)
                                             : src + std::size_t(2 * v) * src_row + std::size_t(u * nch + c);
                        float sum = a[0] + a[along_u ? nch : src_row];
                        dst[(std::size_t(v) * uw + std::size_t(u)) * nch + std::size_t(c)] =
                            integer ? std::floor(sum / 2) : sum / 2;
                    }
            have[i][slot(ru, rv)] = 1;
        };
        for (int ru = 0; ru <= face.ulog2; ++ru)
            for (int rv = 0; rv <= face.vlog2; ++rv) make(ru, rv, make);
    }
    return f;
}

} // namespace illum
