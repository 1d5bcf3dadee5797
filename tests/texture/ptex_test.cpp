// Ptex files (texture/ptex_file.h) written here in the format of ptex.us's "Ptex File Format" (a small
// writer: header, zipped face info, constant data, level info, level 0's zipped header and face blocks)
// and read back: texels of every encoding (constant, zipped, difference-zipped, tiled) and data type come
// back; the lookup interpolates texel centres bilinearly within a face; broken files are errors naming
// the file. (The "ptex" texture itself is not wired yet: see docs/scenes.md.)
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>
#include <zlib.h>

#include "illum/texture/ptex_file.h"
#include "illum/util/error.h"

namespace illum {
namespace {

std::string zip(const std::string& raw) {
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
// with 2x2 texel tiles, each zipped) and its texels as raw channel values (row-major, interleaved).
struct TestFace {
    int ulog2 = 0, vlog2 = 0, encoding = 1;
    std::vector<double> texels;
};

// Values as the data type stores them: 0 uint8, 1 uint16, 3 float.
std::string encode_values(const std::vector<double>& v, int type) {
    std::string s;
    for (double x : v) {
        if (type == 0) put(s, std::uint8_t(x));
        if (type == 1) put(s, std::uint16_t(x));
        if (type == 3) put(s, float(x));
    }
    return s;
}

// Channel planes of a ures x vres block cut from the face's texels at (u0, v0).
std::vector<double> planes(const TestFace& f, int nch, int u0, int v0, int ures, int vres) {
    std::vector<double> p;
    for (int c = 0; c < nch; ++c)
        for (int v = v0; v < v0 + vres; ++v)
            for (int u = u0; u < u0 + ures; ++u)
                p.push_back(f.texels[std::size_t(((v << f.ulog2) + u) * nch + c)]);
    return p;
}

std::string block(const TestFace& f, int nch, int type, int u0, int v0, int ures, int vres, int encoding,
                  std::uint32_t* word) {
    std::string data;
    if (encoding == 0) {
        data = encode_values(std::vector<double>(f.texels.begin(), f.texels.begin() + nch), type);
    } else {
        std::vector<double> p = planes(f, nch, u0, v0, ures, vres);
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

std::string ptex_bytes(const std::vector<TestFace>& faces, int nch, int type) {
    std::string info, constant, header_words, blocks;
    for (const TestFace& f : faces) {
        put(info, std::int8_t(f.ulog2));
        put(info, std::int8_t(f.vlog2));
        put(info, std::uint8_t(0));
        put(info, std::uint8_t(f.encoding == 0 ? 1 : 0));
        for (int i = 0; i < 4; ++i) put(info, std::int32_t(-1));
        constant += encode_values(std::vector<double>(f.texels.begin(), f.texels.begin() + nch), type);
        std::uint32_t word;
        int ures = 1 << f.ulog2, vres = 1 << f.vlog2;
        if (f.encoding == 3) {
            std::string tiles_headers, tiles;
            for (int vt = 0; vt < vres / 2; ++vt)
                for (int ut = 0; ut < ures / 2; ++ut) {
                    std::uint32_t w;
                    tiles += block(f, nch, type, ut * 2, vt * 2, 2, 2, 1, &w);
                    put(tiles_headers, w);
                }
            std::string zh = zip(tiles_headers), b;
            put(b, std::int8_t(1));
            put(b, std::int8_t(1));
            put(b, std::uint32_t(zh.size()));
            b += zh + tiles;
            word = std::uint32_t(b.size()) | (3u << 30);
            blocks += b;
        } else {
            blocks += block(f, nch, type, 0, 0, ures, vres, f.encoding, &word);
        }
        put(header_words, word);
    }
    std::string zinfo = zip(info), zconst = zip(constant), zlevel_header = zip(header_words);
    std::string level_data = zlevel_header + blocks;
    std::string level_info;
    put(level_info, std::uint64_t(level_data.size()));
    put(level_info, std::uint32_t(zlevel_header.size()));
    put(level_info, std::uint32_t(faces.size()));
    std::string zlevel_info = zip(level_info);
    std::string h;
    put(h, std::uint32_t('P' | ('t' << 8) | ('e' << 16) | ('x' << 24)));
    put(h, std::uint32_t(1));                  // version
    put(h, std::uint32_t(1));                  // quads
    put(h, std::uint32_t(type));               // data type
    put(h, std::int32_t(-1));                  // no alpha
    put(h, std::uint16_t(nch));                // channels
    put(h, std::uint16_t(1));                  // levels
    put(h, std::uint32_t(faces.size()));       // faces
    put(h, std::uint32_t(0));                  // extended header size
    put(h, std::uint32_t(zinfo.size()));       // face info
    put(h, std::uint32_t(zconst.size()));      // constant data
    put(h, std::uint32_t(zlevel_info.size())); // level info
    put(h, std::uint32_t(0));                  // minor version
    put(h, std::uint64_t(level_data.size()));
    put(h, std::uint32_t(0)); // meta data
    put(h, std::uint32_t(0));
    EXPECT_EQ(h.size(), 64u);
    return h + zinfo + zconst + zlevel_info + level_data;
}

std::string write_ptex(const std::string& name, const std::vector<TestFace>& faces, int nch, int type) {
    std::string path = ::testing::TempDir() + name;
    std::ofstream(path, std::ios::binary) << ptex_bytes(faces, nch, type);
    return path;
}

// A face of 2^ulog2 x 2^vlog2 texels with distinct values below `max`.
TestFace face(int ulog2, int vlog2, int encoding, int nch, int seed, double max) {
    TestFace f{ulog2, vlog2, encoding, {}};
    int n = (1 << ulog2) * (1 << vlog2) * nch;
    for (int i = 0; i < n; ++i) f.texels.push_back(std::fmod(37.0 * (i + 1) * (seed + 3), max));
    if (encoding == 0) // a constant face: every texel the same
        for (int i = 0; i < n; ++i) f.texels[std::size_t(i)] = 10.0 * (seed % 7) + i % nch;
    return f;
}

TEST(Ptex, EveryEncodingAndDataTypeReadsBack) {
    for (int type : {0, 1, 3}) {
        double max = type == 0 ? 256 : type == 1 ? 65536 : 1000;
        double scale = type == 0 ? 255 : type == 1 ? 65535 : 1;
        std::vector<TestFace> faces = {face(2, 1, 1, 3, 1, max), face(0, 0, 0, 3, 2, max),
                                       face(3, 2, 2, 3, 3, max), face(2, 2, 3, 3, 4, max),
                                       face(1, 3, 1, 3, 5, max)};
        PtexFile f = PtexFile::read(write_ptex("types.ptx", faces, 3, type));
        ASSERT_EQ(f.faces.size(), faces.size());
        EXPECT_EQ(f.channels, 3);
        for (std::size_t i = 0; i < faces.size(); ++i) {
            const PtexFace& got = f.faces[i];
            EXPECT_EQ(got.ures, 1 << faces[i].ulog2);
            EXPECT_EQ(got.vres, 1 << faces[i].vlog2);
            ASSERT_EQ(got.texels.size(), faces[i].texels.size());
            for (std::size_t k = 0; k < got.texels.size(); ++k)
                EXPECT_NEAR(got.texels[k], faces[i].texels[k] / scale, 1e-6)
                    << "type " << type << " face " << i;
        }
    }
}

TEST(Ptex, LookupInterpolatesTexelCentresWithinTheFace) {
    TestFace f{1, 0, 1, {0, 100}}; // 2 x 1 texels, one channel: 0 and 100 (uint8)
    PtexFile p = PtexFile::read(write_ptex("lookup.ptx", {f}, 1, 0));
    float v;
    auto at = [&](float u) {
        p.lookup(0, {u, 0.5f}, &v);
        return v * 255;
    };
    EXPECT_NEAR(at(0.25f), 0, 1e-4);   // the first texel's centre
    EXPECT_NEAR(at(0.75f), 100, 1e-4); // the second's
    EXPECT_NEAR(at(0.5f), 50, 1e-4);   // between them
    EXPECT_NEAR(at(0.0f), 0, 1e-4);    // clamped at the face's edges
    EXPECT_NEAR(at(1.0f), 100, 1e-4);
    p.lookup(7, {0.5f, 0.5f}, &v); // no such face
    EXPECT_EQ(v, 0.0f);
}

TEST(Ptex, BrokenFilesAreErrorsNamingTheFile) {
    std::string good = ptex_bytes({face(2, 2, 1, 3, 1, 256)}, 3, 0);
    std::string path = ::testing::TempDir() + "broken.ptx";
    auto expect = [&](const std::string& bytes, const std::string& needle) {
        std::ofstream(path, std::ios::binary) << bytes;
        try {
            PtexFile::read(path);
            ADD_FAILURE() << "no error for " << needle;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("broken.ptx"), std::string::npos) << e.what();
        }
    };
    expect("Ptxx" + good.substr(4), "does not start with \"Ptex\"");
    expect(good.substr(0, good.size() - 10), "truncated");
    std::string bad_type = good;
    bad_type[12] = 9;
    expect(bad_type, "unknown data type 9");
}

} // namespace
} // namespace illum
