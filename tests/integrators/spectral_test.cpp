// Spectral mode end to end: a white furnace returns white, a prism of a named glass disperses light at the
// angles Snell's law gives for that glass's index, and a lossless prism conserves energy.
#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>
#include <vector>

#include "test_support.h"

namespace illum {
namespace {

// A closed furnace of white (1, 1, 1) Lambertian walls emitting (1, 1, 1), albedo 0.8: every pixel sees
// Le / (1 - ρ) = 5 in each channel, in RGB and, when the white uplifts to the constant 1 and the emission
// to the colour space's white, in spectral mode. Tolerance: 0.5% (the acceptance) plus 4 standard errors
// of the image mean (pixels are independent estimates).
TEST(SpectralMode, WhiteFurnaceIsWhite) {
    test::RenderSetup s;
    s.spp = 1024;
    s.spectral = true;
    Image img = test::render_pbrt(test::closed_furnace(0.8, 1, 24), s).image;
    for (int c = 0; c < 3; ++c) {
        test::MeanEstimate m = test::pixel_mean(img, c);
        std::printf("channel %d: %.5f ± %.5f (expected 5)\n", c, m.mean, m.standard_error);
        EXPECT_NEAR(m.mean, 5, 5 * 0.005 + 4 * m.standard_error) << "channel " << c;
    }
}

// --- The prism ------------------------------------------------------------------------------------------
//
// An equilateral prism of Schott N-SF11 ("glass-F11", pbrt-v4's name for its SF11 table), extruded along y.
// The camera at the origin looks along +z through it at a narrow emitting slit; a ray of wavelength λ
// that reaches the slit has been deviated by δ(θ1, n(λ)) at the prism, so the slit appears, per
// wavelength band, at the image column whose ray Snell's law sends to the slit's centre. (This is the
// reciprocal of a thin beam from the slit landing on a screen at the camera: light paths are reversible
// through a lossless dielectric; illum renders it from the camera, which its path tracer converges on
// without a light tracer.)
//
// The prediction below is an independent 2D trace in the prism's principal plane with the Sellmeier
// index (Schott's catalogue coefficients for SF11), not illum's code.

struct V2 {
    double x, z;
};
V2 operator+(V2 a, V2 b) { return {a.x + b.x, a.z + b.z}; }
V2 operator-(V2 a, V2 b) { return {a.x - b.x, a.z - b.z}; }
V2 operator*(double s, V2 a) { return {s * a.x, s * a.z}; }
double dot(V2 a, V2 b) { return a.x * b.x + a.z * b.z; }
V2 unit(V2 a) { return (1 / std::sqrt(dot(a, a))) * a; }
V2 rotate(V2 a, double t) {
    return {a.x * std::cos(t) - a.z * std::sin(t), a.x * std::sin(t) + a.z * std::cos(t)};
}

// Schott N-SF11 / SF11 Sellmeier coefficients: n² = 1 + Σ B_i λ² / (λ² - C_i), λ in µm.
double sf11_index(double nm) {
    const double B[3] = {1.73759695, 0.313747346, 1.89878101}, C[3] = {0.013188707, 0.0623068142, 155.23629};
    double l2 = (nm / 1000) * (nm / 1000), n2 = 1;
    for (int i = 0; i < 3; ++i) n2 += B[i] * l2 / (l2 - C[i]);
    return std::sqrt(n2);
}

// Refraction of unit direction d at a surface of unit normal n (against d) from index n1 to n2.
bool refract(V2 d, V2 n, double eta1, double eta2, V2* t) {
    double cos_i = -dot(d, n), r = eta1 / eta2;
    double k = 1 - r * r * (1 - cos_i * cos_i);
    if (k < 0) return false;
    *t = r * d + (r * cos_i - std::sqrt(k)) * n;
    return true;
}
// Ray (o, d) against the line through a and b: the parameter along the ray, or -1.
double hit_line(V2 o, V2 d, V2 a, V2 b, V2* p) {
    V2 e = b - a, n = {-e.z, e.x};
    double den = dot(d, n);
    if (den == 0) return -1;
    double t = dot(a - o, n) / den;
    *p = o + t * d;
    double s = dot(*p - a, e) / dot(e, e);
    return s >= 0 && s <= 1 ? t : -1;
}

struct Prism {
    V2 apex, b1, b2;   // face 1 = b1-apex (entry), face 2 = apex-b2 (exit)
    V2 slit_c, slit_u; // the slit's centre and its unit direction across
    double slit_width = 0.25;
};

constexpr int kW = 480, kH = 8;
constexpr double kHalfWidth = 0.5; // screen window: the camera sees tan angles in [-0.5, 0.5]

V2 camera_dir(double raster_x) { return unit({-kHalfWidth + 2 * kHalfWidth * raster_x / kW, 1}); }

// The ray through raster column x after the prism at index n: its exit point and direction.
bool through_prism(const Prism& p, double x, double n, V2* o, V2* d) {
    V2 dir = camera_dir(x), hit;
    if (hit_line({0, 0}, dir, p.b1, p.apex, &hit) < 0) return false;
    V2 e1 = p.apex - p.b1, n1 = unit({e1.z, -e1.x}); // outward normal of face 1 (towards the camera)
    if (dot(n1, dir) > 0) n1 = -1 * n1;
    V2 in;
    if (!refract(dir, n1, 1, n, &in)) return false;
    V2 exit_p;
    if (hit_line(hit, in, p.apex, p.b2, &exit_p) < 0) return false;
    V2 e2 = p.b2 - p.apex, n2 = unit({e2.z, -e2.x});
    if (dot(n2, in) > 0) n2 = -1 * n2;
    if (!refract(in, n2, n, 1, d)) return false;
    *o = exit_p;
    return true;
}

Prism make_prism() {
    // Canonical frame: apex up, base on the x axis, side 8; a ray at angle φ above +x meets face 1 at
    // incidence φ + 30°. φ = 40°: incidence 70°, far from minimum deviation so the slit's image stays
    // compact. The frame is rotated so that this ray is the camera's +z, face 1's midpoint on the axis.
    const double s = 8, h = s * std::sqrt(3.0) / 2, phi = 40 * kPiD / 180;
    V2 apex{0, h}, b1{-s / 2, 0}, b2{s / 2, 0};
    double rot = kPiD / 2 - phi;
    auto place = [&](V2 v) { return rotate(v, rot); };
    Prism p{place(apex), place(b1), place(b2), {}, {}};
    V2 mid = 0.5 * (p.apex + p.b1);
    V2 shift = V2{0, 12} - mid;
    // The ray along +z must meet face 1 at its midpoint: shift so the midpoint lies on x = 0, z = 12.
    p.apex = p.apex + shift;
    p.b1 = p.b1 + shift;
    p.b2 = p.b2 + shift;
    // The slit: 40 units along the central column's 550 nm exit ray, across it.
    V2 o, d;
    EXPECT_TRUE(through_prism(p, kW / 2.0, sf11_index(550), &o, &d));
    p.slit_c = o + 40 * d;
    p.slit_u = {-d.z, d.x};
    return p;
}

// The raster column whose ray reaches the slit's centre for a prism of index n (bisection).
double predicted_column(const Prism& p, double n) {
    auto side = [&](double x) {
        V2 o, d;
        if (!through_prism(p, x, n, &o, &d)) return std::nan("");
        // Where the exit ray crosses the slit's line, measured across it.
        V2 nrm = {p.slit_u.z, -p.slit_u.x};
        double t = dot(p.slit_c - o, nrm) / dot(d, nrm);
        return dot(o + t * d - p.slit_c, p.slit_u);
    };
    // Bracket the crossing between two adjacent columns whose rays pass through the prism, then bisect.
    double lo = -1, hi = -1, slo = 0;
    for (int x = 0; x + 1 < kW && lo < 0; ++x) {
        double a = side(x + 0.5), b = side(x + 1.5);
        if (!std::isnan(a) && !std::isnan(b) && (a < 0) != (b < 0)) {
            lo = x + 0.5;
            hi = x + 1.5;
            slo = a;
        }
    }
    EXPECT_GE(lo, 0) << "the slit is not within the image at index " << n;
    for (int i = 0; i < 60; ++i) {
        double mid = 0.5 * (lo + hi), sm = side(mid);
        if ((sm < 0) == (slo < 0)) {
            lo = mid;
            slo = sm;
        } else {
            hi = mid;
        }
    }
    return 0.5 * (lo + hi);
}

// max_depth 2 (two refractions) for the deviation test: the beam that crosses the prism once, without the
// ghosts of internal reflections.
std::string prism_scene(const Prism& p, const std::string& light_spectrum, const std::string& world_extra,
                        int max_depth, const std::string& eta = R"("spectrum eta" "glass-F11")") {
    auto pt = [](V2 v, double y) { return fmt::format("{} {} {}", v.x, y, v.z); };
    const double y = 20;
    std::string prism = fmt::format(
        R"(Shape "trianglemesh" "point3 P" [ {} {} {} {} {} {} ]
  "integer indices" [ 0 1 2  3 5 4  0 3 4  0 4 1  1 4 5  1 5 2  2 5 3  2 3 0 ])",
        pt(p.apex, -y), pt(p.b1, -y), pt(p.b2, -y), pt(p.apex, y), pt(p.b1, y), pt(p.b2, y));
    V2 a = p.slit_c - (p.slit_width / 2) * p.slit_u, b = p.slit_c + (p.slit_width / 2) * p.slit_u;
    std::string slit = light_spectrum.empty()
                           ? ""
                           : fmt::format(R"(AttributeBegin
  Material "diffuse" "rgb reflectance" [0 0 0]
  AreaLightSource "diffuse" "spectrum L" [ {} ] "bool twosided" true
  Shape "trianglemesh" "point3 P" [ {} {} {} {} ] "integer indices" [ 0 1 2 0 2 3 ]
AttributeEnd)",
                                         light_spectrum, pt(a, -y), pt(b, -y), pt(b, y), pt(a, y));
    return fmt::format(R"(
Integrator "path" "integer maxdepth" [{depth}]
Camera "perspective" "float fov" [90] "float screenwindow" [ {hw} {hw2} -{vh} {vh} ]
Film "rgb" "integer xresolution" [{w}] "integer yresolution" [{h}]
Sampler "independent"
WorldBegin
{extra}
AttributeBegin
  Material "dielectric" {eta}
  {prism}
AttributeEnd
{slit}
)",
                       fmt::arg("hw", -kHalfWidth), fmt::arg("hw2", kHalfWidth),
                       fmt::arg("vh", kHalfWidth * kH / kW), fmt::arg("w", kW), fmt::arg("h", kH),
                       fmt::arg("extra", world_extra), fmt::arg("prism", prism), fmt::arg("slit", slit),
                       fmt::arg("depth", max_depth), fmt::arg("eta", eta));
}

