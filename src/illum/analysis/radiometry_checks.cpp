#include "illum/analysis/radiometry_checks.h"

#include <cmath>

#include <fmt/format.h>

#include "illum/analysis/check_render.h"
#include "illum/bsdf/lambert.h"
#include "illum/bsdf/material.h"
#include "illum/geometry/disk.h"
#include "illum/geometry/sphere.h"
#include "illum/light/diffuse_area_light.h"

namespace illum {

namespace {

// The material of the surface under test: the given Lambertian BSDF in the surface's shading frame.
class SubjectMaterial final : public Material {
public:
    SubjectMaterial(LambertMaker make, Color3 reflectance)
        : make_(std::move(make)), reflectance_(reflectance) {
        may_be_specular = false;
    }
    BSDF bsdf(const SurfaceHit& hit, SampledWavelengths&, ScratchArena& arena) const override {
        return placed(make_(SampledSpectrum(reflectance_), arena), hit);
    }
    Color3 albedo(const SurfaceHit&) const override { return reflectance_; }

private:
    LambertMaker make_;
    Color3 reflectance_;
};

// A disk light of radiance L and radius r at height h above the origin, facing down (black material).
std::string disk_light(double r, double h, double L) {
    return fmt::format(R"(
AttributeBegin
  Material "diffuse" "rgb reflectance" [0 0 0]
  AreaLightSource "diffuse" "rgb L" [{0} {0} {0}]
  Translate 0 0 {1}
  ReverseOrientation
  Shape "disk" "float radius" [{2}]
AttributeEnd
)",
                       L, h, r);
}

// E at the receiver's origin (π times its pixels' mean) with its standard error.
Estimate irradiance(const std::string& world, const std::string& integrator, int spp,
                    const VerifyOptions& o) {
    auto scene = scene_from_text(irradiance_receiver(world));
    Estimate e = pixel_estimate(render_check(*scene, integrator, 1, spp, o), 1);
    return {kPiD * e.mean, kPiD * e.standard_error, e.dropped};
}

} // namespace

const BxDF* renderer_lambert(SampledSpectrum reflectance, ScratchArena& arena) {
    return arena.make<LambertBxDF>(reflectance);
}

std::vector<VerifyCheck> check_disk_irradiance(const VerifyOptions& o) {
    std::vector<VerifyCheck> out;
    const double L = 2;
    for (auto [r, h] : {std::pair{1.0, 1.0}, std::pair{0.5, 2.0}, std::pair{2.0, 0.5}})
        for (const char* integrator : {"path", "direct"}) {
            double expected = kPiD * L * r * r / (r * r + h * h);
            out.push_back(
                judge("radiometry",
                      fmt::format("disk irradiance on axis, r = {} h = {} L = 2 ({})", r, h, integrator),
                      "E = π L sin²α = π L r²/(r² + h²)", expected,
                      irradiance(disk_light(r, h, L), integrator, 256, o), 1e-4, o));
        }
    return out;
}

std::vector<VerifyCheck> check_rule_of_five(const VerifyOptions& o) {
    std::vector<VerifyCheck> out;
    const double L = 1, r = 0.1, D = 2 * r;
    for (double h : {5 * D, 2.5 * D}) {
        double I = L * kPiD * r * r; // the disk's intensity along its axis
        Estimate disk = irradiance(disk_light(r, h, L), "direct", 256, o);
        Estimate point = irradiance(
            fmt::format(R"(LightSource "point" "point3 from" [0 0 {0}] "rgb I" [{1} {1} {1}])", h, I),
            "direct", 1, o);
        Estimate ratio{disk.mean / point.mean, disk.standard_error / point.mean,
                       disk.dropped + point.dropped};
        std::string detail = fmt::format("E_point = {:.6g}, E_disk = {:.6g} ± {:.2g}", point.mean, disk.mean,
                                         disk.standard_error);
        // The ratio does not see the receiver's BSDF; the point source's irradiance does.
        out.push_back(judge("radiometry",
                            fmt::format("inverse-square law: a point source of I = {:.4g} at h = {:g}", I, h),
                            "E = I/h² (on the axis)", I / (h * h), point, 1e-4, o));
        out.push_back(
            judge("radiometry", fmt::format("rule of five: E_disk/E_point, D = {} at h = {} D", D, h / D),
                  "E_disk/E_point = h²/(r² + h²)", h * h / (r * r + h * h), ratio, 1e-4, o, detail));
        if (h >= 5 * D)
            out.push_back(judge("radiometry",
                                "rule of five: a disk at 5 diameters is a point source within 1%",
                                "h >= 5 D  =>  |E_disk/E_point - 1| = (r/h)²/(1 + (r/h)²) <= 1%", 1.0, ratio,
                                0.01, o, detail));
    }
    return out;
}

