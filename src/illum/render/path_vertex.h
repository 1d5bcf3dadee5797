// Path vertices for bidirectional methods (Veach 1997 §10.2-10.3; PBR 4th ed. §16.3 (pbrt-v4's BDPT
// Vertex)): a camera or light subpath is an array of vertices (camera, light, surface, medium), each with
// the throughput β of its subpath prefix and the two area densities that the balance heuristic needs:
//   pdf_fwd: the density with which its own subpath generated it (per unit area at the vertex, with the
//            cosine there when it is on a surface; per steradian for a vertex at infinity),
//   pdf_rev: the density with which the other subpath would have generated it, reversed through its
//            successor (set by the walk, and recomputed for the vertices next to a connection).
// A vertex sampled by a specular lobe is `delta` (both densities 0 there, remapped to 1 by the weight).
//
// As in pbrt-v4, the densities are those of the directions only: free-flight sampling (σ T) is left out
// on both sides, so the weights are not exactly the balance heuristic in media but still sum to one over
// the strategies of every path (each is evaluated from the same per-vertex ratios).
//
// Spectral: a walk samples its distances in one channel (chosen per subpath); β is the one-sample spectral
// MIS estimate over the channel choice, f / avg_c p_c (volpath_integrator.h), which pbrt-v4's BDPT (channel
// 0, f / p_0) is not; the directional densities do not depend on the channel.
//
// The layer is shared: BDPT uses it, and vertex merging can reuse walk(), the densities and connect_g().
#pragma once

#include <cstdint>

#include "illum/bsdf/bxdf.h"
#include "illum/camera/camera.h"
#include "illum/geometry/surface_hit.h"
#include "illum/light/light.h"
#include "illum/math/rng.h"
#include "illum/medium/henyey_greenstein.h"
#include "illum/render/integrator.h"

namespace illum {

enum class VertexType : std::uint8_t { Camera, Light, Surface, Medium };

struct PathVertex {
    VertexType type = VertexType::Surface;
    bool delta = false;
    SampledSpectrum beta;
    float pdf_fwd = 0, pdf_rev = 0;
    Point3f p;
    Vector3f p_error;
    Normal3f ng, ns;                // geometric and shading normals; zero off surfaces (and for the camera)
    Vector3f wo;                    // surface / medium: unit direction towards the previous vertex
    const Medium* medium = nullptr; // medium vertex: its medium; camera / point light: where it sits
    HenyeyGreenstein phase;         // medium vertex
    const Light* light = nullptr;   // light vertex (nullptr: an escaped ray, every infinite light)
    SurfaceHit hit;                 // surface vertex
    BSDF bsdf;                      // surface vertex (in the thread's arena)