// The centroid column of the image's main spot. The slit is seen along more than one path through the
// prism (entering by face 1 and leaving by the base, say: faint ghosts at other columns, as a screen would
// show them too); the main spot is the cluster of lit columns (gaps of at most 3 columns) with the largest
// luminance, Y ≥ 0 even where a narrow band's RGB has a negative component.
double centroid_column(const Image& img, double* total) {
    std::vector<double> col(std::size_t(img.width()), 0.0);
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) col[std::size_t(x)] += std::max(0.0f, img(x, y).luminance());
    double best = 0, best_centroid = -1;
    for (int x = 0; x < img.width();) {
        if (col[std::size_t(x)] <= 0) {
            ++x;
            continue;
        }
        double sw = 0, sx = 0;
        int gap = 0, end = x;
        for (; end < img.width() && gap <= 3; ++end) {
            double w = col[std::size_t(end)];
            gap = w > 0 ? 0 : gap + 1;
            sw += w;
            sx += w * (end + 0.5);
        }
        if (sw > best) {
            best = sw;
            best_centroid = sx / sw;
        }
        x = end;
    }
    *total = best;
    return best_centroid;
}

TEST(SpectralMode, PrismDeviatesEachBandAsSnellsLawWithTheGlassIndex) {
    // The coefficients above are SF11's: n_d = 1.78472 (Schott).
    EXPECT_NEAR(sf11_index(587.56), 1.78472, 2e-4);
    Prism p = make_prism();
    double previous = -1;
    for (double centre : {450.0, 550.0, 650.0}) {
        double lo = centre - 5, hi = centre + 5;
        std::string band = fmt::format("{} 0 {} 1 {} 1 {} 0", lo - 0.01, lo, hi, hi + 0.01);
        test::RenderSetup s;
        s.spp = 512;
        s.spectral = true;
        s.seed = 3;
        Image img = test::render_pbrt(prism_scene(p, band, "", 2), s).image;
        double total = 0, measured = centroid_column(img, &total);
        double predicted = predicted_column(p, sf11_index(centre));
        std::printf("%.0f nm band (n = %.5f): slit seen at column %.2f, Snell's law predicts %.2f\n", centre,
                    sf11_index(centre), measured, predicted);
        ASSERT_GT(total, 0) << centre << " nm: the slit is not seen";
        EXPECT_NEAR(measured, predicted, 1.0) << centre << " nm";
        // Shorter wavelengths see a higher index and are deviated more: the bands are separated.
        if (previous >= 0) {
            EXPECT_GT(std::abs(measured - previous), 10) << "bands not separated";
        }
        previous = measured;
    }
}

