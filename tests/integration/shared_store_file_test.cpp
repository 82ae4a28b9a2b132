// One SQLite store file serves one server: a second relmap-server on the same
// --data-dir refuses to start, while the first serves on.
#include <gtest/gtest.h>

#include <string>

#include "integration/test_support.h"
#include "local_server.h"
#include "relevance_client.h"

namespace relmap::testing {
namespace {

TEST(SqliteStoreFile, ASecondServerOnTheSameDataDirectoryRefusesToStart) {
  TemporaryDirectory directory;
  client::LocalServerOptions options;
  options.memory_only = true;  // the data directory is given below, the same for both
  options.extra_arguments = {"--data-dir", directory.path() + "/data"};
  options.log_path = directory.path() + "/first.log";
  auto first = client::LocalServer::Start(RELMAP_SERVER_BINARY, options);
  ASSERT_TRUE(first.ok()) << first.status().message();

  options.log_path = directory.path() + "/second.log";
  auto second = client::LocalServer::Start(RELMAP_SERVER_BINARY, options);
  ASSERT_FALSE(second.ok());
  EXPECT_NE(second.status().message().find("in use by another server"), std::string::npos)
      << second.status().message();

  client::RelevanceClient client((*first)->address());
  client::SessionHandle session;
  EXPECT_TRUE(client.CreateSession({}, &session).ok());
}

}  // namespace
}  // namespace relmap::testing
