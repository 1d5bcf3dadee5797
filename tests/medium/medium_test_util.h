// Helpers for the medium tests: MediumDesc built in code, the wavelengths of both modes, and an
// independent trilinear interpolation (a sum of tent weights) to check SampledGrid against.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "illum/medium/create_medium.h"
#include "illum/radiometry/color_space.h"
#include "illum/util/diagnostics.h"

namespace illum::test {

inline SourceLocation at_line(int line) { return {"media.pbrt", line, 5}; }

struct DescBuilder {
    MediumDesc desc;
    int line = 2;
    explicit DescBuilder(const std::string& type, const Transform& world_from_medium = Transform()) {
        desc.type = type;
        desc.name = std::string(1, 'm'); // (assigning the literal trips GCC 12's false -Wrestrict)
        desc.loc = at_line(1);
        desc.world_from_medium = world_from_medium;
    }
    DescBuilder& add(ParamType type, const std::string& name, std::vector<double> numbers,
                     std::vector<std::string> strings = {}) {
        Param p;
        p.type = type;
        p.name = name;
        p.numbers = std::move(numbers);
        p.strings = std::move(strings);
        p.loc = at_line(line++);
        desc.params.add(std::move(p));
        return *this;
    }
    DescBuilder& f(const std::string& name, std::vector<double> v) {
        return add(ParamType::Float, name, std::move(v));
    }
    DescBuilder& i(const std::string& name, int v) { return add(ParamType::Integer, name, {double(v)}); }
    DescBuilder& rgb(const std::string& name, std::vector<double> v) {
        return add(ParamType::RGB, name, std::move(v));
    }
    DescBuilder& p3(const std::string& name, Point3f p) {
        return add(ParamType::Point3, name, {p.x, p.y, p.z});
    }
    DescBuilder& s(const std::string& name, const std::string& v) {
        return add(ParamType::String, name, {}, {v});
    }
    DescBuilder& res(int nx, int ny, int nz) { return i("nx", nx).i("ny", ny).i("nz", nz); }
    // The source line of a parameter added above.
    int line_of(const std::string& name) const { return desc.params.find(name)->loc.line; }

    CreatedMedium create() const {
        Diagnostics diag;
        return create_medium(desc, diag);
    }
};

inline SampledWavelengths spectral_wavelengths(float u) {
    return SampledWavelengths::sample_visible(u, &RGBColorSpace::srgb());
}

// Trilinear interpolation of samples at voxel centres, zero outside, written as Σ value · Π tent weights.
template <class T, class F>
auto tent_interpolate(const std::vector<T>& v, int nx, int ny, int nz, double ux, double uy, double uz,
                      F convert) {
    using R = decltype(convert(v[0]));
    R sum = convert(v[0]) * 0.0f;
    auto tent = [](double x) { return std::max(0.0, 1 - std::abs(x)); };
    for (int z = 0; z < nz; ++z)
        for (int y = 0; y < ny; ++y)
            for (int x = 0; x < nx; ++x) {
                double w = tent(ux * nx - 0.5 - x) * tent(uy * ny - 0.5 - y) * tent(uz * nz - 0.5 - z);
                if (w > 0) sum = sum + convert(v[std::size_t((z * ny + y) * nx + x)]) * float(w);
            }
    return sum;
}

inline Transform test_transform() {
    return Transform::translate(Vector3f(0.4f, -1.2f, 2.0f)) *
           Transform::rotate(37, Vector3f(0.3f, 1, -0.5f)) * Transform::scale(1.5f, 0.8f, 1.2f);
}

} // namespace illum::test
