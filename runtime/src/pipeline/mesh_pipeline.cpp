// The mesh pipeline's CPU reference (mesh_pipeline.hpp), compiled once with contraction and fast-math off
// (runtime/CMakeLists.txt): the per-edge factors, the patch setup and the emit loop decide counts and shared
// edges' points, so they must not change with the caller's flags (docs/api.md, "Crack-free evaluation").
// The loops are written once over the pattern family; each family contributes its setup, its record check
// and its base points.
#include <ctess/runtime/pipeline/mesh_pipeline.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <concepts>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <span>
#include <type_traits>
#include <vector>

#include <ctess/core/patch_concept.hpp>
#include <ctess/cp/quad.hpp>
#include <ctess/d3d11/tessellator.hpp>
#include <ctess/runtime/cp/line_state.hpp>
#include <ctess/runtime/displace/displace.hpp>
#include <ctess/runtime/uniform/split.hpp>

namespace ctess::rt {

namespace {

constexpr std::uint32_t one = cp::fixed_one;

Vec3 mesh_position(const MeshView& mesh, std::uint32_t v) {
    const float* p = mesh.vertices + std::size_t{v} * mesh_vertex_floats;
    return {p[0], p[1], p[2]};
}

// The corner's index orders shared edges (surface/eval.hpp): the vertex's position id where the mesh has
// them, so the two sides of a uv or normal seam (different vertices at one position) order the edge the same
// way.
SurfaceCorner mesh_corner(const MeshView& mesh, std::uint32_t v) {
    const float* p = mesh.vertices + std::size_t{v} * mesh_vertex_floats;
    const std::uint32_t order = mesh.position_ids != nullptr ? mesh.position_ids[v] : v;
    return {{p[0], p[1], p[2]}, {p[3], p[4], p[5]}, {p[6], p[7]}, order};
}

// The PN-AEN neighbours of face triangle f (a base triangle, or half of a quad: MeshView::adjacency), edge e
// (corner e -> e + 1): the adjacent triangle's two vertices on it. An index outside the mesh gives the own
// corners, which evaluate_surface_aen treats as a boundary.
AdjacentEdge adjacent_edge(const MeshView& mesh, std::uint64_t f, unsigned e, const SurfaceCorner& a,
                           const SurfaceCorner& b) {
    const std::uint32_t* t = mesh.adjacency + 12 * f;
    const std::uint32_t i = t[3 + 2 * e], j = t[4 + 2 * e];
    if (i >= mesh.vertex_count || j >= mesh.vertex_count) return {{a, b}};
    return {{mesh_corner(mesh, i), mesh_corner(mesh, j)}};
}

// Which surface evaluation a patch runs: its corners, and for PN-AEN with adjacency its neighbours per edge.
struct PatchSurface {
    explicit PatchSurface(const SurfaceOptions& o = {}) : options(o) {}
    SurfaceOptions options;
    bool aen = false; // Surface::pn_aen with MeshView::adjacency
    AdjacentEdge adjacent[4];
    DisplacementPatch displace; // source null: no displacement (docs/algorithm.md §8)
};

PatchSurface triangle_surface(const MeshView& mesh, std::uint32_t t, const SurfaceCorner (&corner)[3],
                              const PipelineOptions& pipeline) {
    const SurfaceOptions& options = pipeline.surface;
    PatchSurface ps(options);
    if (pipeline.displacement != nullptr) {
        std::uint32_t w[3];
        PatchFaces faces;
        for (unsigned k = 0; k < 3; ++k) {
            w[k] = mesh.indices[std::size_t{t} * 3 + k];
            faces.corner_face[k] = faces.edge_face[k] = t;
            faces.corner_slot[k] = faces.edge_slot[k] = k;
        }
        ps.displace = displacement_patch(*pipeline.displacement, mesh, 3, w, faces);
    }
    ps.aen = options.surface == Surface::pn_aen && mesh.adjacency != nullptr;
    if (ps.aen)
        for (unsigned e = 0; e < 3; ++e)
            ps.adjacent[e] = adjacent_edge(mesh, t, e, corner[e], corner[(e + 1) % 3]);
    return ps;
}

// A quad's face triangles are (q0, q1, q2) and (q0, q2, q3) of the mesh's labelling
// (models::build_adjacency): mesh edge 0 and 1 are the first's edges 0 and 1, mesh edges 2 and 3 the second's
// edges 1 and 2. Pattern edge k (q[k] -> q[k + 1], q in pattern order) is mesh edge (k + rotation) % 4.
PatchSurface quad_surface(const MeshView& mesh, std::uint32_t q, std::uint32_t rotation,
                          const SurfaceCorner (&corner)[4], const PipelineOptions& pipeline) {
    const SurfaceOptions& options = pipeline.surface;
    PatchSurface ps(options);
    const std::uint64_t first = std::uint64_t{mesh.triangle_count} + 2 * std::uint64_t{q};
    const std::uint64_t face[4] = {first, first, first + 1, first + 1};
    const unsigned edge[4] = {0, 1, 1, 2};
    if (pipeline.displacement != nullptr) {
        // Mesh corners q0, q1, q2 are slots 0-2 of (q0, q1, q2), q3 slot 2 of (q0, q2, q3).
        const unsigned corner_slot[4] = {0, 1, 2, 2};
        std::uint32_t w[4];
        PatchFaces faces;
        for (unsigned k = 0; k < 4; ++k) {
            const unsigned m = (k + rotation) % 4;
            w[k] = mesh.quad_indices[std::size_t{q} * 4 + m];
            faces.corner_face[k] = face[m == 3 ? 2 : 0];
            faces.corner_slot[k] = corner_slot[m];
            faces.edge_face[k] = face[m];
            faces.edge_slot[k] = edge[m];
        }
        ps.displace = displacement_patch(*pipeline.displacement, mesh, 4, w, faces);
    }
    ps.aen = options.surface == Surface::pn_aen && mesh.adjacency != nullptr;
    if (!ps.aen) return ps;
    for (unsigned k = 0; k < 4; ++k) {
        const unsigned m = (k + rotation) % 4;
        ps.adjacent[k] = adjacent_edge(mesh, face[m], edge[m], corner[k], corner[(k + 1) % 4]);
        // adjacent_edge reads the neighbour's pair in either order; the own corners stand in at a boundary.
    }
    return ps;
}

bool base_triangle(const MeshView& mesh, std::uint32_t t, std::uint32_t (&w)[3]) {
    for (unsigned k = 0; k < 3; ++k) w[k] = mesh.indices[std::size_t{t} * 3 + k];
    return w[0] < mesh.vertex_count && w[1] < mesh.vertex_count && w[2] < mesh.vertex_count;
}

bool base_quad(const MeshView& mesh, std::uint32_t q, std::uint32_t (&w)[4]) {
    bool inside = true;
    for (unsigned k = 0; k < 4; ++k) {
        w[k] = mesh.quad_indices[std::size_t{q} * 4 + k];
        inside = inside && w[k] < mesh.vertex_count;
    }
    return inside;
}

// The unclamped factor of mesh edge (i, j) and its squared length, endpoints in mesh-index order so that
// every face sharing the edge computes the same bits (tess_factor.hpp).
float mesh_edge_factor(const MeshView& mesh, std::uint32_t i, std::uint32_t j,
                       const PipelineOptions& options) {
    const Vec3 a = mesh_position(mesh, i < j ? i : j), b = mesh_position(mesh, i < j ? j : i);
    const float f = edge_factor(a, b, options.dice);
    // Displacement can lengthen the edge: grown by its bound (docs/algorithm.md §8.4).
    return options.displacement != nullptr ? displaced_edge_factor(*options.displacement, f, a, b) : f;
}

float mesh_edge_length2(const MeshView& mesh, std::uint32_t i, std::uint32_t j) {
    const Vec3 d = mesh_position(mesh, i < j ? j : i) - mesh_position(mesh, i < j ? i : j);
    return dot(d, d);
}

// An output vertex: its domain point (base weights, or a quad's unit square) and its surface point.
TessVertex tess_vertex(DomainPoint base, const SurfacePoint& s) {
    return {base.u,
            base.v,
            {s.position.x, s.position.y, s.position.z},
            {s.normal.x, s.normal.y, s.normal.z},
            {s.uv[0], s.uv[1]}};
}

// A base triangle's points in batches, for the emits without PN-AEN: surface_vertex's values (bit for bit)
// through evaluate_surface_points, without a call per point. Made once per emit: its arrays zero-initialise.
class TrianglePointBatch {
  public:
    static constexpr std::size_t size = 64;
    // The k-th point of the batch (k < size), base weights.
    DomainPoint& base(std::size_t k) { return base_[k]; }
    // Evaluates the first count points (count <= size) on the triangle with the patch's surface and
    // displacement; point(k) is then their surface point.
    void evaluate(const SurfaceCorner (&corner)[3], const PatchSurface& surface, std::size_t count) {
        evaluate_surface_points(std::span(point_.data(), count), corner, std::span(base_.data(), count),
                                surface.options);
        if (surface.displace.source == nullptr) return; // displace_triangle_point would return at once
        for (std::size_t k = 0; k < count; ++k) {
            const std::uint32_t w[3] = {one - base_[k].u - base_[k].v, base_[k].u, base_[k].v};
            displace_triangle_point(surface.displace, w, point_[k]); // §8
        }
    }
    const SurfacePoint& point(std::size_t k) const { return point_[k]; }

  private:
    std::array<DomainPoint, size> base_;
    std::array<SurfacePoint, size> point_;
};

// The output vertex of exact base weights (w1, w2) = (base.u, base.v), units of cp::fixed_one.
TessVertex surface_vertex(const SurfaceCorner (&corner)[3], DomainPoint base, const PatchSurface& surface) {
    const std::uint32_t w[3] = {one - base.u - base.v, base.u, base.v};
    SurfacePoint s;
    if (surface.aen) {
        const AdjacentEdge adjacent[3] = {surface.adjacent[0], surface.adjacent[1], surface.adjacent[2]};
        s = evaluate_surface_aen(corner, adjacent, w, surface.options);
    } else {
        s = evaluate_surface(corner, w, surface.options);
    }
    displace_triangle_point(surface.displace, w, s); // no-op without displacement (§8)
    return tess_vertex(base, s);
}

// The output vertex of quad point (s, t) of the unit square (docs/algorithm.md §7.3): a point on a quad edge
// goes through evaluate_surface's edge rule on that edge's two corners (the very operations a triangle on
// the other side runs), an inner point through evaluate_quad_surface with the patch's surface.
TessVertex quad_vertex(const SurfaceCorner (&q)[4], DomainPoint square, const PatchSurface& surface) {
    const std::uint32_t s = square.u, t = square.v;
    const bool on_edge[4] = {t == 0, s == one, t == one, s == 0};
    const std::uint32_t r[4] = {s, t, one - s, one - t}; // measured from q_k along edge k
    SurfacePoint p;
    bool done = false;
    for (unsigned k = 0; k < 4 && !done; ++k) {
        if (!on_edge[k]) continue;
        const SurfaceCorner tri[3] = {q[k], q[(k + 1) % 4], q[(k + 2) % 4]};
        const std::uint32_t w[3] = {one - r[k], r[k], 0};
        if (surface.aen) {
            // Only edge 0 (the quad's edge k) carries the point; the other two are the own boundary.
            const AdjacentEdge adjacent[3] = {surface.adjacent[k], {{tri[1], tri[2]}}, {{tri[2], tri[0]}}};
            p = evaluate_surface_aen(tri, adjacent, w, surface.options);
        } else {
            p = evaluate_surface(tri, w, surface.options);
        }
        done = true;
    }
    if (!done)
        p = surface.aen ? evaluate_quad_surface_aen(q, surface.adjacent, s, t, surface.options)
                        : evaluate_quad_surface(q, s, t, surface.options);
    displace_quad_point(surface.displace, s, t, p); // no-op without displacement (§8)
    return tess_vertex(square, p);
}

// Distinct interior parameters of one edge's line, ascending, units of cp::fixed_one. The set is
// mirror-symmetric (§1.2, §3.2), so it is the same measured from either end.
struct EdgeParams {
    std::vector<std::uint32_t> value; // count used; a split uniform edge has up to 32,767
    unsigned count = 0;

