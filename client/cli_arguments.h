// The relmap CLI's command line after its command words: positional words and
// `--name value` flags, with environment fallbacks. Misuse ends the program with
// exit code 2 and the usage text.
#pragma once

#include <initializer_list>
#include <map>
#include <string>
#include <vector>

namespace relmap::client {

// The usage text of the relmap CLI.
extern const char kCliUsage[];

// Prints "relmap: <message>" and the usage, exits 2.
[[noreturn]] void UsageError(const std::string& message);

class CommandLine {
 public:
  // argv[first..argc): a word starting with "--" takes the next word as its value.
  CommandLine(int argc, char** argv, int first);

  // Exits with a usage error for a flag not in `allowed` (nor global), or for more
  // than `max_positional` words.
  void Expect(std::initializer_list<const char*> allowed, std::size_t max_positional) const;

  std::size_t positional_count() const { return positional_.size(); }
  // Positional word `index`, named `name` in the error when it is missing.
  const std::string& Positional(std::size_t index, const char* name) const;

  bool Has(const std::string& flag) const { return flags_.count(flag) > 0; }
  // The flag's value, else the environment variable's (if given and set), else `fallback`.
  std::string Get(const std::string& flag, const char* environment = nullptr,
                  const std::string& fallback = "") const;
  // As Get, but a usage error when it ends up empty.
  std::string Required(const std::string& flag, const char* environment = nullptr) const;
  // The flag as a number (a usage error if it is not one).
  double Number(const std::string& flag) const;

 private:
  std::vector<std::string> positional_;
  std::map<std::string, std::string> flags_;
};

}  // namespace relmap::client
