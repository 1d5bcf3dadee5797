#include "illum/camera/create_camera.h"

#include <fmt/format.h>

namespace illum {

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
    return f;
}

std::unique_ptr<Filter> create_filter(const EntityDesc& f, Diagnostics& diag) {
    Vector2f radius{f.params.get_float("xradius", -1), f.params.get_float("yradius", -1)};
    if (f.type == "box" || f.type == "triangle" || f.type == "gaussian")
        return make_filter(f.type, radius, f.params.get_float("sigma", 0.5f));
    if (f.type == "mitchell" || f.type == "sinc") {
        diag.unsupported(f.loc, fmt::format("pixel filter \"{}\" is approximated by a gaussian", f.type));
        return make_filter("gaussian", {1.5f, 1.5f});
    }
    throw Error(f.loc, fmt::format("unknown pixel filter \"{}\"", f.type));
}

std::unique_ptr<Camera> create_camera(const CameraDesc& c, const FilmSettings& film, Diagnostics& diag) {
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
    if (c.type == "realistic" || c.type == "spherical") {
        diag.unsupported(c.loc, fmt::format("camera \"{}\" is approximated by a perspective camera", c.type));
        return std::make_unique<PerspectiveCamera>(world_from_camera, w, h, 90.0f);
    }
    throw Error(c.loc, fmt::format("unknown camera type \"{}\"", c.type));
}

} // namespace illum
