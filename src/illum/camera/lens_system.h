// A lens system of spherical surfaces and one plane stop, traced exactly: each surface is met by
// intersecting its sphere, the ray refracts by Snell's law in vector form (total internal reflection and
// every rim or stop it misses block it), as pbrt-v4's RealisticCamera does (PBR 4th ed. §5.3). The
// tracing runs in double: it costs little next to the scene's rays and keeps near-axis rays (thick-lens
// constants, paraxial tests) exact to far below a micrometre.
//
// Coordinates are camera space in metres: the film is the plane z = 0, +z points to the scene, the axis is
// x = y = 0; the rear surface's vertex sits at z = film_distance() and the front one at front_z().
// (pbrt-v4 traces in a "lens space" with z negated; nothing else differs.)
#pragma once

#include <memory>
#include <vector>

#include "illum/camera/cauchy_glass.h"
#include "illum/camera/lens_file.h"

namespace illum {

struct LensVec {
    double x = 0, y = 0, z = 0;
    LensVec operator+(LensVec b) const { return {x + b.x, y + b.y, z + b.z}; }
    LensVec operator-(LensVec b) const { return {x - b.x, y - b.y, z - b.z}; }
    LensVec operator*(double s) const { return {x * s, y * s, z * s}; }
    LensVec operator-() const { return {-x, -y, -z}; }
};
inline double dot(LensVec a, LensVec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
LensVec normalize(LensVec v);

struct LensRay {
    LensVec o, d;
    LensVec operator()(double t) const { return o + d * t; }
};

// How much a point of the stop transmits, at (u, v) = the point over the stop's radius, in [-1, 1]²
// (aperture_shape.h); a system without one has a circular stop.
class ApertureShape {
public:
    virtual ~ApertureShape() = default;
    virtual double transmission(double u, double v) const = 0;
};

struct LensInterface {
    double radius = 0;          // m; > 0: centre of curvature on the film side; 0: the aperture stop
    double thickness = 0;       // m, along the axis to the next surface towards the film (the last: to it)
    double aperture_radius = 0; // m
    double n_d = 1;             // the medium after the surface (towards the film) at the d line; 1: air
    CauchyGlass glass;          // its index at other wavelengths
    bool is_stop() const { return radius == 0; }
};

class LensSystem {
public:
    LensSystem() = default;
    explicit LensSystem(std::vector<LensInterface> interfaces,
                        std::shared_ptr<const ApertureShape> stop_shape = nullptr);
    // From a prescription in millimetres; stop_diameter_mm > 0 replaces the stop's diameter (the caller
    // clamps it to the file's, as pbrt-v4 does).
    static LensSystem from_prescription(const LensPrescription& lens, double stop_diameter_mm,
                                        std::shared_ptr<const ApertureShape> stop_shape = nullptr);

    const std::vector<LensInterface>& interfaces() const { return interfaces_; }
    double film_distance() const { return interfaces_.back().thickness; } // = the rear vertex's z
    void set_film_distance(double d);
    // The stop's shape (nullptr: circular). pbrt-v4 ignores the shape for the thick-lens rays; so does
    // RealisticCamera, which sets it after focusing.
    void set_stop_shape(std::shared_ptr<const ApertureShape> shape) { stop_shape_ = std::move(shape); }
    double front_z() const { return vertex_z_.front(); }
    double vertex_z(std::size_t i) const { return vertex_z_[i]; }
    double rear_aperture_radius() const { return interfaces_.back().aperture_radius; }
    bool dispersive() const;
    // The index of the medium after surface i (towards the film) at wavelength lambda_nm.
    double index_after(std::size_t i, double lambda_nm) const;

    // Traces a ray from the film side through every surface to the scene. Returns its weight (the stop's
    // transmission; 0 when blocked) and, when not blocked, the ray leaving the front surface (unit
    // direction) in *out.
    double trace_from_film(const LensRay& in, double lambda_nm, LensRay* out) const;
    // The same from the scene side to the film: *out leaves the rear surface.
    double trace_from_scene(const LensRay& in, double lambda_nm, LensRay* out) const;

private:
    // Meets surface i with ray r (unit direction), refracting from index n_from into n_to; false if blocked.
    bool cross(std::size_t i, double n_from, double n_to, LensRay* r, double* weight) const;

    std::vector<LensInterface> interfaces_;
    std::vector<double> vertex_z_; // vertex of surface i: the sum of thicknesses from i to the film
    std::shared_ptr<const ApertureShape> stop_shape_;
};

} // namespace illum
