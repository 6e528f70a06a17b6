// Reads a fuzzer's bytes as typed values: every read succeeds, returning zeros once the input is used up, so
// that every input, however short, is a valid case.
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace ctess::fuzz {

class Input {
  public:
    Input(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
    std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }
    std::uint32_t u32() {
        std::uint32_t x = 0;
        for (unsigned k = 0; k < 4; ++k) x |= std::uint32_t{byte()} << (8 * k);
        return x;
    }
    // Any bit pattern: NaN payloads, infinities, denormals, negative zero.
    float float_bits() {
        const std::uint32_t x = u32();
        float f;
        std::memcpy(&f, &x, sizeof f);
        return f;
    }
    bool empty() const { return pos_ >= size_; }

  private:
    const std::uint8_t* data_;
    std::size_t size_;
    std::size_t pos_ = 0;
};

// A failed property: abort, which libFuzzer reports as a crash with the input saved.
#define CTESS_FUZZ_CHECK(cond)                                                                               \
    do {                                                                                                     \
        if (!(cond)) {                                                                                       \
            std::fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond);                    \
            std::abort();                                                                                    \
        }                                                                                                    \
    } while (0)

} // namespace ctess::fuzz
