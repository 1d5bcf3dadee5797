#include "illum/medium/nanovdb_medium.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fmt/format.h>
#include <fstream>
#include <optional>
#include <tbb/parallel_for.h>

#include <iostream> // nanovdb/util/GridValidator.h uses std::cerr without including it
#include <nanovdb/NanoVDB.h>
#include <nanovdb/util/GridValidator.h>
#include <nanovdb/util/IO.h>
#include <nanovdb/util/SampleFromVoxels.h>

#include "illum/medium/blackbody_emission.h"

namespace illum {

struct NanoVDBGrids {
    nanovdb::GridHandle<nanovdb::HostBuffer> density_handle, temperature_handle;
    const nanovdb::FloatGrid* density = nullptr;
    const nanovdb::FloatGrid* temperature = nullptr;
    Bounds3f bounds; // medium space: the union of the grids' world boxes
    MajorantGrid majorant;
};

namespace {

using Handle = nanovdb::GridHandle<nanovdb::HostBuffer>;
using Sampler = nanovdb::SampleFromVoxels<nanovdb::FloatGrid::TreeType, 1, false>;

Bounds3f world_bounds(const nanovdb::FloatGrid& g) {
    const auto& b = g.worldBBox();
    Bounds3f r;
    r.lo = Point3f(float(b.min()[0]), float(b.min()[1]), float(b.min()[2]));
    r.hi = Point3f(float(b.max()[0]), float(b.max()[1]), float(b.max()[2]));
    return r;
}

// One named grid of the file, checked; `error` says why not (empty handle and no error: not in the file).
const nanovdb::FloatGrid* read_float_grid(const std::string& filename, const std::string& name,
                                          Handle* handle, std::string* error) {
    std::ifstream is(filename, std::ios::in | std::ios::binary);
    if (!is) {
        *error = fmt::format("cannot read NanoVDB file \"{}\": {}", filename, std::strerror(errno));
        return nullptr;
    }
    try {
        *handle = nanovdb::io::readGrid<nanovdb::HostBuffer>(is, name);
    } catch (const std::exception& e) {
        *error = fmt::format("cannot read NanoVDB file \"{}\": {}", filename, e.what());
        return nullptr;
    }
    if (!*handle) return nullptr;
    // nanovdb does not check its reads: a short one leaves the buffer partly unwritten.
    if (!is) {
        *error = fmt::format("NanoVDB file \"{}\" is truncated (grid \"{}\")", filename, name);
        *handle = Handle();
        return nullptr;
    }
    const nanovdb::FloatGrid* g = handle->grid<float>();
    if (!g) {
        *error = fmt::format("\"{}\": grid \"{}\" is not a float grid", filename, name);
        return nullptr;
    }
    if (!nanovdb::isValid(*g, true, false)) {
        *error = fmt::format("\"{}\": grid \"{}\" is corrupt (nanovdb's validation fails)", filename, name);
        return nullptr;
    }
    if (!g->isFogVolume() && !g->isUnknown()) {
        *error = fmt::format("\"{}\": grid \"{}\" is not a fog volume", filename, name);
        return nullptr;
    }
    return g;
}

// The largest value of the samples that influence trilinear lookups inside world box wb, and whether any
// of them is negative or NaN (bad; temperature grids only check for NaN).
float region_max(const nanovdb::FloatGrid& g, const Bounds3f& wb, bool* bad, bool allow_negative) {
    nanovdb::Vec3d lo(INFINITY), hi(-INFINITY);
    for (int c = 0; c < 8; ++c) {
        nanovdb::Vec3d w((c & 1) ? wb.hi.x : wb.lo.x, (c & 2) ? wb.hi.y : wb.lo.y,
                         (c & 4) ? wb.hi.z : wb.lo.z);
        nanovdb::Vec3d i = g.worldToIndex(w);
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], i[a]);
            hi[a] = std::max(hi[a], i[a]);
        }
    }
    const auto& box = g.indexBBox();
    int l[3], h[3];
    bool outside = false;
    for (int a = 0; a < 3; ++a) {
        // Samples beyond one voxel below or two above the active box cannot reach the world box.
        double fl = std::floor(lo[a]), fh = std::floor(hi[a]) + 1;
        double cl = std::max(fl, double(box.min()[a]) - 1), ch = std::min(fh, double(box.max()[a]) + 2);
        outside = outside || fl < cl || fh > ch;
        l[a] = int(cl);
        h[a] = int(ch);
    }
    float m = outside ? std::max(0.0f, g.tree().background()) : 0.0f;
    auto acc = g.getAccessor();
    for (int z = l[2]; z <= h[2]; ++z)
        for (int y = l[1]; y <= h[1]; ++y)
            for (int x = l[0]; x <= h[0]; ++x) {
                float v = acc.getValue(nanovdb::Coord(x, y, z));
                if (std::isnan(v) || std::isinf(v) || (!allow_negative && v < 0)) *bad = true;
                m = std::max(m, v);
            }
    return m;
}

} // namespace

