// relmap_ros_bridge for real: a rosmaster on loopback, a relmap-server, the bridge as
// its own process, and this test as the ROS node that publishes the project's real
// Kinect frames and checks what comes back.
#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/PoseStamped.h>
#include <gtest/gtest.h>
#include <relmap_ros/Outcome.h>
#include <relmap_ros/PostOutcome.h>
#include <relmap_ros/Push.h>
#include <sys/wait.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <visualization_msgs/Marker.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>

#include "integration/test_support.h"
#include "local_server.h"
#include "relevance_client.h"
#include "ros_test_support.h"

namespace relmap::ros_testing {
namespace {

using Cloud2 = sensor_msgs::PointCloud2;

// A relmap-server, a bridge named `name_` on it, and the topics it publishes.
class RosBridgeTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string failure = StartRosOnce();
    if (!failure.empty()) GTEST_SKIP() << failure;
    node_.emplace();
    first_ = KinectCloud("kinect_static_seq_1.pcd", ros::Time(100, 1));
    second_ = KinectCloud("kinect_static_seq_2.pcd", ros::Time(101, 2));
    if (!first_ || !second_) GTEST_SKIP() << "no Kinect frames in " RELMAP_REAL_DATA_DIR;
    StatusOr<std::unique_ptr<client::LocalServer>> server =
        client::LocalServer::Start(RELMAP_SERVER_BINARY, {true, {}, ""});
    ASSERT_TRUE(server.ok()) << server.status().message();
    server_ = std::move(*server);
    const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
    name_ = std::string("bridge_") + test->name();
    cloud_topic_ = "/" + name_ + "_camera/points";
  }

  // The bridge with `params` (name:=value, as on a rosrun command line) besides the
  // server and the cloud topic; waits for its post_outcome service.
  void StartBridge(const std::vector<std::string>& params = {}) {
    std::vector<std::string> argv = {RELMAP_ROS_BRIDGE_BINARY,
                                     "__name:=" + name_,
                                     "_server:=" + server_->address(),
                                     "_cloud_topic:=" + cloud_topic_,
                                     "_after_cloud_topic:=" + cloud_topic_ + "_after",
                                     "_diagnostics_period_seconds:=0.2"};
    for (const std::string& param : params) argv.push_back("_" + param);
    bridge_ = std::make_unique<ChildProcess>(argv, directory_.path() + "/bridge.log");
    ASSERT_TRUE(ros::service::waitForService(Private("post_outcome"), ros::Duration(20)))
        << relmap::testing::ReadFile(bridge_->log_path());
    cloud_publisher_ = node_->advertise<Cloud2>(cloud_topic_, 1);
    after_publisher_ = node_->advertise<Cloud2>(cloud_topic_ + "_after", 1);
    ASSERT_TRUE(WaitForSubscribers(cloud_publisher_));
    ASSERT_TRUE(WaitForSubscribers(after_publisher_));
  }

  std::string Private(const std::string& name) const { return "/" + name_ + "/" + name; }

  static auto StampedAs(const Cloud2& cloud) {
    return
        [stamp = cloud.header.stamp](const auto& message) { return message.header.stamp == stamp; };
  }

  // post_outcome, called; fails the test when the service itself could not answer.
  relmap_ros::PostOutcome::Response PostOutcome(ros::Time stamp, std::uint32_t supervoxel,
                                                bool moved) {
    relmap_ros::PostOutcome call;
    call.request.stamp = stamp;
    call.request.supervoxel_id = supervoxel;
    call.request.moved = moved;
    EXPECT_TRUE(ros::service::call(Private("post_outcome"), call))
        << relmap::testing::ReadFile(bridge_->log_path());
    return call.response;
  }

  std::optional<ros::NodeHandle> node_;  // after ros::init
  relmap::testing::TemporaryDirectory directory_;
  std::unique_ptr<client::LocalServer> server_;
  std::unique_ptr<ChildProcess> bridge_;
  std::string name_;
  std::string cloud_topic_;
  ros::Publisher cloud_publisher_;
  ros::Publisher after_publisher_;
  std::optional<Cloud2> first_;
  std::optional<Cloud2> second_;
};

const sensor_msgs::PointField* Field(const Cloud2& cloud, const std::string& name) {
  for (const sensor_msgs::PointField& field : cloud.fields) {
    if (field.name == name) return &field;
  }
  return nullptr;
}

template <typename T>
T ValueAt(const Cloud2& cloud, std::size_t point, const std::string& name) {
  T value{};
  std::memcpy(&value, cloud.data.data() + point * cloud.point_step + Field(cloud, name)->offset,
              sizeof value);
  return value;
}

