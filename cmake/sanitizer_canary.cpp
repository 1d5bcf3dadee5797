// Proof that the sanitizer build reports what it should (tests/CMakeLists.txt, ILLUM_SANITIZE): each mode
// commits one deliberate error and the CTest passes only if the matching sanitizer report appears.
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>

int main(int argc, char** argv) {
    const char* mode = argc > 1 ? argv[1] : "";
    volatile int n = argc > 2 ? std::atoi(argv[2]) : 8;
    if (!std::strcmp(mode, "asan")) {
        char* p = new char[n];
        p[n] = 1; // heap-buffer-overflow
        delete[] p;
    } else if (!std::strcmp(mode, "ubsan")) {
        volatile int big = INT_MAX;
        std::printf("%d\n", big + n); // signed integer overflow
    } else if (!std::strcmp(mode, "lsan")) {
        void* volatile leaked = std::malloc(64 * n);
        leaked = nullptr;
        (void)leaked;
    }
    return 0;
}
