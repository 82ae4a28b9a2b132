// OdeWorld: ODE's world and hash space, geom tags, the kinematic pusher, and a
// physics step whose contacts do not depend on the space's pair order.
#include "ode_world.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <mutex>

#include "ode_math.h"

namespace relmap::sim {
namespace {

// A box or a cylinder rests flat on a table on up to 8 contact points; with
// fewer, ODE's cylinder-box contacts may all lie on one side and the cylinder
// rocks.
constexpr int kMaxContacts = 8;
// The hash space's cell sizes, 2^-6 m (1.6 cm, the smallest part) to 2^5 m (the floor).
constexpr int kHashMinLevel = -6;
constexpr int kHashMaxLevel = 5;
// Resting contacts may sink this much (m) before being pushed out: without it
// a body on a table jitters between contact and no contact.
constexpr double kSurfaceLayer = 0.0005;
// Contact softness: ERP and CFM at 1 kHz (ODE's defaults are for 100 Hz games).
constexpr double kContactErp = 0.2;
constexpr double kContactCfm = 1e-4;
// Where the parked pusher waits, far from everything.
constexpr double kParkingDepth = -1000.0;

// ODE's messages are warnings it recovers from; the only one it prints in our
// use is the LCP solver's "s <= 0" on a degenerate contact set (a few per
// hundred pushes), which would only garble relmap-sim's progress line. Any other
// message still goes to standard error.
void PrintOdeMessage(int number, const char* format, va_list arguments) {
  if (number == d_ERR_LCP) return;
  std::fprintf(stderr, "ODE message %d: ", number);
  std::vfprintf(stderr, format, arguments);
  std::fputc('\n', stderr);
}

}  // namespace

void EnsureOdeReady() {
  static std::once_flag initialised;
  std::call_once(initialised, [] {
    dInitODE2(0);
    dSetMessageHandler(&PrintOdeMessage);
  });
  // Debian's ODE is built without thread-local storage, where this is a no-op;
  // with it, every thread that calls ODE must have allocated its data.
  thread_local bool allocated = false;
  if (!allocated) allocated = dAllocateODEDataForThread(dAllocateMaskAll) != 0;
}

OdeWorld::OdeWorld(const PhysicsSettings& physics) : physics_(physics) {
  EnsureOdeReady();
  world_ = dWorldCreate();
  // ODE steps every world through one process-wide "self-threaded" job list
  // unless a world has its own: a private one lets scenes step on different
  // threads at the same time (without it, two threads pushing in two scenes
  // crash or diverge: tests/sim/push_test.cpp).
  threading_ = dThreadingAllocateSelfThreadedImplementation();
  dWorldSetStepThreadingImplementation(world_, dThreadingImplementationGetFunctions(threading_),
                                       threading_);
  dWorldSetGravity(world_, 0, 0, -physics_.gravity);
  dWorldSetContactSurfaceLayer(world_, kSurfaceLayer);
  space_ = dHashSpaceCreate(nullptr);
  dHashSpaceSetLevels(space_, kHashMinLevel, kHashMaxLevel);
  contacts_ = dJointGroupCreate(0);

  effector_body_ = dBodyCreate(world_);
  dBodySetKinematic(effector_body_);
  effector_geom_ = dCreateSphere(space_, physics_.effector_radius);
  dGeomSetBody(effector_geom_, effector_body_);
  Tag(effector_geom_, kNoBody, /*moveable=*/false, Material{});
  ParkEffector();
}

OdeWorld::~OdeWorld() {
  dJointGroupDestroy(contacts_);
  dSpaceDestroy(space_);  // and its geoms
  for (const auto& mesh : meshes_) dGeomTriMeshDataDestroy(mesh->id);
  dWorldSetStepThreadingImplementation(world_, nullptr, nullptr);
  dWorldDestroy(world_);  // and its bodies
  dThreadingFreeImplementation(threading_);
}

void OdeWorld::Tag(dGeomID geom, std::int32_t body_id, bool moveable, const Material& material,
                   const MeshData* mesh) {
  auto tag = std::make_unique<GeomTag>();
  tag->body_id = body_id;
  tag->moveable = moveable;
  tag->order = static_cast<std::uint32_t>(tags_.size());
  tag->material = material;
  tag->mesh = mesh;
  dGeomSetData(geom, tag.get());
  tags_.push_back(std::move(tag));
}

MeshData* OdeWorld::NewMesh(std::vector<double> vertices, std::vector<dTriIndex> indices) {
  auto mesh = std::make_unique<MeshData>();
  mesh->vertices = std::move(vertices);
  mesh->indices = std::move(indices);
  mesh->id = dGeomTriMeshDataCreate();
  dGeomTriMeshDataBuildDouble(mesh->id, mesh->vertices.data(), 3 * sizeof(double),
                              static_cast<int>(mesh->vertices.size() / 3), mesh->indices.data(),
                              static_cast<int>(mesh->indices.size()), 3 * sizeof(dTriIndex));
  meshes_.push_back(std::move(mesh));
  return meshes_.back().get();
}

void OdeWorld::PlaceEffector(const Eigen::Vector3d& position) {
  dBodyEnable(effector_body_);
  dBodySetPosition(effector_body_, position.x(), position.y(), position.z());
  dBodySetLinearVel(effector_body_, 0, 0, 0);
  dBodySetAngularVel(effector_body_, 0, 0, 0);
  dGeomEnable(effector_geom_);
}

void OdeWorld::ParkEffector() {
  dGeomDisable(effector_geom_);
  dBodySetLinearVel(effector_body_, 0, 0, 0);
  dBodySetAngularVel(effector_body_, 0, 0, 0);
  dBodySetPosition(effector_body_, 0, 0, kParkingDepth);
  dBodyDisable(effector_body_);
}

void OdeWorld::CollectPair(void* data, dGeomID o1, dGeomID o2) {
  auto* self = static_cast<OdeWorld*>(data);
  if (TagOf(o2).order < TagOf(o1).order) std::swap(o1, o2);
  self->pairs_.push_back({o1, o2});
}

void OdeWorld::AddContacts(dGeomID a, dGeomID b) {
  const dBodyID body_a = dGeomGetBody(a), body_b = dGeomGetBody(b);
  if (body_a == body_b) return;  // static-static, or two parts of one body
  const bool pusher_a = a == effector_geom_, pusher_b = b == effector_geom_;
  if ((pusher_a && body_b == nullptr) || (pusher_b && body_a == nullptr)) {
    // The kinematic pusher against a static body: both immovable, so no joint;
    // the push primitive stops advancing instead.
    dContactGeom touch;
    if (dCollide(a, b, 1, &touch, sizeof touch) > 0) effector_hit_static_ = true;
    return;
  }
  dContact contact[kMaxContacts]{};
  const int n = dCollide(a, b, kMaxContacts, &contact[0].geom, sizeof(dContact));
  if (n <= 0) return;
  const Material& ma = TagOf(a).material;
  const Material& mb = TagOf(b).material;
  const double mu = std::sqrt(ma.friction * mb.friction);
  for (int i = 0; i < n; ++i) {
    dSurfaceParameters& s = contact[i].surface;
    // Approx1: the friction bound proportional to the normal force.
    s.mode = dContactApprox1 | dContactSoftERP | dContactSoftCFM;
    s.mu = mu;
    s.soft_erp = kContactErp;
    s.soft_cfm = kContactCfm;
    const dJointID joint = dJointCreateContact(world_, contacts_, &contact[i]);
    dJointAttach(joint, body_a, body_b);
  }
  const double rho = std::sqrt(ma.rolling_friction * mb.rolling_friction);
  for (const dBodyID body : {body_a, body_b}) {
    if (body == nullptr || body == effector_body_) continue;
    const auto it = std::find_if(rolling_.begin(), rolling_.end(),
                                 [body](const auto& r) { return r.first == body; });
    if (it == rolling_.end()) {
      rolling_.emplace_back(body, rho);
    } else {
      it->second = std::max(it->second, rho);
    }
  }
}

// Rolling resistance, applied by hand: ODE's own (dContactRolling) adds
// friction-coupled rows that make dWorldStep's LCP solver report "s <= 0" on
// every resting ball. The torque opposes the spin with the body's weight acting
// `rho` metres ahead of the contact, and never more than stops the spin within
// one step.
void OdeWorld::ApplyRollingResistance() {
  const double dt = step_seconds();
  for (const auto& [body, rho] : rolling_) {
    const dReal* w = dBodyGetAngularVel(body);
    const Eigen::Vector3d omega(w[0], w[1], w[2]);
    const double speed = omega.norm();
    if (speed < 1e-12 || rho <= 0) continue;
    dMass mass;
    dBodyGetMass(body, &mass);
    const Eigen::Matrix3d rotation = FromOde(dBodyGetRotation(body));
    const Eigen::Matrix3d inertia = rotation * FromOde(mass.I) * rotation.transpose();
    const Eigen::Vector3d axis = omega / speed;
    const double stopping = axis.dot(inertia * axis) * speed / dt;
    const double resisting = rho * mass.mass * physics_.gravity;
    const Eigen::Vector3d torque = -std::min(stopping, resisting) * axis;
    dBodyAddTorque(body, torque.x(), torque.y(), torque.z());
  }
}

bool OdeWorld::Step() {
  effector_hit_static_ = false;
  pairs_.clear();
  rolling_.clear();
  dSpaceCollide(space_, this, &CollectPair);
  std::sort(pairs_.begin(), pairs_.end(), [](const Pair& x, const Pair& y) {
    return std::pair(TagOf(x.a).order, TagOf(x.b).order) <
           std::pair(TagOf(y.a).order, TagOf(y.b).order);
  });
  for (const Pair& pair : pairs_) AddContacts(pair.a, pair.b);
  ApplyRollingResistance();
  // dWorldStep (a direct LCP solve), not dWorldQuickStep: quickstep reorders
  // constraints with ODE's process-wide random generator, which would make one
  // scene's result depend on what other scenes did.
  dWorldStep(world_, step_seconds());
  dJointGroupEmpty(contacts_);
  return effector_hit_static_;
}

bool OdeWorld::Collides(dGeomID geom) {
  struct Query {
    dGeomID geom;
    bool hit;
  } query{geom, false};
  dSpaceCollide2(geom, reinterpret_cast<dGeomID>(space_), &query,
                 [](void* data, dGeomID o1, dGeomID o2) {
                   auto* q = static_cast<Query*>(data);
                   const dGeomID other = o1 == q->geom ? o2 : o1;
                   if (q->hit || other == q->geom || !dGeomIsEnabled(other)) return;
                   const dBodyID body = dGeomGetBody(q->geom);
                   if (body != nullptr && dGeomGetBody(other) == body) return;
                   dContactGeom touch;
                   if (dCollide(q->geom, other, 1, &touch, sizeof touch) > 0) q->hit = true;
                 });
  return query.hit;
}

}  // namespace relmap::sim