    void reset(std::size_t capacity) {
        if (value.size() < capacity) value.resize(capacity);
        count = 0;
    }
    void finish() {
        std::sort(value.begin(), value.begin() + count);
        count = static_cast<unsigned>(std::unique(value.begin(), value.begin() + count) - value.begin());
    }
    // The rank of parameter x, or count when it is not a point of the line.
    unsigned rank(std::uint32_t x) const {
        const auto* end = value.data() + count;
        const auto* it = std::lower_bound(value.data(), end, x);
        return it != end && *it == x ? static_cast<unsigned>(it - value.data()) : count;
    }
};

// The CP family (docs/algorithm.md §2): rotation by the smallest edge, CP line states, the setup block.
struct CpFamily {
    using patch_type = CpPatch;
    static constexpr bool own_diagonal = false; // a quad's diagonal takes q0q1's factor (§7.2)
    const CpTableSet& tables;

    // Pattern factors f (rotation already applied) into line states.
    void set_lines(PatchRecord& rec, const float (&f)[3]) const {
        for (unsigned k = 0; k < 3; ++k) {
            const cp::LineState s =
                cp::clamp_line_state(rt::line_state(f[k], tables.max_factor), tables.max_factor);
            rec.token[k] = s.token;
            rec.t16[k] = s.t16;
        }
    }
    // The rotation and line states only: all the weld reads of a record (no counts, no block).
    void lines(PatchRecord& rec, const float (&length2)[3]) const {
        const cp::Rotation rot = cp::smallest_edge_rotation(length2[0], length2[1], length2[2]);
        rec.rotation = rot.shift;
        const float f[3] = {rec.factor[rot.shift % 3], rec.factor[(rot.shift + 1) % 3],
                            rec.factor[(rot.shift + 2) % 3]};
        set_lines(rec, f);
    }
    void setup(PatchRecord& rec, const float (&length2)[3]) const {
        lines(rec, length2);
        // One CpPatchSetup gives both the counts and the block.
        const PatchSetupBlock block = patch_setup_block(tables, cp::LineState{rec.token[0], rec.t16[0]},
                                                        cp::LineState{rec.token[1], rec.t16[1]},
                                                        cp::LineState{rec.token[2], rec.t16[2]});
        rec.vertex_count = block.vertices;
        rec.triangle_count = block.triangles;
        for (unsigned k = 0; k < setup_word::words; ++k) rec.setup[k] = block.word[k];
    }
    bool clamped(float f) const { return f > static_cast<float>(tables.max_factor); }
    // The counts a record must have (none for a culled patch); false when setup() cannot have written it.
    bool record_counts(const PatchRecord& rec, bool culled, Counts& counts) const {
        if (rec.rotation > 2) return false;
        if (!culled) counts = patch_of(tables, rec).counts();
        return true;
    }
    patch_type patch(const PatchRecord& rec) const { return patch_of(tables, rec); }
    Counts counts_of(const PatchRecord& rec) const { return patch(rec).counts(); }
    patch_type welded_patch(const PatchRecord& rec) const {
        return CpPatch(tables, cp::LineState{rec.token[0], rec.t16[0]},
                       cp::LineState{rec.token[1], rec.t16[1]}, cp::LineState{rec.token[2], rec.t16[2]},
                       PatchOptions{Layout::shared, Winding::ccw});
    }
    static DomainPoint base_point(const patch_type& patch, const PatchRecord& rec, std::uint32_t i) {
        return cp::to_base_point(cp::Rotation{static_cast<std::uint8_t>(rec.rotation)}, patch.vertex(i));
    }
    // The line's distinct interior parameters: cp::edge_points' positions, computed here from the token's
    // tracks so that no 257-entry buffer is zeroed per edge (two kilobytes for every edge of the mesh, in
    // setup_welded and again in emit_welded_mesh's check of the edge list).
    void params_of_state(cp::LineState state, EdgeParams& out) const {
        union Tracks {
            cp::PointTrack item[cp::max_segments + 1];
            Tracks() noexcept {}
        } tracks;
        state = cp::clamp_line_state(state, tables.max_factor);
        const unsigned n = cp::token_points(state.token, tracks.item);
        out.reset(cp::max_segments + 1);
        for (unsigned i = 0; i < n; ++i) {
            const std::uint32_t x = cp::point_position(tracks.item[i], state.t16);
            if (x != 0 && x != one) out.value[out.count++] = x;
        }
        out.finish();
    }
    void edge_params(float f, EdgeParams& out) const {
        params_of_state(rt::line_state(f, tables.max_factor), out);
    }
    void record_edge_params(const PatchRecord& rec, unsigned k, EdgeParams& out) const {
        params_of_state(cp::LineState{rec.token[k], rec.t16[k]}, out);
    }
};

// The uniform family (§3.4): rotation 0, each base edge's factor rounded and clamped to [1, N].
struct UniformFamily {
    using patch_type = UniformPatch;
    static constexpr bool own_diagonal = true; // a quad's diagonal takes its own factor (§7.2)
    const UniformTableSet& tables;

    void set_lines(PatchRecord& rec, const float (&f)[3]) const {
        for (unsigned k = 0; k < 3; ++k) rec.set_uniform_factor(k, uniform_factor(f[k], tables.max_factor));
    }
    void lines(PatchRecord& rec, const float (&)[3]) const { set_lines(rec, rec.factor); }
    void setup(PatchRecord& rec, const float (&)[3]) const {
        set_lines(rec, rec.factor);
        const UniformPatch patch = uniform_patch_of(tables, rec);
        rec.vertex_count = patch.counts().vertices;
        rec.triangle_count = patch.counts().triangles;
        uniform_setup_words(rec.setup, patch);
    }
    // Rounds above N: with one more allowed, the rounded factor would exceed N.
    bool clamped(float f) const { return uniform_factor(f, tables.max_factor + 1) > tables.max_factor; }
    bool record_counts(const PatchRecord& rec, bool culled, Counts& counts) const {
        if (culled) return true;
        if (rec.rotation != 0) return false;
        for (unsigned k = 0; k < 3; ++k)
            if (rec.uniform_factor(k) < 1 || rec.uniform_factor(k) > tables.max_factor || rec.t16[k] != 0)
                return false;
        counts = uniform_patch_of(tables, rec).counts();
        return true;
    }
    patch_type patch(const PatchRecord& rec) const { return uniform_patch_of(tables, rec); }
    Counts counts_of(const PatchRecord& rec) const { return patch(rec).counts(); }
    patch_type welded_patch(const PatchRecord& rec) const { return uniform_patch_of(tables, rec); }
    static DomainPoint base_point(const patch_type& patch, const PatchRecord&, std::uint32_t i) {
        return uniform_base_point(patch, i);
    }
    void params_of_factor(std::uint32_t n, EdgeParams& out) const {
        out.reset(n);
        for (std::uint32_t i = 1; i < n; ++i)
            out.value[out.count++] = uniform_weight_to_fixed(uniform::edge_parameter(i, n));
        out.finish();
    }
    void edge_params(float f, EdgeParams& out) const {
        params_of_factor(uniform_factor(f, tables.max_factor), out);
    }
    void record_edge_params(const PatchRecord& rec, unsigned k, EdgeParams& out) const {
        params_of_factor(rec.uniform_factor(k), out);
    }
};

// A pattern generated whole, kept as an indexed patch: for the families without O(1) random access
// (UniformSplit's tree walk, the D3D11 tessellator), whose points and triangles are written once per use.
template <class Point>
class StoredPatch {
  public:
    using point_type = Point;
    Counts counts() const noexcept {
        return {static_cast<std::uint32_t>(points_.size()), static_cast<std::uint32_t>(indices_.size() / 3)};
    }
    bool emit(std::span<point_type> points, std::span<std::uint32_t> indices) const noexcept {
        if (points.size() < points_.size() || indices.size() < indices_.size()) return false;
        std::copy(points_.begin(), points_.end(), points.begin());
        std::copy(indices_.begin(), indices_.end(), indices.begin());
        return true;
    }
    point_type vertex(std::uint32_t i) const noexcept { return points_[i]; }
    std::array<std::uint32_t, 3> triangle(std::uint32_t p) const noexcept {
        return {indices_[3 * std::size_t{p}], indices_[3 * std::size_t{p} + 1],
                indices_[3 * std::size_t{p} + 2]};
    }

  protected:
    void resize(Counts c) {
        points_.resize(c.vertices);
        indices_.resize(c.index_count());
    }
    std::vector<point_type> points_;
    std::vector<std::uint32_t> indices_;
};

// A UniformSplit (§3.5) in the pipeline's shared, counter-clockwise layout: leaf by leaf (the unwelded
// output's layout, the shaders', §7.5) or welded within the patch (what the weld reads: fewer slots).
class SplitPatch : public StoredPatch<uniform::SplitPoint> {
  public:
    enum class Points { leaves, welded };
    SplitPatch(const UniformSplit& split, Points points) {
        // The spans are the counts long, so the emit writes them whole (split.hpp); anything else is a broken
        // invariant, never an output with a silently empty or zeroed patch.
        if (points == Points::leaves) {
            resize(split.leaf_counts());
            if (!split.emit_leaves(points_, indices_)) std::abort();
        } else {
            resize(split.counts());
            if (!split.emit(points_, indices_)) std::abort();
        }
    }
};

// Uniform density at any factor (§7.5): each base edge's factor rounded and clamped to [1, 32768]
// (uniform_split_max_factor), patches above N split with the table's own patterns (UniformSplit), their
// points converted to base weights by to_base_weights. Up to N it is UniformFamily's output exactly.
struct UniformSplitFamily {
    using patch_type = SplitPatch;
    static constexpr bool own_diagonal = true;
    const UniformTableSet& tables;

