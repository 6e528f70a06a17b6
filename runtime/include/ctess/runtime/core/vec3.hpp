// A minimal float 3-vector for the mesh pipeline. Every operation is written out component by component, in
// the order the generated shaders use, so that CPU and GPU round the same way (no fused multiply-add: the
// project builds with -std=c++20, which turns contraction off, and x86-64 has no FMA by default).
#pragma once
#include <cmath>

namespace ctess::rt {

struct Vec3 {
    float x = 0.0f, y = 0.0f, z = 0.0f;
};

inline Vec3 operator+(Vec3 a, Vec3 b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline Vec3 operator-(Vec3 a, Vec3 b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline Vec3 operator*(float s, Vec3 a) {
    return {s * a.x, s * a.y, s * a.z};
}
inline float dot(Vec3 a, Vec3 b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
// Zero stays zero (no NaN from a degenerate normal).
inline Vec3 normalize_or_zero(Vec3 a) {
    const float len2 = dot(a, a);
    if (!(len2 > 0.0f)) return {0.0f, 0.0f, 0.0f};
    const float inv = 1.0f / std::sqrt(len2);
    return inv * a;
}

} // namespace ctess::rt
