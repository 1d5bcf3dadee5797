// The list of reflection models with their parameters (name, kind, default, range, description), used by
// `illum brdf` and later by scene materials to build a BxDF by name. Models stay constructible from plain
// values (see each model's header); the registry only parses and validates strings.
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "illum/bsdf/bxdf.h"
#include "illum/param/param_set.h"
#include "illum/radiometry/densely_sampled_spectrum.h"
#include "illum/radiometry/uplift.h"
#include "illum/texture/texture.h"
#include "illum/util/arena.h"

namespace illum {

enum class ParamKind { Scalar, Rgb, Integer, Choice, Path };
const char* to_string(ParamKind kind);

struct ParamSpec {
    std::string name;
    ParamKind kind = ParamKind::Scalar;
    std::string default_value; // empty: optional, see description
    double min = 0, max = 0;   // for Scalar, Rgb (each component) and Integer
    std::string description;
    std::vector<std::string> choices; // for Choice
};

// A parameter's name as the code names it: a hash computed at compile time ("kd"_p), so looking a
// parameter up at a shading point compares integers, never strings. The registry checks at start-up that
// no two parameters of a model share a hash.
struct ParamId {
    std::uint32_t hash = 0;
    // FNV-1a, 32 bit.
    static constexpr std::uint32_t of(std::string_view s) {
        std::uint32_t h = 2166136261u;
        for (char c : s) h = (h ^ std::uint8_t(c)) * 16777619u;
        return h;
    }
};
// clang 14 (Debian 12's, used by `make test-sanitize`) does not evaluate a consteval call inside a generic
// lambda at compile time and emits a call to the consteval function instead, which then fails to link
// ("undefined reference to operator""_p"). There the literal is constexpr; the optimiser folds it.
#if defined(__clang__) && __clang_major__ < 17
#define ILLUM_PARAM_ID_CONSTEVAL constexpr
#else
#define ILLUM_PARAM_ID_CONSTEVAL consteval
#endif
ILLUM_PARAM_ID_CONSTEVAL ParamId operator""_p(const char* s, std::size_t n) {
    return {ParamId::of(std::string_view(s, n))};
}

// One parameter of a model after validation: its constant value or the texture that gives it, the range
// that shading clamps a textured value to, and the group of parameters whose sum must stay <= 1.
struct ModelArg {
    // What a shading point reads first, together (a lookup scans the ids of a model's few parameters).
    std::uint32_t id = 0;
    int unit_sum_group = -1;              // index into ModelSpec::unit_sums, -1 for none
    const ColorTexture* color = nullptr;  // a textured Rgb parameter
    const FloatTexture* scalar = nullptr; // a textured Scalar parameter
    Color3 constant;                      // Scalar, Rgb, Integer (in .r); a textured one's default
    // A parameter given as a spectrum (a named metal's η, a glass's index): its table for spectral mode
    // (`constant` holds its RGB or mean reduction for RGB mode).
    std::shared_ptr<const DenselySampledSpectrum> spectrum;
    // A constant Rgb parameter's spectrum in each colour space (uplifted once; `spectrum()` reads it).
    UpliftCache uplifted;
    float lo = 0, hi = 0;
    ParamKind kind = ParamKind::Scalar;
    std::string text; // Choice, Path
    std::string name; // for reports only
};

// A model's validated parameters (defaults applied, in the order of the model's spec): what the tools,
// the audits and scene materials build a model from. `describe()` gives "name=value ..." for reports.
struct ParamValues {
    std::vector<ModelArg> args;
    std::string describe() const;
};

// The values a model's constructor reads, at one shading point (textures evaluated there and clamped to
// each parameter's range, unit-sum groups scaled down to 1) or, without a point, the constants as given
// (the constructor rejects a broken unit sum). A lookup
// is a scan of a few integers: nothing is allocated, thrown or compared as text.
class ModelArgs {
public:
    // w: the path's wavelengths (null: RGB mode, as for the tools and audits).
    ModelArgs(const std::vector<ModelArg>& args, const TextureEvalContext* at,
              SampledWavelengths* w = nullptr)
        : args_(args), at_(at), w_(w) {}