    static std::uint32_t factor(float f) { return uniform_factor(f, uniform_split_max_factor); }
    static UniformSplit split_of(const UniformTableSet& tables, const PatchRecord& rec) {
        return UniformSplit(tables, static_cast<float>(rec.uniform_factor(0)),
                            static_cast<float>(rec.uniform_factor(1)),
                            static_cast<float>(rec.uniform_factor(2)), uniform_pipeline_options);
    }
    void set_lines(PatchRecord& rec, const float (&f)[3]) const {
        for (unsigned k = 0; k < 3; ++k) rec.set_uniform_factor(k, factor(f[k]));
    }
    void lines(PatchRecord& rec, const float (&)[3]) const { set_lines(rec, rec.factor); }
    void setup(PatchRecord& rec, const float (&)[3]) const {
        set_lines(rec, rec.factor);
        const Counts c = counts_of(rec);
        rec.vertex_count = c.vertices;
        rec.triangle_count = c.triangles;
    }
    bool clamped(float f) const {
        return uniform_factor(f, uniform_split_max_factor + 1) > uniform_split_max_factor;
    }
    bool record_counts(const PatchRecord& rec, bool culled, Counts& counts) const {
        if (culled) return true;
        if (rec.rotation != 0) return false;
        for (unsigned k = 0; k < 3; ++k)
            if (rec.uniform_factor(k) < 1 || rec.uniform_factor(k) > uniform_split_max_factor ||
                rec.t16[k] != 0)
                return false;
        counts = counts_of(rec);
        return true;
    }
    patch_type patch(const PatchRecord& rec) const {
        return SplitPatch(split_of(tables, rec), SplitPatch::Points::leaves);
    }
    // The leaves' counts from the split's walk, without emitting; counts past 32 bits (which UniformSplit
    // gives as {0, 0}; none with the shipped tables) as the most a record holds, so that the totals check
    // refuses them (too_many_vertices) instead of losing the patch.
    Counts counts_of(const PatchRecord& rec) const {
        const Counts c = split_of(tables, rec).leaf_counts();
        return c.triangles == 0 ? Counts{0xFFFFFFFFu, 0xFFFFFFFFu} : c;
    }
    patch_type welded_patch(const PatchRecord& rec) const {
        return SplitPatch(split_of(tables, rec), SplitPatch::Points::welded);
    }
    static DomainPoint base_point(const patch_type& patch, const PatchRecord&, std::uint32_t i) {
        return to_base_weights(patch.vertex(i));
    }
    void params_of_factor(std::uint32_t n, EdgeParams& out) const {
        const std::uint32_t count = UniformSplit::root_edge_point_count(tables, static_cast<float>(n));
        points_.resize(count);
        UniformSplit::root_edge_points(tables, static_cast<float>(n), points_);
        out.reset(count);
        for (std::uint32_t i = 1; i + 1 < count; ++i) out.value[out.count++] = to_base_weights(points_[i]).u;
        out.finish();
    }
    void edge_params(float f, EdgeParams& out) const { params_of_factor(factor(f), out); }
    void record_edge_params(const PatchRecord& rec, unsigned k, EdgeParams& out) const {
        params_of_factor(rec.uniform_factor(k), out);
    }
    mutable std::vector<uniform::SplitPoint> points_; // scratch of params_of_factor
};

// The reference's TRIANGLE_CW is counter-clockwise in the base weights (w1, w2) that (u, v) become.
constexpr Winding d3d11_winding = Winding::cw;

// The D3D11 tessellator's triangle domain (§5) on one patch, as an indexed patch. Domain (u, v) are the base
// weights of w1 and w2 (w0 = 1 - u - v), so Ueq0 is base edge E2, Veq0 is E0 and Weq0 is E1 (§7.6).
class D3d11Patch : public StoredPatch<d3d11::Point> {
  public:
    D3d11Patch(const std::array<float, 4>& factors, d3d11::Partitioning partitioning) {
        const d3d11::TessOptions options{partitioning, d3d11_winding};
        resize(d3d11::detail::tessellate_tri_into(nullptr, nullptr, factors, options));
        d3d11::detail::tessellate_tri_into(points_.data(), indices_.data(), factors, options);
    }
};

// The D3D11 patterns (§7.6): each base edge's factor as the tessellator takes it (it clamps to the
// partitioning's range), a factor that would cull (NaN, zero, negative) raised to 1 so that no face is ever
// dropped, the inside factor the mean of the three edges in base-edge order (a per-patch value: it moves the
// interior only).
struct D3d11Family {
    using patch_type = D3d11Patch;
    static constexpr bool own_diagonal = true;
    d3d11::Partitioning partitioning;

