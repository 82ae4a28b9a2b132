// The OpenNI2 camera source: PCL's grabber thread hands over its newest cloud; Next()
// takes the first one that arrives after it was called. The only file that includes
// PCL.
#include "openni2_source.h"

#include <pcl/pcl_config.h>

#if defined(HAVE_OPENNI2)
#include <pcl/exceptions.h>
#include <pcl/io/openni2_grabber.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <condition_variable>
#include <cstring>
#include <functional>
#include <mutex>
#endif

namespace relmap::robot {

#if defined(HAVE_OPENNI2)
namespace {

using Points = pcl::PointCloud<pcl::PointXYZRGBA>;

// The API's packed layout: float32 x, y, z, then r, g, b, a; holes stay NaN.
v1::Cloud Pack(const Points& points) {
  v1::Cloud cloud;
  v1::PackedCloud* packed = cloud.mutable_packed();
  packed->set_width(points.width);
  packed->set_height(points.height);
  std::string* bytes = packed->mutable_points();
  bytes->resize(points.size() * 16);
  char* out = bytes->data();
  for (const pcl::PointXYZRGBA& p : points) {
    const float xyz[3] = {p.x, p.y, p.z};
    const unsigned char rgba[4] = {p.r, p.g, p.b, p.a};
    std::memcpy(out, xyz, sizeof xyz);
    std::memcpy(out + 12, rgba, sizeof rgba);
    out += 16;
  }
  return cloud;
}

class OpenNI2Source final : public CloudSource {
 public:
  OpenNI2Source(std::unique_ptr<pcl::io::OpenNI2Grabber> grabber, const OpenNI2Options& options,
                const std::atomic<bool>* stop)
      : grabber_(std::move(grabber)), options_(options), stop_(stop) {}

  ~OpenNI2Source() override {
    try {
      grabber_->stop();
    } catch (const std::exception&) {
      // a camera unplugged while running: nothing left to stop
    }
  }

  // Starts the grabber with the callback; UNAVAILABLE when it cannot.
  Status Start() {
    std::function<void(const Points::ConstPtr&)> on_cloud = [this](const Points::ConstPtr& cloud) {
      {
        const std::lock_guard<std::mutex> lock(mutex_);
        latest_ = cloud;
        ++delivered_;
      }
      arrived_.notify_all();
    };
    try {
      grabber_->registerCallback(on_cloud);
      grabber_->start();
    } catch (const std::exception& e) {
      return Status(StatusCode::kUnavailable, std::string("OpenNI2: ") + e.what());
    }
    return OkStatus();
  }

  StatusOr<std::optional<SourceFrame>> Next() override {
    std::unique_lock<std::mutex> lock(mutex_);
    const std::uint64_t seen = delivered_;
    const auto deadline = std::chrono::steady_clock::now() + options_.frame_timeout;
    while (delivered_ == seen) {
      if (stop_ != nullptr && stop_->load()) return std::optional<SourceFrame>();
      if (std::chrono::steady_clock::now() >= deadline) {
        return Status(StatusCode::kDeadlineExceeded,
                      "OpenNI2: no frame from the camera within " +
                          std::to_string(options_.frame_timeout.count()) + " ms");
      }
      arrived_.wait_for(lock, std::chrono::milliseconds(100));
    }
    const Points::ConstPtr cloud = latest_;
    lock.unlock();
    SourceFrame frame;
    frame.cloud = Pack(*cloud);
    return std::optional<SourceFrame>(std::move(frame));
  }

 private:
  std::unique_ptr<pcl::io::OpenNI2Grabber> grabber_;
  OpenNI2Options options_;
  const std::atomic<bool>* stop_;
  std::mutex mutex_;
  std::condition_variable arrived_;
  Points::ConstPtr latest_;
  std::uint64_t delivered_ = 0;
};

}  // namespace

bool OpenNI2Available() { return true; }

StatusOr<std::unique_ptr<CloudSource>> OpenOpenNI2Source(const OpenNI2Options& options,
                                                         const std::atomic<bool>* stop) {
  std::unique_ptr<pcl::io::OpenNI2Grabber> grabber;
  try {
    grabber = std::make_unique<pcl::io::OpenNI2Grabber>(options.device);
  } catch (const std::exception& e) {
    return Status(StatusCode::kUnavailable,
                  "OpenNI2: cannot open device \"" + options.device + "\": " + e.what());
  }
  auto source = std::make_unique<OpenNI2Source>(std::move(grabber), options, stop);
  if (Status started = source->Start(); !started.ok()) return started;
  return std::unique_ptr<CloudSource>(std::move(source));
}

#else

bool OpenNI2Available() { return false; }

StatusOr<std::unique_ptr<CloudSource>> OpenOpenNI2Source(const OpenNI2Options&,
                                                         const std::atomic<bool>*) {
  return Status(StatusCode::kUnimplemented,
                "this build of relmap-robot has no OpenNI2 (its PCL was built without it)");
}

#endif

}  // namespace relmap::robot
