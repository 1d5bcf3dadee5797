// volpath with its caustics by light tracing. Paths whose first scattering after the light is specular and
// whose first scattering from the camera is not (a caustic on a diffuse surface or in a medium: light
// focused by a glass sphere into fog, say) are found by volpath only when a path hits the light after a
// specular bounce: with a small light almost never, with a point light never. Path space is split in two
// (a partition, not a weighting): volpath leaves those paths out, and a light-tracing pass of one particle
// per pixel sample (lightpath_integrator.h, caustics_only) renders exactly them; the two images add up to
// volpath's expectation, with the caustic converged instead of in fireflies. Environment lights' caustics
// stay with volpath (their particles are not traced). The same pass also connects each particle's origin to
// the lens, and an area light seen directly is weighed between that and volpath's camera rays
// (direct_view_mis.h): a light smaller than a pixel is then seen at all.
#pragma once

#include "illum/render/lightpath_integrator.h"
#include "illum/render/volpath_integrator.h"

namespace illum {

class VolPathCausticsIntegrator final : public WholeImageIntegrator {
public:
    VolPathCausticsIntegrator(const Scene& scene, int max_depth);
    RenderResult render_image(const RenderOptions& options) const override;
    // The camera paths are spread by adaptive sampling; the light-tracing pass stays uniform.
    bool adapts_samples() const override { return true; }

private:
    VolPathIntegrator camera_paths_;
    LightPathIntegrator caustics_;
};

} // namespace illum
