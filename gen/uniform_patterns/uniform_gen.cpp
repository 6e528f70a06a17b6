// Offline generator of the uniform-density pattern data (docs/algorithm.md §3): for every
// sorted factor triple a >= b >= c in [1, N] the fewest triangles whose longest edge, in the intrinsic metric
// with the factors as edge lengths, stays short. Writes constexpr/ctess/uniform/patterns_data.hpp.
//
// Deterministic: fixed processing orders, no randomness, no threads; the same compiler and flags give the
// same bytes (a ctest regenerates the data and compares).
//
//   uniform_gen [--max N] [--out FILE] [--stats]   (writes the data)
//   uniform_gen --check K                          (regenerates the triples with f0 <= K and compares)
//
// Method per triple: (1) a dynamic-programming min-max triangulation of the boundary polygon (the only
// candidate for non-Euclidean triples a >= b + c); (2) Euclidean triples: triangular lattice starts inserted
// with Delaunay flips, minimax polish (each interior vertex to the centre of the smallest circle around its
// neighbours, shorter-diagonal flips), then decimation one vertex at a time, recording the longest edge for
// every interior count; (3) a global knapsack over the interior-vertex budget minimises the triangle count
// under the longest-edge bounds; (n, n, n) is always the regular grid.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include <ctess/analysis/signed_area.hpp>
#include <ctess/uniform/pattern.hpp>
#include <ctess/uniform/quantise.hpp>

