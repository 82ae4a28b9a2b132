// The Kinect noise model's formulas against values worked out by hand from the
// published figures (Nguyen, Izadi & Lovell 2012; Khoshelham & Elberink 2012).
#include "kinect_noise_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace relmap::sim {
namespace {

// The Kinect v1's figures, typed here from the papers rather than taken from the
// code under test.
KinectNoiseModel Published() {
  return {.axial_constant = 0.0012,
          .axial_quadratic = 0.0019,
          .axial_offset = 0.4,
          .axial_grazing = 0.0001,
          .lateral_constant_px = 0.8,
          .lateral_grazing_px = 0.035,
          .ir_focal_px = 580,
          .baseline = 0.075,
          .disparity_steps_per_px = 8,
          .reference_width_px = 640};
}

TEST(KinectNoiseModel, AxialSigmaGrowsWithTheSquareOfDepthFromHalfAMetre) {
  // 0.0012 + 0.0019 (1.0 - 0.4)² = 0.0012 + 0.0019 * 0.36 = 0.001884 m.
  EXPECT_NEAR(AxialSigma(Published(), 1.0, 0.0), 0.001884, 1e-12);
  // 0.0012 + 0.0019 (2.5 - 0.4)² = 0.0012 + 0.0019 * 4.41 = 0.009579 m.
  EXPECT_NEAR(AxialSigma(Published(), 2.5, 0.0), 0.009579, 1e-12);
}

TEST(KinectNoiseModel, AxialSigmaAddsTheGrazingTermAtObliqueAngles) {
  // θ = 45°: θ / (π/2 - θ) = 1, so the term is 0.0001 / sqrt(z): at z = 1, 0.0001 m.
  EXPECT_NEAR(AxialSigma(Published(), 1.0, std::numbers::pi / 4), 0.001884 + 0.0001, 1e-12);
  // At z = 4: 0.0001 / 2 = 0.00005 m on top of 0.0012 + 0.0019 * 12.96 = 0.025824.
  EXPECT_NEAR(AxialSigma(Published(), 4.0, std::numbers::pi / 4), 0.025824 + 0.00005, 1e-12);
}

TEST(KinectNoiseModel, LateralSigmaIsInPixelsOfTheImageSize) {
  EXPECT_NEAR(LateralSigmaPixels(Published(), 0.0, 640), 0.8, 1e-12);
  // θ = 45°: 0.8 + 0.035 * 1 = 0.835 px at 640 wide, half that at 320.
  EXPECT_NEAR(LateralSigmaPixels(Published(), std::numbers::pi / 4, 640), 0.835, 1e-12);
  EXPECT_NEAR(LateralSigmaPixels(Published(), std::numbers::pi / 4, 320), 0.4175, 1e-12);
}

TEST(KinectNoiseModel, DepthStepsAreAboutSevenCentimetresAtFiveMetres) {
  // 1 / (8 * 580 * 0.075) = 1 / 348 per metre; at 5 m: 25 / 348 = 0.0718 m.
  EXPECT_NEAR(QuantisationCoefficient(Published()), 1.0 / 348.0, 1e-15);
  EXPECT_NEAR(QuantisationStep(Published(), 5.0), 25.0 / 348.0, 1e-12);
  EXPECT_NEAR(QuantisationStep(Published(), 1.0), 1.0 / 348.0, 1e-12);
}

TEST(KinectNoiseModel, DisparityAndDepthAreInverse) {
  // f b = 580 * 0.075 = 43.5 pixel metres.
  EXPECT_NEAR(DisparityOf(Published(), 1.0), 43.5, 1e-12);
  EXPECT_NEAR(DepthOf(Published(), 43.5 / 2.5), 2.5, 1e-12);
}

TEST(KinectNoiseModel, DisparitiesRoundToEighthsOfAPixel) {
  // 43.56 * 8 = 348.48 -> 348 -> 43.5; 43.57 * 8 = 348.56 -> 349 -> 43.625.
  EXPECT_EQ(QuantisedDisparity(Published(), 43.56), 43.5);
  EXPECT_EQ(QuantisedDisparity(Published(), 43.57), 43.625);
}

TEST(KinectNoiseModel, DisparitySigmaLeavesRoomForTheRoundingVariance) {
  // z = 1: σz = 0.001884, step = 1/348; before rounding sqrt(σz² - step²/12),
  // in disparity times f b / z² = 43.5.
  const double step = 1.0 / 348.0;
  const double expected = std::sqrt(0.001884 * 0.001884 - step * step / 12.0) * 43.5;
  EXPECT_NEAR(DisparitySigma(Published(), 1.0, 0.0), expected, 1e-12);
  EXPECT_NEAR(expected, 0.07358, 1e-5);
}

TEST(KinectNoiseModel, DisparitySigmaIsZeroWhenTheStepsAloneExceedSigma) {
  KinectNoiseModel fine = Published();
  fine.axial_constant = 0.0001;  // below step / sqrt(12) = 0.00083 m at 1 m
  fine.axial_quadratic = 0;
  EXPECT_EQ(DisparitySigma(fine, 1.0, 0.0), 0.0);
}

}  // namespace
}  // namespace relmap::sim
