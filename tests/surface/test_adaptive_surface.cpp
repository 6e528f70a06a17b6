// Adaptive parametric tessellation (Męciński 2011): conformity of the bintree (exact areas, shared edges),
// the two split tests checked on the output against double-precision reference normals, the ripple case, the
// size bounds, and bad input.
#include <catch2/catch.hpp>

#include <ctess/runtime/surface/adaptive.hpp>
#include <ctess/runtime/surface/chord_error.hpp>
#include <ctess/runtime/surface/eval.hpp>
#include <ctess/runtime/surface/parametric.hpp>
#include <ctess/surface/conforming_bintree.hpp>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <ctess/analysis/square_mesh_checks.hpp>

using namespace ctess;
using namespace ctess::rt;
using adaptive::fixed_one;
using adaptive::Node;
using adaptive::ParamPoint;

namespace {

struct Result {
    AdaptiveStatus status{};
    Counts counts{};
    std::vector<Node> nodes; // the tree; leaves in node order are the triangles in emit order
    std::uint32_t node_count = 0;
    std::vector<ParamPoint> params;
    std::vector<SurfaceVertex> vertices;
    std::vector<std::uint32_t> triangles;

    std::vector<const Node*> leaves() const {
        std::vector<const Node*> out;
        for (std::uint32_t i = 0; i < node_count; ++i)
            if (nodes[i].is_leaf()) out.push_back(&nodes[i]);
        return out;
    }
    std::string violation() const {
        std::vector<analysis::SquarePoint> sq;
        for (std::uint32_t i = 0; i < counts.vertices; ++i) sq.push_back({params[i].p, params[i].q});
        return analysis::square_mesh_violation(sq, triangles, fixed_one);
    }
};

template <class S>
Result tessellate(const S& surface, const AdaptiveOptions& opt, std::size_t node_capacity = 0,
                  std::size_t vertex_capacity = 0) {
    const unsigned level = opt.max_level <= adaptive::max_level_limit ? opt.max_level : 0;
    Result r;
    r.nodes.resize(node_capacity ? node_capacity : adaptive::max_nodes(level));
    r.params.resize(vertex_capacity ? vertex_capacity : adaptive::max_vertices(level));
    r.vertices.resize(r.params.size());
    const AdaptiveSurface mesh({r.nodes, r.params, r.vertices}, surface, opt);
    r.status = mesh.status();
    r.counts = mesh.counts();
    r.node_count = r.counts.triangles ? mesh.tree().node_count() : 0;
    r.triangles.resize(3 * std::size_t{r.counts.triangles});
    REQUIRE(mesh.emit_triangles(r.triangles) == (r.counts.triangles != 0));
    return r;
}

// Double-precision reference geometry (position and unit normal) of the built-in surfaces.
struct Ref {
    double x, y, z, nx, ny, nz;
};

Ref ref_sphere(double u, double v) {
    const double t = 2 * M_PI * u, f = M_PI * v;
    const double x = std::sin(f) * std::cos(t), y = std::sin(f) * std::sin(t), z = -std::cos(f);
    return {x, y, z, x, y, z};
}

Ref ref_torus(double u, double v) {
    const double t = 2 * M_PI * u, f = 2 * M_PI * v, ring = 1.0 + 0.35 * std::cos(f);
    return {ring * std::cos(t),        ring * std::sin(t),        0.35 * std::sin(f),
            std::cos(f) * std::cos(t), std::cos(f) * std::sin(t), std::sin(f)};
}

Ref ref_ripple(double u, double v) {
    const double a = 0.03, k = 16 * M_PI;
    const double e = v < 0.5 ? std::pow(std::sin(2 * M_PI * v), 2) : 0.0;
    const double de = v < 0.5 ? 4 * M_PI * std::sin(2 * M_PI * v) * std::cos(2 * M_PI * v) : 0.0;
    const double hu = a * k * std::cos(k * u) * e, hv = a * std::sin(k * u) * de;
    const double nx = -2 * hu, ny = -2 * hv, nz = 4, len = std::sqrt(nx * nx + ny * ny + nz * nz);
    return {2 * u - 1, 2 * v - 1, a * std::sin(k * u) * e, nx / len, ny / len, nz / len};
}

double angle_deg(const Ref& a, const Ref& b) {
    const double c = a.nx * b.nx + a.ny * b.ny + a.nz * b.nz;
    return std::acos(c > 1 ? 1 : (c < -1 ? -1 : c)) * 180.0 / M_PI;
}

double chord_ratio(const Ref& a, const Ref& b, const Ref& m) {
    const double cx = b.x - a.x, cy = b.y - a.y, cz = b.z - a.z, len2 = cx * cx + cy * cy + cz * cz;
    double t = len2 > 0 ? ((m.x - a.x) * cx + (m.y - a.y) * cy + (m.z - a.z) * cz) / len2 : 0;
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    const double dx = m.x - a.x - t * cx, dy = m.y - a.y - t * cy, dz = m.z - a.z - t * cz;
    const double d = std::sqrt(dx * dx + dy * dy + dz * dz);
    return len2 > 0 ? d / std::sqrt(len2) : (d > 0 ? INFINITY : 0);
}

double to_double(std::uint32_t fixed) {
    return static_cast<double>(fixed) / fixed_one;
}

// Every leaf that the tests kept (level in [min_level, max_level)) passes both tests within float noise.
template <class RefFn>
void check_criteria_hold(const Result& r, const AdaptiveOptions& opt, RefFn ref) {
    std::uint32_t tested = 0;
    for (const Node* n : r.leaves()) {
        REQUIRE(n->level <= opt.max_level);
        if (n->level < opt.min_level || n->level >= opt.max_level) continue;
        const ParamPoint a = r.params[n->vertex[1]], b = r.params[n->vertex[2]];
        const Ref ra = ref(to_double(a.p), to_double(a.q)), rb = ref(to_double(b.p), to_double(b.q));
        const Ref rm = ref(to_double((a.p + b.p) / 2), to_double((a.q + b.q) / 2));
        CHECK(angle_deg(rm, ra) <= opt.max_angle_deg + 0.1);
        CHECK(angle_deg(rm, rb) <= opt.max_angle_deg + 0.1);
        CHECK(chord_ratio(ra, rb, rm) <= opt.max_distance * 1.001 + 1e-5);
        ++tested;
    }
    INFO("triangles " << r.counts.triangles << " max level " << opt.max_level << " angle "
                      << opt.max_angle_deg << " distance " << opt.max_distance);
    CHECK(tested > 0);
}

} // namespace

