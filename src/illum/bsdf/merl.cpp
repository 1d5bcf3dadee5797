#include "illum/bsdf/merl.h"

#include "illum/bsdf/glossy_diffuse_sampling.h"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>

#include "illum/image/file_bytes.h"
#include "illum/math/warp.h"
#include "illum/util/error.h"

namespace illum {

namespace {

constexpr double kScale[3] = {1.0 / 1500, 1.15 / 1500, 1.66 / 1500};

Vector3f rotate_z(Vector3f v, float a) {
    float c = std::cos(a), s = std::sin(a);
    return {v.x * c - v.y * s, v.x * s + v.y * c, v.z};
}
Vector3f rotate_y(Vector3f v, float a) {
    float c = std::cos(a), s = std::sin(a);
    return {v.x * c + v.z * s, v.y, -v.x * s + v.z * c};
}

} // namespace

int MerlTable::index(Vector3f wo, Vector3f wi) {
    if (wo.z < 0) {
        wo = -wo;
        wi = -wi;
    }
    if (wo.z <= 0 || wi.z <= 0) return -1;
    Vector3f h = wo + wi;
    if (length_squared(h) == 0) return -1;
    h = normalize(h);
    float theta_h = safe_acos(h.z), phi_h = std::atan2(h.y, h.x);
    Vector3f d = rotate_y(rotate_z(wi, -phi_h), -theta_h);
    float theta_d = safe_acos(d.z), phi_d = std::atan2(d.y, d.x);
    // Reciprocity folds φd into [0, π).
    if (phi_d < 0) phi_d += kPi;
    if (phi_d >= kPi) phi_d -= kPi;
    int ih = theta_h <= 0 ? 0 : int(std::sqrt(theta_h / kPiOver2) * kThetaH);
    int id = int(theta_d / kPiOver2 * kThetaD);
    int ip = int(phi_d / kPi * kPhiD);
    ih = std::clamp(ih, 0, kThetaH - 1);
    id = std::clamp(id, 0, kThetaD - 1);
    ip = std::clamp(ip, 0, kPhiD - 1);
    return ip + kPhiD * (id + kThetaD * ih);
}

Color3 MerlTable::lookup(Vector3f wo, Vector3f wi) const {
    int i = index(wo, wi);
    if (i < 0) return {};
    return {float(std::max(0.0, data[i] * kScale[0])), float(std::max(0.0, data[i + kSize] * kScale[1])),
            float(std::max(0.0, data[i + 2 * kSize] * kScale[2]))};
}

MerlTable MerlTable::read(const std::string& path) {
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        // The standard does not promise errno from a stream, but the C library under it sets it; say
        // the reason when there is one.
        int err = errno;
        throw Error("cannot open MERL file '" + path + "'" +
                    (err ? std::string(": ") + std::strerror(err) : ""));
    }
    std::int32_t dims[3];
    if (!in.read(reinterpret_cast<char*>(dims), sizeof dims))
        throw Error("MERL file '" + path + "' is truncated: it ends inside the 12-byte header");
    if (dims[0] != kThetaH || dims[1] != kThetaD || dims[2] != kPhiD)
        throw Error("MERL file '" + path + "' has wrong dimensions " + std::to_string(dims[0]) + "x" +
                    std::to_string(dims[1]) + "x" + std::to_string(dims[2]) + " (expected 90x90x180)");
    MerlTable t;
    t.data.resize(3 * std::size_t(kSize));
    in.read(reinterpret_cast<char*>(t.data.data()), std::streamsize(t.data.size() * sizeof(double)));
    auto got = in.gcount();
    if (std::size_t(got) != t.data.size() * sizeof(double))
        throw Error("MERL file '" + path + "' is truncated: expected " +
                    std::to_string(t.data.size() * sizeof(double)) +
                    " bytes of data after the header, found " + std::to_string(got));
    return t;
}

void MerlTable::write(const std::string& path) const {
    std::string bytes(sizeof(std::int32_t) * 3 + data.size() * sizeof(double), '\0');
    std::int32_t dims[3] = {kThetaH, kThetaD, kPhiD};
    std::memcpy(bytes.data(), dims, sizeof dims);
    std::memcpy(bytes.data() + sizeof dims, data.data(), data.size() * sizeof(double));
    write_file_atomically(path, bytes); // throws illum::Error naming the file
}

