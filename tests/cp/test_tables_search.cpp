// The O(1) reverse lookups over the column table, checked for every element of every token pair of both
// table sets (docs/algorithm.md §4.2): vertex -> column, strip triangle -> strip and provoking
// copy -> column. The first guess is also moved by -1 and +1, so that a target whose float square root or
// division differs by a few ulp still lands inside the window. Every Newton step must leave a residual in
// [0, search_window].
#include "support/cp_search.hpp"
#include <ctess/runtime/cp/table_set.hpp>

#include <cstdint>
#include <string>

#include <catch2/catch.hpp>

#include "support/mesh_checks.hpp"

using ctess::rt::CpTableSet;
using ctess::test::cat;
namespace tables = ctess::cp::tables;

namespace {

struct PairView {
    const tables::ColumnRecord* rec;
    const std::uint16_t* c;
};

PairView pair_view(const CpTableSet& t, unsigned s0, unsigned s2) {
    const ctess::rt::CpColumnChunk& chunk = t.column_chunks[t.chunk_of_shape2[s2 - 1]];
    const tables::ColumnRecord* rec = &chunk.records[(s2 - chunk.first_shape2) * t.shapes + s0 - 1];
    return {rec, chunk.pool + rec->offset};
}

struct SearchStats {
    std::uint64_t queries = 0;
    int worst_residual = 0;
    int least_residual = 0;
    std::uint64_t wrong = 0;
    std::string first;
};

// Checks the search for every e in [y(0), y(h)) of one sequence.
template <class Y>
void check_sequence(const Y& y, unsigned h, float alpha, float beta, float shift, SearchStats& st,
                    const std::string& where) {
    unsigned truth = 0;
    for (int e = y(0); e < y(static_cast<int>(h)); ++e) {
        while (truth + 1 < h && y(static_cast<int>(truth) + 1) <= e) ++truth;
        const int guess = ctess::rt::search_first_guess(alpha, beta, static_cast<float>(e) - shift, h);
        for (int d = -1; d <= 1; ++d) {
            ++st.queries;
            const int x = ctess::rt::search_newton_step(y, h, e, guess + d);
            const int residual = static_cast<int>(truth) - x;
            st.worst_residual = residual > st.worst_residual ? residual : st.worst_residual;
            st.least_residual = residual < st.least_residual ? residual : st.least_residual;
            if (ctess::rt::search_from(y, h, e, guess + d) != truth) {
                if (st.wrong++ == 0)
                    st.first = cat(where, " e=", e, " guess ", guess, "+", d, " residual ", residual);
            }
        }
    }
}

void check_all_pairs(const CpTableSet& t) {
    SearchStats vertex, strip, copy;
    for (unsigned s2 = 1; s2 <= t.shapes; ++s2) {
        for (unsigned s0 = 1; s0 <= t.shapes; ++s0) {
            const PairView p = pair_view(t, s0, s2);
            const std::uint16_t* c = p.c;
            const unsigned h = p.rec->head;
            const float a = p.rec->a, b = p.rec->b;
            const int r0 = c[1];
            const std::string where = cat("pair (T", s0, ", T", s2, ")");
            check_sequence([c](int k) { return static_cast<int>(c[k]); }, h, a, b, 0.0f, vertex, where);
            check_sequence([c, r0](int k) { return c[k] + c[k + 1] - 2 * k - r0; }, h, 2 * a - 2 * b - 2,
                           2 * b, a - b - static_cast<float>(r0), strip, where);
            check_sequence([c](int k) { return static_cast<int>(c[k]) - k; }, h, a - 1, b, 0.0f, copy, where);
        }
    }
    const int window = static_cast<int>(tables::search_window);
    for (const auto* s : {&vertex, &strip, &copy}) {
        INFO("max " << t.max_factor << ": " << s->queries << " queries, residual after the Newton step in ["
                    << s->least_residual << ", " << s->worst_residual << "], first wrong: " << s->first);
        CHECK(s->wrong == 0);
        CHECK(s->least_residual >= 0);
        CHECK(s->worst_residual <= window);
        CHECK(s->queries > 0);
    }
}

} // namespace

TEST_CASE("tables: the column lookups are exact for every element of every pair, max 64",
          "[tables][search]") {
    check_all_pairs(ctess::rt::cp_tables_64);
}

TEST_CASE("tables: the column lookups are exact for every element of every pair, max 256",
          "[tables][search]") {
    check_all_pairs(ctess::rt::cp_tables_256);
}