    static float sanitized(float f) { return f > 0.0f ? f : 1.0f; } // NaN compares false: 1
    // The tessellator's factors {Ueq0, Veq0, Weq0, inside}: base edges E2, E0, E1, and the mean of the three
    // as the tessellator clamps (and, in the integer modes, rounds) them.
    std::array<float, 4> domain_factors(const PatchRecord& rec) const {
        const float f[3] = {std::bit_cast<float>(rec.token[0]), std::bit_cast<float>(rec.token[1]),
                            std::bit_cast<float>(rec.token[2])};
        const float inside =
            (d3d11::clamped_edge_float(partitioning, f[0]) + d3d11::clamped_edge_float(partitioning, f[1]) +
             d3d11::clamped_edge_float(partitioning, f[2])) /
            3.0f;
        return {f[2], f[0], f[1], inside};
    }
    void set_lines(PatchRecord& rec, const float (&f)[3]) const {
        for (unsigned k = 0; k < 3; ++k) rec.token[k] = std::bit_cast<std::uint32_t>(sanitized(f[k]));
    }
    void lines(PatchRecord& rec, const float (&)[3]) const { set_lines(rec, rec.factor); }
    void setup(PatchRecord& rec, const float (&)[3]) const {
        set_lines(rec, rec.factor);
        const Counts c = counts_of(rec);
        rec.vertex_count = c.vertices;
        rec.triangle_count = c.triangles;
    }
    bool clamped(float f) const { return sanitized(f) > d3d11::factor_range(partitioning).hi; }
    bool record_counts(const PatchRecord& rec, bool culled, Counts& counts) const {
        if (culled) return true;
        if (rec.rotation != 0) return false;
        for (unsigned k = 0; k < 3; ++k)
            if (!(std::bit_cast<float>(rec.token[k]) > 0.0f) || rec.t16[k] != 0) return false;
        counts = counts_of(rec);
        return true;
    }
    patch_type patch(const PatchRecord& rec) const { return D3d11Patch(domain_factors(rec), partitioning); }
    Counts counts_of(const PatchRecord& rec) const {
        return d3d11::detail::tessellate_tri_into(nullptr, nullptr, domain_factors(rec),
                                                  {partitioning, d3d11_winding});
    }
    patch_type welded_patch(const PatchRecord& rec) const { return patch(rec); }
    static DomainPoint base_point(const patch_type& patch, const PatchRecord&, std::uint32_t i) {
        const d3d11::Point p = patch.vertex(i);
        constexpr std::uint32_t scale = cp::fixed_one / d3d11::fixed_one; // 2^8: exact
        return {p.u * scale, p.v * scale};
    }
    // The points of an edge of factor f (mirror-symmetric, edge.hpp), scaled exactly to 2^-24.
    void edge_params(float f, EdgeParams& out) const {
        const d3d11::FixedFactor factor = d3d11::process_edge_factor(partitioning, sanitized(f));
        const d3d11::EdgeContext context = d3d11::edge_context(factor);
        const std::uint32_t n = d3d11::point_count(factor);
        out.reset(n);
        for (std::uint32_t p = 0; p < n; ++p) {
            const std::uint32_t x = d3d11::place_point(context, p) * (cp::fixed_one / d3d11::fixed_one);
            if (x != 0 && x != one) out.value[out.count++] = x;
        }
        out.finish();
    }
    void record_edge_params(const PatchRecord& rec, unsigned k, EdgeParams& out) const {
        edge_params(std::bit_cast<float>(rec.token[k]), out);
    }
};

// What a family gives the loops below: an indexed patch type and its setup, record check and base points.
template <class F>
concept PipelineFamily = IndexedTessPatch<typename F::patch_type> &&
    requires(const F& f, PatchRecord& rec, const PatchRecord& crec, const float (&l)[3], Counts& counts,
             const typename F::patch_type& p, EdgeParams& params) {
    f.setup(rec, l);
    f.lines(rec, l);
    f.set_lines(rec, l);
    { f.clamped(0.0f) } -> std::same_as<bool>;
    { f.record_counts(crec, true, counts) } -> std::same_as<bool>;
    { f.counts_of(crec) } -> std::same_as<Counts>;
    { f.patch(crec) } -> std::same_as<typename F::patch_type>;
    { f.welded_patch(crec) } -> std::same_as<typename F::patch_type>;
    { f.base_point(p, crec, 0u) } -> std::same_as<DomainPoint>;
    f.edge_params(0.0f, params);
    f.record_edge_params(crec, 0u, params);
};

// Half h of a quad record (A = 0, B = 1) as a triangle record with rotation 0.
PatchRecord half_record(const PatchRecord& rec, unsigned h) {
    PatchRecord half;
    for (unsigned k = 0; k < 3; ++k) {
        half.token[k] = h == 0 ? rec.token[k] : rec.setup[quad_setup_word::b_token + k];
        half.t16[k] = h == 0 ? rec.t16[k] : rec.setup[quad_setup_word::b_t16 + k];
    }
    return half;
}

// The quad rule (docs/algorithm.md §7.2), from the quad's squared edge lengths (a per-quad constant, so the
// choice never pops). CP: q0q1 is the longer edge of the opposite pair with the larger summed length: the
// diagonal takes q0q1's factor and A's and B's columns run across the pair, so the long direction gets the
// dense lines. Uniform: the shorter diagonal, whose factor is its own. Ties and NaN keep the labelled order.
unsigned cp_quad_rotation(const float (&length2)[4], QuadRule rule) {
    if (rule == QuadRule::as_labelled) return 0;
    float len[4];
    for (unsigned k = 0; k < 4; ++k) len[k] = std::sqrt(length2[k]);
    const unsigned first = len[1] + len[3] > len[0] + len[2] ? 1u : 0u;
    return len[first + 2] > len[first] ? first + 2 : first;
}

unsigned uniform_quad_rotation(const MeshView& mesh, const std::uint32_t (&w)[4], QuadRule rule) {
    if (rule == QuadRule::as_labelled) return 0;
    // Rotation 0 splits along q1q3, rotation 1 along q2q0 (= input q0q2).
    return mesh_edge_length2(mesh, w[0], w[2]) < mesh_edge_length2(mesh, w[1], w[3]) ? 1u : 0u;
}

template <PipelineFamily F>
PatchRecord setup_quad_record(const F& family, const MeshView& mesh, std::uint32_t q,
                              const PipelineOptions& options, std::uint32_t& clamped, bool counted) {
    PatchRecord rec;
    rec.kind = patch_kind_quad;
    std::uint32_t w[4];
    if (!base_quad(mesh, q, w)) return rec;
    float f[4], length2[4];
    for (unsigned k = 0; k < 4; ++k) {
        f[k] = mesh_edge_factor(mesh, w[k], w[(k + 1) % 4], options);
        length2[k] = mesh_edge_length2(mesh, w[k], w[(k + 1) % 4]);
        clamped += family.clamped(f[k]) ? 1u : 0u;
    }
    for (unsigned k = 0; k < 3; ++k) rec.factor[k] = f[k];
    rec.setup[quad_setup_word::q3_factor] = std::bit_cast<std::uint32_t>(f[3]);
    unsigned r;
    float diagonal;
    if constexpr (F::own_diagonal) {
        r = uniform_quad_rotation(mesh, w, options.quad_rule);
        diagonal = mesh_edge_factor(mesh, w[(1 + r) % 4], w[(3 + r) % 4], options);
        clamped += family.clamped(diagonal) ? 1u : 0u;
    } else {
        r = cp_quad_rotation(length2, options.quad_rule);
        diagonal = f[r]; // A's e0, edge q0q1 (§2.12)
    }
    rec.rotation = r;
    const float fq[4] = {f[r], f[(r + 1) % 4], f[(r + 2) % 4], f[(r + 3) % 4]};
    // A = (q0, q1, q3): e0 = q0q1, e1 = the diagonal, e2 = q0q3; B = (q2, q3, q1): e0 = q2q3, e2 = q2q1.
    const float fa[3] = {fq[0], diagonal, fq[3]};
    const float fb[3] = {fq[2], diagonal, fq[1]};
    PatchRecord a, b;
    family.set_lines(a, fa);
    family.set_lines(b, fb);
    for (unsigned k = 0; k < 3; ++k) {
        rec.token[k] = a.token[k];
        rec.t16[k] = a.t16[k];
        rec.setup[quad_setup_word::b_token + k] = b.token[k];
        rec.setup[quad_setup_word::b_t16 + k] = b.t16[k];
    }
    if (!counted) return rec;
    // Counted, not emitted; a sum past 32 bits saturates, so the totals check refuses it.
    const Counts ca = family.counts_of(a), cb = family.counts_of(b);
    const auto saturated = [](std::uint64_t x) {
        return x < 0xFFFFFFFFu ? static_cast<std::uint32_t>(x) : 0xFFFFFFFFu;
    };
    rec.vertex_count = saturated(std::uint64_t{ca.vertices} + cb.vertices);
    rec.triangle_count = saturated(std::uint64_t{ca.triangles} + cb.triangles);
    return rec;
}

// Patch p's record: a base triangle (p < triangle_count) or a quad. counted = false: the rotation and line
// states only (what the weld reads), without the counts and the setup block, which can cost a whole pattern
// walk (split, D3D11).
template <PipelineFamily F>
PatchRecord setup_record(const F& family, const MeshView& mesh, std::uint32_t p,
                         const PipelineOptions& options, std::uint32_t& clamped, bool counted = true) {
    if (p >= mesh.triangle_count)
        return setup_quad_record(family, mesh, p - mesh.triangle_count, options, clamped, counted);
    PatchRecord rec;
    std::uint32_t w[3];
    if (!base_triangle(mesh, p, w)) return rec;
    float length2[3];
    for (unsigned k = 0; k < 3; ++k) {
        rec.factor[k] = mesh_edge_factor(mesh, w[k], w[(k + 1) % 3], options);
        length2[k] = mesh_edge_length2(mesh, w[k], w[(k + 1) % 3]);
        clamped += family.clamped(rec.factor[k]) ? 1u : 0u;
    }
    if (counted)
        family.setup(rec, length2);
    else
        family.lines(rec, length2);
    return rec;
}

bool patch_culled(const MeshView& mesh, std::uint32_t p) {
    if (p < mesh.triangle_count) {
        std::uint32_t w[3];
        return !base_triangle(mesh, p, w);
    }
    std::uint32_t w[4];
    return !base_quad(mesh, p - mesh.triangle_count, w);
}

// The counts a record must have: a triangle's as the family checks them, a quad's as its two halves'.
template <PipelineFamily F>
bool record_counts(const F& family, const MeshView& mesh, std::uint32_t p, const PatchRecord& rec,
                   Counts& counts) {
    const bool culled = patch_culled(mesh, p);
    counts = {};
    if (p < mesh.triangle_count)
        return rec.kind == patch_kind_triangle && family.record_counts(rec, culled, counts);
    if (rec.kind != patch_kind_quad || rec.rotation > 3) return false;
    if (culled) return true;
    for (unsigned h = 0; h < 2; ++h) {
        Counts c;
        if (!family.record_counts(half_record(rec, h), false, c)) return false;
        counts.vertices += c.vertices;
        counts.triangles += c.triangles;
    }
    return true;
}

PipelineStatus check_options(const UniformTableSet* uniform, const PipelineOptions& options) {
    if (static_cast<std::uint32_t>(options.pattern) >
        static_cast<std::uint32_t>(Pattern::d3d11_fractional_even))
        return PipelineStatus::bad_option;
    if (options.quad_rule != QuadRule::longer_pair && options.quad_rule != QuadRule::as_labelled)
        return PipelineStatus::bad_option;
    if ((options.pattern == Pattern::uniform || options.pattern == Pattern::uniform_split) &&
        uniform == nullptr)
        return PipelineStatus::no_uniform_tables;
    const Surface surface = options.surface.surface;
    if (surface != Surface::flat && surface != Surface::pn_triangles && surface != Surface::phong &&
        surface != Surface::pn_aen)
        return PipelineStatus::bad_option;
    if (options.displacement != nullptr && !displacement_valid(*options.displacement))
        return PipelineStatus::bad_option;
    return PipelineStatus::ok;
}

// Runs fn with the family of options.pattern (check_options has accepted it).
template <class Fn>
PipelineStatus with_family(const CpTableSet& tables, const UniformTableSet* uniform,
                           const PipelineOptions& options, Fn&& fn) {
    switch (options.pattern) {
    case Pattern::uniform:
        return fn(UniformFamily{*uniform});
    case Pattern::uniform_split:
        return fn(UniformSplitFamily{*uniform, {}});
    case Pattern::d3d11_integer:
        return fn(D3d11Family{d3d11::Partitioning::integer});
    case Pattern::d3d11_pow2:
        return fn(D3d11Family{d3d11::Partitioning::pow2});
    case Pattern::d3d11_fractional_odd:
        return fn(D3d11Family{d3d11::Partitioning::fractional_odd});
    case Pattern::d3d11_fractional_even:
        return fn(D3d11Family{d3d11::Partitioning::fractional_even});
    case Pattern::cp:
        break;
    }
    return fn(CpFamily{tables});
}

template <PipelineFamily F>
PipelineStatus setup_all(const F& family, const MeshView& mesh, const PipelineOptions& options,
                         std::span<PatchRecord> patches, PipelineTotals& totals) {
    if (const PipelineStatus s = check_pipeline_size(mesh.patch_count(), 0, 0); s != PipelineStatus::ok)
        return s;
    std::uint64_t vertices = 0, triangles = 0;
    std::uint32_t clamped = 0;
    const auto count = static_cast<std::uint32_t>(mesh.patch_count());
    for (std::uint32_t p = 0; p < count; ++p) {
        PatchRecord rec = setup_record(family, mesh, p, options, clamped);
        rec.first_vertex = static_cast<std::uint32_t>(vertices);
        rec.first_triangle = static_cast<std::uint32_t>(triangles);
        vertices += rec.vertex_count;
        triangles += rec.triangle_count;
        if (const PipelineStatus s = check_pipeline_size(0, vertices, triangles); s != PipelineStatus::ok)
            return s;
        patches[p] = rec;
    }
    totals = {static_cast<std::uint32_t>(vertices), static_cast<std::uint32_t>(triangles), clamped};
    return PipelineStatus::ok;
}

PipelineStatus setup_patches(const CpTableSet& tables, const UniformTableSet* uniform, const MeshView& mesh,
                             const PipelineOptions& options, std::span<PatchRecord> patches,
                             PipelineTotals& totals) {
    if (patches.size() < mesh.patch_count()) return PipelineStatus::span_too_small;
    if (const PipelineStatus s = check_options(uniform, options); s != PipelineStatus::ok) return s;
    return with_family(tables, uniform, options,
                       [&](const auto& family) { return setup_all(family, mesh, options, patches, totals); });
}

// The corners of a quad in pattern order (q_k = mesh corner (k + rotation) % 4).
void quad_corners(const MeshView& mesh, const std::uint32_t (&w)[4], std::uint32_t rotation,
                  SurfaceCorner (&q)[4]) {
    for (unsigned k = 0; k < 4; ++k) q[k] = mesh_corner(mesh, w[(k + rotation) % 4]);
}

// Checks every record and the spans, then writes every patch's vertices and triangles.
template <PipelineFamily F>
PipelineStatus emit_all(const F& family, const MeshView& mesh, const PipelineOptions& options,
                        std::span<const PatchRecord> patches, std::span<TessVertex> vertices,
                        std::span<std::uint32_t> indices, bool range) {
    if (const PipelineStatus s = check_pipeline_size(mesh.patch_count(), 0, 0); s != PipelineStatus::ok)
        return s;
    const auto count = static_cast<std::uint32_t>(mesh.patch_count());
    // The offsets run on from 0 for a whole mesh; a range (emit_mesh_range) starts where its first record
    // does, so threads emit ranges into one pair of buffers. The spans are checked against the end.
    std::uint64_t vertex_sum = range && count != 0 ? patches[0].first_vertex : 0,
                  triangle_sum = range && count != 0 ? patches[0].first_triangle : 0;
    for (std::uint32_t p = 0; p < count; ++p) {
        const PatchRecord& rec = patches[p];
        Counts counts;
        if (!record_counts(family, mesh, p, rec, counts) || rec.first_vertex != vertex_sum ||
            rec.first_triangle != triangle_sum || rec.vertex_count != counts.vertices ||
            rec.triangle_count != counts.triangles)
            return PipelineStatus::bad_patch_record;
        vertex_sum += rec.vertex_count;
        triangle_sum += rec.triangle_count;
        if (const PipelineStatus s = check_pipeline_size(0, vertex_sum, triangle_sum);
            s != PipelineStatus::ok)
            return s;
    }
    if (vertex_sum > vertices.size() || 3 * triangle_sum > indices.size())
        return PipelineStatus::span_too_small;
    TrianglePointBatch batch;
    for (std::uint32_t p = 0; p < count; ++p) {
        const PatchRecord& rec = patches[p];
        if (rec.vertex_count == 0) continue;
        std::uint32_t* out = indices.data() + 3 * std::size_t{rec.first_triangle};
        if (p < mesh.triangle_count) {
            std::uint32_t w[3];
            base_triangle(mesh, p, w);
            const SurfaceCorner corner[3] = {mesh_corner(mesh, w[0]), mesh_corner(mesh, w[1]),
                                             mesh_corner(mesh, w[2])};
            const PatchSurface surface = triangle_surface(mesh, p, corner, options);
            const typename F::patch_type patch = family.patch(rec);
            TessVertex* out_vertex = vertices.data() + rec.first_vertex;
            if (surface.aen) {
                for (std::uint32_t i = 0; i < rec.vertex_count; ++i)
                    out_vertex[i] = surface_vertex(corner, family.base_point(patch, rec, i), surface);
            }
            // Without PN-AEN: the same values in batches.
            for (std::uint32_t i = 0; i < rec.vertex_count && !surface.aen; i += TrianglePointBatch::size) {
                const auto n = static_cast<std::uint32_t>(
                    std::min<std::size_t>(TrianglePointBatch::size, rec.vertex_count - i));
                for (std::uint32_t k = 0; k < n; ++k) batch.base(k) = family.base_point(patch, rec, i + k);
                batch.evaluate(corner, surface, n);
                for (std::uint32_t k = 0; k < n; ++k)
                    out_vertex[i + k] = tess_vertex(batch.base(k), batch.point(k));
            }
            for (std::uint32_t t = 0; t < rec.triangle_count; ++t) {
                const std::array<std::uint32_t, 3> tri = patch.triangle(t);
                for (unsigned k = 0; k < 3; ++k) out[3 * t + k] = rec.first_vertex + tri[k];
            }
            continue;
        }
        // A quad: A's vertices and triangles, then B's, each half's points mapped into the unit square.
        std::uint32_t w[4];
        base_quad(mesh, p - mesh.triangle_count, w);
        SurfaceCorner q[4];
        quad_corners(mesh, w, rec.rotation, q);
        const PatchSurface surface = quad_surface(mesh, p - mesh.triangle_count, rec.rotation, q, options);
        std::uint32_t first = rec.first_vertex;
        for (unsigned h = 0; h < 2; ++h) {
            const PatchRecord half = half_record(rec, h);
            const typename F::patch_type patch = family.patch(half);
            const Counts c = patch.counts();
            for (std::uint32_t i = 0; i < c.vertices; ++i)
                vertices[first + i] =
                    quad_vertex(q, cp::quad_point(h, family.base_point(patch, half, i)), surface);
            for (std::uint32_t t = 0; t < c.triangles; ++t) {
                const std::array<std::uint32_t, 3> tri = patch.triangle(t);
                for (unsigned k = 0; k < 3; ++k) out[3 * t + k] = first + tri[k];
            }
            first += c.vertices;
            out += 3 * std::size_t{c.triangles};
        }
    }
    return PipelineStatus::ok;
}

PipelineStatus emit_mesh(const CpTableSet& tables, const UniformTableSet* uniform, const MeshView& mesh,
                         const PipelineOptions& options, std::span<const PatchRecord> patches,
                         std::span<TessVertex> vertices, std::span<std::uint32_t> indices, bool range) {
    if (patches.size() < mesh.patch_count()) return PipelineStatus::span_too_small;
    if (const PipelineStatus s = check_options(uniform, options); s != PipelineStatus::ok) return s;
    return with_family(tables, uniform, options, [&](const auto& family) {
        return emit_all(family, mesh, options, patches, vertices, indices, range);
    });
}

// --- The welded output (docs/algorithm.md §7.4) ---

// A function object, not a function: std::sort and std::lower_bound inline its comparison (through a function
// pointer they called it, a quarter of setup_welded's time in the edge sort).
constexpr auto edge_less = [](const WeldedEdge& a, const WeldedEdge& b) {
    return a.lo != b.lo ? a.lo < b.lo : a.hi < b.hi;
};

WeldedEdge edge_key(std::uint32_t i, std::uint32_t j) {
    WeldedEdge e;
    e.lo = i < j ? i : j;
    e.hi = i < j ? j : i;
    return e;
}

// One triangle of a patch as the weld sees it: the record of its pattern (a base triangle's, or a quad half
// with rotation 0), the mesh indices of the corners its base weights refer to, and whether its e1 (opposite
// pattern corner 0) is a quad's diagonal, inside the patch.
// Where a pattern slot of weights w lies (docs/algorithm.md §7.4): corner c when its weight is one, else on
// the edge opposite the first corner k of zero weight (a quad half's inner edge E1, k = 0, is interior), else
// inside; 3 means none.
struct SlotPlace {
    unsigned corner = 3, edge = 3;
};
SlotPlace slot_place(const std::uint32_t (&w)[3], bool inner_e1) {
    SlotPlace place;
    for (unsigned j = 0; j < 3 && place.edge == 3; ++j)
        if (w[j] == 0 && !(inner_e1 && j == 0)) place.edge = j;
    if (w[0] == one || w[1] == one || w[2] == one) place.corner = w[0] == one ? 0 : w[1] == one ? 1 : 2;
    return place;
}

struct WeldTriangle {
    PatchRecord rec;
    std::uint32_t corner[3] = {};
    unsigned local[3] = {}; // which patch corner each is: 0-2 of the base triangle, 0-3 of the mesh quad
    bool inner_e1 = false;
    unsigned half = 0; // quad half (A = 0, B = 1)
};

// Patch edge e of a patch with 3 or 4 corners, by its local corners: a triangle's edge e is opposite corner e
// (the weld's numbering), a quad's runs from mesh corner e to e + 1.
constexpr unsigned patch_edge_from(unsigned corners, unsigned e) {
    return corners == 3 ? (e + 1) % 3 : e;
}
constexpr unsigned patch_edge_to(unsigned corners, unsigned e) {
    return corners == 3 ? (e + 2) % 3 : (e + 1) % 4;
}

// A patch's weld in local ids (docs/algorithm.md §7.4, "Patch shapes"): the patch corners first, then each
// patch edge's distinct interior points by the rank of their parameter measured from the edge's first local
// corner, then the patch's distinct interior points by rank. It is a function of the record's pattern words
// alone (the key: kind, rotation, line states of both halves), because each edge's line is its record line
// (set_lines and edge_params read the same factor), and the equalities among its ids are the mesh's whenever
// the patch's corners are distinct: corners are distinct mesh indices, distinct edges own disjoint id ranges
// after them, interior ids follow the edges. A patch is then its shape plus a table of its ids.
struct WeldShape {
    static constexpr unsigned key_words = 14;
    std::array<std::uint32_t, key_words> key{};
    bool filled = false;
    bool usable = false; // false: the patches of this key take the general path (PatchWeld::run_general)
    unsigned corners = 3;
    std::uint32_t edge_count[4] = {}; // distinct interior parameters of each patch edge's line
    std::uint32_t edge_base[4] = {};  // local id of rank 0
    std::uint32_t interior_base = 0;
    std::uint32_t interior_count = 0;
    std::uint32_t local_count = 0;
    std::vector<std::uint32_t> eval_id;   // every local id a slot reaches, once
    std::vector<DomainPoint> eval_point;  // its domain point (base weights, or a quad's unit square)
    std::vector<std::uint32_t> triangles; // the kept triangles in local ids, A's then B's, pattern order
};

std::array<std::uint32_t, WeldShape::key_words> weld_shape_key(const PatchRecord& rec) {
    std::array<std::uint32_t, WeldShape::key_words> key{};
    key[0] = rec.kind;
    key[1] = rec.rotation;
    for (unsigned k = 0; k < 3; ++k) {
        key[2 + k] = rec.token[k];
        key[5 + k] = rec.t16[k];
    }
    if (rec.kind == patch_kind_quad)
        for (unsigned k = 0; k < 6; ++k) key[8 + k] = rec.setup[quad_setup_word::b_token + k];
    return key;
}

// The welded ids of one patch: the triangle of a base triangle or the two halves of a quad, every slot of
// their shared-layout patterns mapped to a corner (its mesh index), an edge point (by the rank of its
// parameter on the edge's line) or an interior point of the patch (by the rank of its exact domain point
// among the patch's distinct interior points: a quad's diagonal and coincident slots become one vertex).
// A patch with distinct corners reads its shape from a small cache (the pattern is generated and classified
// once per key); one with a repeated corner takes the general path, slot by slot.
unsigned patch_edges(const MeshView& mesh, std::uint32_t p, WeldedEdge (&out)[4]);

template <PipelineFamily F>
class PatchWeld {
  public:
    PatchWeld(const F& family, const MeshView& mesh, const PipelineOptions& options,
              std::span<const WeldedEdge> edges)
        : family_(family), mesh_(mesh), options_(options), edges_(edges), shapes_(shape_slots + 1),
          edge_start_(std::size_t{mesh.vertex_count} + 1) {
        // The edge list is sorted by (lo, hi): the edges of each lo are one run, found in O(1).
        std::size_t e = 0;
        for (std::uint32_t v = 0; v <= mesh.vertex_count; ++v) {
            while (e < edges.size() && edges[e].lo < v) ++e;
            edge_start_[v] = static_cast<std::uint32_t>(e);
        }
    }

