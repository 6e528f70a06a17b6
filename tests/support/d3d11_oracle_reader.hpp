// Reads the D3D11 reference vectors (tests/data/d3d11_<domain>_<partitioning>.jsonl.gz, format in
// tests/data/README.md): a gzip reader and a small JSON parser for exactly that schema.
#pragma once
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <zlib.h>

namespace ctess::test {

struct OracleCase {
    std::string partitioning;
    std::string domain;
    std::vector<float> factors;                                  // NaN / +-inf for the string spellings
    std::vector<std::pair<std::uint32_t, std::uint32_t>> points; // (u, v) in 1/65536
    std::vector<std::uint32_t> indices;
    int line = 0;
};

inline std::string read_gzip_file(const std::string& path) {
    gzFile f = gzopen(path.c_str(), "rb");
    if (f == nullptr) throw std::runtime_error("cannot open " + path);
    std::string out;
    char buf[1 << 16];
    for (;;) {
        const int n = gzread(f, buf, sizeof buf);
        if (n < 0) {
            gzclose(f);
            throw std::runtime_error("gzip error in " + path);
        }
        if (n == 0) break;
        out.append(buf, static_cast<std::size_t>(n));
    }
    gzclose(f);
    return out;
}

namespace detail {

class JsonLineParser {
  public:
    explicit JsonLineParser(const std::string& text) : s_(text) {}

    OracleCase parse() {
        OracleCase c;
        expect('{');
        for (bool first = true;; first = false) {
            skip_ws();
            if (peek() == '}') break;
            if (!first) expect(',');
            const std::string key = string();
            expect(':');
            if (key == "partitioning")
                c.partitioning = string();
            else if (key == "domain")
                c.domain = string();
            else if (key == "factors")
                c.factors = factor_list();
            else if (key == "points_u16_16")
                c.points = point_list();
            else if (key == "indices")
                c.indices = uint_list();
            else
                fail("unknown key " + key);
        }
        expect('}');
        return c;
    }

  private:
    const std::string& s_;
    std::size_t i_ = 0;

    [[noreturn]] void fail(const std::string& what) const {
        throw std::runtime_error("oracle parse error at " + std::to_string(i_) + ": " + what);
    }
    void skip_ws() {
        while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\r')) ++i_;
    }
    char peek() {
        skip_ws();
        return i_ < s_.size() ? s_[i_] : '\0';
    }
    void expect(char ch) {
        if (peek() != ch) fail(std::string("expected ") + ch);
        ++i_;
    }
    std::string string() {
        expect('"');
        const std::size_t end = s_.find('"', i_);
        if (end == std::string::npos) fail("unterminated string");
        std::string out = s_.substr(i_, end - i_);
        i_ = end + 1;
        return out;
    }
    std::string number_token() {
        skip_ws();
        const std::size_t start = i_;
        while (i_ < s_.size() && (std::isdigit(static_cast<unsigned char>(s_[i_])) || s_[i_] == '-' ||
                                  s_[i_] == '+' || s_[i_] == '.' || s_[i_] == 'e' || s_[i_] == 'E'))
            ++i_;
        if (start == i_) fail("expected a number");
        return s_.substr(start, i_ - start);
    }
    float factor() {
        if (peek() == '"') {
            const std::string word = string();
            if (word == "nan") return std::numeric_limits<float>::quiet_NaN();
            if (word == "inf") return std::numeric_limits<float>::infinity();
            if (word == "-inf") return -std::numeric_limits<float>::infinity();
            fail("unknown factor " + word);
        }
        const std::string tok = number_token();
        return std::strtof(tok.c_str(), nullptr); // the text has 9 significant digits: exact for a float
    }
    std::uint32_t unsigned_int() {
        const std::string tok = number_token();
        char* end = nullptr;
        const unsigned long v = std::strtoul(tok.c_str(), &end, 10);
        if (*end != '\0' || tok[0] == '-') fail("expected an unsigned integer");
        return static_cast<std::uint32_t>(v);
    }
    template <class F>
    void list(F&& element) {
        expect('[');
        if (peek() == ']') {
            ++i_;
            return;
        }
        for (;;) {
            element();
            if (peek() == ']') {
                ++i_;
                return;
            }
            expect(',');
        }
    }
    std::vector<float> factor_list() {
        std::vector<float> out;
        list([&] { out.push_back(factor()); });
        return out;
    }
    std::vector<std::uint32_t> uint_list() {
        std::vector<std::uint32_t> out;
        list([&] { out.push_back(unsigned_int()); });
        return out;
    }
    std::vector<std::pair<std::uint32_t, std::uint32_t>> point_list() {
        std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
        list([&] {
            expect('[');
            const std::uint32_t u = unsigned_int();
            expect(',');
            const std::uint32_t v = unsigned_int();
            expect(']');
            out.emplace_back(u, v);
        });
        return out;
    }
};

} // namespace detail

// All cases of one gzip'd JSON-lines file, in file order.
inline std::vector<OracleCase> read_oracle_cases(const std::string& path) {
    const std::string text = read_gzip_file(path);
    std::vector<OracleCase> cases;
    std::size_t start = 0;
    int line = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        ++line;
        if (end > start) {
            const std::string row = text.substr(start, end - start);
            OracleCase c = detail::JsonLineParser(row).parse();
            c.line = line;
            cases.push_back(std::move(c));
        }
        start = end + 1;
    }
    return cases;
}

} // namespace ctess::test
