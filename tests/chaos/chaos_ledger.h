// What one session's client was told about its writes, and the check of a session's
// stored samples against it: every acknowledged sample stored exactly once, nothing
// the server refused stored at all.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "relmap/v1/relevance_service.pb.h"

namespace relmap::chaos {

// How the stored samples of a session compare with its ledger.
struct LedgerCheck {
  std::uint64_t acknowledged = 0;  // samples the server acknowledged
  std::uint64_t stored = 0;        // samples the session holds
  std::uint64_t lost = 0;          // acknowledged, not stored
  std::uint64_t duplicated = 0;    // acknowledged, stored more than once
  std::uint64_t unexpected = 0;    // stored, but refused or never sent

  LedgerCheck& operator+=(const LedgerCheck& other);
};

class Ledger {
 public:
  // The server acknowledged `sample`: it must be stored exactly once.
  void Acknowledged(const v1::LabelledFeature& sample);
  // The server answered that it did not learn `sample` (an outcome on a frame it no
  // longer has): it must not be stored.
  void Refused(const v1::LabelledFeature& sample);
  // The client gave up on `sample` without an answer: stored at most once.
  void Unsettled(const v1::LabelledFeature& sample);

  std::uint64_t acknowledged() const { return acknowledged_; }
  std::uint64_t refused() const { return refused_; }
  std::uint64_t unsettled() const { return unsettled_; }

  // Compares `stored` (ExportSession's samples) with what was recorded. Samples are
  // told apart by their label and the exact bits of their values, so that two
  // acknowledged outcomes of the same supervoxel with the same label are two expected
  // copies of one sample.
  LedgerCheck Check(const google::protobuf::RepeatedPtrField<v1::LabelledFeature>& stored) const;

 private:
  struct Expected {
    std::uint64_t acknowledged = 0;
    std::uint64_t unsettled = 0;
  };
  std::map<std::string, Expected> expected_;
  std::uint64_t acknowledged_ = 0;
  std::uint64_t refused_ = 0;
  std::uint64_t unsettled_ = 0;
};

}  // namespace relmap::chaos
