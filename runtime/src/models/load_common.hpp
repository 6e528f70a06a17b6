// Shared between the glTF and OBJ loaders (runtime/src/models/): the error type that unwinds a load, and the
// checks every loader applies to its output (docs/models.md, "Bad files").
#pragma once
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include <ctess/runtime/models/model.hpp>

namespace ctess::models::detail {

// Thrown inside the loaders only; load_model turns it into a LoadError (nothing escapes).
struct LoadFailure {
    std::string problem;
};

// A position with -0.0 written as +0.0, so that meshoptimizer's bitwise position equality (Adjacency) joins
// the two zeros.
inline float canonical_zero(float x) {
    return x == 0.0f ? 0.0f : x;
}

inline bool same_position(const float* a, const float* b) {
    return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

// Appends a triangle or quad, or counts it as degenerate when two of its corners share a position (a
// zero-length edge: no area to tessellate, and an edge that adjacency could not pair).
void append_face(Model& model, const std::uint32_t* corners, unsigned corner_count);

// After loading: the model has at least one face and every value is finite.
void check_model(const Model& model);

} // namespace ctess::models::detail
