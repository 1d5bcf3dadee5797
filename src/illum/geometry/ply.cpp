#include "illum/geometry/ply.h"

#include <algorithm>
#include <bit>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fmt/format.h>
#include <limits>
#include <string_view>
#include <sys/stat.h>
#include <zlib.h>

#include "illum/util/error.h"

namespace illum {

namespace {

enum class PlyType { I8, U8, I16, U16, I32, U32, F32, F64 };

int type_size(PlyType t) {
    switch (t) {
    case PlyType::I8:
    case PlyType::U8:
        return 1;
    case PlyType::I16:
    case PlyType::U16:
        return 2;
    case PlyType::I32:
    case PlyType::U32:
    case PlyType::F32:
        return 4;
    case PlyType::F64:
        return 8;
    }
    return 1;
}

bool type_from_name(std::string_view s, PlyType& t) {
    struct Entry {
        const char* a;
        const char* b;
        PlyType t;
    };
    static const Entry table[] = {{"char", "int8", PlyType::I8},      {"uchar", "uint8", PlyType::U8},
                                  {"short", "int16", PlyType::I16},   {"ushort", "uint16", PlyType::U16},
                                  {"int", "int32", PlyType::I32},     {"uint", "uint32", PlyType::U32},
                                  {"float", "float32", PlyType::F32}, {"double", "float64", PlyType::F64}};
    for (auto& e : table)
        if (s == e.a || s == e.b) {
            t = e.t;
            return true;
        }
    return false;
}

struct Property {
    std::string name;
    PlyType type = PlyType::F32; // value type (list element type for a list)
    bool is_list = false;
    PlyType count_type = PlyType::U8;
};

struct Element {
    std::string name;
    uint64_t count = 0;
    std::vector<Property> props;
};

enum class Format { Ascii, BinaryLE, BinaryBE };

// Reads values from the body, in one of the three encodings, with bounds checks.
class BodyReader {
public:
    BodyReader(const char* p, const char* end, Format fmt, int first_line, const std::string& name)
        : p_(p), end_(end), fmt_(fmt), line_(first_line), name_(name) {
        swap_ = (fmt == Format::BinaryLE) != (std::endian::native == std::endian::little);
    }

    // Context for errors.
    const char* element = "";
    uint64_t item = 0, count = 0;

    size_t remaining() const { return size_t(end_ - p_); }
    bool ascii() const { return fmt_ == Format::Ascii; }

    [[noreturn]] void fail(const std::string& what) const {
        SourceLocation loc{name_, ascii() ? line_ : 0, 0};
        if (ascii()) loc.column = 1;
        throw Error(loc, fmt::format("{} (element \"{}\", item {} of {})", what, element, item, count));
    }

    double read(PlyType t) {
        if (ascii()) return read_ascii();
        int n = type_size(t);
        if (remaining() < size_t(n)) fail("truncated file: the data ends early");
        unsigned char b[8];
        std::memcpy(b, p_, n);
        p_ += n;
        if (swap_)
            for (int i = 0; i < n / 2; ++i) std::swap(b[i], b[n - 1 - i]);
        switch (t) {
        case PlyType::I8:
            return double(int8_t(b[0]));
        case PlyType::U8:
            return double(b[0]);
        case PlyType::I16:
            return double(load<int16_t>(b));
        case PlyType::U16:
            return double(load<uint16_t>(b));
        case PlyType::I32:
            return double(load<int32_t>(b));
        case PlyType::U32:
            return double(load<uint32_t>(b));
        case PlyType::F32:
            return double(load<float>(b));
        case PlyType::F64:
            return load<double>(b);
        }
        return 0;
    }

    // Skips n values of type t.
    void skip(PlyType t, uint64_t n) {
        if (ascii()) {
            for (uint64_t i = 0; i < n; ++i) read_ascii();
            return;
        }
        uint64_t bytes = uint64_t(type_size(t));
        if (n > remaining() / bytes) fail("truncated file: the data ends early");
        p_ += n * bytes;
    }