TEST_F(RosBridgeTest, PublishesTheMapsAndTargetOfARealKinectFrame) {
  StartBridge();
  Inbox<Cloud2> relevance(*node_, Private("relevance"));
  Inbox<Cloud2> choice(*node_, Private("choice"));
  Inbox<geometry_msgs::PoseStamped> target(*node_, Private("target"));
  Inbox<visualization_msgs::Marker> marker(*node_, Private("target_marker"));
  Inbox<diagnostic_msgs::DiagnosticArray> diagnostics(*node_, "/diagnostics");
  ASSERT_TRUE(relevance.Connected() && choice.Connected() && target.Connected() &&
              marker.Connected());
  cloud_publisher_.publish(*first_);

  const std::optional<Cloud2> relevance_map = relevance.WaitFor(StampedAs(*first_));
  ASSERT_TRUE(relevance_map) << relmap::testing::ReadFile(bridge_->log_path());
  const std::optional<Cloud2> choice_map = choice.WaitFor(StampedAs(*first_));
  const auto pose = target.WaitFor(StampedAs(*first_));
  const auto arrow = marker.WaitFor(StampedAs(*first_));
  ASSERT_TRUE(choice_map && pose && arrow);

  for (const Cloud2* map : {&*relevance_map, &*choice_map}) {
    EXPECT_EQ(map->header.frame_id, "kinect");
    EXPECT_EQ(map->height, 1U);
    EXPECT_EQ(map->data.size(), std::size_t{map->width} * map->point_step);
    for (const char* name : {"x", "y", "z", "rgb", "intensity", "supervoxel"}) {
      EXPECT_NE(Field(*map, name), nullptr) << name;
    }
  }
  // A real tabletop frame: thousands of segmented points of a 640×480 frame.
  EXPECT_GT(relevance_map->width, 1000U);
  EXPECT_LT(relevance_map->width, 640U * 480U);
  EXPECT_EQ(choice_map->width, relevance_map->width);
  float min[3] = {INFINITY, INFINITY, INFINITY}, max[3] = {-INFINITY, -INFINITY, -INFINITY};
  std::size_t target_points = 0;
  for (std::size_t i = 0; i < relevance_map->width; ++i) {
    const auto relevance_value = ValueAt<float>(*relevance_map, i, "intensity");
    EXPECT_GE(relevance_value, 0.0F);
    EXPECT_LE(relevance_value, 1.0F);
    const auto choice_value = ValueAt<float>(*choice_map, i, "intensity");
    EXPECT_GE(choice_value, 0.0F);
    EXPECT_LE(choice_value, 1.0F);
    const char* axes[3] = {"x", "y", "z"};
    for (int axis = 0; axis < 3; ++axis) {
      const auto coordinate = ValueAt<float>(*relevance_map, i, axes[axis]);
      min[axis] = std::min(min[axis], coordinate);
      max[axis] = std::max(max[axis], coordinate);
    }
    if (ValueAt<std::uint32_t>(*relevance_map, i, "supervoxel") ==
        static_cast<std::uint32_t>(arrow->id)) {
      ++target_points;
    }
  }
  EXPECT_GT(target_points, 0U) << "the marker names a supervoxel of the maps";
  EXPECT_EQ(pose->header.frame_id, "kinect");
  const double position[3] = {pose->pose.position.x, pose->pose.position.y, pose->pose.position.z};
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_GE(position[axis], min[axis]);
    EXPECT_LE(position[axis], max[axis]);
  }
  const auto& q = pose->pose.orientation;
  EXPECT_NEAR(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w, 1.0, 1e-6);
  EXPECT_EQ(arrow->ns, "relmap_target");

  const auto mapped = diagnostics.WaitFor([&](const diagnostic_msgs::DiagnosticArray& array) {
    for (const auto& status : array.status) {
      if (status.name != "/" + name_ + ": relmap") continue;
      for (const auto& value : status.values) {
        if (value.key == "frames mapped" && value.value == "1") return true;
      }
    }
    return false;
  });
  EXPECT_TRUE(mapped) << "diagnostics count the frame";
}

