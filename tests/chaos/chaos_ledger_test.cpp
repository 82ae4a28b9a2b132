// The check of a session's stored samples against what its client was told.
#include "chaos/chaos_ledger.h"

#include <gtest/gtest.h>

#include <initializer_list>

namespace relmap::chaos {
namespace {

v1::LabelledFeature Sample(std::initializer_list<double> values,
                           v1::Label label = v1::LABEL_MOVEABLE) {
  v1::LabelledFeature sample;
  sample.set_label(label);
  for (double value : values) sample.mutable_feature()->add_values(value);
  return sample;
}

google::protobuf::RepeatedPtrField<v1::LabelledFeature> Stored(
    std::initializer_list<v1::LabelledFeature> samples) {
  google::protobuf::RepeatedPtrField<v1::LabelledFeature> stored;
  for (const v1::LabelledFeature& sample : samples) *stored.Add() = sample;
  return stored;
}

TEST(Ledger, AcknowledgedSamplesStoredOnceAreNeitherLostNorDuplicated) {
  Ledger ledger;
  ledger.Acknowledged(Sample({0.1, 0.2}));
  ledger.Acknowledged(Sample({0.3, 0.4}));
  const LedgerCheck check = ledger.Check(Stored({Sample({0.3, 0.4}), Sample({0.1, 0.2})}));
  EXPECT_EQ(check.acknowledged, 2u);
  EXPECT_EQ(check.stored, 2u);
  EXPECT_EQ(check.lost, 0u);
  EXPECT_EQ(check.duplicated, 0u);
  EXPECT_EQ(check.unexpected, 0u);
}

TEST(Ledger, AnAcknowledgedSampleNotStoredIsLost) {
  Ledger ledger;
  ledger.Acknowledged(Sample({0.1, 0.2}));
  ledger.Acknowledged(Sample({0.3, 0.4}));
  const LedgerCheck check = ledger.Check(Stored({Sample({0.1, 0.2})}));
  EXPECT_EQ(check.lost, 1u);
  EXPECT_EQ(check.duplicated, 0u);
}

TEST(Ledger, AnAcknowledgedSampleStoredTwiceIsDuplicated) {
  Ledger ledger;
  ledger.Acknowledged(Sample({0.1, 0.2}));
  const LedgerCheck check = ledger.Check(Stored({Sample({0.1, 0.2}), Sample({0.1, 0.2})}));
  EXPECT_EQ(check.lost, 0u);
  EXPECT_EQ(check.duplicated, 1u);
}

// Two outcomes of the same supervoxel with the same label are one sample acknowledged
// twice: two copies are expected, one is a loss, three a duplicate.
TEST(Ledger, ASampleAcknowledgedTwiceIsExpectedTwice) {
  Ledger ledger;
  ledger.Acknowledged(Sample({0.5}));
  ledger.Acknowledged(Sample({0.5}));
  EXPECT_EQ(ledger.Check(Stored({Sample({0.5}), Sample({0.5})})).lost, 0u);
  EXPECT_EQ(ledger.Check(Stored({Sample({0.5})})).lost, 1u);
  EXPECT_EQ(ledger.Check(Stored({Sample({0.5}), Sample({0.5}), Sample({0.5})})).duplicated, 1u);
}

TEST(Ledger, ARefusedSampleStoredIsUnexpected) {
  Ledger ledger;
  ledger.Refused(Sample({0.7}));
  const LedgerCheck check = ledger.Check(Stored({Sample({0.7})}));
  EXPECT_EQ(check.unexpected, 1u);
  EXPECT_EQ(check.duplicated, 0u);
  EXPECT_EQ(ledger.refused(), 1u);
}

TEST(Ledger, ASampleNeverSentIsUnexpected) {
  const Ledger ledger;
  EXPECT_EQ(ledger.Check(Stored({Sample({0.9})})).unexpected, 1u);
}

// A write given up without an answer may or may not have been stored, but once only.
TEST(Ledger, AnUnsettledSampleMayBeStoredAtMostOnce) {
  Ledger ledger;
  ledger.Unsettled(Sample({0.2}));
  EXPECT_EQ(ledger.Check(Stored({})).lost, 0u);
  const LedgerCheck once = ledger.Check(Stored({Sample({0.2})}));
  EXPECT_EQ(once.lost + once.duplicated + once.unexpected, 0u);
  EXPECT_EQ(ledger.Check(Stored({Sample({0.2}), Sample({0.2})})).unexpected, 1u);
}

TEST(Ledger, TheLabelIsPartOfASamplesIdentity) {
  Ledger ledger;
  ledger.Acknowledged(Sample({0.1}, v1::LABEL_MOVEABLE));
  const LedgerCheck check = ledger.Check(Stored({Sample({0.1}, v1::LABEL_NOT_MOVEABLE)}));
  EXPECT_EQ(check.lost, 1u);
  EXPECT_EQ(check.unexpected, 1u);
}

}  // namespace
}  // namespace relmap::chaos