// illum's dispersion formulas: "sellmeier eta" with SF11's coefficients disperses as the named glass, and
// a "cauchy eta" fitted to SF11 at 486 and 656 nm deviates the 450 nm band where Snell's law with that
// two-term index says (a column off the Sellmeier glass's: the fit is not exact at 450 nm).
TEST(SpectralMode, SellmeierAndCauchyIndicesDisperse) {
    Prism p = make_prism();
    std::string band = "444.99 0 445 1 455 1 455.01 0";
    test::RenderSetup s;
    s.spp = 512;
    s.spectral = true;
    s.seed = 3;
    double total = 0;
    double named = centroid_column(test::render_pbrt(prism_scene(p, band, "", 2), s).image, &total);
    double sellmeier = centroid_column(
        test::render_pbrt(
            prism_scene(
                p, band, "", 2,
                R"("sellmeier eta" [1.73759695 0.313747346 1.89878101 0.013188707 0.0623068142 155.23629])"),
            s)
            .image,
        &total);
    // n = A + B / λ² through SF11's n_F and n_C.
    double lf = 0.48613, lc = 0.65627, nf = sf11_index(486.13), nc = sf11_index(656.27);
    double b = (nf - nc) / (1 / (lf * lf) - 1 / (lc * lc)), a = nf - b / (lf * lf);
    double cauchy = centroid_column(
        test::render_pbrt(prism_scene(p, band, "", 2, fmt::format(R"("cauchy eta" [{} {}])", a, b)), s).image,
        &total);
    double cauchy_predicted = predicted_column(p, a + b / (0.45 * 0.45));
    std::printf(
        "450 nm band: glass-F11 %.2f, sellmeier %.2f (Snell's law %.2f); cauchy %.2f (Snell's law with its "
        "index %.2f)\n",
        named, sellmeier, predicted_column(p, sf11_index(450)), cauchy, cauchy_predicted);
    EXPECT_NEAR(sellmeier, named, 0.3);
    EXPECT_NEAR(cauchy, cauchy_predicted, 1.0);
}

