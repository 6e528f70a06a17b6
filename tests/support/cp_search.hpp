// O(1) reverse lookup in a concave prefix sequence Y_0 = 0 <= Y_1 <= ... (column starts, strip starts):
// the largest k in [0, h-1] with Y_k <= e, from a float first guess on a stored quadratic, one integer Newton
// step and a fixed window of compares (docs/algorithm.md §4.4). No loop depends on the data, and
// the Newton step's two directions are written as selects. The GPU shaders use it (no per-patch state);
// CpPatch uses per-patch bucket searches for strips and columns instead (cp_patch.hpp), which cost fewer
// instructions on a CPU.
//
// Why it is exact: a Newton step on a concave sequence never overshoots (residual >= 0), and the tests check
// for every element of every token pair, with the first guess moved by -1, 0 and +1, that the residual left
// for the window is at most cp::tables::search_window.
#pragma once
#include <cmath>
#include <cstdint>

#include <ctess/cp/tables_layout.hpp>

namespace ctess::rt {

// Smaller root of alpha x - beta x^2 = e, clamped to [0, h-1]; any NaN or inf gives 0 or h-1.
inline int search_first_guess(float alpha, float beta, float e, unsigned h) {
    float d = alpha * alpha - 4.0f * beta * e;
    d = d > 0.0f ? d : 0.0f;
    float x = 2.0f * e / (alpha + std::sqrt(d));
    const float last = static_cast<float>(h - 1);
    x = x > 0.0f ? x : 0.0f; // also NaN -> 0
    x = x < last ? x : last;
    return static_cast<int>(x);
}

// One integer Newton step from x0 (clamped to [0, h-1]) towards the largest k with y(k) <= e. On a concave y
// it never passes that k, so the result is at or below it. Forward from y(x0) <= e, else backward (rounding
// the step up); both sides are computed and selected.
template <class Y>
inline int search_newton_step(const Y& y, unsigned h, int e, int x0) {
    const int last = static_cast<int>(h) - 1;
    const int x = x0 < 0 ? 0 : x0 > last ? last : x0;
    const int y0 = y(x);
    const int ahead = y(x + 1) - y0;              // >= 1 inside the head
    const int behind = y0 - y(x > 0 ? x - 1 : 0); // 0 at x = 0, where the step is never backward
    const bool forward = e >= y0;
    const int step = forward ? ahead : behind;
    const int den = step > 0 ? step : 1; // no input divides by 0
    const int num = forward ? e - y0 : (y0 - e) + den - 1;
    const int q = num / den;
    const int next = forward ? x + q : x - q;
    return next < 0 ? 0 : next > last ? last : next;
}

// Largest k in [0, h-1] with y(k) <= e, given y(0) <= e < y(h) and y concave with steps >= 1 below h: a
// Newton step, then the window. y is read at most at x0 - 1 .. x0 + window + 1.
template <class Y>
inline unsigned search_from(const Y& y, unsigned h, int e, int x0) {
    const int last = static_cast<int>(h) - 1;
    const int x = search_newton_step(y, h, e, x0);
    unsigned i = static_cast<unsigned>(x);
    for (unsigned k = 1; k <= cp::tables::search_window; ++k) {
        const int at = x + static_cast<int>(k);
        i += static_cast<unsigned>((at <= last) & (y(at) <= e));
    }
    return i;
}

} // namespace ctess::rt
