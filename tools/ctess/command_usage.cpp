#include "command_usage.hpp"

#include <sstream>
#include <string_view>

namespace ctess::cli {

std::string command_usage(const std::string& usage_text, const std::string& command) {
    std::istringstream in(usage_text);
    std::string line, out;
    const std::string head = "  " + command + " ";
    bool inside = false;
    while (std::getline(in, line)) {
        if (!inside && line.starts_with(head)) {
            inside = true;
            out = "usage: ctess " + command + " " + line.substr(line.find_first_not_of(' ', head.size())) +
                  "\n";
        } else if (inside) {
            if (line.size() < 3 || line[2] != ' ') break; // the next command or the end of the list
            out += "       " + line.substr(2) + "\n";
        }
    }
    return out;
}

bool asks_for_help(int argc, char** argv) {
    for (int i = 2; i < argc; ++i) {
        const std::string_view arg = argv[i];
        if (arg == "--help" || arg == "-h") return true;
    }
    return false;
}

} // namespace ctess::cli
