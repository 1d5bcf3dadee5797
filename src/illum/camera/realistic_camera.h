// pbrt-v4's "realistic" camera (PBR 4th ed. §5.3; cameras.cpp, RealisticCamera; after Kolb, Mitchell &
// Hanrahan, "A Realistic Camera Model for Computer Graphics", SIGGRAPH 1995): camera rays start on the
// film, go to a point of the exit pupil's bounds and are traced through the lens system's real surfaces
// (lens_system.h); the lens is focused by moving the film with the thick-lens approximation
// (thick_lens.h). illum's addition: each glass's index varies with wavelength (cauchy_glass.h), so the
// ray depends on the wavelength asked for and a spectral render shows lateral and longitudinal colour
// (in RGB mode every ray is traced at the d line, so the image is the lens's at 587.56 nm).
//
// Film: the film's diagonal d (pbrt-v4's "diagonal", mm) with the image's aspect a = height / width gives
// a sensor of width d / sqrt(1 + a²) and height a times that, centred on the axis at z = 0. A raster point
// maps to (-x, y) of that rectangle (x and y from its lower left corner): the lens inverts the image, so
// the picture comes out upright, raster +x to the right (camera +x) and raster +y down.
//
// Weight (the camera measurement equation, PBR 4th ed. §5.4.1, eq. 5.3): the irradiance at a film point
// is E = (1 / z²) ∫ L cos⁴θ dA over the plane of the rear vertex, at axial distance z from the film, θ the
// angle of the ray to the axis. Sampling that plane uniformly in the pupil box (pdf = 1 / A) gives the
// weight L-multiplier w = cos⁴θ A / z². So the image is irradiance (W m^-2), not radiance like the other
// cameras: an f/N lens at infinity focus gives w ≈ π / (4 N²) at the centre (about 0.2 at f/2, 3e-4 at
// the default 1 mm stop of a 50 mm lens), and images are darker than a pinhole's by that much; pbrt-v4
// leaves that to the sensor's exposure (its PixelSensor imaging ratio), illum to `--exposure`. The 1/z²
// is exact for the plane where the pupil is sampled, which is why that plane is the rear vertex's.
#pragma once

#include <memory>
#include <optional>

#include "illum/camera/camera.h"
#include "illum/camera/exit_pupil.h"
#include "illum/camera/lens_system.h"
#include "illum/camera/thick_lens.h"

namespace illum {

class RealisticCamera final : public Camera {
public:
    struct Settings {
        double focus_distance = 10;   // m, from the film to the plane in focus
        double film_diagonal = 0.035; // m
        int pupil_bins = 64;          // film-radius intervals of the exit-pupil table
        int pupil_samples = 1 << 16;  // rays per interval (pbrt-v4: 2^20)
    };
    // `lens` has the stop diameter wanted; `shape` is the stop's (nullptr: circular). Scene units are
    // metres. Throws illum::Error when no paraxial ray passes, the lens does not converge, or the focus
    // distance is too short for it.
    RealisticCamera(const Transform& world_from_camera, int width, int height, LensSystem lens,
                    std::shared_ptr<const ApertureShape> shape, const Settings& settings);

    std::optional<CameraRay> generate_ray(Point2f p_raster, Point2f u_lens, float lambda_nm) const override;
    bool is_dispersive() const override { return lens_.dispersive(); }

    const LensSystem& lens() const { return lens_; }
    // At the d line, with the film where the lens file put it (before focusing).
    const CardinalPoints& cardinal_points() const { return cardinal_; }
    const ExitPupil& exit_pupil() const { return pupil_; }
    double film_width() const { return film_w_; }
    double film_height() const { return film_h_; }
    // The camera-space point (z = 0) of a raster position, and the raster position of a film point.
    LensVec film_point(Point2f p_raster) const;
    Point2f raster_point(double x, double y) const;

private:
    Transform world_from_camera_;
    int width_, height_;
    LensSystem lens_;
    CardinalPoints cardinal_;
    ExitPupil pupil_;
    double film_w_, film_h_;
};

} // namespace illum
