// First-order (paraxial) optics of a lens prescription by ray-transfer matrices (Gerrard & Burch,
// "Introduction to Matrix Methods in Optics", 1975; Hecht, "Optics", 5th ed., §6.2), independent of the
// ray tracer: the reference the tests hold the traced lens to.
//
// A ray is (y, n u): height and reduced slope. Refraction at a surface of radius R from index n to n' is
// [[1, 0], [-φ, 1]] with power φ = (n' - n) / R; a gap of thickness t in index n is [[1, t / n], [0, 1]].
// Their product from the front vertex to the rear vertex is M = [[A, B], [C, D]], and with air on both
// sides (det M = 1):
//     effective focal length  f   = -1 / C
//     back focal distance     BFD = -A / C  (rear vertex to F')
//     front focal distance    FFD = -D / C  (F to the front vertex)
//     an axial object s in front of the front vertex images at s' = -(A s + B) / (C s + D) behind the rear
//     one, with lateral magnification A + s' C (the object-to-image matrix T(s') M T(s) has B = 0 there
//     and this A).
#pragma once

#include "illum/camera/lens_file.h"

namespace illum {

struct ParaxialLens {
    double a = 1, b = 0, c = 0, d = 1;

    double efl() const { return -1 / c; }
    double back_focal_distance() const { return -a / c; }
    double front_focal_distance() const { return -d / c; }
    double image_distance(double object_distance) const {
        return -(a * object_distance + b) / (c * object_distance + d);
    }
    double magnification(double object_distance) const { return a + image_distance(object_distance) * c; }
};

// The system matrix at wavelength lambda_nm (each glass's index from cauchy_glass.h), in metres; the last
// surface's thickness (to the film) is not part of it.
ParaxialLens paraxial_lens(const LensPrescription& lens, double lambda_nm);

} // namespace illum
