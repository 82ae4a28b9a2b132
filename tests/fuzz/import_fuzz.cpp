// libFuzzer target: the import of an exported session (ImportSession), the one
// request that carries a whole session's state: the input is a serialized
// ImportSessionRequest, answered by an in-process service (service_harness.h).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz/service_harness.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view request(reinterpret_cast<const char*>(data), size);
  return relmap::fuzz::CallOnce(relmap::fuzz::Rpc::kImportSession, request, {}) ? 0 : -1;
}
