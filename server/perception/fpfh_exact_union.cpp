// §2 literally: for each supervoxel, PCL FPFHEstimation at every voxel of the supervoxel and
// its neighbours, with that union as search surface, averaged. Kept as the reference the
// shared scheme is measured against.
#include <pcl/features/fpfh.h>
#include <pcl/point_types.h>
#include <pcl/search/kdtree.h>

#include <limits>
#include <memory>

#include "perception/fpfh.h"

namespace relmap::perception {

Eigen::MatrixXd SupervoxelFpfhExactUnion(const Segmentation& segmentation, float radius,
                                         int threads) {
  const auto n = static_cast<std::ptrdiff_t>(segmentation.supervoxels.size());
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(n, kFpfhDims);
#pragma omp parallel for schedule(dynamic, 4) num_threads(threads)
  for (std::ptrdiff_t s = 0; s < n; ++s) {
    std::vector<Eigen::Vector3f> positions, normals;
    CollectUnionVoxels(segmentation, segmentation.supervoxels[static_cast<std::size_t>(s)],
                       positions, normals);
    if (positions.empty()) {
      out.row(s).setConstant(std::numeric_limits<double>::quiet_NaN());
      continue;
    }
    pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
    pcl::PointCloud<pcl::Normal>::Ptr cloud_normals(new pcl::PointCloud<pcl::Normal>);
    cloud->resize(positions.size());
    cloud_normals->resize(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
      (*cloud)[i].getVector3fMap() = positions[i];
      (*cloud_normals)[i].getNormalVector3fMap() = normals[i];
    }
    pcl::FPFHEstimation<pcl::PointXYZ, pcl::Normal, pcl::FPFHSignature33> estimation;
    estimation.setInputCloud(cloud);
    estimation.setInputNormals(cloud_normals);
    estimation.setSearchMethod(std::make_shared<pcl::search::KdTree<pcl::PointXYZ>>());
    estimation.setRadiusSearch(radius);
    pcl::PointCloud<pcl::FPFHSignature33> histograms;
    estimation.compute(histograms);
    for (const pcl::FPFHSignature33& h : histograms) {
      for (int b = 0; b < kFpfhDims; ++b) out(s, b) += h.histogram[b];
    }
    // §2: divide by 100 (PCL's blocks sum to 100) and average over the union.
    out.row(s) /= 100.0 * static_cast<double>(histograms.size());
  }
  return out;
}

}  // namespace relmap::perception