namespace {

constexpr int quant_one = int(ctess::uniform::fixed_one); // Karis 2026: 1.0 = 65534 so 0.5 is exact
constexpr double pi = 3.14159265358979323846;

struct V2 {
    double x = 0, y = 0;
};
V2 operator-(V2 a, V2 b) {
    return {a.x - b.x, a.y - b.y};
}
V2 operator+(V2 a, V2 b) {
    return {a.x + b.x, a.y + b.y};
}
V2 operator*(double s, V2 a) {
    return {s * a.x, s * a.y};
}
double cross(V2 a, V2 b) {
    return a.x * b.y - a.y * b.x;
}
double dot(V2 a, V2 b) {
    return a.x * b.x + a.y * b.y;
}
// Twice the signed area of a, b, c: positive counter-clockwise.
using ctess::analysis::signed_area2;
double dist(V2 a, V2 b) {
    return std::sqrt(dot(a - b, a - b));
}

using Tri = std::array<int, 3>;

struct Triple {
    int f0, f1, f2; // factors of e0 (v = 0), e1 (u + v = 1), e2 (u = 0); f0 >= f1 >= f2
};

// Barycentric (u, v) of the domain; corners v0 = (0, 0), v1 = (1, 0), v2 = (0, 1).
struct Bary {
    double u = 0, v = 0;
};

// Intrinsic squared length of the barycentric vector q - p (clamped at 0 for non-Euclidean triples).
double intrinsic_len(const Triple& t, Bary p, Bary q) {
    const double du = q.u - p.u, dv = q.v - p.v, dw = -du - dv;
    const double a2 = double(t.f2) * t.f2, b2 = double(t.f0) * t.f0, c2 = double(t.f1) * t.f1;
    const double s = -a2 * dv * dw - b2 * dw * du - c2 * du * dv;
    return s > 0 ? std::sqrt(s) : 0.0;
}

// The boundary in canonical order (counter-clockwise): v0, e0 interior points, v1, e1 points, v2, e2 points
// back to v0. side: bit 0 on e0, bit 1 on e1, bit 2 on e2.
struct Boundary {
    std::vector<Bary> bary;
    std::vector<unsigned> side;
};

Boundary make_boundary(const Triple& t) {
    Boundary b;
    b.bary.push_back({0, 0});
    b.side.push_back(1u | 4u);
    for (int i = 1; i < t.f0; ++i) b.bary.push_back({double(i) / t.f0, 0}), b.side.push_back(1u);
    b.bary.push_back({1, 0});
    b.side.push_back(1u | 2u);
    for (int i = 1; i < t.f1; ++i)
        b.bary.push_back({1 - double(i) / t.f1, double(i) / t.f1}), b.side.push_back(2u);
    b.bary.push_back({0, 1});
    b.side.push_back(2u | 4u);
    for (int i = 1; i < t.f2; ++i) b.bary.push_back({0, 1 - double(i) / t.f2}), b.side.push_back(4u);
    return b;
}

// DP over the boundary polygon: minimise the longest edge, then the sum of squared lengths under it.
// Triangles with all three vertices on one domain edge are forbidden (zero area).
std::vector<Tri> dp_triangulation(const Triple& t, const Boundary& b) {
    const int n = int(b.bary.size());
    const double inf = 1e300;
    auto len = [&](int i, int j) { return intrinsic_len(t, b.bary[i], b.bary[j]); };
    auto valid = [&](int i, int k, int j) { return (b.side[i] & b.side[k] & b.side[j]) == 0; };
    std::vector<double> cost(n * n, inf), sum(n * n, inf);
    std::vector<int> pick(n * n, -1);
    for (int i = 0; i + 1 < n; ++i) cost[i * n + i + 1] = 0, sum[i * n + i + 1] = 0;
    for (int span = 2; span < n; ++span)
        for (int i = 0; i + span < n; ++i) {
            const int j = i + span;
            for (int k = i + 1; k < j; ++k) {
                if (!valid(i, k, j)) continue;
                const double c = std::max({cost[i * n + k], cost[k * n + j], len(i, k), len(k, j)});
                if (c < cost[i * n + j]) cost[i * n + j] = c;
            }
        }
    double limit = std::max(cost[0 * n + n - 1], len(0, n - 1)) + 1e-12;
    // Second pass: minimum sum of squared lengths with every edge within the limit.
    for (int span = 2; span < n; ++span)
        for (int i = 0; i + span < n; ++i) {
            const int j = i + span;
            for (int k = i + 1; k < j; ++k) {
                if (!valid(i, k, j)) continue;
                const double li = len(i, k), lj = len(k, j);
                if (li > limit || lj > limit) continue;
                const double s = sum[i * n + k] + sum[k * n + j] + li * li + lj * lj;
                if (s < sum[i * n + j]) sum[i * n + j] = s, pick[i * n + j] = k;
            }
        }
    std::vector<Tri> tris;
    std::vector<std::pair<int, int>> stack{{0, n - 1}};
    while (!stack.empty()) {
        auto [i, j] = stack.back();
        stack.pop_back();
        if (j - i < 2) continue;
        const int k = pick[i * n + j];
        if (k < 0) {
            std::fprintf(stderr, "dp failed\n");
            std::exit(1);
        }
        tris.push_back({i, k, j});
        stack.push_back({i, k});
        stack.push_back({k, j});
    }
    return tris;
}

// --- Euclidean meshes in a 2D embedding ---------------------------------------------------------------

struct Mesh {
    std::vector<V2> p;
    int nb = 0; // the first nb vertices are the boundary, fixed
    std::vector<Tri> t;
};

struct Embedding {
    V2 c0, c1, c2;
    V2 to2d(Bary b) const { return c0 + b.u * (c1 - c0) + b.v * (c2 - c0); }
    Bary to_bary(V2 q) const {
        const V2 e1 = c1 - c0, e2 = c2 - c0, d = q - c0;
        const double det = cross(e1, e2);
        return {cross(d, e2) / det, cross(e1, d) / det};
    }
};

bool euclidean(const Triple& t) {
    return t.f0 < t.f1 + t.f2;
}

Embedding embed(const Triple& t) {
    const double a = t.f0, b = t.f1, c = t.f2; // |v0 v1| = f0, |v1 v2| = f1, |v0 v2| = f2
    const double x = (a * a + c * c - b * b) / (2 * a);
    return {{0, 0}, {a, 0}, {x, std::sqrt(std::max(0.0, c * c - x * x))}};
}

double tri_min_angle(V2 a, V2 b, V2 c) {
    const double la = dist(b, c), lb = dist(a, c), lc = dist(a, b);
    if (la <= 0 || lb <= 0 || lc <= 0) return 0;
    const double area2 = std::fabs(signed_area2(a, b, c));
    // sin of each angle = area2 / (product of adjacent sides); the smallest angle is opposite the shortest
    // side
    const double m = std::min({la, lb, lc});
    const double s = m == la ? area2 / (lb * lc) : m == lb ? area2 / (la * lc) : area2 / (la * lb);
    return std::asin(std::min(1.0, s));
}

// Vertex -> incident triangles.
std::vector<std::vector<int>> incidence(const Mesh& m) {
    std::vector<std::vector<int>> inc(m.p.size());
    for (int i = 0; i < int(m.t.size()); ++i)
        for (int k = 0; k < 3; ++k) inc[m.t[i][k]].push_back(i);
    return inc;
}

// Edge (ordered a < b) -> the two triangles; -1 on the boundary.
std::map<std::pair<int, int>, std::array<int, 2>> edge_map(const Mesh& m) {
    std::map<std::pair<int, int>, std::array<int, 2>> e;
    for (int i = 0; i < int(m.t.size()); ++i)
        for (int k = 0; k < 3; ++k) {
            int a = m.t[i][k], b = m.t[i][(k + 1) % 3];
            auto key = std::make_pair(std::min(a, b), std::max(a, b));
            auto it = e.find(key);
            if (it == e.end())
                e[key] = {i, -1};
            else
                it->second[1] = i;
        }
    return e;
}

int opposite(const Tri& t, int a, int b) {
    for (int k = 0; k < 3; ++k)
        if (t[k] != a && t[k] != b) return t[k];
    return -1;
}

bool in_circle(V2 a, V2 b, V2 c, V2 d) {
    const double adx = a.x - d.x, ady = a.y - d.y, bdx = b.x - d.x, bdy = b.y - d.y, cdx = c.x - d.x,
                 cdy = c.y - d.y;
    const double det = (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) -
                       (bdx * bdx + bdy * bdy) * (adx * cdy - cdx * ady) +
                       (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
    return det > 1e-9;
}

// Flip passes. delaunay: the incircle test; otherwise flip to the strictly shorter diagonal.
void flip_edges(Mesh& m, bool delaunay, double min_angle) {
    for (int pass = 0; pass < 200; ++pass) {
        bool changed = false;
        auto edges = edge_map(m);
        std::vector<char> touched(m.t.size(), 0);
        for (const auto& [key, tr] : edges) {
            if (tr[1] < 0 || touched[tr[0]] || touched[tr[1]]) continue;
            const Tri t1 = m.t[tr[0]], t2 = m.t[tr[1]];
            // orient the edge as it appears in t1: (a, b) with c opposite
            int a = -1, b = -1;
            for (int k = 0; k < 3; ++k) {
                const int x = t1[k], y = t1[(k + 1) % 3];
                if (std::min(x, y) == key.first && std::max(x, y) == key.second) a = x, b = y;
            }
            const int c = opposite(t1, a, b), d = opposite(t2, a, b);
            const V2 pa = m.p[a], pb = m.p[b], pc = m.p[c], pd = m.p[d];
            if (signed_area2(pa, pd, pc) <= 1e-9 || signed_area2(pd, pb, pc) <= 1e-9) continue;
            bool flip = false;
            if (delaunay)
                flip = in_circle(pa, pb, pc, pd);
            else {
                flip = dist(pc, pd) < dist(pa, pb) - 1e-9 && tri_min_angle(pa, pd, pc) >= min_angle &&
                       tri_min_angle(pd, pb, pc) >= min_angle;
            }
            if (!flip) continue;
            m.t[tr[0]] = {a, d, c};
            m.t[tr[1]] = {d, b, c};
            touched[tr[0]] = touched[tr[1]] = 1;
            changed = true;
        }
        if (!changed) return;
    }
}

// Inserts q: a 1 -> 3 split inside a triangle or a 2 -> 4 split on an interior edge. False when q falls on
// the boundary or outside.
bool insert_point(Mesh& m, V2 q) {
    int best = -1;
    double best_min = -1e300;
    std::array<double, 3> best_w{};
    for (int i = 0; i < int(m.t.size()); ++i) {
        const V2 a = m.p[m.t[i][0]], b = m.p[m.t[i][1]], c = m.p[m.t[i][2]];
        const double area = signed_area2(a, b, c);
        const std::array<double, 3> w{signed_area2(b, c, q) / area, signed_area2(c, a, q) / area,
                                      signed_area2(a, b, q) / area};
        const double mn = std::min({w[0], w[1], w[2]});
        if (mn > best_min) best_min = mn, best = i, best_w = w;
    }
    if (best < 0 || best_min < -1e-9) return false;
    const int id = int(m.p.size());
    const Tri t = m.t[best];
    if (best_min > 1e-6) {
        m.p.push_back(q);
        m.t[best] = {t[0], t[1], id};
        m.t.push_back({t[1], t[2], id});
        m.t.push_back({t[2], t[0], id});
        return true;
    }
    // on the edge opposite the smallest weight
    int k = 0;
    for (int j = 1; j < 3; ++j)
        if (best_w[j] < best_w[k]) k = j;
    const int a = t[(k + 1) % 3], b = t[(k + 2) % 3], c = t[k];
    int other = -1;
    for (int i = 0; i < int(m.t.size()); ++i) {
        if (i == best) continue;
        const Tri& s = m.t[i];
        for (int j = 0; j < 3; ++j)
            if (s[j] == b && s[(j + 1) % 3] == a) other = i;
    }
    if (other < 0) return false;
    const int d = opposite(m.t[other], a, b);
    m.p.push_back(q);
    m.t[best] = {a, id, c};
    m.t.push_back({id, b, c});
    m.t[other] = {b, id, d};
    m.t.push_back({id, a, d});
    return true;
}

// Smallest enclosing circle of a few points (exhaustive over pairs and triples; rings are small).
V2 enclosing_centre(const std::vector<V2>& q) {
    V2 best{};
    double best_r = 1e300;
    auto covers = [&](V2 c, double r) {
        for (const V2& x : q)
            if (dist(c, x) > r + 1e-12) return false;
        return true;
    };
    const int n = int(q.size());
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j) {
            const V2 c = 0.5 * (q[i] + q[j]);
            const double r = dist(c, q[i]);
            if (r < best_r && covers(c, r)) best = c, best_r = r;
        }
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j)
            for (int k = j + 1; k < n; ++k) {
                const V2 a = q[i], b = q[j], c = q[k];
                const double d = 2 * (a.x * (b.y - c.y) + b.x * (c.y - a.y) + c.x * (a.y - b.y));
                if (std::fabs(d) < 1e-12) continue;
                const double a2 = dot(a, a), b2 = dot(b, b), c2 = dot(c, c);
                const V2 o{(a2 * (b.y - c.y) + b2 * (c.y - a.y) + c2 * (a.y - b.y)) / d,
                           (a2 * (c.x - b.x) + b2 * (a.x - c.x) + c2 * (b.x - a.x)) / d};
                const double r = dist(o, a);
                if (r < best_r && covers(o, r)) best = o, best_r = r;
            }
    return best;
}

