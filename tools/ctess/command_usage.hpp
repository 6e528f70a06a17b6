// `ctess <command> --help`: one command's lines of the main usage text.
#pragma once
#include <string>

namespace ctess::cli {

// The usage of `command` cut out of the main usage text (its "  <command> ..." line and the deeper-indented
// lines after it), as "usage: ctess <command> ..."; empty when the text has no such command.
std::string command_usage(const std::string& usage_text, const std::string& command);
// True when an argument after the command is --help or -h.
bool asks_for_help(int argc, char** argv);

} // namespace ctess::cli
