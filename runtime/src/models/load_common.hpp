// Shared between the glTF and OBJ loaders (runtime/src/models/): the error type that unwinds a load, and the
// checks every loader applies to its output (docs/models.md, "Bad files").
#pragma once
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include <ctess/runtime/models/model.hpp>

namespace ctess::models::detail {

// The whole file at path, for the loaders: an empty string, or the problem ("PATH: no such file", too large
// for max_bytes, a read error). May throw std::bad_alloc, which the callers turn into their error.
inline std::string read_file_bytes(const std::string& path, std::uintmax_t max_bytes, const char* limit_name,
                                   std::vector<std::uint8_t>& bytes) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return path + ": no such file";
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec || size > max_bytes)
        return path + ": cannot read the file size, or the file is larger than " + limit_name;
    bytes.resize(static_cast<std::size_t>(size));
    std::ifstream in(path, std::ios::binary);
    if (!in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size())))
        return path + ": read error";
    return {};
}

// Thrown inside the loaders only; load_model turns it into a LoadError (nothing escapes).
struct LoadFailure {
    std::string problem;
};

// The loaders' one error boundary: runs load() and turns what escapes it into the result's error, "NAME:
// problem" (a LoadFailure's problem, "out of memory", or the exception's message). Nothing escapes.
template <class Result, class Load>
Result guarded_load(const std::string& name, Load&& load) {
    Result failed;
    try {
        return load();
    } catch (const LoadFailure& failure) {
        failed.error.message = name + ": " + failure.problem;
    } catch (const std::bad_alloc&) {
        failed.error.message = name + ": out of memory";
    } catch (const std::exception& e) {
        failed.error.message = name + ": " + e.what();
    }
    return failed;
}

// A position with -0.0 written as +0.0, so that meshoptimizer's bitwise position equality (Adjacency) joins
// the two zeros.
inline float canonical_zero(float x) {
    return x == 0.0f ? 0.0f : x;
}

inline bool same_position(const float* a, const float* b) {
    return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

// Appends a triangle or quad, or counts it as degenerate when two of its corners share a position (a
// zero-length edge: no area to tessellate, and an edge that adjacency could not pair).
void append_face(Model& model, const std::uint32_t* corners, unsigned corner_count);

// After loading: the model has at least one face and every value is finite.
void check_model(const Model& model);

} // namespace ctess::models::detail