TEST(SpectralMode, DispersionFormulaErrorsNameTheirPosition) {
    for (const char* bad : {R"("sellmeier eta" [1 2 3])", R"("cauchy eta" [1.5])",
                            R"("cauchy eta" "glass-BK7")", R"("cauchy eta" [-5 0.01])"}) {
        std::string scene = fmt::format("WorldBegin\nMaterial \"dielectric\" {}\nShape \"sphere\"\n", bad);
        try {
            test::render_pbrt(scene);
            ADD_FAILURE() << bad << " was accepted";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("<test>:2:"), std::string::npos) << e.what();
        }
    }
}

// Energy: inside a uniform white environment of radiance 1, a lossless (dispersive) prism changes no
// radiance: every path leaves to the environment with total weight 1 (radiance scaling by 1/η² on entry
// is undone on exit), at every wavelength. Each channel's image mean must be 1 within 0.5% plus 4
// standard errors.
TEST(SpectralMode, LosslessPrismConservesEnergy) {
    Prism p = make_prism();
    test::RenderSetup s;
    s.spp = 64;
    s.spectral = true;
    std::string scene = prism_scene(p, "", R"(LightSource "infinite" "rgb L" [1 1 1])", -1);
    Image img = test::render_pbrt(scene, s).image;
    // Only the columns that look through both faces of the prism (the others see the environment directly).
    std::vector<int> through;
    for (int x = 0; x < kW; ++x) {
        V2 o, d;
        if (through_prism(p, x + 0.5, sf11_index(587.56), &o, &d)) through.push_back(x);
    }
    ASSERT_GT(through.size(), 50u);
    for (int c = 0; c < 3; ++c) {
        double sum = 0, sum2 = 0;
        std::size_t n = 0;
        for (int x : through)
            for (int y = 0; y < kH; ++y, ++n) {
                double v = img(x, y)[c];
                sum += v;
                sum2 += v * v;
            }
        double mean = sum / n, se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / (n - 1));
        std::printf("channel %d over %zu pixels through the prism: %.5f ± %.5f (expected 1)\n", c, n, mean,
                    se);
        EXPECT_NEAR(mean, 1, 0.005 + 4 * se) << "channel " << c;
    }
}

} // namespace
} // namespace illum