NanoVDBLoad load_nanovdb(const std::string& filename, const std::string& density_name,
                         const std::string& temperature_name) {
    auto grids = std::make_shared<NanoVDBGrids>();
    NanoVDBLoad r;
    grids->density = read_float_grid(filename, density_name, &grids->density_handle, &r.error);
    if (!r.error.empty()) return r;
    if (!grids->density) {
        r.error = fmt::format("\"{}\" has no grid named \"{}\"", filename, density_name);
        return r;
    }
    if (grids->density->activeVoxelCount() == 0) {
        r.error = fmt::format("\"{}\": grid \"{}\" has no active voxels", filename, density_name);
        return r;
    }
    grids->temperature = read_float_grid(filename, temperature_name, &grids->temperature_handle, &r.error);
    if (!r.error.empty()) return r;
    grids->bounds = world_bounds(*grids->density);
    if (grids->temperature && grids->temperature->activeVoxelCount() > 0)
        grids->bounds.extend(world_bounds(*grids->temperature));
    Vector3f diag = grids->bounds.diagonal();
    if (!(diag.x > 0 && diag.y > 0 && diag.z > 0 && std::isfinite(diag.x + diag.y + diag.z))) {
        r.error = fmt::format("\"{}\": grid \"{}\" has degenerate bounds", filename, density_name);
        return r;
    }

    // The majorant grid over the bounds, and the value checks on the way (every sample of the density's
    // active box is read by some voxel).
    grids->majorant = MajorantGrid({64, 64, 64});
    std::atomic<bool> bad{false};
    const Bounds3f& b = grids->bounds;
    tbb::parallel_for(0, 64, [&](int z) {
        bool local_bad = false;
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x) {
                Bounds3f u = grids->majorant.voxel_bounds(x, y, z), wb;
                wb.lo = b.lo + Vector3f(u.lo.x * diag.x, u.lo.y * diag.y, u.lo.z * diag.z);
                wb.hi = b.lo + Vector3f(u.hi.x * diag.x, u.hi.y * diag.y, u.hi.z * diag.z);
                grids->majorant.at(x, y, z) = region_max(*grids->density, wb, &local_bad, false);
            }
        if (local_bad) bad = true;
    });
    if (bad) {
        r.error =
            fmt::format("\"{}\": grid \"{}\" has negative or non-finite values", filename, density_name);
        return r;
    }
    if (grids->temperature && grids->temperature->activeVoxelCount() > 0) {
        bool tbad = false;
        Bounds3f whole = world_bounds(*grids->temperature);
        region_max(*grids->temperature, whole, &tbad, true);
        if (tbad) {
            r.error = fmt::format("\"{}\": grid \"{}\" has non-finite values", filename, temperature_name);
            return r;
        }
    }
    r.grids = std::move(grids);
    return r;
}

NanoVDBMedium::NanoVDBMedium(NanoVDBParams p)
    : p_(std::move(p)), box_(p_.world_from_medium, p_.grids->bounds) {}

const MajorantGrid& NanoVDBMedium::majorant_grid() const { return p_.grids->majorant; }

bool NanoVDBMedium::is_emissive() const { return p_.grids->temperature && p_.le_scale > 0; }

std::size_t NanoVDBMedium::bytes() const {
    std::size_t b = p_.grids->density_handle.size() + p_.grids->majorant.bytes();
    if (p_.grids->temperature) b += p_.grids->temperature_handle.size() + blackbody_table_bytes();
    return b;
}

MediumProperties NanoVDBMedium::sample_point(Point3f p, const SampledWavelengths& lambda) const {
    Point3f m = box_.medium_point(p);
    nanovdb::Vec3f pm(m.x, m.y, m.z);
    const NanoVDBGrids& g = *p_.grids;
    float d = Sampler(g.density->tree())(g.density->worldToIndexF(pm));
    MediumProperties mp{p_.sigma_a.at(lambda) * d, p_.sigma_s.at(lambda) * d, HenyeyGreenstein{p_.g},
                        SampledSpectrum(0.0f)};
    if (g.temperature && p_.le_scale > 0) {
        float t = Sampler(g.temperature->tree())(g.temperature->worldToIndexF(pm));
        t = (t - p_.temperature_offset) * p_.temperature_scale;
        mp.le = blackbody_emission(t, lambda) * p_.le_scale;
    }
    return mp;
}

MajorantIterator NanoVDBMedium::sample_ray(const Ray& ray, float tmax,
                                           const SampledWavelengths& lambda) const {
    Point3f o;
    Vector3f d;
    float t0, t1;
    if (!box_.clip(ray, tmax, &o, &d, &t0, &t1)) return {};
    return MajorantIterator::dda(&p_.grids->majorant, o, d, t0, t1,
                                 p_.sigma_a.at(lambda) + p_.sigma_s.at(lambda));
}

} // namespace illum