constexpr double angle_guard = 15.0 * pi / 180.0;

// The neighbours of v, sorted.
std::vector<int> ring_of(const Mesh& m, const std::vector<std::vector<int>>& inc, int v) {
    std::vector<int> ring;
    for (int ti : inc[v])
        for (int k = 0; k < 3; ++k)
            if (m.t[ti][k] != v) ring.push_back(m.t[ti][k]);
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    return ring;
}

// Minimax polish: each interior vertex to the centre of the smallest circle around its neighbours, if every
// incident triangle stays positive and its smallest angle stays above min(15 degrees, the current one).
void polish(Mesh& m, int sweeps) {
    for (int s = 0; s < sweeps; ++s) {
        auto inc = incidence(m);
        bool moved = false;
        for (int v = m.nb; v < int(m.p.size()); ++v) {
            const std::vector<int> ring = ring_of(m, inc, v);
            std::vector<V2> q;
            for (int r : ring) q.push_back(m.p[r]);
            const V2 c = enclosing_centre(q);
            const V2 old = m.p[v];
            double cur_angle = pi, cur_len = 0;
            for (int ti : inc[v]) {
                const Tri& t = m.t[ti];
                cur_angle = std::min(cur_angle, tri_min_angle(m.p[t[0]], m.p[t[1]], m.p[t[2]]));
            }
            for (const V2& x : q) cur_len = std::max(cur_len, dist(old, x));
            const double guard = std::min(angle_guard, cur_angle);
            for (double step : {1.0, 0.5, 0.25}) {
                const V2 cand = old + step * (c - old);
                bool ok = true;
                double len = 0;
                for (const V2& x : q) len = std::max(len, dist(cand, x));
                if (len > cur_len - 1e-12) ok = false;
                m.p[v] = cand;
                for (int ti : inc[v]) {
                    const Tri& t = m.t[ti];
                    if (!ok) break;
                    if (signed_area2(m.p[t[0]], m.p[t[1]], m.p[t[2]]) <= 1e-9 ||
                        tri_min_angle(m.p[t[0]], m.p[t[1]], m.p[t[2]]) < guard)
                        ok = false;
                }
                if (ok) {
                    moved = true;
                    break;
                }
                m.p[v] = old;
            }
        }
        flip_edges(m, false, 5.0 * pi / 180.0);
        if (!moved) break;
    }
}

