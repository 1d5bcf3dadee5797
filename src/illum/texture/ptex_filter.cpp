#include "illum/texture/ptex_filter.h"

#include <algorithm>
#include <cmath>

namespace illum {

namespace {

enum Edge { kBottom = 0, kRight = 1, kTop = 2, kLeft = 3 };

// The uniform cubic B-spline on [-2, 2]: Mitchell and Netravali's cubic (1988) with B = 1, C = 0, as their
// polynomials evaluated by Horner's rule, x³/2 - x² + 2/3 on [0, 1) and -x³/6 + x² - 2x + 4/3 on [1, 2) (the
// form Ptex evaluates: near |x| = 2 its float rounding gives the same tiny, even negative, weights, which
// decide where a kernel's zero taps are stripped and so which neighbours it reaches).
float bspline(float x) {
    x = std::abs(x);
    const float third = float(1.0 / 3.0);
    if (x < 1) return (0.5f * x - 1.0f) * x * x + (1.0f - third);
    if (x < 2) return (((third - 0.5f) * x + 1.0f) * x - 2.0f) * x + (2.0f - float(2.0 / 3.0));
    return 0;
}

// The cubic Hermite step on [-1, 1]: 2|x|³ - 3x² + 1.
float hermite(float x) {
    x = std::abs(x);
    return x < 1 ? (2 * x - 3) * x * x + 1 : 0;
}

// The taps of one axis: weights w[0..n) on the texels start..start+n-1 of a 2^res_log2 resolution.
struct Axis {
    static constexpr int kMax = 20;
    int res_log2 = 0, start = 0, n = 0;
    float w[kMax] = {};

