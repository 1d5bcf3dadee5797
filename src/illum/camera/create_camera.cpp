#include "illum/camera/create_camera.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>

#include "illum/camera/aperture_shape.h"
#include "illum/camera/lens_file.h"
#include "illum/camera/realistic_camera.h"
#include "illum/camera/spherical_camera.h"
#include "illum/image/image_io.h"

namespace illum {

namespace {

// pbrt-v4's FilmBaseParameters: the crop window (NDC) if given, else the pixel bounds, else every pixel.
PixelBounds film_pixel_bounds(const ParamSet& ps, int width, int height) {
    std::vector<float> cw = ps.get_floats("cropwindow");
    std::vector<int> pb = ps.get_ints("pixelbounds");
    PixelBounds b = PixelBounds::full(width, height);
    if (!cw.empty()) {
        const SourceLocation& loc = ps.find("cropwindow")->loc;
        if (cw.size() != 4) throw Error(loc, fmt::format("\"cropwindow\" needs 4 values, not {}", cw.size()));
        for (float v : cw)
            if (!(v >= 0 && v <= 1))
                throw Error(loc, fmt::format("\"cropwindow\" value {} is outside [0, 1] (pixel coordinates "
                                             "go in \"pixelbounds\")",
                                             v));
        auto edge = [](int n, float t) { return int(std::ceil(float(n) * t)); }; // in float, as pbrt-v4
        b = {edge(width, std::min(cw[0], cw[1])), edge(height, std::min(cw[2], cw[3])),
             edge(width, std::max(cw[0], cw[1])), edge(height, std::max(cw[2], cw[3]))};
        if (b.empty())
            throw Error(loc, fmt::format("\"cropwindow\" [{} {} {} {}] keeps no pixel of the {}x{} film",
                                         cw[0], cw[1], cw[2], cw[3], width, height));
        return b;
    }
    if (!pb.empty()) {
        const SourceLocation& loc = ps.find("pixelbounds")->loc;
        if (pb.size() != 4)
            throw Error(loc, fmt::format("\"pixelbounds\" needs 4 values, not {}", pb.size()));
        b = {std::min(pb[0], pb[1]), std::min(pb[2], pb[3]), std::max(pb[0], pb[1]), std::max(pb[2], pb[3])};
        if (b.x0 < 0 || b.y0 < 0 || b.x1 > width || b.y1 > height)
            throw Error(loc, fmt::format("\"pixelbounds\" [{} {} {} {}] reach outside the {}x{} film", pb[0],
                                         pb[1], pb[2], pb[3], width, height));
        if (b.empty())
            throw Error(
                loc, fmt::format("\"pixelbounds\" [{} {} {} {}] keep no pixel", pb[0], pb[1], pb[2], pb[3]));
    }
    return b;
}

} // namespace

FilmSettings create_film(const EntityDesc& film, Diagnostics& diag) {
    if (film.type != "rgb" && film.type != "gbuffer" && film.type != "spectral")
        throw Error(film.loc, fmt::format("unknown film type \"{}\"", film.type));
    if (film.type != "rgb")
        diag.unsupported(film.loc, fmt::format("film \"{}\" is rendered as \"rgb\"", film.type));
    FilmSettings f;
    f.width = film.params.get_int("xresolution", 1280);
    f.height = film.params.get_int("yresolution", 720);
    if (f.width <= 0 || f.height <= 0 || f.width > 65536 || f.height > 65536)
        throw Error(film.loc, fmt::format("film resolution {}x{} is out of range", f.width, f.height));
    f.filename = film.params.get_string("filename", "");
    f.diagonal_mm = film.params.get_float("diagonal", 35);
    if (!(f.diagonal_mm > 0))
        throw Error(film.params.find("diagonal")->loc, "film diagonal must be positive");
    f.save_fp16 = film.params.get_bool("savefp16", true);
    f.pixel_bounds = film_pixel_bounds(film.params, f.width, f.height);
    return f;
}

std::unique_ptr<Filter> create_filter(const EntityDesc& f, Diagnostics& /*diag*/) {
    Vector2f radius{f.params.get_float("xradius", -1), f.params.get_float("yradius", -1)};
    if (f.type == "box" || f.type == "triangle" || f.type == "gaussian")
        return make_filter(f.type, radius, f.params.get_float("sigma", 0.5f));
    auto pick = [&](Vector2f def) {
        return Vector2f{radius.x > 0 ? radius.x : def.x, radius.y > 0 ? radius.y : def.y};
    };
    if (f.type == "mitchell")
        return std::make_unique<MitchellFilter>(pick({2, 2}), f.params.get_float("B", 1.0f / 3),
                                                f.params.get_float("C", 1.0f / 3));
    if (f.type == "sinc") {
        float tau = f.params.get_float("tau", 3);
        if (!(tau > 0)) throw Error(f.params.find("tau")->loc, "the sinc filter's tau must be positive");
        return std::make_unique<LanczosSincFilter>(pick({4, 4}), tau);
    }
    throw Error(f.loc, fmt::format("unknown pixel filter \"{}\"", f.type));
}

namespace {

bool readable(const std::string& path, const Param& p, Diagnostics& diag, const char* what) {
    if (std::ifstream(path)) return true;
    diag.missing_file(p.loc, fmt::format("cannot read {} \"{}\": {}", what, path, std::strerror(errno)));
    return false;
}

// pbrt-v4's RealisticCamera::Create: lensfile, aperturediameter [mm], focusdistance [m], aperture.
std::unique_ptr<Camera> realistic_camera(const CameraDesc& c, const FilmSettings& film, Diagnostics& diag) {
    const Transform world_from_camera = c.camera_from_world.inverse();
    const ParamSet& ps = c.params;
    const Param* lens_param = ps.find("lensfile");
    std::string lens_file = ps.get_string("lensfile", "");
    if (lens_file.empty()) throw Error(c.loc, "realistic camera needs \"string lensfile\"");
    float aperture_mm = ps.get_float("aperturediameter", 1.0f);
    float focus = ps.get_float("focusdistance", 10.0f);
    if (!(aperture_mm > 0))
        throw Error(ps.find("aperturediameter")->loc, "aperturediameter must be positive");
    if (!(focus > 0)) throw Error(ps.find("focusdistance")->loc, "focusdistance must be positive");
    std::string aperture = ps.get_string("aperture", "");

    bool ok = readable(lens_file, *lens_param, diag, "lens file");
    std::shared_ptr<const ApertureShape> shape;
    if (!aperture.empty() && aperture != "circular") {
        shape = builtin_aperture(aperture);
        if (!shape) {
            const Param& ap = *ps.find("aperture");
            if (readable(aperture, ap, diag, "aperture image")) {
                try {
                    shape = image_aperture(read_image(aperture));
                } catch (const Error& e) {
                    throw Error(ap.loc, e.message());
                }
            } else {
                ok = false;
            }
        }
    }
    // A stand-in while the build collects every missing file; it never renders.
    if (!ok) return std::make_unique<PerspectiveCamera>(world_from_camera, film.width, film.height, 90.0f);

    LensPrescription lens = read_lens_file(lens_file); // its errors name the lens file's line
    double file_stop_mm = 0;
    for (const LensSurfaceSpec& s : lens.surfaces)
        if (s.is_stop()) file_stop_mm = s.aperture_mm;
    double stop_mm = aperture_mm;
    if (file_stop_mm > 0 && stop_mm > file_stop_mm) {
        diag.unsupported(ps.find("aperturediameter")->loc,
                         fmt::format("aperturediameter {} mm exceeds the lens file's stop, {} mm: clamped",
                                     stop_mm, file_stop_mm));
        stop_mm = file_stop_mm;
    }
    RealisticCamera::Settings settings;
    settings.focus_distance = focus;
    settings.film_diagonal = film.diagonal_mm * 1e-3;
    try {
        return std::make_unique<RealisticCamera>(world_from_camera, film.width, film.height,
                                                 LensSystem::from_prescription(lens, stop_mm), shape,
                                                 settings);
    } catch (const Error& e) {
        throw Error(c.loc, e.message());
    }
}

} // namespace

namespace {

std::unique_ptr<Camera> camera_of_type(const CameraDesc& c, const FilmSettings& film, Diagnostics& diag) {
    if (c.type == "realistic") return realistic_camera(c, film, diag);
    int w = film.width, h = film.height;
    Transform world_from_camera = c.camera_from_world.inverse();
    float lens_radius = c.params.get_float("lensradius", 0);
    float focal_distance = c.params.get_float("focaldistance", 1e6f);
    if (lens_radius < 0) throw Error(c.loc, "camera lensradius must be non-negative");
    if (!(focal_distance > 0)) throw Error(c.loc, "camera focaldistance must be positive");
    Screen screen = PerspectiveCamera::default_screen(w, h);
    float frame = c.params.get_float("frameaspectratio", 0);
    if (frame > 0) screen = frame > 1 ? Screen{-frame, frame, -1, 1} : Screen{-1, 1, -1 / frame, 1 / frame};
    auto sw = c.params.get_floats("screenwindow");
    if (!sw.empty()) {
        if (sw.size() != 4) throw Error(c.params.find("screenwindow")->loc, "screenwindow needs 4 values");
        screen = {sw[0], sw[1], sw[2], sw[3]};
    }
    if (c.type == "perspective" || c.type.empty()) {
        float fov = c.params.get_float("fov", 90);
        if (!(fov > 0 && fov < 180)) throw Error(c.loc, fmt::format("camera fov {} is out of (0, 180)", fov));
        return std::make_unique<PerspectiveCamera>(world_from_camera, w, h, fov, lens_radius, focal_distance,
                                                   &screen);
    }
    if (c.type == "orthographic")
        return std::make_unique<OrthographicCamera>(world_from_camera, w, h, lens_radius, focal_distance,
                                                    &screen);
    if (c.type == "spherical") {
        // pbrt-v4 reads the projective parameters above for this camera too and ignores them.
        std::string m = c.params.get_string("mapping", "equalarea");
        std::optional<SphericalMapping> mapping = spherical_mapping_from_string(m);
        if (!mapping)
            throw Error(
                c.params.find("mapping")->loc,
                fmt::format("unknown spherical camera mapping \"{}\" (use equalarea or equirectangular)", m));
        return std::make_unique<SphericalCamera>(world_from_camera, w, h, *mapping);
    }
    throw Error(c.loc, fmt::format("unknown camera type \"{}\"", c.type));
}

} // namespace

std::unique_ptr<Camera> create_camera(const CameraDesc& c, const FilmSettings& film, Diagnostics& diag) {
    std::unique_ptr<Camera> camera = camera_of_type(c, film, diag);
    camera->init_differentials(c.camera_from_world.inverse(), film.width, film.height);
    return camera;
}

} // namespace illum