// Removes interior vertex v by collapsing it onto its neighbour n.
Mesh collapse(const Mesh& m, int v, int n) {
    Mesh r;
    r.nb = m.nb;
    for (int i = 0; i < int(m.p.size()); ++i)
        if (i != v) r.p.push_back(m.p[i]);
    auto remap = [&](int i) { return i == v ? (n > v ? n - 1 : n) : (i > v ? i - 1 : i); };
    for (const Tri& t : m.t) {
        if ((t[0] == v || t[1] == v || t[2] == v) && (t[0] == n || t[1] == n || t[2] == n)) continue;
        r.t.push_back({remap(t[0]), remap(t[1]), remap(t[2])});
    }
    return r;
}

// The best single collapse (shortest longest new edge) or false when none is valid.
bool best_collapse(const Mesh& m, int& out_v, int& out_n) {
    auto inc = incidence(m);
    double best = 1e300;
    bool found = false;
    for (int v = m.nb; v < int(m.p.size()); ++v) {
        const std::vector<int> ring = ring_of(m, inc, v);
        for (int n : ring) {
            // link condition: v and n share exactly two neighbours
            int common = 0;
            for (int ti : inc[n])
                for (int k = 0; k < 3; ++k) {
                    const int x = m.t[ti][k];
                    if (x != n && x != v && std::binary_search(ring.begin(), ring.end(), x)) ++common;
                }
            if (common != 4) continue; // each common neighbour is seen in two of n's triangles
            double len = 0;
            for (int x : ring)
                if (x != n) len = std::max(len, dist(m.p[n], m.p[x]));
            if (len >= best) continue;
            bool ok = true;
            for (int ti : inc[v]) {
                Tri t = m.t[ti];
                if (t[0] == n || t[1] == n || t[2] == n) continue;
                for (int& x : t)
                    if (x == v) x = n;
                if (signed_area2(m.p[t[0]], m.p[t[1]], m.p[t[2]]) <= 1e-9 ||
                    tri_min_angle(m.p[t[0]], m.p[t[1]], m.p[t[2]]) < 2.0 * pi / 180.0)
                    ok = false;
            }
            if (!ok) continue;
            best = len, out_v = v, out_n = n, found = true;
        }
    }
    return found;
}

// --- Candidates per triple -------------------------------------------------------------------------------

struct Pattern {
    std::vector<std::array<int, 2>> interior; // quantised (u, v)
    std::vector<Tri> tris;                    // canonical numbering: boundary, then interior
    double longest = 0;                       // after quantisation
};

int quantise_boundary(int i, int f) {
    return int(ctess::uniform::edge_parameter(unsigned(i), unsigned(f)));
}

std::vector<std::array<int, 2>> quantised_boundary(const Triple& t) {
    std::vector<std::array<int, 2>> b;
    b.push_back({0, 0});
    for (int i = 1; i < t.f0; ++i) b.push_back({quantise_boundary(i, t.f0), 0});
    b.push_back({quant_one, 0});
    for (int i = 1; i < t.f1; ++i) {
        const int v = quantise_boundary(i, t.f1);
        b.push_back({quant_one - v, v});
    }
    b.push_back({0, quant_one});
    for (int i = 1; i < t.f2; ++i) b.push_back({0, quantise_boundary(t.f2 - i, t.f2)});
    return b;
}

// Measures a quantised pattern: the longest intrinsic edge, or a negative value when a triangle has zero or
// negative area in the quantised (u, v) plane.
double measure(const Triple& t, const Pattern& p) {
    auto all = quantised_boundary(t);
    all.insert(all.end(), p.interior.begin(), p.interior.end());
    double longest = 0;
    for (const Tri& tr : p.tris) {
        const auto& a = all[tr[0]];
        const auto& b = all[tr[1]];
        const auto& c = all[tr[2]];
        const long long o =
            (long long)(b[0] - a[0]) * (c[1] - a[1]) - (long long)(b[1] - a[1]) * (c[0] - a[0]);
        if (o <= 0) return -1;
        for (int k = 0; k < 3; ++k) {
            const auto& x = all[tr[k]];
            const auto& y = all[tr[(k + 1) % 3]];
            longest = std::max(longest, intrinsic_len(t, {x[0] / double(quant_one), x[1] / double(quant_one)},
                                                      {y[0] / double(quant_one), y[1] / double(quant_one)}));
        }
    }
    return longest;
}

