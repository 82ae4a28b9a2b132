// The stored form of a CmmSnapshot: a compact, versioned, little-endian binary
// blob with a CRC-32, decoded bit for bit or refused with DATA_LOSS.
#pragma once

#include <string>
#include <string_view>

#include "cmm/snapshot.h"
#include "common/status.h"

namespace relmap::session {

// Layout, version 1 (integers unsigned little-endian, doubles IEEE-754 bits):
//   "RMCS"  u32 version
//   config: u8 variant, f64 alpha, f64 regularization, u64 seed, u8 switch bits
//   u32 dimension p, u64 samples n, n·p f64 features, n u8 labels
//   per class: u32 components, each: u32 m, m u32 sample indices, p f64 mean,
//              u8 scatter form, scatter, f64 weight
//     scatter form 1: the scatter is symmetric bit for bit, and only its lower
//     triangle is stored, column by column (p(p+1)/2 f64: 45% smaller at p = 48);
//     form 0: all p·p f64, column-major.
//   4 u64 random state, u64 splits, u64 merges
//   u32 CRC-32 (zlib's) of every byte before it
// Version 2 (today's): variant 0 = corrected_v1 (what version 1 called
// corrected), 1 = paper2018, 2 = corrected; after the switch bits the config
// has u8 covariance, f64 prior_pseudo_samples, f64 variance_floor,
// u8 acceptance, u8 split_overlap, u8 prediction, u8 fit_label_noise,
// u32 max_merge_candidates; after the
// merges, f64 κ of the prior, f64 temperature, f64 label noise. A version 1
// blob decodes with its variant's preset for the options it lacks.
// A snapshot whose vectors do not match its dimension and sample count →
// INVALID_ARGUMENT (it would not decode).
StatusOr<std::string> EncodeSnapshot(const cmm::CmmSnapshot& snapshot);

// The snapshot `blob` encodes. A wrong magic, checksum or length, an unknown
// version or an impossible value → DATA_LOSS saying which.
StatusOr<cmm::CmmSnapshot> DecodeSnapshot(std::string_view blob);

}  // namespace relmap::session
