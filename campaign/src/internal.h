// Internals of the campaign module shared by its source files.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace highlift::campaign::detail {

/// FNV-1a, 64 bits: a stable hash of text (campaign ids, per-case seeds).
inline std::uint64_t Hash64(std::string_view text) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned char c : text) {
    h ^= c;
    h *= 0x100000001b3ULL;
  }
  return h;
}

/// SplitMix64 finaliser: well-mixed 64 bits from any 64-bit input.
inline std::uint64_t SplitMix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

/// 16 lower-case hex digits.
inline std::string Hex(std::uint64_t value) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string s(16, '0');
  for (int i = 15; i >= 0; --i, value >>= 4) s[static_cast<std::size_t>(i)] = kDigits[value & 15];
  return s;
}

/// The draws a sample's label says were rejected for breaking a parameter relation
/// (Plan::SampleOf appends ", N rejected draw(s)"); 0 when it says none.
int RejectedDraws(const std::string& label);

}  // namespace highlift::campaign::detail
