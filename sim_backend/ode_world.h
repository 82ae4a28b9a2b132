// The ODE side of one scene: world, collision space, the tags the camera and the
// contacts read from each geom, the kinematic pusher, and one deterministic
// physics step. One OdeWorld belongs to one OdeScene and is used by one thread
// at a time.
#pragma once

#include <ode/ode.h>

#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "scene_settings.h"
#include "simulated_scene.h"

namespace relmap::sim {

// A triangle mesh's data, kept alive for ODE (which does not copy it).
struct MeshData {
  std::vector<double> vertices;  // x, y, z per vertex
  std::vector<dTriIndex> indices;
  dTriMeshDataID id = nullptr;
};

// What a geom is (dGeomGetData).
struct GeomTag {
  std::int32_t body_id = kNoBody;  // kNoBody: the pusher
  bool moveable = false;
  // Creation order: the key contacts are sorted by, so a step does not depend on
  // the order ODE's space happens to report pairs in.
  std::uint32_t order = 0;
  Material material;
  const MeshData* mesh = nullptr;  // mesh geoms only
};

// A body of the scene: static (geoms only) or moveable (an ODE body).
struct SimBody {
  std::int32_t id = kNoBody;
  std::string name;
  bool moveable = false;
  dBodyID body = nullptr;  // null for static bodies
  std::vector<dGeomID> geoms;
  int object_index = -1;  // objects: index in Scene::objects
  // objects: the object frame (the scene file's shape frame) in the ODE body's
  // frame, whose origin ODE requires at the centre of mass.
  Eigen::Isometry3d body_from_object = Eigen::Isometry3d::Identity();
};

inline const GeomTag& TagOf(dGeomID geom) {
  return *static_cast<const GeomTag*>(dGeomGetData(geom));
}

// Calls dInitODE2 once per process, and ODE's per-thread allocation once per
// calling thread; every entry point into ODE goes through it.
void EnsureOdeReady();

class OdeWorld {
 public:
  explicit OdeWorld(const PhysicsSettings& physics);
  ~OdeWorld();
  OdeWorld(const OdeWorld&) = delete;
  OdeWorld& operator=(const OdeWorld&) = delete;

  dWorldID world() const { return world_; }
  dSpaceID space() const { return space_; }
  double step_seconds() const { return 1.0 / physics_.step_hz; }
  const PhysicsSettings& physics() const { return physics_; }

  // Tags `geom` (already in space()) for `body_id`.
  void Tag(dGeomID geom, std::int32_t body_id, bool moveable, const Material& material,
           const MeshData* mesh = nullptr);
  // A mesh's data, owned by the world.
  MeshData* NewMesh(std::vector<double> vertices, std::vector<dTriIndex> indices);
  bool has_meshes() const { return !meshes_.empty(); }

  // The pusher: a kinematic sphere, out of every collision and every picture
  // while parked.
  dBodyID effector() const { return effector_body_; }
  dGeomID effector_geom() const { return effector_geom_; }
  void PlaceEffector(const Eigen::Vector3d& position);
  void ParkEffector();

  // One physics step of 1/step_hz: contacts (sorted), then dWorldStep. Returns
  // whether the pusher touched a static body (it has no contacts with them: a
  // push into a wall is blocked, see push_primitive.cpp).
  bool Step();
  // Whether `geom` overlaps an enabled geom of another body (the pusher included
  // when it is active).
  bool Collides(dGeomID geom);

 private:
  struct Pair {
    dGeomID a, b;
  };
  static void CollectPair(void* data, dGeomID o1, dGeomID o2);
  void AddContacts(dGeomID a, dGeomID b);
  void ApplyRollingResistance();

  PhysicsSettings physics_;
  dWorldID world_ = nullptr;
  dSpaceID space_ = nullptr;
  dJointGroupID contacts_ = nullptr;
  dThreadingImplementationID threading_ = nullptr;
  dBodyID effector_body_ = nullptr;
  dGeomID effector_geom_ = nullptr;
  std::vector<std::unique_ptr<GeomTag>> tags_;
  std::vector<std::unique_ptr<MeshData>> meshes_;
  std::vector<Pair> pairs_;
  // The bodies touching something this step, with their rolling resistance (m).
  std::vector<std::pair<dBodyID, double>> rolling_;
  bool effector_hit_static_ = false;
};

}  // namespace relmap::sim
