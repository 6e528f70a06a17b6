// Adaptive tessellation of a parametric surface (Męciński 2011, surfaces.md §2): the conforming bintree of
// <ctess/surface/conforming_bintree.hpp> driven by two tests on each triangle's base (its longest parameter
// edge):
//
// * chord distance: the distance of the surface point at the base midpoint from the chord between the base's
//   end points, relative to the chord's length, above max_distance;
// * normal angle: the angle between the normal at the midpoint and the normal at either end, above
//   max_angle_deg (default 5 degrees, the post's). Normals are the surface's normal(u, v) when it has one,
//   otherwise the cross product of central finite differences (one-sided at the domain border).
//
// A triangle below min_level is split without testing; one at max_level is never split. Both tests depend on
// the edge only, so the two triangles of a diamond agree.
//
// Memory: the caller passes an AdaptiveWorkspace of spans (nodes, parameters, vertices). max_nodes(L) and
// max_vertices(L) of conforming_bintree.hpp bound what max_level L can use, so spans of those sizes never
// run out; smaller spans are allowed, and when they fill up the refinement stops with status
// node_capacity or vertex_capacity and a conforming but coarser mesh. Nothing is allocated or thrown.
//
// Bad input: a NaN or negative threshold, min_level > max_level or max_level > max_level_limit give a status
// and an empty mesh; a surface value (position or normal) that is not finite stops the refinement with
// surface_not_finite. max_distance = +inf or max_angle_deg >= 180 switch a test off.
#pragma once
#include <cmath>
#include <concepts>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <span>

#include <ctess/core/counts.hpp>
#include <ctess/surface/conforming_bintree.hpp>

#include "parametric.hpp"
#include <ctess/runtime/core/vec3.hpp>

