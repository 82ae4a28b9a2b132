// The CSV reader of relmap-cmm: every malformed input is an error that names
// the file and line, and what is written reads back exactly.
#include "common/labelled_csv.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "common/random.h"

namespace relmap::datasets {
namespace {

StatusOr<LabelledSamples> Parse(const std::string& text) {
  std::istringstream in(text);
  return ParseLabelledCsv(in, "data.csv");
}

void ExpectError(const std::string& text, const std::string& message) {
  const auto parsed = Parse(text);
  ASSERT_FALSE(parsed.ok());
  EXPECT_EQ(parsed.status().code(), StatusCode::kInvalidArgument);
  EXPECT_EQ(parsed.status().message(), message);
}

TEST(ReadLabelledCsv, ReadsRowsWithAnOptionalHeader) {
  const auto parsed = Parse("label,a,b\n1,0.5,2\n0, -1e-3 ,4\n\n");
  ASSERT_TRUE(parsed.ok()) << parsed.status().message();
  EXPECT_EQ(parsed->labels, (std::vector<int>{1, 0}));
  EXPECT_EQ(parsed->features.rows(), 2);
  EXPECT_EQ(parsed->features.cols(), 2);
  EXPECT_DOUBLE_EQ(parsed->features(1, 0), -1e-3);
}

TEST(ReadLabelledCsv, RaggedRowNamesItsLine) {
  ExpectError("1,0.5,2\n0,1\n", "data.csv:2: row has 1 features, earlier rows have 2");
}

TEST(ReadLabelledCsv, NonNumericValueNamesItsLineAndField) {
  ExpectError("1,0.5,x2\n", "data.csv:1: field 3 'x2' is not a number");
}

TEST(ReadLabelledCsv, NonFiniteValueIsRefused) {
  ExpectError("1,0.5,2\n0,nan,1\n", "data.csv:2: field 2 'nan' is not finite");
  ExpectError("0,inf,1\n", "data.csv:1: field 2 'inf' is not finite");
}

TEST(ReadLabelledCsv, LabelMustBeZeroOrOne) {
  ExpectError("2,0.5\n", "data.csv:1: label '2' is not 0 or 1");
  ExpectError("1.0,0.5\n", "data.csv:1: label '1.0' is not 0 or 1");
}

TEST(ReadLabelledCsv, EmptyFileIsAnError) {
  ExpectError("", "data.csv: no data row");
  ExpectError("label,f1\n", "data.csv: no data row");
}

TEST(ReadLabelledCsv, MissingFileIsNotFound) {
  EXPECT_EQ(ReadLabelledCsv("/nonexistent/train.csv").status().code(), StatusCode::kNotFound);
}

TEST(WriteLabelledCsv, RoundTripsExactly) {
  // 50 samples of 5 random doubles of every magnitude from 1e-12 to 1e12, either sign.
  Random random(7);
  LabelledSamples original;
  original.features.resize(50, 5);
  for (Eigen::Index i = 0; i < 50; ++i) {
    original.labels.push_back(static_cast<int>(random.UniformIndex(2)));
    for (Eigen::Index k = 0; k < 5; ++k) {
      const double magnitude = std::pow(10.0, -12.0 + 24.0 * random.UniformUnit());
      original.features(i, k) = (random.UniformUnit() - 0.5) * magnitude;
    }
  }
  std::stringstream buffer;
  WriteLabelledCsv(original, buffer);
  const auto read = ParseLabelledCsv(buffer, "buffer");
  ASSERT_TRUE(read.ok()) << read.status().message();
  EXPECT_EQ(read->labels, original.labels);
  EXPECT_TRUE((read->features.array() == original.features.array()).all());
}

}  // namespace
}  // namespace relmap::datasets