    // Skips corners and edge points already marked in written (bit per id below the patches' interiors)
    // and marks the ones it writes: patches run last to first then write each shared point once, with the
    // value the last patch to reach it gives (the order of the forward loop, where later patches overwrite).
    void set_written(std::uint64_t* written) { written_ = written; }

    // Marks every corner and edge point of patch p (none when culled): what running it would mark. False,
    // marking part of them, when one of its edges is missing from the list.
    bool mark_reached(std::uint32_t p) {
        WeldedEdge e[4];
        const unsigned m = patch_edges(mesh_, p, e);
        for (unsigned k = 0; k < m; ++k) {
            const WeldedEdge* edge = find_edge(e[k].lo, e[k].hi);
            if (edge == nullptr) return false;
            mark(e[k].lo), mark(e[k].hi);
            for (std::uint32_t i = 0; i < edge->vertex_count; ++i) mark(edge->first_vertex + i);
        }
        return true;
    }
    // Marks the corners of patch p (none when culled).
    void mark_corners(std::uint32_t p) {
        WeldedEdge e[4];
        const unsigned m = patch_edges(mesh_, p, e);
        for (unsigned k = 0; k < m; ++k) mark(e[k].lo), mark(e[k].hi);
    }

    // Runs patch p with its interior ids from first_vertex. Counts its interior vertices and kept triangles;
    // writes them when vertices is not empty (triangles at indices). False when a point is not on its edge's
    // line or an edge is missing from the list (a list setup_welded did not produce).
    bool run(std::uint32_t p, std::uint32_t first_vertex, Counts& counts, std::span<TessVertex> vertices,
             std::uint32_t* indices) {
        counts = {};
        if (patch_culled(mesh_, p)) return true;
        std::uint32_t clamped = 0;
        const PatchRecord rec = setup_record(family_, mesh_, p, options_, clamped, false);
        WeldTriangle tri[2];
        unsigned n = 1;
        std::uint32_t w[4] = {};
        if (p < mesh_.triangle_count) {
            std::uint32_t t[3];
            base_triangle(mesh_, p, t);
            tri[0].rec = rec;
            for (unsigned k = 0; k < 3; ++k) {
                w[k] = t[k];
                tri[0].corner[k] = t[k];
                tri[0].local[k] = k;
            }
        } else {
            base_quad(mesh_, p - mesh_.triangle_count, w);
            const unsigned order[2][3] = {{0, 1, 3}, {2, 3, 1}};
            n = 2;
            for (unsigned h = 0; h < 2; ++h) {
                tri[h].rec = half_record(rec, h);
                tri[h].inner_e1 = true;
                tri[h].half = h;
                for (unsigned k = 0; k < 3; ++k) {
                    tri[h].local[k] = (order[h][k] + rec.rotation) % 4;
                    tri[h].corner[k] = w[tri[h].local[k]];
                }
            }
        }
        const unsigned corners = n == 1 ? 3 : 4;
        bool distinct = true;
        for (unsigned i = 0; i < corners; ++i)
            for (unsigned j = i + 1; j < corners; ++j) distinct = distinct && w[i] != w[j];
        if (!vertices.empty()) {
            if (n == 1) {
                for (unsigned k = 0; k < 3; ++k) corner_[k] = mesh_corner(mesh_, w[k]);
                surface_ = triangle_surface(mesh_, p, corner_, options_);
            } else {
                quad_corners(mesh_, w, rec.rotation, q_);
                surface_ = quad_surface(mesh_, p - mesh_.triangle_count, rec.rotation, q_, options_);
            }
        }
        if (distinct) {
            const WeldShape& shape = shape_of(rec, tri, n, w);
            if (shape.usable) return run_shape(shape, n, w, first_vertex, counts, vertices, indices);
        }
        return run_general(tri, n, first_vertex, counts, vertices, indices);
    }

  private:
    // The shape cache: shape_slots direct-mapped by a hash of the key, plus one slot for a shape with more
    // than large_shape local ids (or twice as many triangles). At most about 5 MB with CP at 64.
    static constexpr std::size_t shape_slots = 32;
    static constexpr std::uint32_t large_shape = 4096;

