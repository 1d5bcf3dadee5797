// What the files of the Python module share: one bind function per idea (each adds its functions and
// classes to the module), and the conversions between NumPy arrays and the library's types.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "illum/image/image.h"

namespace illum::python {

namespace py = pybind11;

// illum.Error (a ValueError) for illum::Error, with its file, line, column and message.
void bind_errors(py::module_& m);
// illum.read_image, illum.write_image.
void bind_images(py::module_& m);
// illum.load, illum.cornell_box, illum.Scene.
void bind_scene(py::module_& m);
// The submodule illum.brdf.
void bind_brdf(py::module_& m);
// The submodule illum.envmap.
void bind_envmap(py::module_& m);

// An Image as a float32 array of shape (height, width, 3) over the Image's own pixels, without a copy: the
// Image is moved to the heap and owned by a capsule that is the array's base, so it lives as long as the
// array (and every view of it) does. The capsule's name is kImageCapsuleName.
inline constexpr const char* kImageCapsuleName = "illum.Image";
py::array_t<float> image_to_array(Image&& image);
// How many Images capsules own now (illum._live_images(), for the test that the array frees its Image).
long live_images();

// A (height, width, 3) array of real numbers as an Image (a copy: an Image owns its pixels). Throws
// py::value_error naming `what` for another shape or dtype.
Image array_to_image(const py::handle& array, const char* what);

// Rows of k real numbers: an (N, k) array, or one row of shape (k,) (then `single` is set). Any real dtype
// (float, int) and any strides are accepted; `data` is C-contiguous float64 (the array itself when it is
// one already, else a converted copy that `array` holds). Throws py::value_error naming `what` for another
// shape, or a complex, boolean, object or string dtype. `data` may be read with the GIL released.
struct Rows {
    py::array_t<double> array;
    const double* data = nullptr; // n * k, row-major
    std::size_t n = 0;
    bool single = false;
};
Rows real_rows(const py::handle& array, std::size_t k, const char* what);
// Real numbers: one (shape (), then `single` is set) or a vector of shape (N,); k is 1.
Rows real_values(const py::handle& array, const char* what);

// A keyword argument that must be a whole number (int or NumPy integer, not bool) in [lo, hi]; throws
// py::value_error "`name` must be `expected`, not `repr(value)`" otherwise.
long long whole_number(const py::handle& value, const char* name, long long lo, long long hi,
                       const char* expected);
// A seed: a whole number in [0, 2^64); py::value_error otherwise.
std::uint64_t seed_value(const py::handle& value, const char* name);

// Python warnings (warnings.warn with UserWarning), one per message: what the CLI prints as `warning: ...`.
void warn_all(const std::vector<std::string>& messages);

} // namespace illum::python
