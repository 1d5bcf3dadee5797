// PLY reader: the three encodings read back identically, gzip, odd layouts, errors, and the coffee meshes.
#include "illum/geometry/ply.h"

#include <gtest/gtest.h>

#include <bit>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <unistd.h>
#include <zlib.h>

#include "test_util.h"

namespace illum {
namespace {

using test::expect_error;

// Writes PLY bodies in any of the three encodings. Type codes: b=int8 B=uint8 h=int16 H=uint16 i=int32
// I=uint32 f=float d=double.
class PlyWriter {
public:
    enum Fmt { Ascii, LE, BE };
    explicit PlyWriter(Fmt f) : fmt_(f) {}

    void header(const std::string& body_header) {
        static const char* names[] = {"ascii", "binary_little_endian", "binary_big_endian"};
        out_ += fmt::format("ply\nformat {} 1.0\n{}end_header\n", names[fmt_], body_header);
    }

    void put(char type, double v) {
        if (fmt_ == Ascii) {
            if (!line_start_) out_ += ' ';
            out_ += fmt::format("{}", v);
            line_start_ = false;
            return;
        }
        switch (type) {
        case 'b':
            raw<int8_t>(int8_t(v));
            break;
        case 'B':
            raw<uint8_t>(uint8_t(v));
            break;
        case 'h':
            raw<int16_t>(int16_t(v));
            break;
        case 'H':
            raw<uint16_t>(uint16_t(v));
            break;
        case 'i':
            raw<int32_t>(int32_t(v));
            break;
        case 'I':
            raw<uint32_t>(uint32_t(v));
            break;
        case 'f':
            raw<float>(float(v));
            break;
        case 'd':
            raw<double>(v);
            break;
        default:
            ADD_FAILURE() << "bad type code";
        }
    }
    void end_item() {
        if (fmt_ == Ascii) out_ += '\n';
        line_start_ = true;
    }
    const std::string& data() const { return out_; }

private:
    template <class T>
    void raw(T v) {
        unsigned char b[sizeof(T)];
        std::memcpy(b, &v, sizeof(T));
        bool little = std::endian::native == std::endian::little;
        if ((fmt_ == LE) != little)
            for (size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
        out_.append(reinterpret_cast<const char*>(b), sizeof(T));
    }
    Fmt fmt_;
    std::string out_;
    bool line_start_ = true;
};

struct V {
    float x, y, z, nx, ny, nz, s, t;
};
const V kVerts[] = {{0, 0, 0, 0, 0, 1, 0, 0},
                    {1, 0, 0, 0, 0, 1, 1, 0},
                    {1, 1, 0, 0, 0, 1, 1, 1},
                    {0, 1, 0.5f, 0, 0.5f, 1, 0, 1},
                    {-1.25f, 2, 3e-3f, 1, 0, 0, 0.25f, 0.75f}};
const std::vector<std::vector<int>> kFaces = {{0, 1, 2}, {0, 1, 3, 4}, {0, 1, 2, 3, 4}, {2, 3}};

// A mesh with unusual layout: an unknown element first, mixed property types and order, an unknown list
// property per vertex, per-face indices, a quad, a pentagon and a two-vertex face.
std::string make_ply(PlyWriter::Fmt f) {
    PlyWriter w(f);
    w.header("comment written by ply_test\n"
             "element material 2\nproperty list uchar float coeffs\nproperty int id\n"
             "element vertex 5\nproperty double x\nproperty uchar flag\nproperty float y\nproperty float z\n"
             "property float nx\nproperty float ny\nproperty float nz\nproperty float s\nproperty float t\n"
             "property list uchar int extra\n"
             "element face 4\nproperty int face_indices\nproperty list uchar uint vertex_indices\n");
    for (int m = 0; m < 2; ++m) {
        w.put('B', 2);
        w.put('f', 0.5);
        w.put('f', 1.5);
        w.put('i', m);
        w.end_item();
    }
    for (const V& v : kVerts) {
        w.put('d', v.x);
        w.put('B', 200);
        w.put('f', v.y);
        w.put('f', v.z);
        w.put('f', v.nx);
        w.put('f', v.ny);
        w.put('f', v.nz);
        w.put('f', v.s);
        w.put('f', v.t);
        w.put('B', 1);
        w.put('i', -7);
        w.end_item();
    }
    int fi = 7;
    for (auto& face : kFaces) {
        w.put('i', fi++);
        w.put('B', double(face.size()));
        for (int i : face) w.put('I', i);
        w.end_item();
    }
    return w.data();
}

void expect_test_mesh(const TriangleMeshData& m) {
    ASSERT_EQ(m.positions.size(), 5u);
    ASSERT_EQ(m.normals.size(), 5u);
    ASSERT_EQ(m.uvs.size(), 5u);
    for (int i = 0; i < 5; ++i) {
        const V& v = kVerts[i];
        EXPECT_EQ(m.positions[i], Point3f(v.x, v.y, v.z));
        EXPECT_EQ(m.normals[i], Normal3f(v.nx, v.ny, v.nz));
        EXPECT_EQ(m.uvs[i], Point2f(v.s, v.t));
    }
    EXPECT_EQ(m.indices, (std::vector<int>{0, 1, 2, 0, 1, 3, 0, 3, 4, 0, 1, 2, 0, 2, 3, 0, 3, 4}));
    EXPECT_EQ(m.face_indices, (std::vector<int>{7, 8, 8, 9, 9, 9}));
    EXPECT_EQ(m.skipped_faces, 1u);
}

TEST(Ply, ThreeEncodingsReadBackIdentically) {
    test::TempDir dir("ply");
    TriangleMeshData r[3];
    const char* names[] = {"ascii.ply", "le.ply", "be.ply"};
    for (int f = 0; f < 3; ++f) {
        SCOPED_TRACE(names[f]);
        std::string path = dir.write(names[f], make_ply(PlyWriter::Fmt(f)));
        r[f] = read_ply(path);
        expect_test_mesh(r[f]);
    }
    EXPECT_EQ(r[0].positions, r[1].positions);
    EXPECT_EQ(r[1].positions, r[2].positions);
    EXPECT_EQ(r[0].indices, r[2].indices);
}

TEST(Ply, CrlfHeaderAndOtherNames) {
    // vertex_index, texture_u/texture_v, int16 positions, no normals, big-endian ushort counts.
    PlyWriter w(PlyWriter::BE);
    std::string h = "element vertex 3\r\nproperty short x\r\nproperty short y\r\nproperty short z\r\n"
                    "property float texture_u\r\nproperty float texture_v\r\n"
                    "element face 1\r\nproperty list ushort short vertex_index\r\n";
    std::string data = "ply\r\nformat binary_big_endian 1.0\r\n" + h + "end_header\r\n";
    PlyWriter body(PlyWriter::BE);
    const int P[3][3] = {{1, 2, 3}, {-4, 5, 6}, {7, 8, -9}};
    for (int i = 0; i < 3; ++i) {
        for (int k = 0; k < 3; ++k) body.put('h', P[i][k]);
        body.put('f', 0.5 * i);
        body.put('f', 1);
    }
    body.put('H', 3);
    for (int i : {2, 1, 0}) body.put('h', i);
    data += body.data();
    TriangleMeshData m = parse_ply(data.data(), data.size(), "mem.ply");
    ASSERT_EQ(m.positions.size(), 3u);
    EXPECT_EQ(m.positions[1], Point3f(-4, 5, 6));
    EXPECT_TRUE(m.normals.empty());
    ASSERT_EQ(m.uvs.size(), 3u);
    EXPECT_EQ(m.uvs[2], Point2f(1, 1));
    EXPECT_EQ(m.indices, (std::vector<int>{2, 1, 0}));
    EXPECT_TRUE(m.face_indices.empty());
}

TEST(Ply, GzipCompressed) {
    test::TempDir dir("plygz");
    std::string raw = make_ply(PlyWriter::LE);
    std::string path = dir.file("mesh.ply.gz");
    gzFile g = gzopen(path.c_str(), "wb");
    ASSERT_NE(g, nullptr);
    ASSERT_EQ(gzwrite(g, raw.data(), unsigned(raw.size())), int(raw.size()));
    gzclose(g);
    ASSERT_NE(raw.size(), std::filesystem::file_size(path)); // it really is compressed
    expect_test_mesh(read_ply(path));
}

TEST(Ply, Errors) {
    test::TempDir dir("plyerr");
    std::string good = make_ply(PlyWriter::LE);
    std::string truncated = dir.write("truncated.ply", good.substr(0, good.size() - 3));
    expect_error([&] { read_ply(truncated); }, truncated, "truncated file");
    expect_error([&] { read_ply(truncated); }, truncated, "element \"face\", item 3 of 4");

    std::string no_faces = dir.write("short.ply", good.substr(0, good.find("end_header") + 11 + 20));
    expect_error([&] { read_ply(no_faces); }, no_faces, "element \"material\"");

    std::string ascii =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 5\n";
    std::string bad_index = dir.write("bad_index.ply", ascii);
    expect_error([&] { read_ply(bad_index); }, bad_index + ":14:1",
                 "vertex index 5 out of range (3 vertices)");

    std::string bad_number = dir.write("bad_number.ply", ascii.substr(0, ascii.size() - 8) + "3 0 x 2\n");
    expect_error([&] { read_ply(bad_number); }, bad_number + ":14:1", "malformed number \"x\"");

    std::string not_ply = dir.write("not.ply", "hello\n");
    expect_error([&] { read_ply(not_ply); }, not_ply + ":1:1", "does not start with \"ply\"");

    std::string bad_format = dir.write("fmt.ply", "ply\nformat binary_middle_endian 1.0\nend_header\n");
    expect_error([&] { read_ply(bad_format); }, bad_format + ":2:1", "unsupported format");

    std::string bad_type =
        dir.write("type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty flaot x\n");
    expect_error([&] { read_ply(bad_type); }, bad_type + ":4:1", "unknown property type \"flaot\"");

    std::string no_end =
        dir.write("noend.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n");
    expect_error([&] { read_ply(no_end); }, no_end, "no end_header");

    std::string no_z = dir.write("noz.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                                            "property float y\nelement face 0\nproperty list uchar int "
                                            "vertex_indices\nend_header\n0 0\n");
    expect_error([&] { read_ply(no_z); }, no_z, "lacks x, y or z");

    // The operating system's reason is part of the message.
    expect_error([&] { read_ply(dir.file("missing.ply")); }, dir.file("missing.ply"),
                 std::string("cannot open PLY file: ") + std::strerror(ENOENT));
    std::filesystem::create_directories(dir.file("adir.ply"));
    expect_error([&] { read_ply(dir.file("adir.ply")); }, dir.file("adir.ply"),
                 std::string("cannot open PLY file: ") + std::strerror(EISDIR));
    std::string locked = dir.write("locked.ply", "ply\n");
    std::filesystem::permissions(locked, std::filesystem::perms::none);
    if (::geteuid() != 0) { // root reads it anyway
        expect_error([&] { read_ply(locked); }, locked,
                     std::string("cannot open PLY file: ") + std::strerror(EACCES));
    }

    std::string huge =
        dir.write("huge.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000000\n"
                              "property float x\nproperty float y\nproperty float z\n"
                              "element face 1\nproperty list uchar int vertex_indices\n"
                              "end_header\n\1\2\3\4");
    expect_error([&] { read_ply(huge); }, huge, "too many vertices");
}

TEST(Ply, CoffeeMeshes) {
    if (!test::shared_dir_exists()) GTEST_SKIP() << "shared dir absent";
    std::filesystem::path models = std::filesystem::path(ILLUM_SHARED_DIR) / "scenes/coffee/models";
    if (!std::filesystem::is_directory(models)) GTEST_SKIP() << "coffee models absent";
    int files = 0;
    for (auto& entry : std::filesystem::directory_iterator(models)) {
        if (entry.path().extension() != ".ply") continue;
        SCOPED_TRACE(entry.path().string());
        TriangleMeshData m = read_ply(entry.path().string());
        ++files;
        EXPECT_GT(m.positions.size(), 0u);
        EXPECT_GT(m.indices.size(), 0u);
        EXPECT_EQ(m.indices.size() % 3, 0u);
        EXPECT_TRUE(m.normals.empty() || m.normals.size() == m.positions.size());
        EXPECT_EQ(m.uvs.size(), m.positions.size()); // every coffee mesh has u v
        for (int i : m.indices) ASSERT_TRUE(i >= 0 && size_t(i) < m.positions.size());
        for (auto& p : m.positions)
            ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
        if (entry.path().filename() == "Mesh000.ply") {
            EXPECT_EQ(m.positions.size(), 8150u);
            EXPECT_EQ(m.normals.size(), 8150u);
            EXPECT_GE(m.indices.size(), 3u * 10848u);
        }
        if (entry.path().filename() == "Mesh005.ply") {
            EXPECT_EQ(m.positions.size(), 8968u);
            EXPECT_TRUE(m.normals.empty());
        }
    }
    EXPECT_EQ(files, 20);
}

} // namespace
} // namespace illum
