// Bounds of the exit pupil, the part of the rear element's plane through which light from a film point
// passes the whole lens system, tabulated over the distance from the film centre, and sampling of camera
// rays within them (pbrt-v4's RealisticCamera::BoundExitPupil and SampleExitPupil, PBR 4th ed. §5.3).
//
// For film radii in [r0, r1] (one bin), rays from film points (x, 0, 0), x in [r0, r1], towards points of
// the square of 1.5 rear radii around the axis in the plane z = film distance are traced; the box of the
// targets that pass, grown by twice the sample spacing (so a thin sliver missed between samples is
// inside), bounds the pupil for every point of the bin. A film point at angle φ uses its bin's box rotated
// by φ (the system is rotationally symmetric). For a dispersive lens the boxes are the union over the
// wavelengths given; the first (the d line) is traced for every target, the others only near its box
// (exit_pupil.cpp). Sampling is uniform in the box: pdf = 1 / area.
#pragma once

#include <optional>
#include <vector>

#include "illum/camera/lens_system.h"
#include "illum/math/vector.h"

namespace illum {

struct PupilBounds {
    double x0 = 1, y0 = 1, x1 = -1, y1 = -1; // empty when x0 > x1
    bool empty() const { return x0 > x1 || y0 > y1; }
    double area() const { return empty() ? 0 : (x1 - x0) * (y1 - y0); }
    bool contains(double x, double y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
    void extend(double x, double y);
};

struct PupilSample {
    LensVec p;  // on the plane z = film distance
    double pdf; // per unit area of that plane
};

class ExitPupil {
public:
    ExitPupil() = default;
    // bins film-radius intervals over [0, film_radius] with `samples` rays each, at every wavelength.
    ExitPupil(const LensSystem& lens, double film_radius, int bins, int samples,
              const std::vector<double>& lambdas);

    int bins() const { return int(bounds_.size()); }
    const PupilBounds& bounds(int bin) const { return bounds_[bin]; }
    int bin_of(double film_r) const;
    // A point of the pupil bounds of the film point (x, y, 0) for the uniform sample u; nullopt where no
    // light reaches the film.
    std::optional<PupilSample> sample(double x, double y, Point2f u) const;

private:
    std::vector<PupilBounds> bounds_;
    double film_radius_ = 0, rear_z_ = 0;
};

} // namespace illum
