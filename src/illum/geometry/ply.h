// PLY mesh reader (ASCII, binary_little_endian, binary_big_endian; gzip-compressed files through zlib),
// for pbrt's "plymesh" shape. The file is read whole into memory and decoded in one pass.
//
// Vertex properties: x y z (required), nx ny nz, and texture coordinates as u v, s t, texture_u
// texture_v or texture_s texture_t; any order and any scalar type (char/uchar/short/ushort/int/uint/
// float/double and the int8/uint8/int16/uint16/int32/uint32/float32/float64 aliases). Faces: a list
// property vertex_indices (or vertex_index) with any count and index types; quads become two triangles
// (0 1 2, 0 2 3), or bilinear patches when asked (keep_quads), and larger polygons a fan; an optional
// per-face "face_indices" integer is kept for each triangle or patch made from the face. Unknown elements and
// properties are skipped. Problems (missing file, bad header, unsupported format, truncated data, an index
// out of range) throw illum::Error naming the file and, where known, the element, item and (ASCII) line.
#pragma once

#include <string>
#include <vector>

#include "illum/math/vector.h"

namespace illum {

struct TriangleMeshData {
    std::vector<Point3f> positions;
    std::vector<Normal3f> normals; // empty, or one per position
    std::vector<Point2f> uvs;      // empty, or one per position
    std::vector<int> indices;      // three per triangle, each in [0, positions.size())
    std::vector<int> face_indices; // empty, or one per triangle
    // With keep_quads: four-vertex faces as bilinear patches, four indices each in pbrt-v4's order
    // (v0 v1 v3 v2: p00 p10 p01 p11), instead of two triangles, and their face_indices (empty, or one per
    // patch).
    std::vector<int> quads;
    std::vector<int> quad_face_indices;
    size_t skipped_faces = 0; // faces with fewer than 3 vertices, left out
};

TriangleMeshData read_ply(const std::string& path, bool keep_quads = false);

// Decodes PLY data already in memory; `name` is used in errors.
TriangleMeshData parse_ply(const char* data, size_t size, const std::string& name, bool keep_quads = false);

} // namespace illum
