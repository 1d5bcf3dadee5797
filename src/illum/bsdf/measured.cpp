#include "illum/bsdf/measured.h"

#include <algorithm>
#include <cmath>

#include "illum/math/frame.h"
#include "illum/radiometry/spectra.h"
#include "illum/radiometry/uplift.h"
#include "illum/util/error.h"

namespace illum {

namespace {

std::string shape_text(const TensorField& f) {
    std::string s = "[";
    for (std::size_t i = 0; i < f.shape.size(); ++i) s += (i ? ", " : "") + std::to_string(f.shape[i]);
    return s + "]";
}

// The spectral table reduced to linear sRGB per node: the spectrum at the file's wavelengths, piecewise
// linear and constant beyond them, weighted by D65 (unbounded_spectrum_to_rgb).
std::vector<float> spectra_to_rgb(const std::vector<float>& spectra, const std::vector<float>& wavelengths,
                                  std::size_t slices, std::size_t nodes) {
    const std::size_t nl = wavelengths.size();
    std::vector<float> rgb(slices * 3 * nodes);
    PiecewiseLinearSpectrum s;
    s.lambda.assign(wavelengths.begin(), wavelengths.end());
    s.value.resize(nl);
    // The map from a spectrum's samples to RGB is linear: find each wavelength's RGB once.
    std::vector<Color3> basis(nl);
    for (std::size_t l = 0; l < nl; ++l) {
        std::fill(s.value.begin(), s.value.end(), 0.0);
        s.value[l] = 1;
        basis[l] = unbounded_spectrum_to_rgb(s);
    }
    for (std::size_t sl = 0; sl < slices; ++sl)
        for (std::size_t n = 0; n < nodes; ++n) {
            Color3 c;
            for (std::size_t l = 0; l < nl; ++l) c += basis[l] * spectra[(sl * nl + l) * nodes + n];
            for (int k = 0; k < 3; ++k) rgb[(sl * 3 + std::size_t(k)) * nodes + n] = c[k];
        }
    return rgb;
}

} // namespace

RglBrdf RglBrdf::from_tensor(const TensorFile& file, const std::string& name) {
    auto fail = [&](const std::string& why) {
        return Error("\"" + name + "\": invalid measured BRDF: " + why);
    };
    auto field = [&](const char* f, TensorField::Type type, std::size_t rank) -> const TensorField& {
        const TensorField* t = file.find(f);
        if (!t) throw fail(std::string("no field \"") + f + "\"");
        if (t->type != type || t->shape.size() != rank)
            throw fail(std::string("field \"") + f + "\" has shape " + shape_text(*t) + " or the wrong type");
        return *t;
    };
    using T = TensorField::Type;
    const TensorField& description = field("description", T::UInt8, 1);
    const TensorField& theta_i = field("theta_i", T::Float32, 1);
    const TensorField& phi_i = field("phi_i", T::Float32, 1);
    const TensorField& ndf = field("ndf", T::Float32, 2);
    const TensorField& sigma = field("sigma", T::Float32, 2);
    const TensorField& vndf = field("vndf", T::Float32, 4);
    const TensorField& luminance = field("luminance", T::Float32, 4);
    const TensorField& jacobian = field("jacobian", T::UInt8, 1);
    const bool spectral = file.find("wavelengths") != nullptr;
    const TensorField& wavelengths = spectral ? field("wavelengths", T::Float32, 1) : theta_i;
    const TensorField& spectra = field(spectral ? "spectra" : "rgb", T::Float32, 5);
    const std::uint64_t n_phi = phi_i.shape[0], n_theta = theta_i.shape[0];
    const std::uint64_t n_lambda = spectral ? wavelengths.shape[0] : 3;
    if (vndf.shape[0] != n_phi || vndf.shape[1] != n_theta || luminance.shape[0] != n_phi ||
        luminance.shape[1] != n_theta || luminance.shape[2] != luminance.shape[3] ||
        spectra.shape[0] != n_phi || spectra.shape[1] != n_theta || spectra.shape[2] != n_lambda ||
        spectra.shape[3] != spectra.shape[4] || luminance.shape[2] != spectra.shape[3] ||
        jacobian.shape[0] != 1 || n_phi == 0 || n_theta == 0)
        throw fail("the fields' shapes do not fit together (vndf " + shape_text(vndf) + ", luminance " +
                   shape_text(luminance) + ", spectra " + shape_text(spectra) + ", " + std::to_string(n_phi) +
                   " phi_i, " + std::to_string(n_theta) + " theta_i)");

    RglBrdf b;
    b.description.assign(description.bytes.begin(), description.bytes.end());
    std::vector<float> phi = phi_i.as_floats(), theta = theta_i.as_floats();
    b.isotropic = n_phi <= 2;
    if (!b.isotropic) {
        int reduction = int(std::rint(2 * kPi / (phi.back() - phi.front())));
        if (reduction != 1)
            throw fail("its phi_i cover 1/" + std::to_string(reduction) +
                       " of the circle; symmetry-reduced files are not supported (as in pbrt-v4)");
    }
    auto grid = [&](const TensorField& t, int rank_x, int rank_y) {
        return std::pair{int(t.shape[std::size_t(rank_x)]), int(t.shape[std::size_t(rank_y)])};
    };
    try {
        auto [ndf_x, ndf_y] = grid(ndf, 1, 0);
        b.ndf = PiecewiseBilinear2D(ndf.as_floats(), ndf_x, ndf_y, {}, false);
        auto [sig_x, sig_y] = grid(sigma, 1, 0);
        b.sigma = PiecewiseBilinear2D(sigma.as_floats(), sig_x, sig_y, {}, false);
        auto [v_x, v_y] = grid(vndf, 3, 2);
        b.vndf = PiecewiseBilinear2D(vndf.as_floats(), v_x, v_y, {phi, theta}, true);
        auto [l_x, l_y] = grid(luminance, 3, 2);
        b.luminance = PiecewiseBilinear2D(luminance.as_floats(), l_x, l_y, {phi, theta}, true);
        auto [s_x, s_y] = grid(spectra, 4, 3);
        std::vector<float> values = spectra.as_floats();
        for (float v : values)
            if (!std::isfinite(v)) throw Error("the spectra hold a value that is not finite");
        if (spectral) {
            b.wavelengths = wavelengths.as_floats();
            std::vector<float> rgb = spectra_to_rgb(values, b.wavelengths, std::size_t(n_phi * n_theta),
                                                    std::size_t(s_x) * std::size_t(s_y));
            b.spectra = PiecewiseBilinear2D(std::move(values), s_x, s_y, {phi, theta, b.wavelengths}, false);
            b.rgb = PiecewiseBilinear2D(std::move(rgb), s_x, s_y, {phi, theta, {0, 1, 2}}, false);
        } else {
            b.rgb = PiecewiseBilinear2D(std::move(values), s_x, s_y, {phi, theta, {0, 1, 2}}, false);
        }
    } catch (const Error& e) {
        throw fail(e.what());
    }
    return b;
}

MeasuredBxDF::MeasuredBxDF(const RglBrdf* data, const SampledWavelengths* lambda,
                           std::shared_ptr<const RglBrdf> owner)
    : data_(data), owner_(std::move(owner)) {
    if (lambda) lambda_ = *lambda;
    spectral_ = lambda && lambda->spectral();
}

Point2f MeasuredBxDF::u_of_normal(Vector3f m, float phi_o) const {
    float phi_m = std::atan2(m.y, m.x);
    if (data_->isotropic) phi_m -= phi_o;
    float v = rgl_phi_to_u(phi_m);
    return {rgl_theta_to_u(spherical_theta(m)), v - std::floor(v)};
}

SampledSpectrum MeasuredBxDF::reflectance(Point2f s, float phi_o, float theta_o) const {
    SampledSpectrum r;
    if (spectral_ && data_->spectral()) {
        for (int i = 0; i < kSpectrumSamples; ++i) {
            float p[3] = {phi_o, theta_o, lambda_.lambda[i]};
            r[i] = std::max(0.0f, data_->spectra.evaluate(s, p));
        }
        return r;
    }
    Color3 c;
    for (int k = 0; k < 3; ++k) {
        float p[3] = {phi_o, theta_o, float(k)};
        c[k] = std::max(0.0f, data_->rgb.evaluate(s, p));
    }
    if (spectral_) return uplift_albedo(c, lambda_);
    return SampledSpectrum(c);
}

Bsdf3 MeasuredBxDF::f(Vector3f wo, Vector3f wi, TransportMode) const {
    if (!same_hemisphere(wo, wi)) return {};
    if (wo.z < 0) {
        wo = -wo;
        wi = -wi;
    }
    Vector3f m = wo + wi;
    if (length_squared(m) == 0) return {};
    m = normalize(m);
    float theta_o = spherical_theta(wo), phi_o = std::atan2(wo.y, wo.x);
    float params[2] = {phi_o, theta_o};
    Point2f u_m = u_of_normal(m, phi_o);
    Point2f s = data_->vndf.invert(u_m, params).p;
    float sigma = data_->sigma.evaluate({rgl_theta_to_u(theta_o), rgl_phi_to_u(phi_o)});
    float denom = 4 * sigma * wi.z;
    if (!(denom > 0)) return {};
    return Bsdf3(reflectance(s, phi_o, theta_o) * (data_->ndf.evaluate(u_m) / denom));
}

std::optional<BSDFSample> MeasuredBxDF::sample(Vector3f wo, float, Point2f u, TransportMode mode) const {
    bool flip = wo.z < 0;
    Vector3f w = flip ? -wo : wo;
    float theta_o = spherical_theta(w), phi_o = std::atan2(w.y, w.x);
    float params[2] = {phi_o, theta_o};
    Point2f s = data_->luminance.sample(u, params).p;
    Point2f u_m = data_->vndf.sample(s, params).p;
    float phi_m = rgl_u_to_phi(u_m.y) + (data_->isotropic ? phi_o : 0), theta_m = rgl_u_to_theta(u_m.x);
    Vector3f m = spherical_direction(std::sin(theta_m), std::cos(theta_m), phi_m);
    Vector3f wi = reflect(w, m);
    if (!(dot(w, m) > 0) || wi.z <= 0) return std::nullopt;
    if (flip) wi = -wi;
    // f and the density as f() and pdf() give them at wi (through the inverse warp; they equal the
    // values at s, p_lum(s) p_vndf(u_m) / (4 (wo·m) 2π² u_θ sin θm), to float rounding), so that MIS
    // weights computed either way agree.
    SolidAnglePdf pdf_wi = pdf(wo, wi, mode);
    if (!(pdf_wi.value > 0)) return std::nullopt;
    return BSDFSample{wi, f(wo, wi, mode), pdf_wi, kGlossyReflection};
}

SolidAnglePdf MeasuredBxDF::pdf(Vector3f wo, Vector3f wi, TransportMode) const {
    if (!same_hemisphere(wo, wi)) return SolidAnglePdf(0);
    if (wo.z < 0) {
        wo = -wo;
        wi = -wi;
    }
    Vector3f m = wo + wi;
    if (length_squared(m) == 0) return SolidAnglePdf(0);
    m = normalize(m);
    float theta_o = spherical_theta(wo), phi_o = std::atan2(wo.y, wo.x);
    float params[2] = {phi_o, theta_o};
    Point2f u_m = u_of_normal(m, phi_o);
    PiecewiseBilinear2D::Sample v = data_->vndf.invert(u_m, params);
    float lum = data_->luminance.evaluate(v.p, params);
    float sin_m = std::sqrt(m.x * m.x + m.y * m.y);
    float jacobian = 4 * dot(wo, m) * std::max(2 * kPi * kPi * u_m.x * sin_m, 1e-6f);
    return SolidAnglePdf(v.pdf * lum / jacobian);
}

} // namespace illum