int quantise(double x) {
    const long q = std::lround(x * quant_one);
    return int(std::clamp<long>(q, 1, quant_one - 1));
}

Pattern from_mesh(const Triple& t, const Mesh& m, const Embedding& e) {
    Pattern p;
    for (int i = m.nb; i < int(m.p.size()); ++i) {
        const Bary b = e.to_bary(m.p[i]);
        p.interior.push_back({quantise(b.u), quantise(b.v)});
    }
    p.tris = m.t;
    p.longest = measure(t, p);
    return p;
}

Pattern regular_grid(const Triple& t) {
    const int n = t.f0;
    Pattern p;
    // grid (i, j): u = i / n, v = j / n; boundary ids from the canonical order
    auto id = [&](int i, int j) -> int {
        const int k = n - i - j;
        if (j == 0) return i;                                         // e0: v0 .. v1
        if (k == 0) return n + j;                                     // e1: v1 .. v2
        if (i == 0) return 2 * n + (n - j);                           // e2: v2 .. back to v0
        return 3 * n + (j - 1) * (n - 1) - (j - 1) * j / 2 + (i - 1); // interior, row by row
    };
    for (int j = 1; j < n; ++j)
        for (int i = 1; i + j < n; ++i) {
            p.interior.push_back(
                {int((2L * i * quant_one + n) / (2L * n)), int((2L * j * quant_one + n) / (2L * n))});
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i + j < n; ++i) {
            p.tris.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
            if (i + j + 2 <= n) p.tris.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    p.longest = measure(t, p);
    return p;
}

// All candidates of one triple: for each interior count, the one with the shortest longest edge.
std::map<int, Pattern> candidates(const Triple& t) {
    std::map<int, Pattern> best;
    auto offer = [&](Pattern&& p) {
        if (p.longest < 0) return;
        const int k = int(p.interior.size());
        auto it = best.find(k);
        if (it == best.end() || p.longest < it->second.longest - 1e-12) best[k] = std::move(p);
    };
    const Boundary b = make_boundary(t);
    {
        Pattern p;
        p.tris = dp_triangulation(t, b);
        p.longest = measure(t, p);
        offer(std::move(p));
    }
    if (!euclidean(t)) return best;
    if (t.f0 == t.f2) {
        offer(regular_grid(t));
        return best; // (n, n, n) is always the regular grid
    }
    const Embedding e = embed(t);
    Mesh base;
    for (const Bary& x : b.bary) base.p.push_back(e.to2d(x));
    base.nb = int(base.p.size());
    base.t = dp_triangulation(t, b);
    const V2 corners[3] = {e.c0, e.c1, e.c2};
    // Lattice starts: three orientations (along each edge), ten spacings (0.82 to 1.27), three distances kept
    // from the domain edges (in spacings). The closer margins find the sparser patterns.
    for (const double margin : {0.15, 0.25, 0.35})
        for (int edge = 0; edge < 3; ++edge)
            for (int sp = 0; sp < 10; ++sp) {
                const double s = 0.82 + 0.05 * sp;
                const V2 o = corners[edge], dir = corners[(edge + 1) % 3] - o;
                const V2 ex = (1.0 / dist(corners[(edge + 1) % 3], o)) * dir;
                const V2 ey{-ex.y, ex.x};
                const V2 l1 = s * ex, l2 = s * (0.5 * ex + (std::sqrt(3.0) / 2) * ey);
                Mesh m = base;
                const int span = t.f0 * 3 + 3;
                for (int j = 1; j <= span; ++j)
                    for (int i = -span; i <= span; ++i) {
                        const V2 q = o + double(i) * l1 + double(j) * l2;
                        // keep the margin from every domain edge
                        bool inside = true;
                        for (int k = 0; k < 3; ++k) {
                            const V2 a = corners[k], c = corners[(k + 1) % 3];
                            if (signed_area2(a, c, q) / dist(a, c) < margin * s) inside = false;
                        }
                        if (inside) insert_point(m, q);
                    }
                flip_edges(m, true, 0);
                polish(m, 30);
                offer(from_mesh(t, m, e));
                // decimate while the longest edge stays reasonable
                while (int(m.p.size()) > m.nb) {
                    int v = -1, n = -1;
                    if (!best_collapse(m, v, n)) break;
                    m = collapse(m, v, n);
                    flip_edges(m, false, 5.0 * pi / 180.0);
                    polish(m, 12);
                    const Pattern p = from_mesh(t, m, e);
                    if (p.longest > 1.8) break;
                    offer(Pattern(p));
                }
            }
    return best;
}

// Triangle order for the post-transform vertex cache: greedy over a 16-entry LRU cache (most cached corners
// first, then the corners with the fewest triangles left), then interior vertices renumbered by first use.
void order_for_cache(Pattern& p, int boundary_count) {
    const int nv = boundary_count + int(p.interior.size());
    std::vector<int> left(nv, 0);
    for (const Tri& t : p.tris)
        for (int x : t) ++left[x];
    std::vector<char> done(p.tris.size(), 0);
    std::vector<int> cache; // most recent first
    std::vector<Tri> out;
    while (out.size() < p.tris.size()) {
        int pick = -1;
        long best = -1;
        for (int i = 0; i < int(p.tris.size()); ++i) {
            if (done[i]) continue;
            long score = 0;
            for (int x : p.tris[i]) {
                const auto it = std::find(cache.begin(), cache.end(), x);
                if (it != cache.end()) score += 1000 + (16 - (it - cache.begin()));
                score += 40 / left[x];
            }
            if (score > best) best = score, pick = i;
        }
        done[pick] = 1;
        const Tri t = p.tris[pick];
        out.push_back(t);
        for (int x : t) {
            --left[x];
            cache.erase(std::remove(cache.begin(), cache.end(), x), cache.end());
            cache.insert(cache.begin(), x);
        }
        if (cache.size() > 16) cache.resize(16);
    }
    std::vector<int> remap(nv, -1);
    for (int i = 0; i < boundary_count; ++i) remap[i] = i;
    int next = boundary_count;
    for (const Tri& t : out)
        for (int x : t)
            if (remap[x] < 0) remap[x] = next++;
    std::vector<std::array<int, 2>> interior(p.interior.size());
    for (int i = 0; i < int(p.interior.size()); ++i)
        interior[remap[boundary_count + i] - boundary_count] = p.interior[i];
    p.interior = interior;
    for (Tri& t : out)
        for (int& x : t) x = remap[x];
    p.tris = out;
}

struct Option {
    int interior;
    double longest;
};

// The Pareto options of one triple (more interior vertices only when the longest edge gets shorter), capped.
std::vector<Option> pareto(const std::map<int, Pattern>& c, double cap) {
    std::vector<Option> all, out;
    for (const auto& [k, p] : c) all.push_back({k, p.longest});
    for (const Option& o : all) {
        if (!out.empty() && o.longest >= out.back().longest - 1e-12) continue;
        out.push_back(o);
    }
    std::vector<Option> capped;
    for (const Option& o : out)
        if (o.longest <= cap + 1e-9) capped.push_back(o);
    if (capped.empty()) capped.push_back(out.back());
    return capped;
}

// Exact knapsack: the fewest interior vertices in total with the sum of per-pattern maxima within
// max_sum. Returns the chosen interior count per pattern (empty when infeasible).
std::vector<int> knapsack(const std::vector<std::vector<Option>>& opts, double max_sum) {
    int total = 0;
    for (const auto& o : opts) total += o.back().interior;
    const double inf = 1e300;
    std::vector<double> d(total + 1, inf), nd;
    d[0] = 0;
    std::vector<std::vector<unsigned char>> choice(opts.size(), std::vector<unsigned char>(total + 1, 255));
    int reach = 0;
    for (size_t p = 0; p < opts.size(); ++p) {
        nd.assign(total + 1, inf);
        const int top = reach + opts[p].back().interior;
        for (int b = 0; b <= reach; ++b) {
            if (d[b] >= inf) continue;
            for (size_t k = 0; k < opts[p].size(); ++k) {
                const int nb = b + opts[p][k].interior;
                const double v = d[b] + opts[p][k].longest;
                if (v < nd[nb]) nd[nb] = v, choice[p][nb] = (unsigned char)k;
            }
        }
        reach = top;
        d.swap(nd);
    }
    int budget = -1;
    for (int b = 0; b <= total; ++b)
        if (d[b] <= max_sum + 1e-9) {
            budget = b;
            break;
        }
    if (budget < 0) return {};
    std::vector<int> pick(opts.size());
    for (size_t p = opts.size(); p-- > 0;) {
        const int k = choice[p][budget];
        pick[p] = opts[p][k].interior;
        budget -= opts[p][k].interior;
    }
    return pick;
}

int boundary_count(const Triple& t) {
    return t.f0 + t.f1 + t.f2;
}
int triangle_count(const Triple& t, int interior) {
    return 2 * interior + boundary_count(t) - 2;
}

// The data header's opening: what it is, how it is regenerated, and the record types.
std::string header_preamble() {
    std::string s;
    s += "// Uniform-density pattern data, generated by gen/uniform_gen (docs/algorithm.md \"Uniform "
         "density\").\n";
    s += "// Do not edit; regenerate with the command in gen/uniform_patterns/README.md. ctest regenerates "
         "the "
         "triples\n";
    s += "// with f0 <= 6; -DCTESS_UNIFORM_FULL_REGEN=ON adds the whole file, compared byte for byte.\n";
    s += "// clang-format off\n#pragma once\n#include <cstdint>\n\nnamespace ctess::uniform::data {\n\n";
    s += "// One sorted factor triple f0 >= f1 >= f2 (the factors of e0, e1, e2) and its interior vertex "
         "count.\n";
    s += "struct PatternRecord {\n    std::uint8_t f0, f1, f2, interior;\n};\n";
    s += "// An interior vertex (u, v) in units of 1/65534.\nstruct InteriorVertex {\n    std::uint16_t u, "
         "v;\n};\n";
    s += "// A counter-clockwise triangle over the canonical numbering: the f0 + f1 + f2 boundary vertices "
         "(v0, e0,\n";
    s += "// v1, e1, v2, e2 back to v0), then the interior vertices.\nstruct TriangleRecord {\n    "
         "std::uint8_t i0, i1, i2;\n};\n\n";
    return s;
}

// Appends one array row per pattern: its records, `format`ted, wrapped at 110 columns.
template <class Items, class Format>
void append_wrapped(std::string& s, const Items& items, Format format) {
    char buf[256];
    std::string line = "   ";
    for (const auto& item : items) {
        format(buf, sizeof buf, item);
        if (line.size() + std::strlen(buf) > 110) s += line + "\n", line = "   ";
        line += buf;
    }
    s += line + "\n";
}

void write_file(const std::string& path, const std::string& s) {
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) {
        std::fprintf(stderr, "uniform_gen: cannot write %s\n", path.c_str());
        std::exit(1);
    }
    std::fwrite(s.data(), 1, s.size(), f);
    std::fclose(f);
}

