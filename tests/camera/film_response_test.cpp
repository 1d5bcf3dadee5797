// FilmResponse, the sensor's map folded into a 3 × 4 matrix per set of wavelengths, against the sensor's own
// to_rgb and to_film: equal within float rounding for any spectrum, in spectral and RGB mode, with a white
// balance and an imaging ratio, at terminated secondary wavelengths, and with a maxcomponentvalue (where
// to_film is not linear and FilmResponse defers to it).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "illum/camera/sensor.h"

namespace illum {
namespace {

// Float rounding of a sum of four products whose terms may cancel (the output matrix has negative
// entries): relative to the largest channel, not to each.
void expect_close(Color3 a, Color3 b, const char* what) {
    const float scale = std::max({1.0f, std::abs(b.r), std::abs(b.g), std::abs(b.b)});
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 1e-5f * scale) << what << " channel " << c;
}

TEST(FilmResponse, EqualsTheSensorsMapWithinRounding) {
    const Sensor sensors[] = {Sensor(), Sensor(RGBColorSpace::srgb(), 2.5f, 3200)};
    std::mt19937 gen(7);
    std::uniform_real_distribution<float> u(0, 1);
    for (const Sensor& sensor : sensors)
        for (int k = 0; k < 200; ++k) {
            SampledWavelengths lambda = SampledWavelengths::sample_visible(u(gen), &RGBColorSpace::srgb());
            if (k % 4 == 3) lambda.terminate_secondary();
            const Radiance3 l(SampledSpectrum(3 * u(gen), u(gen), 10 * u(gen), u(gen)));
            const FilmResponse response(sensor, lambda);
            expect_close(response.rgb(l.s), sensor.to_rgb(l, lambda), "spectral rgb");
            expect_close(response.film(l), sensor.to_film(l, lambda), "spectral film");
            const SampledWavelengths rgb = SampledWavelengths::rgb_mode();
            expect_close(FilmResponse(sensor, rgb).film(l), sensor.to_film(l, rgb), "rgb mode");
        }
}

TEST(FilmResponse, DefersToTheSensorWithAMaxComponentValue) {
    Sensor sensor;
    sensor.set_max_component_value(0.5f);
    const SampledWavelengths lambda = SampledWavelengths::sample_visible(0.3f, &RGBColorSpace::srgb());
    const Radiance3 l(SampledSpectrum(4, 2, 1, 3));
    const FilmResponse response(sensor, lambda);
    const Color3 limited = sensor.to_film(l, lambda);
    EXPECT_LT(limited.luminance(), sensor.to_rgb(l, lambda).luminance()); // the limit applies here
    const Color3 f = response.film(l);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(f[c], limited[c]);
}

} // namespace
} // namespace illum
