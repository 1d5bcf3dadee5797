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
    std::function<std::unique_ptr<BxDF>(const ParamValues&)> make;
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
