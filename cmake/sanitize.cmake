# Initial cache for the sanitizer build (`make test-sanitize`): cmake -C cmake/sanitize.cmake -S . -B build-sanitize
#
# clang++ with AddressSanitizer + UndefinedBehaviorSanitizer (any UB report aborts the test), -O1 -g so
# reports have usable stacks. Every object also gets libFuzzer's coverage instrumentation
# (-fsanitize=fuzzer-no-link), so the same build produces the libFuzzer target fuzz/pbrt_scene_fuzz
# (ILLUM_FUZZ) linked against the whole library, instead of a second full build just for the fuzzer.
# Third-party libraries (Embree, TBB, OpenEXR, gtest) come from Debian and are not instrumented.
set(CMAKE_CXX_COMPILER clang++ CACHE STRING "")
set(CMAKE_BUILD_TYPE RelWithDebInfo CACHE STRING "")
set(CMAKE_CXX_FLAGS_RELWITHDEBINFO "-O1 -g" CACHE STRING "")
set(CMAKE_CXX_FLAGS
    "-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined -fsanitize=fuzzer-no-link"
    CACHE STRING "")
set(CMAKE_EXE_LINKER_FLAGS "-fsanitize=address,undefined" CACHE STRING "")
set(CMAKE_SHARED_LINKER_FLAGS "-fsanitize=address,undefined" CACHE STRING "")
set(CMAKE_MODULE_LINKER_FLAGS "-fsanitize=address,undefined" CACHE STRING "") # illum-http.so
set(ILLUM_SANITIZE ON CACHE BOOL "")
set(ILLUM_FUZZ ON CACHE BOOL "")
# The benchmark kernels say nothing under ASan; `make bench` builds them in the normal build.
set(ILLUM_BUILD_BENCH OFF CACHE BOOL "")
# MPI (distributed rendering) is tested in the normal build: Open MPI's own allocations at start-up would be
# LeakSanitizer reports here, and its libraries are not instrumented.
set(ILLUM_MPI OFF CACHE BOOL "")
# An ASan-instrumented Python module cannot be loaded by a plain python3: the sanitizer build has none.
set(ILLUM_BUILD_PYTHON OFF CACHE BOOL "")
# One build of the program is enough to check: the x86-64-v3 copy (and its launcher) runs the same code.
set(ILLUM_X86_64_V3 OFF CACHE BOOL "")
