# Finds what the Python module (python/) needs: a Python 3 interpreter with its development files and NumPy,
# and pybind11 (Debian's pybind11-dev installs its CMake package). Sets ILLUM_PYTHON_FOUND.
#
# The interpreter: Python3_EXECUTABLE when given, else the first `python3` on PATH that can import numpy.
# FindPython3 alone takes the first python3 on PATH, which may be a pyenv or virtualenv interpreter without
# NumPy that hides Debian's /usr/bin/python3 (then the module would silently not be built).
set(ILLUM_PYTHON_FOUND OFF)
if(DEFINED ILLUM_BUILD_PYTHON AND NOT ILLUM_BUILD_PYTHON)
    return() # switched off (the sanitizer build): do not look
endif()
if(NOT Python3_EXECUTABLE)
    string(REPLACE ":" ";" illum_path "$ENV{PATH}")
    foreach(dir ${illum_path})
        if(EXISTS "${dir}/python3")
            execute_process(COMMAND "${dir}/python3" -c "import numpy" RESULT_VARIABLE illum_numpy_rc
                            OUTPUT_QUIET ERROR_QUIET)
            if(illum_numpy_rc EQUAL 0)
                set(Python3_EXECUTABLE "${dir}/python3" CACHE FILEPATH "Python 3 interpreter (with NumPy)")
                break()
            endif()
        endif()
    endforeach()
endif()
find_package(Python3 COMPONENTS Interpreter Development.Module NumPy QUIET)
if(Python3_FOUND)
    # After Python3, so that pybind11 uses the interpreter found above (its FindPython mode).
    find_package(pybind11 2.6 CONFIG QUIET)
endif()
if(Python3_FOUND AND Python3_NumPy_FOUND AND pybind11_FOUND)
    set(ILLUM_PYTHON_FOUND ON)
    message(STATUS "Python module: ${Python3_EXECUTABLE} ${Python3_VERSION}, NumPy ${Python3_NumPy_VERSION}, "
                   "pybind11 ${pybind11_VERSION}")
else()
    message(STATUS "Python module not built: needs Python 3 with its development files and NumPy, and "
                   "pybind11 (scripts/setup.sh installs python3-dev, python3-numpy, pybind11-dev)")
endif()
