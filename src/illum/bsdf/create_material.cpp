#include "illum/bsdf/create_material.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "illum/bsdf/albedo.h"
#include "illum/bsdf/hair_material.h"
#include "illum/bsdf/measured_material.h"
#include "illum/bsdf/pbrt_materials.h"
#include "illum/bsdf/registry.h"
#include "illum/bsdf/shared_bxdf_material.h"
#include "illum/bsdf/subsurface_material.h"
#include "illum/medium/homogeneous_medium.h"
#include "illum/medium/subsurface_coefficients.h"
#include "illum/medium/textured_subsurface_medium.h"
#include "illum/param/spectrum_param.h"
#include "illum/radiometry/named_spectra.h"
#include "illum/radiometry/spectra.h"

namespace illum {

namespace {

// pbrt-v4 material names that are a registry model under another name, with the same parameter names
// (both aliases so far need no renaming; pbrt-v4 parameters the model lacks are left to the unused-
// parameter warning).
struct MaterialAlias {
    const char* pbrt_name;
    const char* model;
};
constexpr MaterialAlias kMaterialAliases[] = {
    {"diffuse", "lambert"},
    {"thindielectric", "thin-dielectric"},
};

class MaterialMaker {
public:
    MaterialMaker(const EntityDesc& m, MaterialContext& ctx) : m_(m), ctx_(ctx), tex_(ctx.textures) {}

    const Material* make(const std::string& type) {
        if (type == "conductor") return conductor("");
        if (type == "dielectric")
            return own(std::make_unique<DielectricMaterial>(eta_param("eta", 1.5f), roughness()));
        if (type == "coateddiffuse")
            return own(
                std::make_unique<CoatedDiffuseMaterial>(tex_.color(m_.params, "reflectance", Color3(0.5f)),
                                                        eta_param("eta", 1.5f), roughness(), layer()));
        if (type == "coatedconductor") {
            DispersiveScalar ieta = eta_param("interface.eta", 1.5f);
            RoughnessParams coat = roughness("interface.");
            const ConductorMaterial* c = conductor("conductor.");
            return own(std::make_unique<CoatedConductorMaterial>(std::move(ieta), coat, c,
                                                                 roughness("conductor."), layer()));
        }
        if (type == "diffusetransmission")
            return own(std::make_unique<DiffuseTransmissionMaterial>(
                tex_.color(m_.params, "reflectance", Color3(0.25f)),
                tex_.color(m_.params, "transmittance", Color3(0.25f)), m_.params.get_float("scale", 1)));
        if (type == "interface") return own(std::make_unique<InterfaceMaterial>());
        if (type == "mix") return mix();
        if (type == "subsurface") return subsurface();
        if (type == "hair") return hair();
        if (type == "measured") return measured();
        for (const MaterialAlias& a : kMaterialAliases)
            if (type == a.pbrt_name) return model(find_bxdf_model(a.model), true);
        for (const ModelSpec& spec : bxdf_models())
            if (spec.name == type) return model(spec, false);
        throw Error(m_.loc, fmt::format("unknown material type \"{}\"", type));
    }

private:
    // A constant RGB or spectrum parameter: its RGB and, for a spectrum, its table; nothing when absent or
    // a texture.
    struct ConstantSpectrum {
        Color3 rgb;
        std::shared_ptr<const DenselySampledSpectrum> spectrum;
    };
    std::optional<ConstantSpectrum> constant_spectrum(const std::string& name, SpectrumKind kind) {
        const Param* p = m_.params.find(name);
        if (!p) return std::nullopt;
        if (p->type == ParamType::RGB) return ConstantSpectrum{*m_.params.get_rgb(name), nullptr};
        if (p->type == ParamType::Spectrum) {
            SpectrumParam s = spectrum_param(*p, kind);
            return ConstantSpectrum{s.rgb, std::move(s.spectrum)};
        }
        if (p->type == ParamType::Float) {
            float v = m_.params.get_float(name, 0);
            return ConstantSpectrum{Color3(v), nullptr};
        }
        return std::nullopt;
    }
    bool textured(const std::string& name) const {
        const Param* p = m_.params.find(name);
        return p && p->type == ParamType::Texture;
    }
    // A subsurface coefficient parameter of a textured pair (textured_subsurface_medium.h): its texture,
    // or the constant's (with its spectrum, for spectral mode); `def` when absent.
    SubsurfaceParam subsurface_param(const std::string& name, SpectrumKind kind, Color3 def) {
        SubsurfaceParam s;
        if (auto c = constant_spectrum(name, kind)) s.spectrum = c->spectrum;
        s.texture = tex_.color(m_.params, name, def);
        return s;
    }