void write_header(const std::string& path, int max_factor, const std::vector<Triple>& triples,
                  const std::vector<Pattern>& chosen) {
    std::string s = header_preamble();
    char buf[256];
    std::snprintf(buf, sizeof buf, "inline constexpr unsigned max_factor = %d;\n", max_factor);
    s += buf;
    std::snprintf(buf, sizeof buf, "inline constexpr unsigned pattern_count = %zu;\n\n", triples.size());
    s += buf;
    s += "// Patterns in index order: f0 = 1..N, f1 = 1..f0, f2 = 1..f1.\ninline constexpr PatternRecord "
         "patterns[] = {\n";
    for (size_t i = 0; i < triples.size(); ++i) {
        std::snprintf(buf, sizeof buf, "    {%d, %d, %d, %zu},\n", triples[i].f0, triples[i].f1,
                      triples[i].f2, chosen[i].interior.size());
        s += buf;
    }
    s += "};\n\ninline constexpr InteriorVertex interior[] = {\n";
    for (size_t i = 0; i < triples.size(); ++i) {
        if (chosen[i].interior.empty()) continue;
        append_wrapped(s, chosen[i].interior, [](char* out, size_t size, const auto& q) {
            std::snprintf(out, size, " {%d, %d},", q[0], q[1]);
        });
    }
    s += "};\n\ninline constexpr TriangleRecord triangles[] = {\n";
    for (size_t i = 0; i < triples.size(); ++i)
        append_wrapped(s, chosen[i].tris, [](char* out, size_t size, const Tri& t) {
            std::snprintf(out, size, " {%d, %d, %d},", t[0], t[1], t[2]);
        });
    s += "};\n\n} // namespace ctess::uniform::data\n// clang-format on\n";
    write_file(path, s);
}

