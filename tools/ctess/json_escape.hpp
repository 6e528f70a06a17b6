// The one JSON string escaper for what the CLI and `ctess serve` write: text that reaches a JSON document
// (error messages quote the caller's input) goes through json_escape, so no input can add keys or break the
// document.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace ctess::cli {

// The body of a JSON string (no quotes): `"` and `\` backslash-escaped, control characters (and DEL) as
// \u00XX, valid UTF-8 kept as is, and each byte that does not start a valid UTF-8 sequence (overlong forms,
// surrogates and code points past U+10FFFF included) replaced by \ufffd.
inline std::string json_escape(std::string_view s) {
    std::string out;
    out.reserve(s.size());
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(s[i]); };
    for (std::size_t i = 0; i < s.size();) {
        const unsigned char c = byte(i);
        if (c == '"' || c == '\\') {
            out += '\\';
            out += static_cast<char>(c);
            ++i;
        } else if (c < 0x20 || c == 0x7f) {
            static constexpr char hex[] = "0123456789abcdef";
            out += "\\u00";
            out += hex[c >> 4];
            out += hex[c & 15];
            ++i;
        } else if (c < 0x80) {
            out += static_cast<char>(c);
            ++i;
        } else {
            const std::size_t len = c >= 0xc2 && c <= 0xdf   ? 2
                                    : c >= 0xe0 && c <= 0xef ? 3
                                    : c >= 0xf0 && c <= 0xf4 ? 4
                                                             : 0;
            bool ok = len != 0 && i + len <= s.size();
            for (std::size_t k = 1; ok && k < len; ++k) ok = (byte(i + k) & 0xc0) == 0x80;
            if (ok && len >= 3) {
                // The second byte's range rules out overlong forms, surrogates and values past U+10FFFF.
                const unsigned char c1 = byte(i + 1);
                ok = !(c == 0xe0 && c1 < 0xa0) && !(c == 0xed && c1 > 0x9f) && !(c == 0xf0 && c1 < 0x90) &&
                     !(c == 0xf4 && c1 > 0x8f);
            }
            if (ok) {
                out.append(s.substr(i, len));
                i += len;
            } else {
                out += "\\ufffd";
                ++i;
            }
        }
    }
    return out;
}

} // namespace ctess::cli
