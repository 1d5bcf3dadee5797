// The multiple-importance weights of vertex connection and merging (Georgiev, Křivánek, Davidovič,
// Slusallek, "Light Transport Simulation with Vertex Connection and Merging", SIGGRAPH Asia 2012, §4-5,
// and its technical report "Implementing Vertex Connection and Merging", 2012).
//
// A path x_0 (on a light) … x_k (on the camera) can be made by these techniques:
//   VC(s): a connection between the light subpath x_0..x_{s-1} and the camera subpath x_s..x_k (BDPT's
//          strategy (s, t = k + 1 - s), Veach 1997 §10.2), with density
//              p_VC(s) = Π_{i<s} p→(x_i) · Π_{i>=s} p←(x_i)
//          (p→ the area density of x_i from the light side, p← from the camera side), times
//          n_VC = 1 light subpath per camera subpath, or n_LT = N_light / N_pixels for s = k (t = 1, light
//          tracing: each of the N_light subpaths may land in the pixel);
//   VM(j): merging at an interior non-specular vertex x_j (1 <= j <= k-1): the light subpath reaches x_j,
//          the camera subpath reaches a point within r of it; by the paper's eq. 10-11 (and the report's
//          §2) its density is
//              p_VM(j) = p_VC(j + 1) · p←(x_j) · η_VCM,   η_VCM = N_light π r²
//          (the acceptance probability π r² p←(x_j) of the camera's vertex, over any of N_light subpaths).
// Each estimator is weighted by the balance (β = 1) or power (β = 2) heuristic over every technique
// enabled, w_X = p_X^β / Σ_Y p_Y^β (paper eq. 12). The sum is evaluated, as in Veach's eq. 10.9 and
// bdpt_integrator.cpp, from ratios of the vertices' densities: moving the connection towards the camera
// across x_i multiplies p_VC by p→(x_i)/p←(x_i), towards the light by the inverse. (The paper's
// recursive quantities dVCM, dVC, dVM are the running sums of these ratios along a subpath; here the sum
// is taken over the whole path at each connection and merge, which costs O(k) but shares the densities
// with BDPT's path vertices, media and all.)
//
// Delta vertices (a specular lobe sampled) have both densities 0, remapped to 1; a connection may not
// touch one, merging may not happen at one. A vertex is mergeable where its BSDF has a non-specular part
// and its scattering in this path was not specular.
#pragma once

namespace illum {

// What the weights read of a path vertex.
struct MisVertex {
    float fwd = 0;            // the density with which its own subpath made it (area; see path_vertex.h)
    float rev = 0;            // the density with which the other subpath would make it
    bool delta = false;       // its scattering in the path was specular
    bool nonspecular = false; // a surface whose BSDF has a non-specular part (merging can happen here)
    bool mergeable() const { return nonspecular && !delta; }
};

// Which techniques a render uses and their constants.
struct MisTechniques {
    bool vc = true;    // vertex connection: every BDPT strategy (off: only s = 0, the emitter hit)
    bool vm = true;    // vertex merging at interior vertices
    float eta_vcm = 0; // N_light π r²
    float n_lt = 1;    // N_light / N_pixels: light tracing's subpaths per camera subpath
    float power = 1;   // 1: balance heuristic, 2: power heuristic
};

// Σ over the enabled techniques Y of (p_Y / p_VC(s))^β for the path of light vertices lv[0..s) and
// camera vertices cv[0..t) (cv[0] on the camera) joined between lv[s-1] and cv[t-1]. The densities of the
// vertices next to the joint must already be those of this path (the caller sets them as BDPT does).
// light0_delta: lv[0] (or, for s = 0, the emitter) is a delta light.
// light_tail / camera_tail (optional, from subpath_tails over the same subpaths): the terms beyond the two
// vertices next to the joint, which do not change from one join to the next (the paper's dVCM, dVC, dVM
// hold the same running sums); with them a join costs O(1) instead of O(s + t).
float technique_sum(const MisVertex* lv, int s, const MisVertex* cv, int t, bool light0_delta,
                    const MisTechniques& m, const float* light_tail = nullptr,
                    const float* camera_tail = nullptr);

// The running sums of a subpath's own terms: tail[i] is the part of technique_sum's loop over this subpath
// from vertex i down to its end (the light, or the camera's first vertex), with the ratio 1 before vertex
// i. camera: v[0] is on the camera (tail[0] = 0); else v[0] is on the light.
void subpath_tails(const MisVertex* v, int n, bool camera, bool light0_delta, const MisTechniques& m,
                   float* tail);

// p_VC(s, t) itself in the same units as technique_sum's terms: n^β when the connection is one of the
// enabled techniques (n = n_lt for t = 1), else 0.
float connection_term(const MisVertex* lv, int s, const MisVertex* cv, int t, const MisTechniques& m);

} // namespace illum
