// Reading Ptex files (Burley & Lacewell 2008, "Ptex: Per-Face Texture Mapping for Production Rendering";
// the file format of ptex.us, "Ptex File Format"): one texture per face of a mesh, each face a grid of
// 2^ulog2 x 2^vlog2 texels. Little-endian:
//   header (64 bytes: magic "Ptex", version 1, mesh type, data type uint8/uint16/half/float, alpha channel,
//     channels, levels, faces, the sizes of the extended header, face-info, constant-data and level-info
//     blocks, minor version, level-data size, meta-data sizes), the extended header (its size from the
//     header), then zlib streams: face info (per face: log2 resolutions u, v, adjacent edges, flags,
//     four adjacent faces: 20 bytes), constant data (each face's mean texel), level info (per level: data
//     size, header size, faces: 16 bytes); then each level: its zipped header (a 32-bit word per face:
//     block size in bits 0-29, encoding in 30-31) and the faces' blocks in order. A block is one texel
//     (constant), the face's texels zipped channel by channel (each channel's plane of rows), the same with
//     integer values stored as differences from the previous one (diffzipped), or tiles (tile resolution,
//     zipped tile headers, tiles as blocks of their own).
// Only level 0 (full resolution) is read: illum evaluates without a filter footprint. Meta data, edits and
// the reductions of levels 1+ are skipped.
#pragma once

#include <string>
#include <vector>

#include "illum/math/vector.h"

namespace illum {

struct PtexFace {
    int ures = 1, vres = 1;    // texels along u and v
    std::vector<float> texels; // vres rows of ures texels, `channels` values each, in [0, 1] for integers
};

struct PtexFile {
    int channels = 0;
    int alpha_channel = -1;
    bool triangles = false; // mesh type: triangles (pbrt-v4 meshes are quads for Ptex)
    std::vector<PtexFace> faces;

    // Throws illum::Error naming the file and what is wrong (not Ptex, truncated, bad zlib stream).
    static PtexFile read(const std::string& path);

    // The face's texels bilinearly interpolated at (u, v) in [0, 1]² (texel centres at (i + 1/2) / res,
    // clamped to the face: no filtering across its edges). `out` receives `channels` values. A face index
    // outside the file reads as 0.
    void lookup(int face, Point2f uv, float* out) const;
};

} // namespace illum
