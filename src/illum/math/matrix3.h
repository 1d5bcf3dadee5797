// 3x3 matrices in double, row-major (colour-space and chromatic-adaptation matrices).
#pragma once

#include <array>
#include <cmath>
#include <optional>

namespace illum {

using Matrix3d = std::array<double, 9>;

inline Matrix3d multiply(const Matrix3d& a, const Matrix3d& b) {
    Matrix3d r{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k)
                r[std::size_t(3 * i + j)] += a[std::size_t(3 * i + k)] * b[std::size_t(3 * k + j)];
    return r;
}

// The inverse by the adjugate over the determinant; nothing for a singular matrix.
inline std::optional<Matrix3d> inverse(const Matrix3d& m) {
    double c00 = m[4] * m[8] - m[5] * m[7], c01 = m[5] * m[6] - m[3] * m[8], c02 = m[3] * m[7] - m[4] * m[6];
    double det = m[0] * c00 + m[1] * c01 + m[2] * c02;
    if (!(std::abs(det) > 0)) return std::nullopt;
    double inv = 1 / det;
    return Matrix3d{c00 * inv, (m[2] * m[7] - m[1] * m[8]) * inv, (m[1] * m[5] - m[2] * m[4]) * inv,
                    c01 * inv, (m[0] * m[8] - m[2] * m[6]) * inv, (m[2] * m[3] - m[0] * m[5]) * inv,
                    c02 * inv, (m[1] * m[6] - m[0] * m[7]) * inv, (m[0] * m[4] - m[1] * m[3]) * inv};
}

} // namespace illum
