// illum.read_image and illum.write_image: the library's readers and writers on NumPy arrays.
#include <cstdint>
#include <filesystem>
#include <string>

#include <fmt/core.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.h"
#include "illum/image/image_io.h"
#include "illum/image/tonemap.h"
#include "illum/util/error.h"

namespace illum::python {

void bind_images(py::module_& m) {
    m.def(
        "read_image",
        [](const std::filesystem::path& path) {
            Image image;
            {
                py::gil_scoped_release unlocked;
                image = read_image(path.string());
            }
            return image_to_array(std::move(image));
        },
        py::arg("path"),
        "Reads an image (.exr, .pfm, .hdr linear; .png, .jpg, .tga, .bmp decoded from sRGB to linear) as a "
        "float32 array of shape (height, width, 3), without a copy of the pixels.");

    m.def(
        "write_image",
        [](const std::filesystem::path& path, const py::handle& array, float exposure,
           const std::string& tonemap) {
            auto t = tonemap_from_string(tonemap);
            if (!t)
                throw py::value_error(
                    fmt::format("unknown tone map \"{}\" (use clamp, reinhard or aces)", tonemap));
            Image image = array_to_image(array, "the image");
            WriteOptions options;
            options.exposure_stops = exposure;
            options.tonemap = *t;
            py::gil_scoped_release unlocked;
            write_image(image, path.string(), options);
        },
        py::arg("path"), py::arg("array"), py::arg("exposure") = 0.0f, py::arg("tonemap") = "clamp",
        "Writes an array of shape (height, width, 3) of linear RGB (float32, or any real dtype) as .exr, "
        ".pfm, "
        ".hdr (linear) or .png (tone mapped: exposure in stops, then clamp, reinhard or aces), through a "
        "temporary file renamed over `path`, so an existing file is replaced whole or not at all.");

    // For the tests: how many Images handed to Python are alive, and where an array's Image keeps its
    // pixels (the address of the Image's own buffer, read through the capsule that owns it).
    m.def("_live_images", &live_images);
    m.def("_image_data_address", [](const py::handle& owner) {
        const char* name = PyCapsule_CheckExact(owner.ptr()) ? PyCapsule_GetName(owner.ptr()) : nullptr;
        if (!name || std::string(name) != kImageCapsuleName)
            throw py::value_error("not the capsule of an image array (its .base)");
        auto* image = static_cast<const Image*>(PyCapsule_GetPointer(owner.ptr(), kImageCapsuleName));
        return reinterpret_cast<std::uintptr_t>(image->data());
    });
}

} // namespace illum::python
