// {{NAME}} substitution for the shader templates in shaders/. Every placeholder of the template must be given
// and every given value must be used, so that a renamed constant fails the build instead of shipping a shader
// with a hole in it.
#pragma once
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>

namespace ctess::gen {

inline std::string fill_template(std::string_view text,
                                 const std::map<std::string, std::string, std::less<>>& values) {
    std::string out;
    std::map<std::string, bool, std::less<>> used;
    std::size_t pos = 0;
    while (true) {
        const std::size_t open = text.find("{{", pos);
        if (open == std::string_view::npos) break;
        const std::size_t close = text.find("}}", open + 2);
        if (close == std::string_view::npos) throw std::runtime_error("unterminated {{ in template");
        out.append(text.data() + pos, open - pos);
        const std::string_view name = text.substr(open + 2, close - open - 2);
        const auto it = values.find(name);
        if (it == values.end()) {
            std::string why = "template placeholder without a value: ";
            why += name;
            throw std::runtime_error(why);
        }
        out += it->second;
        used[it->first] = true;
        pos = close + 2;
    }
    out.append(text.data() + pos, text.size() - pos);
    for (const auto& [name, value] : values)
        if (!used.count(name)) {
            std::string why = "value not used by the template: ";
            why += name;
            throw std::runtime_error(why);
        }
    return out;
}

} // namespace ctess::gen