struct Totals {
    long triangles = 0;
    double longest = 0, mean = 0;
};

Totals totals(const std::vector<Triple>& triples, const std::vector<Pattern>& chosen, size_t count) {
    Totals r;
    for (size_t i = 0; i < count; ++i) {
        r.triangles += long(chosen[i].tris.size());
        r.longest = std::max(r.longest, chosen[i].longest);
        r.mean += chosen[i].longest;
    }
    r.mean /= double(count);
    (void)triples;
    return r;
}

// Regenerates the candidates of every triple with f0 <= check_max and compares the checked-in pattern
// (compiled into this program) with the candidate of the same interior count, ordered for the cache: the
// cheap form of the regenerate-and-compare test (the knapsack choice itself needs every triple).
int check_data(int check_max) {
    int bad = 0, checked = 0;
    for (int a = 1; a <= check_max; ++a)
        for (int b = 1; b <= a; ++b)
            for (int c = 1; c <= b; ++c) {
                const Triple t{a, b, c};
                const ctess::uniform::Pattern stored =
                    ctess::uniform::pattern(unsigned(a), unsigned(b), unsigned(c));
                const auto cands = candidates(t);
                const auto it = cands.find(int(stored.interior_count()));
                bool same = it != cands.end();
                if (same) {
                    Pattern p = it->second;
                    order_for_cache(p, boundary_count(t));
                    same = p.tris.size() == stored.triangle_count();
                    for (unsigned k = 0; same && k < stored.interior_count(); ++k) {
                        const ctess::uniform::Point q = stored.vertex(stored.boundary_count() + k);
                        same = int(q.u) == p.interior[k][0] && int(q.v) == p.interior[k][1];
                    }
                    for (unsigned k = 0; same && k < stored.triangle_count(); ++k) {
                        const auto tri = stored.triangle(k);
                        same = int(tri[0]) == p.tris[k][0] && int(tri[1]) == p.tris[k][1] &&
                               int(tri[2]) == p.tris[k][2];
                    }
                }
                if (!same) {
                    std::fprintf(stderr, "uniform_gen: pattern %d,%d,%d differs from the checked-in data\n",
                                 a, b, c);
                    ++bad;
                }
                ++checked;
            }
    std::fprintf(stderr, "uniform_gen: %d patterns regenerated, %d differ\n", checked, bad);
    return bad == 0 ? 0 : 1;
}

// The command line: generate (--max, --out, --stats) or check the checked-in data (--check N).
struct Options {
    int max_factor = 16;
    std::string out;
    bool stats = false;
    int check_max = -1; // --check N: N, else -1
};

// Parses argv into `o`; false on a usage error.
bool parse_options(int argc, char** argv, Options& o) {
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--max") && i + 1 < argc)
            o.max_factor = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--out") && i + 1 < argc)
            o.out = argv[++i];
        else if (!std::strcmp(argv[i], "--stats"))
            o.stats = true;
        else if (!std::strcmp(argv[i], "--check") && i + 1 < argc) {
            o.check_max = std::atoi(argv[++i]);
            return true;
        } else {
            std::fprintf(stderr, "usage: uniform_gen [--max N] [--out FILE] [--stats] | --check N\n");
            return false;
        }
    }
    return true;
}