TEST_CASE("uniform refinement fills exactly the worst-case sizes, in constant expressions too",
          "[adaptive]") {
    constexpr auto uniform3 = [] {
        std::array<Node, 30> nodes{};
        std::array<ParamPoint, 13> params{};
        adaptive::ConformingBintree tree(nodes, params);
        tree.refine(
            3, [](std::uint32_t) { return adaptive::SplitDecision::split; },
            [](std::uint32_t) { return true; });
        return tree.counts();
    }();
    STATIC_REQUIRE(uniform3 == Counts{13, 16});
    STATIC_REQUIRE(adaptive::max_nodes(3) == 30);
    for (unsigned level = 0; level <= 12; ++level) {
        AdaptiveOptions opt;
        opt.min_level = opt.max_level = level;
        const Result r = tessellate(SphereSurface{}, opt);
        REQUIRE(r.status == AdaptiveStatus::ok);
        CHECK(r.counts.triangles == adaptive::max_triangles(level));
        CHECK(r.counts.vertices == adaptive::max_vertices(level));
        CHECK(r.node_count == adaptive::max_nodes(level));
        REQUIRE(r.violation().empty());
    }
}

TEST_CASE("random splits keep the bintree conforming and the base-neighbour invariant", "[adaptive]") {
    for (std::uint32_t seed = 1; seed <= 40; ++seed) {
        const unsigned max_level = 4 + seed % 13;
        std::vector<Node> nodes(adaptive::max_nodes(max_level));
        std::vector<ParamPoint> params(adaptive::max_vertices(max_level));
        adaptive::ConformingBintree tree(nodes, params);
        std::uint32_t state = seed * 2654435761u;
        const auto status = tree.refine(
            max_level,
            [&](std::uint32_t) {
                state = state * 1664525u + 1013904223u;
                return (state >> 24) < 90 ? adaptive::SplitDecision::split : adaptive::SplitDecision::keep;
            },
            [](std::uint32_t) { return true; });
        REQUIRE(status == adaptive::RefineStatus::ok);
        // The invariant the termination argument rests on.
        for (std::uint32_t i = 0; i < tree.node_count(); ++i) {
            const Node& n = tree.node(i);
            if (!n.is_leaf()) continue;
            REQUIRE(n.level <= max_level);
            const std::uint32_t b = n.neighbour[adaptive::edge_base];
            if (b == adaptive::no_node) continue;
            const Node& nb = tree.node(b);
            REQUIRE(nb.is_leaf());
            const bool diamond = nb.level == n.level && nb.neighbour[adaptive::edge_base] == i;
            REQUIRE((diamond || nb.level + 1 == n.level));
        }
        std::vector<std::uint32_t> tris(3 * tree.counts().triangles);
        REQUIRE(tree.emit_triangles(tris));
        std::vector<analysis::SquarePoint> sq;
        for (std::uint32_t i = 0; i < tree.vertex_count(); ++i) sq.push_back({params[i].p, params[i].q});
        REQUIRE(analysis::square_mesh_violation(sq, tris, fixed_one) == "");
    }
}

