// illum.brdf: the reflection models of `illum brdf list`, created from a name and parameters as
// `illum brdf eval MODEL -p name=value` does (the registry's one validation), and evaluated, sampled and
// integrated over NumPy arrays of directions in the local shading frame (z = the normal, wo towards the
// viewer, wi towards the light, both away from the surface). The loops run in C++ on all cores with the
// GIL released.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <pybind11/stl.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "bindings.h"
#include "illum/bsdf/albedo.h"
#include "illum/bsdf/registry.h"
#include "illum/math/rng.h"

namespace illum::python {

namespace {

// A model with its validated parameters, built once and evaluated many times.
class Model {
public:
    Model(const std::string& name, const py::object& params)
        : spec_(&find_bxdf_model(name)), values_(resolve_params(*spec_, text_params(params))),
          bxdf_(spec_->make(values_)) {}

    const ModelSpec& spec() const { return *spec_; }
    const BxDF& bxdf() const { return *bxdf_; }
    std::string describe() const { return values_.describe(); }

private:
    // {name: value} as the command line's name=value text: a string as it is, a number in the shortest
    // form that reads back to the same double, three numbers (an RGB) as "r,g,b".
    static std::map<std::string, std::string> text_params(const py::object& params) {
        std::map<std::string, std::string> out;
        if (params.is_none()) return out;
        if (!py::isinstance<py::dict>(params))
            throw py::value_error(
                fmt::format("params must be a dict {{name: value}}, not {}", std::string(py::repr(params))));
        for (auto [key, value] : py::reinterpret_borrow<py::dict>(params)) {
            if (!py::isinstance<py::str>(key))
                throw py::value_error(
                    fmt::format("a parameter's name must be a string, not {}", std::string(py::repr(key))));
            std::string name = py::cast<std::string>(key);
            out[name] = text_value(name, value);
        }
        return out;
    }

    static std::string number_text(const std::string& name, const py::handle& v) {
        if (PyBool_Check(v.ptr()) || !(PyFloat_Check(v.ptr()) || PyIndex_Check(v.ptr()) ||
                                       py::isinstance(v, py::module_::import("numbers").attr("Real"))))
            throw py::value_error(
                fmt::format("parameter \"{}\": expected a number, a string or three numbers, not {}", name,
                            std::string(py::repr(v))));
        if (PyIndex_Check(v.ptr()))
            return std::string(py::str(py::reinterpret_steal<py::object>(PyNumber_Index(v.ptr()))));
        return fmt::format("{}", py::cast<double>(v));
    }

    static std::string text_value(const std::string& name, const py::handle& value) {
        if (py::isinstance<py::str>(value)) return py::cast<std::string>(value);
        if (py::isinstance<py::sequence>(value) || py::isinstance<py::array>(value)) {
            py::list items = py::list(py::reinterpret_borrow<py::object>(value));
            if (items.size() != 3)
                throw py::value_error(fmt::format("parameter \"{}\": an RGB value has three numbers, not {}",
                                                  name, std::string(py::repr(value))));
            return number_text(name, items[0]) + "," + number_text(name, items[1]) + "," +
                   number_text(name, items[2]);
        }
        return number_text(name, value);
    }

    const ModelSpec* spec_;
    ParamValues values_;
    std::unique_ptr<BxDF> bxdf_;
};

TransportMode parse_mode(const std::string& mode) {
    if (mode == "radiance") return TransportMode::Radiance;
    if (mode == "importance") return TransportMode::Importance;
    throw py::value_error("mode must be radiance or importance, got '" + mode + "'");
}

// The number of rows of arguments that are each one row (broadcast) or n rows; a ValueError otherwise.
std::size_t common_rows(std::initializer_list<std::pair<const Rows*, const char*>> args) {
    std::size_t n = 1;
    const char* from = nullptr;
    for (auto [rows, what] : args) {
        if (rows->single) continue;
        if (from && rows->n != n)
            throw py::value_error(fmt::format("{} has {} rows but {} has {}", what, rows->n, from, n));
        n = rows->n;
        from = what;
    }
    return n;
}
bool all_single(std::initializer_list<const Rows*> args) {
    return std::all_of(args.begin(), args.end(), [](const Rows* r) { return r->single; });
}

const double* row(const Rows& r, std::size_t i, std::size_t k) { return r.single ? r.data : r.data + i * k; }

// A row as a unit direction (normalised in double, then rounded to float as direction_deg does); false
// for a zero-length or non-finite one.
bool unit_direction(const double* p, Vector3f* d) {
    double len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    if (!(len > 0) || !std::isfinite(len)) return false;
    *d = Vector3f(float(p[0] / len), float(p[1] / len), float(p[2] / len));
    return true;
}

// The first row a parallel loop found bad (SIZE_MAX: none).
struct FirstBad {
    std::atomic<std::size_t> index{std::numeric_limits<std::size_t>::max()};
    void note(std::size_t i) {
        std::size_t cur = index.load();
        while (i < cur && !index.compare_exchange_weak(cur, i)) {
        }
    }
    bool any() const { return index.load() != std::numeric_limits<std::size_t>::max(); }
};

// Runs body(i) for i in [0, n) on all cores, with the GIL released.
template <class Body>
void parallel_rows(std::size_t n, const Body& body) {
    py::gil_scoped_release unlocked;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4096),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t i = r.begin(); i != r.end(); ++i) body(i);
                      });
}