namespace illum {
namespace {

// A film filled by an emitter seen head-on: every pixel is the emitter's radiance in the output space.
std::string emitter_view(const std::string& color_space, const std::string& emission,
                         const std::string& film_extra, const std::string& camera_extra = "") {
    return fmt::format(R"(
ColorSpace "{}"
Camera "orthographic" {}
Film "rgb" "integer xresolution" [8] "integer yresolution" [8] {}
Sampler "independent"
WorldBegin
AreaLightSource "diffuse" {} "bool twosided" true
Material "diffuse" "rgb reflectance" [0 0 0]
Shape "trianglemesh" "point3 P" [ -5 -5 1  5 -5 1  5 5 1  -5 5 1 ] "integer indices" [ 0 1 2 0 2 3 ]
)",
                       color_space, camera_extra, film_extra, emission);
}

Color3 mean_of(const Image& img) { return img.channel_mean(); }

// In every colour space, an RGB emitter seen directly renders as that RGB in spectral mode too: the
// emitter's RGB is uplifted in the scene's space and the film writes the same space. Tolerance: the
// uplift round trip (≤ 2·10⁻³ over sRGB's colours in the wide spaces, relative to the largest component
// here) plus 4 standard errors of the wavelength sampling noise.
TEST(SpectralMode, ColorSpacesRoundTripThroughTheFilm) {
    const Color3 rgb(0.8f, 0.4f, 0.2f);
    for (const char* cs : {"srgb", "rec2020", "aces2065-1", "dci-p3"}) {
        test::RenderSetup s;
        s.spp = 1024;
        s.spectral = true;
        s.max_depth = 1;
        std::string scene = emitter_view(cs, fmt::format("\"rgb L\" [{} {} {}]", rgb.r, rgb.g, rgb.b), "");
        Image img = test::render_pbrt(scene, s).image;
        Color3 m = mean_of(img);
        std::printf("%s: (%.4f %.4f %.4f) for (0.8 0.4 0.2)\n", cs, m.r, m.g, m.b);
        for (int c = 0; c < 3; ++c) {
            test::MeanEstimate e = test::pixel_mean(img, c);
            EXPECT_NEAR(e.mean, rgb[c], 0.8 * 3e-3 + 4 * e.standard_error) << cs << " channel " << c;
        }
        s.spectral = false; // RGB mode: exactly the input
        Color3 r = mean_of(test::render_pbrt(scene, s).image);
        for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(r[c], rgb[c]) << cs;
    }
}

// Uplifted spectra of RGB values that sum to at most 1 may sum to more at some wavelengths; the models
// whose parameters must sum to at most 1 are given spectra scaled back per wavelength, so a spectral render
// of saturated complementary colours neither throws from a constructor nor gains energy (the furnace stays
// below its emission bound).
TEST(SpectralMode, UnitSumParametersStayValidAtEveryWavelength) {
    for (const char* m : {R"("phong" "rgb kd" [0.9 0.05 0.05] "rgb ks" [0.1 0.95 0.95])",
                          R"("ward" "rgb rho_d" [0.05 0.9 0.05] "rgb rho_s" [0.95 0.1 0.95])",
                          R"("cook-torrance" "rgb kd" [0.05 0.05 0.9] "rgb ks" [0.95 0.95 0.1])"}) {
        std::string scene = fmt::format(R"(
Integrator "path" "integer maxdepth" [-1]
LookAt 0.1 0.2 0  1 0.3 0.2  0 0 1
Camera "perspective" "float fov" [60]
Film "rgb" "integer xresolution" [8] "integer yresolution" [8]
WorldBegin
Material {}
AreaLightSource "diffuse" "rgb L" [1 1 1]
ReverseOrientation
Shape "sphere" "float radius" [1]
)",
                                        m);
        test::RenderSetup s;
        s.spp = 64;
        s.spectral = true;
        RenderResult r;
        ASSERT_NO_THROW(r = test::render_pbrt(scene, s)) << m;
        EXPECT_EQ(r.nonfinite_samples, 0u) << m;
        EXPECT_FALSE(r.image.has_non_finite()) << m;
    }
}

