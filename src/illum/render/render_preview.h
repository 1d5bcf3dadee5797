// What a live preview sees of a render in progress (`illum render --serve`, apps/illum/preview_server.*):
// with a preview the render loops render in passes of one sample per pixel, so the image converges as a
// whole, and hand the preview the film's image after every pass. The sample set, and so the final image,
// is the same as without a preview.
#pragma once

#include "illum/image/image.h"

namespace illum {

class RenderPreview {
public:
    virtual ~RenderPreview() = default;
    // The image after `spp` samples per pixel of `total_spp` (0 when a time budget decides), and the
    // fraction of the render done. Called by the render loop's thread between passes.
    virtual void frame(Image image, int spp, int total_spp, double fraction) = 0;
};

} // namespace illum
