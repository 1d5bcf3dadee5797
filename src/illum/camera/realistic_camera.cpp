#include "illum/camera/realistic_camera.h"

#include <cmath>
#include <fmt/format.h>

#include "illum/util/error.h"

namespace illum {

RealisticCamera::RealisticCamera(const Transform& world_from_camera, int width, int height, LensSystem lens,
                                 std::shared_ptr<const ApertureShape> shape, const Settings& s)
    : world_from_camera_(world_from_camera), width_(width), height_(height), lens_(std::move(lens)) {
    double aspect = double(height) / width;
    film_w_ = s.film_diagonal / std::sqrt(1 + aspect * aspect);
    film_h_ = aspect * film_w_;

    // Focus at the d line, the wavelength the prescription's n_d is for, with the circular stop (pbrt-v4
    // leaves the aperture image out of the thick-lens rays too).
    std::optional<CardinalPoints> cp = trace_cardinal_points(lens_, kLambdaD, paraxial_height(lens_));
    if (!cp) throw Error("realistic camera: no paraxial ray passes the lens system (is the stop closed?)");
    if (!(cp->efl() > 0))
        throw Error(fmt::format("realistic camera: the lens system does not converge (focal length {} mm)",
                                cp->efl() * 1e3));
    cardinal_ = *cp;
    std::optional<double> film = thick_lens_film_distance(lens_, cardinal_, s.focus_distance);
    if (!film)
        throw Error(fmt::format("realistic camera: focus distance {} m is too short for a {:.4g} mm lens",
                                s.focus_distance, cardinal_.efl() * 1e3));
    lens_.set_film_distance(*film);
    lens_.set_stop_shape(std::move(shape));

    std::vector<double> lambdas{kLambdaD};
    if (lens_.dispersive()) lambdas = {360.0, kLambdaD, 830.0}; // the spectral mode's range
    pupil_ = ExitPupil(lens_, s.film_diagonal / 2, s.pupil_bins, s.pupil_samples, lambdas);
}

LensVec RealisticCamera::film_point(Point2f p) const {
    double x = (double(p.x) / width_ - 0.5) * film_w_, y = (double(p.y) / height_ - 0.5) * film_h_;
    return {-x, y, 0};
}

Point2f RealisticCamera::raster_point(double x, double y) const {
    return {float((-x / film_w_ + 0.5) * width_), float((y / film_h_ + 0.5) * height_)};
}

std::optional<CameraRay> RealisticCamera::generate_ray(Point2f p_raster, Point2f u_lens,
                                                       float lambda_nm) const {
    LensVec pf = film_point(p_raster);
    std::optional<PupilSample> ps = pupil_.sample(pf.x, pf.y, u_lens);
    if (!ps) return std::nullopt;
    LensRay r_film{pf, ps->p - pf}, out;
    double w = lens_.trace_from_film(r_film, lambda_nm, &out);
    if (w == 0) return std::nullopt;
    // w = cos⁴θ A / z² (the camera measurement equation; see the header).
    double cos_theta = normalize(r_film.d).z, z = lens_.film_distance();
    w *= (cos_theta * cos_theta) * (cos_theta * cos_theta) / (ps->pdf * z * z);
    Point3f o = world_from_camera_(Point3f(float(out.o.x), float(out.o.y), float(out.o.z)));
    Vector3f d = normalize(world_from_camera_(Vector3f(float(out.d.x), float(out.d.y), float(out.d.z))));
    return CameraRay{{o, d, kInfinity}, float(w)};
}

} // namespace illum
