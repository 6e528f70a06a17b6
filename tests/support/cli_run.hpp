// Runs the ctess CLI (CTESS_CLI) as a user would, through the shell, and captures what it prints.
#pragma once
#include <catch2/catch.hpp>

#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace ctess::test {

struct Run {
    int exit_code = -1;
    std::string out; // stdout and stderr together (or only stderr, see ctess_cli_redirected)
};

// `ctess <args> <redirections>` through /bin/sh; captures the standard output of the shell command.
inline Run run_shell(const std::string& cmd) {
    Run r;
    FILE* pipe = popen(cmd.c_str(), "r");
    REQUIRE(pipe != nullptr);
    std::array<char, 65536> buf{};
    std::size_t n = 0;
    while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) r.out.append(buf.data(), n);
    const int status = pclose(pipe);
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

inline Run ctess_cli(const std::string& args) {
    return run_shell(std::string(CTESS_CLI) + " " + args + " 2>&1");
}

} // namespace ctess::test