TEST_F(RosBridgeTest, MovesCloudsIntoTheWorkspaceFrameWithTf2) {
  // "table" is "kinect" turned half a turn about x and lifted by 20 m:
  // (x, y, z) → (x, −y, 20 − z).
  tf2_ros::StaticTransformBroadcaster broadcaster;
  geometry_msgs::TransformStamped table;
  table.header.stamp = ros::Time(1, 0);
  table.header.frame_id = "table";
  table.child_frame_id = "kinect";
  table.transform.rotation.x = 1.0;
  table.transform.translation.z = 20.0;
  broadcaster.sendTransform(table);
  StartBridge({"workspace_frame:=table"});
  Inbox<Cloud2> relevance(*node_, Private("relevance"));
  Inbox<geometry_msgs::PoseStamped> target(*node_, Private("target"));
  Inbox<diagnostic_msgs::DiagnosticArray> diagnostics(*node_, "/diagnostics");
  ASSERT_TRUE(relevance.Connected() && target.Connected());

  sensor_msgs::PointCloud2 elsewhere = *second_;
  elsewhere.header.frame_id = "nowhere";
  cloud_publisher_.publish(elsewhere);
  const auto refused = diagnostics.WaitFor([](const diagnostic_msgs::DiagnosticArray& array) {
    return !array.status.empty() &&
           array.status[0].message.find("no transform from nowhere to table") != std::string::npos;
  });
  EXPECT_TRUE(refused) << relmap::testing::ReadFile(bridge_->log_path());

  cloud_publisher_.publish(*first_);
  const auto map = relevance.WaitFor(StampedAs(*first_));
  ASSERT_TRUE(map) << relmap::testing::ReadFile(bridge_->log_path());
  EXPECT_EQ(map->header.frame_id, "table");
  const auto pose = target.WaitFor(StampedAs(*first_));
  ASSERT_TRUE(pose);
  EXPECT_EQ(pose->header.frame_id, "table");
  // A Kinect sees 0.5 to at most 10 m ahead (camera z): moved, every point has
  // 10 < z < 20, where none of the camera's own coordinates can be.
  std::size_t moved = 0;
  for (std::size_t i = 0; i < map->width; ++i) {
    const auto z = ValueAt<float>(*map, i, "z");
    if (z > 10.0F && z < 20.0F) ++moved;
  }
  EXPECT_EQ(moved, map->width);
  EXPECT_GT(pose->pose.position.z, 10.0);
  EXPECT_LT(pose->pose.position.z, 20.0);
  EXPECT_FALSE(relevance.WaitFor(StampedAs(elsewhere), 0)) << "the untransformable cloud";
}

TEST_F(RosBridgeTest, RefusesABadParameterNamingIt) {
  ChildProcess bridge({RELMAP_ROS_BRIDGE_BINARY, "__name:=" + name_, "_max_pushes:=-1"},
                      directory_.path() + "/bad.log");
  for (int waited = 0; bridge.Running() && waited < 400; ++waited) ros::Duration(0.05).sleep();
  ASSERT_FALSE(bridge.Running());
  EXPECT_EQ(WEXITSTATUS(bridge.wait_status()), 2);
  EXPECT_NE(relmap::testing::ReadFile(directory_.path() + "/bad.log")
                .find("~max_pushes must be 0 (no limit) or more, not -1"),
            std::string::npos);
  ChildProcess typed({RELMAP_ROS_BRIDGE_BINARY, "__name:=" + name_ + "_typed", "_seed:=one"},
                     directory_.path() + "/typed.log");
  for (int waited = 0; typed.Running() && waited < 400; ++waited) ros::Duration(0.05).sleep();
  ASSERT_FALSE(typed.Running());
  EXPECT_EQ(WEXITSTATUS(typed.wait_status()), 2);
  EXPECT_NE(
      relmap::testing::ReadFile(directory_.path() + "/typed.log").find("~seed must be an integer"),
      std::string::npos);
}

TEST_F(RosBridgeTest, PostOutcomeLearnsAndRefusesBadRequestsWithMessages) {
  StartBridge();
  Inbox<visualization_msgs::Marker> marker(*node_, Private("target_marker"));
  Inbox<relmap_ros::Outcome> outcomes(*node_, Private("outcomes"));
  ASSERT_TRUE(marker.Connected() && outcomes.Connected());
  cloud_publisher_.publish(*first_);
  const auto arrow = marker.WaitFor(StampedAs(*first_));
  ASSERT_TRUE(arrow) << relmap::testing::ReadFile(bridge_->log_path());
  const auto target = static_cast<std::uint32_t>(arrow->id);

  const auto unknown = PostOutcome(ros::Time(5, 0), target, true);
  EXPECT_FALSE(unknown.success);
  EXPECT_NE(unknown.message.find("no frame stamped 5.000000000"), std::string::npos)
      << unknown.message;

  const auto bad_supervoxel = PostOutcome(first_->header.stamp, 1000000, true);
  EXPECT_FALSE(bad_supervoxel.success);
  EXPECT_NE(bad_supervoxel.message.find("PostOutcome"), std::string::npos)
      << bad_supervoxel.message;
  EXPECT_NE(bad_supervoxel.message.find("supervoxel"), std::string::npos) << bad_supervoxel.message;

  const auto good = PostOutcome(first_->header.stamp, target, true);
  EXPECT_TRUE(good.success) << good.message;
  EXPECT_EQ(good.moveable_samples, 1U);
  EXPECT_EQ(good.non_moveable_samples, 0U);
  const auto announced = outcomes.WaitFor(StampedAs(*first_));
  ASSERT_TRUE(announced);
  EXPECT_EQ(announced->supervoxel_id, target);
  EXPECT_TRUE(announced->moved);
  EXPECT_FALSE(announced->from_after_cloud);
  EXPECT_TRUE(bridge_->Running());
}

