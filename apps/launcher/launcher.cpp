// The `illum` launcher: starts the build of illum made for this processor. CMakeLists.txt builds the program
// twice, for the x86-64 baseline (illum-x86-64) and for the x86-64-v3 level (illum-x86-64-v3: AVX, AVX2,
// BMI1, BMI2, F16C, FMA, LZCNT, MOVBE, as the x86-64 psABI defines the level), and this launcher, installed
// beside them as `illum`, replaces itself with one of them (execv: same process, arguments and
// environment, so mpirun, exit codes and signals behave as if illum itself had been started).
//
// ILLUM_ISA=x86-64 or ILLUM_ISA=x86-64-v3 asks for one build by name; unset (or "auto"), the launcher takes
// x86-64-v3 where the processor and the operating system support it and the file is there, else x86-64.
// Both builds compute every floating-point operation alike (no fused multiply-adds are formed), so they
// give the same images bit for bit.
//
// Plain C library calls only, linked statically: it starts in well under a millisecond.
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <unistd.h>

#if defined(__x86_64__)
#include <cpuid.h>
#endif

namespace {

// Whether the processor has every feature of x86-64-v3 and the operating system saves the AVX registers
// (XCR0 bits 1 and 2), from CPUID (Intel SDM vol. 2A, CPUID; AMD APM vol. 3, appendix E).
bool cpu_has_x86_64_v3() {
#if defined(__x86_64__)
    unsigned a, b, c, d;
    if (!__get_cpuid(1, &a, &b, &c, &d)) return false;
    const bool fma = c & (1u << 12), movbe = c & (1u << 22), osxsave = c & (1u << 27), avx = c & (1u << 28),
               f16c = c & (1u << 29);
    if (!(fma && movbe && osxsave && avx && f16c)) return false;
    unsigned xcr0_lo, xcr0_hi;
    __asm__ volatile("xgetbv" : "=a"(xcr0_lo), "=d"(xcr0_hi) : "c"(0));
    if ((xcr0_lo & 0x6u) != 0x6u) return false; // SSE and AVX state
    if (!__get_cpuid_count(7, 0, &a, &b, &c, &d)) return false;
    const bool bmi1 = b & (1u << 3), avx2 = b & (1u << 5), bmi2 = b & (1u << 8);
    if (!(bmi1 && avx2 && bmi2)) return false;
    if (!__get_cpuid(0x80000001u, &a, &b, &c, &d)) return false;
    const bool lzcnt = c & (1u << 5);
    return lzcnt;
#else
    return false;
#endif
}

[[noreturn]] void fail(const char* what, const char* detail) {
    std::fprintf(stderr, "error: illum: %s%s\n", what, detail);
    std::exit(2);
}

} // namespace

int main(int argc, char** argv) {
    (void)argc;
    // The folder of this executable, where the two builds are.
    char self[PATH_MAX];
    ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    if (n <= 0) fail("cannot find its own executable (/proc/self/exe): ", std::strerror(errno));
    self[n] = '\0';
    char* slash = std::strrchr(self, '/');
    if (!slash) fail("cannot find its own folder in ", self);
    slash[1] = '\0';

    const char* asked = std::getenv("ILLUM_ISA");
    const bool automatic = !asked || !*asked || std::strcmp(asked, "auto") == 0;
    if (!automatic && std::strcmp(asked, "x86-64") != 0 && std::strcmp(asked, "x86-64-v3") != 0)
        fail("ILLUM_ISA must be x86-64, x86-64-v3 or auto, not ", asked);
    if (!automatic && std::strcmp(asked, "x86-64-v3") == 0 && !cpu_has_x86_64_v3())
        fail("ILLUM_ISA=x86-64-v3, but this processor lacks part of x86-64-v3 ",
             "(AVX2, BMI1/2, F16C, FMA, LZCNT, MOVBE or the operating system's AVX state)");

    char path[PATH_MAX];
    const char* level = automatic ? "x86-64-v3" : asked;
    std::snprintf(path, sizeof path, "%sillum-%s", self, level);
    if (automatic && (!cpu_has_x86_64_v3() || access(path, X_OK) != 0)) {
        level = "x86-64";
        std::snprintf(path, sizeof path, "%sillum-%s", self, level);
    }
    execv(path, argv);
    std::fprintf(stderr, "error: illum: cannot start %s: %s (the launcher needs the builds beside it)\n",
                 path, std::strerror(errno));
    return 2;
}
