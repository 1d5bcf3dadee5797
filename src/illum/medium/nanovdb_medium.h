// pbrt-v4's "nanovdb" medium (NanoVDBMedium; pbrt-v4 media.h/.cpp): a sparse float grid named "density"
// (pbrt-v4's "gridname") read from a NanoVDB file (Museth 2021, "NanoVDB: A GPU-Friendly and Portable
// VDB Data Structure For Real-Time Rendering And Simulation"), trilinearly interpolated in the grid's index
// space (values at integer index points; nanovdb's SampleFromVoxels of order 1) and scaling σ_a and σ_s; an
// optional float grid "temperature" ("temperaturename") gives the emission
// Lescale · B((T - temperatureoffset) · temperaturescale), B pbrt-v4's peak-normalised blackbody, black at
// or below 100 K. The grids' world space is medium space. The bounds are the grids' world bounding boxes
// (their union), and the majorant grid is 64^3 there, as pbrt-v4's. Each majorant voxel holds the largest
// density among the samples that can influence a point in it (pbrt-v4 pads by a voxel on either side and
// converts two corners; here the voxel's eight corners go to index space, which also holds for a rotated
// index-to-world map, and the samples from floor(lo) to floor(hi) + 1 are read, with the background value
// when that range leaves the grid's active box).
#pragma once

#include <memory>
#include <string>

#include "illum/medium/medium.h"
#include "illum/medium/medium_box.h"
#include "illum/medium/medium_spectrum.h"

namespace illum {

struct NanoVDBGrids; // the loaded grids (nanovdb types stay in nanovdb_medium.cpp)

struct NanoVDBParams {
    Transform world_from_medium;
    std::shared_ptr<const NanoVDBGrids> grids;
    MediumSpectrum sigma_a, sigma_s; // already times "scale"
    float g = 0;
    float le_scale = 1, temperature_offset = 0, temperature_scale = 1;
};

// The result of reading a file: the grids, or the message of why not.
struct NanoVDBLoad {
    std::shared_ptr<const NanoVDBGrids> grids;
    std::string error;
};
// Reads grid `density_name` and, when the file has one, `temperature_name`; each must be a float grid of
// class fog volume or unknown (as pbrt-v4 requires), pass nanovdb's validation (magic, checksum, tree),
// and the density must be non-empty with finite, non-negative values (the temperature finite). Builds the
// majorant grid.
NanoVDBLoad load_nanovdb(const std::string& filename, const std::string& density_name,
                         const std::string& temperature_name);

class NanoVDBMedium final : public Medium {
public:
    explicit NanoVDBMedium(NanoVDBParams p);

    bool is_emissive() const override;
    MediumProperties sample_point(Point3f p, const SampledWavelengths& lambda) const override;
    MajorantIterator sample_ray(const Ray& ray, float tmax, const SampledWavelengths& lambda) const override;

    const MajorantGrid& majorant_grid() const;
    const MediumBox& box() const { return box_; }
    std::size_t bytes() const;

private:
    NanoVDBParams p_;
    MediumBox box_;
};

} // namespace illum
