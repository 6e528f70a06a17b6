// The index logic of adaptive parametric tessellation (Męciński 2011, docs/surfaces.md §2): a conforming
// longest-edge bisection of the parameter square, usable in constant expressions.
//
// The square [0, 1]^2 starts as two right isosceles triangles split along its diagonal. A triangle is split
// by the midpoint of its longest edge (its hypotenuse, the "base"), which gives two right isosceles
// triangles one level deeper whose bases are the parent's legs; this is newest-vertex bisection, and in
// this hierarchy the two coincide. To keep the mesh free of T-junctions a split always splits the triangle
// on the other side of the base too (a "diamond"); if that neighbour is one level coarser its own base is a
// different edge, so it is split first, recursively (neighbour propagation, as in ROAM).
//
// Termination: in this hierarchy a leaf's base neighbour is either a leaf of the same level whose base is the
// same edge (they form a diamond and split together), or a leaf exactly one level coarser. Following base
// neighbours therefore visits strictly decreasing levels and stops after at most level + 1 steps; each pair
// split removes the coarsest triangle of that chain, so split(t) performs at most level(t) + 1 pair splits,
// and no split ever produces a triangle deeper than the one asked for.
//
// Parameters are exact integers in units of 1 / fixed_one: a triangle of level l has its vertices on the
// grid of spacing 2^-ceil(l / 2), and max_level_limit = 32 keeps every midpoint on the 2^-16 grid. A vertex
// is created once, by the split of its diamond, and both triangles index it, so shared vertices are the same
// vertex by construction (bit-identical parameters and positions).
//
// Memory: the caller provides the node and vertex arrays (spans); nothing is allocated. A pair split needs up
// to 4 nodes and 1 vertex and checks for them first, so running out of space stops the refinement with a
// status and leaves a conforming mesh.
#pragma once
#include <cstdint>
#include <span>

#include <ctess/core/counts.hpp>
#include <ctess/core/fixed_point.hpp>

namespace ctess::adaptive {

inline constexpr unsigned max_level_limit = 32;
inline constexpr std::uint32_t fixed_one = units::bintree::one; // the parameter square's 1.0 (2^16)
inline constexpr std::uint32_t no_node = 0xffffffffu;

struct ParamPoint {
    std::uint32_t p = 0, q = 0; // (u, v) = (p, q) / fixed_one
    friend constexpr bool operator==(const ParamPoint&, const ParamPoint&) = default;
};

// A node's vertices are (apex, v0, v1), counter-clockwise in (p, q) with q up; its base is v0 -> v1.
// neighbour[e] is the leaf across edge e: e = 0 apex -> v0, e = 1 the base, e = 2 v1 -> apex.
inline constexpr unsigned edge_apex_v0 = 0, edge_base = 1, edge_v1_apex = 2;

struct Node {
    std::uint32_t vertex[3] = {0, 0, 0};
    std::uint32_t neighbour[3] = {no_node, no_node, no_node};
    std::uint32_t first_child = no_node; // the children are first_child and first_child + 1
    std::uint32_t level = 0;
    constexpr bool is_leaf() const { return first_child == no_node; }
};

enum class RefineStatus : std::uint8_t {
    ok,
    node_capacity,   // the node span is full
    vertex_capacity, // the vertex span is full
    rejected,        // the caller's callback refused a vertex or a decision (e.g. a non-finite surface value)
};

// What refine() asks the caller about each leaf.
enum class SplitDecision : std::uint8_t { keep, split, stop };

// Worst-case sizes for refinement to max_level (every triangle split to that level), for sizing the spans.
constexpr std::uint64_t max_triangles(unsigned max_level) {
    return std::uint64_t{2} << max_level;
}
constexpr std::uint64_t max_nodes(unsigned max_level) {
    return (std::uint64_t{4} << max_level) - 2;
}
constexpr std::uint64_t max_vertices(unsigned max_level) {
    const std::uint64_t cells = std::uint64_t{1} << (max_level / 2); // grid cells per side at even levels
    return (cells + 1) * (cells + 1) + (max_level % 2 != 0 ? cells * cells : 0); // odd: plus cell centres
}

class ConformingBintree {
  public:
    // Starts from the two triangles of the square (4 vertices, 2 nodes); status() is node_capacity or
    // vertex_capacity (and the tree empty) when the spans cannot hold them.
    constexpr ConformingBintree(std::span<Node> nodes, std::span<ParamPoint> params)
        : nodes_(nodes), params_(params) {
        if (params_.size() < 4) {
            status_ = RefineStatus::vertex_capacity;
            return;
        }
        if (nodes_.size() < 2) {
            status_ = RefineStatus::node_capacity;
            return;
        }
        params_[0] = {0, 0};
        params_[1] = {fixed_one, 0};
        params_[2] = {fixed_one, fixed_one};
        params_[3] = {0, fixed_one};
        vertex_count_ = 4;
        nodes_[0] = Node{{1, 2, 0}, {no_node, 1, no_node}, no_node, 0}; // below the diagonal (0,0)-(1,1)
        nodes_[1] = Node{{3, 0, 2}, {no_node, 0, no_node}, no_node, 0}; // above it
        node_count_ = 2;
        leaf_count_ = 2;
    }

    constexpr RefineStatus status() const { return status_; }
    constexpr std::uint32_t node_count() const { return node_count_; }
    constexpr std::uint32_t vertex_count() const { return vertex_count_; }
    constexpr Counts counts() const { return {vertex_count_, leaf_count_}; }
    constexpr const Node& node(std::uint32_t i) const { return nodes_[i]; }
    constexpr ParamPoint param(std::uint32_t i) const { return params_[i]; }