    bool has(ParamId id) const { return find(id) != nullptr; }
    float scalar(ParamId id) const;
    Color3 rgb(ParamId id) const;
    // An Rgb parameter at the path's wavelengths: its table if given as a spectrum, else its RGB uplifted
    // as a reflectance (range within [0, 1]) or as an unbounded value; the RGB itself in RGB mode.
    SampledSpectrum spectrum(ParamId id) const;
    // A Scalar parameter that may vary with wavelength (an index of refraction given as a spectrum): in
    // spectral mode its value at the hero wavelength, the other wavelengths terminated (dispersion);
    // the scalar otherwise.
    float dispersive_scalar(ParamId id) const;
    int integer(ParamId id) const { return int(scalar(id)); }
    const std::string& str(ParamId id) const { return get(id).text; }
    // How many lookups named a parameter the model's spec does not have (a registry bug; tests assert 0).
    static int misses() { return misses_.load(); }

private:
    static const ModelArg& miss(); // counted; reads as zero
    static std::atomic<int> misses_;
    const ModelArg& get(ParamId id) const {
        const ModelArg* v = find(id);
        return v ? *v : miss();
    }
    Color3 raw_rgb(const ModelArg& v) const; // evaluated and clamped to the parameter's range
    SampledSpectrum raw_spectrum(const ModelArg& v) const;
    const ModelArg* find(ParamId id) const {
        for (const ModelArg& v : args_)
            if (v.id == id.hash) return &v;
        return nullptr;
    }
    const std::vector<ModelArg>& args_;
    const TextureEvalContext* at_;
    SampledWavelengths* w_;
};

// Defined here so that a textured material's constructor inlines them (they run at every hit).
// x clamped to [lo, hi], NaN to lo (the comparisons are false for NaN): two min/max instructions.
inline float clamp_to_range(float x, float lo, float hi) { return x > lo ? (x < hi ? x : hi) : lo; }

inline float ModelArgs::scalar(ParamId id) const {
    const ModelArg& v = get(id);
    float x = v.scalar && at_ ? v.scalar->evaluate(*at_) : v.constant.r;
    return clamp_to_range(x, v.lo, v.hi);
}

inline Color3 ModelArgs::raw_rgb(const ModelArg& v) const {
    Color3 c = v.color && at_ ? v.color->evaluate(*at_) : v.constant;
    for (int i = 0; i < 3; ++i) c[i] = clamp_to_range(c[i], v.lo, v.hi);
    return c;
}

inline Color3 ModelArgs::rgb(ParamId id) const {
    const ModelArg& v = get(id);
    Color3 c = raw_rgb(v);
    // Only textures can break a unit sum at a shading point; constants were checked by the constructor.
    if (v.unit_sum_group < 0 || !at_) return c;
    Color3 sum;
    for (const ModelArg& w : args_)
        if (w.unit_sum_group == v.unit_sum_group) sum += raw_rgb(w);
    // Scaled to a hair below 1 (one part in 10^6), so float rounding of the sum cannot exceed the
    // constructor's bound of 1.
    for (int i = 0; i < 3; ++i)
        if (sum[i] > 1) c[i] *= (1 - 1e-6f) / sum[i];
    return c;
}

// Spectral mode: the parameter at the path's wavelengths, clamped to its range (an uplifted unbounded
// value can reach 0 where the sigmoid saturates, below an index's lower bound).
inline SampledSpectrum ModelArgs::raw_spectrum(const ModelArg& v) const {
    SampledSpectrum s;
    if (!v.color)
        s = v.spectrum ? v.spectrum->sample(*w_) : v.uplifted.at(*w_);
    else
        s = v.hi <= 1 ? uplift_albedo(raw_rgb(v), *w_) : uplift_unbounded(raw_rgb(v), *w_);
    return clamp(s, v.lo, v.hi);
}

inline SampledSpectrum ModelArgs::spectrum(ParamId id) const {
    if (!w_ || !w_->spectral()) return SampledSpectrum(rgb(id));
    const ModelArg& v = get(id);
    SampledSpectrum s = raw_spectrum(v);
    if (v.unit_sum_group < 0) return s;
    // Spectra uplifted from RGB values whose sum is at most 1 may sum to more at some wavelengths (constants
    // too): each wavelength of the group is scaled to a hair below 1 as textured RGB values are.
    SampledSpectrum sum;
    for (const ModelArg& w : args_)
        if (w.unit_sum_group == v.unit_sum_group) sum += raw_spectrum(w);
    for (int i = 0; i < kSpectrumSamples; ++i)
        if (sum[i] > 1) s[i] *= (1 - 1e-6f) / sum[i];
    return s;
}

inline float ModelArgs::dispersive_scalar(ParamId id) const {
    const ModelArg& v = get(id);
    if (!w_ || !w_->spectral() || !v.spectrum || v.scalar) return scalar(id);
    w_->terminate_secondary();
    return clamp_to_range((*v.spectrum)(w_->hero()), v.lo, v.hi);
}

class Material;

// A model's constructors: on the heap (tools, audits, constant materials), or in the arena at a shading
// point; and a textured material that places the model per hit with the constructor inlined into it
// (both null for a model that cannot be placed in the arena, such as the measured one with its shared
// table).
struct ModelFactory {
    using Place = const BxDF* (*)(const ModelArgs&, ScratchArena&);
    using NormalAlbedo = Color3 (*)(const ModelArgs&);
    using MakeTextured = std::unique_ptr<Material> (*)(ParamValues values, Color3 albedo, NormalAlbedo);
    std::function<std::unique_ptr<BxDF>(const ModelArgs&)> make;
    Place place = nullptr;
    MakeTextured textured = nullptr;
};

struct AuditCase {
    std::map<std::string, std::string> params;
    bool lossless = false; // albedo must be 1 (within error) at every angle
};

struct ModelSpec {
    std::string name;
    std::string description;
    std::vector<ParamSpec> params;
    std::vector<AuditCase> audit_grid;
    bool delta = false;        // only delta lobes: f() and pdf() are 0
    bool non_physical = false; // reciprocity and energy are reported, not required
    bool stochastic = false;   // f() is a stochastic estimate and pdf() approximate
    std::string eta_param;     // interior index for generalised reciprocity of transmission
    ModelFactory factory;
    // Groups of Rgb parameters whose sum the model requires to be at most 1 (kd + ks, say). Where textures
    // break that at a shading point, the group is scaled down per channel to sum to 1.
    std::vector<std::vector<std::string>> unit_sums = {};
    // The directional albedo at normal incidence in closed form, where the model has one (the albedo pass
    // shows it at each hit of a textured material; otherwise it shows the estimate at the defaults).
    ModelFactory::NormalAlbedo normal_albedo = nullptr;
    // Why f(wo, wi) = f(wi, wo) does not hold for this model (empty: it must); the audit then skips the
    // reciprocity check and shows the reason.
    std::string not_reciprocal = {};

