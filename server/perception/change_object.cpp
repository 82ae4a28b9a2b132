// The objects of a frame's supervoxels: the connected parts of their adjacency through
// locally convex or smooth connections (LCCP, Stein et al. 2014).
#include "perception/change_object.h"

#include <cmath>
#include <deque>
#include <numbers>

namespace relmap::perception {

bool OnOneObject(const Supervoxel& a, const Supervoxel& b, double smooth_angle_deg) {
  const Eigen::Vector3f na = a.normal.normalized(), nb = b.normal.normalized();
  const Eigen::Vector3f between = a.centroid - b.centroid;
  if (between.squaredNorm() == 0.0f) return true;
  const Eigen::Vector3f d = between.normalized();
  // Eq. (3): alpha_a < alpha_b, the angles of the normals to d.
  if (na.dot(d) > nb.dot(d)) return true;
  // Eq. (4): a concave connection still joins when the normals barely differ.
  const double cos_smooth = std::cos(smooth_angle_deg * std::numbers::pi / 180.0);
  return static_cast<double>(na.dot(nb)) >= cos_smooth;
}

std::vector<std::uint32_t> ObjectLabels(const std::vector<Supervoxel>& frame,
                                        double smooth_angle_deg) {
  constexpr std::uint32_t kUnlabelled = ~std::uint32_t{0};
  std::vector<std::uint32_t> labels(frame.size(), kUnlabelled);
  std::uint32_t next_label = 0;
  std::deque<std::uint32_t> open;
  for (std::uint32_t seed = 0; seed < frame.size(); ++seed) {
    if (labels[seed] != kUnlabelled) continue;
    labels[seed] = next_label;
    open.push_back(seed);
    while (!open.empty()) {
      const std::uint32_t id = open.front();
      open.pop_front();
      for (const std::uint32_t next : frame[id].neighbours) {
        if (next >= frame.size() || labels[next] != kUnlabelled) continue;
        if (!OnOneObject(frame[id], frame[next], smooth_angle_deg)) continue;
        labels[next] = next_label;
        open.push_back(next);
      }
    }
    ++next_label;
  }
  return labels;
}

std::vector<std::uint32_t> ObjectOf(const std::vector<Supervoxel>& frame, std::uint32_t target_id,
                                    double smooth_angle_deg) {
  if (target_id >= frame.size()) return {};
  const std::vector<std::uint32_t> labels = ObjectLabels(frame, smooth_angle_deg);
  std::vector<std::uint32_t> object{target_id};
  for (std::uint32_t id = 0; id < frame.size(); ++id) {
    if (id != target_id && labels[id] == labels[target_id]) object.push_back(id);
  }
  return object;
}

}  // namespace relmap::perception