    // pbrt-v4's "measured" (measured_material.h): the tables of the "filename" RGL .bsdf file.
    const Material* measured() {
        const Param* p = m_.params.find("filename");
        if (!p) throw Error(m_.loc, "material \"measured\" needs \"string filename\" (an RGL .bsdf file)");
        std::string file = m_.params.get_string("filename", "");
        std::shared_ptr<const RglBrdf> data;
        try {
            data = measured_brdf_data(file);
        } catch (const Error& e) { // reported with the scene's other unreadable files
            tex_.diagnostics().missing_file(p->loc, e.what());
            return own(std::make_unique<DiffuseMaterial>(tex_.constant(Color3(0.5f))));
        }
        return own(std::make_unique<MeasuredMaterial>(std::move(data)));
    }

    // pbrt-v4's "subsurface" (subsurface_material.h): the medium inside from the parameters, as pbrt-v4
    // derives its coefficients (medium/subsurface_coefficients.h), and the dielectric boundary.
    const Material* subsurface() {
        const ParamSet& ps = m_.params;
        float scale = ps.get_float("scale", kSubsurfaceDefaultScale);
        float g = ps.get_float("g", kSubsurfaceDefaultG);
        if (!(g > -1 && g < 1)) throw Error(ps.find("g")->loc, "\"g\" must lie in (-1, 1)");
        if (!(scale >= 0)) throw Error(ps.find("scale")->loc, "\"scale\" must be non-negative");
        DispersiveScalar eta = eta_param("eta", kSubsurfaceDefaultEta);
        RoughnessParams rough = roughness();
        std::string name = ps.get_string("name", "");
        MediumSpectrum sigma_a, sigma_s;
        std::unique_ptr<Medium> interior; // set by a textured pair, else made from sigma_a and sigma_s
        auto check = [&](const std::string& param, Color3 c) {
            for (float v : {c.r, c.g, c.b})
                if (!std::isfinite(v) || v < 0)
                    throw Error(ps.find(param)->loc,
                                fmt::format("\"{}\" must be finite and non-negative", param));
        };
        if (!name.empty()) {
            std::optional<SubsurfaceCoefficients> c = subsurface_from_name(name, scale);
            if (!c) throw Error(ps.find("name")->loc, fmt::format("unknown measured medium \"{}\"", name));
            if (g != 0)
                tex_.diagnostics().unsupported(
                    ps.find("g")->loc, "subsurface: \"g\" is 0 with a named medium (its σ_s is reduced)");
            g = 0;
            sigma_a = MediumSpectrum(c->sigma_a);
            sigma_s = MediumSpectrum(c->sigma_s);
        } else if ((ps.has("sigma_a") || ps.has("sigma_s")) && (textured("sigma_a") || textured("sigma_s"))) {
            if (!ps.has("sigma_a") || !ps.has("sigma_s"))
                throw Error(m_.loc, "subsurface: give both \"sigma_a\" and \"sigma_s\", or neither");
            for (const char* n : {"sigma_a", "sigma_s"})
                if (auto c = constant_spectrum(n, SpectrumKind::Unbounded)) check(n, c->rgb);
            interior = TexturedSubsurfaceMedium::from_sigma(
                subsurface_param("sigma_a", SpectrumKind::Unbounded, Color3(0.0f)),
                subsurface_param("sigma_s", SpectrumKind::Unbounded, Color3(0.0f)), scale, g);
        } else if (ps.has("sigma_a") || ps.has("sigma_s")) {
            auto sa = constant_spectrum("sigma_a", SpectrumKind::Unbounded);
            auto ss = constant_spectrum("sigma_s", SpectrumKind::Unbounded);
            if (!sa || !ss)
                throw Error(m_.loc, "subsurface: give both \"sigma_a\" and \"sigma_s\", or neither");
            check("sigma_a", sa->rgb);
            check("sigma_s", ss->rgb);
            sigma_a = sa->spectrum ? MediumSpectrum(sa->rgb, sa->spectrum) : MediumSpectrum(sa->rgb);
            sigma_s = ss->spectrum ? MediumSpectrum(ss->rgb, ss->spectrum) : MediumSpectrum(ss->rgb);
            sigma_a *= scale;
            sigma_s *= scale;
        } else if (ps.has("reflectance") && (textured("reflectance") || textured("mfp"))) {
            if (!(scale > 0))
                throw Error(ps.find("scale")->loc, "subsurface: \"scale\" must be positive with \"mfp\"");
            if (auto r = constant_spectrum("reflectance", SpectrumKind::Unbounded))
                check("reflectance", clamp(r->rgb, 0.0f, 1.0f));
            if (auto l = constant_spectrum("mfp", SpectrumKind::Unbounded))
                for (float v : {l->rgb.r, l->rgb.g, l->rgb.b})
                    if (!(v > 0)) throw Error(ps.find("mfp")->loc, "subsurface: \"mfp\" must be positive");
            interior = TexturedSubsurfaceMedium::from_reflectance(
                subsurface_param("reflectance", SpectrumKind::Unbounded, Color3(0.5f)),
                subsurface_param("mfp", SpectrumKind::Unbounded, Color3(kSubsurfaceDefaultMfp)), scale,
                eta.value, g);
        } else if (ps.has("reflectance")) {
            auto refl = constant_spectrum("reflectance", SpectrumKind::Unbounded);
            auto mfp = constant_spectrum("mfp", SpectrumKind::Unbounded);
            Color3 r = refl ? clamp(refl->rgb, 0.0f, 1.0f) : Color3(0.5f);
            Color3 l = mfp ? mfp->rgb : Color3(kSubsurfaceDefaultMfp);
            check("reflectance", r);
            if (mfp) check("mfp", l);
            if (!(scale > 0))
                throw Error(ps.find("scale")->loc, "subsurface: \"scale\" must be positive with \"mfp\"");
            for (float v : {l.r, l.g, l.b})
                if (!(v > 0))
                    throw Error(mfp ? ps.find("mfp")->loc : m_.loc, "subsurface: \"mfp\" must be positive");
            EffectiveAlbedoTable table(eta.value, g);
            SubsurfaceCoefficients c = subsurface_from_reflectance(r, l, scale, table);
            // Spectral mode: reflectance and mean free path at each wavelength, inverted there (as pbrt-v4
            // does per wavelength sample), tabulated per colour space the RGB inputs may be in.
            auto sa = std::make_shared<MediumSpectrum::PerColorSpace>();
            auto ss = std::make_shared<MediumSpectrum::PerColorSpace>();
            for (int i = 0; i < RGBColorSpace::kCount; ++i) {
                const RGBColorSpace& cs = RGBColorSpace::by_index(i);
                UpliftedRgb rp = uplift_albedo_poly(r, cs), mp = uplift_unbounded_poly(l, cs);
                auto at = [&](double nm) {
                    float rho = refl && refl->spectrum ? (*refl->spectrum)(float(nm)) : float(rp(nm));
                    float len = mfp && mfp->spectrum ? (*mfp->spectrum)(float(nm)) : float(mp(nm));
                    return subsurface_from_reflectance_value(rho, len, scale, table);
                };
                (*sa)[std::size_t(i)] =
                    DenselySampledSpectrum::from([&](double nm) { return at(nm).sigma_a; });
                (*ss)[std::size_t(i)] =
                    DenselySampledSpectrum::from([&](double nm) { return at(nm).sigma_s; });
            }
            sigma_a = MediumSpectrum(c.sigma_a, std::shared_ptr<const MediumSpectrum::PerColorSpace>(sa));
            sigma_s = MediumSpectrum(c.sigma_s, std::shared_ptr<const MediumSpectrum::PerColorSpace>(ss));
        } else {
            SubsurfaceCoefficients c = subsurface_default(scale);
            sigma_a = MediumSpectrum(c.sigma_a);
            sigma_s = MediumSpectrum(c.sigma_s);
        }
        if (!interior)
            interior =
                std::make_unique<HomogeneousMedium>(sigma_a, sigma_s, g, Emission(Color3(0.0f)), false);
        return own(std::make_unique<SubsurfaceMaterial>(std::move(eta), rough, std::move(interior)));
    }

