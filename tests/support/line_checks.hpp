// Exact checks on edge point lists (sorted parameters in fixed point), shared by the line-mode tests.
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

namespace ctess::test {

// True when p(N-1-i) + p(i) == one for every i, bit for bit.
inline bool mirror_exact(const std::vector<std::uint32_t>& p, std::uint32_t one) {
    for (std::size_t i = 0; i < p.size(); ++i)
        if (std::uint64_t{p[i]} + p[p.size() - 1 - i] != one) return false;
    return true;
}

inline bool non_decreasing(const std::vector<std::uint32_t>& p) {
    return std::is_sorted(p.begin(), p.end());
}

// Largest distance from a point of `a` to the nearest point of `b` and back (both sorted).
inline std::uint32_t hausdorff(const std::vector<std::uint32_t>& a, const std::vector<std::uint32_t>& b) {
    auto one_way = [](const std::vector<std::uint32_t>& x, const std::vector<std::uint32_t>& y) {
        std::uint32_t worst = 0;
        for (std::uint32_t p : x) {
            auto it = std::lower_bound(y.begin(), y.end(), p);
            std::uint32_t d = UINT32_MAX;
            if (it != y.end()) d = *it - p;
            if (it != y.begin()) d = std::min(d, p - *(it - 1));
            worst = std::max(worst, d);
        }
        return worst;
    };
    return std::max(one_way(a, b), one_way(b, a));
}

inline std::vector<std::uint32_t> distinct(std::vector<std::uint32_t> p) {
    p.erase(std::unique(p.begin(), p.end()), p.end());
    return p;
}

} // namespace ctess::test
