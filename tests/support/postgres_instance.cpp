// PostgresInstance: initdb and pg_ctl, run as the postgres user under root.
#include "support/postgres_instance.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <libpq-fe.h>
#include <netinet/in.h>
#include <pwd.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "common/exec_argv.h"

namespace relmap::testing {
namespace {

// A port nobody listens on now. Another process may take it before the server
// binds it; Start then retries with another.
int FreeLoopbackPort() {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) return -1;
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = 0;
  socklen_t length = sizeof address;
  int port = -1;
  if (bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0 &&
      getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length) == 0) {
    port = ntohs(address.sin_port);
  }
  close(fd);
  return port;
}

// Runs `argv` (as the postgres user under root) with its output appended to
// `log`, and waits; its exit status.
int Run(std::vector<std::string> argv, const std::string& log) {
  if (geteuid() == 0) argv.insert(argv.begin(), {"runuser", "-u", "postgres", "--"});
  const std::vector<char*> args = ExecArgv(argv);
  const pid_t child = fork();
  if (child < 0) return -1;
  if (child == 0) {
    // The postgres user may not be allowed into the test's working directory.
    if (chdir("/") != 0) _exit(126);
    const int out = open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
    if (out < 0 || dup2(out, STDOUT_FILENO) < 0 || dup2(out, STDERR_FILENO) < 0) _exit(126);
    execvp(args[0], args.data());
    _exit(127);
  }
  int status = 0;
  if (waitpid(child, &status, 0) != child) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

std::string ReadFile(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string QuotedIdentifier(std::string_view name) {
  std::string quoted = "\"";
  for (char c : name) {
    if (c == '"') quoted.push_back('"');
    quoted.push_back(c);
  }
  return quoted.append("\"");
}

}  // namespace

StatusOr<std::unique_ptr<PostgresInstance>> PostgresInstance::Start(
    const PostgresInstanceOptions& options) {
  std::string pattern = (std::filesystem::temp_directory_path() / "relmap_pg_XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) {
    return Status(StatusCode::kUnavailable, "cannot create a directory for PostgreSQL");
  }
  const std::filesystem::path directory = pattern;
  // From here on the destructor removes the directory, whatever fails.
  std::unique_ptr<PostgresInstance> instance(new PostgresInstance(pattern, 0, options));
  if (geteuid() == 0) {
    const passwd* postgres = getpwnam("postgres");
    if (postgres == nullptr || chown(pattern.c_str(), postgres->pw_uid, postgres->pw_gid) != 0) {
      return Status(StatusCode::kUnavailable,
                    "running as root needs the postgres system user (Debian's postgresql package)");
    }
  }
  const std::string data = (directory / "data").string();
  const std::string log = (directory / "server.log").string();
  // initdb's and pg_ctl's own output; the server writes to `log`.
  const std::string setup_log = (directory / "setup.log").string();
  const std::string bin = options.bin_directory + "/";
  // --no-sync: initdb's own fsync of the new cluster protects against a power
  // cut during the test, which nothing survives anyway; the server runs with
  // fsync as the options say.
  if (Run({bin + "initdb", "--pgdata=" + data, "--username=postgres", "--auth=trust",
           "--encoding=UTF8", "--no-locale", "--no-sync", "--no-instructions"},
          setup_log) != 0) {
    return Status(StatusCode::kUnavailable, "initdb failed:\n" + ReadFile(setup_log));
  }
  for (int attempt = 0; attempt < 5; ++attempt) {
    const int port = FreeLoopbackPort();
    if (port < 0) break;
    const std::string server_options =
        "-p " + std::to_string(port) + " -k " + directory.string() +
        " -c listen_addresses=127.0.0.1 -c fsync=" + (options.fsync ? "on" : "off") +
        " -c max_connections=60 -c shared_buffers=16MB";
    // -w waits until the server accepts connections.
    if (Run({bin + "pg_ctl", "--pgdata=" + data, "--log=" + log, "--wait", "--timeout=60",
             "--options=" + server_options, "--silent", "start"},
            setup_log) == 0) {
      instance->port_ = port;
      return instance;
    }
  }
  return Status(StatusCode::kUnavailable,
                "PostgreSQL did not start:\n" + ReadFile(setup_log) + ReadFile(log));
}

PostgresInstance::~PostgresInstance() {
  if (port_ != 0) {
    Run({options_.bin_directory + "/pg_ctl", "--pgdata=" + directory_ + "/data", "--wait",
         "--timeout=60", "--mode=fast", "--silent", "stop"},
        directory_ + "/setup.log");
  }
  std::error_code ignored;
  std::filesystem::remove_all(directory_, ignored);
}

std::string PostgresInstance::Uri(std::string_view database) const {
  return "postgresql://postgres@127.0.0.1:" + std::to_string(port_) + "/" + std::string(database);
}

Status PostgresInstance::CreateDatabase(std::string_view name) {
  return Execute("postgres", "CREATE DATABASE " + QuotedIdentifier(name));
}

Status PostgresInstance::Execute(std::string_view database, std::string_view sql) {
  const Status status = Query(database, sql).status();
  return status.code() == StatusCode::kNotFound ? OkStatus() : status;
}

StatusOr<std::string> PostgresInstance::Query(std::string_view database, std::string_view sql) {
  PGconn* conn = PQconnectdb(Uri(database).c_str());
  StatusOr<std::string> value = Status(StatusCode::kNotFound, std::string(sql) + ": no row");
  if (PQstatus(conn) != CONNECTION_OK) {
    value = Status(StatusCode::kUnavailable, PQerrorMessage(conn));
  } else {
    PQsetNoticeProcessor(
        conn, [](void*, const char*) {}, nullptr);
    PGresult* result = PQexec(conn, std::string(sql).c_str());
    const ExecStatusType code = PQresultStatus(result);
    if (code != PGRES_COMMAND_OK && code != PGRES_TUPLES_OK) {
      value = Status(StatusCode::kInternal, std::string(sql) + ": " + PQerrorMessage(conn));
    } else if (PQntuples(result) > 0 && PQnfields(result) > 0) {
      value = std::string(PQgetvalue(result, 0, 0));
    }
    PQclear(result);
  }
  PQfinish(conn);
  return value;
}

}  // namespace relmap::testing
