#include "mesh.hpp"

#include "cli_args.hpp"

#include <ctess/analysis/signed_area.hpp>
#include <ctess/cp/pattern.hpp>
#include <ctess/cp/quad.hpp>
#include <ctess/d3d11/tessellator.hpp>

#include <array>
#include <limits>
#include <map>

#include <fmt/core.h>

namespace ctess::cli {

const std::vector<std::string>& pattern_modes() {
    static const std::vector<std::string> modes = {"cp",        "d3d11-integer", "d3d11-pow2",
                                                   "d3d11-odd", "d3d11-even",    "uniform"};
    return modes;
}

bool is_d3d11_mode(const std::string& mode) {
    return mode.rfind("d3d11-", 0) == 0;
}

namespace {

d3d11::Partitioning partitioning_of(const std::string& mode) {
    if (mode == "d3d11-integer") return d3d11::Partitioning::integer;
    if (mode == "d3d11-pow2") return d3d11::Partitioning::pow2;
    if (mode == "d3d11-odd") return d3d11::Partitioning::fractional_odd;
    return d3d11::Partitioning::fractional_even;
}

float max_of(const std::vector<float>& v, std::size_t n) {
    float m = v[0];
    for (std::size_t i = 1; i < n; ++i) m = v[i] > m ? v[i] : m;
    return m;
}

template <class Point, class Tessellate>
void fill(Mesh& mesh, Tessellate&& tessellate) {                                    // counts, then fill
    const auto counts = tessellate(std::span<Point>{}, std::span<std::uint32_t>{}); // or IsolineCounts
    std::vector<Point> points(counts.vertices);
    mesh.indices.resize(counts.index_count());
    tessellate(std::span<Point>(points), std::span<std::uint32_t>(mesh.indices));
    set_points(mesh, std::span<const Point>(points));
}

Mesh tessellate_d3d11(const PatternRequest& r) {
    const d3d11::TessOptions opt{partitioning_of(r.mode), r.ccw ? d3d11::Winding::ccw : d3d11::Winding::cw};
    Mesh mesh;
    const auto& f = r.factors;
    auto run = [&](auto fn, const auto& factors) {
        fill<d3d11::Point>(mesh, [&](std::span<d3d11::Point> v, std::span<std::uint32_t> i) {
            return fn(v, i, factors, opt);
        });
    };
    if (r.domain == "tri") {
        if (f.size() != 3 && f.size() != 4)
            throw UsageError(fmt::format(
                "--factors: the tri domain takes Ueq0,Veq0,Weq0[,inside], got {} values", f.size()));
        // Without an inside factor, use the largest edge factor (HLSL's "max" inside reduction).
        const std::array<float, 4> tf = {f[0], f[1], f[2], f.size() == 4 ? f[3] : max_of(f, 3)};
        run([](auto&&... a) { return d3d11::tessellate_tri(a...); }, tf);
    } else if (r.domain == "quad") {
        if (f.size() != 4 && f.size() != 6)
            throw UsageError(fmt::format(
                "--factors: the quad domain takes Ueq0,Veq0,Ueq1,Veq1[,insideU,insideV], got {} values",
                f.size()));
        const float in_u = f.size() == 6 ? f[4] : (f[1] > f[3] ? f[1] : f[3]);
        const float in_v = f.size() == 6 ? f[5] : (f[0] > f[2] ? f[0] : f[2]);
        const std::array<float, 6> tf = {f[0], f[1], f[2], f[3], in_u, in_v};
        run([](auto&&... a) { return d3d11::tessellate_quad(a...); }, tf);
    } else {
        if (f.size() != 2)
            throw UsageError(
                fmt::format("--factors: the iso domain takes density,detail, got {} values", f.size()));
        const std::array<float, 2> tf = {f[0], f[1]};
        run([](auto&&... a) { return d3d11::tessellate_isoline(a...); }, tf);
        mesh.vertices_per_primitive = 2;
    }
    return mesh;
}

Mesh tessellate_cp(const PatternRequest& r) {
    if (r.domain == "iso") throw UsageError("--domain: the cp mode tessellates tri and quad domains");
    const bool quad = r.domain == "quad";
    if (r.factors.size() != (quad ? 4u : 3u))
        throw UsageError(
            quad ? fmt::format("--factors: a cp quad takes four edge factors (q0q1, q1q2, q2q3, q3q0), "
                               "got {} values",
                               r.factors.size())
                 : fmt::format("--factors: cp takes three edge factors n0,n1,n2, got {} values",
                               r.factors.size()));
    cp::PatternOptions opt;
    opt.max_factor = r.max_factor;
    opt.layout = r.provoking_layout ? Layout::provoking : Layout::shared;
    opt.winding = r.ccw ? Winding::ccw : Winding::cw; // the provoking vertex stays first either way
    opt.column_rule = r.staircase_columns ? cp::ColumnRule::staircase : cp::ColumnRule::minimal;
    Mesh mesh;
    const auto& f = r.factors;
    if (!quad)
        fill<DomainPoint>(mesh, [&](std::span<DomainPoint> v, std::span<std::uint32_t> i) {
            return cp::tessellate(v, i, f[0], f[1], f[2], opt);
        });
    else // the shared layout welds the diagonal (cp::tessellate_quad)
        fill<DomainPoint>(mesh, [&](std::span<DomainPoint> v, std::span<std::uint32_t> i) {
            return cp::tessellate_quad(v, i, {f[0], f[1], f[2], f[3]}, opt);
        });
    return mesh;
}

} // namespace

Mesh tessellate(const PatternRequest& request) {
    choice(request.mode, pattern_modes(), "--mode");
    choice(request.domain, {"tri", "quad", "iso"}, "--domain");
    if (request.mode == "uniform") return tessellate_uniform(request);
    return is_d3d11_mode(request.mode) ? tessellate_d3d11(request) : tessellate_cp(request);
}

std::int64_t doubled_area(const Mesh& mesh, std::size_t t) {
    // Exact in 128 bits: split uniform patches use fixed_one = 65534^2, whose squares exceed 64 bits; the
    // result saturates (sign and zero kept).
    const analysis::int128 area =
        analysis::signed_area2(mesh.vertices[mesh.indices[3 * t]], mesh.vertices[mesh.indices[3 * t + 1]],
                               mesh.vertices[mesh.indices[3 * t + 2]]);
    constexpr std::int64_t top = std::numeric_limits<std::int64_t>::max();
    return area > top ? top : area < -top ? -top : static_cast<std::int64_t>(area);
}

std::size_t degenerate_triangles(const Mesh& mesh) {
    if (mesh.vertices_per_primitive != 3) return 0;
    std::size_t n = 0;
    for (std::size_t t = 0; t < mesh.primitive_count(); ++t) n += doubled_area(mesh, t) == 0;
    return n;
}

} // namespace ctess::cli