    TessVertex evaluate(unsigned n, DomainPoint d) const {
        return n == 1 ? surface_vertex(corner_, d, surface_) : quad_vertex(q_, d, surface_);
    }
    bool take(std::uint32_t id) const { return (written_[id / 64] >> (id % 64) & 1u) == 0; }
    void mark(std::uint32_t id) { written_[id / 64] |= std::uint64_t{1} << (id % 64); }

    // Edge (a, b) of the sorted list, or null: a binary search in the run of its lower index.
    const WeldedEdge* find_edge(std::uint32_t a, std::uint32_t b) const {
        const WeldedEdge key = edge_key(a, b);
        if (key.lo >= mesh_.vertex_count) return nullptr;
        const auto first = edges_.begin() + edge_start_[key.lo],
                   last = edges_.begin() + edge_start_[key.lo + 1];
        const auto it = std::lower_bound(first, last, key, edge_less);
        return it == last || it->hi != key.hi ? nullptr : &*it;
    }

    WeldShape& shape_of(const PatchRecord& rec, const WeldTriangle (&tri)[2], unsigned n,
                        const std::uint32_t (&w)[4]) {
        const std::array<std::uint32_t, WeldShape::key_words> key = weld_shape_key(rec);
        std::uint64_t hash = 0xcbf29ce484222325u; // FNV-1a over the key words
        for (const std::uint32_t word : key) hash = (hash ^ word) * 0x100000001b3u;
        WeldShape& shape = shapes_[(hash ^ hash >> 29) % shape_slots];
        WeldShape& large = shapes_[shape_slots];
        if (shape.filled && shape.key == key) return shape;
        if (large.filled && large.key == key) return large;
        shape.key = key;
        build_shape(shape, tri, n, w);
        if (shape.local_count <= large_shape && shape.triangles.size() <= 6 * std::size_t{large_shape})
            return shape;
        // A large pattern (a split or D3D11 patch far above the tables' factors) is kept alone, so that the
        // cache holds at most one shape larger than large_shape.
        std::swap(shape, large);
        shape = WeldShape{};
        return large;
    }

    // Classifies every slot of the patch's pattern as run_general does, in local ids. Leaves the shape
    // unusable (the general path, whose result it would have to reproduce) where a parameter is not on its
    // line, where the line's parameter set is not mirror-symmetric at a point (its rank from the other end
    // is not count - 1 - rank), or where one id's slots disagree on their domain point.
    void build_shape(WeldShape& s, const WeldTriangle (&tri)[2], unsigned n, const std::uint32_t (&w)[4]) {
        s.filled = true;
        s.usable = false;
        s.local_count = 0;
        s.corners = n == 1 ? 3 : 4;
        s.eval_id.clear();
        s.eval_point.clear();
        s.triangles.clear();
        std::uint32_t next = s.corners;
        for (unsigned e = 0; e < s.corners; ++e) {
            const std::uint32_t a = w[patch_edge_from(s.corners, e)], b = w[patch_edge_to(s.corners, e)];
            family_.edge_params(mesh_edge_factor(mesh_, a, b, options_), params_[e]);
            s.edge_count[e] = params_[e].count;
            s.edge_base[e] = next;
            next += params_[e].count;
        }
        s.interior_base = next;
        std::uint32_t offset[2] = {0, 0}, total = 0;
        inner_.clear();
        std::optional<typename F::patch_type> patches[2];
        for (unsigned h = 0; h < n; ++h) {
            const WeldTriangle& t = tri[h];
            const typename F::patch_type& patch = patches[h].emplace(family_.welded_patch(t.rec));
            const Counts c = patch.counts();
            offset[h] = total;
            total += c.vertices;
            if (map_.size() < total) map_.resize(total);
            if (slot_point_.size() < total) slot_point_.resize(total);
            for (std::uint32_t i = 0; i < c.vertices; ++i) {
                const DomainPoint base = family_.base_point(patch, t.rec, i);
                const std::uint32_t bw[3] = {one - base.u - base.v, base.u, base.v};
                const DomainPoint d = n == 1 ? base : cp::quad_point(t.half, base);
                slot_point_[offset[h] + i] = d;
                const SlotPlace place = slot_place(bw, t.inner_e1);
                const unsigned k = place.edge;
                if (place.corner < 3) {
                    map_[offset[h] + i] = t.local[place.corner];
                } else if (k < 3) {
                    const unsigned i1 = (k + 1) % 3, i2 = (k + 2) % 3;
                    const unsigned ci = t.local[i1], cj = t.local[i2];
                    const unsigned e = n == 1 ? k : (ci + 1) % 4 == cj ? ci : cj;
                    // The parameter from the edge's first local corner, and from its second.
                    const std::uint32_t x = ci == patch_edge_from(s.corners, e) ? bw[i2] : bw[i1];
                    const unsigned count = params_[e].count;
                    const unsigned r = params_[e].rank(x), back = params_[e].rank(one - x);
                    if (r == count || back != count - 1 - r) return;
                    map_[offset[h] + i] = s.edge_base[e] + r;
                } else {
                    inner_.push_back({std::uint64_t{d.u} << 32 | d.v, offset[h] + i});
                }
            }
        }
        const std::uint32_t interior = rank_interior(s.interior_base);
        s.interior_count = interior;
        s.local_count = s.interior_base + interior;
        // One evaluation per local id, at its first slot's domain point.
        if (seen_.size() < s.local_count) seen_.resize(s.local_count);
        std::fill(seen_.begin(), seen_.begin() + s.local_count, none);
        for (std::uint32_t j = 0; j < total; ++j) {
            const std::uint32_t id = map_[j];
            if (seen_[id] == none) {
                seen_[id] = static_cast<std::uint32_t>(s.eval_id.size());
                s.eval_id.push_back(id);
                s.eval_point.push_back(slot_point_[j]);
            } else if (s.eval_point[seen_[id]].u != slot_point_[j].u ||
                       s.eval_point[seen_[id]].v != slot_point_[j].v) {
                return;
            }
        }
        for (unsigned h = 0; h < n; ++h) {
            const typename F::patch_type& patch = *patches[h];
            const std::uint32_t* map = map_.data() + offset[h];
            for (std::uint32_t k = 0; k < patch.counts().triangles; ++k) {
                const std::array<std::uint32_t, 3> local = patch.triangle(k);
                const std::uint32_t a = map[local[0]], b = map[local[1]], d = map[local[2]];
                if (!options_.weld.keep_degenerate && (a == b || b == d || a == d)) continue;
                s.triangles.insert(s.triangles.end(), {a, b, d});
            }
        }
        s.usable = true;
    }

    // A patch with distinct corners: its ids from its corners, its edges' ranges and first_vertex.
    bool run_shape(const WeldShape& s, unsigned n, const std::uint32_t (&w)[4], std::uint32_t first_vertex,
                   Counts& counts, std::span<TessVertex> vertices, std::uint32_t* indices) {
        // Counting (setup_welded, and emit_welded_mesh's check of the records) needs only the edges' checks.
        const bool count_only = indices == nullptr && vertices.empty();
        if (ids_.size() < s.local_count) ids_.resize(s.local_count);
        std::uint32_t* ids = ids_.data();
        for (unsigned c = 0; c < s.corners; ++c) ids[c] = w[c];
        for (unsigned e = 0; e < s.corners; ++e) {
            const std::uint32_t a = w[patch_edge_from(s.corners, e)], b = w[patch_edge_to(s.corners, e)];
            const WeldedEdge* edge = find_edge(a, b);
            if (edge == nullptr || edge->vertex_count != s.edge_count[e]) return false;
            if (count_only) continue;
            const std::uint32_t count = s.edge_count[e];
            std::uint32_t* out = ids + s.edge_base[e];
            // Ranks count from the lower mesh index (the set is symmetric, build_shape checked it).
            if (a < b)
                for (std::uint32_t r = 0; r < count; ++r) out[r] = edge->first_vertex + r;
            else
                for (std::uint32_t r = 0; r < count; ++r) out[r] = edge->first_vertex + (count - 1 - r);
        }
        counts = {s.interior_count, static_cast<std::uint32_t>(s.triangles.size() / 3)};
        if (count_only) return true;
        for (std::uint32_t j = 0; j < s.interior_count; ++j) ids[s.interior_base + j] = first_vertex + j;
        if (indices != nullptr) {
            const std::uint32_t* local = s.triangles.data();
            for (std::size_t k = 0; k < s.triangles.size(); ++k) indices[k] = ids[local[k]];
        }
        if (vertices.empty()) return true;
        if (n == 1 && !surface_.aen) {
            write_triangle_points(s, ids, vertices);
            return true;
        }
        for (std::size_t j = 0; j < s.eval_id.size(); ++j) {
            const std::uint32_t local = s.eval_id[j], id = ids[local];
            const bool shared = local < s.interior_base; // a corner or an edge point
            if (shared && written_ != nullptr) {
                if (!take(id)) continue;
                mark(id);
            }
            TessVertex v = evaluate(n, s.eval_point[j]);
            if (shared) v.u = v.v = 0;
            vertices[id] = v;
        }
        return true;
    }

    // run_shape's vertices for a base triangle without PN-AEN: surface_vertex's values in batches, the
    // skipped shared points left out.
    void write_triangle_points(const WeldShape& s, const std::uint32_t* ids, std::span<TessVertex> vertices) {
        std::size_t j = 0;
        while (j < s.eval_id.size()) {
            std::size_t count = 0;
            for (; j < s.eval_id.size() && count < TrianglePointBatch::size; ++j) {
                const std::uint32_t local = s.eval_id[j];
                const bool on_edge = local < s.interior_base; // a corner or an edge point
                if (on_edge && written_ != nullptr) {
                    if (!take(ids[local])) continue;
                    mark(ids[local]);
                }
                batch_.base(count) = s.eval_point[j];
                batch_id_[count] = ids[local];
                batch_shared_[count] = on_edge;
                ++count;
            }
            batch_.evaluate(corner_, surface_, count);
            for (std::size_t k = 0; k < count; ++k)
                vertices[batch_id_[k]] =
                    tess_vertex(batch_shared_[k] ? DomainPoint{0, 0} : batch_.base(k), batch_.point(k));
        }
    }

