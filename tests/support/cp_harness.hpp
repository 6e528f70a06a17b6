// Test harness for the CP triangle pattern: token enumeration, a seeded generator, line points of a state,
// and running cp::tessellate into reusable buffers sized by cp::max_pattern_counts.
#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <ctess/cp/line.hpp>
#include <ctess/cp/pattern.hpp>

#include "mesh_checks.hpp"

namespace ctess::test {

// splitmix64: small, seeded, identical on every platform.
struct Rng {
    std::uint64_t state;
    explicit Rng(std::uint64_t seed) : state(seed) {}
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    std::uint32_t below(std::uint32_t n) { return static_cast<std::uint32_t>(next() % n); }
    std::uint32_t lerp() { return below(cp::lerp_one + 1); }           // t16 in [0, 65536]
    std::uint32_t inner_lerp() { return 1 + below(cp::lerp_one - 1); } // t16 in [1, 65535]
    float factor(float lo, float hi) {
        return lo + (hi - lo) * static_cast<float>(next() >> 40) / static_cast<float>(1ull << 24);
    }
};

// The default options at an explicit maximum (the tests never depend on the CTESS_MAX_TESS_FACTOR build
// option).
constexpr cp::PatternOptions default_options(unsigned max_factor) {
    cp::PatternOptions o;
    o.max_factor = max_factor;
    return o;
}

// A valid line state of a token: T0 has no lerp (t16 = 0).
constexpr cp::LineState state(unsigned token, std::uint32_t t16) {
    return {token, token == 0 ? 0u : t16};
}

// Boundary k | k+1 of a line: the state at the end of token k and the one at the start of token k+1. They
// have the same point positions. T0 ends at its only state (f = 1).
constexpr cp::LineState boundary_before(unsigned k) {
    return state(k, cp::lerp_one);
}
constexpr cp::LineState boundary_after(unsigned k) {
    return {k + 1, 0};
}

// Every valid state of every token at the given lerps (T0 once).
inline std::vector<cp::LineState> token_states(unsigned max_factor, std::span<const std::uint32_t> lerps) {
    std::vector<cp::LineState> out{{0, 0}};
    for (unsigned t = 1; t < cp::token_count(max_factor); ++t)
        for (std::uint32_t l : lerps) out.push_back({t, l});
    return out;
}

inline std::vector<std::uint32_t> line_points(cp::LineState s) {
    std::vector<std::uint32_t> p(cp::max_segments + 1);
    p.resize(cp::edge_points(s, p.data()));
    return p;
}

// Largest distance (units of 2^-24 per unit of t16) a line point of this token moves.
inline std::uint32_t max_track_length(unsigned token) {
    std::array<cp::PointTrack, cp::max_segments + 1> tracks{};
    const unsigned n = cp::token_points(token, tracks.data());
    std::uint32_t worst = 0;
    for (unsigned i = 0; i < n; ++i) {
        const std::uint32_t d = tracks[i].final > tracks[i].start ? tracks[i].final - tracks[i].start
                                                                  : tracks[i].start - tracks[i].final;
        worst = d > worst ? d : worst;
    }
    return worst;
}

inline std::string describe(cp::LineState s) {
    return cat("T", s.token, "@", s.t16);
}
inline std::string describe(cp::LineState s0, cp::LineState s1, cp::LineState s2) {
    return cat("(", describe(s0), ", ", describe(s1), ", ", describe(s2), ")");
}

// Runs cp::tessellate into buffers allocated once for the largest pattern of the options' max_factor. The
// buffers have slack beyond max_pattern_counts, so that a count above the bound is reported instead of
// overrunning.
class CpRunner {
  public:
    explicit CpRunner(const cp::PatternOptions& options)
        : options_(options), capacity_(cp::max_pattern_counts(options.max_factor)),
          vertices_(2 * std::size_t{capacity_.vertices} + slack),
          indices_(3 * (2 * std::size_t{capacity_.triangles} + slack)) {}

    const cp::PatternOptions& options() const { return options_; }
    Counts capacity() const { return capacity_; }

    MeshView run(cp::LineState s0, cp::LineState s1, cp::LineState s2) {
        counts_ = cp::tessellate(vertices_, indices_, s0, s1, s2, options_);
        return view();
    }
    MeshView run(float f0, float f1, float f2) {
        counts_ = cp::tessellate(vertices_, indices_, f0, f1, f2, options_);
        return view();
    }
    Counts counts() const { return counts_; }
    // True when the last run fits the buffers (a larger count would have written past them).
    bool within_capacity() const {
        return counts_.vertices <= capacity_.vertices && counts_.triangles <= capacity_.triangles;
    }

  private:
    static constexpr std::size_t slack = 4096;
    MeshView view() const {
        if (!within_capacity()) return {};
        return {std::span<const DomainPoint>(vertices_.data(), counts_.vertices),
                std::span<const std::uint32_t>(indices_.data(), 3 * std::size_t{counts_.triangles})};
    }
    cp::PatternOptions options_;
    Counts capacity_;
    Counts counts_{};
    std::vector<DomainPoint> vertices_;
    std::vector<std::uint32_t> indices_;
};

// Validity of one CP mesh against the line points of its three states (see check_valid_tessellation).
inline ValidityReport check_cp_mesh(const MeshView& m, cp::LineState s0, cp::LineState s1, cp::LineState s2) {
    const auto p0 = line_points(s0), p1 = line_points(s1), p2 = line_points(s2);
    return check_valid_tessellation(m, cp::fixed_one, p0, p1, p2);
}

// Collects failure descriptions and keeps the first few for the report.
struct FailureLog {
    std::size_t count = 0;
    std::string first;
    void add(const std::string& what) {
        if (count++ < 12) first += cat(what, "\n");
    }
    std::string summary() const { return cat(count, " failures; first:\n", first); }
};

} // namespace ctess::test
