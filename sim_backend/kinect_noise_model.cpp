// The Kinect noise model's formulas (see kinect_noise_model.h for the sources).
#include "kinect_noise_model.h"

#include <algorithm>
#include <cmath>

namespace relmap::sim {
namespace {
constexpr double kHalfPi = 1.57079632679489661923;
}  // namespace

double AxialSigma(const KinectNoiseModel& m, double z, double theta) {
  const double from_offset = z - m.axial_offset;
  const double grazing = theta / (kHalfPi - theta);
  return m.axial_constant + m.axial_quadratic * from_offset * from_offset +
         m.axial_grazing / std::sqrt(z) * grazing * grazing;
}

double LateralSigmaPixels(const KinectNoiseModel& m, double theta, double image_width) {
  const double at_reference =
      m.lateral_constant_px + m.lateral_grazing_px * theta / (kHalfPi - theta);
  return at_reference * image_width / m.reference_width_px;
}

double QuantisationCoefficient(const KinectNoiseModel& m) {
  return 1.0 / (m.disparity_steps_per_px * m.ir_focal_px * m.baseline);
}

double QuantisationStep(const KinectNoiseModel& m, double z) {
  return QuantisationCoefficient(m) * z * z;
}

double DisparityOf(const KinectNoiseModel& m, double z) { return m.ir_focal_px * m.baseline / z; }

double DepthOf(const KinectNoiseModel& m, double disparity) {
  return m.ir_focal_px * m.baseline / disparity;
}

double QuantisedDisparity(const KinectNoiseModel& m, double disparity) {
  return std::round(disparity * m.disparity_steps_per_px) / m.disparity_steps_per_px;
}

double DisparitySigma(const KinectNoiseModel& m, double z, double theta) {
  const double sigma_z = AxialSigma(m, z, theta);
  const double step = QuantisationStep(m, z);
  const double before_rounding = std::sqrt(std::max(0.0, sigma_z * sigma_z - step * step / 12.0));
  // First order: |dd/dz| = f b / z².
  return before_rounding * m.ir_focal_px * m.baseline / (z * z);
}

}  // namespace relmap::sim