    // The parameter of the midpoint of a node's base: the vertex its split would create.
    constexpr ParamPoint base_midpoint(std::uint32_t t) const {
        const ParamPoint a = params_[nodes_[t].vertex[1]], b = params_[nodes_[t].vertex[2]];
        return {(a.p + b.p) / 2, (a.q + b.q) / 2}; // exact: both sums are even below max_level_limit
    }

    // Splits leaf t and whatever it takes to keep the mesh conforming. on_vertex(index) is called for each
    // new vertex after its parameter is stored; returning false rejects it (nothing changes, status
    // rejected). A node at max_level_limit is not split.
    template <class OnVertex>
    constexpr RefineStatus split(std::uint32_t t, OnVertex&& on_vertex) {
        if (status_ != RefineStatus::ok) return status_;
        if (nodes_[t].level >= max_level_limit) return status_;
        while (nodes_[t].is_leaf()) { // at most level(t) + 1 rounds (see the head of this file)
            std::uint32_t s = t;
            for (std::uint32_t b = nodes_[s].neighbour[edge_base];
                 b != no_node && nodes_[b].neighbour[edge_base] != s; b = nodes_[s].neighbour[edge_base])
                s = b; // s's base neighbour is coarser: it goes first
            if (split_pair(s, on_vertex) != RefineStatus::ok) return status_;
        }
        return status_;
    }

    // Visits every leaf once, in creation order (children after parents, so new leaves are visited too);
    // decide(node index) chooses. Leaves at max_level (clamped to max_level_limit) are kept without asking.
    template <class Decide, class OnVertex>
    constexpr RefineStatus refine(unsigned max_level, Decide&& decide, OnVertex&& on_vertex) {
        if (max_level > max_level_limit) max_level = max_level_limit;
        for (std::uint32_t i = 0; i < node_count_ && status_ == RefineStatus::ok; ++i) {
            if (!nodes_[i].is_leaf() || nodes_[i].level >= max_level) continue;
            const SplitDecision d = decide(i);
            if (d == SplitDecision::stop) status_ = RefineStatus::rejected;
            if (d == SplitDecision::split) split(i, on_vertex);
        }
        return status_;
    }

    // The leaves as a triangle list (counter-clockwise in (p, q)), in node order. False (nothing written)
    // when the span is shorter than 3 * counts().triangles.
    constexpr bool emit_triangles(std::span<std::uint32_t> indices) const {
        if (indices.size() < 3 * std::size_t{leaf_count_}) return false;
        std::size_t out = 0;
        for (std::uint32_t i = 0; i < node_count_; ++i) {
            if (!nodes_[i].is_leaf()) continue;
            for (std::uint32_t v : nodes_[i].vertex) indices[out++] = v;
        }
        return true;
    }

  private:
    // Splits t and its base neighbour (a diamond; t alone on the domain boundary). The neighbour, if any, has
    // t as its own base neighbour.
    template <class OnVertex>
    constexpr RefineStatus split_pair(std::uint32_t t, OnVertex& on_vertex) {
        const std::uint32_t b = nodes_[t].neighbour[edge_base];
        const std::uint32_t need = b == no_node ? 2 : 4;
        if (nodes_.size() - node_count_ < need) return status_ = RefineStatus::node_capacity;
        if (params_.size() <= vertex_count_) return status_ = RefineStatus::vertex_capacity;
        const std::uint32_t m = vertex_count_;
        params_[m] = base_midpoint(t);
        ++vertex_count_;
        if (!on_vertex(m)) {
            --vertex_count_;
            return status_ = RefineStatus::rejected;
        }
        const std::uint32_t tc = split_one(t, m);
        if (b != no_node) {
            const std::uint32_t bc = split_one(b, m);
            // t = (a, v0, v1) and b = (c, v1, v0): t's first child (m, a, v0) meets b's second (m, v0, c)
            // along m-v0, and t's second (m, v1, a) meets b's first (m, c, v1) along m-v1.
            nodes_[tc].neighbour[edge_v1_apex] = bc + 1;
            nodes_[bc + 1].neighbour[edge_apex_v0] = tc;
            nodes_[tc + 1].neighbour[edge_apex_v0] = bc;
            nodes_[bc].neighbour[edge_v1_apex] = tc + 1;
        }
        return status_;
    }

    // Appends the two children of t = (a, v0, v1): (m, a, v0) and (m, v1, a). Their bases are t's legs, so
    // they inherit t's leg neighbours; the sides along t's base are linked by split_pair.
    constexpr std::uint32_t split_one(std::uint32_t t, std::uint32_t m) {
        const Node n = nodes_[t];
        const std::uint32_t c = node_count_;
        nodes_[c] = Node{
            {m, n.vertex[0], n.vertex[1]}, {c + 1, n.neighbour[edge_apex_v0], no_node}, no_node, n.level + 1};
        nodes_[c + 1] = Node{
            {m, n.vertex[2], n.vertex[0]}, {no_node, n.neighbour[edge_v1_apex], c}, no_node, n.level + 1};
        relink(n.neighbour[edge_apex_v0], t, c);
        relink(n.neighbour[edge_v1_apex], t, c + 1);
        nodes_[t].first_child = c;
        node_count_ += 2;
        ++leaf_count_;
        return c;
    }

    constexpr void relink(std::uint32_t node, std::uint32_t from, std::uint32_t to) {
        if (node == no_node) return;
        for (std::uint32_t& n : nodes_[node].neighbour)
            if (n == from) n = to;
    }

    std::span<Node> nodes_;
    std::span<ParamPoint> params_;
    std::uint32_t node_count_ = 0;
    std::uint32_t vertex_count_ = 0;
    std::uint32_t leaf_count_ = 0;
    RefineStatus status_ = RefineStatus::ok;
};

} // namespace ctess::adaptive
