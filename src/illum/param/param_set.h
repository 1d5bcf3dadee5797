// Typed parameter lists, as written in scene files ("float radius" [1], "rgb L" [17 12 4]). Plain data:
// the builder looks parameters up by name and type; each lookup marks the parameter used, so unused
// ones can be reported with their source position.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "illum/math/vector.h"
#include "illum/radiometry/color.h"
#include "illum/util/error.h"

namespace illum {

enum class ParamType {
    Float,
    Integer,
    Bool,
    String,
    RGB,
    Spectrum,
    Point2,
    Point3,
    Vector3,
    Normal,
    Texture
};
const char* to_string(ParamType t);
std::optional<ParamType> param_type_from_string(const std::string& s);

// A pbrt-v4 "blackbody T" parameter is stored as type Spectrum with strings = {"blackbody"} and
// numbers = {T} (T in kelvin); a named or file spectrum has one string and no numbers; a sampled spectrum
// has numbers only (wavelength-value pairs).
struct Param {
    ParamType type = ParamType::Float;
    std::string name;
    std::vector<double> numbers;      // float, integer, rgb, point*, vector3, normal, numeric spectrum
    std::vector<std::string> strings; // string, texture, named spectrum
    std::vector<bool> bools;
    SourceLocation loc;
    mutable bool used = false;
};

class ParamSet {
public:
    void add(Param p); // replaces a parameter of the same name
    bool has(const std::string& name) const { return find(name) != nullptr; }
    const Param* find(const std::string& name) const;
    const std::vector<Param>& params() const { return params_; }

    // Single values; a parameter of the name but another type, or with the wrong count, is an error
    // naming its position.
    float get_float(const std::string& name, float def) const;
    int get_int(const std::string& name, int def) const;
    bool get_bool(const std::string& name, bool def) const;
    std::string get_string(const std::string& name, const std::string& def) const;
    std::optional<Color3> get_rgb(const std::string& name) const;
    std::optional<Point3f> get_point3(const std::string& name) const;
    std::optional<Vector3f> get_vector3(const std::string& name) const;
    std::string get_texture(const std::string& name) const; // "" when absent

    // Arrays.
    std::vector<float> get_floats(const std::string& name) const;
    std::vector<int> get_ints(const std::string& name) const;
    std::vector<Point2f> get_point2s(const std::string& name) const;
    std::vector<Point3f> get_point3s(const std::string& name) const;
    std::vector<Normal3f> get_normals(const std::string& name) const;
    std::vector<std::string> get_strings(const std::string& name) const;

    // Parameters no lookup asked for.
    std::vector<const Param*> unused() const;
    [[noreturn]] void fail(const Param& p, const std::string& message) const;

private:
    const Param* lookup(const std::string& name, std::initializer_list<ParamType> types) const;
    // A three-number parameter of `type` as T (Color3, Point3f, Vector3f), each number finite.
    template <class T>
    std::optional<T> get_triple(const std::string& name, ParamType type) const;
    template <class T>
    std::vector<T> get_triples(const std::string& name, ParamType type) const; // a list of them
    std::vector<Param> params_;
};

} // namespace illum
