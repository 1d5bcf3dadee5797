#include "illum/light/light.h"

#include "illum/math/frame.h"
#include "illum/math/warp.h"

namespace illum {

LightLeSample disk_emission(Point3f c, float r, Vector3f wi, Point2f u, Radiance3 l, SolidAnglePdf pdf_dir) {
    Frame f = Frame::from_z(wi);
    Point2f d = sample_uniform_disk_concentric(u);
    Point3f o = c + wi * r + (f.s * d.x + f.t * d.y) * r;
    AreaPdf pdf_pos(1 / (kPi * r * r));
    return LightLeSample{Ray{o, -wi}, {}, l, pdf_pos, pdf_dir, l / pdf_pos / pdf_dir, o, {}};
}

} // namespace illum
