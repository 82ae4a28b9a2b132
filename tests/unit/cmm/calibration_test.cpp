// Calibration of the prediction (docs/method.md §3.3): the temperature and the
// label-noise rate, against hand-computed optima.
#include "cmm/calibration.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace relmap::cmm {
namespace {

TEST(FitTemperature, IsOneWhenEverySampleIsPredictedRight) {
  const std::vector<double> z{3.0, 0.5, 8.0};
  EXPECT_EQ(FitTemperature(z), 1.0);
}

TEST(FitTemperature, IsZeroWhenTheLogOddsPointTheWrongWay) {
  // d/dτ at τ = 0 is Σ z/2 < 0: no positive temperature helps.
  const std::vector<double> z{-3.0, -1.0, 2.0};
  EXPECT_EQ(FitTemperature(z), 0.0);
}

TEST(FitTemperature, FindsTheRootOfTheDerivative) {
  // z = (2, 2, −2): d/dτ = 2·2σ(−2τ) − 2σ(2τ) = 0 ⇔ 2/(1 + u) = 1/(1 + 1/u),
  // u = e^{2τ} ⇔ u² − u − 2 = 0 ⇔ u = 2: τ = ln 2 / 2 = 0.346574.
  const std::vector<double> z{2.0, 2.0, -2.0};
  EXPECT_NEAR(FitTemperature(z), std::log(2.0) / 2.0, 1e-9);
  EXPECT_NEAR(FitTemperature(z, {}, 0.9), std::log(2.0) / 2.0, 1e-9);  // any start
}

TEST(FitTemperature, WeighsTheSamples) {
  // Weights (1, 1, 2) are z = (2, 2, −2, −2): the derivative 4σ(−2τ) − 4σ(2τ)
  // vanishes at τ = 0 and is negative beyond: τ = 0.
  const std::vector<double> z{2.0, 2.0, -2.0};
  const std::vector<double> w{1.0, 1.0, 2.0};
  EXPECT_NEAR(FitTemperature(z, w), 0.0, 1e-9);
}

TEST(LogCalibratedProbability, MixesTheModelWithCoinFlips) {
  // ε/2 + (1 − ε)σ(τz): at z = 0, 0.1 + 0.8·0.5 = 0.5; at τz = ln 3
  // (σ = 0.75), 0.1 + 0.8·0.75 = 0.7.
  EXPECT_NEAR(LogCalibratedProbability(0.0, {1.0, 0.2}), std::log(0.5), 1e-15);
  EXPECT_NEAR(LogCalibratedProbability(std::log(3.0) / 0.5, {0.5, 0.2}), std::log(0.7), 1e-15);
  EXPECT_NEAR(LogCalibratedProbability(std::log(3.0), {1.0, 0.0}), std::log(0.75), 1e-15);
}

TEST(FitCalibration, EstimatesTheShareOfLabelsNoModelExplains) {
  // 90 samples confidently right (z = 20), 10 confidently wrong (z = −20):
  // F(ε) ≈ 90 log(1 − ε/2) + 10 log(ε/2), F′ = 0 ⇔ 10/ε = 45/(1 − ε/2) ⇔
  // ε = 0.2, with τ = 1: the 10 wrong labels are explained as noise.
  std::vector<double> z(100, 20.0);
  for (int i = 0; i < 10; ++i) z[i] = -20.0;
  Calibration c{1.0, 0.0};
  for (int round = 0; round < 10; ++round) c = FitCalibration(z, c);  // warm starts
  EXPECT_NEAR(c.label_noise, 0.2, 1e-3);
  // Without ε the ten wrong labels drag τ down to 9σ(−20τ) = σ(20τ), i.e.
  // τ = ln 9/20 = 0.110; with it the objective is flat in τ once every log-odds
  // is saturated, and τ stays well above that.
  EXPECT_NEAR(FitTemperature(z), std::log(9.0) / 20.0, 1e-9);
  EXPECT_GT(c.temperature, 0.3);
}

}  // namespace
}  // namespace relmap::cmm

namespace relmap::cmm {
namespace {

TEST(LogProbabilityAndSlope, HasTheBitsOfTheTwoCallsItReplaces) {
  for (const double tau : {0.0, 1e-3, 0.3131888582887193, 0.5, 1.0}) {
    for (const double z : {-800.0, -37.5, -1.0, -1e-9, -0.0, 0.0, 1e-9, 0.7, 20.0, 745.0}) {
      const ProbabilityAndSlope at = LogProbabilityAndSlope(z, tau);
      EXPECT_EQ(at.log_probability, LogCalibratedProbability(z, {tau, 0.0})) << z << " " << tau;
      EXPECT_EQ(at.slope, TemperatureSlope(z, tau)) << z << " " << tau;
    }
  }
}

}  // namespace
}  // namespace relmap::cmm