    // pbrt-v4's "hair" (hair_material.h): the first of sigma_a, reflectance (or "color") and the melanins
    // that is given sets the absorption; the others stay unread, so the builder reports them unused.
    const Material* hair() {
        const ParamSet& ps = m_.params;
        HairMaterial::Absorption a;
        if (const Param* p = ps.find("sigma_a"); p && p->type == ParamType::Spectrum) {
            SpectrumParam s = spectrum_param(*p, SpectrumKind::Unbounded);
            p->used = true;
            a.sigma_a.texture = tex_.constant(s.rgb);
            a.sigma_a.spectrum = std::move(s.spectrum);
        } else if (p) {
            a.sigma_a.texture = tex_.color(ps, "sigma_a", std::nullopt);
        } else if (ps.has("reflectance") || ps.has("color")) {
            a.reflectance = tex_.color(ps, ps.has("reflectance") ? "reflectance" : "color", std::nullopt);
        } else if (ps.has("eumelanin") || ps.has("pheomelanin")) {
            a.eumelanin = tex_.scalar(ps, "eumelanin", 0.0f);
            a.pheomelanin = tex_.scalar(ps, "pheomelanin", 0.0f);
        } else {
            a.eumelanin = tex_.constant(1.3f);
        }
        return own(std::make_unique<HairMaterial>(
            std::move(a), tex_.scalar(ps, "eta", 1.55f), tex_.scalar(ps, "beta_m", 0.3f),
            tex_.scalar(ps, "beta_n", 0.3f), tex_.scalar(ps, "alpha", 2.0f)));
    }

