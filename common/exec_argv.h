// The argument vector that execv, execvp and posix_spawn take, from owned strings.
#pragma once

#include <string>
#include <vector>

namespace relmap {

// Pointers into `words`, then the terminating null. `words` must outlive the result
// unchanged. Build it before fork(): the child of a multi-threaded process may
// deadlock on malloc's locks if it allocates.
inline std::vector<char*> ExecArgv(std::vector<std::string>& words) {
  std::vector<char*> argv;
  argv.reserve(words.size() + 1);
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  return argv;
}

}  // namespace relmap
