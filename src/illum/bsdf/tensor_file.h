// The "tensor file" container of the RGL material database (Dupuy & Jakob 2018; the format Mitsuba and
// pbrt-v4 read `.bsdf` files in). Little-endian:
//   "tensor_file\0" (12 bytes), version 1, 0 (two uint8), field count (uint32), then per field:
//   name length (uint16), name, rank (uint16), type (uint8: 1..8 the integer types uint8, int8, uint16,
//   int16, uint32, int32, uint64, int64; 9, 10, 11 float16, float32, float64), data offset from the file's
//   start (uint64), the size along each dimension (rank x uint64; the last dimension varies fastest);
//   the fields' data lie at their offsets.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace illum {

struct TensorField {
    enum class Type : std::uint8_t {
        UInt8 = 1,
        Int8,
        UInt16,
        Int16,
        UInt32,
        Int32,
        UInt64,
        Int64,
        Float16,
        Float32,
        Float64
    };
    Type type = Type::Float32;
    std::vector<std::uint64_t> shape;
    std::vector<unsigned char> bytes; // the raw data, element size x product of shape

    std::uint64_t count() const;
    static std::size_t element_size(Type t);
    static TensorField floats(std::vector<std::uint64_t> shape, const std::vector<float>& values);
    static TensorField uint8s(std::vector<std::uint64_t> shape, const std::vector<std::uint8_t>& values);
    std::vector<float> as_floats() const; // Float32 fields only (the caller checks the type)
};

struct TensorFile {
    std::map<std::string, TensorField> fields;

    // Throws illum::Error naming the file and what is wrong (missing, not a tensor file, truncated).
    static TensorFile read(const std::string& path);
    // Written atomically (a temporary file renamed over the path).
    void write(const std::string& path) const;
    const TensorField* find(const std::string& name) const {
        auto it = fields.find(name);
        return it == fields.end() ? nullptr : &it->second;
    }
};

} // namespace illum
