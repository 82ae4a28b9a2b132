// Writes the seed corpora of tests/fuzz/corpus/ (small files, committed): cuts of
// the real Kinect clouds re-encoded as ascii, binary and binary_compressed PCD and
// as packed clouds, classifier snapshots, and RPC requests in service_fuzz's
// envelope, with the crashers found before the fuzzers existed.
//   fuzz_make_seeds <dir of real .pcd files> <corpus dir>
#include <Eigen/Core>
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "cmm/collaborative_mixture_models.h"
#include "common/pcd/pcd_encoder.h"
#include "common/pcd/pcd_reader.h"
#include "common/random.h"
#include "relmap/v1/relevance_service.pb.h"
#include "session/records/snapshot_codec.h"

namespace {

namespace fs = std::filesystem;
using relmap::pcd::Point;

void Write(const fs::path& path, const std::string& bytes) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << bytes;
}

void AppendU32(std::string& out, std::uint32_t value) {
  for (int shift = 0; shift < 32; shift += 8) out.push_back(static_cast<char>(value >> shift));
}

std::uint32_t Rgba(const Point& p) {
  return std::uint32_t{p.a} << 24 | std::uint32_t{p.r} << 16 | std::uint32_t{p.g} << 8 | p.b;
}

// Every `step`-th point of every `step`-th row: the whole scene, few points.
relmap::pcd::Points Decimate(const relmap::pcd::Points& cloud, std::uint32_t step) {
  relmap::pcd::Points cut;
  cut.width = cloud.width / step;
  cut.height = cloud.height / step;
  for (std::uint32_t row = 0; row < cut.height; ++row) {
    for (std::uint32_t column = 0; column < cut.width; ++column) {
      cut.points.push_back(
          cloud.points[std::size_t{row} * step * cloud.width + std::size_t{column} * step]);
    }
  }
  return cut;
}

std::string Header(const relmap::pcd::Points& cloud, const char* data) {
  return "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS x y z rgba\n"
         "SIZE 4 4 4 4\nTYPE F F F U\nCOUNT 1 1 1 1\nWIDTH " +
         std::to_string(cloud.width) + "\nHEIGHT " + std::to_string(cloud.height) +
         "\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " + std::to_string(cloud.points.size()) + "\nDATA " +
         data + "\n";
}

std::string Ascii(const relmap::pcd::Points& cloud) {
  std::string out = Header(cloud, "ascii");
  char line[96];
  for (const Point& p : cloud.points) {
    std::snprintf(line, sizeof line, "%.9g %.9g %.9g %u\n", p.x, p.y, p.z, Rgba(p));
    out += line;
  }
  return out;
}

// binary_compressed: the fields one after another (x of every point, then y, ...),
// LZF-coded as literal runs only (a valid LZF stream; the reader's back references
// are the fuzzer's to find).
std::string Compressed(const relmap::pcd::Points& cloud) {
  std::string fields;
  for (int field = 0; field < 4; ++field) {
    for (const Point& p : cloud.points) {
      const float xyz[3] = {p.x, p.y, p.z};
      std::uint32_t word = Rgba(p);
      if (field < 3) std::memcpy(&word, &xyz[field], 4);
      AppendU32(fields, word);
    }
  }
  std::string lzf;
  for (std::size_t at = 0; at < fields.size(); at += 32) {
    const std::string run = fields.substr(at, 32);
    lzf.push_back(static_cast<char>(run.size() - 1));
    lzf += run;
  }
  std::string out = Header(cloud, "binary_compressed");
  AppendU32(out, static_cast<std::uint32_t>(lzf.size()));
  AppendU32(out, static_cast<std::uint32_t>(fields.size()));
  return out + lzf;
}

std::string PackedPoints(const relmap::pcd::Points& cloud) {
  std::string out;
  for (const Point& p : cloud.points) {
    const float xyz[3] = {p.x, p.y, p.z};
    out.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
    for (std::uint8_t byte : {p.r, p.g, p.b, p.a}) out.push_back(static_cast<char>(byte));
  }
  return out;
}

// A seed must read back as the cloud it was cut from, or it tests nothing.
void CheckReadsBack(const std::string& file, const relmap::pcd::Points& cloud) {
  const auto read = relmap::pcd::ReadPcd(file);
  if (!read.ok() || read->points.size() != cloud.points.size()) {
    std::fprintf(stderr, "make_seeds: a seed does not read back: %s\n",
                 read.ok() ? "size" : read.status().message().c_str());
    std::exit(1);
  }
}

// service_fuzz's envelope (service_fuzz.cpp).
void AppendSized(std::string& out, const google::protobuf::Message& message) {
  const std::string bytes = message.SerializeAsString();
  out.push_back(static_cast<char>(bytes.size() & 0xff));
  out.push_back(static_cast<char>(bytes.size() >> 8));
  out += bytes;
}

