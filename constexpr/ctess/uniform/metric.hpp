// The intrinsic metric of uniform density (docs/algorithm.md §3.1): the factors are the side lengths of the
// patch. The squared length of a barycentric vector (du, dv, dw = -du - dv) is
// -f2^2 dv dw - f0^2 dw du - f1^2 du dv (f0 on e0 = v0v1, f1 on e1 = v1v2, f2 on e2 = v2v0); it goes negative
// for some vectors when f0 >= f1 + f2 (no Euclidean triangle), and intrinsic_length clamps it at 0.
#pragma once
#include <array>
#include <cmath>

namespace ctess::uniform {

constexpr double intrinsic_length_squared(const std::array<double, 3>& f, double du, double dv) noexcept {
    const double dw = -du - dv;
    return -f[2] * f[2] * dv * dw - f[0] * f[0] * dw * du - f[1] * f[1] * du * dv;
}

// Whether the factors are the sides of a real triangle (every one shorter than the other two together), so
// that every nonzero vector has a positive length.
constexpr bool is_real_triangle(const std::array<double, 3>& f) noexcept {
    return f[0] < f[1] + f[2] && f[1] < f[2] + f[0] && f[2] < f[0] + f[1];
}

inline double intrinsic_length(const std::array<double, 3>& f, double du, double dv) noexcept {
    const double s = intrinsic_length_squared(f, du, dv);
    return s > 0 ? std::sqrt(s) : 0.0;
}

} // namespace ctess::uniform