    // Any patch, slot by slot: corners by mesh index, edge points by a binary search of their edge and the
    // rank of their parameter, interior points collected and sorted. Within the patch every slot writes
    // (the last one wins, as in the forward loop); the marks of its shared points are set afterwards.
    bool run_general(const WeldTriangle (&tri)[2], unsigned n, std::uint32_t first_vertex, Counts& counts,
                     std::span<TessVertex> vertices, std::uint32_t* indices) {
        // Pass 1: corners and edge points directly, interior points collected and ranked.
        std::uint32_t offset[2] = {0, 0}, total = 0;
        inner_.clear();
        // Each half's pattern once per run: the split and D3D11 patterns generate their whole output.
        std::optional<typename F::patch_type> patches[2];
        for (unsigned h = 0; h < n; ++h) {
            const WeldTriangle& t = tri[h];
            const typename F::patch_type& patch = patches[h].emplace(family_.welded_patch(t.rec));
            const Counts c = patch.counts();
            offset[h] = total;
            total += c.vertices;
            if (map_.size() < total) map_.resize(total);
            for (unsigned k = 0; k < 3; ++k) {
                const std::uint32_t a = t.corner[(k + 1) % 3], b = t.corner[(k + 2) % 3];
                edge_first_[k] = 0;
                if (t.inner_e1 && k == 0) continue;
                const WeldedEdge* edge = find_edge(a, b);
                if (edge == nullptr) return false;
                family_.edge_params(mesh_edge_factor(mesh_, a, b, options_), params_[k]);
                if (params_[k].count != edge->vertex_count) return false;
                edge_first_[k] = edge->first_vertex;
            }
            for (std::uint32_t i = 0; i < c.vertices; ++i) {
                const DomainPoint base = family_.base_point(patch, t.rec, i);
                const std::uint32_t w[3] = {one - base.u - base.v, base.u, base.v};
                const SlotPlace place = slot_place(w, t.inner_e1);
                const unsigned k = place.edge;
                if (place.corner < 3) {
                    map_[offset[h] + i] = t.corner[place.corner];
                } else if (k < 3) {
                    const unsigned i1 = (k + 1) % 3, i2 = (k + 2) % 3;
                    // The parameter from the lower mesh index (the set is symmetric, so either end will do).
                    const std::uint32_t x = t.corner[i1] <= t.corner[i2] ? w[i2] : w[i1];
                    const unsigned r = params_[k].rank(x);
                    if (r == params_[k].count) return false;
                    map_[offset[h] + i] = edge_first_[k] + r;
                } else {
                    const DomainPoint d = n == 1 ? base : cp::quad_point(t.half, base);
                    inner_.push_back({std::uint64_t{d.u} << 32 | d.v, offset[h] + i});
                }
            }
        }
        counts.vertices = rank_interior(first_vertex);
        // Pass 2: the vertices (when asked) and the kept triangles.
        for (unsigned h = 0; h < n; ++h) {
            const WeldTriangle& t = tri[h];
            const typename F::patch_type& patch = *patches[h];
            const Counts c = patch.counts();
            const std::uint32_t* map = map_.data() + offset[h];
            if (!vertices.empty()) {
                for (std::uint32_t i = 0; i < c.vertices; ++i) {
                    if (map[i] < first_vertex && written_ != nullptr && !take(map[i])) continue;
                    const DomainPoint base = family_.base_point(patch, t.rec, i);
                    TessVertex v = evaluate(n, n == 1 ? base : cp::quad_point(t.half, base));
                    if (map[i] < first_vertex) v.u = v.v = 0; // a corner or an edge point
                    vertices[map[i]] = v;
                }
            }
            for (std::uint32_t k = 0; k < c.triangles; ++k) {
                const std::array<std::uint32_t, 3> local = patch.triangle(k);
                const std::uint32_t a = map[local[0]], b = map[local[1]], d = map[local[2]];
                if (!options_.weld.keep_degenerate && (a == b || b == d || a == d)) continue;
                if (indices != nullptr) {
                    indices[3 * std::size_t{counts.triangles}] = a;
                    indices[3 * std::size_t{counts.triangles} + 1] = b;
                    indices[3 * std::size_t{counts.triangles} + 2] = d;
                }
                ++counts.triangles;
            }
        }
        if (!vertices.empty() && written_ != nullptr)
            for (std::uint32_t j = 0; j < total; ++j)
                if (map_[j] < first_vertex) mark(map_[j]);
        return true;
    }

    // Numbers the collected interior points by rank of their domain point, from first (equal points, such as
    // a quad's diagonal seen from both halves, get one id); returns how many distinct points there are.
    std::uint32_t rank_interior(std::uint32_t first) {
        std::sort(inner_.begin(), inner_.end());
        std::uint32_t distinct = 0;
        for (std::size_t j = 0; j < inner_.size(); ++j) {
            if (j > 0 && inner_[j].point != inner_[j - 1].point) ++distinct;
            map_[inner_[j].slot] = first + distinct;
        }
        return inner_.empty() ? 0 : distinct + 1;
    }

