// Encoding and decoding of model snapshots (layout in snapshot_codec.h). Every
// count is checked against the bytes left before anything is allocated, so a
// corrupt blob cannot ask for gigabytes.
#include "session/records/snapshot_codec.h"

#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "session/records/little_endian.h"
#include "session/records/session_record.h"

namespace relmap::session {
namespace {

constexpr std::string_view kMagic = "RMCS";
// Version 2 (December 2026) adds the generalisation options to the config and
// the prior's κ and the calibration to the state; version 1 blobs still decode.
constexpr std::uint32_t kVersion = 2;
constexpr std::uint32_t kVersionBeforeGeneralisation = 1;
constexpr std::size_t kChecksumBytes = 4;

constexpr auto& kSwitchBits = kPaper2018SwitchFields;
// 0 is what version 1 called "corrected": today's corrected_v1.
constexpr std::uint8_t kVariantCorrectedV1 = 0;
constexpr std::uint8_t kVariantPaper2018 = 1;
constexpr std::uint8_t kVariantCorrected = 2;
constexpr std::uint8_t kScatterFull = 0;
constexpr std::uint8_t kScatterSymmetric = 1;

std::uint32_t Crc32(std::string_view bytes) {
  // zlib takes uInt lengths; snapshots stay far below 4 GiB but feed it in
  // chunks anyway rather than truncate.
  uLong crc = crc32(0L, Z_NULL, 0);
  while (!bytes.empty()) {
    const std::size_t chunk = std::min<std::size_t>(bytes.size(), 1u << 30);
    crc = crc32(crc, reinterpret_cast<const Bytef*>(bytes.data()), static_cast<uInt>(chunk));
    bytes.remove_prefix(chunk);
  }
  return static_cast<std::uint32_t>(crc);
}

std::uint8_t VariantCode(cmm::Variant variant) {
  switch (variant) {
    case cmm::Variant::kPaper2018:
      return kVariantPaper2018;
    case cmm::Variant::kCorrectedV1:
      return kVariantCorrectedV1;
    case cmm::Variant::kCorrected:
      break;
  }
  return kVariantCorrected;
}

void EncodeConfig(const cmm::CmmConfig& config, LittleEndianWriter& out) {
  out.U8(VariantCode(config.variant));
  out.F64(config.alpha);
  out.F64(config.regularization);
  out.U64(config.seed);
  std::uint8_t bits = 0;
  for (std::size_t i = 0; i < std::size(kSwitchBits); ++i) {
    if (config.switches.*kSwitchBits[i]) bits = static_cast<std::uint8_t>(bits | (1u << i));
  }
  out.U8(bits);
  out.U8(static_cast<std::uint8_t>(config.covariance));
  out.F64(config.prior_pseudo_samples);
  out.F64(config.variance_floor);
  out.U8(static_cast<std::uint8_t>(config.acceptance));
  out.U8(static_cast<std::uint8_t>(config.split_overlap));
  out.U8(static_cast<std::uint8_t>(config.prediction));
  out.U8(config.fit_label_noise ? 1 : 0);
  out.U32(static_cast<std::uint32_t>(config.max_merge_candidates));
}

// Reads a one-byte enum of values 0 .. last.
template <typename Enum>
bool ReadEnum(LittleEndianReader& in, Enum last, Enum& out) {
  std::uint8_t v = 0;
  if (!in.U8(v) || v > static_cast<std::uint8_t>(last)) return false;
  out = static_cast<Enum>(v);
  return true;
}

Status DecodeGeneralisation(LittleEndianReader& in, cmm::CmmConfig& config) {
  std::uint8_t label_noise = 0;
  std::uint32_t max_merge_candidates = 0;
  if (!ReadEnum(in, cmm::CovarianceEstimate::kPooledPrior, config.covariance) ||
      !in.F64(config.prior_pseudo_samples) || !in.F64(config.variance_floor) ||
      !ReadEnum(in, cmm::AcceptanceTest::kLeaveOneOut, config.acceptance) ||
      !ReadEnum(in, cmm::SplitOverlap::kOtherSamples, config.split_overlap) ||
      !ReadEnum(in, cmm::Prediction::kCalibrated, config.prediction) || !in.U8(label_noise) ||
      label_noise > 1 || !in.U32(max_merge_candidates) ||
      max_merge_candidates > static_cast<std::uint32_t>(std::numeric_limits<int>::max())) {
    return DataLossError("snapshot blob has a truncated or unknown generalisation option");
  }
  config.fit_label_noise = label_noise == 1;
  config.max_merge_candidates = static_cast<int>(max_merge_candidates);
  return OkStatus();
}

Status Truncated(std::string_view what) {
  return DataLossError("snapshot blob truncated in " + std::string(what));
}

Status DecodeConfig(LittleEndianReader& in, std::uint32_t version, cmm::CmmConfig& config) {
  std::uint8_t variant = 0;
  if (!in.U8(variant)) return Truncated("the config");
  if (variant > (version == kVersionBeforeGeneralisation ? kVariantPaper2018 : kVariantCorrected)) {
    return DataLossError("snapshot blob has unknown variant " + std::to_string(variant));
  }
  config = cmm::CmmConfig::ForVariant(variant == kVariantPaper2018     ? cmm::Variant::kPaper2018
                                      : variant == kVariantCorrectedV1 ? cmm::Variant::kCorrectedV1
                                                                       : cmm::Variant::kCorrected);
  std::uint8_t bits = 0;
  if (!in.F64(config.alpha) || !in.F64(config.regularization) || !in.U64(config.seed) ||
      !in.U8(bits)) {
    return Truncated("the config");
  }
  if (version != kVersionBeforeGeneralisation) {
    if (Status status = DecodeGeneralisation(in, config); !status.ok()) return status;
  }
  if (bits >> std::size(kSwitchBits) != 0) {
    return DataLossError("snapshot blob has unknown switch bits " + std::to_string(bits));
  }
  for (std::size_t i = 0; i < std::size(kSwitchBits); ++i) {
    config.switches.*kSwitchBits[i] = ((bits >> i) & 1u) != 0;
  }
  return OkStatus();
}

// Reads a count of items of `item_bytes` each and checks that they fit in what
// is left.
bool ReadCount32(LittleEndianReader& in, std::size_t item_bytes, std::size_t& count) {
  std::uint32_t n = 0;
  if (!in.U32(n)) return false;
  count = n;
  return item_bytes == 0 || count <= in.remaining() / item_bytes;
}

Status DecodeComponent(LittleEndianReader& in, std::size_t p, cmm::ComponentSnapshot& c) {
  std::size_t m = 0;
  if (!ReadCount32(in, 4, m)) return Truncated("a component's samples");
  c.samples.resize(m);
  for (int& index : c.samples) {
    std::uint32_t v = 0;
    in.U32(v);
    if (v > static_cast<std::uint32_t>(std::numeric_limits<int>::max())) {
      return DataLossError("snapshot blob has sample index " + std::to_string(v));
    }
    index = static_cast<int>(v);
  }
  if (in.remaining() / 8 < p) return Truncated("a component's mean");
  c.mean.resize(p);
  in.F64s(c.mean);
  std::uint8_t form = 0;
  if (!in.U8(form)) return Truncated("a component's scatter");
  if (form != kScatterFull && form != kScatterSymmetric) {
    return DataLossError("snapshot blob has unknown scatter form " + std::to_string(form));
  }
  const std::size_t stored = form == kScatterFull ? p * p : p * (p + 1) / 2;
  if (in.remaining() / 8 < stored + 1) return Truncated("a component's scatter");
  c.scatter.resize(p * p);
  if (form == kScatterFull) {
    in.F64s(c.scatter);
  } else {
    for (std::size_t j = 0; j < p; ++j) {
      for (std::size_t i = j; i < p; ++i) {
        in.F64(c.scatter[i + j * p]);
        c.scatter[j + i * p] = c.scatter[i + j * p];
      }
    }
  }
  in.F64(c.weight);
  return OkStatus();
}

Status DecodeBody(LittleEndianReader& in, std::uint32_t version, cmm::CmmSnapshot& s) {
  if (Status status = DecodeConfig(in, version, s.config); !status.ok()) return status;
  std::uint32_t dimension = 0;
  std::uint64_t n = 0;
  if (!in.U32(dimension) || !in.U64(n)) return Truncated("the dataset size");
  if (dimension == 0 || dimension > static_cast<std::uint32_t>(std::numeric_limits<int>::max())) {
    return DataLossError("snapshot blob has dimension " + std::to_string(dimension));
  }
  const std::size_t p = dimension;
  s.dimension = static_cast<int>(dimension);
  // n·(8p + 1) bytes must follow; dividing keeps the check free of overflow.
  if (n > in.remaining() / (8 * p + 1)) return Truncated("the samples");
  s.features.resize(n * p);
  in.F64s(s.features);
  s.labels.resize(n);
  for (std::int8_t& label : s.labels) {
    std::uint8_t v = 0;
    in.U8(v);
    label = static_cast<std::int8_t>(v);
  }
  for (auto& components : s.components) {
    std::size_t count = 0;
    // The smallest component: its count, the mean, a symmetric scatter, the weight.
    if (!ReadCount32(in, 4 + 8 * (p + p * (p + 1) / 2 + 1) + 1, count)) {
      return Truncated("the components");
    }
    components.resize(count);
    for (cmm::ComponentSnapshot& c : components) {
      if (Status status = DecodeComponent(in, p, c); !status.ok()) return status;
    }
  }
  for (std::uint64_t& word : s.random_state) {
    if (!in.U64(word)) return Truncated("the random state");
  }
  if (!in.U64(s.splits) || !in.U64(s.merges)) return Truncated("the split and merge counts");
  if (version != kVersionBeforeGeneralisation &&
      (!in.F64(s.prior_pseudo_samples) || !in.F64(s.temperature) || !in.F64(s.label_noise))) {
    return Truncated("the prior and the calibration");
  }
  if (in.remaining() != 0) {
    return DataLossError("snapshot blob has " + std::to_string(in.remaining()) +
                         " unexpected trailing bytes");
  }
  return OkStatus();
}

// Bitwise, so that -0.0 against 0.0 (equal as numbers) keeps the full form.
bool IsSymmetric(const std::vector<double>& scatter, std::size_t p) {
  for (std::size_t j = 0; j < p; ++j) {
    for (std::size_t i = j + 1; i < p; ++i) {
      if (std::bit_cast<std::uint64_t>(scatter[i + j * p]) !=
          std::bit_cast<std::uint64_t>(scatter[j + i * p])) {
        return false;
      }
    }
  }
  return true;
}

void EncodeScatter(const std::vector<double>& scatter, std::size_t p, LittleEndianWriter& out) {
  if (!IsSymmetric(scatter, p)) {
    out.U8(kScatterFull);
    out.F64s(scatter);
    return;
  }
  out.U8(kScatterSymmetric);
  for (std::size_t j = 0; j < p; ++j) {
    for (std::size_t i = j; i < p; ++i) out.F64(scatter[i + j * p]);
  }
}

Status CheckShape(const cmm::CmmSnapshot& s) {
  if (s.dimension < 1) {
    return InvalidArgumentError("snapshot has dimension " + std::to_string(s.dimension));
  }
  const auto p = static_cast<std::size_t>(s.dimension);
  if (s.features.size() != s.labels.size() * p) {
    return InvalidArgumentError("snapshot holds " + std::to_string(s.features.size()) +
                                " feature values for " + std::to_string(s.labels.size()) +
                                " samples of dimension " + std::to_string(p));
  }
  for (const auto& of_class : s.components) {
    for (const cmm::ComponentSnapshot& c : of_class) {
      if (c.mean.size() != p || c.scatter.size() != p * p) {
        return InvalidArgumentError("snapshot component mean or scatter has the wrong size");
      }
    }
  }
  return OkStatus();
}

}  // namespace

StatusOr<std::string> EncodeSnapshot(const cmm::CmmSnapshot& s) {
  if (Status status = CheckShape(s); !status.ok()) return status;
  std::string blob;
  const auto p = static_cast<std::size_t>(s.dimension);
  std::size_t components = 0;
  for (const auto& of_class : s.components) components += of_class.size();
  blob.reserve(64 + s.features.size() * 8 + s.labels.size() * 5 + components * 8 * (p * p + p));

  LittleEndianWriter out(blob);
  blob.append(kMagic);
  out.U32(kVersion);
  EncodeConfig(s.config, out);
  out.U32(static_cast<std::uint32_t>(s.dimension));
  out.U64(s.labels.size());
  out.F64s(s.features);
  for (std::int8_t label : s.labels) out.U8(static_cast<std::uint8_t>(label));
  for (const auto& of_class : s.components) {
    out.U32(static_cast<std::uint32_t>(of_class.size()));
    for (const cmm::ComponentSnapshot& c : of_class) {
      out.U32(static_cast<std::uint32_t>(c.samples.size()));
      for (int index : c.samples) out.U32(static_cast<std::uint32_t>(index));
      out.F64s(c.mean);
      EncodeScatter(c.scatter, p, out);
      out.F64(c.weight);
    }
  }
  for (std::uint64_t word : s.random_state) out.U64(word);
  out.U64(s.splits);
  out.U64(s.merges);
  out.F64(s.prior_pseudo_samples);
  out.F64(s.temperature);
  out.F64(s.label_noise);
  out.U32(Crc32(blob));
  return blob;
}

StatusOr<cmm::CmmSnapshot> DecodeSnapshot(std::string_view blob) {
  if (blob.size() < kMagic.size() + 4 + kChecksumBytes || !blob.starts_with(kMagic)) {
    return DataLossError("snapshot blob of " + std::to_string(blob.size()) +
                         " bytes does not start with the magic \"RMCS\"");
  }
  const std::string_view body = blob.substr(0, blob.size() - kChecksumBytes);
  LittleEndianReader trailer(blob.substr(body.size()));
  std::uint32_t stored = 0;
  trailer.U32(stored);
  if (const std::uint32_t computed = Crc32(body); computed != stored) {
    return DataLossError("snapshot blob checksum mismatch: stored " + std::to_string(stored) +
                         ", computed " + std::to_string(computed));
  }
  LittleEndianReader in(body.substr(kMagic.size()));
  std::uint32_t version = 0;
  in.U32(version);
  if (version != kVersion && version != kVersionBeforeGeneralisation) {
    return DataLossError("snapshot blob has format version " + std::to_string(version) +
                         "; this build reads versions 1 and " + std::to_string(kVersion));
  }
  cmm::CmmSnapshot snapshot;
  if (Status status = DecodeBody(in, version, snapshot); !status.ok()) return status;
  return snapshot;
}

}  // namespace relmap::session
