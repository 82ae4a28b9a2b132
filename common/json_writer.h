// A small streaming JSON writer for reports (relmap-sim's summary, relmap-load's
// figures): nested objects and arrays, two spaces of indentation, undefined numbers
// (nullopt, NaN, ±∞) written as null.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace relmap::client {

// `value` as a JSON string: quoted, with quotes, backslashes and control characters
// escaped.
std::string JsonQuoted(std::string_view value);

class JsonWriter {
 public:
  // Inside an object every value is preceded by Key(); inside an array it is not.
  JsonWriter& Key(std::string_view key);
  JsonWriter& BeginObject();
  JsonWriter& EndObject();
  JsonWriter& BeginArray();
  JsonWriter& EndArray();
  JsonWriter& Number(double value);
  JsonWriter& Number(std::optional<double> value);
  JsonWriter& Integer(std::int64_t value);
  JsonWriter& Unsigned(std::uint64_t value);
  JsonWriter& Boolean(bool value);
  JsonWriter& Null();
  JsonWriter& String(std::string_view value);

  // The document, with a final newline.
  std::string Finish() const { return text_ + "\n"; }

 private:
  // Separator and indentation before a value or a key.
  void BeforeValue();
  void Close(char bracket);

  std::string text_;
  // Per open container: whether it has a member yet.
  std::vector<bool> has_member_;
  bool after_key_ = false;
};

}  // namespace relmap::client
