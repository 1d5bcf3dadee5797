// illum.envmap: the environment-map tools of `illum envmap` on files or NumPy arrays. So far the nine
// spherical-harmonic radiance coefficients of `illum envmap sh`.
#include <optional>
#include <string>

#include <fmt/core.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "illum/envmap/environment_map.h"
#include "illum/envmap/spherical_harmonics.h"

namespace illum::python {

namespace {

const char* kLayouts = "latlong, octahedral, mirrorball, angular or cubemap";

std::optional<EnvLayout> parse_layout(const std::optional<std::string>& name) {
    if (!name) return std::nullopt;
    auto layout = env_layout_from_string(*name);
    if (!layout) throw py::value_error(fmt::format("unknown layout \"{}\" (expected {})", *name, kLayouts));
    return layout;
}

// A map from a file name (as `illum envmap sh FILE [--from LAYOUT]`) or from an array of shape
// (height, width, 3), with the warnings the CLI prints.
EnvironmentMap load_map(const py::handle& source, std::optional<EnvLayout> layout) {
    EnvironmentMap map;
    std::string what;
    if (py::isinstance<py::str>(source) || py::hasattr(source, "__fspath__")) {
        what = py::str(py::module_::import("os").attr("fspath")(source));
        py::gil_scoped_release unlocked;
        map = EnvironmentMap::load(what, layout);
    } else {
        Image image = array_to_image(source, "the environment map");
        what = "the environment map";
        EnvLayout l = layout ? *layout : EnvironmentMap::default_layout(image.width(), image.height(), what);
        map = EnvironmentMap(std::move(image), l, what);
    }
    if (map.non_finite_count() > 0)
        warn_all({fmt::format("\"{}\": {} non-finite values were set to 0", what, map.non_finite_count())});
    if (map.mean_radiance().is_black()) warn_all({fmt::format("\"{}\": the map is black (no energy)", what)});
    return map;
}

} // namespace

void bind_envmap(py::module_& m) {
    py::module_ e = m.def_submodule("envmap", "Environment-map tools, as `illum envmap`.");
    py::module_::import("sys").attr("modules")["illum.envmap"] = e;
    e.attr("SH_NAMES") = py::make_tuple(kSHNames[0], kSHNames[1], kSHNames[2], kSHNames[3], kSHNames[4],
                                        kSHNames[5], kSHNames[6], kSHNames[7], kSHNames[8]);
    e.def(
        "sh",
        [](const py::handle& source, const std::optional<std::string>& layout) {
            EnvironmentMap map = load_map(source, parse_layout(layout));
            SH9 sh;
            {
                py::gil_scoped_release unlocked;
                sh = project_sh(map);
            }
            py::array_t<double> out(std::vector<py::ssize_t>{9, 3});
            double* p = out.mutable_data();
            for (int i = 0; i < 9; ++i)
                for (int c = 0; c < 3; ++c) p[3 * i + c] = sh.c[i][c];
            return out;
        },
        py::arg("source"), py::arg("layout") = py::none(),
        R"(The nine spherical-harmonic radiance coefficients L_lm = ∫ L(ω) Y_lm(ω) dω of an environment map
(Ramamoorthi & Hanrahan 2001), as `illum envmap sh` prints them: a float64 array of shape (9, 3), rows
in the order of SH_NAMES (L00, L1m1, L10, L11, L2m2, L2m1, L20, L21, L22), columns R, G, B. The irradiance
at normal n is Σ Â_l L_lm Y_lm(n) with Â0 = π, Â1 = 2π/3, Â2 = π/4. source: a file (.exr, .pfm, .hdr) or
an array of shape (height, width, 3); layout: latlong, octahedral, mirrorball, angular or cubemap (None:
by the aspect ratio, 2:1 latlong, 1:1 octahedral, 6:1 cubemap).)");
}

} // namespace illum::python