void throw_bad_direction(const FirstBad& wi_bad, const FirstBad& wo_bad) {
    // The lower index first, wi before wo on a tie: the first bad row as a loop in order would see it.
    bool wi_first = wi_bad.any() && (!wo_bad.any() || wi_bad.index.load() <= wo_bad.index.load());
    std::size_t i = wi_first ? wi_bad.index.load() : wo_bad.index.load();
    throw py::value_error(
        fmt::format("{}[{}] is not a direction (zero length or not finite)", wi_first ? "wi" : "wo", i));
}

std::vector<py::ssize_t> shape(bool single, std::size_t n, py::ssize_t k) {
    if (single) return k ? std::vector<py::ssize_t>{k} : std::vector<py::ssize_t>{};
    return k ? std::vector<py::ssize_t>{py::ssize_t(n), k} : std::vector<py::ssize_t>{py::ssize_t(n)};
}

// Runs body(i, wo, wi) on the rows whose two directions are unit vectors with wo off the surface's plane
// (the renderer's BSDF gives nothing in the plane) and zero(i) on the others, in parallel; then throws for
// the first row whose direction was not a unit vector.
template <class Body, class Zero>
void over_direction_pairs(const Rows& wi, const Rows& wo, std::size_t n, Body&& body, Zero&& zero) {
    FirstBad wi_bad, wo_bad;
    parallel_rows(n, [&](std::size_t i) {
        Vector3f a, b;
        bool ok_i = unit_direction(row(wi, i, 3), &a), ok_o = unit_direction(row(wo, i, 3), &b);
        if (!ok_i) wi_bad.note(i);
        if (!ok_o) wo_bad.note(i);
        if (ok_i && ok_o && b.z != 0)
            body(i, b, a);
        else
            zero(i);
    });
    if (wi_bad.any() || wo_bad.any()) throw_bad_direction(wi_bad, wo_bad);
}

py::array_t<float> eval(const Model& m, const py::handle& wi_in, const py::handle& wo_in,
                        const std::string& mode_in) {
    TransportMode mode = parse_mode(mode_in);
    Rows wi = real_rows(wi_in, 3, "wi"), wo = real_rows(wo_in, 3, "wo");
    std::size_t n = common_rows({{&wi, "wi"}, {&wo, "wo"}});
    py::array_t<float> out(shape(all_single({&wi, &wo}), n, 3));
    float* f = out.mutable_data();
    const BxDF& bxdf = m.bxdf();
    over_direction_pairs(
        wi, wo, n,
        [&](std::size_t i, Vector3f w_o, Vector3f w_i) {
            Color3 v = bxdf.f(w_o, w_i, mode).rgb();
            f[3 * i] = v.r, f[3 * i + 1] = v.g, f[3 * i + 2] = v.b;
        },
        [&](std::size_t i) { f[3 * i] = f[3 * i + 1] = f[3 * i + 2] = 0; });
    return out;
}

py::array_t<float> pdf(const Model& m, const py::handle& wi_in, const py::handle& wo_in,
                       const std::string& mode_in) {
    TransportMode mode = parse_mode(mode_in);
    Rows wi = real_rows(wi_in, 3, "wi"), wo = real_rows(wo_in, 3, "wo");
    std::size_t n = common_rows({{&wi, "wi"}, {&wo, "wo"}});
    py::array_t<float> out(shape(all_single({&wi, &wo}), n, 0));
    float* p = out.mutable_data();
    const BxDF& bxdf = m.bxdf();
    over_direction_pairs(
        wi, wo, n, [&](std::size_t i, Vector3f w_o, Vector3f w_i) { p[i] = bxdf.pdf(w_o, w_i, mode).value; },
        [&](std::size_t i) { p[i] = 0; });
    return out;
}