TEST_CASE(
    "sphere, torus and ripple are conforming and meet both tests wherever the max level was not reached",
    "[adaptive]") {
    for (float angle : {5.0f, 2.0f, 15.0f}) {
        for (float distance : {0.05f, 0.02f}) {
            AdaptiveOptions opt;
            opt.max_angle_deg = angle;
            opt.max_distance = distance;
            opt.max_level = 14;
            const Result sphere = tessellate(SphereSurface{}, opt);
            REQUIRE(sphere.status == AdaptiveStatus::ok);
            REQUIRE(sphere.violation() == "");
            check_criteria_hold(sphere, opt, ref_sphere);
            const Result torus = tessellate(TorusSurface{}, opt);
            REQUIRE(torus.status == AdaptiveStatus::ok);
            REQUIRE(torus.violation() == "");
            check_criteria_hold(torus, opt, ref_torus);
            const Result ripple = tessellate(RippleSurface{}, opt);
            REQUIRE(ripple.status == AdaptiveStatus::ok);
            REQUIRE(ripple.violation() == "");
            check_criteria_hold(ripple, opt, ref_ripple);
        }
    }
}

TEST_CASE("on ripple the normal test refines where the distance test sees a flat plane", "[adaptive]") {
    AdaptiveOptions both;
    AdaptiveOptions distance_only = both;
    distance_only.max_angle_deg = 180.0f;
    const Result with_angle = tessellate(RippleSurface{}, both);
    const Result without = tessellate(RippleSurface{}, distance_only);
    REQUIRE(with_angle.status == AdaptiveStatus::ok);
    REQUIRE(without.status == AdaptiveStatus::ok);
    // Every sample the distance test sees lies on z = 0: it keeps the uniform min-level mesh.
    CHECK(without.counts.triangles == adaptive::max_triangles(both.min_level));

    const auto in_ripples = [](const Result& r) {
        std::uint32_t n = 0;
        for (std::size_t t = 0; t < r.triangles.size(); t += 3) {
            bool below = true;
            for (int k = 0; k < 3; ++k) below = below && r.params[r.triangles[t + k]].q <= fixed_one / 2;
            n += below;
        }
        return n;
    };
    CHECK(in_ripples(with_angle) > 8 * in_ripples(without));
    // The flat top quarter needs nothing beyond what conformity forces near the band.
    const auto in_top = [](const Result& r) {
        std::uint32_t n = 0;
        for (std::size_t t = 0; t < r.triangles.size(); t += 3) {
            bool above = true;
            for (int k = 0; k < 3; ++k) above = above && r.params[r.triangles[t + k]].q >= 3 * fixed_one / 4;
            n += above;
        }
        return n;
    };
    CHECK(in_top(with_angle) == in_top(without));
}

