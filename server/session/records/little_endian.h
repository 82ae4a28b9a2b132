// Byte-order-independent encoding of integers and IEEE doubles as little-endian
// bytes: the on-disk form of sample features and model snapshots.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace relmap::session {

// Appends values to a byte string. Doubles are written as their IEEE-754 bit
// pattern, so -0.0, denormals and NaN payloads survive unchanged.
class LittleEndianWriter {
 public:
  explicit LittleEndianWriter(std::string& out) : out_(out) {}

  void U8(std::uint8_t v) { out_.push_back(static_cast<char>(v)); }
  void U32(std::uint32_t v) { Unsigned(v, 4); }
  void U64(std::uint64_t v) { Unsigned(v, 8); }
  void F64(double v) { U64(std::bit_cast<std::uint64_t>(v)); }
  void F64s(std::span<const double> values) {
    for (double v : values) F64(v);
  }

 private:
  void Unsigned(std::uint64_t v, int bytes) {
    for (int i = 0; i < bytes; ++i) out_.push_back(static_cast<char>((v >> (8 * i)) & 0xFFu));
  }
  std::string& out_;
};

// Reads values back from a byte string. Every read checks the remaining length
// and returns false once the input is exhausted (the value is then unspecified),
// so a truncated blob is detected instead of read past its end.
class LittleEndianReader {
 public:
  explicit LittleEndianReader(std::string_view in) : in_(in) {}

  std::size_t remaining() const { return in_.size(); }

  bool U8(std::uint8_t& v) {
    std::uint64_t wide = 0;
    const bool ok = Unsigned(wide, 1);
    v = static_cast<std::uint8_t>(wide);
    return ok;
  }
  bool U32(std::uint32_t& v) {
    std::uint64_t wide = 0;
    const bool ok = Unsigned(wide, 4);
    v = static_cast<std::uint32_t>(wide);
    return ok;
  }
  bool U64(std::uint64_t& v) { return Unsigned(v, 8); }
  bool F64(double& v) {
    std::uint64_t bits = 0;
    const bool ok = U64(bits);
    v = std::bit_cast<double>(bits);
    return ok;
  }
  // Reads values.size() doubles.
  bool F64s(std::span<double> values) {
    if (in_.size() / 8 < values.size()) return false;
    for (double& v : values) F64(v);
    return true;
  }

 private:
  bool Unsigned(std::uint64_t& v, std::size_t bytes) {
    if (in_.size() < bytes) return false;
    v = 0;
    for (std::size_t i = 0; i < bytes; ++i) {
      v |= static_cast<std::uint64_t>(static_cast<unsigned char>(in_[i])) << (8 * i);
    }
    in_.remove_prefix(bytes);
    return true;
  }
  std::string_view in_;
};

}  // namespace relmap::session