bool MerlTable::bin_directions(int ih, int id, int ip, Vector3f* wo, Vector3f* wi) {
    double u = (ih + 0.5) / kThetaH;
    float theta_h = float(u * u * (kPiD / 2));
    Vector3f h(std::sin(theta_h), 0, std::cos(theta_h));
    float theta_d = float((id + 0.5) / kThetaD * (kPiD / 2));
    float phi_d = float((ip + 0.5) / kPhiD * kPiD);
    Vector3f d = spherical_direction(std::sin(theta_d), std::cos(theta_d), phi_d);
    *wi = rotate_y(d, theta_h);
    *wo = reflect(*wi, h);
    if (wi->z <= 0 || wo->z <= 0) return false;
    *wo = normalize(*wo);
    *wi = normalize(*wi);
    return true;
}

double MerlTable::value(int ih, int id, int ip, int channel) const {
    std::size_t i = std::size_t(ip + kPhiD * (id + kThetaD * ih)) + std::size_t(channel) * std::size_t(kSize);
    return data[i] * kScale[channel];
}

MerlTable MerlTable::from_bxdf(const BxDF& bxdf) {
    MerlTable t;
    t.data.assign(3 * std::size_t(kSize), -1.0);
    for (int ih = 0; ih < kThetaH; ++ih)
        for (int id = 0; id < kThetaD; ++id)
            for (int ip = 0; ip < kPhiD; ++ip) {
                Vector3f wo, wi;
                if (!bin_directions(ih, id, ip, &wo, &wi)) continue;
                Color3 f = bxdf.f(wo, wi, TransportMode::Radiance).rgb();
                int i = ip + kPhiD * (id + kThetaD * ih);
                for (int c = 0; c < 3; ++c) t.data[i + c * std::size_t(kSize)] = f[c] / kScale[c];
            }
    return t;
}

MerlBxDF::MerlBxDF(std::shared_ptr<const MerlTable> table) : table_(std::move(table)) {
    // Fit a GGX lobe to the luminance along θd ≈ 0.5°, φd ≈ 0.5° (near the specular configuration):
    // subtract the minimum (the diffuse floor), normalise by the peak and pick the α whose D(θh)/D(0)
    // matches best in least squares.
    const auto& d = table_->data;
    double spec[MerlTable::kThetaH];
    double floor = 1e30;
    for (int ih = 0; ih < MerlTable::kThetaH; ++ih) {
        std::size_t i = std::size_t(MerlTable::kPhiD) * MerlTable::kThetaD * ih;
        double lum = 0;
        for (int c = 0; c < 3; ++c)
            lum += std::max(0.0, d[i + c * std::size_t(MerlTable::kSize)] * kScale[c]) / 3;
        spec[ih] = lum;
        floor = std::min(floor, lum);
    }
    double peak = spec[0] - floor;
    float best_alpha = 0.3f;
    if (peak > 1e-6) {
        double best = 1e300;
        for (int k = 0; k <= 80; ++k) {
            double alpha = 0.005 * std::pow(200.0, k / 80.0); // 0.005 .. 1
            double err = 0;
            for (int ih = 0; ih < MerlTable::kThetaH; ++ih) {
                double u = (ih + 0.5) / MerlTable::kThetaH, th = u * u * (kPiD / 2);
                double t2 = sqr(std::tan(th)), c4 = sqr(sqr(std::cos(th)));
                double ratio = 1 / (c4 * sqr(1 + t2 / (alpha * alpha)));
                err += sqr((spec[ih] - floor) / peak - ratio);
            }
            if (err < best) {
                best = err;
                best_alpha = float(alpha);
            }
        }
        // Share of the lobe: its peak against the diffuse floor's albedo π floor, kept in [0.1, 0.9].
        double diffuse = kPiD * floor, lobe = std::min(1.0, peak * kPiD * best_alpha * best_alpha);
        p_lobe_ = float(std::clamp(lobe / (lobe + diffuse + 1e-9), 0.1, 0.9));
    } else {
        p_lobe_ = 0;
    }
    lobe_ = MicrofacetDistribution(MicrofacetType::GGX, best_alpha, best_alpha);
}

Bsdf3 MerlBxDF::f(Vector3f wo, Vector3f wi, TransportMode) const {
    if (!same_hemisphere(wo, wi)) return {};
    return Bsdf3(SampledSpectrum(table_->lookup(wo, wi)));
}

std::optional<BSDFSample> MerlBxDF::sample(Vector3f wo, float uc, Point2f u, TransportMode mode) const {
    return sample_glossy_diffuse(*this, lobe_, p_lobe_, wo, uc, u, mode);
}

SolidAnglePdf MerlBxDF::pdf(Vector3f wo, Vector3f wi, TransportMode) const {
    return SolidAnglePdf(glossy_diffuse_pdf(lobe_, p_lobe_, wo, wi));
}

} // namespace illum