    // A list count: a nonnegative integer.
    uint64_t read_count(PlyType t) {
        double v = read(t);
        if (!(v >= 0 && v == std::floor(v) && v < 1e15)) fail(fmt::format("bad list length {}", v));
        return uint64_t(v);
    }

private:
    template <class T>
    static T load(const unsigned char* b) {
        T v;
        std::memcpy(&v, b, sizeof(T));
        return v;
    }

    double read_ascii() {
        while (p_ < end_ && (*p_ == ' ' || *p_ == '\t' || *p_ == '\r' || *p_ == '\n')) {
            if (*p_ == '\n') ++line_;
            ++p_;
        }
        if (p_ >= end_) fail("truncated file: the data ends early");
        const char* s = p_;
        while (p_ < end_ && !(*p_ == ' ' || *p_ == '\t' || *p_ == '\r' || *p_ == '\n')) ++p_;
        const char* b = s;
        if (*b == '+') ++b;
        double v = 0;
        auto [ptr, ec] = std::from_chars(b, p_, v);
        if (ptr != p_ || (ec != std::errc() && ec != std::errc::result_out_of_range))
            fail(fmt::format("malformed number \"{}\"", std::string_view(s, std::min<size_t>(p_ - s, 40))));
        return v;
    }

    const char* p_;
    const char* end_;
    Format fmt_;
    bool swap_ = false;
    int line_;
    const std::string& name_;
};

std::vector<std::string_view> split_words(std::string_view line) {
    std::vector<std::string_view> w;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        size_t j = i;
        while (j < line.size() && line[j] != ' ' && line[j] != '\t') ++j;
        if (j > i) w.push_back(line.substr(i, j - i));
        i = j;
    }
    return w;
}

// "cannot open PLY file: <the operating system's reason>", so a wrong path and a missing permission read
// differently. errno is read at once, before anything else can change it.
[[noreturn]] void open_failed(const std::string& path, int err) {
    throw Error(SourceLocation{path, 0, 0}, fmt::format("cannot open PLY file: {}", std::strerror(err)));
}

// The file's bytes, gunzipped when it starts with gzip's magic number. Throws illum::Error with the reason.
void read_file(const std::string& path, std::string& out) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) open_failed(path, errno);
    struct CloseFile {
        std::FILE*& f;
        ~CloseFile() {
            if (f) std::fclose(f);
        }
    } close_file{f};
    // fopen opens a directory on Linux (reading it then fails with EISDIR): say so at once. Other
    // non-regular files (a FIFO, /dev/zero) might never end, so they are refused too.
    struct stat st {};
    if (::fstat(::fileno(f), &st) != 0) open_failed(path, errno);
    if (S_ISDIR(st.st_mode)) open_failed(path, EISDIR);
    if (!S_ISREG(st.st_mode))
        throw Error(SourceLocation{path, 0, 0}, "cannot open PLY file: not a regular file");
    unsigned char magic[2] = {0, 0};
    size_t m = std::fread(magic, 1, 2, f);
    bool gz = m == 2 && magic[0] == 0x1f && magic[1] == 0x8b;
    if (!gz) {
        // One read into a buffer of the file's size (no growing copies: PLY files reach hundreds of MB).
        out.resize(size_t(st.st_size));
        std::memcpy(out.data(), magic, std::min(m, out.size()));
        size_t got = out.size() > m ? std::fread(out.data() + m, 1, out.size() - m, f) : 0;
        out.resize(std::min(out.size(), m + got));
        if (std::ferror(f)) {
            int err = errno;
            throw Error(SourceLocation{path, 0, 0},
                        fmt::format("cannot read PLY file: {}", std::strerror(err)));
        }
        return;
    }
    std::fclose(f);
    f = nullptr;
    errno = 0;
    gzFile g = gzopen(path.c_str(), "rb");
    if (!g) open_failed(path, errno ? errno : ENOMEM); // zlib leaves errno 0 when it ran out of memory
    gzbuffer(g, 1 << 17);
    out.clear();
    size_t used = 0;
    while (true) {
        if (out.size() - used < (1 << 20)) out.resize(std::max<size_t>(out.size() * 2, used + (1 << 20)));
        int n = gzread(g, out.data() + used,
                       unsigned(out.size() - used > (1u << 30) ? (1u << 30) : out.size() - used));
        if (n < 0) {
            int err = 0;
            std::string msg = gzerror(g, &err);
            gzclose(g);
            throw Error(SourceLocation{path, 0, 0}, fmt::format("gzip error: {}", msg));
        }
        if (n == 0) break;
        used += size_t(n);
    }
    gzclose(g);
    out.resize(used);
}

} // namespace

