// A sample's identity is its label and the bytes of its values.
#include "chaos/chaos_ledger.h"

#include <algorithm>

namespace relmap::chaos {
namespace {

std::string KeyOf(const v1::LabelledFeature& sample) {
  const auto& values = sample.feature().values();
  std::string key(1, static_cast<char>(sample.label()));
  key.append(reinterpret_cast<const char*>(values.data()),
             static_cast<std::size_t>(values.size()) * sizeof(double));
  return key;
}

}  // namespace

LedgerCheck& LedgerCheck::operator+=(const LedgerCheck& other) {
  acknowledged += other.acknowledged;
  stored += other.stored;
  lost += other.lost;
  duplicated += other.duplicated;
  unexpected += other.unexpected;
  return *this;
}

void Ledger::Acknowledged(const v1::LabelledFeature& sample) {
  ++expected_[KeyOf(sample)].acknowledged;
  ++acknowledged_;
}

// A refused sample has no entry of its own: stored, it counts as unexpected, unless
// an acknowledged copy of the same sample accounts for it.
void Ledger::Refused(const v1::LabelledFeature& /*sample*/) { ++refused_; }

void Ledger::Unsettled(const v1::LabelledFeature& sample) {
  ++expected_[KeyOf(sample)].unsettled;
  ++unsettled_;
}

LedgerCheck Ledger::Check(
    const google::protobuf::RepeatedPtrField<v1::LabelledFeature>& stored) const {
  std::map<std::string, std::uint64_t> copies;
  for (const v1::LabelledFeature& sample : stored) ++copies[KeyOf(sample)];
  LedgerCheck check;
  check.acknowledged = acknowledged_;
  check.stored = static_cast<std::uint64_t>(stored.size());
  for (const auto& [key, expected] : expected_) {
    const auto found = copies.find(key);
    const std::uint64_t present = found == copies.end() ? 0 : found->second;
    check.lost += expected.acknowledged - std::min(present, expected.acknowledged);
  }
  for (const auto& [key, present] : copies) {
    const auto known = expected_.find(key);
    const Expected expected = known == expected_.end() ? Expected{} : known->second;
    const std::uint64_t allowed = expected.acknowledged + expected.unsettled;
    if (present <= allowed) continue;
    (expected.acknowledged > 0 ? check.duplicated : check.unexpected) += present - allowed;
  }
  return check;
}

}  // namespace relmap::chaos
