// The media on the two sides of a surface (pbrt-v4's MediumInterface): `inside` against its geometric
// normal, `outside` along it. Only a surface that separates two different media has one; any other leaves
// a ray in the medium it travels in. The media themselves are defined above (medium/medium.h).
#pragma once

namespace illum {

class Medium;

struct MediumInterface {
    const Medium* inside = nullptr;
    const Medium* outside = nullptr;
    bool is_transition() const { return inside != outside; }
};

} // namespace illum
