// The list of reflection models with their parameters (name, kind, default, range, description), used by
// `illum brdf` and later by scene materials to build a BxDF by name. Models stay constructible from plain
// values (see each model's header); the registry only parses and validates strings.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "illum/bsdf/bxdf.h"
#include "illum/geometry/surface_hit.h"
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

// Parameter values after defaults, parsing and validation.
class ParamValues {
public:
    bool has(const std::string& name) const { return values_.count(name) != 0; }
    float scalar(const std::string& name) const;
    Color3 rgb(const std::string& name) const;
    int integer(const std::string& name) const;
    const std::string& str(const std::string& name) const;
    void set(const std::string& name, std::string value) { values_[name] = std::move(value); }
    const std::map<std::string, std::string>& all() const { return values_; }

private:
    std::map<std::string, std::string> values_;
};

// Parameter values at one shading point, for placing a model in the per-thread arena: constants, or
// textures evaluated at the hit. Values are clamped to each parameter's range, so a texture cannot make a
// model invalid in the middle of a render. Lookups compare names; nothing is allocated.
class ShadingArgs {
public:
    struct Value {
        std::string name;
        ParamKind kind = ParamKind::Scalar;
        Color3 constant;                      // Scalar, Rgb, Integer (in .r)
        std::string text;                     // Choice, Path
        const ColorTexture* color = nullptr;  // a textured Rgb parameter
        const FloatTexture* scalar = nullptr; // a textured Scalar parameter
        float lo = 0, hi = 0;
        int unit_sum_group = -1; // index into ModelSpec::unit_sums, -1 for none
    };
    ShadingArgs(const std::vector<Value>& values, const SurfaceHit& hit) : values_(values), hit_(hit) {}

    bool has(const std::string& name) const { return find(name) != nullptr; }
    float scalar(const std::string& name) const;
    Color3 rgb(const std::string& name) const;
    int integer(const std::string& name) const { return int(scalar(name)); }
    const std::string& str(const std::string& name) const;

private:
    const Value& get(const std::string& name) const;
    Color3 raw_rgb(const Value& v) const; // evaluated and clamped to the parameter's range
    const Value* find(const std::string& name) const {
        for (const Value& v : values_)
            if (v.name == name) return &v;
        return nullptr;
    }
    const std::vector<Value>& values_;
    const SurfaceHit& hit_;
};

// A model's constructors: on the heap from validated values (tools, audits, constant materials), or in
// the arena from a shading point's values (textured materials; null for a model that cannot be placed
// there, such as the measured one with its shared table).
struct ModelFactory {
    std::function<std::unique_ptr<BxDF>(const ParamValues&)> make;
    std::function<const BxDF*(const ShadingArgs&, ScratchArena&)> place;
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

    std::unique_ptr<BxDF> make(const ParamValues& values) const { return factory.make(values); }
};

const std::vector<ModelSpec>& bxdf_models();
// Throws illum::Error naming the unknown model and listing the known ones.
const ModelSpec& find_bxdf_model(const std::string& name);
// Applies defaults and validates every value (unknown name, not a number, out of range, bad choice).
ParamValues resolve_params(const ModelSpec& model, const std::map<std::string, std::string>& params);
std::unique_ptr<BxDF> make_bxdf(const std::string& model, const std::map<std::string, std::string>& params);
// The interior index used by reciprocity checks (1 when the model has none).
float model_eta(const ModelSpec& model, const ParamValues& values);

} // namespace illum
