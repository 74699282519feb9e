#pragma once
// What every fuzz target shares: the input as text, and the rule that a reader either returns or
// throws gestura::Error. Any other exception escapes LLVMFuzzerTestOneInput, which libFuzzer
// reports as a crash: a reader must turn every bad input into a located error.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "gestura/core/error.hpp"

namespace gestura::fuzz {

inline std::string_view text_of(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// Runs `read`; a gestura::Error is the expected answer to bad input.
template <class Read>
void expect_result_or_error(Read&& read) {
  try {
    read();
  } catch (const gestura::Error&) {
  }
}

}  // namespace gestura::fuzz