// Every sorted triple f0 >= f1 >= f2 up to max_factor, in index order.
std::vector<Triple> sorted_triples(int max_factor) {
    std::vector<Triple> triples;
    for (int a = 1; a <= max_factor; ++a)
        for (int b = 1; b <= a; ++b)
            for (int c = 1; c <= b; ++c) triples.push_back({a, b, c});
    return triples;
}

constexpr double cap = 1.433, mean_target = 1.137; // NVIDIA's table (docs/algorithm.md)

// --stats: the Pareto front over the first `first` triples (N = 11): total triangles against the longest edge
// (cap) and the mean.
void print_pareto_front(const std::vector<Triple>& triples, const std::vector<std::map<int, Pattern>>& cands,
                        size_t first, int max_factor) {
    for (double c : {1.25, 1.30, 1.35, 1.40, cap})
        for (double m : {1.04, 1.06, 1.08, 1.10, 1.12, 1.137, 1.16, 1.20}) {
            std::vector<std::vector<Option>> o;
            for (size_t i = 0; i < first; ++i) o.push_back(pareto(cands[i], c));
            const auto pick = knapsack(o, m * double(first));
            if (pick.empty()) continue;
            long tri = 0;
            double mx = 0, sum = 0;
            for (size_t i = 0; i < first; ++i) {
                tri += triangle_count(triples[i], pick[i]);
                mx = std::max(mx, cands[i].at(pick[i]).longest);
                sum += cands[i].at(pick[i]).longest;
            }
            std::fprintf(stderr,
                         "front N=%zu: cap %.3f, mean <= %.3f: %ld triangles, longest %.3f, mean %.4f\n",
                         first == 286 ? size_t(11) : size_t(max_factor), c, m, tri, mx, sum / double(first));
        }
}

// The interior count of every triple: the first `first` triples (N = 11) meet the mean target on their own,
// the rest with what they leave. Empty when no selection meets the bounds.
std::vector<int> select_interior_counts(const std::vector<std::map<int, Pattern>>& cands, size_t first) {
    std::vector<std::vector<Option>> opts;
    for (const auto& c : cands) opts.push_back(pareto(c, cap));
    std::vector<int> pick;
    {
        std::vector<std::vector<Option>> o(opts.begin(), opts.begin() + first);
        pick = knapsack(o, mean_target * double(first));
    }
    double used = 0;
    for (size_t i = 0; i < first; ++i) used += cands[i].at(pick[i]).longest;
    if (cands.size() > first) {
        std::vector<std::vector<Option>> o(opts.begin() + first, opts.end());
        const auto rest = knapsack(o, mean_target * double(cands.size()) - used);
        pick.insert(pick.end(), rest.begin(), rest.end());
    }
    return pick;
}

// The chosen candidates, ordered for the cache and measured again; false on a zero-area triangle.
bool order_chosen(const std::vector<Triple>& triples, const std::vector<std::map<int, Pattern>>& cands,
                  const std::vector<int>& pick, std::vector<Pattern>& chosen) {
    for (size_t i = 0; i < triples.size(); ++i) {
        chosen.push_back(cands[i].at(pick[i]));
        order_for_cache(chosen.back(), boundary_count(triples[i]));
        chosen.back().longest = measure(triples[i], chosen.back());
        if (chosen.back().longest < 0) {
            std::fprintf(stderr, "uniform_gen: zero-area triangle after ordering\n");
            return false;
        }
    }
    return true;
}

void print_totals(const std::vector<Triple>& triples, const std::vector<Pattern>& chosen, size_t first,
                  int max_factor) {
    const Totals t11 = totals(triples, chosen, first), tall = totals(triples, chosen, triples.size());
    std::fprintf(stderr, "N<=11: %zu patterns, %ld triangles, longest %.4f, mean of maxima %.4f\n", first,
                 t11.triangles, t11.longest, t11.mean);
    std::fprintf(stderr, "N<=%d: %zu patterns, %ld triangles, longest %.4f, mean of maxima %.4f\n",
                 max_factor, triples.size(), tall.triangles, tall.longest, tall.mean);
}

} // namespace

int main(int argc, char** argv) {
    Options options;
    if (!parse_options(argc, argv, options)) return 2;
    if (options.check_max >= 0) return check_data(options.check_max);
    const std::vector<Triple> triples = sorted_triples(options.max_factor);
    std::vector<std::map<int, Pattern>> cands;
    for (const Triple& t : triples) {
        cands.push_back(candidates(t));
        if (options.stats)
            std::fprintf(stderr, "%d %d %d: %zu candidates\n", t.f0, t.f1, t.f2, cands.back().size());
    }
    const size_t first = std::min<size_t>(triples.size(), 286); // a <= 11
    if (options.stats) print_pareto_front(triples, cands, first, options.max_factor);
    const std::vector<int> pick = select_interior_counts(cands, first);
    if (pick.size() != triples.size()) {
        std::fprintf(stderr, "uniform_gen: no selection meets the bounds\n");
        return 1;
    }
    std::vector<Pattern> chosen;
    if (!order_chosen(triples, cands, pick, chosen)) return 1;
    print_totals(triples, chosen, first, options.max_factor);
    if (!options.out.empty()) write_header(options.out, options.max_factor, triples, chosen);
    return 0;
}
