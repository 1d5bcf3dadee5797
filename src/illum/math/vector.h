// Vectors, points and normals: distinct types so that only geometric operations that make sense compile
// (point - point is a vector, point + point is not; a normal turns with the inverse transpose).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace illum {

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kInvPi = 0.31830988618379067154f;
inline constexpr float kInv4Pi = 0.07957747154594766788f;
inline constexpr float kPiOver2 = 1.57079632679489661923f;
inline constexpr double kPiD = 3.14159265358979323846;

struct Vector2f {
    float x = 0, y = 0;
    constexpr Vector2f() = default;
    constexpr Vector2f(float x_, float y_) : x(x_), y(y_) {}
    constexpr float operator[](int i) const { return i == 0 ? x : y; }
    constexpr Vector2f operator+(Vector2f o) const { return {x + o.x, y + o.y}; }
    constexpr Vector2f operator-(Vector2f o) const { return {x - o.x, y - o.y}; }
    constexpr Vector2f operator*(float s) const { return {x * s, y * s}; }
};

struct Point2f {
    float x = 0, y = 0;
    constexpr Point2f() = default;
    constexpr Point2f(float x_, float y_) : x(x_), y(y_) {}
    constexpr float operator[](int i) const { return i == 0 ? x : y; }
    float& operator[](int i) { return i == 0 ? x : y; }
    constexpr Point2f operator+(Vector2f v) const { return {x + v.x, y + v.y}; }
    constexpr Vector2f operator-(Point2f o) const { return {x - o.x, y - o.y}; }
    constexpr bool operator==(const Point2f&) const = default;
};

struct Point2i {
    int x = 0, y = 0;
    constexpr bool operator==(const Point2i&) const = default;
};

struct Vector3f {
    float x = 0, y = 0, z = 0;
    constexpr Vector3f() = default;
    constexpr Vector3f(float x_, float y_, float z_) : x(x_), y(y_), z(z_) {}
    constexpr float operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    float& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
    constexpr Vector3f operator+(Vector3f o) const { return {x + o.x, y + o.y, z + o.z}; }
    constexpr Vector3f operator-(Vector3f o) const { return {x - o.x, y - o.y, z - o.z}; }
    constexpr Vector3f operator-() const { return {-x, -y, -z}; }
    constexpr Vector3f operator*(float s) const { return {x * s, y * s, z * s}; }
    // One division and three multiplications (as pbrt does): division is the slowest arithmetic there is.
    constexpr Vector3f operator/(float s) const {
        float inv = 1 / s;
        return {x * inv, y * inv, z * inv};
    }
    Vector3f& operator+=(Vector3f o) { return *this = *this + o; }
    Vector3f& operator-=(Vector3f o) { return *this = *this - o; }
    Vector3f& operator*=(float s) { return *this = *this * s; }
    constexpr bool operator==(const Vector3f&) const = default;
};
constexpr Vector3f operator*(float s, Vector3f v) { return v * s; }

struct Normal3f {
    float x = 0, y = 0, z = 0;
    constexpr Normal3f() = default;
    constexpr Normal3f(float x_, float y_, float z_) : x(x_), y(y_), z(z_) {}
    constexpr explicit Normal3f(Vector3f v) : x(v.x), y(v.y), z(v.z) {}
    constexpr explicit operator Vector3f() const { return {x, y, z}; }
    constexpr float operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    constexpr Normal3f operator+(Normal3f o) const { return {x + o.x, y + o.y, z + o.z}; }
    constexpr Normal3f operator-() const { return {-x, -y, -z}; }
    constexpr Normal3f operator*(float s) const { return {x * s, y * s, z * s}; }
    Normal3f& operator+=(Normal3f o) { return *this = *this + o; }
    constexpr bool operator==(const Normal3f&) const = default;
};
constexpr Normal3f operator*(float s, Normal3f n) { return n * s; }

struct Point3f {
    float x = 0, y = 0, z = 0;
    constexpr Point3f() = default;
    constexpr Point3f(float x_, float y_, float z_) : x(x_), y(y_), z(z_) {}
    constexpr explicit Point3f(Vector3f v) : x(v.x), y(v.y), z(v.z) {}
    constexpr explicit operator Vector3f() const { return {x, y, z}; }
    constexpr float operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    float& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
    constexpr Point3f operator+(Vector3f v) const { return {x + v.x, y + v.y, z + v.z}; }
    constexpr Point3f operator-(Vector3f v) const { return {x - v.x, y - v.y, z - v.z}; }
    constexpr Vector3f operator-(Point3f o) const { return {x - o.x, y - o.y, z - o.z}; }
    Point3f& operator+=(Vector3f v) { return *this = *this + v; }
    constexpr bool operator==(const Point3f&) const = default;
};

