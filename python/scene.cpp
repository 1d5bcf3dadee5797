// illum.load, illum.cornell_box and illum.Scene.render: what `illum render` does (load_scene_desc,
// set_film_resolution, build_scene, make_integrator, render with RenderOptions), through the library, with
// the image handed to NumPy without a copy.
#include <climits>
#include <cmath>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/core.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.h"
#include "illum/render/renderer.h"
#include "illum/scene/build.h"
#include "illum/scene/load.h"

namespace illum::python {

namespace {

using Resolution = std::pair<int, int>;

// A loaded scene: its description, kept so that a render at another resolution can rebuild it, and the
// scene last built (at the file's resolution until a render asks for another). Renders may run from several
// Python threads at once (the GIL is released): the built scene is swapped under a mutex and each render
// holds its own reference to the one it renders; what the properties read is copied once, at load.
class PyScene {
public:
    PyScene(SceneDesc desc, bool strict) : desc_(std::move(desc)), strict_(strict) {
        built_ = build(desc_);
        native_ = {built_->width, built_->height};
        built_resolution_ = native_;
        request_ = built_->request;
        warnings_ = built_->warnings;
    }

    // The scene built at `resolution` (the file's when none): the one built last if it matches, else a
    // new one. Called with the GIL released.
    std::shared_ptr<const Scene> at(std::optional<Resolution> resolution) {
        Resolution want = resolution.value_or(native_);
        {
            std::lock_guard lock(mutex_);
            if (want == built_resolution_) return built_;
        }
        SceneDesc desc = desc_;
        desc.set_film_resolution(want.first, want.second);
        std::shared_ptr<const Scene> scene = build(desc);
        std::lock_guard lock(mutex_);
        built_ = scene;
        built_resolution_ = want;
        return scene;
    }

    const SceneDesc& desc() const { return desc_; }
    Resolution native() const { return native_; }
    // The scene file's integrator, spp, max depth and sampler: what a render uses unless told otherwise.
    const RenderRequest& request() const { return request_; }
    // The parser's and the builder's warnings.
    const std::vector<std::string>& warnings() const { return warnings_; }

private:
    std::shared_ptr<const Scene> build(const SceneDesc& desc) const {
        BuildOptions options;
        options.strict = strict_;
        return build_scene(desc, options);
    }