// A uniform number in [0, 1] as the float in [0, 1) that BxDF::sample expects (1 becomes the largest float
// below 1); false outside [0, 1] or for NaN.
bool unit_interval(double u, float* out) {
    if (!(u >= 0 && u <= 1)) return false;
    *out = std::min(float(u), 0x1.fffffep-1f);
    return true;
}

py::dict sample(const Model& m, const py::handle& wo_in, const py::handle& u_in, const py::object& uc_in,
                const py::handle& seed_in, const std::string& mode_in) {
    TransportMode mode = parse_mode(mode_in);
    std::uint64_t seed = seed_value(seed_in, "seed");
    Rows wo = real_rows(wo_in, 3, "wo"), u = real_rows(u_in, 2, "u");
    Rows uc;
    bool have_uc = !uc_in.is_none();
    if (have_uc)
        uc = real_values(uc_in, "uc");
    else
        uc.single = true;
    std::size_t n =
        have_uc ? common_rows({{&wo, "wo"}, {&u, "u"}, {&uc, "uc"}}) : common_rows({{&wo, "wo"}, {&u, "u"}});
    bool single = all_single({&wo, &u, &uc});
    py::array_t<float> wi_out(shape(single, n, 3)), f_out(shape(single, n, 3)),
        weight_out(shape(single, n, 3)), pdf_out(shape(single, n, 0)), eta_out(shape(single, n, 0));
    py::array_t<std::uint8_t> flags_out(shape(single, n, 0));
    py::array_t<bool> valid_out(shape(single, n, 0));
    float *wi = wi_out.mutable_data(), *f = f_out.mutable_data(), *weight = weight_out.mutable_data(),
          *pdf = pdf_out.mutable_data(), *eta = eta_out.mutable_data();
    std::uint8_t* flags = flags_out.mutable_data();
    bool* valid = valid_out.mutable_data();
    FirstBad wo_bad, u_bad, uc_bad;
    const BxDF& bxdf = m.bxdf();
    parallel_rows(n, [&](std::size_t i) {
        Vector3f o;
        float u0 = 0, u1 = 0, c = 0;
        bool ok_o = unit_direction(row(wo, i, 3), &o);
        const double* ur = row(u, i, 2);
        bool ok_u = unit_interval(ur[0], &u0) && unit_interval(ur[1], &u1);
        bool ok_c = true;
        if (have_uc)
            ok_c = unit_interval(*row(uc, i, 1), &c);
        else
            c = float(hash(seed, i) >> 40) * 0x1p-24f; // a deterministic stream per row
        if (!ok_o) wo_bad.note(i);
        if (!ok_u) u_bad.note(i);
        if (!ok_c) uc_bad.note(i);
        std::optional<BSDFSample> s;
        // What the renderer's BSDF::sample accepts: a sample with a value, a density and a direction off
        // the surface.
        if (ok_o && ok_u && ok_c && o.z != 0) s = bxdf.sample(o, c, Point2f(u0, u1), mode);
        if (s && (s->f.is_black() || !(s->pdf.value > 0) || s->wi.z == 0)) s.reset();
        Color3 fv = s ? s->f.rgb() : Color3(0.0f), wv = s ? s->weight().rgb() : Color3(0.0f);
        Vector3f d = s ? s->wi : Vector3f();
        for (int k = 0; k < 3; ++k) {
            wi[3 * i + k] = d[k];
            f[3 * i + k] = fv[k];
            weight[3 * i + k] = wv[k];
        }
        pdf[i] = s ? s->pdf.value : 0.0f;
        eta[i] = s ? s->eta : 1.0f;
        flags[i] = s ? s->flags : std::uint8_t(kNone);
        valid[i] = bool(s);
    });
    if (wo_bad.any())
        throw py::value_error(
            fmt::format("wo[{}] is not a direction (zero length or not finite)", wo_bad.index.load()));
    if (u_bad.any()) throw py::value_error(fmt::format("u[{}] is not in [0, 1]", u_bad.index.load()));
    if (uc_bad.any()) throw py::value_error(fmt::format("uc[{}] is not in [0, 1]", uc_bad.index.load()));
    py::dict out;
    out["wi"] = wi_out;
    out["f"] = f_out;
    out["pdf"] = pdf_out;
    out["weight"] = weight_out;
    out["flags"] = flags_out;
    out["eta"] = eta_out;
    out["valid"] = valid_out;
    return out;
}