    struct Inner {
        std::uint64_t point; // u << 32 | v: the patch's domain (a quad's unit square)
        std::uint32_t slot;  // offset of the half + its vertex
        friend bool operator<(const Inner& a, const Inner& b) {
            return a.point != b.point ? a.point < b.point : a.slot < b.slot;
        }
    };
    static constexpr std::uint32_t none = 0xFFFFFFFFu;
    const F& family_;
    const MeshView& mesh_;
    const PipelineOptions& options_;
    std::span<const WeldedEdge> edges_;
    std::vector<WeldShape> shapes_;
    std::vector<std::uint32_t> edge_start_; // vertex v: its first edge with lo = v (vertex_count + 1 entries)
    std::vector<std::uint32_t> map_;        // slot -> id (general) or local id (build_shape)
    std::vector<Inner> inner_;
    std::vector<DomainPoint> slot_point_; // build_shape: each slot's domain point
    std::vector<std::uint32_t> seen_;     // build_shape: local id -> its eval entry
    std::vector<std::uint32_t> ids_;      // run_shape: local id -> output id
    // write_triangle_points' batch: each point's output id, and whether it is a corner or an edge point.
    TrianglePointBatch batch_;
    std::array<std::uint32_t, TrianglePointBatch::size> batch_id_{};
    std::array<bool, TrianglePointBatch::size> batch_shared_{};
    EdgeParams params_[4];
    std::uint32_t edge_first_[3] = {};
    std::uint64_t* written_ = nullptr;
    // The patch being written: its corners and surface (run sets them when vertices is not empty).
    SurfaceCorner corner_[3];
    SurfaceCorner q_[4];
    PatchSurface surface_;
};

// The mesh edges of patch p (3 or 4; none when culled).
unsigned patch_edges(const MeshView& mesh, std::uint32_t p, WeldedEdge (&out)[4]) {
    if (patch_culled(mesh, p)) return 0;
    if (p < mesh.triangle_count) {
        std::uint32_t w[3];
        base_triangle(mesh, p, w);
        for (unsigned k = 0; k < 3; ++k) out[k] = edge_key(w[k], w[(k + 1) % 3]);
        return 3;
    }
    std::uint32_t w[4];
    base_quad(mesh, p - mesh.triangle_count, w);
    for (unsigned k = 0; k < 4; ++k) out[k] = edge_key(w[k], w[(k + 1) % 4]);
    return 4;
}

} // namespace

std::uint32_t weld_edge_list(const MeshView& mesh, std::span<WeldedEdge> edges) {
    if (edges.size() < weld_edge_capacity(mesh) ||
        check_pipeline_size(mesh.patch_count(), 0, 0) != PipelineStatus::ok)
        return 0;
    const auto count = static_cast<std::uint32_t>(mesh.patch_count());
    std::size_t n = 0;
    for (std::uint32_t p = 0; p < count; ++p) {
        WeldedEdge e[4];
        const unsigned m = patch_edges(mesh, p, e);
        for (unsigned k = 0; k < m; ++k) edges[n++] = e[k];
    }
    std::sort(edges.begin(), edges.begin() + static_cast<std::ptrdiff_t>(n), edge_less);
    return static_cast<std::uint32_t>(
        std::unique(edges.begin(), edges.begin() + static_cast<std::ptrdiff_t>(n),
                    [](const WeldedEdge& a, const WeldedEdge& b) { return a.lo == b.lo && a.hi == b.hi; }) -
        edges.begin());
}

namespace {

template <PipelineFamily F>
PipelineStatus setup_welded_all(const F& family, const MeshView& mesh, const PipelineOptions& options,
                                std::span<WeldedEdge> edges, std::span<WeldedPatch> patches,
                                WeldedTotals& totals) {
    if (const PipelineStatus s = check_pipeline_size(mesh.patch_count(), mesh.vertex_count, 0);
        s != PipelineStatus::ok)
        return s;
    const auto count = static_cast<std::uint32_t>(mesh.patch_count());
    // The distinct edges, sorted by their vertex indices, numbered by prefix sums after the mesh's vertices.
    // The unwelded counts first (counted, never emitted), checked against the limits as they add up: the weld
    // below generates every patch's pattern, so a mesh too large for the pipeline is refused before any is.
    std::uint32_t clamped = 0;
    std::uint64_t unwelded_vertices = 0, unwelded_triangles = 0;
    for (std::uint32_t p = 0; p < count; ++p) {
        const PatchRecord rec = setup_record(family, mesh, p, options, clamped);
        unwelded_vertices += rec.vertex_count;
        unwelded_triangles += rec.triangle_count;
        if (const PipelineStatus s = check_pipeline_size(0, unwelded_vertices, unwelded_triangles);
            s != PipelineStatus::ok)
            return s;
    }
    const std::size_t n = weld_edge_list(mesh, edges);
    std::uint64_t vertices = mesh.vertex_count, triangles = 0;
    EdgeParams params;
    for (std::size_t i = 0; i < n; ++i) {
        family.edge_params(mesh_edge_factor(mesh, edges[i].lo, edges[i].hi, options), params);
        edges[i].first_vertex = static_cast<std::uint32_t>(vertices);
        edges[i].vertex_count = params.count;
        vertices += params.count;
        if (const PipelineStatus s = check_pipeline_size(0, vertices, 0); s != PipelineStatus::ok) return s;
    }
    // Interior ids only need to be distinct from the corners and edge points while counting.
    PatchWeld<F> weld(family, mesh, options, edges.first(n));
    for (std::uint32_t p = 0; p < count; ++p) {
        Counts c;
        if (!weld.run(p, static_cast<std::uint32_t>(vertices), c, {}, nullptr))
            return PipelineStatus::bad_patch_record;
        patches[p] = {static_cast<std::uint32_t>(vertices), c.vertices, static_cast<std::uint32_t>(triangles),
                      c.triangles};
        vertices += c.vertices;
        triangles += c.triangles;
        if (const PipelineStatus s = check_pipeline_size(0, vertices, triangles); s != PipelineStatus::ok)
            return s;
    }
    totals = {static_cast<std::uint32_t>(vertices), static_cast<std::uint32_t>(triangles),
              static_cast<std::uint32_t>(n), clamped};
    return PipelineStatus::ok;
}

template <PipelineFamily F>
PipelineStatus emit_welded_all(const F& family, const MeshView& mesh, const PipelineOptions& options,
                               std::span<const WeldedEdge> edges, std::span<const WeldedPatch> patches,
                               std::optional<WeldedRange> part, std::span<TessVertex> vertices,
                               std::span<std::uint32_t> indices) {
    if (const PipelineStatus s = check_pipeline_size(mesh.patch_count(), mesh.vertex_count, 0);
        s != PipelineStatus::ok)
        return s;
    const auto count = static_cast<std::uint32_t>(mesh.patch_count());
    // A mesh without patches has no ranges: every one would be {0, 0} and write the same vertices.
    if (part && (part->first_patch > part->end_patch || part->end_patch > count || count == 0))
        return PipelineStatus::bad_range;
    const WeldedRange range = part.value_or(WeldedRange{0, count});
    // The edge list: sorted, distinct, inside the mesh, numbered by prefix sums with its lines' counts.
    std::uint64_t vertices_sum = mesh.vertex_count, triangle_sum = 0;
    EdgeParams params;
    for (std::size_t i = 0; i < edges.size(); ++i) {
        const WeldedEdge& e = edges[i];
        if (e.lo > e.hi || e.hi >= mesh.vertex_count || (i > 0 && !edge_less(edges[i - 1], e)) ||
            e.first_vertex != vertices_sum)
            return PipelineStatus::bad_patch_record;
        family.edge_params(mesh_edge_factor(mesh, e.lo, e.hi, options), params);
        if (e.vertex_count != params.count) return PipelineStatus::bad_patch_record;
        vertices_sum += e.vertex_count;
        if (check_pipeline_size(0, vertices_sum, 0) != PipelineStatus::ok)
            return PipelineStatus::bad_patch_record;
    }
    const std::uint64_t edge_vertices = vertices_sum - mesh.vertex_count;
    // The patch records: every offset at the prefix sums (so that ranges never overlap), the range's own
    // counts as run here.
    PatchWeld<F> weld(family, mesh, options, edges);
    for (std::uint32_t p = 0; p < count; ++p) {
        const WeldedPatch& wp = patches[p];
        if (wp.first_vertex != vertices_sum || wp.first_triangle != triangle_sum)
            return PipelineStatus::bad_patch_record;
        Counts c;
        if (p >= range.first_patch && p < range.end_patch &&
            (!weld.run(p, wp.first_vertex, c, {}, nullptr) || c.vertices != wp.vertex_count ||
             c.triangles != wp.triangle_count))
            return PipelineStatus::bad_patch_record;
        vertices_sum += wp.vertex_count;
        triangle_sum += wp.triangle_count;
        if (check_pipeline_size(0, vertices_sum, triangle_sum) != PipelineStatus::ok)
            return PipelineStatus::bad_patch_record;
    }
    if (vertices_sum > vertices.size() || 3 * triangle_sum > indices.size())
        return PipelineStatus::span_too_small;
    // The patches last to first: each corner and edge point is written once, by the last patch that reaches
    // it (the value the forward order leaves), marked in one bit per id below the patches' interiors. The
    // points that patches after the range reach are marked first: their last patch is not in the range.
    const std::uint64_t shared_ids = mesh.vertex_count + std::uint64_t{edge_vertices};
    std::vector<std::uint64_t> written((shared_ids + 63) / 64);
    weld.set_written(written.data());
    for (std::uint32_t p = range.end_patch; p < count; ++p)
        if (!weld.mark_reached(p)) return PipelineStatus::bad_patch_record; // an edge missing from the list
    for (std::uint32_t p = range.end_patch; p-- > range.first_patch;) {
        Counts c;
        weld.run(p, patches[p].first_vertex, c, vertices,
                 indices.data() + 3 * std::size_t{patches[p].first_triangle});
    }
    // The range of the last patch (or the whole call) writes the mesh vertices no face reaches, once the
    // faces before it are marked too.
    if (part && (range.end_patch != count || range.first_patch == count)) return PipelineStatus::ok;
    for (std::uint32_t p = 0; p < range.first_patch; ++p) weld.mark_corners(p);
    // Every mesh vertex no face reaches is output vertex v: its corner value.
    for (std::uint32_t v = 0; v < mesh.vertex_count; ++v) {
        if ((written[v / 64] >> (v % 64) & 1u) != 0) continue;
        const SurfaceCorner c[3] = {mesh_corner(mesh, v), mesh_corner(mesh, v), mesh_corner(mesh, v)};
        PatchSurface corner_surface{options.surface};
        if (options.displacement != nullptr) {
            // No face: the dominant vertex by position id.
            const std::uint32_t w[3] = {v, v, v};
            const MeshView own{mesh.vertices, mesh.vertex_count, nullptr, 0, nullptr, 0, mesh.position_ids};
            corner_surface.displace = displacement_patch(*options.displacement, own, 3, w, PatchFaces{});
        }
        vertices[v] = surface_vertex(c, DomainPoint{0, 0}, corner_surface);
    }
    return PipelineStatus::ok;
}

PipelineStatus setup_welded(const CpTableSet& tables, const UniformTableSet* uniform, const MeshView& mesh,
                            const PipelineOptions& options, std::span<WeldedEdge> edges,
                            std::span<WeldedPatch> patches, WeldedTotals& totals) {
    if (patches.size() < mesh.patch_count() || edges.size() < weld_edge_capacity(mesh))
        return PipelineStatus::span_too_small;
    if (const PipelineStatus s = check_options(uniform, options); s != PipelineStatus::ok) return s;
    return with_family(tables, uniform, options, [&](const auto& family) {
        return setup_welded_all(family, mesh, options, edges, patches, totals);
    });
}

PipelineStatus emit_welded_mesh(const CpTableSet& tables, const UniformTableSet* uniform,
                                const MeshView& mesh, const PipelineOptions& options,
                                std::span<const WeldedEdge> edges, std::span<const WeldedPatch> patches,
                                std::optional<WeldedRange> range, std::span<TessVertex> vertices,
                                std::span<std::uint32_t> indices) {
    if (patches.size() < mesh.patch_count()) return PipelineStatus::span_too_small;
    if (const PipelineStatus s = check_options(uniform, options); s != PipelineStatus::ok) return s;
    return with_family(tables, uniform, options, [&](const auto& family) {
        return emit_welded_all(family, mesh, options, edges, patches, range, vertices, indices);
    });
}

} // namespace

PatchRecord setup_patch(const CpTableSet& tables, const MeshView& mesh, std::uint32_t p,
                        const PipelineOptions& options) {
    std::uint32_t clamped = 0;
    return setup_record(CpFamily{tables}, mesh, p, options, clamped);
}

PatchRecord setup_uniform_patch(const UniformTableSet& tables, const MeshView& mesh, std::uint32_t p,
                                const PipelineOptions& options) {
    std::uint32_t clamped = 0;
    return setup_record(UniformFamily{tables}, mesh, p, options, clamped);
}

PipelineStatus setup_patches(const CpTableSet& tables, const MeshView& mesh, const PipelineOptions& options,
                             std::span<PatchRecord> patches, PipelineTotals& totals) {
    return setup_patches(tables, nullptr, mesh, options, patches, totals);
}

PipelineStatus setup_patches(const CpTableSet& tables, const UniformTableSet& uniform, const MeshView& mesh,
                             const PipelineOptions& options, std::span<PatchRecord> patches,
                             PipelineTotals& totals) {
    return setup_patches(tables, &uniform, mesh, options, patches, totals);
}

TessVertex patch_vertex(const CpPatch& patch, const PatchRecord& rec, const SurfaceCorner (&corner)[3],
                        std::uint32_t i, const SurfaceOptions& surface) {
    return surface_vertex(corner, CpFamily::base_point(patch, rec, i), PatchSurface{surface});
}

PipelineStatus emit_mesh(const CpTableSet& tables, const MeshView& mesh, const PipelineOptions& options,
                         std::span<const PatchRecord> patches, std::span<TessVertex> vertices,
                         std::span<std::uint32_t> indices) {
    return emit_mesh(tables, nullptr, mesh, options, patches, vertices, indices, false);
}

PipelineStatus emit_mesh(const CpTableSet& tables, const UniformTableSet& uniform, const MeshView& mesh,
                         const PipelineOptions& options, std::span<const PatchRecord> patches,
                         std::span<TessVertex> vertices, std::span<std::uint32_t> indices) {
    return emit_mesh(tables, &uniform, mesh, options, patches, vertices, indices, false);
}

PipelineStatus emit_mesh_range(const CpTableSet& tables, const MeshView& range,
                               const PipelineOptions& options, std::span<const PatchRecord> patches,
                               std::span<TessVertex> vertices, std::span<std::uint32_t> indices) {
    return emit_mesh(tables, nullptr, range, options, patches, vertices, indices, true);
}

PipelineStatus emit_mesh_range(const CpTableSet& tables, const UniformTableSet& uniform,
                               const MeshView& range, const PipelineOptions& options,
                               std::span<const PatchRecord> patches, std::span<TessVertex> vertices,
                               std::span<std::uint32_t> indices) {
    return emit_mesh(tables, &uniform, range, options, patches, vertices, indices, true);
}

PipelineStatus setup_welded(const CpTableSet& tables, const MeshView& mesh, const PipelineOptions& options,
                            std::span<WeldedEdge> edges, std::span<WeldedPatch> patches,
                            WeldedTotals& totals) {
    return setup_welded(tables, nullptr, mesh, options, edges, patches, totals);
}

PipelineStatus setup_welded(const CpTableSet& tables, const UniformTableSet& uniform, const MeshView& mesh,
                            const PipelineOptions& options, std::span<WeldedEdge> edges,
                            std::span<WeldedPatch> patches, WeldedTotals& totals) {
    return setup_welded(tables, &uniform, mesh, options, edges, patches, totals);
}

PipelineStatus emit_welded_mesh(const CpTableSet& tables, const MeshView& mesh,
                                const PipelineOptions& options, std::span<const WeldedEdge> edges,
                                std::span<const WeldedPatch> patches, std::span<TessVertex> vertices,
                                std::span<std::uint32_t> indices) {
    return emit_welded_mesh(tables, nullptr, mesh, options, edges, patches, std::nullopt, vertices, indices);
}

PipelineStatus emit_welded_mesh(const CpTableSet& tables, const UniformTableSet& uniform,
                                const MeshView& mesh, const PipelineOptions& options,
                                std::span<const WeldedEdge> edges, std::span<const WeldedPatch> patches,
                                std::span<TessVertex> vertices, std::span<std::uint32_t> indices) {
    return emit_welded_mesh(tables, &uniform, mesh, options, edges, patches, std::nullopt, vertices, indices);
}

PipelineStatus emit_welded_mesh(const CpTableSet& tables, const MeshView& mesh,
                                const PipelineOptions& options, std::span<const WeldedEdge> edges,
                                std::span<const WeldedPatch> patches, WeldedRange range,
                                std::span<TessVertex> vertices, std::span<std::uint32_t> indices) {
    return emit_welded_mesh(tables, nullptr, mesh, options, edges, patches, range, vertices, indices);
}

PipelineStatus emit_welded_mesh(const CpTableSet& tables, const UniformTableSet& uniform,
                                const MeshView& mesh, const PipelineOptions& options,
                                std::span<const WeldedEdge> edges, std::span<const WeldedPatch> patches,
                                WeldedRange range, std::span<TessVertex> vertices,
                                std::span<std::uint32_t> indices) {
    return emit_welded_mesh(tables, &uniform, mesh, options, edges, patches, range, vertices, indices);
}

WeldedRange welded_range(const MeshView& mesh, std::span<const WeldedPatch> patches, std::uint32_t part,
                         std::uint32_t parts) {
    parts = parts == 0 ? 1 : parts;
    part = part < parts ? part : parts;
    const auto count = static_cast<std::uint32_t>(
        std::min<std::uint64_t>({patches.size(), mesh.patch_count(), std::uint64_t{0xFFFFFFFFu}}));
    const std::uint64_t total =
        count == 0 ? 0 : std::uint64_t{patches[count - 1].first_triangle} + patches[count - 1].triangle_count;
    // The first patch at or past part k's share of the triangles: a bisection that stays inside the span
    // whatever the records hold (a bad list gives some range, which emit_welded_mesh's checks refuse).
    const auto boundary = [&](std::uint32_t k) -> std::uint32_t {
        if (k == 0) return 0;
        if (k >= parts) return count;
        const std::uint64_t target = total * k / parts;
        std::uint32_t lo = 0, hi = count;
        while (lo < hi) {
            const std::uint32_t mid = lo + (hi - lo) / 2;
            if (patches[mid].first_triangle < target)
                lo = mid + 1;
            else
                hi = mid;
        }
        return lo;
    };
    const std::uint32_t first = boundary(part), end = boundary(part + 1);
    return {first, end > first ? end : first};
}

} // namespace ctess::rt