TEST(SpectralMode, UnknownColorSpaceAndSensorAreErrorsWithTheirPosition) {
    for (const char* scene :
         {"ColorSpace \"prophoto\"\nWorldBegin\n",
          "Film \"rgb\" \"string sensor\" \"canon_eos_100d\"\nWorldBegin\nShape \"sphere\"\n"}) {
        try {
            test::render_pbrt(scene);
            ADD_FAILURE() << scene << " was accepted";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("<test>:1:"), std::string::npos) << e.what();
        }
    }
}

// pbrt-v4's sensor parameters: a CIE illuminant A emitter (luminance 1), white-balanced for 2856 K,
// renders neutral (r = g = b within the noise; unbalanced it is orange, r/b > 2); "iso" 200 doubles the
// image; an exposure of 0.5 s (shutterclose - shutteropen) halves it.
TEST(SpectralMode, SensorWhiteBalanceIsoAndExposure) {
    test::RenderSetup s;
    s.spp = 1024;
    s.spectral = true;
    s.max_depth = 1;
    const std::string a = R"("spectrum L" "stdillum-A")";
    Color3 plain = mean_of(test::render_pbrt(emitter_view("srgb", a, ""), s).image);
    Color3 balanced =
        mean_of(test::render_pbrt(emitter_view("srgb", a, R"("float whitebalance" [2856])"), s).image);
    std::printf("illuminant A: (%.4f %.4f %.4f); white-balanced for 2856 K: (%.4f %.4f %.4f)\n", plain.r,
                plain.g, plain.b, balanced.r, balanced.g, balanced.b);
    EXPECT_GT(plain.r / plain.b, 2);
    EXPECT_NEAR(balanced.r / balanced.g, 1, 0.01);
    EXPECT_NEAR(balanced.b / balanced.g, 1, 0.01);
    Color3 iso = mean_of(test::render_pbrt(emitter_view("srgb", a, R"("float iso" [200])"), s).image);
    Color3 half =
        mean_of(test::render_pbrt(
                    emitter_view("srgb", a, "", R"("float shutteropen" [0] "float shutterclose" [0.5])"), s)
                    .image);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(iso[c], 2 * plain[c], 1e-4 * plain[c]) << c; // the same samples, scaled
        EXPECT_NEAR(half[c], 0.5f * plain[c], 1e-4 * plain[c]) << c;
    }
    // The luminance of a luminance-1 illuminant is 1.
    EXPECT_NEAR(plain.luminance(), 1, 0.01);
}

} // namespace
} // namespace illum
