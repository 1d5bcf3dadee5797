// Reading Ptex files (Burley & Lacewell 2008, "Ptex: Per-Face Texture Mapping for Production Rendering";
// the file format of ptex.us, "Ptex File Format"): one texture per face of a mesh, each face a grid of
// 2^ulog2 x 2^vlog2 texels. Little-endian:
//   header (64 bytes: magic "Ptex", version 1, mesh type, data type uint8/uint16/half/float, alpha channel,
//     channels, levels, faces, the sizes of the extended header, face-info, constant-data and level-info
//     blocks, minor version, level-data size, meta-data sizes), the extended header (its size from the
//     header; its first fields are the u and v border modes and the edge filter mode), then zlib streams of
//     the face info (per face: log2 resolutions u, v, adjacent edges (2 bits each), flags (constant 1, has
//     edits 2, neighbourhood constant 4, subface 8), four adjacent faces: 20 bytes), constant data (each
//     face's mean texel); then, not zipped, the level info (per level: data size, header size, faces: 16
//     bytes); then each level: its zipped header (a 32-bit word per face: block size in bits 0-29, encoding
//     in 30-31) and the faces' blocks in order. A block is one texel (constant), the face's texels zipped
//     channel by channel (each channel's plane of rows), the same with integer values stored as differences
//     from the previous one (diffzipped), or tiles (tile resolution, zipped tile headers, tiles as blocks of
//     their own).
// Level 0 holds every face at full resolution; level i > 0 the faces whose smaller side is at least 2^i
// (in the order of decreasing smaller side, stable; a constant face counts as 2), each reduced by 2^i
// along both sides. Meta data and edits are not read.
//
// The reductions a filter reads (PtexReader::getData): 1 x 1 is the face's constant-data texel; a reduction
// by the same power of two along both sides is the file's level when it has one; any other is made from
// the next larger one along u or v (u when the u reduction is the larger one; for equal reductions, u when
// the target's log2 u resolution is odd) by averaging texel pairs in the data type (integers rounded down,
// as Ptex's reduceu/reducev). Texels are kept in the data type's units (0-255 for uint8, 0-65535 for
// uint16), so those averages are exact; `one_value` turns them into [0, 1].
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "illum/math/vector.h"

namespace illum {

enum class PtexBorder { Clamp = 0, Black = 1, Periodic = 2 };

struct PtexFace {
    int ulog2 = 0, vlog2 = 0;
    std::uint8_t flags = 0;
    std::array<int, 4> adjacent_faces{-1, -1, -1, -1}; // bottom, right, top, left; -1: none
    std::array<int, 4> adjacent_edges{0, 0, 0, 0};     // the edge of the adjacent face that touches each
    // Every reduction 2^ru x 2^rv (0 <= ru <= ulog2, 0 <= rv <= vlog2): vres rows of ures texels, channels
    // interleaved, at `offsets[ru * (vlog2 + 1) + rv]` in `texels`.
    std::vector<float> texels;
    std::vector<std::uint32_t> offsets;

    static constexpr std::uint8_t kConstant = 1, kNeighbourhoodConstant = 4, kSubface = 8;
    int ures() const { return 1 << ulog2; }
    int vres() const { return 1 << vlog2; }
    bool constant() const { return (flags & kConstant) != 0; }
    bool neighbourhood_constant() const { return (flags & kNeighbourhoodConstant) != 0; }
    bool subface() const { return (flags & kSubface) != 0; }
    // The texels of the reduction to 2^ru x 2^rv (row-major, `channels` values each).
    const float* level(int ru, int rv) const {
        return texels.data() + offsets[std::size_t(ru * (vlog2 + 1) + rv)];
    }
};

struct PtexFile {
    int channels = 0;
    int alpha_channel = -1;
    bool triangles = false; // mesh type: triangles (pbrt-v4's meshes are quads for Ptex)
    float one_value = 1;    // the stored value of 1: 255 (uint8), 65535 (uint16), 1 (half, float)
    PtexBorder u_border = PtexBorder::Clamp, v_border = PtexBorder::Clamp;
    // The extended header's edge filter mode "tanvec": the first two channels are a tangent-space vector,
    // turned with the face when a filter reads across an edge.
    bool tangent_vectors = false;
    std::vector<PtexFace> faces;

    // Throws illum::Error naming the file and what is wrong (not Ptex, truncated, bad zlib stream).
    static PtexFile read(const std::string& path);

    // A texel of the face's full resolution in [0, 1] (for integer data).
    float texel(int face, int u, int v, int c) const {
        const PtexFace& f = faces[std::size_t(face)];
        return f.level(f.ulog2, f.vlog2)[(std::size_t(v) * std::size_t(f.ures()) + std::size_t(u)) *
                                             std::size_t(channels) +
                                         std::size_t(c)] /
               one_value;
    }
};

} // namespace illum
