// A PCD file as a Cloud message.
#include "load_cloud.h"

#include <fstream>
#include <iterator>

#include "relevance_client.h"

namespace relmap::load {

StatusOr<LoadCloud> ReadPcdCloud(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return NotFoundError("cannot open " + path);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.empty()) return InvalidArgumentError(path + " is empty");
  LoadCloud cloud;
  cloud.cloud = client::PcdCloud(std::move(bytes));
  cloud.description = path;
  return cloud;
}

}  // namespace relmap::load
