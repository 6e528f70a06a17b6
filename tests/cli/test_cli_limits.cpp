// The CLI's bounded work and loud failures (docs/cli.md, "Limits" and "Errors and bad input"): every
// command's work is bounded before it starts, every output is checked through close, and a failed write never
// leaves a half-written file behind.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <unistd.h>
#include <vector>

#include "support/cli_run.hpp"

namespace {

using ctess::test::ctess_cli;
using ctess::test::Run;
using ctess::test::run_shell;

std::string temp_path(const std::string& name) {
    return (std::filesystem::temp_directory_path() /
            ("ctess_limits_" + std::to_string(::getpid()) + "_" + name))
        .string();
}

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

} // namespace

TEST_CASE("sweep to huge factors finishes with a bounded chart", "[cli][limits]") {
    // The tick loop used to add the step to f; above about 1e18 f + 128 == f and it never ended.
    for (const char* to : {"1e9", "1e15", "1e30", "3.4028235e38"}) {
        INFO("--to " << to);
        const std::string svg = temp_path("sweep_huge.svg");
        const Run r = ctess_cli(std::string("sweep --mode cp --from 1 --to ") + to + " --svg " + svg);
        REQUIRE(r.exit_code == 0);
        const std::string text = read_file(svg);
        CHECK(text.size() < 2'000'000);
        // At most 17 grid lines: 16 intervals of a power-of-two step.
        std::size_t ticks = 0;
        for (std::size_t at = 0; (at = text.find("stroke=\"#e3e6ea\"", at)) != std::string::npos; ++at)
            ++ticks;
        CHECK(ticks <= 17 + 5); // vertical ticks + the five horizontal lines
        std::filesystem::remove(svg);
    }
}

TEST_CASE("work past a command's limit is refused before it starts, naming the limit", "[cli][limits]") {
    const std::string dir = temp_path("anim_limit");
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"sweep --mode cp --from 1 --to 300 --max 256 --steps 20000 --svg " + dir + ".svg",
         "would draw 5140000 path segments; the limit is 2000000"},
        {"animate --mode cp --max 256 --from 256,256,256 --to 256,256,256 --frames 1000 --out " + dir,
         "the limit is 512 MiB"},
        {"efficiency --random 100001", "--random: 100001 is outside [1, 100000]"},
        {"animate --mode cp --from 1,1,1 --to 2,2,2 --frames 1001 --out " + dir, "outside [2, 1000]"},
    };
    for (const auto& [args, message] : cases) {
        INFO("ctess " << args);
        const Run r = ctess_cli(args);
        CHECK(r.exit_code == 2);
        CHECK(contains(r.out, message));
    }
    // Refused before anything was written.
    CHECK_FALSE(std::filesystem::exists(dir));
    CHECK_FALSE(std::filesystem::exists(dir + ".svg"));
}

TEST_CASE("a full output exits 1 with the OS reason", "[cli][limits]") {
    const Run file = ctess_cli("pattern --factors 4,4,4 --out /dev/full");
    CHECK(file.exit_code == 1);
    CHECK(contains(file.out, "cannot write '/dev/full': No space left on device"));
    // Standard output on a full device: the JSON written with fwrite, the line command's fmt::print, the main
    // usage text; stderr goes to the pipe, stdout to /dev/full.
    for (const char* args :
         {"pattern --factors 4,4,4", "line --factor 4", "efficiency", "--help", "sweep --help"}) {
        INFO("ctess " << args);
        const Run r = run_shell(std::string(CTESS_CLI) + " " + args + " 2>&1 >/dev/full");
        CHECK(r.exit_code == 1);
        CHECK(contains(r.out, "cannot write 'standard output': No space left on device"));
    }
    const Run missing = ctess_cli("pattern --factors 4,4,4 --format svg --out /nonexistent-dir/x.svg");
    CHECK(missing.exit_code == 1);
    CHECK(contains(missing.out, "cannot write '/nonexistent-dir/x.svg': No such file or directory"));
}

TEST_CASE("a failed write leaves the previous file intact and no temporary behind", "[cli][limits]") {
    const std::string dir = temp_path("atomic");
    std::filesystem::create_directories(dir);
    const std::string out = dir + "/p.svg";
    { std::ofstream(out) << "previous content\n"; }
    // A 4 KiB file-size limit (SIGXFSZ ignored, so write() fails with EFBIG) stops the SVG part-way.
    const Run r = run_shell("trap '' XFSZ; ulimit -f 4; " + std::string(CTESS_CLI) +
                            " pattern --factors 16,16,16 --format svg --out " + out + " 2>&1");
    CHECK(r.exit_code == 1);
    CHECK(contains(r.out, "cannot write '" + out + "': File too large"));
    CHECK(read_file(out) == "previous content\n");
    CHECK(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()) ==
          1);
    // Without the limit the file is replaced whole.
    REQUIRE(ctess_cli("pattern --factors 16,16,16 --format svg --out " + out).exit_code == 0);
    CHECK(contains(read_file(out), "</svg>"));
    std::filesystem::remove_all(dir);
}

