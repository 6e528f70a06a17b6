// The D3D11 tessellator against Microsoft's reference (CHWTessellator): 600 cases, points and indices bit for
// bit. The reference output is TRIANGLE_CW; TRIANGLE_CCW must equal it with the last two indices of each
// triangle swapped, and isolines ignore the winding.
#include <catch2/catch.hpp>

#include <cstdint>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include <ctess/d3d11/tessellator.hpp>

#include "support/d3d11_oracle_reader.hpp"

namespace {

using namespace ctess::d3d11;
using ctess::test::OracleCase;

struct Mesh {
    std::uint32_t vertex_count = 0; // Counts::vertices or IsolineCounts::vertices
    std::uint32_t index_count = 0;  // their index_count(): 3 per triangle, 2 per segment
    std::vector<Point> points;
    std::vector<std::uint32_t> indices;
};

Partitioning parse_partitioning(const std::string& name) {
    if (name == "integer") return Partitioning::integer;
    if (name == "pow2") return Partitioning::pow2;
    if (name == "fractional_odd") return Partitioning::fractional_odd;
    REQUIRE(name == "fractional_even");
    return Partitioning::fractional_even;
}

// Count first, then fill buffers of exactly that size (the count-only path must agree with the fill).
template <std::size_t N, class Tessellate>
Mesh run(Tessellate tessellate, const TessOptions& options, const std::vector<float>& factors) {
    REQUIRE(factors.size() == N);
    std::array<float, N> f{};
    for (std::size_t k = 0; k < N; ++k) f[k] = factors[k];
    Mesh m;
    const auto counts = tessellate({}, {}, f, options);
    m.vertex_count = counts.vertices;
    m.index_count = counts.index_count();
    m.points.resize(m.vertex_count);
    m.indices.resize(m.index_count);
    const auto filled = tessellate(m.points, m.indices, f, options);
    REQUIRE(filled == counts);
    return m;
}

Mesh run_case(const OracleCase& c, Winding winding) {
    const TessOptions options{parse_partitioning(c.partitioning), winding};
    if (c.domain == "tri") return run<4>(tessellate_tri, options, c.factors);
    if (c.domain == "quad") return run<6>(tessellate_quad, options, c.factors);
    REQUIRE(c.domain == "iso");
    return run<2>(tessellate_isoline, options, c.factors);
}

std::string describe(const OracleCase& c) {
    std::ostringstream s; // not operator+: g++ 12 warns falsely (-Wrestrict) on it
    s << c.domain << ' ' << c.partitioning << " line " << c.line << " factors";
    for (const float f : c.factors) s << ' ' << std::setprecision(9) << f;
    return s.str();
}

struct FileResult {
    std::size_t cases = 0;
    std::size_t culled = 0;
};

FileResult check_file(const std::string& domain, const std::string& partitioning) {
    std::string path = CTESS_TEST_DATA_DIR;
    path.append("/d3d11_").append(domain).append("_").append(partitioning).append(".jsonl.gz");
    const std::vector<OracleCase> cases = ctess::test::read_oracle_cases(path);
    std::size_t culled = 0;
    for (const OracleCase& c : cases) {
        INFO(describe(c));
        REQUIRE(c.domain == domain);
        REQUIRE(c.partitioning == partitioning);
        const Mesh cw = run_case(c, Winding::cw);

        REQUIRE(cw.vertex_count == c.points.size());
        REQUIRE(cw.index_count == c.indices.size());
        // Culled exactly when an edge factor (isoline: either factor) is NaN or not positive.
        const std::size_t edges = domain == "tri" ? 3 : domain == "quad" ? 4 : 2;
        bool expect_culled = false;
        for (std::size_t k = 0; k < edges; ++k) expect_culled = expect_culled || !(c.factors[k] > 0.0f);
        REQUIRE(c.points.empty() == expect_culled);
        if (expect_culled) {
            ++culled;
            REQUIRE(cw.index_count == 0);
        }
        for (std::size_t k = 0; k < c.points.size(); ++k) {
            INFO("point " << k);
            REQUIRE(cw.points[k].u == c.points[k].first);
            REQUIRE(cw.points[k].v == c.points[k].second);
        }
        REQUIRE(cw.indices == c.indices);

        const Mesh ccw = run_case(c, Winding::ccw);
        REQUIRE(ccw.vertex_count == cw.vertex_count);
        REQUIRE(ccw.index_count == cw.index_count);
        REQUIRE(ccw.points == cw.points);
        std::vector<std::uint32_t> expected = c.indices;
        if (domain != "iso")
            for (std::size_t k = 0; k + 2 < expected.size(); k += 3)
                std::swap(expected[k + 1], expected[k + 2]);
        REQUIRE(ccw.indices == expected);
    }
    return {cases.size(), culled};
}

const char* const partitionings[] = {"integer", "pow2", "fractional_odd", "fractional_even"};

// Every partitioning's file of one domain.
FileResult check_domain(const char* domain) {
    FileResult total;
    for (const char* p : partitionings) {
        const FileResult r = check_file(domain, p);
        total.cases += r.cases;
        total.culled += r.culled;
    }
    return total;
}

} // namespace

TEST_CASE("d3d11 oracle: triangle domain, 400 cases bit-exact", "[d3d11][oracle]") {
    const FileResult total = check_domain("tri");
    REQUIRE(total.cases == 400);
    REQUIRE(total.culled == 15); // culled cases present in the data
}

TEST_CASE("d3d11 oracle: quad domain, 160 cases bit-exact", "[d3d11][oracle]") {
    const FileResult total = check_domain("quad");
    REQUIRE(total.cases == 160);
    REQUIRE(total.culled == 4); // culled cases present in the data
}

TEST_CASE("d3d11 oracle: isoline domain, 40 cases bit-exact", "[d3d11][oracle]") {
    const FileResult total = check_domain("iso");
    REQUIRE(total.cases == 40);
    REQUIRE(total.culled == 1); // culled cases present in the data
}
