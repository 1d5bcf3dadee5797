// The Python module `illum`: scenes rendered to NumPy arrays, images read and written, the reflection
// models and environment-map tools of the CLI, vectorised over NumPy arrays. Each idea has its own file;
// this one only assembles the module.
#include "bindings.h"

PYBIND11_MODULE(illum, m) {
    m.doc() = "illum: a physically based renderer and reflectance toolkit (the C++ library, from Python)";
    m.attr("__version__") = ILLUM_VERSION;
    illum::python::bind_errors(m);
    illum::python::bind_images(m);
    illum::python::bind_scene(m);
    illum::python::bind_brdf(m);
    illum::python::bind_envmap(m);
}
