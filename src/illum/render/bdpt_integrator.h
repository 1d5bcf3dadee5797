// Bidirectional path tracing (pbrt-v4's "bdpt"; Veach 1997 ch. 10, PBR 4th ed. §16.3): for every pixel
// sample a camera subpath and a light subpath are traced through surfaces and participating media
// (path_vertex.h: delta tracking, real collisions become medium vertices, interfaces are crossed), and
// every strategy (s light vertices, t camera vertices) with s + t - 2 <= maxdepth is evaluated:
//   s = 0:  the camera subpath reaches an emitter (area light, or an environment when it escapes);
//   s = 1:  a freshly sampled point on a light is connected to camera vertex t - 1 (next-event estimation);
//   t = 1:  light vertex s - 1 is connected to a lens point from camera.sample_wi and splatted where it
//           lands on the film;
//   else:   vertices s - 1 and t - 1 are joined (their BSDFs or phase functions, the geometry term and the
//           transmittance of the segment through interfaces and media).
// Each is weighted by the balance heuristic over the strategies that could have made the same path,
// from the vertices' forward and reverse densities (Veach eq. 10.9 as a recursion of ratios; the
// reverse densities next to the connection are computed when it is made; a density 0 at a delta vertex
// is remapped to 1 and strategies that would have to connect through a delta vertex are left out).
//
// Departures from pbrt-v4, with reasons:
// - Spectral: each subpath samples its free flights in its own channel, chosen uniformly (pbrt-v4 uses
//   channel 0, the hero; illum's RGB mode has fixed lanes), and weighs by one-sample spectral MIS over that
//   choice (path_vertex.h); a chromatic medium then costs no fireflies in the other channels.
// - The adjoint BSDF's shading-normal factor (Veach eq. 5.19) is applied on the light subpath and at its
//   connections, as illum's light tracer does; pbrt-v4's BDPT omits it.
// - Media's emission is not collected (neither does pbrt-v4's BDPT); volpath does.
// - maxdepth -1 (unbounded; pbrt-v4's BDPT has no Russian roulette and needs a bound) is taken as 32.
// - An orthographic camera (a delta direction) gets no t = 1 strategy (its lens point is fixed by the
//   vertex, so it would have to be weighted against a delta); pbrt-v4 only allows the perspective camera.
//   Cameras without importance (realistic) are refused.
//
// Debug outputs, as pbrt-v4's: with "bool visualizestrategies" each strategy's unweighted contribution
// (what it estimates alone), with "bool visualizeweights" its MIS-weighted one, is splatted into an image of
// its own, bdpt_d<depth>_s<s>_t<t>.exr (RenderResult::extra_images); the weighted images of all strategies
// add up to the render.
//
// Determinism: as light tracing (lightpath_integrator.h): chunks of pixels at one sample index are traced
// in parallel; each chunk keeps its camera estimates (pixel, value, filter weight) and its t = 1 splats in
// its own lists, which are added to the film in chunk order. The image is the filter-weighted mean of the
// camera estimates (as the tiled renderer's film) plus the splat film's image.
#pragma once

#include "illum/render/renderer.h"

namespace illum {

class BDPTIntegrator final : public WholeImageIntegrator {
public:
    static constexpr int kUnboundedDepth = 32;

    // max_depth: the most scattering events of a path (pbrt-v4's "maxdepth"; -1: kUnboundedDepth). Throws
    // illum::Error if the camera has no importance function.
    BDPTIntegrator(const Scene& scene, int max_depth);
    RenderResult render_image(const RenderOptions& options) const override;
    // Adaptive sampling spreads the camera samples by the noise of the camera strategies' estimates (t >= 2);
    // each sample traces its light subpath as always, and the splats (t = 1) are normalised by the samples in
    // all.
    bool adapts_samples() const override { return true; }
    int max_depth() const { return max_depth_; }

private:
    int max_depth_;
};

} // namespace illum
