#include "illum/param/param_set.h"

#include <cmath>
#include <fmt/format.h>

namespace illum {

namespace {
const char* kTypeNames[] = {"float",  "integer", "bool",    "string", "rgb",    "spectrum",
                            "point2", "point3",  "vector3", "normal", "texture"};
}

const char* to_string(ParamType t) { return kTypeNames[int(t)]; }

std::optional<ParamType> param_type_from_string(const std::string& s) {
    for (int i = 0; i < int(std::size(kTypeNames)); ++i)
        if (s == kTypeNames[i]) return ParamType(i);
    if (s == "point") return ParamType::Point3;
    if (s == "vector") return ParamType::Vector3;
    if (s == "normal3") return ParamType::Normal;
    if (s == "color") return ParamType::RGB;
    return std::nullopt;
}

void ParamSet::add(Param p) {
    for (auto& q : params_)
        if (q.name == p.name) {
            q = std::move(p);
            return;
        }
    params_.push_back(std::move(p));
}

const Param* ParamSet::find(const std::string& name) const {
    for (auto& p : params_)
        if (p.name == name) return &p;
    return nullptr;
}

void ParamSet::fail(const Param& p, const std::string& message) const { throw Error(p.loc, message); }

const Param* ParamSet::lookup(const std::string& name, std::initializer_list<ParamType> types) const {
    const Param* p = find(name);
    if (!p) return nullptr;
    for (ParamType t : types)
        if (p->type == t) {
            p->used = true;
            return p;
        }
    std::string expected;
    for (ParamType t : types) expected += (expected.empty() ? "" : " or ") + std::string(to_string(t));
    fail(*p, fmt::format("parameter \"{}\" has type {}, expected {}", name, to_string(p->type), expected));
}

namespace {
void expect_count(const ParamSet& ps, const Param& p, size_t n) {
    size_t have = p.type == ParamType::Bool                                       ? p.bools.size()
                  : (p.type == ParamType::String || p.type == ParamType::Texture) ? p.strings.size()
                                                                                  : p.numbers.size();
    if (have != n)
        ps.fail(p,
                fmt::format("parameter \"{}\" needs {} value{}, has {}", p.name, n, n == 1 ? "" : "s", have));
}
void expect_multiple(const ParamSet& ps, const Param& p, size_t k) {
    if (p.numbers.size() % k != 0)
        ps.fail(p, fmt::format("parameter \"{}\" needs a multiple of {} values, has {}", p.name, k,
                               p.numbers.size()));
}
float finite_float(const ParamSet& ps, const Param& p, double v) {
    if (!std::isfinite(v)) ps.fail(p, fmt::format("parameter \"{}\" is not a finite number", p.name));
    return float(v);
}
} // namespace

float ParamSet::get_float(const std::string& name, float def) const {
    const Param* p = lookup(name, {ParamType::Float});
    if (!p) return def;
    expect_count(*this, *p, 1);
    return finite_float(*this, *p, p->numbers[0]);
}

int ParamSet::get_int(const std::string& name, int def) const {
    const Param* p = lookup(name, {ParamType::Integer});
    if (!p) return def;
    expect_count(*this, *p, 1);
    return int(p->numbers[0]);
}

bool ParamSet::get_bool(const std::string& name, bool def) const {
    const Param* p = lookup(name, {ParamType::Bool});
    if (!p) return def;
    expect_count(*this, *p, 1);
    return p->bools[0];
}

std::string ParamSet::get_string(const std::string& name, const std::string& def) const {
    const Param* p = lookup(name, {ParamType::String});
    if (!p) return def;
    expect_count(*this, *p, 1);
    return p->strings[0];
}

template <class T>
std::optional<T> ParamSet::get_triple(const std::string& name, ParamType type) const {
    const Param* p = lookup(name, {type});
    if (!p) return std::nullopt;
    expect_count(*this, *p, 3);
    return T(finite_float(*this, *p, p->numbers[0]), finite_float(*this, *p, p->numbers[1]),
             finite_float(*this, *p, p->numbers[2]));
}

std::optional<Color3> ParamSet::get_rgb(const std::string& name) const {
    return get_triple<Color3>(name, ParamType::RGB);
}
std::optional<Point3f> ParamSet::get_point3(const std::string& name) const {
    return get_triple<Point3f>(name, ParamType::Point3);
}
std::optional<Vector3f> ParamSet::get_vector3(const std::string& name) const {
    return get_triple<Vector3f>(name, ParamType::Vector3);
}

std::string ParamSet::get_texture(const std::string& name) const {
    const Param* p = lookup(name, {ParamType::Texture});
    if (!p) return {};
    expect_count(*this, *p, 1);
    return p->strings[0];
}

std::vector<float> ParamSet::get_floats(const std::string& name) const {
    const Param* p = lookup(name, {ParamType::Float});
    std::vector<float> r;
    if (!p) return r;
    for (double v : p->numbers) r.push_back(finite_float(*this, *p, v));
    return r;
}

std::vector<int> ParamSet::get_ints(const std::string& name) const {
    const Param* p = lookup(name, {ParamType::Integer});
    std::vector<int> r;
    if (!p) return r;
    for (double v : p->numbers) r.push_back(int(v));
    return r;
}

std::vector<Point2f> ParamSet::get_point2s(const std::string& name) const {
    const Param* p = lookup(name, {ParamType::Point2, ParamType::Float});
    std::vector<Point2f> r;
    if (!p) return r;
    expect_multiple(*this, *p, 2);
    for (size_t i = 0; i + 1 < p->numbers.size(); i += 2)
        r.push_back({finite_float(*this, *p, p->numbers[i]), finite_float(*this, *p, p->numbers[i + 1])});
    return r;
}

template <class T>
std::vector<T> ParamSet::get_triples(const std::string& name, ParamType type) const {
    const Param* p = lookup(name, {type});
    std::vector<T> r;
    if (!p) return r;
    expect_multiple(*this, *p, 3);
    for (size_t i = 0; i + 2 < p->numbers.size(); i += 3)
        r.push_back({finite_float(*this, *p, p->numbers[i]), finite_float(*this, *p, p->numbers[i + 1]),
                     finite_float(*this, *p, p->numbers[i + 2])});
    return r;
}

std::vector<Point3f> ParamSet::get_point3s(const std::string& name) const {
    return get_triples<Point3f>(name, ParamType::Point3);
}
std::vector<Normal3f> ParamSet::get_normals(const std::string& name) const {
    return get_triples<Normal3f>(name, ParamType::Normal);
}

std::vector<std::string> ParamSet::get_strings(const std::string& name) const {
    const Param* p = lookup(name, {ParamType::String});
    return p ? p->strings : std::vector<std::string>{};
}

std::vector<const Param*> ParamSet::unused() const {
    std::vector<const Param*> r;
    for (auto& p : params_)
        if (!p.used) r.push_back(&p);
    return r;
}

} // namespace illum