    const Material* own(std::unique_ptr<Material> m) {
        ctx_.owned.push_back(std::move(m));
        return ctx_.owned.back().get();
    }

    int int_param(const char* name, int def, int lo, int hi) {
        int v = m_.params.get_int(name, def);
        if (v < lo || v > hi)
            throw Error(m_.params.find(name)->loc, fmt::format("\"{}\" must be in [{}, {}]", name, lo, hi));
        return v;
    }

    // A scalar index of refraction: float, or a spectrum, which disperses in spectral mode and in RGB mode
    // is reduced to its value at 550 nm (named glasses) or the mean of its RGB.
    DispersiveScalar eta_param(const std::string& name, float def) {
        const Param* p = m_.params.find(name);
        if (!p) return {def, nullptr};
        float eta = def;
        std::shared_ptr<const DenselySampledSpectrum> spectrum;
        if (p->type == ParamType::Spectrum) {
            ScalarSpectrumParam s = spectrum_param_scalar(*p, &tex_.diagnostics());
            eta = s.mean;
            spectrum = std::move(s.spectrum);
        } else if (p->type == ParamType::Texture) {
            p->used = true;
            tex_.diagnostics().unsupported(p->loc,
                                           fmt::format("a textured \"{}\" is rendered with {}", name, def));
        } else {
            eta = m_.params.get_float(name, def);
        }
        if (!(eta > 0 && eta <= 100))
            throw Error(p->loc, fmt::format("\"{}\" must be in (0, 100], got {}", name, eta));
        return {eta, std::move(spectrum)};
    }