TEST_F(RosBridgeTest, AServerThatIsGoneIsAFailedOutcomeNotAFailedNode) {
  StartBridge({"deadline_seconds:=3"});
  Inbox<visualization_msgs::Marker> marker(*node_, Private("target_marker"));
  ASSERT_TRUE(marker.Connected());
  cloud_publisher_.publish(*first_);
  const auto arrow = marker.WaitFor(StampedAs(*first_));
  ASSERT_TRUE(arrow) << relmap::testing::ReadFile(bridge_->log_path());
  server_->Stop();
  for (int call = 0; call < 2; ++call) {
    const auto refused =
        PostOutcome(first_->header.stamp, static_cast<std::uint32_t>(arrow->id), false);
    EXPECT_FALSE(refused.success);
    EXPECT_NE(refused.message.find("PostOutcome: "), std::string::npos) << refused.message;
  }
  EXPECT_TRUE(bridge_->Running());
}

TEST_F(RosBridgeTest, AnAfterPushCloudIsLabelledByTheChangeDetector) {
  StartBridge();
  Inbox<visualization_msgs::Marker> marker(*node_, Private("target_marker"));
  Inbox<relmap_ros::Outcome> outcomes(*node_, Private("outcomes"));
  ASSERT_TRUE(marker.Connected() && outcomes.Connected());
  cloud_publisher_.publish(*first_);
  ASSERT_TRUE(marker.WaitFor(StampedAs(*first_))) << relmap::testing::ReadFile(bridge_->log_path());
  after_publisher_.publish(*second_);
  const auto outcome = outcomes.WaitFor(StampedAs(*first_));
  ASSERT_TRUE(outcome) << relmap::testing::ReadFile(bridge_->log_path());
  EXPECT_TRUE(outcome->from_after_cloud);
}

// A push controller as a ROS service: answers every push with `label`.
class FakePushService {
 public:
  FakePushService(ros::NodeHandle& node, const std::string& name, std::string label)
      : label_(std::move(label)),
        server_(node.advertiseService(name, &FakePushService::Push, this)) {}
  std::vector<relmap_ros::Push::Request> requests() {
    std::lock_guard lock(mutex_);
    return requests_;
  }

 private:
  bool Push(relmap_ros::Push::Request& request, relmap_ros::Push::Response& response) {
    std::lock_guard lock(mutex_);
    requests_.push_back(request);
    response.result = "done";
    response.label = label_;
    response.message = "fake push";
    return true;
  }

  std::string label_;
  std::mutex mutex_;
  std::vector<relmap_ros::Push::Request> requests_;
  ros::ServiceServer server_;
};

TEST_F(RosBridgeTest, ThePushLoopPushesTheTargetAndPostsTheControllersLabel) {
  FakePushService push(*node_, "/" + name_ + "_push", "moved");
  StartBridge({"push_loop:=true", "push_service:=/" + name_ + "_push", "max_pushes:=1"});
  Inbox<relmap_ros::Outcome> outcomes(*node_, Private("outcomes"));
  Inbox<visualization_msgs::Marker> marker(*node_, Private("target_marker"));
  ASSERT_TRUE(marker.Connected() && outcomes.Connected());
  cloud_publisher_.publish(*first_);
  const auto outcome = outcomes.WaitFor(StampedAs(*first_));
  ASSERT_TRUE(outcome) << relmap::testing::ReadFile(bridge_->log_path());
  EXPECT_TRUE(outcome->moved);
  const auto arrow = marker.WaitFor(StampedAs(*first_));
  ASSERT_TRUE(arrow);
  const std::vector<relmap_ros::Push::Request> requests = push.requests();
  ASSERT_EQ(requests.size(), 1U);
  EXPECT_EQ(requests[0].supervoxel_id, static_cast<std::uint32_t>(arrow->id));
  EXPECT_EQ(outcome->supervoxel_id, requests[0].supervoxel_id);
  EXPECT_EQ(requests[0].target.header.frame_id, "kinect");
  EXPECT_EQ(requests[0].push, 1U);

  // max_pushes is 1: the next frame is mapped, not pushed.
  cloud_publisher_.publish(*second_);
  ASSERT_TRUE(marker.WaitFor(StampedAs(*second_)));
  EXPECT_EQ(push.requests().size(), 1U);
}