VerifyCheck check_closed_furnace(double rho, double le, const VerifyOptions& o, const LambertMaker& lambert) {
    auto scene = scene_from_text(R"(
LookAt 0.1 0.2 0  1 0.3 0.2  0 0 1
Camera "perspective" "float fov" [60]
Film "rgb" "integer xresolution" [24] "integer yresolution" [24]
WorldBegin
)");
    // The sphere, its emission and its material, added to the built scene so that its BSDF is the one
    // under test: a unit sphere with its normals inwards, emitting Le inwards (one-sided).
    scene->materials.push_back(std::make_unique<SubjectMaterial>(lambert, Color3(float(rho))));
    auto sphere = std::make_unique<SphereShape>(Point3f(0, 0, 0), 1.0f, true);
    auto light = std::make_unique<DiffuseAreaLight>(sphere.get(), Emission(Color3(float(le))), false);
    scene->accelerator.add_shape(std::move(sphere), scene->materials.back().get(), light.get());
    scene->lights.push_back(std::move(light));
    scene->finalize();
    RenderResult r = render_check(*scene, "path", 1000, 256, o);
    return judge("radiometry", fmt::format("closed furnace, ρ = {} Le = {}, unbounded depth (path)", rho, le),
                 "L = Le/(1 - ρ)", le / (1 - rho), pixel_estimate(r, 1), 1e-4, o);
}

std::vector<VerifyCheck> check_radiance_invariance(const VerifyOptions& o) {
    std::vector<VerifyCheck> out;
    const Color3 L(0.25f, 1.5f, 4.0f);
    for (double d : {0.5, 5.0, 500.0}) {
        auto scene = scene_from_text(fmt::format(R"(
LookAt 0 0 {0}  0 0 0  0 1 0
Camera "perspective" "float fov" [{1}]
Film "rgb" "integer xresolution" [8] "integer yresolution" [8]
WorldBegin
Material "diffuse" "rgb reflectance" [0 0 0]
AreaLightSource "diffuse" "rgb L" [0.25 1.5 4]
Shape "trianglemesh" "point3 P" [-1 -1 0 1 -1 0 1 1 0 -1 1 0] "integer indices" [0 1 2 0 2 3]
)",
                                                 d, 2 * std::atan(0.8 / d) * 180 / kPiD));
        RenderResult r = render_check(*scene, "path", 5, 4, o);
        const Image& img = r.image;
        // The pixel farthest from L (every pixel sees the emitter only: no sampling is involved).
        double worst = L.b;
        for (std::size_t i = 0; i < img.pixel_count(); ++i)
            if (std::abs(img.data()[i].b - L.b) > std::abs(worst - L.b)) worst = img.data()[i].b;
        out.push_back(judge("radiometry",
                            fmt::format("radiance invariance: an emitter seen from {} units", d),
                            "L_seen = L_emitted (blue channel, the pixel farthest from it)", L.b,
                            {worst, 0.0, r.nonfinite_samples}, 1e-6, o));
    }
    return out;
}

VerifyCheck check_lambertian_plane(double rho, const VerifyOptions& o, const LambertMaker& lambert) {
    const Color3 L(1, 0.5f, 0.25f);
    auto scene = scene_from_text(R"(
LookAt 0 -3 2  0 0 0  0 0 1
Camera "perspective" "float fov" [10]
Film "rgb" "integer xresolution" [24] "integer yresolution" [24]
WorldBegin
LightSource "infinite" "rgb L" [1 0.5 0.25]
)");
    scene->materials.push_back(std::make_unique<SubjectMaterial>(lambert, Color3(float(rho))));
    scene->accelerator.add_shape(std::make_unique<DiskShape>(Transform(), 0.0f, 100.0f, 0.0f, false),
                                 scene->materials.back().get(), nullptr);
    scene->finalize();
    RenderResult img = render_check(*scene, "path", 5, 256, o);
    double expected[3];
    Estimate measured[3];
    for (int c = 0; c < 3; ++c) {
        expected[c] = rho * L[c];
        measured[c] = pixel_estimate(img, c);
    }
    return judge_rgb(
        "radiometry",
        fmt::format("Lambertian plane ρ = {} under a uniform sky L = (1, 0.5, 0.25) (path)", rho),
        "L_o = ρ L", expected, measured, 1e-4, o);
}

} // namespace illum