TEST_CASE("ctess <command> --help prints that command's usage", "[cli]") {
    for (const char* command : {"pattern", "line", "sweep", "animate", "efficiency"}) {
        INFO(command);
        for (const char* flag : {"--help", "-h"}) {
            const Run r = ctess_cli(std::string(command) + " --mode cp " + flag);
            CHECK(r.exit_code == 0);
            CHECK(r.out.starts_with(std::string("usage: ctess ") + command + " "));
            CHECK_FALSE(contains(r.out, "commands:")); // only this command's lines
        }
    }
    const Run pattern = ctess_cli("pattern --help");
    CHECK(contains(pattern.out, "[--column-rule minimal|staircase]")); // its continuation lines too
    const Run unknown = ctess_cli("frobnicate --help");
    CHECK(unknown.exit_code == 2);
    CHECK(contains(unknown.out, "unknown command"));
}

TEST_CASE("surface writes a non-finite --angle or --distance as JSON null", "[cli][limits]") {
    for (const char* option : {"--angle inf", "--distance inf"}) {
        for (const char* format : {"json", "stats"}) {
            INFO(option << " --format " << format);
            const Run r = ctess_cli(std::string("surface --name sphere --max-level 6 ") + option +
                                    " --format " + format);
            CHECK(r.exit_code == 0);
            CHECK_FALSE(contains(r.out, "inf"));
            CHECK_FALSE(contains(r.out, "nan"));
            CHECK(contains(r.out, option[2] == 'a' ? "\"angle\": null" : "\"distance\": null"));
        }
    }
    CHECK(contains(ctess_cli("surface --name sphere --max-level 6").out, "\"distance\": 0.05,"));
}

TEST_CASE("--out writes through a symbolic link and keeps the replaced file's permissions", "[cli][limits]") {
    namespace fs = std::filesystem;
    const fs::path dir = fs::path(CTESS_TEST_BINARY_DIR) / ("cli_out_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path target = dir / "target.json";
    const fs::path link = dir / "link.json";
    { std::ofstream(target) << "previous\n"; }
    fs::permissions(target, fs::perms::owner_read | fs::perms::owner_write);
    fs::create_symlink("target.json", link);
    REQUIRE(ctess_cli("pattern --factors 4,4,4 --out " + link.string()).exit_code == 0);
    CHECK(fs::is_symlink(link));
    CHECK(fs::read_symlink(link) == "target.json");
    CHECK(contains(read_file(target.string()), "\"triangle_count\""));
    CHECK((fs::status(target).permissions() & fs::perms::all) ==
          (fs::perms::owner_read | fs::perms::owner_write));
    // A plain file keeps its bits too; a new file gets the default mode.
    fs::permissions(target, fs::perms::owner_all | fs::perms::group_read, fs::perm_options::replace);
    REQUIRE(ctess_cli("pattern --factors 3,3,3 --out " + target.string()).exit_code == 0);
    CHECK((fs::status(target).permissions() & fs::perms::all) ==
          (fs::perms::owner_all | fs::perms::group_read));
    // A dangling link is refused and left alone.
    const fs::path dangling = dir / "dangling.json";
    fs::create_symlink("missing/x.json", dangling);
    const Run r = ctess_cli("pattern --factors 4,4,4 --out " + dangling.string());
    CHECK(r.exit_code == 1);
    CHECK(contains(r.out, "cannot resolve the symbolic link '" + dangling.string() + "'"));
    CHECK(fs::is_symlink(dangling));
    CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 3);
    fs::remove_all(dir);
}

TEST_CASE("animate bounds every frame, not only the two ends", "[cli][limits]") {
    const std::string dir = temp_path("anim_middle");
    const Run big =
        ctess_cli("animate --mode cp --max 256 --from 1,1,256 --to 256,256,1 --frames 1000 --out " + dir);
    CHECK(big.exit_code == 2);
    CHECK(contains(big.out, "the limit is 512 MiB"));
    CHECK_FALSE(std::filesystem::exists(dir));
    const Run small = ctess_cli("animate --mode cp --from 1,1,4 --to 4,4,1 --frames 3 --out " + dir);
    CHECK(small.exit_code == 0);
    CHECK(std::filesystem::exists(dir + "/frame_002.svg"));
    CHECK(std::filesystem::exists(dir + "/index.html"));
    std::filesystem::remove_all(dir);
}
