// Movement metrics of a tessellation as its factors change: how far vertices move and how far those that
// appear or vanish jump (pops), over a sweep of the edge factors. Any generator plugs in as a function that
// writes its pattern as barycentric weights, so CP, D3D11, OpenSubdiv and uniform density are measured alike.
// Lengths are in the domain's own metric: the equilateral triangle with unit edges.
#pragma once
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace ctess::analysis {

using Factors = std::array<float, 3>;

// One tessellation: barycentric weights (w0, w1, w2) per vertex, three indices per triangle.
struct Pattern {
    std::vector<std::array<double, 3>> w;
    std::vector<std::uint32_t> indices;
};

// Writes the pattern of the given edge factors.
using PatternFunction = void (*)(const Factors&, Pattern&);

struct Point2 {
    double x, y;
};
// The position of barycentric weights w in the equilateral triangle with unit edges.
Point2 to_metric(const std::array<double, 3>& w);
double dist(Point2 a, Point2 b);

// A pattern split by where its vertices lie: corners, the points of each edge (their parameter along it, in
// order), and the interior points in output order.
struct Places {
    std::array<Point2, 3> corner{};
    std::array<std::vector<double>, 3> edge; // edge k: opposite corner k (w_k = 0), parameter w_{k+1}
    std::vector<Point2> interior;
    std::vector<Point2> all; // every position once: corners, edge points, interior
};
Places places(const Pattern& p);

// The moves between two steps of a sweep.
struct Moves {
    double total = 0;          // path length (parameter = length along the unit edge)
    double largest = 0;        // the largest single move
    std::size_t unmatched = 0; // points that appear or vanish
    double pop = 0;            // for each of those, the distance to the other step's nearest point, summed
    double largest_pop = 0;
    void add_pop(double d) {
        pop += d;
        largest_pop = std::max(largest_pop, d);
    }
};

// Edge points keep their identity in order: between two steps, the points of the shorter list are matched to
// the longer list's in order, choosing the points that appear (or disappear) so that the total move is
// least.
Moves edge_moves(const std::vector<double>& a, const std::vector<double>& b);

// Interior points have no order to keep: the closest pairs (within r, a bound on one step's move) are matched
// first, each point at most once; the rest appear or vanish.
// An unmatched point pops from (or into) the nearest point of the other step (all_b for a, all_a for b).
Moves interior_moves(const std::vector<Point2>& a, const std::vector<Point2>& b, double r,
                     const std::vector<Point2>& all_a, const std::vector<Point2>& all_b);

struct Movement {
    double all = 0, edges = 0;       // path length per unit factor change
    double largest = 0;              // the largest move of one vertex in one step
    std::size_t unmatched = 0;       // vertices without a partner in the next step (appear or disappear)
    double pop = 0, largest_pop = 0; // per unit factor change; the largest single one
    std::vector<std::pair<double, double>> cumulative; // factor, edge-point path length so far
};

// Sweep the generator from `from` to `to` in `steps` equal steps.
Movement sweep(PatternFunction pattern, const Factors& from, const Factors& to, int steps);

} // namespace ctess::analysis