TEST_CASE("bad options give a status and an empty mesh", "[adaptive]") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const auto status_of = [](AdaptiveOptions opt) {
        const Result r = tessellate(SphereSurface{}, opt, 64, 64);
        CHECK(r.counts == Counts{});
        return r.status;
    };
    struct Case {
        float angle, distance;
        unsigned min_level, max_level;
        AdaptiveStatus expect;
    };
    const Case cases[] = {
        {nan, 0.05f, 4, 16, AdaptiveStatus::bad_angle},
        {-1.0f, 0.05f, 4, 16, AdaptiveStatus::bad_angle},
        {5.0f, nan, 4, 16, AdaptiveStatus::bad_distance},
        {5.0f, -0.5f, 4, 16, AdaptiveStatus::bad_distance},
        {5.0f, 0.05f, 6, 5, AdaptiveStatus::bad_levels},
        {5.0f, 0.05f, 4, adaptive::max_level_limit + 1, AdaptiveStatus::bad_levels},
    };
    for (const Case& c : cases) {
        CHECK(status_of(AdaptiveOptions{c.angle, c.distance, c.min_level, c.max_level}) == c.expect);
    }
    CHECK(std::string(status_message(AdaptiveStatus::bad_levels)).find("min_level <= max_level") !=
          std::string::npos);
}

TEST_CASE("a surface returning NaN stops the refinement with a status and a conforming mesh", "[adaptive]") {
    struct HoleSurface { // NaN in a small square that only the level-4 tests sample
        Vec3 position(float u, float v) const {
            if (u > 0.3f && u < 0.4f && v > 0.3f && v < 0.4f) return {NAN, 0.0f, 0.0f};
            return {u, v, u * v};
        }
    };
    const Result r = tessellate(HoleSurface{}, AdaptiveOptions{});
    CHECK(r.status == AdaptiveStatus::surface_not_finite);
    CHECK(r.counts.triangles >= 32);
    CHECK(r.violation() == "");
    for (std::uint32_t i = 0; i < r.counts.vertices; ++i) CHECK(std::isfinite(r.vertices[i].position.x));

    struct NanCorner {
        Vec3 position(float u, float v) const { return {u + v == 0.0f ? NAN : u, v, 0.0f}; }
    };
    const Result corner = tessellate(NanCorner{}, AdaptiveOptions{});
    CHECK(corner.status == AdaptiveStatus::surface_not_finite);
    CHECK(corner.counts == Counts{});
}

TEST_CASE("buffers that are too small stop with a status and a conforming mesh", "[adaptive]") {
    AdaptiveOptions opt;
    opt.max_distance = 0.0f; // refine the torus everywhere up to max_level
    opt.max_level = 12;
    const Result few_nodes = tessellate(TorusSurface{}, opt, 101, 0);
    CHECK(few_nodes.status == AdaptiveStatus::node_capacity);
    CHECK(few_nodes.node_count <= 101);
    CHECK(few_nodes.counts.triangles > 2);
    CHECK(few_nodes.violation() == "");

    const Result few_vertices = tessellate(TorusSurface{}, opt, 0, 40);
    CHECK(few_vertices.status == AdaptiveStatus::vertex_capacity);
    CHECK(few_vertices.counts.vertices <= 40);
    CHECK(few_vertices.violation() == "");

    const Result nothing = tessellate(TorusSurface{}, opt, 1, 40);
    CHECK(nothing.status == AdaptiveStatus::node_capacity);
    CHECK(nothing.counts == Counts{});

    // A short index span is refused, and nothing is written.
    std::vector<Node> nodes(adaptive::max_nodes(opt.max_level));
    std::vector<ParamPoint> params(adaptive::max_vertices(opt.max_level));
    std::vector<SurfaceVertex> vertices(params.size());
    const AdaptiveSurface mesh({nodes, params, vertices}, TorusSurface{}, opt);
    REQUIRE(mesh.status() == AdaptiveStatus::ok);
    CHECK(mesh.counts().triangles <= adaptive::max_triangles(opt.max_level));
    std::vector<std::uint32_t> indices(3 * mesh.counts().triangles - 1, 7u);
    CHECK_FALSE(mesh.emit_triangles(indices));
    for (std::uint32_t i : indices) CHECK(i == 7u);
}

