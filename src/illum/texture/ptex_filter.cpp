#include "illum/texture/ptex_filter.h"

#include <algorithm>
#include <cmath>

namespace illum {

namespace {

// The uniform cubic B-spline on [-2, 2] (Mitchell-Netravali B = 1, C = 0).
float bspline(float x) {
    x = std::abs(x);
    if (x < 1) return (0.5f * x - 1) * x * x + 2.0f / 3;
    if (x < 2) {
        float t = 2 - x;
        return t * t * t / 6;
    }
    return 0;
}

// The cubic Hermite step on [-1, 1]: 2|x|³ - 3x² + 1.
float hermite(float x) {
    x = std::abs(x);
    return x < 1 ? (2 * x - 3) * x * x + 1 : 0;
}

// The taps of one axis: weights w[0..n) on the texels start..start+n-1 of a 2^res_log2 resolution.
struct Axis {
    static constexpr int kMax = 16;
    int res_log2 = 0, start = 0, n = 0;
    float w[kMax] = {};

    float sum() const {
        float s = 0;
        for (int i = 0; i < n; ++i) s += w[i];
        return s;
    }
    void strip_zeros() {
        int lead = 0;
        while (lead < n - 1 && w[lead] == 0) ++lead;
        if (lead > 0) {
            std::copy(w + lead, w + n, w);
            start += lead;
            n -= lead;
        }
        while (n > 1 && w[n - 1] == 0) --n;
    }
    // Each weight split in two over the texels of twice the resolution.
    void upres() {
        for (int i = n - 1; i >= 0; --i) w[2 * i] = w[2 * i + 1] = w[i] / 2;
        n *= 2;
        start *= 2;
        ++res_log2;
    }
};

// One axis of Ptex's width-4 kernel (PtexWidth4Filter::buildKernelAxis without lerp): u in [0, 1], width
// uw, for a face of 2^face_log2 texels.
Axis build_axis(float u, float uw, int face_log2) {
    Axis a;
    const float min_width = std::ldexp(1.0f, -face_log2);
    if (!(uw > min_width)) uw = min_width; // at least a texel (and a NaN width is one texel)
    if (uw >= 0.25f) {
        if (uw < 0.5f) { // the 4-texel reduction, the B-spline at unit spacing, the taps in even pairs
            a.res_log2 = 2;
            float upix = u * 4 - 0.5f;
            int u1 = int(std::ceil(upix - 2)), u2 = int(std::ceil(upix + 2));
            u1 &= ~1;
            u2 = (u2 + 1) & ~1;
            a.start = u1;
            a.n = u2 - u1;
            for (int i = 0; i < a.n; ++i) a.w[i] = bspline(float(u1) - upix + float(i));
        } else if (uw < 1) { // the 2-texel reduction, the Hermite kernel widened with the footprint
            a.res_log2 = 1;
            float upix = u * 2 - 0.5f;
            a.start = int(std::floor(u - 0.5f)) * 2;
            a.n = 4;
            float s = 1 / (uw * 1.5f + 0.5f);
            for (int i = 0; i < a.n; ++i) a.w[i] = hermite((float(a.start) - upix + float(i)) * s);
        } else { // the face's mean, blended with the neighbour's
            a.res_log2 = 0;
            float upix = u - 0.5f, ui = std::floor(upix);
            a.start = int(ui);
            a.n = 2;
            a.w[0] = hermite(upix - ui);
            a.w[1] = 1 - a.w[0];
        }
        return a;
    }
    // The resolution where the width is between one and two texels: ceil(log2(1/uw)).
    int e;
    std::frexp(uw, &e);
    a.res_log2 = 1 - e;
    const float res = std::ldexp(1.0f, a.res_log2);
    const float upix = u * res - 0.5f, uwpix = uw * res;
    int u1 = int(std::ceil(upix - 2 * uwpix)), u2 = int(std::ceil(upix + 2 * uwpix));
    a.start = u1;
    a.n = std::min(u2 - u1, Axis::kMax / 2);
    const float x1 = (float(u1) - upix) / uwpix, step = 1 / uwpix;
    for (int i = 0; i < a.n; ++i) a.w[i] = bspline(x1 + float(i) * step);
    return a;
}

// Taps beyond the face's edges: given to the edge texels, or dropped (black).
void merge_edges(Axis& a, PtexBorder border) {
    const int res = 1 << a.res_log2;
    float merged[Axis::kMax] = {};
    int lo = std::max(a.start, 0), hi = std::min(a.start + a.n, res);
    if (lo >= hi) { // entirely beyond the face (black border only)
        a.n = 0;
        return;
    }
    for (int i = 0; i < a.n; ++i) {
        int t = a.start + i;
        if ((t < 0 || t >= res) && border == PtexBorder::Black) continue;
        merged[std::clamp(t, lo, hi - 1) - lo] += a.w[i];
    }
    a.start = lo;
    a.n = hi - lo;
    std::copy(merged, merged + a.n, a.w);
}

float place(float u, PtexBorder border, bool* black) {
    switch (border) {
    case PtexBorder::Clamp:
        return std::clamp(u, 0.0f, 1.0f);
    case PtexBorder::Periodic:
        return u - std::floor(u);
    case PtexBorder::Black:
        if (u <= -1 || u >= 2) *black = true;
        return u;
    }
    return u;
}

} // namespace

void ptex_filter(const PtexFile& file, int face, float u, float v, float dudx, float dvdx, float dudy,
                 float dvdy, float* out) {
    const int nch = std::min(file.channels, 4);
    std::fill(out, out + nch, 0.0f);
    if (face < 0 || std::size_t(face) >= file.faces.size()) return;
    const PtexFace& f = file.faces[std::size_t(face)];
    if (f.neighbourhood_constant()) {
        for (int c = 0; c < nch; ++c) out[c] = f.level(0, 0)[c] / file.one_value;
        return;
    }
    const float uw = std::abs(dudx) + std::abs(dudy), vw = std::abs(dvdx) + std::abs(dvdy);
    bool black = false;
    u = place(u, file.u_border, &black);
    v = place(v, file.v_border, &black);
    if (black) return;
    Axis ku, kv;
    if (f.subface()) { // built as on the main face, at twice the resolution, then halved
        ku = build_axis(u * 0.5f, uw * 0.5f, f.ulog2 + 1);
        kv = build_axis(v * 0.5f, vw * 0.5f, f.vlog2 + 1);
        if (ku.res_log2 == 0) ku.upres();
        if (kv.res_log2 == 0) kv.upres();
        --ku.res_log2;
        --kv.res_log2;
    } else {
        ku = build_axis(u, uw, f.ulog2);
        kv = build_axis(v, vw, f.vlog2);
    }
    ku.strip_zeros();
    kv.strip_zeros();
    const float weight = ku.sum() * kv.sum();
    merge_edges(ku, file.u_border);
    merge_edges(kv, file.v_border);
    if (!(weight > 0) || ku.n == 0 || kv.n == 0) return;
    // The kernel's resolution never exceeds the face's (its width is at least a texel of the face).
    const int ru = std::min(ku.res_log2, f.ulog2), rv = std::min(kv.res_log2, f.vlog2);
    const float* data = f.level(ru, rv);
    const std::size_t row = std::size_t(1) << ru;
    float acc[4] = {0, 0, 0, 0};
    for (int j = 0; j < kv.n; ++j) {
        const float* texel_row = data + std::size_t(kv.start + j) * row * std::size_t(file.channels);
        for (int i = 0; i < ku.n; ++i) {
            const float wt = ku.w[i] * kv.w[j];
            const float* t = texel_row + std::size_t(ku.start + i) * std::size_t(file.channels);
            for (int c = 0; c < nch; ++c) acc[c] += wt * t[c];
        }
    }
    const float scale = 1 / (weight * file.one_value);
    for (int c = 0; c < nch; ++c) out[c] = acc[c] * scale;
}

} // namespace illum