    std::unique_ptr<BxDF> make(const ParamValues& values) const {
        return factory.make(ModelArgs(values.args, nullptr));
    }
};

const std::vector<ModelSpec>& bxdf_models();
// Throws illum::Error naming the unknown model and listing the known ones.
const ModelSpec& find_bxdf_model(const std::string& name);
// The one validation of a model's parameters, as a scene file gives them (typed, with positions): unknown
// name (listing the model's parameters), wrong type or count, out of range, bad choice, empty path.
// Texture-valued parameters are resolved through `textures` (an error when it is null or the parameter
// cannot be textured); defaults are applied. Marks every parameter it reads used. Throws illum::Error at
// the parameter's position.
// With `pbrt_alias` (a pbrt-v4 material name standing for the model), out-of-range colours are clamped to
// the range (pbrt-v4 clamps reflectances where it uses them) and parameters the model does not know are
// left unused, for the builder to report as pbrt-v4 parameters illum does not use. A spectrum given for a
// scalar (an index of refraction) is reduced to the mean of its RGB, warned unless it is a named glass.
ParamValues resolve_params(const ModelSpec& model, const ParamSet& params,
                           class TextureParams* textures = nullptr, bool pbrt_alias = false);
// Parameters as text (`illum brdf ... name=value`, audit grids): numbers for scalar, integer and rgb
// parameters ("0.5" or "r,g,b"), words for choices and paths; then validated as above.
ParamSet params_from_text(const ModelSpec& model, const std::map<std::string, std::string>& params);
ParamValues resolve_params(const ModelSpec& model, const std::map<std::string, std::string>& params);
std::unique_ptr<BxDF> make_bxdf(const std::string& model, const std::map<std::string, std::string>& params);
// The tables of pbrt-v4's "measured" material: an RGL `.bsdf` file, or for `synthetic:ALPHA` a GGX
// conductor tabulated in that layout (cached per α). Throws illum::Error naming the file.
struct RglBrdf;
std::shared_ptr<const RglBrdf> measured_brdf_data(const std::string& filename);
// The interior index used by reciprocity checks (1 when the model has none).
float model_eta(const ModelSpec& model, const ParamValues& values);

} // namespace illum