TEST_CASE("finite-difference normals agree with the analytic ones", "[adaptive]") {
    struct SphereWithoutNormal {
        Vec3 position(float u, float v) const { return SphereSurface{}.position(u, v); }
    };
    for (float u : {0.1f, 0.37f, 0.5f, 0.93f, 1.0f}) {
        for (float v : {0.05f, 0.25f, 0.5f, 0.8f}) {
            const SurfaceVertex fd = evaluate_vertex(SphereWithoutNormal{}, u, v);
            const SurfaceVertex exact = evaluate_vertex(SphereSurface{}, u, v);
            CHECK(dot(fd.normal, exact.normal) > std::cos(0.1f * pi_f / 180.0f));
        }
    }
    // At a pole the finite differences are degenerate: a zero normal, never a NaN.
    const SurfaceVertex pole = evaluate_vertex(SphereWithoutNormal{}, 0.3f, 0.0f);
    CHECK(std::isfinite(pole.normal.x));
}

TEST_CASE("the chord error of a grid on z = u^2 is h^2 / 4, the worst edge midpoint", "[adaptive]") {
    // Linear interpolation of u^2 between u = a and u = b misses by (b - a)^2 / 4 at the midpoint, and by the
    // variance of u under the barycentric weights elsewhere, which is never more.
    struct Parabola {
        Vec3 position(float u, float v) const { return {u, v, u * u}; }
    };
    struct Plane {
        Vec3 position(float u, float v) const { return {2.0f * u, v - u, 0.5f}; }
    };
    for (std::uint32_t n : {1u, 2u, 3u, 8u, 25u}) {
        const double h = 1.0 / n;
        CHECK(grid_chord_error(Parabola{}, n, 7) == Approx(h * h / 4).margin(1e-6)); // float samples near 1
        CHECK(grid_chord_error(Plane{}, n, n) < 1e-6f);
    }
    CHECK(grid_chord_error(Parabola{}, 0, 3) == 0.0f);
}

TEST_CASE("evaluate_quad_surface: a corner shared by two quads has the same bits, zeros included",
          "[surface][quad]") {
    // V's -0.0 x is reached as 1 * -0 + 0 * 1 on quad A (V is q0) and as 0 * -1 + 1 * -0 on quad B (V is q1):
    // +0 and -0 without canonicalisation.
    const SurfaceCorner v{{-0.0f, 1.0f, 0.0f}, {-0.0f, 0.0f, 1.0f}, {-0.0f, 0.5f}, 5};
    const SurfaceCorner p{{1.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 1.0f}, {1.0f, 0.5f}, 6};
    const SurfaceCorner s{{-1.0f, 1.0f, 0.0f}, {-1.0f, 0.0f, 1.0f}, {-1.0f, 0.5f}, 4};
    const SurfaceCorner top{{0.0f, 2.0f, 0.0f}, {0.0f, 0.0f, 1.0f}, {0.0f, 1.0f}, 9};
    const SurfaceCorner quad_a[4] = {v, p, top, top};
    const SurfaceCorner quad_b[4] = {s, v, top, top};
    const SurfacePoint a = evaluate_quad_surface(quad_a, 0, 0);
    const SurfacePoint b = evaluate_quad_surface(quad_b, cp::fixed_one, 0);
    const auto bits = [](const SurfacePoint& x) {
        return std::array<std::uint32_t, 8>{
            std::bit_cast<std::uint32_t>(x.position.x), std::bit_cast<std::uint32_t>(x.position.y),
            std::bit_cast<std::uint32_t>(x.position.z), std::bit_cast<std::uint32_t>(x.normal.x),
            std::bit_cast<std::uint32_t>(x.normal.y),   std::bit_cast<std::uint32_t>(x.normal.z),
            std::bit_cast<std::uint32_t>(x.uv[0]),      std::bit_cast<std::uint32_t>(x.uv[1])};
    };
    CHECK(bits(a) == bits(b));
    CHECK(std::bit_cast<std::uint32_t>(a.position.x) == 0u); // +0.0, not -0.0
    CHECK(std::bit_cast<std::uint32_t>(b.normal.x) == 0u);
    CHECK(std::bit_cast<std::uint32_t>(b.uv[0]) == 0u);
}
