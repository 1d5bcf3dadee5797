#include "illum/image/drawing_io.h"

#include "illum/image/file_bytes.h"
#include "illum/image/image_io.h"
#include "illum/image/rasterize.h"
#include "illum/image/svg.h"
#include "illum/util/error.h"

namespace illum {

bool is_drawing_extension(const std::string& path) {
    std::string ext = image_extension(path);
    return ext == ".svg" || ext == ".png";
}

void write_drawing(const Drawing& drawing, const std::string& path, float png_scale) {
    std::string ext = image_extension(path);
    if (ext == ".svg")
        write_file_atomically(path, to_svg(drawing));
    else if (ext == ".png")
        write_image(rasterize(drawing, png_scale), path);
    else
        throw Error("cannot write \"" + path + "\": a figure is written as .svg or .png, not \"" + ext +
                    "\"");
}

} // namespace illum
