// ctess efficiency: the CP efficiency table against D3D11 fractional_even, or (--family uniform) the
// uniform-density table against D3D11 integer and CP.
#include "cli_args.hpp"
#include "commands.hpp"
#include "file_output.hpp"

#include <ctess/analysis/efficiency.hpp>
#include <ctess/analysis/efficiency_uniform.hpp>

namespace ctess::cli {

int run_efficiency(int argc, char** argv) {
    using namespace ctess::analysis;
    const Args args(argc, argv, 2, {"max", "random", "seed", "format", "out", "family"});
    const unsigned max = max_factor_from(args);
    const unsigned random = parse_unsigned(args.get_or("random", "40"), "--random", 1, 100000);
    const unsigned seed = parse_unsigned(args.get_or("seed", "2026"), "--seed", 0, 4294967295u);
    const std::string format = choice(args.get_or("format", "markdown"), {"markdown", "json"}, "--format");
    if (choice(args.get_or("family", "cp"), {"cp", "uniform"}, "--family") == "uniform") {
        // every sorted triple of the table and a fixed split sample: no random rows to choose (docs/cli.md)
        if (args.has("random") || args.has("seed"))
            throw UsageError("--random and --seed apply to --family cp only (--family uniform reports every "
                             "sorted triple of the table)");
        const auto rows = uniform_efficiency_rows(max);
        const auto split = uniform_split_summaries();
        write_text(args.get_or("out", "-"),
                   format == "json" ? uniform_efficiency_json(rows, split)
                                    : uniform_efficiency_markdown(rows) + uniform_split_markdown(split));
        return 0;
    }
    const auto rows = efficiency_rows(max, random, seed);
    const auto summary = summarize(rows);
    write_text(args.get_or("out", "-"), format == "json" ? efficiency_json(rows, summary, max)
                                                         : efficiency_markdown(rows, summary, max));
    return 0;
}

} // namespace ctess::cli