    int res() const { return 1 << res_log2; }
    float sum() const {
        float s = 0;
        for (int i = 0; i < n; ++i) s += w[i];
        return s;
    }
    void drop_front(int k) {
        std::copy(w + k, w + n, w);
        start += k;
        n -= k;
    }
    void strip_zeros() {
        int lead = 0;
        while (lead < n - 1 && w[lead] == 0) ++lead;
        if (lead > 0) drop_front(lead);
        while (n > 1 && w[n - 1] == 0) --n;
    }
    // Each weight split in two over the texels of twice the resolution.
    void upres() {
        if (2 * n > kMax) return;
        for (int i = n - 1; i >= 0; --i) w[2 * i] = w[2 * i + 1] = w[i] / 2;
        n *= 2;
        start *= 2;
        ++res_log2;
    }
    // Pairs of weights summed onto the texels of half the resolution (an odd first texel alone).
    void downres() {
        int out = 0, i = 0;
        if (start & 1) w[out++] = w[i++];
        for (; i + 1 < n; i += 2) w[out++] = w[i] + w[i + 1];
        if (i < n) w[out++] = w[i];
        start = start >= 0 ? start / 2 : -((-start + 1) / 2);
        n = out;
        --res_log2;
    }
    // The taps below texel 0 given to texel 0 (dropped for a black border).
    void merge_low(PtexBorder border) {
        int k = std::min(-start, n);
        if (k <= 0) return;
        float s = 0;
        for (int i = 0; i < k; ++i) s += w[i];
        if (k == n) { // entirely beyond the edge
            n = border == PtexBorder::Black ? 0 : 1;
            w[0] = s;
            start = 0;
            return;
        }
        drop_front(k);
        if (border != PtexBorder::Black) w[0] += s;
    }
    // The taps beyond the last texel given to it (dropped for a black border).
    void merge_high(PtexBorder border) {
        int k = std::min(start + n - res(), n);
        if (k <= 0) return;
        float s = 0;
        for (int i = n - k; i < n; ++i) s += w[i];
        n -= k;
        if (n == 0) {
            if (border == PtexBorder::Black) return;
            n = 1;
            start = res() - 1;
            w[0] = s;
            return;
        }
        if (border != PtexBorder::Black) w[n - 1] += s;
    }
    // The taps below texel 0 moved to `out`, placed at the far side of a neighbour of the same resolution.
    void split_low(Axis& out) {
        int k = -start;
        out = *this;
        if (k < n) {
            out.n = k;
            out.start = res() - k;
            drop_front(k);
        } else {
            out.start += res();
            start = 0;
            n = 0;
        }
    }
    // The taps beyond the last texel moved to `out`, starting at texel 0 of the neighbour.
    void split_high(Axis& out) {
        int k = start + n - res();
        out = *this;
        if (k < n) {
            std::copy(w + n - k, w + n, out.w);
            out.n = k;
            out.start = 0;
            n -= k;
        } else {
            out.start -= res();
            start = 0;
            n = 0;
        }
    }
    void flip() {
        start = res() - start - n;
        std::reverse(w, w + n);
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

// u placed by the border mode: clamped, wrapped, or (black) flagged beyond one face width.
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

// Ptex's separable kernel: the two axes, and how often it has been turned a quarter counterclockwise.
struct Kernel {
    Axis u, v;
    int rot = 0;
    float weight() const { return u.sum() * v.sum(); }
    // Turned r quarter turns counterclockwise (into an adjacent face's frame).
    void rotate(int r) {
        switch (r & 3) {
        case 1:
            u.flip();
            std::swap(u, v);
            break;
        case 2:
            u.flip();
            v.flip();
            break;
        case 3:
            v.flip();
            std::swap(u, v);
            break;
        default:
            return;
        }
        rot = (rot + r) & 3;
    }
    // From a main face to the subface across edge eid (half its resolution, offset); whether that is the
    // subface the main face's edge points at (the primary one).
    bool main_to_subface(int eid) {
        if (u.res_log2 == 0) u.upres();
        if (v.res_log2 == 0) v.upres();
        if (u.res_log2 > 0) --u.res_log2;
        if (v.res_log2 > 0) --v.res_log2;
        const int ru = u.res(), rv = v.res();
        bool primary = false;
        switch (eid & 3) {
        case kBottom:
            primary = u.start < ru;
            v.start -= rv;
            if (!primary) u.start -= ru;
            break;
        case kRight:
            primary = v.start < rv;
            if (!primary) v.start -= rv;
            break;
        case kTop:
            primary = u.start >= ru;
            if (primary) u.start -= ru;
            break;
        case kLeft:
            primary = v.start >= rv;
            u.start -= ru;
            if (primary) v.start -= rv;
            break;
        }
        return primary;
    }
    void subface_to_main(int eid) {
        switch (eid & 3) {
        case kBottom:
            v.start += v.res();
            break;
        case kRight:
            break;
        case kTop:
            u.start += u.res();
            break;
        case kLeft:
            u.start += u.res();
            v.start += v.res();
            break;
        }
        ++u.res_log2;
        ++v.res_log2;
    }
    // For a corner of valence 5 or more: one kernel, the same along u and v (the sums of the two axes'
    // weights at the coarser of their resolutions), scaled back to `initial` where that does not amplify.
    float make_symmetric(float initial) {
        while (u.res_log2 > v.res_log2) u.downres();
        while (v.res_log2 > u.res_log2) v.downres();
        u.n = v.n = std::min(u.n, v.n);
        float total = 0;
        for (int i = 0; i < u.n; ++i) {
            u.w[i] = v.w[i] = u.w[i] + v.w[i];
            total += u.w[i];
        }
        total *= total;
        const float scale = total == 0 ? 1.0f : initial / total;
        if (scale >= 1) return total;
        if (scale < -1) {
            for (int i = 0; i < u.n; ++i) u.w[i] = -u.w[i];
            return -total;
        }
        for (int i = 0; i < u.n; ++i) u.w[i] *= scale;
        return initial;
    }
};

// Applies kernels to a file's faces and their neighbours (Ptex's PtexSeparableFilter::splitAndApply and
// what it calls), accumulating the weighted texels and the kernel's total weight.
class Application {
public:
    Application(const PtexFile& file, int nch) : file_(file), nch_(nch) {}
    float acc[4] = {0, 0, 0, 0};
    float weight = 0;

    void split_and_apply(Kernel& k, int id) {
        // Subfaces send kernels on through split_and_apply again; a consistent file needs a few steps,
        // a broken one could loop.
        if (++depth_ > kMaxDepth) return;
        const PtexFace& f = file_.faces[std::size_t(id)];
        const bool right = k.u.start + k.u.n > k.u.res(), left = k.u.start < 0;
        const bool top = k.v.start + k.v.n > k.v.res(), bottom = k.v.start < 0;
        if (right || left || top || bottom) {
            Kernel ka, kc;
            auto adjacent = [&](int e) { return f.adjacent_faces[std::size_t(e)] >= 0; };
            // The part of an edge kernel ka beyond the top or bottom edge too: across the corner (through
            // the corner reached over edge top_corner or bottom_corner) where there is a face there, else
            // folded back by the border mode.
            auto corners_of = [&](Kernel& ka, int top_corner, int bottom_corner) {
                if (top) {
                    if (adjacent(kTop)) {
                        kc = ka;
                        ka.v.split_high(kc.v);
                        corner(kc, id, top_corner);
                    } else {
                        ka.v.merge_high(file_.v_border);
                    }
                }
                if (bottom) {
                    if (adjacent(kBottom)) {
                        kc = ka;
                        ka.v.split_low(kc.v);
                        corner(kc, id, bottom_corner);
                    } else {
                        ka.v.merge_low(file_.v_border);
                    }
                }
            };
            if (right) {
                if (adjacent(kRight)) {
                    ka = k;
                    k.u.split_high(ka.u);
                    corners_of(ka, kTop, kRight);
                    across_edge(ka, id, kRight);
                } else {
                    k.u.merge_high(file_.u_border);
                }
            }
            if (left) {
                if (adjacent(kLeft)) {
                    ka = k;
                    k.u.split_low(ka.u);
                    corners_of(ka, kLeft, kBottom);
                    across_edge(ka, id, kLeft);
                } else {
                    k.u.merge_low(file_.u_border);
                }
            }
            if (top) {
                if (adjacent(kTop)) {
                    ka = k;
                    k.v.split_high(ka.v);
                    across_edge(ka, id, kTop);
                } else {
                    k.v.merge_high(file_.v_border);
                }
            }
            if (bottom) {
                if (adjacent(kBottom)) {
                    ka = k;
                    k.v.split_low(ka.v);
                    across_edge(ka, id, kBottom);
                } else {
                    k.v.merge_low(file_.v_border);
                }
            }
        }
        apply(k, id);
    }

private:
    const PtexFace& face(int id) const { return file_.faces[std::size_t(id)]; }

    void across_edge(Kernel& k, int id, int eid) {
        const PtexFace& f = face(id);
        int aid = f.adjacent_faces[std::size_t(eid)], aeid = f.adjacent_edges[std::size_t(eid)];
        const PtexFace* af = &face(aid);
        int rot = eid - aeid + 2;
        if (f.subface() != af->subface()) {
            if (af->subface()) { // main face to subface
                if (!k.main_to_subface(eid)) {
                    const int next = (aeid + 3) % 4; // on to the secondary subface
                    aid = af->adjacent_faces[std::size_t(next)];
                    aeid = af->adjacent_edges[std::size_t(next)];
                    if (aid < 0) return;
                    af = &face(aid);
                    rot += next - aeid + 2;
                }
            } else { // subface to main face
                const bool primary = af->adjacent_faces[std::size_t(aeid)] == id;
                k.subface_to_main(eid - int(primary));
            }
        }
        k.rotate(rot);
        if (af->subface())
            split_and_apply(k, aid);
        else
            apply(k, aid);
    }

    // The faces around the corner at the end of edge eid (walking clockwise from across that edge).
    void corner(Kernel& k, int id, int eid) {
        constexpr int kMaxValence = 10;
        int ids[kMaxValence], edges[kMaxValence];
        int aid = id, aeid = eid, corners = 0;
        const PtexFace* af = &face(id);
        bool prev_subface = af->subface();
        for (int i = 0; i < kMaxValence; ++i) {
            const int prev = aid;
            const int next_id = af->adjacent_faces[std::size_t(aeid)];
            aeid = (af->adjacent_edges[std::size_t(aeid)] + 1) % 4;
            aid = next_id;
            if (aid < 0 || (aid == id && aeid == eid)) {
                corners = i - 2;
                break;
            }
            af = &face(aid);
            ids[i] = aid;
            edges[i] = aeid;
            const bool subface = af->subface();
            if (prev_subface && !subface && af->adjacent_faces[std::size_t((aeid + 3) % 4)] == prev) {
                const bool primary = i == 1; // a subface "tee": on to the main face
                k.subface_to_main(eid + int(primary) * 2);
                k.rotate(eid - aeid + 3 - int(primary));
                split_and_apply(k, aid);
                return;
            }
            prev_subface = subface;
        }
        if (corners == 1) { // valence 4
            corner_face(k, id, eid, ids[1], edges[1]);
        } else if (corners > 1) { // valence 5+: the same symmetric kernel on each corner face
            k.rotate(eid + 2);
            const float initial = k.weight();
            const float symmetric = k.make_symmetric(initial);
            for (int i = 1; i <= corners; ++i) {
                Kernel kc = k;
                corner_face(kc, id, 2, ids[i], edges[i]);
            }
            weight += symmetric * float(corners) - initial;
        } else { // valence 2 or 3: no corner face, its weight is left out
            weight -= k.weight();
        }
    }

    void corner_face(Kernel& k, int id, int eid, int cid, int ceid) {
        const PtexFace &f = face(id), &cf = face(cid);
        if (f.subface() != cf.subface()) {
            if (cf.subface())
                k.main_to_subface(eid + 3);
            else
                k.subface_to_main(eid + 3);
        }
        k.rotate(eid - ceid + 2);
        if (cf.subface())
            split_and_apply(k, cid);
        else
            apply(k, cid);
    }

    // The kernel on one face (at most the face's resolution), its taps inside the face.
    void apply(Kernel& k, int id) {
        if (k.u.n <= 0 || k.v.n <= 0) return;
        const PtexFace& f = face(id);
        while (k.u.res_log2 > f.ulog2) k.u.downres();
        while (k.v.res_log2 > f.vlog2) k.v.downres();
        const int ru = k.u.res_log2, rv = k.v.res_log2;
        if (ru < 0 || rv < 0 || k.u.start < 0 || k.v.start < 0 || k.u.start + k.u.n > (1 << ru) ||
            k.v.start + k.v.n > (1 << rv))
            return; // cannot happen for a consistent file
        const float* data = f.level(ru, rv);
        const std::size_t row = std::size_t(1) << ru, nch = std::size_t(file_.channels);
        float sum[4] = {0, 0, 0, 0};
        for (int j = 0; j < k.v.n; ++j) {
            const float* texel_row = data + std::size_t(k.v.start + j) * row * nch;
            for (int i = 0; i < k.u.n; ++i) {
                const float wt = k.u.w[i] * k.v.w[j];
                const float* t = texel_row + std::size_t(k.u.start + i) * nch;
                for (int c = 0; c < nch_; ++c) sum[c] += wt * t[c];
            }
        }
        // The first two channels turned back into this face's frame; as Ptex, not for a constant value (a
        // constant face or a face's mean), which it adds unturned.
        const bool constant = f.constant() || (ru == 0 && rv == 0);
        if (file_.tangent_vectors && nch_ >= 2 && k.rot > 0 && !constant) {
            const float x = sum[0], y = sum[1];
            const float rx[4] = {x, -y, -x, y}, ry[4] = {y, x, -y, -x};
            sum[0] = rx[k.rot];
            sum[1] = ry[k.rot];
        }
        for (int c = 0; c < nch_; ++c) acc[c] += sum[c];
    }

    static constexpr int kMaxDepth = 64;
    const PtexFile& file_;
    int nch_;
    int depth_ = 0;
};

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
    Kernel k;
    if (f.subface()) { // built as on the main face, at twice the resolution, then halved
        k.u = build_axis(u * 0.5f, uw * 0.5f, f.ulog2 + 1);
        k.v = build_axis(v * 0.5f, vw * 0.5f, f.vlog2 + 1);
        if (k.u.res_log2 == 0) k.u.upres();
        if (k.v.res_log2 == 0) k.v.upres();
        --k.u.res_log2;
        --k.v.res_log2;
    } else {
        k.u = build_axis(u, uw, f.ulog2);
        k.v = build_axis(v, vw, f.vlog2);
    }
    k.u.strip_zeros();
    k.v.strip_zeros();
    Application a(file, nch);
    a.weight = k.weight();
    a.split_and_apply(k, face);
    if (!(a.weight != 0)) return;
    const float scale = 1 / (a.weight * file.one_value);
    for (int c = 0; c < nch; ++c) out[c] = a.acc[c] * scale;
}

} // namespace illum
