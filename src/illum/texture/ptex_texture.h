// pbrt-v4's "ptex" textures (FloatPtexTexture, SpectrumPtexTexture): the Ptex file's face at the hit's face
// index (a mesh's "faceIndices", a PLY file's "face_indices"; 0 otherwise) filtered at the hit's uv over its
// footprint (texture/ptex_filter.h), no texture mapping. As pbrt-v4: a non-linear `encoding` (default
// "gamma 2.2") quantises the filtered value to 8 bits, q = clamp(⌊255 v + 1/2⌋, 0, 255), and decodes q
// ((q/255)^γ, or sRGB); then `scale` multiplies. 1- or 3-channel files; a float texture averages 3
// channels, a spectrum texture takes 1 channel as grey.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

#include "illum/image/tonemap.h"
#include "illum/texture/ptex_file.h"
#include "illum/texture/ptex_filter.h"
#include "illum/texture/texture.h"

namespace illum {

class PtexLookup {
public:
    // gamma: 0 for sRGB, 1 for linear (no quantisation), else the exponent of "gamma γ".
    PtexLookup(std::shared_ptr<const PtexFile> file, float gamma, float scale)
        : file_(std::move(file)), linear_(gamma == 1), scale_(scale) {
        for (int q = 0; q < 256; ++q)
            decode_[std::size_t(q)] =
                gamma == 0 ? srgb8_decode(static_cast<unsigned char>(q)) : std::pow(float(q) / 255, gamma);
    }
    // The channels' values (one or three), decoded and scaled.
    Color3 rgb(const TextureEvalContext& hit) const {
        float raw[4] = {0, 0, 0, 0};
        ptex_filter(*file_, hit.face_index, hit.uv.x, hit.uv.y, hit.dudx, hit.dvdx, hit.dudy, hit.dvdy, raw);
        const int n = file_->channels == 1 ? 1 : 3;
        for (int c = 0; c < n; ++c) {
            if (!linear_) {
                const float q = raw[c] * 255 + 0.5f; // a NaN reads as 0
                raw[c] = decode_[q >= 255 ? 255 : q > 0 ? std::size_t(q) : 0];
            }
            raw[c] *= scale_;
        }
        return n == 1 ? Color3(raw[0]) : Color3(raw[0], raw[1], raw[2]);
    }

private:
    std::shared_ptr<const PtexFile> file_;
    bool linear_;
    float scale_;
    std::array<float, 256> decode_{};
};

class PtexColorTexture final : public ColorTexture {
public:
    explicit PtexColorTexture(PtexLookup l) : l_(std::move(l)) {}
    Color3 evaluate(const TextureEvalContext& hit) const override { return l_.rgb(hit); }

private:
    PtexLookup l_;
};

class PtexFloatTexture final : public FloatTexture {
public:
    explicit PtexFloatTexture(PtexLookup l) : l_(std::move(l)) {}
    float evaluate(const TextureEvalContext& hit) const override { return l_.rgb(hit).average(); }

private:
    PtexLookup l_;
};

} // namespace illum
