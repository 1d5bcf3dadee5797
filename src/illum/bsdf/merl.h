// Measured isotropic BRDFs in the MERL format (Matusik, Pfister, Brand, McMillan 2003, "A Data-Driven
// Reflectance Model"). A `.binary` file holds three int32 dimensions (90, 90, 180) and then
// 3 x 90 x 90 x 180 doubles: the red, green and blue tables one after the other, indexed by
// (θh, θd, φd) in the half/difference parameterisation of Rusinkiewicz 1998. θh uses the square-root
// mapping index = 90 sqrt(θh / (π/2)), θd and φd (folded into [0, π) by reciprocity) are uniform. Stored
// values are scaled by 1/1500, 1.15/1500 and 1.66/1500 for R, G, B; negative entries mark missing data
// and are read as 0.
//
// Evaluation is a nearest-bin table lookup (as MERL's reference code). Sampling uses a fitted lobe: a
// mixture of cosine-weighted directions and a GGX lobe whose α is fitted to the table's specular peak at
// load time; pdf() is the density of that mixture, so estimates are unbiased.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "illum/bsdf/bxdf.h"
#include "illum/bsdf/microfacet.h"

namespace illum {

struct MerlTable {
    static constexpr int kThetaH = 90, kThetaD = 90, kPhiD = 180;
    static constexpr int kSize = kThetaH * kThetaD * kPhiD;
    std::vector<double> data; // 3 * kSize, as in the file (unscaled)

    // Reads a `.binary` file; throws illum::Error naming the file and the problem (missing, truncated,
    // wrong dimensions).
    static MerlTable read(const std::string& path);
    // Writes the table in the MERL format (atomically: a temporary file renamed over the path).
    void write(const std::string& path) const;
    // Tabulates a BxDF's reflection at the bin centres (the inverse of the lookup), for tests.
    static MerlTable from_bxdf(const BxDF& bxdf);

    // The directions (wo, wi) at the centre of bin (θh index, θd index, φd index), as from_bxdf tabulates
    // them; false when one is at or below the horizon.
    static bool bin_directions(int ih, int id, int ip, Vector3f* wo, Vector3f* wi);
    // The (scaled) value stored for a bin, per channel; negative for missing data.
    double value(int ih, int id, int ip, int channel) const;

    // The (scaled) BRDF value for a pair of directions on +z.
    Color3 lookup(Vector3f wo, Vector3f wi) const;
    static int index(Vector3f wo, Vector3f wi); // -1 when below the horizon
};

class MerlBxDF final : public BxDF {
public:
    explicit MerlBxDF(std::shared_ptr<const MerlTable> table);
    static MerlBxDF load(const std::string& path) {
        return MerlBxDF(std::make_shared<MerlTable>(MerlTable::read(path)));
    }

    std::uint8_t flags() const override { return kGlossyReflection | kDiffuseReflection; }
    Bsdf3 f(Vector3f wo, Vector3f wi, TransportMode mode) const override;
    std::optional<BSDFSample> sample(Vector3f wo, float uc, Point2f u, TransportMode mode) const override;
    SolidAnglePdf pdf(Vector3f wo, Vector3f wi, TransportMode mode) const override;

    float fitted_alpha() const { return lobe_.alpha_x(); }
    float lobe_probability() const { return p_lobe_; }

private:
    std::shared_ptr<const MerlTable> table_;
    MicrofacetDistribution lobe_;
    float p_lobe_ = 0.5f;
};

} // namespace illum
