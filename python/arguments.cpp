// Keyword arguments that are whole numbers, checked as the CLI's options are: a ValueError with a message
// for a wrong type or a value out of range (pybind11's own conversion would give a TypeError, or wrap a
// negative seed around).
#include <fmt/core.h>

#include "bindings.h"

namespace illum::python {

namespace {

[[noreturn]] void reject(const py::handle& value, const char* name, const char* expected) {
    throw py::value_error(fmt::format("{} must be {}, not {}", name, expected, std::string(py::repr(value))));
}

// The integer value of an int or NumPy integer (not a bool, float or string); rejected otherwise.
py::object as_index(const py::handle& value, const char* name, const char* expected) {
    if (PyBool_Check(value.ptr()) || !PyIndex_Check(value.ptr())) reject(value, name, expected);
    return py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr()));
}

} // namespace

long long whole_number(const py::handle& value, const char* name, long long lo, long long hi,
                       const char* expected) {
    py::object index = as_index(value, name, expected);
    int overflow = 0;
    long long v = PyLong_AsLongLongAndOverflow(index.ptr(), &overflow);
    if (overflow || v < lo || v > hi) reject(value, name, expected);
    return v;
}

std::uint64_t seed_value(const py::handle& value, const char* name) {
    const char* expected = "a whole number in [0, 2^64)";
    py::object index = as_index(value, name, expected);
    unsigned long long v = PyLong_AsUnsignedLongLong(index.ptr());
    if (PyErr_Occurred()) {
        PyErr_Clear();
        reject(value, name, expected);
    }
    return v;
}

} // namespace illum::python
