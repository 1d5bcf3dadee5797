// NumPy arrays to and from the library's types: an Image handed to Python without a copy, and rows of
// real numbers (directions, random numbers, angles, images) checked and read as float64 or float32.
#include <atomic>
#include <cstdint>
#include <string>
#include <type_traits>

#include <fmt/core.h>

#include "bindings.h"

namespace illum::python {

namespace {

// Each pixel is three floats with no padding, so the pixels are a (height, width, 3) float array.
static_assert(sizeof(Color3) == 3 * sizeof(float) && std::is_standard_layout_v<Color3>);

std::atomic<long> images_alive{0};

std::string shape_string(const py::array& a) {
    std::string s = "(";
    for (py::ssize_t i = 0; i < a.ndim(); ++i) s += (i ? ", " : "") + std::to_string(a.shape(i));
    return s + (a.ndim() == 1 ? ",)" : ")");
}

// Real numbers only: floats, signed and unsigned integers (not bool, complex, object, strings).
bool is_real(const py::dtype& d) { return d.kind() == 'f' || d.kind() == 'i' || d.kind() == 'u'; }

py::array as_array(const py::handle& h, const char* what) {
    // Lists and tuples become arrays; anything NumPy cannot make an array of is a ValueError too.
    py::array a = py::array::ensure(h);
    if (!a) {
        PyErr_Clear();
        throw py::value_error(fmt::format("{} must be an array of numbers", what));
    }
    if (!is_real(a.dtype()))
        throw py::value_error(
            fmt::format("{} must hold real numbers, not dtype {}", what, std::string(py::str(a.dtype()))));
    return a;
}

} // namespace

py::array_t<float> image_to_array(Image&& image) {
    auto* owned = new Image(std::move(image));
    ++images_alive;
    py::capsule owner(owned, kImageCapsuleName, [](PyObject* capsule) {
        delete static_cast<Image*>(PyCapsule_GetPointer(capsule, kImageCapsuleName));
        --images_alive;
    });
    const auto w = py::ssize_t(owned->width()), h = py::ssize_t(owned->height());
    const auto f = py::ssize_t(sizeof(float));
    // The array points into the Image's pixels; the capsule (its base) keeps the Image alive.
    return py::array_t<float>({h, w, py::ssize_t(3)}, {w * 3 * f, 3 * f, f},
                              reinterpret_cast<float*>(owned->data()), owner);
}

long live_images() { return images_alive.load(); }

Image array_to_image(const py::handle& h, const char* what) {
    py::array a = as_array(h, what);
    if (a.ndim() != 3 || a.shape(2) != 3)
        throw py::value_error(
            fmt::format("{} must have shape (height, width, 3), not {}", what, shape_string(a)));
    if (a.shape(0) == 0 || a.shape(1) == 0)
        throw py::value_error(fmt::format("{} is empty: shape {}", what, shape_string(a)));
    if (a.shape(0) > INT32_MAX || a.shape(1) > INT32_MAX)
        throw py::value_error(fmt::format("{} is too large: shape {}", what, shape_string(a)));
    // A C-contiguous float32 view (a copy only when the array is not one already).
    auto f = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(a);
    if (!f) throw py::error_already_set();
    Image image(int(a.shape(1)), int(a.shape(0)));
    const float* src = f.data();
    for (std::size_t i = 0; i < image.pixel_count(); ++i)
        image.data()[i] = Color3(src[3 * i], src[3 * i + 1], src[3 * i + 2]);
    return image;
}

Rows real_rows(const py::handle& h, std::size_t k, const char* what) {
    py::array a = as_array(h, what);
    Rows rows;
    if (a.ndim() == 1 && std::size_t(a.shape(0)) == k) {
        rows.single = true;
        rows.n = 1;
    } else if (a.ndim() == 2 && std::size_t(a.shape(1)) == k) {
        rows.n = std::size_t(a.shape(0));
    } else {
        throw py::value_error(
            fmt::format("{} must have shape (N, {}) or ({},), not {}", what, k, k, shape_string(a)));
    }
    // No copy when the array is C-contiguous float64 already (NumPy's default).
    rows.array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    if (!rows.array) throw py::error_already_set();
    rows.data = rows.array.data();
    return rows;
}

Rows real_values(const py::handle& h, const char* what) {
    py::array a = as_array(h, what);
    if (a.ndim() > 1)
        throw py::value_error(
            fmt::format("{} must be a number or have shape (N,), not {}", what, shape_string(a)));
    Rows rows;
    rows.single = a.ndim() == 0;
    rows.n = rows.single ? 1 : std::size_t(a.shape(0));
    rows.array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    if (!rows.array) throw py::error_already_set();
    rows.data = rows.array.data();
    return rows;
}

} // namespace illum::python