TEST_F(RosBridgeTest, APushWithoutLabelTakesTheNextCloudAsItsAfterCloud) {
  FakePushService push(*node_, "/" + name_ + "_push", "");
  StartBridge({"push_loop:=true", "push_service:=/" + name_ + "_push", "max_pushes:=1"});
  Inbox<relmap_ros::Outcome> outcomes(*node_, Private("outcomes"));
  Inbox<visualization_msgs::Marker> marker(*node_, Private("target_marker"));
  ASSERT_TRUE(marker.Connected() && outcomes.Connected());
  cloud_publisher_.publish(*first_);
  ASSERT_TRUE(marker.WaitFor(StampedAs(*first_))) << relmap::testing::ReadFile(bridge_->log_path());
  cloud_publisher_.publish(*second_);
  const auto outcome = outcomes.WaitFor(StampedAs(*first_));
  ASSERT_TRUE(outcome) << relmap::testing::ReadFile(bridge_->log_path());
  EXPECT_TRUE(outcome->from_after_cloud);
  EXPECT_TRUE(marker.WaitFor(StampedAs(*second_))) << "the after cloud is mapped too";
}

// relmap_ros_replay's "key value" lines (its log line on standard error is another).
std::map<std::string, std::string> ReplayOutput(const std::string& path) {
  std::map<std::string, std::string> values;
  std::istringstream in(relmap::testing::ReadFile(path));
  for (std::string line; std::getline(in, line);) {
    const std::size_t space = line.find(' ');
    if (space != std::string::npos && line.rfind("session_", 0) == 0) {
      values[line.substr(0, space)] = line.substr(space + 1);
    }
  }
  return values;
}

TEST_F(RosBridgeTest, ARecordedBagReplaysIntoASessionWithTheSameSamples) {
  client::RelevanceClient client(server_->address());
  v1::SessionConfig config;
  config.set_seed(3);
  client::SessionHandle recorded;
  ASSERT_TRUE(client.CreateSession(config, &recorded).ok());
  const std::string bag = directory_.path() + "/run.bag";
  StartBridge(
      {"session_id:=" + recorded.id, "session_token:=" + recorded.token, "record_bag:=" + bag});
  Inbox<visualization_msgs::Marker> marker(*node_, Private("target_marker"));
  ASSERT_TRUE(marker.Connected());
  bool moved = true;
  for (const Cloud2* cloud : {&*first_, &*second_}) {
    cloud_publisher_.publish(*cloud);
    const auto arrow = marker.WaitFor(StampedAs(*cloud));
    ASSERT_TRUE(arrow) << relmap::testing::ReadFile(bridge_->log_path());
    EXPECT_TRUE(
        PostOutcome(cloud->header.stamp, static_cast<std::uint32_t>(arrow->id), moved).success);
    moved = !moved;
  }
  EXPECT_EQ(bridge_->Stop(), 0) << "the bridge ends cleanly, closing its bag";

  const std::string output = directory_.path() + "/replay.out";
  ChildProcess replay({RELMAP_ROS_REPLAY_BINARY, bag, "--server", server_->address()}, output);
  for (int waited = 0; replay.Running() && waited < 600; ++waited) ros::Duration(0.05).sleep();
  ASSERT_FALSE(replay.Running()) << relmap::testing::ReadFile(output);
  const std::map<std::string, std::string> replayed = ReplayOutput(output);
  ASSERT_EQ(replayed.count("session_id"), 1U) << relmap::testing::ReadFile(output);

  v1::ExportSessionResponse original, copy;
  ASSERT_TRUE(client.ExportSession(recorded, &original).ok());
  ASSERT_TRUE(
      client.ExportSession({replayed.at("session_id"), replayed.at("session_token")}, &copy).ok());
  ASSERT_EQ(original.state().samples_size(), 2);
  ASSERT_EQ(copy.state().samples_size(), 2);
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(copy.state().samples(i).SerializeAsString(),
              original.state().samples(i).SerializeAsString())
        << "sample " << i;
  }
  EXPECT_EQ(original.state().samples(0).label(), v1::LABEL_MOVEABLE);
  EXPECT_EQ(original.state().samples(1).label(), v1::LABEL_NOT_MOVEABLE);
}

}  // namespace
}  // namespace relmap::ros_testing
