#include "illum/bsdf/tensor_file.h"

#include <cstring>

#include "illum/image/file_bytes.h"
#include "illum/util/error.h"

namespace illum {

namespace {

constexpr char kMagic[12] = "tensor_file"; // with its terminating 0: 12 bytes

template <class T>
void put(std::string& out, T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    out.append(b, sizeof(T));
}

} // namespace

std::size_t TensorField::element_size(Type t) {
    switch (t) {
    case Type::UInt8:
    case Type::Int8:
        return 1;
    case Type::UInt16:
    case Type::Int16:
    case Type::Float16:
        return 2;
    case Type::UInt32:
    case Type::Int32:
    case Type::Float32:
        return 4;
    case Type::UInt64:
    case Type::Int64:
    case Type::Float64:
        return 8;
    }
    return 0;
}

std::uint64_t TensorField::count() const {
    std::uint64_t n = 1;
    for (std::uint64_t s : shape) n *= s;
    return n;
}

TensorField TensorField::floats(std::vector<std::uint64_t> shape, const std::vector<float>& values) {
    TensorField f;
    f.type = Type::Float32;
    f.shape = std::move(shape);
    if (f.count() != values.size()) throw Error("tensor field: shape and value count differ");
    f.bytes.resize(values.size() * 4);
    if (!values.empty()) std::memcpy(f.bytes.data(), values.data(), f.bytes.size());
    return f;
}

TensorField TensorField::uint8s(std::vector<std::uint64_t> shape, const std::vector<std::uint8_t>& values) {
    TensorField f;
    f.type = Type::UInt8;
    f.shape = std::move(shape);
    if (f.count() != values.size()) throw Error("tensor field: shape and value count differ");
    f.bytes.assign(values.begin(), values.end());
    return f;
}

std::vector<float> TensorField::as_floats() const {
    std::vector<float> v(bytes.size() / 4);
    if (!v.empty()) std::memcpy(v.data(), bytes.data(), v.size() * 4);
    return v;
}

TensorFile TensorFile::read(const std::string& path) {
    std::vector<unsigned char> b = read_file_bytes(path);
    std::size_t at = 0;
    auto fail = [&](const std::string& why) -> Error {
        return Error("\"" + path + "\" is not a valid tensor file: " + why);
    };
    auto get = [&](void* out, std::size_t n) {
        if (b.size() - at < n) throw fail("truncated header");
        std::memcpy(out, b.data() + at, n);
        at += n;
    };
    char magic[12];
    get(magic, 12);
    if (std::memcmp(magic, kMagic, 12) != 0) throw fail("it does not start with \"tensor_file\"");
    std::uint8_t version[2];
    get(version, 2);
    if (version[0] != 1 || version[1] != 0)
        throw fail("version " + std::to_string(version[0]) + "." + std::to_string(version[1]) +
                   " (1.0 expected)");
    std::uint32_t n_fields = 0;
    get(&n_fields, 4);
    TensorFile t;
    for (std::uint32_t i = 0; i < n_fields; ++i) {
        std::uint16_t name_length = 0, rank = 0;
        get(&name_length, 2);
        std::string name(name_length, '\0');
        get(name.data(), name_length);
        get(&rank, 2);
        std::uint8_t type = 0;
        get(&type, 1);
        std::uint64_t offset = 0;
        get(&offset, 8);
        if (type < 1 || type > 11)
            throw fail("field \"" + name + "\" has unknown type " + std::to_string(type));
        TensorField f;
        f.type = TensorField::Type(type);
        f.shape.resize(rank);
        std::uint64_t bytes = TensorField::element_size(f.type);
        for (std::uint16_t d = 0; d < rank; ++d) {
            get(&f.shape[d], 8);
            if (f.shape[d] != 0 && bytes > (std::uint64_t(1) << 40) / f.shape[d])
                throw fail("field \"" + name + "\" is too large");
            bytes *= f.shape[d];
        }
        if (offset > b.size() || b.size() - offset < bytes)
            throw fail("field \"" + name + "\" lies beyond the end of the file (truncated?)");
        f.bytes.assign(b.begin() + std::ptrdiff_t(offset), b.begin() + std::ptrdiff_t(offset + bytes));
        t.fields[name] = std::move(f);
    }
    return t;
}

void TensorFile::write(const std::string& path) const {
    std::size_t header = 12 + 2 + 4;
    for (const auto& [name, f] : fields) header += 2 + name.size() + 2 + 1 + 8 + 8 * f.shape.size();
    auto align = [](std::size_t x) { return (x + 7) & ~std::size_t(7); };
    std::string out(kMagic, 12);
    put(out, std::uint8_t(1));
    put(out, std::uint8_t(0));
    put(out, std::uint32_t(fields.size()));
    std::size_t offset = align(header);
    for (const auto& [name, f] : fields) {
        put(out, std::uint16_t(name.size()));
        out += name;
        put(out, std::uint16_t(f.shape.size()));
        put(out, std::uint8_t(f.type));
        put(out, std::uint64_t(offset));
        for (std::uint64_t s : f.shape) put(out, s);
        offset = align(offset + f.bytes.size());
    }
    for (const auto& [name, f] : fields) {
        out.resize(align(out.size()), '\0');
        out.append(reinterpret_cast<const char*>(f.bytes.data()), f.bytes.size());
    }
    write_file_atomically(path, out);
}

} // namespace illum
