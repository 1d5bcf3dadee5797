#include "illum/geometry/motion_steps.h"

#include <algorithm>
#include <cmath>

namespace illum {

namespace {

bool is_diagonal(const Matrix3d& s) {
    double scale = std::abs(s[0]) + std::abs(s[4]) + std::abs(s[8]);
    for (std::size_t i : {1, 2, 3, 5, 6, 7})
        if (std::abs(s[i]) > 1e-12 * scale) return false;
    return true;
}

// R S rewritten as R' U with U upper triangular: the QR decomposition (Gram-Schmidt on the columns) of
// S = Q U gives R' = R Q; a reflection in Q is moved into U's last row so R' stays a rotation.
TransformComponents triangular(TransformComponents c) {
    const Matrix3d& s = c.scale;
    auto col = [&](int j) {
        return std::array<double, 3>{s[std::size_t(j)], s[std::size_t(3 + j)], s[std::size_t(6 + j)]};
    };
    auto dot3 = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    };
    std::array<std::array<double, 3>, 3> q{};
    Matrix3d u{};
    for (int j = 0; j < 3; ++j) {
        std::array<double, 3> v = col(j);
        for (int k = 0; k < j; ++k) {
            double r = dot3(q[std::size_t(k)], col(j));
            u[std::size_t(3 * k + j)] = r;
            for (std::size_t i = 0; i < 3; ++i) v[i] -= r * q[std::size_t(k)][i];
        }
        double len = std::sqrt(dot3(v, v));
        u[std::size_t(4 * j)] = len;
        for (std::size_t i = 0; i < 3; ++i) q[std::size_t(j)][i] = v[i] / len;
    }
    Matrix3d qm; // columns q[0], q[1], q[2]
    for (std::size_t r = 0; r < 3; ++r)
        for (std::size_t k = 0; k < 3; ++k) qm[3 * r + k] = q[k][r];
    double det = qm[0] * (qm[4] * qm[8] - qm[5] * qm[7]) - qm[1] * (qm[3] * qm[8] - qm[5] * qm[6]) +
                 qm[2] * (qm[3] * qm[7] - qm[4] * qm[6]);
    if (det < 0) {
        for (std::size_t r = 0; r < 3; ++r) qm[3 * r + 2] = -qm[3 * r + 2];
        for (std::size_t k = 0; k < 3; ++k) u[6 + k] = -u[6 + k];
    }
    c.rotation = quaternion_from_rotation(multiply(rotation_matrix(c.rotation), qm));
    c.scale = u;
    return c;
}

// The steps at n evenly spaced times of [open, close], each in Embree's form, rotations on consecutive
// shorter arcs.
template <class At>
std::vector<TransformComponents> steps_at(At&& at, int n, double open, double close) {
    std::vector<TransformComponents> steps;
    steps.reserve(std::size_t(n));
    for (int i = 0; i < n; ++i) {
        double t = i == 0 ? open : i == n - 1 ? close : open + (close - open) * i / (n - 1);
        TransformComponents c = at(t);
        if (!is_diagonal(c.scale)) c = triangular(c);
        if (!steps.empty() && dot(steps.back().rotation, c.rotation) < 0) c.rotation = -c.rotation;
        steps.push_back(c);
    }
    return steps;
}

// What Embree makes of two steps at the fraction s between them: T and U linearly, R by slerp.
Matrix4 embree_interpolation(const TransformComponents& a, const TransformComponents& b, double s) {
    TransformComponents c;
    for (std::size_t i = 0; i < 3; ++i) c.translation[i] = (1 - s) * a.translation[i] + s * b.translation[i];
    for (std::size_t i = 0; i < 9; ++i) c.scale[i] = (1 - s) * a.scale[i] + s * b.scale[i];
    c.rotation = slerp(a.rotation, b.rotation, s);
    return c.matrix();
}

bool spans_shutter(const AnimatedTransform& m, double open, double close) {
    return !m.is_animated() || (m.start_time() <= open && m.end_time() >= close);
}

} // namespace

std::vector<TransformComponents> motion_steps(const AnimatedTransform& outer, const AnimatedTransform& inner,
                                              double open, double close) {
    auto product = [&](double t) { return (outer.interpolate(t) * inner.interpolate(t)).matrix(); };
    if (!(close > open)) return {decompose(product(open))};
    auto at = [&](double t) { return decompose(product(t)); };
    if (spans_shutter(outer, open, close) && spans_shutter(inner, open, close)) {
        std::vector<TransformComponents> two = steps_at(at, 2, open, close);
        bool exact = true;
        for (int k = 1; k < 8 && exact; ++k) {
            double s = k / 8.0;
            Matrix4 want = product(open + (close - open) * s), got = embree_interpolation(two[0], two[1], s);
            double size = 1;
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 4; ++c) size = std::max(size, std::abs(want(r, c)));
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 4; ++c) exact = exact && std::abs(want(r, c) - got(r, c)) <= 1e-9 * size;
        }
        if (exact) return two;
    }
    return steps_at(at, kManyMotionSteps, open, close);
}

std::vector<TransformComponents> motion_steps(const AnimatedTransform& motion, double open, double close) {
    if (!(close > open)) return {decompose(motion.interpolate(open).matrix())};
    bool spans = motion.start_time() <= open && motion.end_time() >= close;
    TransformComponents a = motion.components(open), b = motion.components(close);
    int n = spans && is_diagonal(a.scale) && is_diagonal(b.scale) ? 2 : kManyMotionSteps;
    return steps_at([&](double t) { return motion.components(t); }, n, open, close);
}

} // namespace illum
