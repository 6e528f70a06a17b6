// libFuzzer target: the ctess CLI's argument parsing, in process (tools/ctess/cli_args.hpp, commands.hpp,
// command_usage.hpp). The input is split at NUL bytes into argv after "ctess <command>"; every option parser
// runs on it, then the pattern request is tessellated. Property: a bad argument is a UsageError (exit 2 in
// the CLI); nothing else is thrown, and nothing crashes or reads out of bounds.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "cli_args.hpp"
#include "command_usage.hpp"
#include "commands.hpp"
#include "mesh.hpp"

#include "fuzz_input.hpp"

using namespace ctess::cli;

namespace {

const char* const usage_text = "commands:\n  pattern  --mode M --factors a,b,c\n           [--max 64|256]\n"
                               "  line     --factor f\n";

void parse(int argc, char** argv, unsigned command) {
    if (command == 0) {
        const Args args(
            argc, argv, 2,
            {"mode", "domain", "factors", "winding", "format", "out", "max", "layout", "column-rule"},
            {"provoking"});
        const PatternRequest r = pattern_request_from(args, "factors");
        (void)choice(args.get_or("format", "json"), {"json", "svg", "obj"}, "--format");
        const Mesh mesh = tessellate(r);
        CTESS_FUZZ_CHECK(mesh.indices.size() % mesh.vertices_per_primitive == 0);
        for (std::uint32_t i : mesh.indices) CTESS_FUZZ_CHECK(i < mesh.vertices.size());
    } else if (command == 1) {
        const Args args(argc, argv, 2, {"mode", "factor", "max", "format"});
        (void)line_mode_from(args.get_or("mode", "cp"));
        const float f = parse_float(args.get("factor"), "--factor");
        require_usable_factors({f}, "--factor");
        (void)max_factor_from(args);
    } else {
        const Args args(argc, argv, 2, {"from", "to", "steps", "frames", "random", "seed"});
        (void)parse_float_list(args.get_or("from", "1,2,3"), "--from", 2, 6);
        (void)parse_unsigned(args.get_or("steps", "400"), "--steps", 2, 20000);
        (void)parse_unsigned(args.get_or("seed", "0"), "--seed", 0, 4294967295u);
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const unsigned command = data[0] % 3;
    std::vector<std::string> words = {"ctess", command == 0 ? "pattern" : command == 1 ? "line" : "sweep"};
    std::string word;
    for (std::size_t k = 1; k < size; ++k) {
        if (data[k] == 0) {
            words.push_back(word);
            word.clear();
        } else {
            word += static_cast<char>(data[k]);
        }
    }
    if (!word.empty()) words.push_back(word);
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    const int argc = static_cast<int>(words.size());
    (void)command_usage(usage_text, words[1]);
    (void)asks_for_help(argc, argv.data());
    try {
        parse(argc, argv.data(), command);
    } catch (const UsageError&) {
        // the documented outcome of a bad argument
    }
    return 0;
}
