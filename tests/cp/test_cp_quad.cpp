// CP quads in the library (cp::tessellate_quad, docs/algorithm.md §2.12): the two halves of split_quad in the
// unit square, with the diagonal welded in the shared layout. Checked against the halves tessellated one by
// one and welded by exact coordinates, over factor sets that put every kind of line (T0, T1, fractional, top)
// on every edge and on the diagonal.
#include <catch2/catch.hpp>

#include <ctess/analysis/signed_area.hpp>
#include <ctess/cp/quad.hpp>

#include <array>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

using namespace ctess;

namespace {

struct QuadMesh {
    std::vector<DomainPoint> vertices;
    std::vector<std::uint32_t> indices;
};

QuadMesh library_quad(const std::array<float, 4>& f, const cp::PatternOptions& opt) {
    const Counts n = cp::tessellate_quad({}, {}, f, opt);
    QuadMesh m{std::vector<DomainPoint>(n.vertices + 1, DomainPoint{7, 7}),
               std::vector<std::uint32_t>(n.index_count() + 1, 0xdeadbeef)};
    REQUIRE(cp::tessellate_quad(m.vertices, m.indices, f, opt) == n);
    REQUIRE(m.vertices.back() == DomainPoint{7, 7}); // nothing written past the counts
    REQUIRE(m.indices.back() == 0xdeadbeef);
    m.vertices.pop_back();
    m.indices.pop_back();
    return m;
}

// The reference: each half on its own, mapped, appended; in the shared layout every vertex on the diagonal
// u + v = 1 is replaced by the first vertex with the same coordinates.
QuadMesh reference_quad(const std::array<float, 4>& f, const cp::PatternOptions& opt) {
    const cp::QuadSplit split = cp::split_quad(f);
    QuadMesh m;
    for (unsigned half = 0; half < 2; ++half) {
        const auto& hf = split.triangles[half].factors;
        const Counts n = cp::pattern_counts(hf[0], hf[1], hf[2], opt);
        std::vector<DomainPoint> v(n.vertices);
        std::vector<std::uint32_t> t(n.index_count());
        cp::tessellate(v, t, hf[0], hf[1], hf[2], opt);
        const auto base = static_cast<std::uint32_t>(m.vertices.size());
        for (const DomainPoint& p : v) m.vertices.push_back(cp::quad_point(half, p));
        for (const std::uint32_t i : t) m.indices.push_back(base + i);
    }
    if (opt.layout == Layout::provoking) return m;
    // Shared: B's diagonal vertices go to A's with the same coordinates. At a zero-length segment two
    // diagonal points coincide; B meets them in the opposite order to A, so the k-th of B is the k-th from
    // last of A.
    const auto a_count = static_cast<std::uint32_t>(cp::pattern_counts(split.triangles[0].factors[0],
                                                                       split.triangles[0].factors[1],
                                                                       split.triangles[0].factors[2], opt)
                                                        .vertices);
    auto on_diagonal = [](DomainPoint p) { return std::uint64_t{p.u} + p.v == cp::fixed_one; };
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> in_a, seen_in_b;
    for (std::uint32_t i = 0; i < a_count; ++i)
        if (on_diagonal(m.vertices[i])) in_a[{m.vertices[i].u, m.vertices[i].v}].push_back(i);
    std::vector<std::uint32_t> remap(m.vertices.size());
    std::vector<DomainPoint> kept(m.vertices.begin(), m.vertices.begin() + a_count);
    for (std::uint32_t i = 0; i < a_count; ++i) remap[i] = i;
    for (std::uint32_t i = a_count; i < m.vertices.size(); ++i) {
        const DomainPoint p = m.vertices[i];
        if (on_diagonal(p)) {
            const auto& a = in_a.at({p.u, p.v});
            auto& b = seen_in_b[{p.u, p.v}];
            REQUIRE(b.size() < a.size());
            remap[i] = a[a.size() - 1 - b.size()];
            b.push_back(i);
        } else {
            remap[i] = static_cast<std::uint32_t>(kept.size());
            kept.push_back(p);
        }
    }
    for (auto& i : m.indices) i = remap[i];
    m.vertices = kept;
    return m;
}

} // namespace

TEST_CASE("cp::tessellate_quad equals its halves, welded by coordinates in the shared layout", "[cp_quad]") {
    const float values[] = {1.0f, 1.5f, 2.0f, 2.7f, 4.0f, 6.3f, 13.0f, 64.0f};
    std::size_t quads = 0;
    for (const float a : values)
        for (const float b : values)
            for (const float c : values)
                for (const float d : {1.0f, 2.7f, 13.0f}) {
                    const std::array<float, 4> f = {a, b, c, d};
                    for (const Layout layout : {Layout::provoking, Layout::shared})
                        for (const Winding winding : {Winding::ccw, Winding::cw}) {
                            cp::PatternOptions opt;
                            opt.layout = layout;
                            opt.winding = winding;
                            INFO(a << "," << b << "," << c << "," << d << " shared "
                                   << (layout == Layout::shared) << " cw " << (winding == Winding::cw));
                            const QuadMesh lib = library_quad(f, opt);
                            const QuadMesh ref = reference_quad(f, opt);
                            REQUIRE(lib.vertices == ref.vertices);
                            REQUIRE(lib.indices == ref.indices);
                            ++quads;
                        }
                }
    REQUIRE(quads == 8 * 8 * 8 * 3 * 4);
}

TEST_CASE("a shared-layout CP quad covers the unit square once and keeps one diagonal", "[cp_quad]") {
    cp::PatternOptions opt;
    opt.layout = Layout::shared;
    for (const std::array<float, 4> f : {std::array<float, 4>{12, 5, 12, 30},
                                         {1, 1, 1, 1},
                                         {64, 64, 64, 64},
                                         {1.2f, 40, 2.5f, 7},
                                         {3, 3, 3, 3}}) {
        const QuadMesh m = library_quad(f, opt);
        // The diagonal's segments + 1 points, once (CP keeps coincident points at zero-length segments).
        std::uint32_t on_diagonal = 0;
        for (const DomainPoint& p : m.vertices) on_diagonal += std::uint64_t{p.u} + p.v == cp::fixed_one;
        const cp::LineState diagonal = cp::line_state(f[0], max_tess_factor);
        REQUIRE(on_diagonal == cp::token_info(diagonal.token).segments + 1u);
        ctess::analysis::int128 doubled_area = 0;
        for (std::size_t k = 0; k < m.indices.size(); k += 3) {
            for (unsigned j = 0; j < 3; ++j) REQUIRE(m.indices[k + j] < m.vertices.size());
            const auto cross = ctess::analysis::signed_area2(
                m.vertices[m.indices[k]], m.vertices[m.indices[k + 1]], m.vertices[m.indices[k + 2]]);
            REQUIRE(cross >= 0);
            doubled_area += cross;
        }
        REQUIRE(doubled_area == 2 * std::int64_t{cp::fixed_one} * cp::fixed_one);
    }
}

// Equal factors 4: two triforce halves of 15 vertices and 16 triangles sharing a diagonal of 5 points.
static_assert(cp::tessellate_quad({}, {}, {4, 4, 4, 4}, {{Layout::shared}}) == Counts{25, 32});
static_assert(cp::tessellate_quad({}, {}, {4, 4, 4, 4}) ==
              Counts{2 * cp::pattern_counts(4, 4, 4).vertices, 32});
