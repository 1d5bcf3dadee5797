#include "illum/render/vcm_mis.h"

#include <cmath>

namespace illum {

namespace {

float remap0(float f) { return f != 0 ? f : 1.0f; }

float power_of(float x, float beta) { return beta == 1 ? x : (beta == 2 ? x * x : std::pow(x, beta)); }

// Whether VC(s', t') is one of the techniques: t' >= 1, not the light's own point seen by the camera
// (s' = t' = 1, which neither BDPT nor VCM uses), and with vc off only the emitter hit s' = 0.
bool vc_enabled(int s, int t, const MisTechniques& m) {
    if (t < 1 || (s == 1 && t == 1)) return false;
    return m.vc || s == 0;
}

} // namespace

float connection_term(const MisVertex* lv, int s, const MisVertex* cv, int t, const MisTechniques& m) {
    if (!vc_enabled(s, t, m)) return 0;
    if (s > 0 && lv[s - 1].delta) return 0;
    if (cv[t - 1].delta) return 0;
    return power_of(t == 1 ? m.n_lt : 1.0f, m.power);
}

float technique_sum(const MisVertex* lv, int s, const MisVertex* cv, int t, bool light0_delta,
                    const MisTechniques& m, const float* light_tail, const float* camera_tail) {
    float sum = connection_term(lv, s, cv, t, m);
    if (s == 0 && light0_delta) sum = 0;
    // Towards the camera: after crossing cv[i], ri = p_VC(s + t - i) / p_VC(s).
    float ri = 1;
    for (int i = t - 1; i > 0; --i) {
        if (camera_tail && i == t - 3) {
            sum += power_of(ri, m.power) * camera_tail[i];
            break;
        }
        ri *= remap0(cv[i].rev) / remap0(cv[i].fwd);
        const int s2 = s + t - i, t2 = i;
        if (vc_enabled(s2, t2, m) && !cv[i].delta && !cv[i - 1].delta)
            sum += power_of(t2 == 1 ? ri * m.n_lt : ri, m.power);
        // VM at x_j = cv[i] (j = s2 - 1): p_VC(j + 1) p←(x_j) η; never at the emitter x_0.
        if (m.vm && cv[i].mergeable() && !(s == 0 && i == t - 1))
            sum += power_of(ri * remap0(cv[i].fwd) * m.eta_vcm, m.power);
    }
    // Towards the light: before crossing lv[i], ri = p_VC(i + 1) / p_VC(s); after, p_VC(i) / p_VC(s).
    ri = 1;
    for (int i = s - 1; i >= 0; --i) {
        if (light_tail && i == s - 3) {
            sum += power_of(ri, m.power) * light_tail[i];
            break;
        }
        if (m.vm && i >= 1 && lv[i].mergeable()) sum += power_of(ri * remap0(lv[i].rev) * m.eta_vcm, m.power);
        ri *= remap0(lv[i].rev) / remap0(lv[i].fwd);
        const bool delta_before = i > 0 ? lv[i - 1].delta : light0_delta;
        if (vc_enabled(i, s + t - i, m) && !lv[i].delta && !delta_before) sum += power_of(ri, m.power);
    }
    return sum;
}

void subpath_tails(const MisVertex* v, int n, bool camera, bool light0_delta, const MisTechniques& m,
                   float* tail) {
    // The loops of technique_sum from vertex i on, as a recursion over i (each term is a product of
    // ratios, so the ratio before vertex i factors out: Σ (r x)^β = r^β Σ x^β).
    float below = 0;
    for (int i = 0; i < n; ++i) {
        const float rho = power_of(remap0(v[i].rev) / remap0(v[i].fwd), m.power);
        float t = 0;
        if (camera) {
            if (i == 0) {
                tail[0] = 0;
                continue;
            }
            // Beyond the joint's neighbours the connection VC(s', t' = i) has s' >= 1 and is not (1, 1).
            if (m.vc && !v[i].delta && !v[i - 1].delta) t += power_of(i == 1 ? m.n_lt : 1.0f, m.power);
            if (m.vm && v[i].mergeable()) t += power_of(remap0(v[i].fwd) * m.eta_vcm, m.power);
            tail[i] = rho * (t + below);
        } else {
            const float vm =
                m.vm && i >= 1 && v[i].mergeable() ? power_of(remap0(v[i].rev) * m.eta_vcm, m.power) : 0.0f;
            const bool delta_before = i > 0 ? v[i - 1].delta : light0_delta;
            if ((m.vc || i == 0) && !v[i].delta && !delta_before) t += 1;
            tail[i] = vm + rho * (t + below);
        }
        below = tail[i];
    }
}

} // namespace illum