    RoughnessParams roughness(const std::string& prefix = "") {
        RoughnessParams r;
        const FloatTexture* both = tex_.scalar(m_.params, prefix + "roughness", 0.0f);
        r.u =
            m_.params.has(prefix + "uroughness") ? tex_.scalar(m_.params, prefix + "uroughness", 0.0f) : both;
        r.v =
            m_.params.has(prefix + "vroughness") ? tex_.scalar(m_.params, prefix + "vroughness", 0.0f) : both;
        r.remap = m_.params.get_bool("remaproughness", true);
        return r;
    }

    const ConductorMaterial* conductor(const std::string& prefix) {
        const ColorTexture* refl = tex_.color(m_.params, "reflectance", std::nullopt);
        SpectralColor eta = spectral_color(prefix + "eta", "metal-Cu-eta");
        SpectralColor k = spectral_color(prefix + "k", "metal-Cu-k");
        if (refl && (m_.params.has(prefix + "eta") || m_.params.has(prefix + "k")))
            tex_.diagnostics().unsupported(
                m_.loc, "conductor with both \"reflectance\" and eta/k uses \"reflectance\"");
        auto c = std::make_unique<ConductorMaterial>(std::move(eta), std::move(k), refl, roughness(prefix));
        const ConductorMaterial* ptr = c.get();
        own(std::move(c));
        return ptr;
    }

    // A colour parameter that may be a spectrum (η, k of a conductor), or pbrt-v4's default named one.
    SpectralColor spectral_color(const std::string& name, const char* default_named) {
        SpectralColor c;
        const Param* p = m_.params.find(name);
        if (p && p->type == ParamType::Spectrum) {
            // Read once for both modes: the RGB as a constant texture, the table for spectral mode.
            SpectrumParam s = spectrum_param(*p, SpectrumKind::Unbounded);
            c.texture = tex_.constant(s.rgb);
            c.spectrum = std::move(s.spectrum);
            return c;
        }
        c.texture = tex_.color(m_.params, name, std::nullopt);
        if (!c.texture) {
            c.texture = tex_.constant(*named_spectrum_rgb(default_named));
            c.spectrum = std::make_shared<DenselySampledSpectrum>(named_dense(default_named));
        }
        return c;
    }
    static DenselySampledSpectrum named_dense(const char* name) {
        PiecewiseLinearSpectrum s = *named_spectrum(name);
        return DenselySampledSpectrum::from([&](double l) { return s(l); });
    }

    // The layer of a coated material: pbrt-v4's "thickness" (0.01), "albedo" (0), "g" (0), "maxdepth" (10)
    // and "nsamples" (1).
    LayerParams layer() {
        LayerParams l;
        if (const Param* t = m_.params.find("thickness");
            t && t->type == ParamType::Float && !(m_.params.get_float("thickness", 0.01f) >= 0))
            throw Error(t->loc, "\"thickness\" must be non-negative");
        l.thickness = tex_.scalar(m_.params, "thickness", 0.01f);
        l.albedo = tex_.color(m_.params, "albedo", Color3(0.0f));
        l.g = tex_.scalar(m_.params, "g", 0.0f);
        l.max_depth = int_param("maxdepth", 10, 1, 1000);
        l.samples = int_param("nsamples", 1, 1, 1000);
        return l;
    }

    const Material* mix() {
        auto names = m_.params.get_strings("materials");
        if (names.size() != 2)
            throw Error(m_.params.has("materials") ? m_.params.find("materials")->loc : m_.loc,
                        "mix needs \"string materials\" with two named materials");
        const Material* ab[2];
        for (int i = 0; i < 2; ++i) {
            auto it = ctx_.named.find(names[i]);
            if (it == ctx_.named.end())
                throw Error(m_.params.find("materials")->loc,
                            fmt::format("undefined named material \"{}\"", names[i]));
            ab[i] = it->second;
        }
        auto mix = std::make_unique<MixMaterial>(ab[0], ab[1], tex_.scalar(m_.params, "amount", 0.5f));
        mix->has_surface_detail =
            (ab[0] && ab[0]->has_surface_detail) || (ab[1] && ab[1]->has_surface_detail);
        mix->needs_texture_differentials =
            (ab[0] && ab[0]->needs_texture_differentials) || (ab[1] && ab[1]->needs_texture_differentials);
        return own(std::move(mix));
    }

