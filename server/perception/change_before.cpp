// Packing a frame for the change detector, and unpacking one target.
#include "perception/change_before.h"

#include <bit>

#include "perception/change_object.h"
#include "perception/word_planes.h"

namespace relmap::perception {

ChangeBefore ChangeBefore::Of(const Frame& frame, const ChangeDetectorConfig& config) {
  ChangeBefore before;
  const bool reads_colour =
      config.method == ChangeMethod::kVisibility && config.colour_tolerance > 0;
  before.cloud_ = CompactCloud::Of(frame.cloud, reads_colour);
  const std::vector<std::int32_t>& labels = frame.segmentation.point_labels;
  std::vector<std::uint32_t> words(labels.size());
  for (std::size_t i = 0; i < labels.size(); ++i) words[i] = static_cast<std::uint32_t>(labels[i]);
  before.point_labels_ = PackWords(words);
  before.points_ = labels.size();
  words.clear();
  for (const Supervoxel& sv : frame.segmentation.supervoxels) {
    for (const Voxel& v : sv.voxels) {
      for (int axis = 0; axis < 3; ++axis)
        words.push_back(std::bit_cast<std::uint32_t>(v.position[axis]));
    }
    before.voxel_offsets_.push_back(static_cast<std::uint32_t>(words.size() / 3));
  }
  before.voxel_positions_ = PackWords(words);
  before.voxel_offsets_.shrink_to_fit();
  if (config.method == ChangeMethod::kVisibility) {
    // BuildFrame's objects, or, for a frame put together without it, computed here.
    before.object_labels_ =
        frame.objects.size() == frame.size()
            ? frame.objects
            : ObjectLabels(frame.segmentation.supervoxels, config.object_smooth_angle_deg);
  }
  return before;
}

StatusOr<ChangeInput> ChangeBefore::Expand(std::uint32_t supervoxel_id) const {
  if (supervoxel_id >= supervoxels()) {
    return InvalidArgumentError("the frame has " + std::to_string(supervoxels()) +
                                " supervoxels, no id " + std::to_string(supervoxel_id));
  }
  ChangeInput input;
  auto cloud = cloud_.Expand();
  if (!cloud.ok()) return cloud.status();
  input.before = std::move(cloud).value();
  auto labels = UnpackWords(point_labels_, points_);
  if (!labels.ok()) return labels.status();
  input.target.id = supervoxel_id;
  // The object's other supervoxels, in id order: where each sits in input.object.
  std::vector<std::int32_t> slot(supervoxels(), -1);
  if (!object_labels_.empty()) {
    for (std::uint32_t id = 0; id < supervoxels(); ++id) {
      if (id == supervoxel_id || object_labels_[id] != object_labels_[supervoxel_id]) continue;
      slot[id] = static_cast<std::int32_t>(input.object.size());
      input.object.emplace_back().id = id;
    }
  }
  for (std::size_t i = 0; i < labels->size(); ++i) {
    const std::uint32_t label = (*labels)[i];
    if (label == supervoxel_id) {
      input.target.point_indices.push_back(static_cast<std::int32_t>(i));
    } else if (label < slot.size() && slot[label] >= 0) {
      input.object[static_cast<std::size_t>(slot[label])].point_indices.push_back(
          static_cast<std::int32_t>(i));
    }
  }
  auto positions = UnpackWords(voxel_positions_, 3 * std::size_t{voxel_offsets_.back()});
  if (!positions.ok()) return positions.status();
  for (std::uint32_t v = voxel_offsets_[supervoxel_id]; v < voxel_offsets_[supervoxel_id + 1];
       ++v) {
    Voxel voxel{};
    for (int axis = 0; axis < 3; ++axis) {
      voxel.position[axis] = std::bit_cast<float>((*positions)[3 * std::size_t{v} + axis]);
    }
    voxel.normal = Eigen::Vector3f::Zero();
    input.target.voxels.push_back(voxel);
  }
  return input;
}

std::size_t ChangeBefore::bytes() const {
  return cloud_.bytes() + point_labels_.capacity() + voxel_positions_.capacity() +
         (voxel_offsets_.capacity() + object_labels_.capacity()) * sizeof(std::uint32_t);
}

std::vector<const Supervoxel*> ChangeInput::ObjectPointers() const {
  std::vector<const Supervoxel*> pointers;
  pointers.reserve(object.size());
  for (const Supervoxel& s : object) pointers.push_back(&s);
  return pointers;
}

}  // namespace relmap::perception
