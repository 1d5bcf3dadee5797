#include "illum/geometry/curves.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "illum/util/error.h"

namespace illum {

namespace {

SourceLocation param_loc(const ShapeDesc& s, const char* name) {
    const Param* p = s.params.find(name);
    return p ? p->loc : s.loc;
}

// Degree elevation of a quadratic Bézier (p0, p1, p2): the cubic with the same curve.
std::array<Point3f, 4> elevate(Point3f p0, Point3f p1, Point3f p2) {
    return {p0, lerp(2.0f / 3, p0, p1), lerp(2.0f / 3, p2, p1), p2};
}

// A uniform quadratic B-spline segment (c0, c1, c2) as a quadratic Bézier: the knot midpoints and c1.
std::array<Point3f, 4> quadratic_bspline(Point3f c0, Point3f c1, Point3f c2) {
    return elevate(lerp(0.5f, c0, c1), c1, lerp(0.5f, c1, c2));
}

// A uniform cubic B-spline segment (c0..c3) as a cubic Bézier (the standard change of basis:
// b0 = (c0 + 4c1 + c2)/6, b1 = (2c1 + c2)/3, b2 = (c1 + 2c2)/3, b3 = (c1 + 4c2 + c3)/6).
std::array<Point3f, 4> cubic_bspline(Point3f c0, Point3f c1, Point3f c2, Point3f c3) {
    auto combo = [](float a, Point3f p, float b, Point3f q, float c, Point3f r) {
        return Point3f(Vector3f(p) * a + Vector3f(q) * b + Vector3f(r) * c);
    };
    return {combo(1.0f / 6, c0, 4.0f / 6, c1, 1.0f / 6, c2), lerp(1.0f / 3, c1, c2), lerp(2.0f / 3, c1, c2),
            combo(1.0f / 6, c1, 4.0f / 6, c2, 1.0f / 6, c3)};
}

// Spherical interpolation of unit normals a → b (pbrt-v4's ribbon normal along u).
Vector3f slerp(float u, Vector3f a, Vector3f b) {
    float c = std::clamp(dot(a, b), -1.0f, 1.0f);
    float angle = std::acos(c);
    if (angle < 1e-4f) return normalize(a + (b - a) * u);
    float s = std::sin(angle);
    return a * (std::sin((1 - u) * angle) / s) + b * (std::sin(u * angle) / s);
}

// v rotated by `angle` radians about the unit axis k (Rodrigues), for v ⊥ k.
Vector3f rotate_perpendicular(Vector3f v, Vector3f k, float angle) {
    return v * std::cos(angle) + cross(k, v) * std::sin(angle);
}

} // namespace

Point3f bezier_point(const std::array<Point3f, 4>& c, float u, Vector3f* derivative) {
    Point3f a[3] = {lerp(u, c[0], c[1]), lerp(u, c[1], c[2]), lerp(u, c[2], c[3])};
    Point3f b[2] = {lerp(u, a[0], a[1]), lerp(u, a[1], a[2])};
    if (derivative) {
        // 3 (b1 - b0), or at an end where two control points coincide, the chord of the other two.
        Vector3f d = (b[1] - b[0]) * 3;
        if (length_squared(d) == 0) d = u < 0.5f ? c[2] - c[0] : c[3] - c[1];
        if (length_squared(d) == 0) d = c[3] - c[0];
        *derivative = d;
    }
    return lerp(u, b[0], b[1]);
}

void Curves::append(const Curves& other) {
    cp.insert(cp.end(), other.cp.begin(), other.cp.end());
    width.insert(width.end(), other.width.begin(), other.width.end());
    normal.insert(normal.end(), other.normal.begin(), other.normal.end());
    tessellation = std::max(tessellation, other.tessellation);
}

Bounds3f Curves::bounds() const {
    Bounds3f b;
    for (std::size_t i = 0; i < cp.size(); ++i) {
        Bounds3f s;
        for (Point3f p : cp[i]) s.extend(p);
        float r = 0.5f * std::max(width[i][0], width[i][1]);
        b.extend(s.lo - Vector3f(r, r, r));
        b.extend(s.hi + Vector3f(r, r, r));
    }
    return b;
}

void Curves::fill_hit(std::uint32_t seg, float u, float t, const Ray& ray, SurfaceHit* hit) const {
    u = std::clamp(u, 0.0f, 1.0f);
    Vector3f dpdu;
    Point3f axis = bezier_point(cp[seg], u, &dpdu);
    float w = std::max(width[seg][0] + (width[seg][1] - width[seg][0]) * u, 1e-30f);
    Vector3f d = normalize(ray.d);
    Point3f p = ray.o + ray.d * t;
    Vector3f tangent = normalize(dpdu);
    // dp/dv across the width: d × dp/du for the ray-facing types, n × dp/du for ribbons.
    Vector3f across = type == CurveType::Ribbon
                          ? cross(slerp(u, Vector3f(normal[seg][0]), Vector3f(normal[seg][1])), tangent)
                          : cross(d, tangent);
    if (!(length_squared(across) > 1e-12f)) { // the ray (or the normal) along the curve
        Frame f = Frame::from_z(tangent);
        across = f.s;
    }
    across = normalize(across);
    float v = std::clamp(0.5f + dot(p - axis, across) / w, 0.0f, 1.0f);
    Vector3f dpdv = across * w;
    if (type == CurveType::Cylinder) // pbrt-v4: dp/dv turned by -θ about dp/du, θ = lerp(v, -90°, 90°)
        dpdv = rotate_perpendicular(dpdv, tangent, -(v - 0.5f) * kPi);
    Vector3f n = normalize(cross(dpdu, dpdv));
    if (flip_normal) n = -n;
    hit->p = p;
    hit->p_error = Vector3f(w, w, w); // pbrt-v4's bound: the hit lies within the curve's width
    hit->t = t;
    hit->wo = -d;
    hit->n = Normal3f(n);
    hit->ns = hit->n;
    hit->dpdu = dpdu;
    hit->uv = {u, v};
}

std::unique_ptr<Curves> create_curves(const ShapeDesc& s, Diagnostics& diag) {
    const ParamSet& ps = s.params;
    float width = ps.get_float("width", 1);
    float width0 = ps.get_float("width0", width), width1 = ps.get_float("width1", width);
    for (const char* name : {"width", "width0", "width1"}) {
        float v = ps.get_float(name, 1);
        if (!(v >= 0) || !std::isfinite(v))
            throw Error(param_loc(s, name),
                        fmt::format("curve \"{}\" must be finite and >= 0, not {}", name, v));
    }
    int degree = ps.get_int("degree", 3);
    if (degree != 2 && degree != 3)
        throw Error(param_loc(s, "degree"), fmt::format("curve degree must be 2 or 3, not {}", degree));
    std::string basis = ps.get_string("basis", "bezier");
    if (basis != "bezier" && basis != "bspline")
        throw Error(param_loc(s, "basis"),
                    fmt::format("curve basis must be \"bezier\" or \"bspline\", not \"{}\"", basis));
    std::string type_name = ps.get_string("type", "flat");
    auto curves = std::make_unique<Curves>();
    if (type_name == "flat")
        curves->type = CurveType::Flat;
    else if (type_name == "cylinder")
        curves->type = CurveType::Cylinder;
    else if (type_name == "ribbon")
        curves->type = CurveType::Ribbon;
    else
        throw Error(
            param_loc(s, "type"),
            fmt::format("curve type must be \"flat\", \"cylinder\" or \"ribbon\", not \"{}\"", type_name));
    // pbrt-v4 splits each segment 2^splitdepth times for its own intersector; Embree needs no splitting, so
    // the value is read (and checked) but changes nothing.
    if (int sd = ps.get_int("splitdepth", 3); sd < 0)
        throw Error(param_loc(s, "splitdepth"), fmt::format("curve splitdepth must be >= 0, not {}", sd));

    std::vector<Point3f> cp = ps.get_point3s("P");
    std::size_t n_cp = cp.size(), nd = std::size_t(degree), segments = 0;
    if (basis == "bezier") {
        if (n_cp < nd + 1 || (n_cp - 1) % nd != 0)
            throw Error(param_loc(s, "P"),
                        fmt::format("curve has {} control points: a degree {} Bézier curve needs {} + n·{}",
                                    n_cp, degree, degree + 1, degree));
        segments = (n_cp - 1) / nd;
    } else {
        if (n_cp < nd + 1)
            throw Error(param_loc(s, "P"),
                        fmt::format("curve has {} control points: a degree {} B-spline needs at least {}",
                                    n_cp, degree, degree + 1));
        segments = n_cp - nd;
    }
    std::vector<Normal3f> normals = ps.get_normals("N");
    if (curves->type == CurveType::Ribbon) {
        if (normals.size() != segments + 1)
            throw Error(param_loc(s, "N"),
                        fmt::format("a ribbon curve of {} segment{} needs {} normals \"N\", not {}", segments,
                                    segments == 1 ? "" : "s", segments + 1, normals.size()));
    } else if (!normals.empty()) {
        diag.unsupported(param_loc(s, "N"),
                         "curve normals \"N\" are only used by \"ribbon\" curves (as in pbrt-v4)");
    }

    const Transform& m = s.world_from_object;
    // Widths are lengths in object space: scaled by the transform's mean linear scale, |det|^(1/3) (exact
    // for the similarity transforms hair scenes use; pbrt-v4 intersects in object space).
    const Matrix4& mm = m.matrix();
    double det = mm(0, 0) * (mm(1, 1) * mm(2, 2) - mm(1, 2) * mm(2, 1)) -
                 mm(0, 1) * (mm(1, 0) * mm(2, 2) - mm(1, 2) * mm(2, 0)) +
                 mm(0, 2) * (mm(1, 0) * mm(2, 1) - mm(1, 1) * mm(2, 0));
    float scale = float(std::cbrt(std::abs(det)));
    curves->flip_normal = s.reverse_orientation != m.swaps_handedness();
    std::size_t offset = 0;
    for (std::size_t seg = 0; seg < segments; ++seg) {
        std::array<Point3f, 4> b;
        if (basis == "bezier") {
            b = degree == 2
                    ? elevate(cp[offset], cp[offset + 1], cp[offset + 2])
                    : std::array<Point3f, 4>{cp[offset], cp[offset + 1], cp[offset + 2], cp[offset + 3]};
            offset += nd;
        } else {
            b = degree == 2 ? quadratic_bspline(cp[offset], cp[offset + 1], cp[offset + 2])
                            : cubic_bspline(cp[offset], cp[offset + 1], cp[offset + 2], cp[offset + 3]);
            ++offset;
        }
        for (Point3f& p : b) p = m(p);
        curves->cp.push_back(b);
        float l0 = 0;
        for (int i = 0; i < 2; ++i) {
            Vector3f dd =
                (b[std::size_t(i)] - b[std::size_t(i) + 1]) - (b[std::size_t(i) + 1] - b[std::size_t(i) + 2]);
            l0 = std::max({l0, std::abs(dd.x), std::abs(dd.y), std::abs(dd.z)});
        }
        float eps = 0.05f * scale * std::max(width0, width1);
        if (l0 > 0 && eps > 0) {
            double x = 1.41421356 * 6 * l0 / (8 * eps);
            int r = x >= 4096 ? 6 : (x >= 1 ? int(std::log2(x)) / 2 : 0); // 4096 = 4^6; an overflow too
            curves->tessellation = std::max(curves->tessellation, 1 << r);
        }
        // pbrt-v4: the curve's width interpolated linearly over the segments, by segment index.
        float f0 = float(seg) / float(segments), f1 = float(seg + 1) / float(segments);
        curves->width.push_back(
            {scale * (width0 + (width1 - width0) * f0), scale * (width0 + (width1 - width0) * f1)});
        if (curves->type == CurveType::Ribbon) {
            std::array<Normal3f, 2> n;
            for (int k = 0; k < 2; ++k) {
                Normal3f w = m(normals[seg + std::size_t(k)]);
                float len = length(Vector3f(w));
                if (!(len > 0) || !std::isfinite(len))
                    throw Error(param_loc(s, "N"), "curve normals \"N\" must be non-zero and finite");
                n[std::size_t(k)] = Normal3f(Vector3f(w) / len);
            }
            curves->normal.push_back(n);
        }
    }
    for (const auto& c : curves->cp)
        for (Point3f p : c)
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                throw Error(param_loc(s, "P"), "curve control points must be finite");
    return curves;
}

} // namespace illum