    // A registry model, e.g. Material "ward" "rgb rho_d" [0.2 0.1 0.05] "texture rho_s" "tex", or a pbrt-v4
    // alias of one. Constant parameters: one BxDF built now and shared by every hit. Textured ones: the
    // model is placed in the arena per hit from the slots resolved here.
    const Material* model(const ModelSpec& spec, bool pbrt_alias) {
        ParamValues values;
        try {
            values = resolve_params(spec, m_.params, &tex_, pbrt_alias);
        } catch (const Error& e) {
            if (!e.where().file.empty()) throw;
            throw Error(m_.loc, e.what());
        }
        bool textured = false;
        for (const ModelArg& a : values.args) textured = textured || a.color || a.scalar;
        std::unique_ptr<BxDF> bxdf;
        try {
            bxdf = spec.make(values); // textured parameters at their defaults
        } catch (const Error& e) {
            throw Error(m_.loc, e.what());
        }
        // The albedo pass shows the directional albedo at normal incidence: in closed form where the model
        // has one, else estimated (4096 samples) once here.
        Color3 albedo;
        if (spec.normal_albedo) {
            albedo = spec.normal_albedo(ModelArgs(values.args, nullptr));
        } else {
            AlbedoEstimate a = directional_albedo(*bxdf, {0, 0, 1}, spec.delta, 16, 4096, 1);
            albedo = Color3(float(a.mc[0]), float(a.mc[1]), float(a.mc[2]));
        }
        // A delta lobe at the defaults, or possibly where textures vary the parameters (a roughness of 0);
        // the Lambertian and Oren-Nayar models have none at any parameters.
        const bool specular = has_flag(bxdf->flags(), kSpecular) ||
                              (textured && spec.name != "lambert" && spec.name != "oren-nayar");
        std::unique_ptr<Material> made;
        if (!textured) {
            made = std::make_unique<SharedBxDFMaterial>(
                std::move(bxdf), albedo,
                spec.factory.textured ? spec.factory.textured(values, albedo, spec.normal_albedo) : nullptr);
        } else {
            if (!spec.factory.textured)
                throw Error(m_.loc,
                            fmt::format("material \"{}\" cannot have textured parameters", spec.name));
            made = spec.factory.textured(std::move(values), albedo, spec.normal_albedo);
        }
        made->may_be_specular = specular;
        return own(std::move(made));
    }

    const EntityDesc& m_;
    MaterialContext& ctx_;
    TextureParams& tex_;
};

} // namespace

const Material* create_material(const EntityDesc& m, const std::string& type, MaterialContext& ctx) {
    // pbrt-v4 reads "displacement" and "normalmap" for every material but "mix" and "interface" (and its
    // "hair", which has neither); those leave them to the unused-parameter warning.
    const bool detail = type != "mix" && type != "interface" && type != "hair";
    const int footprint_uses = ctx.textures.footprint_uses();
    std::unique_ptr<const SurfaceDetail> surface_detail =
        detail ? read_surface_detail(m, ctx.textures) : nullptr;
    const Material* made = MaterialMaker(m, ctx).make(type);
    // A bump map's finite differences step by the footprint (pbrt-v4's BumpMap), so it needs one too.
    const bool filters =
        ctx.textures.footprint_uses() > footprint_uses || (surface_detail && surface_detail->bumps());
    if (surface_detail || filters) {
        // The material just made is among the owned ones (the last, or before its inner parts).
        for (auto it = ctx.owned.rbegin(); it != ctx.owned.rend(); ++it)
            if (it->get() == made) {
                if (filters) (*it)->needs_texture_differentials = true;
                if (surface_detail) {
                    (*it)->surface_detail = std::move(surface_detail);
                    (*it)->has_surface_detail = true;
                }
                break;
            }
    }
    return made;
}

} // namespace illum