constexpr float dot(Vector3f a, Vector3f b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr float dot(Normal3f a, Vector3f b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr float dot(Vector3f a, Normal3f b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr float dot(Normal3f a, Normal3f b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline float abs_dot(Vector3f a, Vector3f b) { return std::abs(dot(a, b)); }
inline float abs_dot(Normal3f a, Vector3f b) { return std::abs(dot(a, b)); }
inline float abs_dot(Vector3f a, Normal3f b) { return std::abs(dot(a, b)); }

// Cross product with the difference-of-products evaluated in double to avoid cancellation.
inline Vector3f cross(Vector3f a, Vector3f b) {
    double ax = a.x, ay = a.y, az = a.z, bx = b.x, by = b.y, bz = b.z;
    return {float(ay * bz - az * by), float(az * bx - ax * bz), float(ax * by - ay * bx)};
}

inline float length_squared(Vector3f v) { return dot(v, v); }
inline float length(Vector3f v) { return std::sqrt(dot(v, v)); }
inline Vector3f normalize(Vector3f v) { return v / length(v); }
inline Normal3f normalize(Normal3f n) { return n * (1.0f / std::sqrt(dot(n, n))); }
inline float distance(Point3f a, Point3f b) { return length(a - b); }
inline float distance_squared(Point3f a, Point3f b) { return length_squared(a - b); }
inline Vector3f abs(Vector3f v) { return {std::abs(v.x), std::abs(v.y), std::abs(v.z)}; }
inline Vector3f abs(Point3f p) { return {std::abs(p.x), std::abs(p.y), std::abs(p.z)}; }
inline float max_component(Vector3f v) { return std::max({v.x, v.y, v.z}); }
inline int max_dimension(Vector3f v) { return (v.x > v.y) ? (v.x > v.z ? 0 : 2) : (v.y > v.z ? 1 : 2); }
inline Point3f min(Point3f a, Point3f b) {
    return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
inline Point3f max(Point3f a, Point3f b) {
    return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}

// Turns n to the hemisphere of v.
inline Normal3f face_forward(Normal3f n, Vector3f v) { return dot(n, v) < 0 ? -n : n; }
inline Vector3f face_forward(Vector3f n, Vector3f v) { return dot(n, v) < 0 ? -n : n; }

// Affine combination b0 p0 + b1 p1 + b2 p2 with b0 + b1 + b2 = 1 (barycentric interpolation).
inline Point3f barycentric(Point3f p0, Point3f p1, Point3f p2, float b0, float b1, float b2) {
    return {b0 * p0.x + b1 * p1.x + b2 * p2.x, b0 * p0.y + b1 * p1.y + b2 * p2.y,
            b0 * p0.z + b1 * p1.z + b2 * p2.z};
}
inline Point3f lerp(float t, Point3f a, Point3f b) { return a + (b - a) * t; }

inline bool is_finite(Vector3f v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
inline bool is_finite(Point3f p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

// Spherical coordinates in the local frame (z up): θ from +z, φ from +x towards +y.
inline Vector3f spherical_direction(float sin_theta, float cos_theta, float phi) {
    return {std::clamp(sin_theta, -1.0f, 1.0f) * std::cos(phi),
            std::clamp(sin_theta, -1.0f, 1.0f) * std::sin(phi), std::clamp(cos_theta, -1.0f, 1.0f)};
}
inline float spherical_theta(Vector3f v) { return std::acos(std::clamp(v.z, -1.0f, 1.0f)); }
inline float spherical_phi(Vector3f v) {
    float p = std::atan2(v.y, v.x);
    return p < 0 ? p + 2 * kPi : p;
}

inline float safe_sqrt(float x) { return std::sqrt(std::max(0.0f, x)); }
inline float safe_acos(float x) { return std::acos(std::clamp(x, -1.0f, 1.0f)); }
inline float safe_asin(float x) { return std::asin(std::clamp(x, -1.0f, 1.0f)); }
template <typename T>
constexpr T sqr(T x) {
    return x * x;
}

} // namespace illum
