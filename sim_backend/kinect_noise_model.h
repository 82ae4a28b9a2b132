// The depth noise of a structured-light RGB-D camera (Kinect v1 / Xtion class):
// how uncertain a depth is at distance z and incidence angle θ, and how coarse
// its steps are. Plain numbers and functions, so that the simulator's renderer
// and, from the same parameters, the server's change detector agree on it.
#pragma once

namespace relmap::sim {

// The model's coefficients. Depths z are along the optical axis (what the
// sensor reports), metres; θ is the angle between the surface normal and the
// ray, radians. Pixel figures refer to the sensor's native 640 px width
// (`reference_width_px`) and are scaled to other image sizes.
//
// The Kinect v1's published values are the defaults, filled in by
// DefaultKinectNoise() (scene_settings.h); a scene file may override each one
// (scene_schema.proto, SensorNoise).
struct KinectNoiseModel {
  // Axial noise, Nguyen, Izadi & Lovell 2012, "Modeling Kinect Sensor Noise for
  // Improved 3D Reconstruction and Tracking" (3DIMPVT), fitted for
  // 10° < θ < 60°, plus their grazing-angle term:
  //   σz(z, θ) = axial_constant + axial_quadratic (z - axial_offset)²
  //              + axial_grazing / sqrt(z) · θ² / (π/2 - θ)².
  double axial_constant;   // m (0.0012)
  double axial_quadratic;  // 1/m (0.0019)
  double axial_offset;     // m (0.4)
  double axial_grazing;    // m^1.5 (0.0001)
  // Lateral noise, same paper: σL(θ) = lateral_constant_px
  //   + lateral_grazing_px · θ / (π/2 - θ), pixels at reference_width_px.
  double lateral_constant_px;  // px (0.8)
  double lateral_grazing_px;   // px (0.035)
  // Disparity: z = f b / d with d in steps of 1 / disparity_steps_per_px pixel
  // (Khoshelham & Elberink 2012, "Accuracy and resolution of Kinect depth data
  // for indoor mapping applications", Sensors 12:1437), so a depth step is
  // z² / (disparity_steps_per_px f b), ~7 cm at 5 m.
  double ir_focal_px;             // f, the IR camera's focal length at reference_width_px (580)
  double baseline;                // b, IR projector to IR camera, metres (0.075)
  double disparity_steps_per_px;  // (8: 1/8 px)
  double reference_width_px;      // the width the pixel figures refer to (640)
};

// σz(z, θ), metres: the standard deviation of a reported depth (Nguyen et al.
// measured it on the sensor's quantised output, so it includes the steps).
double AxialSigma(const KinectNoiseModel& model, double z, double theta);

// σL(θ) in pixels of an image `image_width` pixels wide.
double LateralSigmaPixels(const KinectNoiseModel& model, double theta, double image_width);

// 1 / (disparity_steps_per_px f b), 1/m: the depth step at z is this times z².
double QuantisationCoefficient(const KinectNoiseModel& model);

// The spacing of reported depths at z, metres: QuantisationCoefficient · z².
double QuantisationStep(const KinectNoiseModel& model, double z);

// Disparity (pixels at reference_width_px) of depth z, and back: d = f b / z.
double DisparityOf(const KinectNoiseModel& model, double z);
double DepthOf(const KinectNoiseModel& model, double disparity);

// The disparity the sensor would report for `disparity`: rounded to its steps.
double QuantisedDisparity(const KinectNoiseModel& model, double disparity);

// The standard deviation of the Gaussian to add to the disparity before
// quantising it (pixels at reference_width_px) so that the reported depth's
// standard deviation is AxialSigma: rounding adds a variance of step² / 12
// (Sheppard), which is taken out first; 0 when the steps alone exceed σz.
double DisparitySigma(const KinectNoiseModel& model, double z, double theta);

}  // namespace relmap::sim
