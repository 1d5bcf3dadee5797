#include "illum/camera/paraxial.h"

#include "illum/camera/cauchy_glass.h"

namespace illum {

namespace {
struct M2 {
    double a, b, c, d;
    M2 operator*(const M2& o) const {
        return {a * o.a + b * o.c, a * o.b + b * o.d, c * o.a + d * o.c, c * o.b + d * o.d};
    }
};
} // namespace

ParaxialLens paraxial_lens(const LensPrescription& lens, double lambda_nm) {
    M2 m{1, 0, 0, 1};
    double n = 1; // air in front
    for (std::size_t i = 0; i < lens.surfaces.size(); ++i) {
        const LensSurfaceSpec& s = lens.surfaces[i];
        double n_next = s.n_d > 1 ? CauchyGlass::from_abbe(s.n_d, s.abbe).index(lambda_nm) : 1.0;
        if (!s.is_stop()) m = M2{1, 0, -(n_next - n) / (s.radius_mm * 1e-3), 1} * m;
        if (i + 1 < lens.surfaces.size()) m = M2{1, s.thickness_mm * 1e-3 / n_next, 0, 1} * m;
        n = n_next;
    }
    return {m.a, m.b, m.c, m.d};
}

} // namespace illum
