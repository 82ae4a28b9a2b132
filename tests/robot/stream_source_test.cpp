// The stream sources: PCD files one after another on a pipe (standard input) and over
// TCP connections from a fake camera on loopback.
#include "stream_source.h"

#include <gtest/gtest.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstring>
#include <fstream>
#include <thread>

#include "integration/test_support.h"
#include "posix_io.h"

namespace relmap::robot {
namespace {

using std::chrono::milliseconds;

std::string Header(int points, const std::string& data) {
  return "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS x y z rgb\n"
         "SIZE 4 4 4 4\nTYPE F F F U\nCOUNT 1 1 1 1\nWIDTH " +
         std::to_string(points) + "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " +
         std::to_string(points) + "\nDATA " + data + "\n";
}

// Three points, one a line; the last line without its newline when `last_newline` is off.
std::string AsciiPcd(bool last_newline = true) {
  return Header(3, "ascii") +
         "0.1 0.2 0.9 4278190335\n\n-0.1 0.2 1.1 4278255360\n0 0 1 4294901760" +
         (last_newline ? "\n" : "");
}

// `points` points of 16 bytes, with newlines and '#' among the bytes: binary data is
// not read by lines.
std::string BinaryPcd(int points) {
  std::string data;
  for (int i = 0; i < points; ++i) {
    const float xyz[3] = {0.01f * static_cast<float>(i), 0.0f, 1.0f};
    const std::uint32_t rgb = 0x0a230aff;  // '\n', '#', '\n' among the bytes
    char bytes[16];
    std::memcpy(bytes, xyz, 12);
    std::memcpy(bytes + 12, &rgb, 4);
    data.append(bytes, 16);
  }
  return Header(points, "binary") + data;
}

// A binary_compressed file as PCL writes it: sizes, LZF bytes (here just opaque bytes:
// only the server decompresses), then the NUL padding PCL leaves at the end.
std::string CompressedPcd() {
  const std::string lzf("\x05\nsome\nbytes\x00\x01", 14);
  std::string sizes(8, '\0');
  const auto compressed = static_cast<std::uint32_t>(lzf.size());
  const std::uint32_t uncompressed = 3 * 16;
  std::memcpy(sizes.data(), &compressed, 4);
  std::memcpy(sizes.data() + 4, &uncompressed, 4);
  return Header(3, "binary_compressed") + sizes + lzf;
}
const std::string kPclPadding(300, '\0');

// A pipe, its write end fed by a thread; the read end is what the source reads.
class Pipe {
 public:
  explicit Pipe(std::string bytes) {
    int fds[2];
    EXPECT_EQ(::pipe(fds), 0);
    read_.reset(fds[0]);
    writer_ = std::thread([fd = fds[1], bytes = std::move(bytes)] {
      (void)WriteAll(fd, bytes);
      ::close(fd);
    });
  }
  ~Pipe() { writer_.join(); }
  int fd() const { return read_.get(); }