py::dict albedo(const Model& m, const py::handle& theta_in, const py::handle& samples_in,
                const py::handle& quad_in, const py::handle& seed_in) {
    // The ranges of `illum brdf albedo --samples` and `--quad`.
    int samples = int(whole_number(samples_in, "samples", 100, 100000000, "a whole number in [100, 10^8]"));
    int quad = int(whole_number(quad_in, "quad", 8, 4096, "a whole number in [8, 4096]"));
    std::uint64_t seed = seed_value(seed_in, "seed");
    Rows theta = real_values(theta_in, "theta_deg");
    for (std::size_t i = 0; i < theta.n; ++i)
        if (!(theta.data[i] >= 0 && theta.data[i] < 90))
            throw py::value_error(fmt::format("theta_deg values must be in [0, 90), got {}", theta.data[i]));
    std::vector<AlbedoEstimate> e(theta.n);
    {
        py::gil_scoped_release unlocked;
        tbb::parallel_for(std::size_t(0), theta.n, [&](std::size_t i) {
            e[i] = directional_albedo(m.bxdf(), direction_deg(theta.data[i], 0), m.spec().delta, quad,
                                      samples, seed);
        });
    }
    auto table = [&](auto member) {
        py::array_t<double> a(shape(theta.single, theta.n, 3));
        double* p = a.mutable_data();
        for (std::size_t i = 0; i < theta.n; ++i)
            for (int k = 0; k < 3; ++k) p[3 * i + k] = (e[i].*member)[k];
        return a;
    };
    py::dict out;
    out["quadrature"] =
        m.spec().delta ? py::object(py::none()) : py::object(table(&AlbedoEstimate::quadrature));
    out["mc"] = table(&AlbedoEstimate::mc);
    out["mc_stderr"] = table(&AlbedoEstimate::mc_stderr);
    return out;
}

const char* kDirections =
    "Directions are rows of (x, y, z) in the local shading frame (z = the normal), an (N, 3) array or one "
    "(3,) row that is used for every row of the other argument; any real dtype, normalised (in double) "
    "before use; a zero or non-finite one raises ValueError.";

py::dict describe_model(const std::string& name) {
    const ModelSpec& spec = find_bxdf_model(name);
    py::list params;
    for (const ParamSpec& p : spec.params) {
        py::dict d;
        d["name"] = p.name;
        d["kind"] = to_string(p.kind);
        d["default"] = p.default_value;
        if (p.kind == ParamKind::Choice)
            d["choices"] = p.choices;
        else if (p.kind != ParamKind::Path)
            d["range"] = py::make_tuple(p.min, p.max);
        d["description"] = p.description;
        params.append(d);
    }
    py::dict out;
    out["name"] = spec.name;
    out["description"] = spec.description;
    out["params"] = params;
    out["delta"] = spec.delta;
    out["non_physical"] = spec.non_physical;
    out["stochastic"] = spec.stochastic;
    return out;
}

} // namespace

