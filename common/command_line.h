// What the command-line tools share: bad input ends the program with exit code 2
// and a one-line message, and flag values are parsed strictly.
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <optional>
#include <string>
#include <string_view>

namespace relmap::tools {

// Prints "<program>: <message>" to standard error.
inline void PrintError(std::string_view program, const char* message) noexcept {
  std::fprintf(stderr, "%.*s: %s\n", static_cast<int>(program.size()), program.data(), message);
}

// Prints "<program>: <message>" to standard error and exits with code 2.
[[noreturn]] inline void ExitWithError(std::string_view program, const std::string& message) {
  PrintError(program, message.c_str());
  std::exit(2);
}

// `text` as a number, or ExitWithError when any of it is not part of one.
inline double ParseNumberOrExit(std::string_view program, std::string_view flag, const char* text) {
  char* end = nullptr;
  const double value = std::strtod(text, &end);
  if (end == text || *end != '\0') {
    ExitWithError(program, std::string(flag) + " expects a number, got '" + text + "'");
  }
  return value;
}

// `text` as a whole number in [minimum, maximum]; nullopt when it is not a number, has a
// fraction or lies outside (the caller says so with its flag's usage).
inline std::optional<long long> ParseWholeNumber(const char* text, long long minimum,
                                                 long long maximum) {
  char* end = nullptr;
  const double value = std::strtod(text, &end);
  if (end == text || *end != '\0' || value != std::floor(value) ||
      value < static_cast<double>(minimum) || value > static_cast<double>(maximum)) {
    return std::nullopt;
  }
  return static_cast<long long>(value);
}

// `body()`'s exit code, or 1 with "<program>: <what>" on standard error when it throws:
// a program's main runs its work through this, so that an exception nobody expected
// (std::bad_alloc, a library's error) ends it with a message rather than std::terminate.
template <typename Body>
int ExitCodeOf(std::string_view program, Body&& body) noexcept {
  try {
    return body();
  } catch (const std::exception& error) {
    PrintError(program, error.what());
  } catch (...) {
    PrintError(program, "unknown exception");
  }
  return 1;
}

}  // namespace relmap::tools
