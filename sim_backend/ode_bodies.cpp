// Scene bodies -> ODE geoms and bodies. A composite is one body with a geom per
// part; mass is spread over the parts by volume.
#include "ode_bodies.h"

#include <cmath>
#include <numbers>
#include <string>

#include "ode_math.h"

namespace relmap::sim {
namespace {

// A non-composite shape and where it sits in its body's (object's) frame.
struct Part {
  const Body* shape;
  Eigen::Isometry3d pose;
  Material material;
};

std::vector<Part> PartsOf(const Body& body) {
  const Material material = ResolveMaterial(body);
  if (body.shape() != "composite") return {{&body, Eigen::Isometry3d::Identity(), material}};
  std::vector<Part> parts;
  for (const Body& part : body.parts()) {
    parts.push_back({&part,
                     part.has_pose() ? ToIsometry(part.pose()) : Eigen::Isometry3d::Identity(),
                     ResolveMaterial(part, &material)});
  }
  return parts;
}

Eigen::Vector3d MeshVertex(const Mesh& mesh, std::uint32_t i) {
  return {mesh.vertices(3 * i), mesh.vertices(3 * i + 1), mesh.vertices(3 * i + 2)};
}

// A closed mesh's mass properties at density 1 about its frame's origin: the
// sum over triangles of the tetrahedra they make with the origin (signed, so
// the outside cancels). Covariance of a tetrahedron (0, a, b, c):
// C = det(A)/120 * A K A^T, A = [a b c], K = [[2,1,1],[1,2,1],[1,1,2]];
// inertia I = trace(C) Id - C.
void MeshMassAtUnitDensity(const Mesh& mesh, double* volume, Eigen::Vector3d* centroid,
                           Eigen::Matrix3d* inertia) {
  Eigen::Matrix3d k;
  k << 2, 1, 1, 1, 2, 1, 1, 1, 2;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  double v = 0;
  for (int t = 0; t + 2 < mesh.indices_size(); t += 3) {
    Eigen::Matrix3d a;
    a.col(0) = MeshVertex(mesh, mesh.indices(t));
    a.col(1) = MeshVertex(mesh, mesh.indices(t + 1));
    a.col(2) = MeshVertex(mesh, mesh.indices(t + 2));
    const double det = a.determinant();
    v += det / 6.0;
    moment += det / 6.0 * (a.col(0) + a.col(1) + a.col(2)) / 4.0;
    covariance += det / 120.0 * a * k * a.transpose();
  }
  *volume = v;
  *centroid = moment / v;
  *inertia = covariance.trace() * Eigen::Matrix3d::Identity() - covariance;
}

double Volume(const Body& shape) {
  const std::string& s = shape.shape();
  if (s == "box") return shape.size().x() * shape.size().y() * shape.size().z();
  const double r = shape.radius();
  using std::numbers::pi;
  if (s == "sphere") return 4.0 / 3.0 * pi * r * r * r;
  if (s == "cylinder") return pi * r * r * shape.length();
  if (s == "capsule") return pi * r * r * shape.length() + 4.0 / 3.0 * pi * r * r * r;
  double volume = 0;
  Eigen::Vector3d centroid;
  Eigen::Matrix3d inertia;
  MeshMassAtUnitDensity(shape.mesh(), &volume, &centroid, &inertia);
  return volume;
}

// `mass` kg of `shape`, in the shape's own frame.
dMass ShapeMass(const Body& shape, double mass) {
  dMass m;
  dMassSetZero(&m);
  const std::string& s = shape.shape();
  constexpr int kAlongZ = 3;
  if (s == "box") {
    dMassSetBoxTotal(&m, mass, shape.size().x(), shape.size().y(), shape.size().z());
  } else if (s == "sphere") {
    dMassSetSphereTotal(&m, mass, shape.radius());
  } else if (s == "cylinder") {
    dMassSetCylinderTotal(&m, mass, kAlongZ, shape.radius(), shape.length());
  } else if (s == "capsule") {
    dMassSetCapsuleTotal(&m, mass, kAlongZ, shape.radius(), shape.length());
  } else {
    double volume = 0;
    Eigen::Vector3d c;
    Eigen::Matrix3d i;
    MeshMassAtUnitDensity(shape.mesh(), &volume, &c, &i);
    const double density = mass / volume;
    i *= density;
    // dMass keeps the inertia about the frame's origin, like `i`.
    dMassSetParameters(&m, mass, c.x(), c.y(), c.z(), i(0, 0), i(1, 1), i(2, 2), i(0, 1), i(0, 2),
                       i(1, 2));
  }
  return m;
}

dGeomID CreateGeom(OdeWorld& world, const Body& shape, const MeshData** mesh) {
  const std::string& s = shape.shape();
  const dSpaceID space = world.space();
  *mesh = nullptr;
  if (s == "box") return dCreateBox(space, shape.size().x(), shape.size().y(), shape.size().z());
  if (s == "sphere") return dCreateSphere(space, shape.radius());
  if (s == "cylinder") return dCreateCylinder(space, shape.radius(), shape.length());
  if (s == "capsule") return dCreateCapsule(space, shape.radius(), shape.length());
  std::vector<double> vertices(shape.mesh().vertices().begin(), shape.mesh().vertices().end());
  std::vector<dTriIndex> indices(shape.mesh().indices().begin(), shape.mesh().indices().end());
  MeshData* data = world.NewMesh(std::move(vertices), std::move(indices));
  *mesh = data;
  return dCreateTriMesh(space, data->id, nullptr, nullptr, nullptr);
}

std::string DisplayName(const Body& body, const char* fallback, int index) {
  return body.name().empty() ? std::string(fallback) + std::to_string(index) : body.name();
}

void AddStatic(const Body& body, std::int32_t id, OdeWorld& world, SimBody* out) {
  const Eigen::Isometry3d world_from_body =
      body.has_pose() ? ToIsometry(body.pose()) : Eigen::Isometry3d::Identity();
  for (const Part& part : PartsOf(body)) {
    const MeshData* mesh = nullptr;
    const dGeomID geom = CreateGeom(world, *part.shape, &mesh);
    const Eigen::Isometry3d pose = world_from_body * part.pose;
    dMatrix3 r;
    ToOde(pose.linear(), r);
    dGeomSetPosition(geom, pose.translation().x(), pose.translation().y(), pose.translation().z());
    dGeomSetRotation(geom, r);
    world.Tag(geom, id, /*moveable=*/false, part.material, mesh);
    out->geoms.push_back(geom);
  }
}

void AddObject(const Body& body, std::int32_t id, OdeWorld& world, SimBody* out) {
  const std::vector<Part> parts = PartsOf(body);
  double total_volume = 0;
  for (const Part& part : parts) total_volume += Volume(*part.shape);
  dMass total;
  dMassSetZero(&total);
  for (const Part& part : parts) {
    dMass m = ShapeMass(*part.shape, body.mass() * Volume(*part.shape) / total_volume);
    dMatrix3 r;
    ToOde(part.pose.linear(), r);
    dMassRotate(&m, r);
    dMassTranslate(&m, part.pose.translation().x(), part.pose.translation().y(),
                   part.pose.translation().z());
    dMassAdd(&total, &m);
  }
  // ODE wants the body's origin at its centre of mass: shift everything by -c.
  const Eigen::Vector3d c(total.c[0], total.c[1], total.c[2]);
  dMassTranslate(&total, -c.x(), -c.y(), -c.z());
  total.c[0] = total.c[1] = total.c[2] = 0;

  out->body = dBodyCreate(world.world());
  dBodySetMass(out->body, &total);
  out->body_from_object = Eigen::Translation3d(-c) * Eigen::Isometry3d::Identity();
  for (const Part& part : parts) {
    const MeshData* mesh = nullptr;
    const dGeomID geom = CreateGeom(world, *part.shape, &mesh);
    dGeomSetBody(geom, out->body);
    const Eigen::Vector3d offset = part.pose.translation() - c;
    dMatrix3 r;
    ToOde(part.pose.linear(), r);
    dGeomSetOffsetPosition(geom, offset.x(), offset.y(), offset.z());
    dGeomSetOffsetRotation(geom, r);
    world.Tag(geom, id, /*moveable=*/true, part.material, mesh);
    out->geoms.push_back(geom);
  }
}

}  // namespace

std::vector<SimBody> BuildBodies(const Scene& scene, OdeWorld& world) {
  std::vector<SimBody> bodies;
  for (int i = 0; i < scene.static_bodies_size(); ++i) {
    SimBody b;
    b.id = static_cast<std::int32_t>(bodies.size());
    b.name = DisplayName(scene.static_bodies(i), "static", i);
    AddStatic(scene.static_bodies(i), b.id, world, &b);
    bodies.push_back(std::move(b));
  }
  for (int i = 0; i < scene.objects_size(); ++i) {
    const Body& object = scene.objects(i);
    const std::uint32_t count = ObjectCount(object);
    for (std::uint32_t k = 0; k < count; ++k) {
      SimBody b;
      b.id = static_cast<std::int32_t>(bodies.size());
      b.name = DisplayName(object, "object", i);
      // append(), not operator+: GCC 12 warns falsely (-Wrestrict) on "#" + string.
      if (count > 1) b.name.append("#").append(std::to_string(k));
      b.moveable = true;
      b.object_index = i;
      AddObject(object, b.id, world, &b);
      bodies.push_back(std::move(b));
    }
  }
  return bodies;
}

}  // namespace relmap::sim