TriangleMeshData read_ply(const std::string& path, bool keep_quads) {
    std::string data;
    read_file(path, data);
    return parse_ply(data.data(), data.size(), path, keep_quads);
}

TriangleMeshData parse_ply(const char* data, size_t size, const std::string& name, bool keep_quads) {
    auto header_error = [&](int line, const std::string& msg) {
        throw Error(SourceLocation{name, line, line ? 1 : 0}, "bad PLY header: " + msg);
    };

    // ---- Header ----
    std::string_view text(data, size);
    size_t pos = 0;
    int line_no = 0;
    auto next_line = [&](std::string_view& line) {
        if (pos >= text.size()) return false;
        size_t nl = text.find('\n', pos);
        size_t end = nl == std::string_view::npos ? text.size() : nl;
        line = text.substr(pos, end - pos);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        pos = nl == std::string_view::npos ? text.size() : nl + 1;
        ++line_no;
        return true;
    };
    std::string_view line;
    if (!next_line(line) || line != "ply") header_error(1, "the file does not start with \"ply\"");
    Format format = Format::Ascii;
    bool have_format = false, ended = false;
    std::vector<Element> elements;
    while (next_line(line)) {
        auto w = split_words(line);
        if (w.empty()) continue;
        if (w[0] == "comment" || w[0] == "obj_info") continue;
        if (w[0] == "end_header") {
            ended = true;
            break;
        }
        if (w[0] == "format") {
            if (w.size() != 3) header_error(line_no, "expected \"format <type> 1.0\"");
            if (w[1] == "ascii")
                format = Format::Ascii;
            else if (w[1] == "binary_little_endian")
                format = Format::BinaryLE;
            else if (w[1] == "binary_big_endian")
                format = Format::BinaryBE;
            else
                header_error(line_no, fmt::format("unsupported format \"{}\"", w[1]));
            if (w[2] != "1.0" && w[2] != "1")
                header_error(line_no, fmt::format("unsupported version \"{}\"", w[2]));
            have_format = true;
        } else if (w[0] == "element") {
            if (w.size() != 3) header_error(line_no, "expected \"element <name> <count>\"");
            Element e;
            e.name = std::string(w[1]);
            auto [ptr, ec] = std::from_chars(w[2].data(), w[2].data() + w[2].size(), e.count);
            if (ec != std::errc() || ptr != w[2].data() + w[2].size())
                header_error(line_no, fmt::format("bad element count \"{}\"", w[2]));
            elements.push_back(std::move(e));
        } else if (w[0] == "property") {
            if (elements.empty()) header_error(line_no, "property before any element");
            Property p;
            if (w.size() == 5 && w[1] == "list") {
                p.is_list = true;
                if (!type_from_name(w[2], p.count_type))
                    header_error(line_no, fmt::format("unknown property type \"{}\"", w[2]));
                if (p.count_type == PlyType::F32 || p.count_type == PlyType::F64)
                    header_error(line_no, "a list count must have an integer type");
                if (!type_from_name(w[3], p.type))
                    header_error(line_no, fmt::format("unknown property type \"{}\"", w[3]));
                p.name = std::string(w[4]);
            } else if (w.size() == 3) {
                if (!type_from_name(w[1], p.type))
                    header_error(line_no, fmt::format("unknown property type \"{}\"", w[1]));
                p.name = std::string(w[2]);
            } else {
                header_error(line_no, "expected \"property <type> <name>\" or \"property list <count type> "
                                      "<type> <name>\"");
            }
            elements.back().props.push_back(std::move(p));
        } else {
            header_error(line_no, fmt::format("unknown header keyword \"{}\"",
                                              w[0].substr(0, std::min<size_t>(w[0].size(), 40))));
        }
    }
    if (!ended) header_error(0, "no end_header line");
    if (!have_format) header_error(0, "no format line");

    const Element* vertex = nullptr;
    const Element* face = nullptr;
    for (auto& e : elements) {
        if (e.name == "vertex" && !vertex) vertex = &e;
        if (e.name == "face" && !face) face = &e;
    }
    if (!vertex) throw Error(SourceLocation{name, 0, 0}, "PLY file has no \"vertex\" element");
    if (!face) throw Error(SourceLocation{name, 0, 0}, "PLY file has no \"face\" element");

    // Vertex property slots: 0-2 position, 3-5 normal, 6-7 uv.
    std::vector<int> vslot(vertex->props.size(), -1);
    {
        bool have[8] = {};
        auto find = [&](std::initializer_list<const char*> names, int slot) {
            for (size_t i = 0; i < vertex->props.size(); ++i)
                for (const char* n : names)
                    if (vertex->props[i].name == n && !vertex->props[i].is_list && !have[slot]) {
                        vslot[i] = slot;
                        have[slot] = true;
                        return;
                    }
        };
        find({"x"}, 0);
        find({"y"}, 1);
        find({"z"}, 2);
        find({"nx"}, 3);
        find({"ny"}, 4);
        find({"nz"}, 5);
        find({"u", "s", "texture_u", "texture_s"}, 6);
        find({"v", "t", "texture_v", "texture_t"}, 7);
        if (!(have[0] && have[1] && have[2]))
            throw Error(SourceLocation{name, 0, 0}, "PLY vertex element lacks x, y or z");
        bool normals = have[3] && have[4] && have[5], uvs = have[6] && have[7];
        for (auto& s : vslot) {
            if (!normals && s >= 3 && s <= 5) s = -1;
            if (!uvs && s >= 6) s = -1;
        }
    }
    int index_prop = -1, face_index_prop = -1;
    for (size_t i = 0; i < face->props.size(); ++i) {
        const Property& p = face->props[i];
        if (p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index") && index_prop < 0)
            index_prop = int(i);
        if (!p.is_list && p.name == "face_indices" && face_index_prop < 0) face_index_prop = int(i);
    }
    if (index_prop < 0)
        throw Error(SourceLocation{name, 0, 0}, "PLY face element lacks a vertex_indices list property");
    if (vertex->count > uint64_t(std::numeric_limits<int>::max()))
        throw Error(SourceLocation{name, 0, 0}, "PLY file has too many vertices");

    // ---- Body ----
    TriangleMeshData mesh;
    const bool want_normals = std::find(vslot.begin(), vslot.end(), 3) != vslot.end();
    const bool want_uvs = std::find(vslot.begin(), vslot.end(), 6) != vslot.end();
    const bool want_face_indices = face_index_prop >= 0;
    BodyReader in(data + pos, data + size, format, line_no + 1, name);
    const double nverts = double(vertex->count);

    for (const Element& e : elements) {
        in.element = e.name.c_str();
        in.count = e.count;
        in.item = 0;
        if (e.props.empty() || e.count == 0) continue;
        // Reserve no more than the remaining data can hold.
        size_t cap = std::min<uint64_t>(e.count, in.remaining() / (in.ascii() ? 2 : 1));
        if (&e == vertex) {
            mesh.positions.reserve(cap);
            if (want_normals) mesh.normals.reserve(cap);
            if (want_uvs) mesh.uvs.reserve(cap);
            for (uint64_t i = 0; i < e.count; ++i) {
                in.item = i;
                double v[8] = {0, 0, 0, 0, 0, 0, 0, 0};
                for (size_t k = 0; k < e.props.size(); ++k) {
                    const Property& p = e.props[k];
                    if (p.is_list) {
                        in.skip(p.type, in.read_count(p.count_type));
                        continue;
                    }
                    double x = in.read(p.type);
                    if (vslot[k] >= 0) v[vslot[k]] = x;
                }
                mesh.positions.push_back(Point3f(float(v[0]), float(v[1]), float(v[2])));
                if (want_normals) mesh.normals.push_back(Normal3f(float(v[3]), float(v[4]), float(v[5])));
                if (want_uvs) mesh.uvs.push_back(Point2f(float(v[6]), float(v[7])));
            }
        } else if (&e == face) {
            mesh.indices.reserve(std::min<uint64_t>(cap * 3, uint64_t(1) << 40));
            if (want_face_indices) mesh.face_indices.reserve(cap);
            std::vector<int> poly;
            for (uint64_t i = 0; i < e.count; ++i) {
                in.item = i;
                int face_index = 0;
                poly.clear();
                for (size_t k = 0; k < e.props.size(); ++k) {
                    const Property& p = e.props[k];
                    if (int(k) == index_prop) {
                        uint64_t n = in.read_count(p.count_type);
                        if (!in.ascii() && n > in.remaining() / type_size(p.type))
                            in.fail("truncated file: the data ends early");
                        for (uint64_t j = 0; j < n; ++j) {
                            double x = in.read(p.type);
                            if (!(x >= 0 && x < nverts && x == std::floor(x)))
                                in.fail(fmt::format("vertex index {} out of range ({} vertices)", x,
                                                    vertex->count));
                            poly.push_back(int(x));
                        }
                    } else if (p.is_list) {
                        in.skip(p.type, in.read_count(p.count_type));
                    } else {
                        double x = in.read(p.type);
                        if (int(k) == face_index_prop) {
                            if (!(std::abs(x) < 2147483647.0)) in.fail("face_indices value out of range");
                            face_index = int(x);
                        }
                    }
                }
                if (poly.size() < 3) {
                    ++mesh.skipped_faces;
                    continue;
                }
                if (keep_quads && poly.size() == 4) {
                    mesh.quads.insert(mesh.quads.end(), {poly[0], poly[1], poly[3], poly[2]});
                    if (want_face_indices) mesh.quad_face_indices.push_back(face_index);
                    continue;
                }
                for (size_t j = 1; j + 1 < poly.size(); ++j) {
                    mesh.indices.push_back(poly[0]);
                    mesh.indices.push_back(poly[j]);
                    mesh.indices.push_back(poly[j + 1]);
                    if (want_face_indices) mesh.face_indices.push_back(face_index);
                }
            }
        } else {
            bool fixed = true;
            uint64_t stride = 0;
            for (auto& p : e.props) {
                fixed = fixed && !p.is_list;
                stride += type_size(p.type);
            }
            if (fixed && !in.ascii()) {
                if (e.count > in.remaining() / stride) in.fail("truncated file: the data ends early");
                in.skip(PlyType::U8, e.count * stride);
                continue;
            }
            for (uint64_t i = 0; i < e.count; ++i) {
                in.item = i;
                for (auto& p : e.props) {
                    if (p.is_list)
                        in.skip(p.type, in.read_count(p.count_type));
                    else
                        in.read(p.type);
                }
            }
        }
    }
    return mesh;
}

} // namespace illum
