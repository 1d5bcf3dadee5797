# The RGB-to-spectrum tables (src/illum/radiometry/rgb_to_spectrum.h), computed at build time by illum's own
# optimiser and embedded in illum_radiometry. Included from the module loop of CMakeLists.txt for
# radiometry, with `sources` its .cpp files: everything but rgb_to_spectrum.cpp (which embeds the tables)
# and uplift.cpp (which looks them up) becomes the object library illum_radiometry_core, which the
# generator links; the module's library is those objects, uplift.cpp and the tables' object.
# Inside illum_add_modules: `suffix`, `below` and the compile options (ARGN) are the function's. The
# x86-64-v3 copy (suffix _x86_64_v3) has its own core and uplift.cpp but the baseline's tables' object
# (illum_rgb2spec_embedded, data and one accessor): the custom command that computes the tables belongs to
# that one target alone. Were its outputs a dependency of both builds' libraries, make would run the
# command once per library, concurrently, into the same files (CMake's add_custom_command: "do not list
# the output in more than one independent target"), which broke a clean parallel build.
list(FILTER sources EXCLUDE REGEX "/(rgb_to_spectrum|uplift)\\.cpp$")
add_library(illum_radiometry_core${suffix} OBJECT ${sources})
target_compile_options(illum_radiometry_core${suffix} PRIVATE ${ARGN})
target_include_directories(illum_radiometry_core${suffix} PUBLIC src)
target_link_libraries(illum_radiometry_core${suffix} PUBLIC ${below})

if(NOT suffix)
    add_executable(illum_rgb2spec_opt tools/rgb2spec_opt.cpp)
    target_link_libraries(illum_rgb2spec_opt PRIVATE illum_radiometry_core TBB::tbb)

    set(ILLUM_RGB2SPEC_DIR ${CMAKE_BINARY_DIR}/rgb2spec)
    set(ILLUM_RGB2SPEC_TABLES)
    foreach(space srgb rec2020 aces2065-1 dci-p3)
        list(APPEND ILLUM_RGB2SPEC_TABLES ${ILLUM_RGB2SPEC_DIR}/${space}.bin)
    endforeach()
    add_custom_command(
        OUTPUT ${ILLUM_RGB2SPEC_TABLES}
        COMMAND ${CMAKE_COMMAND} -E make_directory ${ILLUM_RGB2SPEC_DIR}
        COMMAND illum_rgb2spec_opt ${ILLUM_RGB2SPEC_DIR}
        DEPENDS illum_rgb2spec_opt
        COMMENT "Computing the RGB-to-spectrum tables (illum_rgb2spec_opt)"
        VERBATIM)
    set(embed ${PROJECT_SOURCE_DIR}/src/illum/radiometry/rgb_to_spectrum.cpp)
    set_source_files_properties(${embed} PROPERTIES OBJECT_DEPENDS "${ILLUM_RGB2SPEC_TABLES}"
                                COMPILE_DEFINITIONS "ILLUM_RGB2SPEC_DIR=\"${ILLUM_RGB2SPEC_DIR}\"")
    add_library(illum_rgb2spec_embedded OBJECT ${embed})
    target_compile_options(illum_rgb2spec_embedded PRIVATE ${ARGN})
    target_include_directories(illum_rgb2spec_embedded PUBLIC src)
    target_link_libraries(illum_rgb2spec_embedded PUBLIC ${below})
endif()
set(sources ${PROJECT_SOURCE_DIR}/src/illum/radiometry/uplift.cpp $<TARGET_OBJECTS:illum_radiometry_core${suffix}>
    $<TARGET_OBJECTS:illum_rgb2spec_embedded>)

# The fit's inner sums: let them vectorise (the `omp simd` reductions) and sqrt be an instruction. The
# order of the sums then depends on the vector width, which changes the tables only below their tolerance.
set_source_files_properties(${PROJECT_SOURCE_DIR}/src/illum/radiometry/sigmoid_fit.cpp PROPERTIES
                            COMPILE_OPTIONS "-fopenmp-simd;-fno-math-errno")