    const SceneDesc desc_;
    const bool strict_;
    Resolution native_;
    RenderRequest request_;
    std::vector<std::string> warnings_;
    std::mutex mutex_;
    std::shared_ptr<const Scene> built_; // guarded by mutex_
    Resolution built_resolution_;        // guarded by mutex_
};

std::unique_ptr<PyScene> load_scene(const std::string& path, bool strict) {
    std::unique_ptr<PyScene> scene;
    {
        py::gil_scoped_release unlocked;
        scene = std::make_unique<PyScene>(load_scene_desc(path, strict), strict);
    }
    warn_all(scene->warnings()); // what the CLI prints as `warning: ...`
    return scene;
}

std::optional<Resolution> parse_resolution(const py::object& value) {
    if (value.is_none()) return std::nullopt;
    const char* expected = "(width, height) with two positive whole numbers";
    if (!py::isinstance<py::sequence>(value) || py::isinstance<py::str>(value) || py::len(value) != 2)
        throw py::value_error(
            fmt::format("resolution must be {}, not {}", expected, std::string(py::repr(value))));
    py::sequence s = value;
    return Resolution{int(whole_number(s[0], "resolution's width", 1, INT_MAX, "a positive whole number")),
                      int(whole_number(s[1], "resolution's height", 1, INT_MAX, "a positive whole number"))};
}

py::object render_scene(PyScene& self, const py::object& spp, const py::object& resolution,
                        const py::object& seed, const py::object& threads,
                        std::optional<std::string> integrator, const py::object& max_depth,
                        std::optional<std::string> sampler, bool spectral, std::optional<double> time,
                        bool adaptive, double adaptive_threshold, bool progress, bool stats) {
    // Every argument is checked before anything is built or rendered.
    const RenderRequest& request = self.request();
    RenderOptions options;
    options.spp =
        spp.is_none() ? request.spp : int(whole_number(spp, "spp", 1, INT_MAX, "a positive whole number"));
    options.seed = seed.is_none() ? request.scene_seed() : seed_value(seed, "seed");
    options.threads =
        threads.is_none() ? 0 : int(whole_number(threads, "threads", 1, 1 << 16, "a positive whole number"));
    if (time && !(*time > 0 && std::isfinite(*time)))
        throw py::value_error(fmt::format("time must be a positive number of seconds, not {}", *time));
    options.time_budget = time.value_or(0);
    options.sampler = sampler.value_or(request.sampler);
    options.sampler_settings = request.sampler_settings;
    options.spectral = spectral;
    if (!(adaptive_threshold >= 0 && std::isfinite(adaptive_threshold)))
        throw py::value_error(
            fmt::format("adaptive_threshold must be a non-negative number, not {}", adaptive_threshold));
    options.adaptive.enabled = adaptive || adaptive_threshold > 0;
    options.adaptive.threshold = adaptive_threshold;
    options.quiet = !progress;
    int depth = max_depth.is_none() ? request.max_depth
                                    : int(whole_number(max_depth, "max_depth", -1, 100000,
                                                       "a whole number in [-1, 100000] (-1: unlimited)"));
    std::string integrator_name = integrator.value_or(request.integrator);
    std::optional<Resolution> res = parse_resolution(resolution);

    RenderResult result;
    {
        py::gil_scoped_release unlocked;
        std::shared_ptr<const Scene> scene = self.at(res);
        auto estimator = make_integrator(integrator_name, *scene, depth);
        result = render(*scene, *estimator, options);
    }
    if (result.nonfinite_samples > 0)
        warn_all({fmt::format("{} samples were NaN, infinite or negative and were dropped",
                              result.nonfinite_samples)});
    py::dict figures;
    if (stats) {
        figures["integrator"] = integrator_name;
        figures["spp"] = result.spp;
        figures["samples"] = result.samples;
        figures["rays"] = result.rays;
        figures["seconds"] = result.seconds;
        figures["threads"] = result.threads;
        figures["seed"] = options.seed;
        figures["nonfinite_samples"] = result.nonfinite_samples;
        figures["mode"] = spectral ? "spectral" : "rgb";
        if (result.adaptive) {
            py::dict a;
            a["min_spp"] = result.adaptive->min_spp;
            a["max_spp"] = result.adaptive->max_spp;
            a["rounds"] = result.adaptive->rounds;
            a["level"] = result.adaptive->level;
            figures["adaptive"] = a;
        }
    }
    py::array_t<float> image = image_to_array(std::move(result.image));
    if (stats) return py::make_tuple(image, figures);
    return image;
}

} // namespace

void bind_scene(py::module_& m) {
    py::class_<PyScene>(m, "Scene",
                        "A scene loaded by illum.load or illum.cornell_box and built (geometry, lights, "
                        "camera), ready to render. A render at another resolution rebuilds it.")
        .def_property_readonly(
            "file", [](const PyScene& s) { return s.desc().filename; },
            "The scene file (\"<built-in cornell-box>\" for the built-in scene)")
        .def_property_readonly(
            "resolution", [](const PyScene& s) { return s.native(); }, "The film's (width, height)")
        .def_property_readonly(
            "spp", [](const PyScene& s) { return s.request().spp; }, "The scene's samples per pixel")
        .def_property_readonly(
            "integrator", [](const PyScene& s) { return s.request().integrator; }, "The scene's integrator")
        .def_property_readonly(
            "max_depth", [](const PyScene& s) { return s.request().max_depth; },
            "The scene's maximum number of scattering events (-1: unlimited)")
        .def_property_readonly(
            "sampler", [](const PyScene& s) { return s.request().sampler; }, "The scene's sampler")
        .def_property_readonly(
            "warnings", [](const PyScene& s) { return s.warnings(); },
            "The warnings of loading and building it (also issued as Python warnings by load)")
        .def("__repr__",
             [](const PyScene& s) {
                 auto [w, h] = s.native();
                 const std::string& file = s.desc().filename;
                 return fmt::format("<illum.Scene {} {}x{}, {} spp, {}>",
                                    file.starts_with("<") ? file : "\"" + file + "\"", w, h, s.request().spp,
                                    s.request().integrator);
             })
        .def("render", &render_scene, py::kw_only(), py::arg("spp") = py::none(),
             py::arg("resolution") = py::none(), py::arg("seed") = py::none(),
             py::arg("threads") = py::none(), py::arg("integrator") = py::none(),
             py::arg("max_depth") = py::none(), py::arg("sampler") = py::none(), py::arg("spectral") = false,
             py::arg("time") = py::none(), py::arg("adaptive") = false, py::arg("adaptive_threshold") = 0.0,
             py::arg("progress") = false, py::arg("stats") = false,
             R"(Renders the scene as `illum render` does and returns the linear radiance as a float32 array of
shape (height, width, 3), which wraps the rendered image's own pixels (no copy). The same arguments give
the same pixels as the command line (`--spp`, `--resolution WxH`, `--seed`, ...); the thread count never
changes the image. None means the scene's own value.

spp: samples per pixel; resolution: (width, height); seed: of the sample sequences (0 to 2^64-1; None:
the scene's Sampler "seed", else its Option "seed",
else 0); threads: worker threads (None: all cores); integrator: path,
volpath, bdpt, direct, lightpath, sppm, albedo or normal; max_depth: -1 (unlimited) to 100000; sampler:
zsobol, sobol, paddedsobol, halton, pmj02bn, stratified or independent; spectral: four sampled
wavelengths per camera sample instead of RGB; time: render whole passes until this many seconds
are spent; adaptive: spread the samples over the pixels by their noise (`--adaptive`,
docs/adaptive.md; path, volpath, bdpt, direct); adaptive_threshold: also stop pixels whose error level
is below it (implies adaptive); progress: print progress on stderr; stats: return (image, dict of the
render's figures).
The GIL is released while the scene renders.)");

    m.def(
        "load",
        [](const std::filesystem::path& path, bool strict) {
            if (path.empty()) throw py::value_error("the scene's path is empty");
            return load_scene(path.string(), strict);
        },
        py::arg("path"), py::arg("strict") = false,
        "Loads and builds a pbrt-v4 scene file. Errors raise illum.Error with the CLI's message "
        "(file:line:column: ...); recognised but unsupported features give Python warnings (errors with "
        "strict=True, as `--strict`).");
    m.def(
        "cornell_box", [] { return load_scene("", false); },
        "The built-in Cornell box (B. Bitterli's), which `illum render` renders with no scene named.");
}

} // namespace illum::python