std::string Envelope(int rpc, int flags, const google::protobuf::Message& request,
                     const relmap::v1::CreateSessionRequest* first_session = nullptr,
                     const relmap::v1::ComputeMapsRequest* first_frame = nullptr) {
  flags |= (first_session ? 1 : 0) | (first_frame ? 8 : 0);
  std::string out{static_cast<char>(rpc), static_cast<char>(flags)};
  if (first_session) AppendSized(out, *first_session);
  if (first_session && first_frame) AppendSized(out, *first_frame);
  return out + request.SerializeAsString();
}

relmap::v1::FeatureVector Vector(int dimension, double scale, double offset) {
  relmap::v1::FeatureVector vector;
  for (int i = 0; i < dimension; ++i) vector.add_values(offset + scale * (i + 1));
  return vector;
}

void WriteServiceSeeds(const fs::path& out, const relmap::pcd::Points& cut) {
  using namespace relmap::v1;
  constexpr int kSession = 2 | 4;  // its id and token in the call
  const fs::path dir = out / "service";
  CreateSessionRequest plain;
  // Supervoxels coarse enough for the 32 x 24 points of the seed cloud.
  CreateSessionRequest coarse;
  coarse.mutable_config()->mutable_supervoxels()->set_voxel_resolution(0.03f);
  coarse.mutable_config()->mutable_supervoxels()->set_seed_resolution(0.15f);
  coarse.mutable_config()->mutable_supervoxels()->set_min_voxels(2);
  CreateSessionRequest features;
  features.mutable_config()->set_feature_dimension(4);
  features.mutable_config()->set_seed(7);
  Write(dir / "create_default", Envelope(0, 0, plain));
  Write(dir / "create_features", Envelope(0, 0, features));
  // The crashers fixed before: PCL's octree assert, and an octree of unbounded size.
  CreateSessionRequest tiny_voxels;
  for (const auto& [name, value] : {std::pair{"1e-9", 1e-9}, std::pair{"1e-30", 1e-30}}) {
    CreateSessionRequest tiny;
    tiny.mutable_config()->mutable_supervoxels()->set_voxel_resolution(static_cast<float>(value));
    Write(dir / (std::string("crash_voxel_resolution_") + name), Envelope(0, 0, tiny));
    if (tiny_voxels.ByteSizeLong() == 0) tiny_voxels = tiny;
  }
  CreateSessionRequest octree;
  octree.mutable_config()->mutable_change_detector()->set_octree_resolution(1e-9);
  Write(dir / "crash_octree_resolution_1e-9", Envelope(0, 0, octree));

  ComputeMapsRequest packed;
  packed.mutable_cloud()->mutable_packed()->set_width(cut.width);
  packed.mutable_cloud()->mutable_packed()->set_height(cut.height);
  packed.mutable_cloud()->mutable_packed()->set_points(PackedPoints(cut));
  Write(dir / "maps_packed", Envelope(4, kSession, packed, &coarse));
  Write(dir / "maps_packed_default_config", Envelope(4, kSession, packed, &plain));
  ComputeMapsRequest pcd;
  const relmap::pcd::Points small = Decimate(cut, 2);
  pcd.mutable_cloud()->set_pcd(relmap::pcd::EncodePcd(small.width, small.height, small.points));
  Write(dir / "maps_pcd", Envelope(4, kSession, pcd, &coarse));
  ComputeMapsRequest huge;  // the crasher fixed before: width x height wrapped
  huge.mutable_cloud()->mutable_packed()->set_width(4294967295u);
  huge.mutable_cloud()->mutable_packed()->set_height(4294967295u);
  huge.mutable_cloud()->mutable_packed()->set_points(std::string(64, '\0'));
  Write(dir / "crash_packed_4294967295", Envelope(4, kSession, huge, &plain));

  PostOutcomeRequest outcome;
  outcome.set_frame_id(0);
  outcome.set_supervoxel_id(0);
  outcome.set_label(LABEL_MOVEABLE);
  outcome.set_request_id("r1");
  Write(dir / "post_label", Envelope(5, kSession, outcome, &coarse, &packed));
  PostOutcomeRequest after = outcome;
  *after.mutable_after_cloud() = packed.cloud();
  Write(dir / "post_after_cloud", Envelope(5, kSession, after, &coarse, &packed));
  // The calls those crashers crashed in, on a session created with them (if it is).
  Write(dir / "crash_voxel_resolution_1e-9_maps", Envelope(4, kSession, packed, &tiny_voxels));
  Write(dir / "crash_octree_resolution_1e-9_post", Envelope(5, kSession, after, &octree, &packed));

  ClassifyFeaturesRequest classify;
  for (int i = 0; i < 3; ++i) *classify.add_features() = Vector(4, 0.1 * i, 0.5);
  Write(dir / "classify", Envelope(6, kSession, classify, &features));
  AddSamplesRequest add;
  add.set_request_id("a1");
  for (int i = 0; i < 6; ++i) {
    LabelledFeature* sample = add.add_samples();
    *sample->mutable_feature() = Vector(4, 0.1, i % 2 ? 1.0 : -1.0);
    sample->set_label(i % 2 ? LABEL_MOVEABLE : LABEL_NOT_MOVEABLE);
  }
  Write(dir / "add_samples", Envelope(7, kSession, add, &features));

  GetSessionRequest get;
  Write(dir / "get", Envelope(1, kSession, get, &plain));
  ListSessionsRequest list;
  list.set_page_size(2);
  Write(dir / "list", Envelope(2, 0, list, &plain));
  DeleteSessionRequest remove;
  Write(dir / "delete", Envelope(3, kSession, remove, &plain));
  ExportSessionRequest exported;
  Write(dir / "export", Envelope(8, kSession, exported, &features));

  ImportSessionRequest import;
  SessionState* state = import.mutable_state();
  *state->mutable_config() = features.config();
  for (const auto& sample : add.samples()) *state->add_samples() = sample;
  for (std::uint64_t word : {1ULL, 2ULL, 3ULL, 4ULL}) state->add_target_rng_state(word);
  state->set_interactions(3);
  Write(dir / "import", Envelope(9, 0, import));
  Write(out / "import" / "import_samples", import.SerializeAsString());
  ImportSessionRequest empty;
  *empty.mutable_state()->mutable_config() = features.config();
  Write(out / "import" / "import_empty", empty.SerializeAsString());
  ImportSessionRequest short_rng = import;
  short_rng.mutable_state()->mutable_target_rng_state()->RemoveLast();
  Write(out / "import" / "import_short_rng", short_rng.SerializeAsString());
}

