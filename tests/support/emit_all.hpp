// Emits a runtime patch (anything with counts() and emit(vertices, indices)) into vectors, requiring success.
#pragma once
#include <cstdint>
#include <vector>

#include <ctess/core/domain_point.hpp>

#include <catch2/catch.hpp>

namespace ctess::test {

struct Emitted {
    std::vector<DomainPoint> vertices;
    std::vector<std::uint32_t> indices;
};

template <class Patch>
Emitted emit_all(const Patch& p) {
    Emitted e;
    e.vertices.resize(p.counts().vertices);
    e.indices.resize(p.counts().index_count());
    REQUIRE(p.emit(e.vertices, e.indices));
    return e;
}

} // namespace ctess::test
