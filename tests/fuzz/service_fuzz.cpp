// libFuzzer target: the request validation of every RPC of RelevanceService, in
// process (service_harness.h). Input, an envelope:
//   u8 rpc (mod 10, the proto's order), u8 flags: bit 0 create a session first,
//   bit 1 put its id (and its frame's) in the request, bit 2 send its token,
//   bit 3 map a frame on it first;
//   with bit 0: u16 length (little endian) and that many bytes of the
//   CreateSessionRequest of the first session; with bit 3 as well: u16 length and
//   the ComputeMapsRequest of its first frame;
//   the rest: the serialized request of the RPC.
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_input.h"
#include "fuzz/service_harness.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  relmap::fuzz::FuzzInput input(data, size);
  const auto rpc = static_cast<relmap::fuzz::Rpc>(input.Byte() % relmap::fuzz::kRpcCount);
  const std::uint8_t flags = input.Byte();
  relmap::fuzz::CallSetup setup;
  setup.create_session = (flags & 1) != 0;
  setup.use_session_id = (flags & 2) != 0;
  setup.send_token = (flags & 4) != 0;
  if (setup.create_session) {
    const std::size_t length = input.Byte() | std::size_t{input.Byte()} << 8;
    setup.create_request = input.Bytes(length);
    if ((flags & 8) != 0)
      setup.first_frame = input.Bytes(input.Byte() | std::size_t{input.Byte()} << 8);
  }
  // An input that does not parse is not a request; -1 keeps it out of the corpus.
  return relmap::fuzz::CallOnce(rpc, input.Rest(), setup) ? 0 : -1;
}
