// Vertex connection and merging (Georgiev, Křivánek, Davidovič, Slusallek, "Light Transport Simulation
// with Vertex Connection and Merging", SIGGRAPH Asia 2012; the same estimator as Hachisuka, Pantaleoni,
// Jensen's unified path sampling, SIGGRAPH Asia 2012): bidirectional path tracing and photon mapping
// combined by multiple importance sampling (vcm_mis.h). Iteration i (one per sample per pixel):
//
//  (a) Light pass: N light subpaths (path_vertex.h's walk; N = "photonsperiteration", the pixel count by
//      default). Each vertex connects to the camera (VC with t = 1, splatted as light tracing does) and is
//      stored for the iteration (per chunk of subpaths, in arrays that keep their capacity).
//  (b) The surface vertices after the first (y_1, y_2, …) where the BSDF has a non-specular part are put
//      in a hash grid (visible_point_grid.h) of radius r_i = r_0 · i^((α−1)/2) (paper §5.1, from Knaus &
//      Zwicker's progressive photon mapping; α = 0.75).
//  (c) Camera pass: one camera subpath per pixel; camera subpath p is joined to light subpath p mod N by
//      every BDPT strategy (s >= 0, t >= 2: emitter hits, next-event estimation, vertex-vertex
//      connections), and at each non-specular surface vertex z merges with every stored light vertex y
//      within r_i (paper eq. 9; the uniform kernel):
//          L_VM = β_cam(z) · f(z, ω_o, ω_y) · β_light(y) / (N π r_i²),
//      each contribution weighted by its MIS weight.
// The image after k iterations is the mean of their estimates: consistent (the merging bias vanishes with
// r_i) and, where merging's weight is low, as unbiased as BDPT.
//
// Modes ("string mode"): "vcm" (both), "vc" (connections only: BDPT with N light subpaths per iteration),
// "vm" (merging only, plus the emitter hits that no merge can make: a progressive photon mapper whose
// estimates are MIS-weighted per path). All three estimate the same image; the tests compare them.
//
// Spectral mode: a light and a camera subpath must carry the same wavelengths to be joined, and every
// light vertex of an iteration may be merged with every camera vertex, so all subpaths of an iteration
// share one set of wavelengths, from the (scrambled) base-3 radical inverse of the iteration (as pbrt-v4's
// SPPM): each iteration's estimate is unbiased for its wavelengths, and so is their mean over iterations.
// A dispersive event (terminate_secondary) on either subpath makes a joined path's estimate the hero
// wavelength's alone.
//
// Media: connections (VC) go through media as BDPT's do, with medium vertices and transmittance; merging
// is on surfaces only (no volume photon beams or points), so medium vertices take part in the weights as
// vertices where no merging happens. Media's own emission is not collected (as BDPT).
//
// Memory: the light vertices of an iteration are kept as path vertices without their BSDFs (rebuilt from the
// stored hit in the camera thread's arena when a connection needs one), in per-chunk arrays that are
// cleared, not freed, between iterations, as are the grid's; a subpath's own vertices live in per-thread
// arrays made once. After the first iteration the render loop allocates nothing (but where an iteration
// stores more vertices than any before it). `illum render` prints the arrays' and the grid's size.
//
// Determinism: the light pass traces fixed chunks of subpaths, each chunk into its own arrays of vertices
// and splats; the camera pass traces fixed chunks of pixels into their own estimate and splat lists; both
// are applied in chunk order. Subpath p of iteration i draws from the Sobol stream of (seed, p, i) (light
// subpaths from "pixels" outside the image). The image does not depend on the thread count.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "illum/render/renderer.h"

namespace illum {

struct VcmSettings {
    enum class Mode { VCM, VC, VM };
    int max_depth = 5;                    // "maxdepth": the most scattering events of a path (-1: 32)
    long long photons_per_iteration = -1; // "photonsperiteration": light subpaths per iteration (-1: pixels)
    float radius = -1;                    // "radius": initial merging radius [world units]; <= 0: default
    float alpha = 0.75f;                  // "alpha": the radius shrinks as i^((α−1)/2)
    Mode mode = Mode::VCM;                // "mode"
    bool power_heuristic = false;         // "misheuristic" "power" (default "balance")
};

// Parses "vcm", "vc", "vm"; false for another name.
bool parse_vcm_mode(const std::string& name, VcmSettings::Mode* mode);

// What a render did besides the image.
struct VcmStats {
    int iterations = 0;
    std::uint64_t light_subpaths = 0;
    std::uint64_t light_vertices = 0; // stored in the last iteration
    std::uint64_t merges = 0;         // (camera vertex, light vertex) pairs within the radius, all iterations
    std::size_t grid_bytes = 0;       // the light-vertex grid's largest size over the iterations
    std::size_t vertex_bytes = 0;     // the stored light vertices (capacity)
    float initial_radius = 0, final_radius = 0;
};

class VCMIntegrator final : public WholeImageIntegrator {
public:
    static constexpr int kUnboundedDepth = 32;

    // Throws illum::Error if the camera has no importance function (as bdpt).
    VCMIntegrator(const Scene& scene, const VcmSettings& settings);
    // options.spp is the number of iterations; a time budget renders whole iterations.
    RenderResult render_image(const RenderOptions& options) const override;
    RenderResult render_vcm(const RenderOptions& options, VcmStats* stats) const;
    // The initial radius used: the setting, or the scene's bounding-sphere radius over the image's larger
    // side in pixels (half a pixel's footprint if the sphere's diameter filled the image; about one pixel's
    // footprint in the Cornell box as framed by the shared scenes).
    float initial_radius() const;
    long long light_subpaths_per_iteration() const;
    const VcmSettings& settings() const { return settings_; }

private:
    VcmSettings settings_;
};

} // namespace illum
