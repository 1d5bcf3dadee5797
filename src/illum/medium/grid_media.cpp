// The factories of pbrt-v4's grid media ("uniformgrid", "rgbgrid", "cloud", "nanovdb"), reading the
// parameters pbrt-v4 reads (pbrt-v4 media.cpp: GridMedium::Create, RGBGridMedium::Create,
// CloudMedium::Create, NanoVDBMedium::Create) with the same defaults. Where pbrt-v4 would accept bad
// values (negative or NaN grid values, nx < 1, p0 >= p1) or exit, these throw illum::Error at the
// parameter's position. One addition: "uniformgrid" also takes a "preset" (medium_scattering), which
// pbrt-v4 leaves unused there.
#include <cmath>
#include <fmt/format.h>

#include "illum/medium/cloud_medium.h"
#include "illum/medium/create_medium.h"
#include "illum/medium/nanovdb_medium.h"
#include "illum/medium/rgb_grid_medium.h"
#include "illum/medium/uniform_grid_medium.h"

namespace illum {

namespace {

[[noreturn]] void fail_at(const MediumDesc& desc, const std::string& param, const std::string& msg) {
    if (const Param* p = desc.params.find(param)) desc.params.fail(*p, msg);
    throw Error(desc.loc, msg);
}

std::string prefix(const MediumDesc& desc) { return fmt::format("{} medium \"{}\"", desc.type, desc.name); }

// "nx", "ny", "nz" (default 1 each), each at least 1, and their product within reach of memory.
std::array<int, 3> resolution(const MediumDesc& desc) {
    std::array<int, 3> n{};
    const char* names[3] = {"nx", "ny", "nz"};
    for (std::size_t a = 0; a < 3; ++a) {
        n[a] = desc.params.get_int(names[a], 1);
        if (n[a] < 1)
            fail_at(desc, names[a], fmt::format("{}: \"{}\" must be at least 1", prefix(desc), names[a]));
    }
    if (double(n[0]) * double(n[1]) * double(n[2]) > 1e10)
        fail_at(desc, "nx", fmt::format("{}: nx * ny * nz is too large", prefix(desc)));
    return n;
}
std::size_t count(const std::array<int, 3>& n) {
    return std::size_t(n[0]) * std::size_t(n[1]) * std::size_t(n[2]);
}

// The box [p0, p1] (default [0, 1]^3), non-empty on every axis.
Bounds3f medium_bounds(const MediumDesc& desc) {
    Bounds3f b;
    b.lo = desc.params.get_point3("p0").value_or(Point3f(0, 0, 0));
    b.hi = desc.params.get_point3("p1").value_or(Point3f(1, 1, 1));
    if (!(b.lo.x < b.hi.x && b.lo.y < b.hi.y && b.lo.z < b.hi.z))
        fail_at(desc, desc.params.has("p1") ? "p1" : "p0",
                fmt::format("{}: \"p0\" must be below \"p1\" on every axis", prefix(desc)));
    return b;
}

// A float grid parameter: empty when absent; else exactly n finite values, non-negative unless
// allow_negative.
std::vector<float> float_grid(const MediumDesc& desc, const std::string& name, std::size_t n,
                              bool allow_negative = false) {
    const Param* p = desc.params.find(name);
    if (!p) return {};
    std::vector<float> v = desc.params.get_floats(name); // checks the type and finiteness
    if (v.size() != n)
        desc.params.fail(*p, fmt::format("{}: \"{}\" has {} values; expected nx * ny * nz = {}", prefix(desc),
                                         name, v.size(), n));
    if (!allow_negative)
        for (float x : v)
            if (x < 0)
                desc.params.fail(*p, fmt::format("{}: \"{}\" has a negative value", prefix(desc), name));
    return v;
}

// An "rgb" grid parameter (3 numbers per sample): empty when absent; else finite, non-negative.
std::vector<Color3> rgb_grid(const MediumDesc& desc, const std::string& name) {
    const Param* p = desc.params.find(name);
    if (!p) return {};
    p->used = true;
    if (p->type != ParamType::RGB)
        desc.params.fail(*p, fmt::format("{}: parameter \"{}\" has type {}, expected rgb", prefix(desc), name,
                                         to_string(p->type)));
    if (p->numbers.empty() || p->numbers.size() % 3 != 0)
        desc.params.fail(*p, fmt::format("{}: \"{}\" needs a multiple of 3 values, got {}", prefix(desc),
                                         name, p->numbers.size()));
    std::vector<Color3> v(p->numbers.size() / 3);
    for (std::size_t i = 0; i < v.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            double x = p->numbers[3 * i + std::size_t(c)];
            if (!std::isfinite(x) || x < 0)
                desc.params.fail(
                    *p, fmt::format("{}: \"{}\" must be finite and non-negative", prefix(desc), name));
            v[i][c] = float(x);
        }
    return v;
}

float non_negative(const MediumDesc& desc, const std::string& name, float def) {
    float v = desc.params.get_float(name, def);
    if (!(v >= 0)) fail_at(desc, name, fmt::format("{}: \"{}\" must be non-negative", prefix(desc), name));
    return v;
}

// pbrt-v4 reads the temperature offset as "temperatureoffset", falling back to the older
// "temperaturecutoff".
float temperature_offset(const MediumDesc& desc) {
    return desc.params.get_float("temperatureoffset", desc.params.get_float("temperaturecutoff", 0));
}

CreatedMedium create_uniform_grid(const MediumDesc& desc) {
    UniformGridParams p;
    std::array<int, 3> n = resolution(desc);
    std::size_t nv = count(n);
    if (!desc.params.has("density"))
        throw Error(desc.loc, fmt::format("{}: no \"density\" values", prefix(desc)));
    p.density = SampledGrid<float>(float_grid(desc, "density", nv), n[0], n[1], n[2]);
    if (desc.params.has("temperature"))
        p.temperature = SampledGrid<float>(float_grid(desc, "temperature", nv), n[0], n[1], n[2]);
    p.le = medium_le(desc, &p.le_nonzero);
    if (p.temperature && desc.params.has("Le"))
        fail_at(desc, "Le", fmt::format("{}: both \"Le\" and \"temperature\" are given", prefix(desc)));
    // The emission is already normalised to luminance 1 (medium_le), pbrt-v4's LeNorm.
    if (desc.params.has("Lescale"))
        p.le_scale = SampledGrid<float>(float_grid(desc, "Lescale", nv), n[0], n[1], n[2]);
    else
        p.le_scale = SampledGrid<float>({1.0f}, 1, 1, 1);
    p.temperature_offset = temperature_offset(desc);
    p.temperature_scale = desc.params.get_float("temperaturescale", 1);
    p.box = MediumBox(desc.world_from_medium, medium_bounds(desc));
    medium_scattering(desc, &p.sigma_a, &p.sigma_s);
    p.g = medium_g(desc);
    auto m = std::make_unique<UniformGridMedium>(std::move(p));
    std::size_t bytes = m->bytes();
    return {std::move(m), {"uniformgrid", bytes}};
}

CreatedMedium create_rgb_grid(const MediumDesc& desc) {
    RGBGridParams p;
    std::vector<Color3> sa = rgb_grid(desc, "sigma_a"), ss = rgb_grid(desc, "sigma_s"),
                        le = rgb_grid(desc, "Le");
    if (sa.empty() && ss.empty())
        throw Error(desc.loc, fmt::format("{}: needs \"sigma_a\" and/or \"sigma_s\" values", prefix(desc)));
    std::size_t nd = sa.empty() ? ss.size() : sa.size();
    if (!sa.empty() && !ss.empty() && ss.size() != sa.size())
        fail_at(desc, "sigma_s",
                fmt::format("{}: \"sigma_a\" has {} values and \"sigma_s\" {}", prefix(desc), sa.size(),
                            ss.size()));
    if (!le.empty() && sa.empty())
        fail_at(desc, "Le", fmt::format("{}: \"Le\" needs \"sigma_a\" values", prefix(desc)));
    if (!le.empty() && le.size() != nd)
        fail_at(desc, "Le",
                fmt::format("{}: \"Le\" has {} values; expected {}", prefix(desc), le.size(), nd));
    std::array<int, 3> n = resolution(desc);
    if (nd != count(n))
        fail_at(desc, sa.empty() ? "sigma_s" : "sigma_a",
                fmt::format("{}: {} values; expected nx * ny * nz = {}", prefix(desc), nd, count(n)));
    if (!sa.empty()) p.sigma_a = SampledGrid<Color3>(std::move(sa), n[0], n[1], n[2]);
    if (!ss.empty()) p.sigma_s = SampledGrid<Color3>(std::move(ss), n[0], n[1], n[2]);
    if (!le.empty()) p.le = SampledGrid<Color3>(std::move(le), n[0], n[1], n[2]);
    p.box = MediumBox(desc.world_from_medium, medium_bounds(desc));
    p.le_scale = non_negative(desc, "Lescale", 1);
    p.g = medium_g(desc);
    p.scale = non_negative(desc, "scale", 1);
    auto m = std::make_unique<RGBGridMedium>(std::move(p));
    std::size_t bytes = m->bytes();
    return {std::move(m), {"rgbgrid", bytes}};
}

CreatedMedium create_cloud(const MediumDesc& desc) {
    CloudParams p;
    p.density = non_negative(desc, "density", 1);
    p.g = medium_g(desc);
    p.wispiness = desc.params.get_float("wispiness", 1);
    p.frequency = desc.params.get_float("frequency", 5);
    p.sigma_a = medium_coefficient(desc, "sigma_a", Color3(1.0f));
    p.sigma_s = medium_coefficient(desc, "sigma_s", Color3(1.0f));
    p.box = MediumBox(desc.world_from_medium, medium_bounds(desc));
    return {std::make_unique<CloudMedium>(std::move(p)), {"cloud", sizeof(CloudMedium)}};
}

CreatedMedium create_nanovdb(const MediumDesc& desc) {
    std::string filename = desc.params.get_string("filename", "");
    if (filename.empty()) throw Error(desc.loc, fmt::format("{}: needs \"string filename\"", prefix(desc)));
    NanoVDBLoad load = load_nanovdb(filename, desc.params.get_string("gridname", "density"),
                                    desc.params.get_string("temperaturename", "temperature"));
    if (!load.grids) fail_at(desc, "filename", fmt::format("{}: {}", prefix(desc), load.error));
    NanoVDBParams p;
    p.world_from_medium = desc.world_from_medium;
    p.grids = std::move(load.grids);
    p.le_scale = non_negative(desc, "Lescale", 1);
    p.temperature_offset = temperature_offset(desc);
    p.temperature_scale = desc.params.get_float("temperaturescale", 1);
    p.g = medium_g(desc);
    p.sigma_a = medium_coefficient(desc, "sigma_a", Color3(1.0f));
    p.sigma_s = medium_coefficient(desc, "sigma_s", Color3(1.0f));
    float scale = non_negative(desc, "scale", 1);
    p.sigma_a *= scale;
    p.sigma_s *= scale;
    auto m = std::make_unique<NanoVDBMedium>(std::move(p));
    std::size_t bytes = m->bytes();
    return {std::move(m), {"nanovdb", bytes}};
}

} // namespace

CreatedMedium create_grid_medium(const MediumDesc& desc, Diagnostics&) {
    if (desc.type == "uniformgrid") return create_uniform_grid(desc);
    if (desc.type == "rgbgrid") return create_rgb_grid(desc);
    if (desc.type == "cloud") return create_cloud(desc);
    if (desc.type == "nanovdb") return create_nanovdb(desc);
    return {};
}

} // namespace illum