    bool on_surface() const { return ng != Normal3f{}; }
    bool is_light() const {
        return type == VertexType::Light || (type == VertexType::Surface && hit.area_light);
    }
    bool is_delta_light() const { return type == VertexType::Light && light && is_delta(light->type()); }
    // A vertex at infinity: an environment or directional light (its p only gives a direction).
    bool is_infinite_light() const {
        return type == VertexType::Light &&
               (!light || light->type() == LightType::Infinite || light->type() == LightType::DeltaDirection);
    }
    bool is_connectible() const {
        switch (type) {
        case VertexType::Medium:
        case VertexType::Camera:
            return true;
        case VertexType::Light:
            return !light || light->type() != LightType::DeltaDirection;
        case VertexType::Surface:
            return bsdf.is_non_specular();
        }
        return false;
    }
    // The medium a ray leaving the vertex towards q travels in.
    const Medium* medium_towards(Point3f q) const;
};

// What the walks and connections read.
struct PathContext {
    const Scene& scene;
    ThreadContext& tc;
    PCG32& rng;         // free-flight and ratio-tracking steps beyond the sampler's first
    float scene_radius; // of the bounding sphere: infinite lights emit from its disk
    float time = 0;     // the pixel sample's time (motion blur), shared by both subpaths
};

// Veach 1997 §5.3 (eq. 5.19): with shading normals the BSDF is not symmetric, and importance transport
// needs the adjoint f*(ωo → ωi) = f(ωi → ωo) |ωo·Ns| |ωi·Ng| / (|ωo·Ng| |ωi·Ns|); this is that factor.
// illum's BSDFs leave it to the integrators (bdpt, vcm, lightpath). ωo: towards the particle's previous
// vertex; ωi: where it goes next.
float shading_normal_adjoint(const SurfaceHit& hit, Vector3f wo, Vector3f wi);

// The density `pdf` per steradian at v of the direction towards `next`, per unit area at next (the cosine
// there when on a surface); unchanged when next is at infinity.
float convert_density(const PathVertex& v, float pdf, const PathVertex& next);
// The unit direction from a to b and 1 / |b - a|² (zero when the two coincide).
struct Segment {
    Vector3f w;
    float inv_d2 = 0;
};
Segment segment(Point3f a, Point3f b);
inline Segment segment(const PathVertex& a, const PathVertex& b) { return segment(a.p, b.p); }
// 1 / |b - a|², zero when the two coincide (the densities towards a coincident vertex are zero).
inline float inv_distance_squared(const PathVertex& a, const PathVertex& b) {
    float d2 = length_squared(b.p - a.p);
    return d2 > 0 ? 1 / d2 : 0.0f;
}

// The density (area, at next) with which v, entered from prev (nullptr for the camera), samples the
// direction towards next. Light vertices: pdf_light.
float vertex_pdf(const PathContext& ctx, const PathVertex& v, const PathVertex* prev, const PathVertex& next);
// The same with the directions at hand: wp towards the vertex v was entered from (unused at the camera and
// at lights), wn towards next, both unit, and inv_d2 = 1 / |next - v|². A connection computes its
// segment once for its two ends (v.wo is already the direction towards v's predecessor in its subpath).
float vertex_pdf(const PathContext& ctx, const PathVertex& v, Vector3f wp, Vector3f wn,
                 const PathVertex& next, float inv_d2);
// What the conversion to area density reads of the vertex a direction leads to: its position, its
// geometric normal (zero off surfaces) and whether it lies at infinity (an environment or directional
// light, where the density stays per solid angle). A merge keeps these of a stored light vertex instead of
// the whole vertex.
struct DensityTarget {
    Point3f p;
    Normal3f ng;
    bool infinite = false;
};
inline DensityTarget density_target(const PathVertex& v) { return {v.p, v.ng, v.is_infinite_light()}; }
// vertex_pdf towards a target, for a v that is not on a light.
float vertex_pdf(const PathContext& ctx, const PathVertex& v, Vector3f wp, Vector3f wn,
                 const DensityTarget& next, float inv_d2);
// The reverse densities next to a join of the light subpath ending in qs (after qs_m) with the camera
// subpath ending in pt (after pt_m), as they are in the joined path (Veach eq. 10.9; the join's ends are
// not delta): pt's from qs, pt_m's through pt from qs, qs's from pt, qs_m's through qs from pt. qs null:
// s = 0, pt is on an emitter (pt_m must exist). Null neighbours leave their entries 0. `joined` is false
// (and all four 0) when qs and pt coincide. The connection's segment is computed once; each end's direction
// towards its predecessor is its wo.
struct JoinDensities {
    float pt_rev = 0, pt_m_rev = 0, qs_rev = 0, qs_m_rev = 0;
    bool joined = true;
};
// What a connection reads at one of its ends v, a surface or medium vertex, with w the unit direction
// towards the other end: the scattering value from v's predecessor towards w (f with the adjoint factor in
// importance mode, or the phase function; without the cosine) and, where the
// BSDF gives them with it (BSDF::eval; phase functions always), the two solid-angle densities
// join_densities needs there, of w given v.wo and of v.wo given w (has_pdfs; else join_densities asks
// the BSDF).
struct EndScattering {
    SampledSpectrum f;
    float pdf_w = 0, pdf_wo = 0;
    bool has_pdfs = false;
};
EndScattering end_scattering(const PathVertex& v, Vector3f w, TransportMode mode);
// at_qs / at_pt (optional): the ends' end_scattering towards each other, for the densities at qs and pt
// in place of new evaluations (only where the end is a surface or medium vertex with a predecessor).
JoinDensities join_densities(const PathContext& ctx, const PathVertex* qs, const PathVertex* qs_m,
                             const PathVertex& pt, const PathVertex* pt_m,
                             const EndScattering* at_qs = nullptr, const EndScattering* at_pt = nullptr);
// The density (area, at next) with which the light at v emits towards next.
float pdf_light(const PathContext& ctx, const PathVertex& v, const PathVertex& next);
// The density with which a light subpath starts at v (light selection times position; for a vertex at
// infinity the selection-weighted direction density towards next).
float pdf_light_origin(const PathContext& ctx, const PathVertex& v, const PathVertex& next);
// Σ over the infinite lights of pmf · pdf_dir of light travelling along w.
float infinite_light_density(const PathContext& ctx, Vector3f w);
// Emitted radiance from the light at v towards `towards`.
SampledSpectrum vertex_le(const PathContext& ctx, const PathVertex& v, const PathVertex& towards);

// The random walk (PBR 4th ed. §16.3.2, RandomWalk) from `ray` (its medium set) with throughput beta and
// the direction's density pdf_dir at path[-1] (which must exist): fills path[0 .. max_vertices) through
// surfaces and media (delta tracking in `channel`; interfaces are crossed, not vertices), and returns the
// number of vertices. An escaped camera ray ends in a light vertex at infinity.
int walk(const PathContext& ctx, Ray ray, SampledSpectrum beta, float pdf_dir, int max_vertices,
         TransportMode mode, int channel, PathVertex* path);

// The transmittance between two vertices through interfaces and media (ratio tracking, shadow_transmittance
// in `channel`, with its one-sample spectral MIS): zero when blocked. to_infinity: b is a direction only.
SampledSpectrum connection_transmittance(const PathContext& ctx, const PathVertex& a, const PathVertex& b,
                                         int channel);
// A light subpath (PBR 4th ed. §16.3.3, GenerateLightSubpath): a light chosen with u_light, a photon from
// sample_le(u_pos, u_dir) as vertex 0, then the random walk in importance mode at the context's time. For a
// light at infinity the origin lies on the scene's disk: vertex 1's forward density is the disk's (with the
// cosine there) and the light's is that of the direction. Returns the number of vertices (0: no photon).
int trace_light_subpath(const PathContext& ctx, float u_light, Point2f u_pos, Point2f u_dir, int max_depth,
                        int channel, PathVertex* path);
// Strategy s = 1 of a connection at camera vertex pt (next-event estimation): a light chosen by the scene's
// light sampler with u_light and a point on it sampled towards pt with u. Fills *sampled (the light vertex,
// whose pdf_fwd is its origin density, for the MIS weights), *l = β_pt f |cos| T L / p and *at_pt with
// pt's end_scattering towards the light; false when no light point was sampled (or it coincides with pt).
bool connect_sampled_light(const PathContext& ctx, const PathVertex& pt, float u_light, Point2f u,
                           int channel, PathVertex* sampled, SampledSpectrum* l, EndScattering* at_pt);
// The geometry term with transmittance: |cos_a| |cos_b| T / d² (cosines with the shading normals, only at
// surface vertices), with ab = segment(a, b) (non-degenerate) at hand.
SampledSpectrum connect_g(const PathContext& ctx, const PathVertex& a, const PathVertex& b, const Segment& ab,
                          int channel);

} // namespace illum
