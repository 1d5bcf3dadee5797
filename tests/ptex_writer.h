// A small Ptex writer for tests, in the format of ptex.us's "Ptex File Format" (texture/ptex_file.h): header,
// extended header (border modes), zipped face info and constant data, the level info (not zipped), then
// level 0 (every face)
// and, when asked, reduction levels as Ptex's writer makes them (faces in the order of decreasing smaller
// side, level i holding those whose smaller side is at least 2^(i+2), each face reduced 2 x 2 by averaging
// in the data type, integers rounded down).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <numeric>
#include <string>
#include <vector>
#include <zlib.h>

namespace illum::test {

inline std::string zip(const std::string& raw) {
    uLongf n = compressBound(uLong(raw.size()));
    std::string out(n, '\0');
    EXPECT_EQ(compress(reinterpret_cast<Bytef*>(out.data()), &n, reinterpret_cast<const Bytef*>(raw.data()),
                       uLong(raw.size())),
              Z_OK);
    out.resize(n);
    return out;
}
template <class T>
void put(std::string& s, T v) {
    s.append(reinterpret_cast<const char*>(&v), sizeof(T));
}

// One face of a test file: log2 resolution, its encoding (0 constant, 1 zipped, 2 diffzipped, 3 tiled
// with 2x2 texel tiles, each zipped), its texels as raw channel values (row-major, interleaved), and its
// adjacent faces and edges (bottom, right, top, left) and flags beyond "constant".
struct TestFace {
    int ulog2 = 0, vlog2 = 0, encoding = 1;
    std::vector<double> texels;
    int adjacent[4] = {-1, -1, -1, -1};
    int edges[4] = {0, 0, 0, 0};
    int extra_flags = 0;
};

// Values as the data type stores them: 0 uint8, 1 uint16, 3 float.
inline std::string encode_values(const std::vector<double>& v, int type) {
    std::string s;
    for (double x : v) {
        if (type == 0) put(s, std::uint8_t(x));
        if (type == 1) put(s, std::uint16_t(x));
        if (type == 3) put(s, float(x));
    }
    return s;
}

// Channel planes of a ures x vres block cut from texels of row length `row` at (u0, v0).
inline std::vector<double> planes(const std::vector<double>& texels, int row, int nch, int u0, int v0,
                                  int ures, int vres) {
    std::vector<double> p;
    for (int c = 0; c < nch; ++c)
        for (int v = v0; v < v0 + vres; ++v)
            for (int u = u0; u < u0 + ures; ++u) p.push_back(texels[std::size_t((v * row + u) * nch + c)]);
    return p;
}

inline std::string block(const std::vector<double>& texels, int row, int nch, int type, int u0, int v0,
                         int ures, int vres, int encoding, std::uint32_t* word) {
    std::string data;
    if (encoding == 0) {
        data = encode_values(std::vector<double>(texels.begin(), texels.begin() + nch), type);
    } else {
        std::vector<double> p = planes(texels, row, nch, u0, v0, ures, vres);
        if (encoding == 2 && type != 3) { // differences, wrapping, for the integer types only (as Ptex)
            double prev = 0, mod = type == 0 ? 256 : 65536;
            for (double& x : p) {
                double d = x - prev;
                prev = x;
                x = d < 0 ? d + mod : d;
            }
        }
        data = zip(encode_values(p, type));
    }
    *word = std::uint32_t(data.size()) | (std::uint32_t(encoding) << 30);
    return data;
}

// The face's data block (encoding as the face says; tiles of 2 x 2 texels for encoding 3).
inline std::string face_block(const std::vector<double>& texels, int ulog2, int vlog2, int encoding, int nch,
                              int type, std::uint32_t* word) {
    int ures = 1 << ulog2, vres = 1 << vlog2;
    if (encoding != 3) return block(texels, ures, nch, type, 0, 0, ures, vres, encoding, word);
    std::string tiles_headers, tiles;
    for (int vt = 0; vt < vres / 2; ++vt)
        for (int ut = 0; ut < ures / 2; ++ut) {
            std::uint32_t w;
            tiles += block(texels, ures, nch, type, ut * 2, vt * 2, 2, 2, 1, &w);
            put(tiles_headers, w);
        }
    std::string zh = zip(tiles_headers), b;
    put(b, std::int8_t(1));
    put(b, std::int8_t(1));
    put(b, std::uint32_t(zh.size()));
    b += zh + tiles;
    *word = std::uint32_t(b.size()) | (3u << 30);
    return b;
}

// A 2 x 2 box reduction of ures x vres texels, in the data type (integers rounded down).
inline std::vector<double> reduce(const std::vector<double>& t, int ures, int vres, int nch, int type) {
    std::vector<double> out;
    for (int v = 0; v < vres / 2; ++v)
        for (int u = 0; u < ures / 2; ++u)
            for (int c = 0; c < nch; ++c) {
                auto at = [&](int uu, int vv) { return t[std::size_t((vv * ures + uu) * nch + c)]; };
                double s =
                    at(2 * u, 2 * v) + at(2 * u + 1, 2 * v) + at(2 * u, 2 * v + 1) + at(2 * u + 1, 2 * v + 1);
                out.push_back(type == 3 ? s / 4 : std::floor(s / 4));
            }
    return out;
}

struct PtexOptions {
    int u_border = 0, v_border = 0; // 0 clamp, 1 black, 2 periodic
    bool reductions = false;
    // Replaces the stored reduction of level 1 of face `marked_face` by this value (to see it read).
    int marked_face = -1;
    double marker = 0;
};

inline std::string ptex_bytes(const std::vector<TestFace>& faces, int nch, int type,
                              const PtexOptions& o = {}) {
    std::string info, constant, header_words, blocks;
    std::vector<std::vector<double>> full;
    for (const TestFace& f : faces) {
        put(info, std::int8_t(f.ulog2));
        put(info, std::int8_t(f.vlog2));
        int adjedges = 0;
        for (int e = 0; e < 4; ++e) adjedges |= (f.edges[e] & 3) << (2 * e);
        put(info, std::uint8_t(adjedges));
        put(info, std::uint8_t((f.encoding == 0 ? 1 : 0) | f.extra_flags));
        for (int e = 0; e < 4; ++e) put(info, std::int32_t(f.adjacent[e]));
        // The constant data: the face's mean (rounded down for integers).
        std::vector<double> mean(std::size_t(nch), 0.0);
        int n = (1 << f.ulog2) * (1 << f.vlog2);
        for (int i = 0; i < n; ++i)
            for (int c = 0; c < nch; ++c) mean[std::size_t(c)] += f.texels[std::size_t(i * nch + c)] / n;
        if (f.encoding == 0) mean.assign(f.texels.begin(), f.texels.begin() + nch);
        for (double& m : mean)
            if (type != 3) m = std::floor(m + 1e-9);
        constant += encode_values(mean, type);
        std::uint32_t word;
        blocks += face_block(f.texels, f.ulog2, f.vlog2, f.encoding, nch, type, &word);
        put(header_words, word);
    }
    std::vector<std::string> level_data;
    std::vector<std::uint32_t> level_header_sizes, level_faces;
    auto add_level = [&](const std::string& words, const std::string& data, std::size_t count) {
        std::string zh = zip(words);
        level_data.push_back(zh + data);
        level_header_sizes.push_back(std::uint32_t(zh.size()));
        level_faces.push_back(std::uint32_t(count));
    };
    add_level(header_words, blocks, faces.size());
    if (o.reductions) {
        std::vector<int> order(faces.size());
        std::iota(order.begin(), order.end(), 0);
        auto smaller = [&](int i) {
            return faces[std::size_t(i)].encoding == 0
                       ? 1
                       : std::min(faces[std::size_t(i)].ulog2, faces[std::size_t(i)].vlog2);
        };
        std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return smaller(a) > smaller(b); });
        std::vector<std::vector<double>> current;
        for (const TestFace& f : faces) current.push_back(f.texels);
        for (int level = 1;; ++level) {
            std::string words, data;
            std::size_t count = 0;
            for (int id : order) {
                const TestFace& f = faces[std::size_t(id)];
                if (smaller(id) - level < 2) break;
                int ures = 1 << (f.ulog2 - level + 1), vres = 1 << (f.vlog2 - level + 1);
                current[std::size_t(id)] = reduce(current[std::size_t(id)], ures, vres, nch, type);
                std::vector<double> stored = current[std::size_t(id)];
                if (id == o.marked_face && level == 1) std::fill(stored.begin(), stored.end(), o.marker);
                std::uint32_t w;
                data += face_block(stored, f.ulog2 - level, f.vlog2 - level, 1, nch, type, &w);
                put(words, w);
                ++count;
            }
            if (count == 0) break;
            add_level(words, data, count);
        }
    }
    std::string zinfo = zip(info), zconst = zip(constant);
    std::string level_info, all_levels;
    for (std::size_t l = 0; l < level_data.size(); ++l) {
        put(level_info, std::uint64_t(level_data[l].size()));
        put(level_info, level_header_sizes[l]);
        put(level_info, level_faces[l]);
        all_levels += level_data[l];
    }
    const std::string& zlevel_info = level_info; // not zipped
    std::string ext;
    put(ext, std::uint16_t(o.u_border));
    put(ext, std::uint16_t(0));
    put(ext, std::uint16_t(o.v_border));
    put(ext, std::uint16_t(0));
    std::string h;
    put(h, std::uint32_t('P' | ('t' << 8) | ('e' << 16) | ('x' << 24)));
    put(h, std::uint32_t(1));                  // version
    put(h, std::uint32_t(1));                  // quads
    put(h, std::uint32_t(type));               // data type
    put(h, std::int32_t(-1));                  // no alpha
    put(h, std::uint16_t(nch));                // channels
    put(h, std::uint16_t(level_data.size()));  // levels
    put(h, std::uint32_t(faces.size()));       // faces
    put(h, std::uint32_t(ext.size()));         // extended header size
    put(h, std::uint32_t(zinfo.size()));       // face info
    put(h, std::uint32_t(zconst.size()));      // constant data
    put(h, std::uint32_t(zlevel_info.size())); // level info
    put(h, std::uint32_t(0));                  // minor version
    put(h, std::uint64_t(all_levels.size()));
    put(h, std::uint32_t(0)); // meta data
    put(h, std::uint32_t(0));
    EXPECT_EQ(h.size(), 64u);
    return h + ext + zinfo + zconst + zlevel_info + all_levels;
}

inline std::string write_ptex(const std::string& name, const std::vector<TestFace>& faces, int nch, int type,
                              const PtexOptions& o = {}) {
    std::string path = ::testing::TempDir() + name;
    std::ofstream(path, std::ios::binary) << ptex_bytes(faces, nch, type, o);
    return path;
}

// A constant face of one colour (raw values), 1 x 1.
inline TestFace constant_face(std::vector<double> value) { return TestFace{0, 0, 0, std::move(value)}; }

} // namespace illum::test
