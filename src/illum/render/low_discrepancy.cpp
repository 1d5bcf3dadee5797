#include "illum/render/low_discrepancy.h"

#include <algorithm>
#include <cmath>

namespace illum::low_discrepancy {

namespace {

constexpr std::array<uint32_t, kPrimeCount> make_primes() {
    std::array<uint32_t, kPrimeCount> p{};
    int n = 0;
    for (uint32_t c = 2; n < kPrimeCount; ++c) {
        bool prime = true;
        for (int i = 0; i < n && p[size_t(i)] * p[size_t(i)] <= c; ++i)
            if (c % p[size_t(i)] == 0) {
                prime = false;
                break;
            }
        if (prime) p[size_t(n++)] = c;
    }
    return p;
}

constexpr std::array<uint32_t, kPrimeCount> kPrimes = make_primes();
static_assert(kPrimes[0] == 2 && kPrimes[1] == 3 && kPrimes[999] == 7919);

// The largest float below 1.
constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

// Digits of base b that float precision resolves: the smallest n with b^n >= 2^24.
int float_digits(uint32_t b) {
    int n = 0;
    for (uint64_t m = 1; m < (uint64_t(1) << 24); m *= b) ++n;
    return n;
}

} // namespace

const std::array<uint32_t, kPrimeCount>& primes() { return kPrimes; }

float radical_inverse(int base_index, uint64_t a) {
    const uint64_t b = kPrimes[size_t(base_index)];
    // Reverse the digits into an integer while tracking b^n; stop before b^n leaves 64 bits (a has at
    // most 64 / log2(b) digits, and the float result needs far fewer).
    uint64_t reversed = 0, scale = 1;
    const uint64_t limit = ~uint64_t(0) / b;
    while (a && scale < limit) {
        uint64_t next = a / b;
        reversed = reversed * b + (a - next * b);
        scale *= b;
        a = next;
    }
    return std::min(float(double(reversed) / double(scale)), kOneMinusEpsilon);
}

uint64_t inverse_radical_inverse(uint64_t inverse, int base, int n_digits) {
    uint64_t a = 0;
    for (int i = 0; i < n_digits; ++i) {
        a = a * uint64_t(base) + inverse % uint64_t(base);
        inverse /= uint64_t(base);
    }
    return a;
}

int64_t multiplicative_inverse(int64_t a, int64_t n) {
    // Extended Euclid on (a, n), keeping only the coefficient of a: r_i = s_i a (mod n).
    int64_t r0 = a % n, r1 = n, s0 = 1, s1 = 0;
    while (r1 != 0) {
        int64_t q = r0 / r1;
        int64_t r = r0 - q * r1, s = s0 - q * s1;
        r0 = r1, s0 = s1, r1 = r, s1 = s;
    }
    int64_t x = s0 % n;
    return x < 0 ? x + n : x;
}

uint32_t permutation_element(uint32_t i, uint32_t n, uint32_t seed) {
    if (n <= 1) return 0;
    // Mask of the smallest power of two >= n; every step below is a bijection on [0, mask]: XOR with a
    // constant, multiplication by an odd number, addition (all mod 2^k), and x ^= (x & mask) >> s.
    uint32_t w = n - 1;
    w |= w >> 1, w |= w >> 2, w |= w >> 4, w |= w >> 8, w |= w >> 16;
    const uint32_t mask = w;
    const uint32_t s1 = uint32_t(mix_bits(seed)), s2 = uint32_t(mix_bits(uint64_t(seed) + 1) >> 32);
    do {
        i ^= s1;
        i *= 0x9e3779b1u;
        i &= mask;
        i ^= i >> 5;
        i ^= s2;
        i *= 0x85ebca6bu;
        i &= mask;
        i ^= i >> 3;
        i += s1 >> 7;
        i *= 0xc2b2ae35u | 1u;
        i &= mask;
        i ^= i >> 7;
        i *= 0x27d4eb2fu;
        i &= mask;
        i ^= i >> 11;
    } while (i >= n);
    return i;
}

std::vector<DigitPermutations> make_digit_permutations(uint64_t seed) {
    std::vector<DigitPermutations> out(static_cast<size_t>(kPrimeCount));
    for (int k = 0; k < kPrimeCount; ++k) {
        DigitPermutations& d = out[size_t(k)];
        d.base = int(kPrimes[size_t(k)]);
        d.n_digits = float_digits(kPrimes[size_t(k)]);
        d.perm.resize(size_t(d.n_digits) * size_t(d.base));
        // Fisher-Yates with a PCG32 stream per (seed, base, digit).
        for (int i = 0; i < d.n_digits; ++i) {
            uint16_t* perm = d.perm.data() + size_t(i) * size_t(d.base);
            for (int j = 0; j < d.base; ++j) perm[j] = uint16_t(j);
            PCG32 rng(hash(seed, d.base, i));
            for (int j = d.base - 1; j > 0; --j) {
                const int k = int(rng.uniform_uint32() % uint32_t(j + 1)); // bias < 2^-19 for b < 7920
                std::swap(perm[j], perm[k]);
            }
        }
    }
    return out;
}

float scrambled_radical_inverse(const DigitPermutations& p, uint64_t a) {
    const uint64_t b = uint64_t(p.base);
    uint64_t reversed = 0, scale = 1;
    const uint16_t* perm = p.perm.data();
    for (int i = 0; i < p.n_digits; ++i, perm += b) {
        uint64_t next = a / b;
        reversed = reversed * b + perm[a - next * b];
        scale *= b;
        a = next;
    }
    return std::min(float(double(reversed) / double(scale)), kOneMinusEpsilon);
}

float owen_scrambled_radical_inverse(int base_index, uint64_t a, uint64_t seed) {
    const uint64_t b = kPrimes[size_t(base_index)];
    const int n = float_digits(uint32_t(b));
    uint64_t reversed = 0, scale = 1;
    for (int i = 0; i < n; ++i) {
        // reversed holds the already scrambled digits above this one; its value and the position pick
        // the shift of this subtree. The hash of the scrambled prefix is a bijective relabelling of the
        // hash of the original prefix, so each subtree still gets an independent shift.
        uint64_t next = a / b;
        uint64_t shift = mix_bits(seed ^ (reversed * 0x9e3779b97f4a7c15ULL + uint64_t(i))) % b;
        uint64_t digit = (a - next * b + shift) % b;
        reversed = reversed * b + digit;
        scale *= b;
        a = next;
    }
    return std::min(float(double(reversed) / double(scale)), kOneMinusEpsilon);
}

uint32_t owen_base2(uint32_t x, uint32_t seed) {
    uint32_t out = x;
    for (int bit = 31; bit >= 0; --bit) {
        const uint32_t above = bit == 31 ? 0u : x >> (bit + 1); // the unscrambled bits above this one
        out ^= uint32_t(mix_bits((uint64_t(seed) << 32) ^ (uint64_t(above) << 5) ^ uint64_t(bit)) & 1u)
               << bit;
    }
    return out;
}

} // namespace illum::low_discrepancy
