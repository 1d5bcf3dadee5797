// illum::Error becomes illum.Error, a subclass of ValueError (as json.JSONDecodeError is): str(e) is the
// message the CLI prints after `error: ` (`scene.pbrt:12:5: unknown material type "foo"`), and the
// attributes file, line, column (0 when unknown) and message (without the position) give its parts.
#include <exception>

#include "bindings.h"
#include "illum/util/error.h"

namespace illum::python {

namespace {

// The exception type, created once with the module and never freed: a translator may run until the
// interpreter shuts down, and a static py::object would be destroyed after it.
PyObject* error_type = nullptr;

} // namespace

void bind_errors(py::module_& m) {
    py::exception<Error> type(m, "Error", PyExc_ValueError);
    type.doc() = "An error of illum's (a ValueError): str(e) is the CLI's message, with file:line:column for "
                 "a scene error; e.file, e.line, e.column (0 when unknown) and e.message (without the "
                 "position) give its parts.";
    error_type = type.release().ptr();
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const Error& e) {
            py::object exc = py::reinterpret_borrow<py::object>(error_type)(e.what());
            exc.attr("file") = e.where().file;
            exc.attr("line") = e.where().line;
            exc.attr("column") = e.where().column;
            exc.attr("message") = e.message();
            PyErr_SetObject(error_type, exc.ptr());
        }
    });
}

void warn_all(const std::vector<std::string>& messages) {
    for (const auto& w : messages)
        if (PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 1) != 0) throw py::error_already_set();
}

} // namespace illum::python
