// libFuzzer target: a stored classifier snapshot (session/records/snapshot_codec.h), decoded,
// restored as a model and asked one prediction. The input is the blob without its
// CRC-32, which the target appends, so that mutations reach the fields behind it.
#include <zlib.h>

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <string>

#include "cmm/collaborative_mixture_models.h"
#include "session/records/snapshot_codec.h"

namespace {

// The widest feature vector a session accepts (session/session_settings.cpp).
constexpr int kMaxFeatureDimension = 4096;

// The blob as the store keeps it: `body` and its CRC-32 (zlib's), little endian.
std::string WithChecksum(const std::uint8_t* body, std::size_t size) {
  std::string blob(reinterpret_cast<const char*>(body), size);
  const auto crc = static_cast<std::uint32_t>(crc32(0L, body, static_cast<uInt>(size)));
  for (int shift = 0; shift < 32; shift += 8) blob.push_back(static_cast<char>(crc >> shift));
  return blob;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto snapshot = relmap::session::DecodeSnapshot(WithChecksum(data, size));
  if (!snapshot.ok()) return 0;
  auto model = relmap::cmm::CollaborativeMixtureModels::Restore(*snapshot);
  if (!model.ok()) return 0;
  const int p = model->dimension();
  if (p > 0 && p <= kMaxFeatureDimension) model->Predict(Eigen::MatrixXd::Zero(1, p));
  // What decoded encodes again, and that decodes.
  const auto again = relmap::session::EncodeSnapshot(*snapshot);
  if (again.ok() && !relmap::session::DecodeSnapshot(*again).ok()) __builtin_trap();
  return 0;
}