namespace ctess::rt {

template <class S>
concept ParametricSurface = requires(const S& s, float u, float v) {
    { s.position(u, v) } -> std::convertible_to<Vec3>;
};

template <class S>
concept SurfaceWithNormal = ParametricSurface<S> && requires(const S& s, float u, float v) {
    { s.normal(u, v) } -> std::convertible_to<Vec3>;
};

struct AdaptiveOptions {
    float max_angle_deg = 5.0f; // >= 180: no angle test
    float max_distance = 0.05f; // relative to the chord length; +inf: no distance test
    unsigned min_level = 4;
    unsigned max_level = 16; // at most adaptive::max_level_limit
};

enum class AdaptiveStatus : std::uint8_t {
    ok,
    bad_angle,          // max_angle_deg is NaN or negative
    bad_distance,       // max_distance is NaN or negative
    bad_levels,         // min_level > max_level, or max_level > max_level_limit
    node_capacity,      // the node span filled up: the mesh is conforming but not fully refined
    vertex_capacity,    // the parameter or vertex span filled up: likewise
    surface_not_finite, // the surface returned a NaN or infinite position or normal
};

constexpr const char* status_message(AdaptiveStatus s) {
    switch (s) {
    case AdaptiveStatus::ok:
        return "ok";
    case AdaptiveStatus::bad_angle:
        return "the angle threshold must be a number >= 0 (degrees)";
    case AdaptiveStatus::bad_distance:
        return "the distance threshold must be a number >= 0 (relative to the chord length)";
    case AdaptiveStatus::bad_levels:
        return "the levels must satisfy min_level <= max_level <= 32";
    case AdaptiveStatus::node_capacity:
        return "the node buffer is full (size it with adaptive::max_nodes(max_level))";
    case AdaptiveStatus::vertex_capacity:
        return "the vertex buffer is full (size it with adaptive::max_vertices(max_level))";
    case AdaptiveStatus::surface_not_finite:
        return "the surface returned a value that is not finite";
    }
    return "unknown status";
}

struct SurfaceVertex {
    Vec3 position{};
    Vec3 normal{}; // unit length, or zero where the surface is degenerate (e.g. finite differences at a pole)
};

struct AdaptiveWorkspace {
    std::span<adaptive::Node> nodes;
    std::span<adaptive::ParamPoint> params;
    std::span<SurfaceVertex> vertices; // index i belongs to params[i]; the smaller of the two spans counts
};

namespace detail {

inline Vec3 cross(Vec3 a, Vec3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline bool finite(Vec3 a) {
    return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}
inline float length(Vec3 a) {
    return std::sqrt(dot(a, a));
}

// Distance of p from the segment a-b.
inline float distance_to_segment(Vec3 p, Vec3 a, Vec3 b) {
    const Vec3 ab = b - a;
    const float len2 = dot(ab, ab);
    float t = len2 > 0.0f ? dot(p - a, ab) / len2 : 0.0f;
    t = t < 0.0f ? 0.0f : (t > 1.0f ? 1.0f : t);
    return length(p - (a + t * ab));
}

} // namespace detail

// The finite-difference step in the parameter domain (2^-12: well above float noise, well below the finest
// feature the default max level resolves).
inline constexpr float normal_step = 1.0f / 4096.0f;

// The surface point and unit normal at (u, v).
template <ParametricSurface S>
SurfaceVertex evaluate_vertex(const S& surface, float u, float v) {
    SurfaceVertex out;
    out.position = surface.position(u, v);
    if constexpr (SurfaceWithNormal<S>) {
        out.normal = normalize_or_zero(surface.normal(u, v));
    } else {
        const float u0 = u - normal_step < 0.0f ? 0.0f : u - normal_step;
        const float u1 = u + normal_step > 1.0f ? 1.0f : u + normal_step;
        const float v0 = v - normal_step < 0.0f ? 0.0f : v - normal_step;
        const float v1 = v + normal_step > 1.0f ? 1.0f : v + normal_step;
        const Vec3 du = surface.position(u1, v) - surface.position(u0, v);
        const Vec3 dv = surface.position(u, v1) - surface.position(u, v0);
        out.normal = normalize_or_zero(detail::cross(du, dv));
    }
    return out;
}

constexpr float to_parameter(std::uint32_t fixed) {
    return static_cast<float>(fixed) * (1.0f / static_cast<float>(adaptive::fixed_one)); // exact
}

constexpr AdaptiveStatus validate(const AdaptiveOptions& opt) {
    if (opt.max_angle_deg != opt.max_angle_deg || opt.max_angle_deg < 0.0f) return AdaptiveStatus::bad_angle;
    if (opt.max_distance != opt.max_distance || opt.max_distance < 0.0f) return AdaptiveStatus::bad_distance;
    if (opt.min_level > opt.max_level || opt.max_level > adaptive::max_level_limit)
        return AdaptiveStatus::bad_levels;
    return AdaptiveStatus::ok;
}

// Whether the base of node t fails a test (so should be split): the split criterion of the header.
// `mid` is the surface at the base midpoint.
inline bool base_needs_split(const SurfaceVertex& end0, const SurfaceVertex& end1, const SurfaceVertex& mid,
                             const AdaptiveOptions& opt) {
    if (opt.max_distance <= std::numeric_limits<float>::max()) {
        const float chord = detail::length(end1.position - end0.position);
        if (detail::distance_to_segment(mid.position, end0.position, end1.position) >
            opt.max_distance * chord)
            return true;
    }
    if (opt.max_angle_deg < 180.0f) {
        const float cos_max = std::cos(opt.max_angle_deg * (pi_f / 180.0f));
        if (!(dot(mid.normal, mid.normal) > 0.0f)) return false; // degenerate normal: no angle to test
        for (const SurfaceVertex* end : {&end0, &end1}) {
            if (!(dot(end->normal, end->normal) > 0.0f)) continue;
            if (dot(mid.normal, end->normal) < cos_max) return true;
        }
    }
    return false;
}

// Adaptive tessellation of `surface` into the workspace (docs/surfaces.md §2). The vertices are
// workspace.vertices[0, counts().vertices) with parameters workspace.params[...], the triangles come from
// emit_triangles(). status() says whether the refinement completed.
class AdaptiveSurface {
  public:
    template <ParametricSurface S>
    AdaptiveSurface(AdaptiveWorkspace workspace, const S& surface, const AdaptiveOptions& options)
        : tree_(workspace.nodes, workspace.params.size() < workspace.vertices.size()
                                     ? workspace.params
                                     : workspace.params.first(workspace.vertices.size())),
          vertices_(workspace.vertices) {
        status_ = validate(options);
        if (status_ == AdaptiveStatus::ok) status_ = from(tree_.status());
        if (status_ != AdaptiveStatus::ok) {
            empty_ = true;
            return;
        }
        auto evaluate = [&](std::uint32_t i) {
            const adaptive::ParamPoint pq = tree_.param(i);
            vertices_[i] = evaluate_vertex(surface, to_parameter(pq.p), to_parameter(pq.q));
            return detail::finite(vertices_[i].position) && detail::finite(vertices_[i].normal);
        };
        for (std::uint32_t i = 0; i < tree_.vertex_count(); ++i) {
            if (!evaluate(i)) {
                status_ = AdaptiveStatus::surface_not_finite;
                empty_ = true;
                return;
            }
        }
        auto decide = [&](std::uint32_t t) {
            const adaptive::Node& n = tree_.node(t);
            if (n.level < options.min_level) return adaptive::SplitDecision::split;
            const adaptive::ParamPoint m = tree_.base_midpoint(t);
            const SurfaceVertex mid = evaluate_vertex(surface, to_parameter(m.p), to_parameter(m.q));
            if (!detail::finite(mid.position) || !detail::finite(mid.normal))
                return adaptive::SplitDecision::stop;
            return base_needs_split(vertices_[n.vertex[1]], vertices_[n.vertex[2]], mid, options)
                       ? adaptive::SplitDecision::split
                       : adaptive::SplitDecision::keep;
        };
        status_ = from(tree_.refine(options.max_level, decide, evaluate));
    }

    AdaptiveStatus status() const { return status_; }
    // The mesh reached (empty when the options were bad or a corner was not finite).
    Counts counts() const { return empty_ ? Counts{} : tree_.counts(); }
    const adaptive::ConformingBintree& tree() const { return tree_; }
    const SurfaceVertex& vertex(std::uint32_t i) const { return vertices_[i]; }
    adaptive::ParamPoint param(std::uint32_t i) const { return tree_.param(i); }
    // The triangles (counter-clockwise in (u, v), facing the way the surface's normals do); false and nothing
    // written when the span is shorter than 3 * counts().triangles.
    bool emit_triangles(std::span<std::uint32_t> indices) const {
        return !empty_ && tree_.emit_triangles(indices);
    }

  private:
    static constexpr AdaptiveStatus from(adaptive::RefineStatus s) {
        switch (s) {
        case adaptive::RefineStatus::ok:
            return AdaptiveStatus::ok;
        case adaptive::RefineStatus::node_capacity:
            return AdaptiveStatus::node_capacity;
        case adaptive::RefineStatus::vertex_capacity:
            return AdaptiveStatus::vertex_capacity;
        case adaptive::RefineStatus::rejected:
            return AdaptiveStatus::surface_not_finite;
        }
        return AdaptiveStatus::surface_not_finite;
    }

    adaptive::ConformingBintree tree_;
    std::span<SurfaceVertex> vertices_;
    AdaptiveStatus status_ = AdaptiveStatus::ok;
    bool empty_ = false;
};

} // namespace ctess::rt