// Snapshots of small models of each variant, without their CRC-32 (snapshot_fuzz.cpp
// appends it).
void WriteSnapshotSeeds(const fs::path& out) {
  using relmap::cmm::Variant;
  const std::pair<const char*, Variant> variants[] = {{"corrected", Variant::kCorrected},
                                                      {"paper2018", Variant::kPaper2018},
                                                      {"corrected_v1", Variant::kCorrectedV1}};
  for (const auto& [name, variant] : variants) {
    for (const int samples : {0, 12}) {
      auto model = relmap::cmm::CollaborativeMixtureModels::Create(
          relmap::cmm::CmmConfig::ForVariant(variant), 3);
      if (!model.ok()) std::exit(1);
      relmap::Random random(11);
      for (int i = 0; i < samples; ++i) {
        const int label = i % 2;
        Eigen::Vector3d x;
        for (int d = 0; d < 3; ++d)
          x[d] = (label ? 1.0 : -1.0) + 0.6 * (random.UniformUnit() - 0.5);
        (void)model->Add(x, label);
      }
      auto blob = relmap::session::EncodeSnapshot(model->Snapshot());
      if (!blob.ok()) std::exit(1);
      blob->resize(blob->size() - 4);
      Write(out / "snapshot" / (std::string(name) + "_" + std::to_string(samples)), *blob);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: fuzz_make_seeds <dir of real .pcd> <corpus dir>\n");
    return 2;
  }
  const fs::path out = argv[2];
  std::vector<fs::path> clouds;
  for (const auto& entry : fs::directory_iterator(argv[1])) {
    if (entry.path().extension() == ".pcd") clouds.push_back(entry.path());
  }
  std::sort(clouds.begin(), clouds.end());
  relmap::pcd::Points first_cut;
  for (const fs::path& path : clouds) {
    const auto bytes = relmap::pcd::ReadFileBytes(path.string(), 64 << 20);
    if (!bytes.ok()) {
      std::fprintf(stderr, "make_seeds: %s: %s\n", path.c_str(), bytes.status().message().c_str());
      return 1;
    }
    const auto cloud = relmap::pcd::ReadPcd(*bytes);
    if (!cloud.ok()) {
      std::fprintf(stderr, "make_seeds: %s: %s\n", path.c_str(), cloud.status().message().c_str());
      return 1;
    }
    const std::string stem = path.stem().string();
    const relmap::pcd::Points cut = Decimate(*cloud, 40);            // 16 x 12 of a 640 x 480 frame
    if (first_cut.points.empty()) first_cut = Decimate(*cloud, 20);  // 32 x 24
    const std::string files[][2] = {
        {"ascii", Ascii(cut)},
        {"binary", relmap::pcd::EncodePcd(cut.width, cut.height, cut.points)},
        {"compressed", Compressed(cut)}};
    for (const auto& [kind, file] : files) {
      CheckReadsBack(file, cut);
      std::string name = stem;
      name.append("_").append(kind).append(".pcd");
      for (const char* target : {"pcd_reader", "pcd_decoder"}) Write(out / target / name, file);
      // The header and the first bytes of the data, for the header parser.
      Write(out / "pcd_header" / name, file.substr(0, file.find("DATA") + 64));
    }
    std::string packed;
    AppendU32(packed, cut.width);
    AppendU32(packed, cut.height);
    Write(out / "packed_decoder" / (stem + ".bin"), packed + PackedPoints(cut));
  }
  // The crasher fixed before: width = height = 2^32 - 1, whose product wrapped.
  std::string huge;
  AppendU32(huge, 4294967295u);
  AppendU32(huge, 4294967295u);
  Write(out / "packed_decoder" / "crash_4294967295", huge + std::string(32, '\0'));
  WriteServiceSeeds(out, first_cut);
  WriteSnapshotSeeds(out);
  return 0;
}