void bind_brdf(py::module_& m) {
    py::module_ b = m.def_submodule(
        "brdf", "The reflection models of `illum brdf list`, vectorised over NumPy arrays of directions in "
                "the local shading frame (z = the normal; wo towards the viewer, wi towards the light).");
    // `import illum.brdf` finds the submodule too.
    py::module_::import("sys").attr("modules")["illum.brdf"] = b;

    b.attr("REFLECTION") = int(kReflection);
    b.attr("TRANSMISSION") = int(kTransmission);
    b.attr("DIFFUSE") = int(kDiffuse);
    b.attr("GLOSSY") = int(kGlossy);
    b.attr("SPECULAR") = int(kSpecular);

    std::string eval_doc =
        std::string("f(wo, wi) [1/sr], the BSDF value without the cosine, as float32 RGB rows: shape (N, 3), "
                    "or (3,) when both directions are one row. mode: radiance or importance. ") +
        kDirections;
    std::string pdf_doc =
        std::string("The solid-angle density [1/sr] of sample() for wo producing wi, as float32: shape (N,) "
                    "or (). ") +
        kDirections;
    const char* sample_doc =
        R"(Samples wi for each wo with the model's own sampling. u: uniform numbers in [0, 1], shape (N, 2) or
(2,); uc: the lobe choice in [0, 1], shape (N,) or a number (None: a deterministic stream of `seed`).
Returns a dict of arrays, one row per sample: wi (N, 3), f (N, 3) [1/sr], pdf (N,) [1/sr], weight (N, 3)
= f |cos θi| / pdf (the path throughput weight), flags (N,) uint8 (REFLECTION, TRANSMISSION, DIFFUSE,
GLOSSY, SPECULAR bits), eta (N,) (the relative index along wi for transmission, 1 otherwise) and valid
(N,) bool (False where no direction was sampled: then wi, f, pdf and weight are 0). For a delta lobe pdf
is the lobe's probability, as in the renderer.)";
    const char* albedo_doc =
        R"(Directional albedo ∫ f(wo, wi) |cos θi| dωi (importance mode) at wo = (θo, φ = 0), as
`illum brdf albedo --theta`: theta_deg in degrees in [0, 90), a number or shape (N,). Returns a dict:
quadrature (N, 3) float64 (None for a delta model), mc and mc_stderr (N, 3) (Monte Carlo with the
model's sampling, `samples` per angle, and its standard error).)";

    py::class_<Model>(b, "Model",
                      "A reflection model by name with its parameters ({name: number, string or "
                      "three numbers}), validated as `illum brdf eval -p name=value` does.")
        .def(py::init<const std::string&, const py::object&>(), py::arg("model"),
             py::arg("params") = py::none())
        .def_property_readonly("name", [](const Model& m) { return m.spec().name; })
        .def_property_readonly("params", &Model::describe, "The parameters with defaults applied, as text")
        .def_property_readonly("delta", [](const Model& m) { return m.spec().delta; })
        .def("__repr__",
             [](const Model& m) {
                 return fmt::format("<illum.brdf.Model {} {}>", m.spec().name, m.describe());
             })
        .def("eval", &eval, py::arg("wi"), py::arg("wo"), py::arg("mode") = "radiance", eval_doc.c_str())
        .def("pdf", &pdf, py::arg("wi"), py::arg("wo"), py::arg("mode") = "radiance", pdf_doc.c_str())
        .def("sample", &sample, py::arg("wo"), py::arg("u"), py::arg("uc") = py::none(), py::arg("seed") = 0,
             py::arg("mode") = "radiance", sample_doc)
        .def("albedo", &albedo, py::arg("theta_deg"), py::arg("samples") = 200000, py::arg("quad") = 256,
             py::arg("seed") = 1, albedo_doc);

    b.def(
        "eval",
        [](const std::string& model, const py::object& params, const py::handle& wi, const py::handle& wo,
           const std::string& mode) { return eval(Model(model, params), wi, wo, mode); },
        py::arg("model"), py::arg("params"), py::arg("wi"), py::arg("wo"), py::arg("mode") = "radiance",
        ("Model(model, params).eval(wi, wo, mode): " + eval_doc).c_str());
    b.def(
        "pdf",
        [](const std::string& model, const py::object& params, const py::handle& wi, const py::handle& wo,
           const std::string& mode) { return pdf(Model(model, params), wi, wo, mode); },
        py::arg("model"), py::arg("params"), py::arg("wi"), py::arg("wo"), py::arg("mode") = "radiance",
        ("Model(model, params).pdf(wi, wo, mode): " + pdf_doc).c_str());
    b.def(
        "sample",
        [](const std::string& model, const py::object& params, const py::handle& wo, const py::handle& u,
           const py::object& uc, const py::handle& seed,
           const std::string& mode) { return sample(Model(model, params), wo, u, uc, seed, mode); },
        py::arg("model"), py::arg("params"), py::arg("wo"), py::arg("u"), py::arg("uc") = py::none(),
        py::arg("seed") = 0, py::arg("mode") = "radiance",
        (std::string("Model(model, params).sample(wo, u, uc, seed, mode): ") + sample_doc).c_str());
    b.def(
        "albedo",
        [](const std::string& model, const py::object& params, const py::handle& theta,
           const py::handle& samples, const py::handle& quad,
           const py::handle& seed) { return albedo(Model(model, params), theta, samples, quad, seed); },
        py::arg("model"), py::arg("params"), py::arg("theta_deg"), py::arg("samples") = 200000,
        py::arg("quad") = 256, py::arg("seed") = 1,
        (std::string("Model(model, params).albedo(theta_deg, samples, quad, seed): ") + albedo_doc).c_str());
    b.def(
        "models",
        [] {
            std::vector<std::string> names;
            for (const auto& s : bxdf_models()) names.push_back(s.name);
            return names;
        },
        "The names of the models, as `illum brdf list` gives them.");
    b.def("describe", &describe_model, py::arg("model"),
          "A model's description and parameters (name, kind, default, range or choices, description).");
}

} // namespace illum::python
