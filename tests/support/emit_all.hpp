// Emits a runtime patch (anything with counts() and emit(vertices, indices)) into vectors, requiring success.
#pragma once
#include <cstdint>
#include <vector>

#include <ctess/core/domain_point.hpp>

#include <catch2/catch.hpp>

namespace ctess::test {

template <class Point>
struct BasicEmitted {
    std::vector<Point> vertices;
    std::vector<std::uint32_t> indices;
};
using Emitted = BasicEmitted<DomainPoint>;

template <class Patch>
BasicEmitted<typename Patch::point_type> emit_all(const Patch& p) {
    BasicEmitted<typename Patch::point_type> e;
    e.vertices.resize(p.counts().vertices);
    e.indices.resize(p.counts().index_count());
    REQUIRE(p.emit(e.vertices, e.indices));
    return e;
}

} // namespace ctess::test