 private:
  UniqueFd read_;
  std::thread writer_;
};

std::string NextPcd(CloudSource& source) {
  StatusOr<std::optional<SourceFrame>> frame = source.Next();
  EXPECT_TRUE(frame.ok()) << frame.status().message();
  if (!frame.ok() || !frame->has_value()) return "<none>";
  return (*frame)->cloud.pcd();
}

TEST(StreamSource, CutsAsciiBinaryAndCompressedFilesApartToTheByte) {
  // 70 000 binary points (1.1 MB) are more than a pipe holds: read while written.
  const std::string big = BinaryPcd(70000);
  Pipe pipe(AsciiPcd() + BinaryPcd(2) + CompressedPcd() + kPclPadding + big + AsciiPcd(false));
  StreamSource source(pipe.fd(), nullptr);
  EXPECT_EQ(NextPcd(source), AsciiPcd());
  EXPECT_EQ(NextPcd(source), BinaryPcd(2));
  EXPECT_EQ(NextPcd(source), CompressedPcd());
  EXPECT_EQ(NextPcd(source), big);
  EXPECT_EQ(NextPcd(source), AsciiPcd(false));
  EXPECT_EQ(NextPcd(source), "<none>");
}

TEST(StreamSource, ReadsRealKinectFramesConcatenated) {
  const std::string directory = RELMAP_REAL_DATA_DIR;
  std::string frames[2];
  for (int i = 0; i < 2; ++i) {
    std::ifstream in(directory + "/kinect_static_seq_" + std::to_string(i + 1) + ".pcd",
                     std::ios::binary);
    if (!in) GTEST_SKIP() << "no real clouds in " << directory;
    frames[i].assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  Pipe pipe(frames[0] + frames[1]);
  StreamSource source(pipe.fd(), nullptr);
  // Each file is the frame and PCL's padding of 3901 NULs after it.
  for (const std::string& file : frames) {
    const std::string frame = NextPcd(source);
    ASSERT_LE(frame.size(), file.size());
    EXPECT_EQ(frame, file.substr(0, frame.size()));
    EXPECT_EQ(file.find_first_not_of('\0', frame.size()), std::string::npos);
  }
  EXPECT_EQ(NextPcd(source), "<none>");
}

TEST(StreamSource, AStreamThatEndsInsideAFileIsDataLoss) {
  const std::string whole = BinaryPcd(4);
  Pipe pipe(AsciiPcd() + whole.substr(0, whole.size() - 5));
  StreamSource source(pipe.fd(), nullptr);
  EXPECT_EQ(NextPcd(source), AsciiPcd());
  StatusOr<std::optional<SourceFrame>> frame = source.Next();
  ASSERT_FALSE(frame.ok());
  EXPECT_EQ(frame.status().code(), StatusCode::kDataLoss);
}

TEST(StreamSource, SomethingElseThanPcdIsInvalid) {
  Pipe pipe("{\"not\": \"a cloud\"}\n");
  StreamSource source(pipe.fd(), nullptr);
  StatusOr<std::optional<SourceFrame>> frame = source.Next();
  ASSERT_FALSE(frame.ok());
  EXPECT_EQ(frame.status().code(), StatusCode::kInvalidArgument);
}

TEST(StreamSource, AHeaderDeclaringAHugeCloudIsRefusedBeforeReadingIt) {
  Pipe pipe(Header(1 << 30, "binary"));
  StreamSource source(pipe.fd(), nullptr);
  StatusOr<std::optional<SourceFrame>> frame = source.Next();
  ASSERT_FALSE(frame.ok());
  EXPECT_EQ(frame.status().code(), StatusCode::kInvalidArgument);
}

TEST(StreamSource, TheStopFlagEndsAWaitForBytes) {
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  UniqueFd read(fds[0]);
  UniqueFd write(fds[1]);  // open, silent: the source waits
  std::atomic<bool> stop{false};
  StreamSource source(read.get(), &stop);
  std::thread operator_presses_ctrl_c([&] {
    std::this_thread::sleep_for(milliseconds(150));
    stop.store(true);
  });
  EXPECT_EQ(NextPcd(source), "<none>");
  operator_presses_ctrl_c.join();
}

// A camera on loopback: connects to the source's port and sends `bytes`, then closes.
void Send(int port, const std::string& bytes) {
  StatusOr<UniqueFd> camera = ConnectTcp("127.0.0.1:" + std::to_string(port), milliseconds(2000));
  ASSERT_TRUE(camera.ok()) << camera.status().message();
  EXPECT_TRUE(WriteAll(camera->get(), bytes));
}

std::unique_ptr<TcpSource> Listen(milliseconds wait_timeout = milliseconds(5000)) {
  TcpSource::Options options;
  options.wait_timeout = wait_timeout;
  StatusOr<std::unique_ptr<TcpSource>> source = TcpSource::Listen("127.0.0.1:0", options, nullptr);
  EXPECT_TRUE(source.ok()) << source.status().message();
  return source.ok() ? std::move(source).value() : nullptr;
}

TEST(TcpSource, TakesFilesFromOneConnectionAndThenFromTheNext) {
  std::unique_ptr<TcpSource> source = Listen();
  ASSERT_NE(source, nullptr);
  const int port = source->port();
  std::thread camera([port] {
    Send(port, AsciiPcd() + BinaryPcd(2));
    Send(port, CompressedPcd() + kPclPadding);
  });
  EXPECT_EQ(NextPcd(*source), AsciiPcd());
  EXPECT_EQ(NextPcd(*source), BinaryPcd(2));
  EXPECT_EQ(NextPcd(*source), CompressedPcd());
  camera.join();
}

TEST(TcpSource, AWaitWithoutACameraEndsAtItsTimeout) {
  std::unique_ptr<TcpSource> source = Listen(milliseconds(200));
  ASSERT_NE(source, nullptr);
  const auto start = Clock::now();
  EXPECT_EQ(NextPcd(*source), "<none>");
  EXPECT_GE(Clock::now() - start, milliseconds(200));
}

TEST(TcpSource, ACameraThatHangsUpInsideAFileIsDataLossAndTheNextOneIsHeard) {
  std::unique_ptr<TcpSource> source = Listen();
  ASSERT_NE(source, nullptr);
  const int port = source->port();
  const std::string whole = BinaryPcd(4);
  std::thread cameras([&] {
    Send(port, whole.substr(0, 100));
    Send(port, whole);
  });
  StatusOr<std::optional<SourceFrame>> broken = source->Next();
  ASSERT_FALSE(broken.ok());
  EXPECT_EQ(broken.status().code(), StatusCode::kDataLoss);
  EXPECT_EQ(NextPcd(*source), whole);
  cameras.join();
}

TEST(TcpSource, AnAddressThatIsNotHostPortIsRefused) {
  StatusOr<std::unique_ptr<TcpSource>> source = TcpSource::Listen("5000", {}, nullptr);
  ASSERT_FALSE(source.ok());
  EXPECT_EQ(source.status().code(), StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace relmap::robot
