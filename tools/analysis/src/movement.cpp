#include <ctess/analysis/movement.hpp>

#include <cmath>
#include <tuple>

namespace ctess::analysis {

Point2 to_metric(const std::array<double, 3>& w) {
    return {w[1] + 0.5 * w[2], w[2] * std::sqrt(3.0) / 2.0};
}
double dist(Point2 a, Point2 b) {
    return std::hypot(a.x - b.x, a.y - b.y);
}

Places places(const Pattern& p) {
    Places out;
    for (const auto& w : p.w) {
        int zeros = 0, zero = 0;
        for (int k = 0; k < 3; ++k)
            if (std::fabs(w[k]) <= 1e-9) ++zeros, zero = k;
        if (zeros >= 2) {
            const int corner = w[0] > w[1] ? (w[0] > w[2] ? 0 : 2) : (w[1] > w[2] ? 1 : 2);
            out.corner[corner] = to_metric(w);
        } else if (zeros == 1) {
            out.edge[zero].push_back(w[(zero + 1) % 3]);
        } else {
            out.interior.push_back(to_metric(w));
        }
    }
    // A position counts once: CP's provoking copies and UniformSplit's per-subpatch vertices repeat points
    // bit for bit.
    for (auto& e : out.edge) {
        std::sort(e.begin(), e.end());
        e.erase(std::unique(e.begin(), e.end()), e.end());
    }
    auto less = [](Point2 a, Point2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); };
    auto same = [](Point2 a, Point2 b) { return a.x == b.x && a.y == b.y; };
    std::sort(out.interior.begin(), out.interior.end(), less);
    out.interior.erase(std::unique(out.interior.begin(), out.interior.end(), same), out.interior.end());
    out.all.assign(out.corner.begin(), out.corner.end());
    for (int k = 0; k < 3; ++k)
        for (double t : out.edge[k]) {
            std::array<double, 3> w{};
            w[(k + 1) % 3] = t;
            w[(k + 2) % 3] = 1 - t;
            out.all.push_back(to_metric(w));
        }
    out.all.insert(out.all.end(), out.interior.begin(), out.interior.end());
    return out;
}

Moves edge_moves(const std::vector<double>& a, const std::vector<double>& b) {
    const std::vector<double>& s = a.size() <= b.size() ? a : b;
    const std::vector<double>& l = a.size() <= b.size() ? b : a;
    const std::size_t n = s.size(), m = l.size(), w = m + 1;
    // cost[i * w + j]: the least total move matching s[0, i) into l[0, j).
    std::vector<double> cost((n + 1) * w, 1e300);
    std::fill(cost.begin(), cost.begin() + w, 0.0);
    for (std::size_t i = 1; i <= n; ++i)
        for (std::size_t j = 1; j <= m; ++j)
            cost[i * w + j] =
                std::min(cost[i * w + j - 1], cost[(i - 1) * w + j - 1] + std::fabs(s[i - 1] - l[j - 1]));
    Moves out{cost[n * w + m], 0, m - n};
    std::vector<bool> matched(m);
    for (std::size_t i = n, j = m; i > 0;) { // walk the least matching back for its largest move
        if (cost[i * w + j] == cost[i * w + j - 1]) {
            --j;
            continue;
        }
        out.largest = std::max(out.largest, std::fabs(s[i - 1] - l[j - 1]));
        matched[j - 1] = true;
        --i, --j;
    }
    for (std::size_t j = 0; j < m;
         ++j) { // an unmatched point pops from (or into) the nearest point or corner
        if (matched[j]) continue;
        double d = std::min(l[j], 1 - l[j]);
        for (double x : s) d = std::min(d, std::fabs(x - l[j]));
        out.add_pop(d);
    }
    return out;
}

Moves interior_moves(const std::vector<Point2>& a, const std::vector<Point2>& b, double r,
                     const std::vector<Point2>& all_a, const std::vector<Point2>& all_b) {
    const int cells = static_cast<int>(std::ceil(1.0 / r)) + 1;
    std::vector<std::vector<std::uint32_t>> grid(static_cast<std::size_t>(cells) * cells);
    auto cell = [&](double x) { return std::clamp(static_cast<int>(x / r), 0, cells - 1); };
    for (std::uint32_t j = 0; j < b.size(); ++j) grid[cell(b[j].y) * cells + cell(b[j].x)].push_back(j);
    std::vector<std::tuple<double, std::uint32_t, std::uint32_t>> pairs;
    for (std::uint32_t i = 0; i < a.size(); ++i) {
        const int cx = cell(a[i].x), cy = cell(a[i].y);
        for (int y = std::max(0, cy - 1); y <= std::min(cells - 1, cy + 1); ++y)
            for (int x = std::max(0, cx - 1); x <= std::min(cells - 1, cx + 1); ++x)
                for (std::uint32_t j : grid[y * cells + x]) {
                    const double d = dist(a[i], b[j]);
                    if (d <= r) pairs.push_back({d, i, j});
                }
    }
    std::sort(pairs.begin(), pairs.end());
    std::vector<bool> used_a(a.size()), used_b(b.size());
    Moves out;
    std::size_t matched = 0;
    for (const auto& [d, i, j] : pairs) {
        if (used_a[i] || used_b[j]) continue;
        used_a[i] = used_b[j] = true;
        out.total += d;
        out.largest = std::max(out.largest, d);
        ++matched;
    }
    out.unmatched = a.size() + b.size() - 2 * matched;
    auto pops = [&](const std::vector<Point2>& from, const std::vector<bool>& used,
                    const std::vector<Point2>& other) {
        for (std::size_t i = 0; i < from.size(); ++i) {
            if (used[i]) continue;
            double d = 1e300;
            for (const Point2& q : other) d = std::min(d, dist(from[i], q));
            out.add_pop(d);
        }
    };
    pops(a, used_a, all_b);
    pops(b, used_b, all_a);
    return out;
}

Movement sweep(PatternFunction pattern, const Factors& from, const Factors& to, int steps) {
    Movement m;
    Pattern p;
    auto at = [&](int s) {
        const double t = double(s) / steps;
        Factors f;
        for (int k = 0; k < 3; ++k) f[k] = static_cast<float>(from[k] + (to[k] - from[k]) * t);
        return f;
    };
    pattern(at(0), p);
    Places prev = places(p);
    double total = 0, edges = 0, pop = 0;
    auto add = [&](const Moves& moves) { // one step's moves of a set of points
        total += moves.total;
        m.largest = std::max(m.largest, moves.largest);
        m.unmatched += moves.unmatched;
        pop += moves.pop;
        m.largest_pop = std::max(m.largest_pop, moves.largest_pop);
    };
    m.cumulative.push_back({from[0], 0});
    for (int s = 1; s <= steps; ++s) {
        pattern(at(s), p);
        Places next = places(p);
        for (int k = 0; k < 3; ++k) {
            total += dist(prev.corner[k], next.corner[k]);
            const Moves e = edge_moves(prev.edge[k], next.edge[k]);
            edges += e.total;
            add(e);
        }
        // A persistent point moves less than the point spacing (1 / factor) per step.
        const Factors f = at(s);
        const double r = 1.5 / std::max({1.0f, f[0], f[1], f[2]});
        add(interior_moves(prev.interior, next.interior, r, prev.all, next.all));
        m.cumulative.push_back({at(s)[0], edges});
        prev = std::move(next);
    }
    double span = 0;
    for (int k = 0; k < 3; ++k) span = std::max(span, double(std::fabs(to[k] - from[k])));
    m.all = total / span;
    m.edges = edges / span;
    m.pop = pop / span;
    return m;
}

} // namespace ctess::analysis
