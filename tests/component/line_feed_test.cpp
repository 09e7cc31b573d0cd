// The receiver power line feed (docs/calibration.md) against a real FIFO and a real file: a writer
// that opens the FIFO as `rtl_power ... > fifo` does (its open blocks until a reader comes), goes
// away and comes back; a file appended to, cut short, replaced, deleted and written again; lines
// over the bound; problems said once. The loop runs in short slices until what a test waits for
// has happened (run_until.hpp), never for a guessed time.
#include "azt/linux/line_feed.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "run_until.hpp"

namespace azt::linux_os {
namespace {

namespace fs = std::filesystem;

class TempDir {
 public:
  TempDir() {
    std::string pattern = (fs::temp_directory_path() / "azt_line_feed_XXXXXX").string();
    if (::mkdtemp(pattern.data()) != nullptr) path_ = pattern;
  }
  ~TempDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  [[nodiscard]] const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

/// A program writing `text` into the FIFO as `program > fifo` does: its open blocks until a
/// reader has the FIFO open, then it writes everything and closes. On its own thread, because it
/// blocks; if no reader ever came, the destructor opens the FIFO once to let it finish.
class FifoWriter {
 public:
  FifoWriter(fs::path path, std::string text)
      : path_(std::move(path)), thread_([this, text = std::move(text)] { run(text); }) {}
  ~FifoWriter() {
    if (!done_) {
      const int fd = ::open(path_.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
      if (fd >= 0) ::close(fd);
    }
    thread_.join();
  }
  FifoWriter(const FifoWriter&) = delete;
  FifoWriter& operator=(const FifoWriter&) = delete;
  [[nodiscard]] bool done() const { return done_; }

 private:
  void run(const std::string& text) {
    // A write after the reader left fails with EPIPE on this thread instead of killing the test.
    sigset_t pipe_signal;
    sigemptyset(&pipe_signal);
    sigaddset(&pipe_signal, SIGPIPE);
    pthread_sigmask(SIG_BLOCK, &pipe_signal, nullptr);
    const int fd = ::open(path_.c_str(), O_WRONLY | O_CLOEXEC);
    for (std::size_t sent = 0; fd >= 0 && sent < text.size();) {
      const ssize_t n = ::write(fd, text.data() + sent, text.size() - sent);
      if (n <= 0) break;
      sent += static_cast<std::size_t>(n);
    }
    if (fd >= 0) ::close(fd);
    done_ = true;
  }

  fs::path path_;
  std::atomic<bool> done_{false};
  std::thread thread_;
};

struct Seen {
  std::vector<std::string> lines;
  std::vector<std::string> problems;
  LineFeedEvents events() {
    return {[this](std::string_view line) { lines.emplace_back(line); },
            [this](const std::string& problem) { problems.push_back(problem); }};
  }
};

void write_file(const fs::path& path, const std::string& text, bool append) {
  std::ofstream out(path, append ? std::ios::app | std::ios::binary : std::ios::binary);
  out << text;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

using Lines = std::vector<std::string>;

TEST(LineFeed, FifoDeliversLinesAndOpensAgainForTheNextWriter) {
  TempDir dir;
  const fs::path fifo = dir.path() / "power";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  boost::asio::io_context io;
  Seen seen;
  LineFeed feed(io, LineFeedConfig{.path = fifo.string(), .retry_s = 0.05}, seen.events());
  ASSERT_TRUE(run_until(io, [&] { return feed.is_open(); }));  // waiting before any writer
  {
    // The last line is unfinished when the writer goes: a writer killed mid-line.
    FifoWriter writer(fifo, "-42.1\n-41.9 dB\r\nhalf a li");
    ASSERT_TRUE(run_until(io, [&] { return writer.done() && feed.writer_hangups() == 1; }));
  }
  EXPECT_EQ(seen.lines, (Lines{"-42.1", "-41.9 dB"}));
  {
    FifoWriter second(fifo, "2024-01-02, 12:34:56, 100, 200, 1, 3, -1\n");
    ASSERT_TRUE(run_until(io, [&] { return second.done() && feed.writer_hangups() == 2; }));
  }
  EXPECT_EQ(seen.lines.size(), 3U);
  EXPECT_EQ(seen.lines.back(), "2024-01-02, 12:34:56, 100, 200, 1, 3, -1");
  EXPECT_EQ(feed.lines(), 3U);
  // Waiting for a writer is not a problem.
  EXPECT_TRUE(seen.problems.empty());
  EXPECT_TRUE(feed.problem().empty());
}

TEST(LineFeed, FifoDropsAnOverlongLineUpToTheNextNewline) {
  TempDir dir;
  const fs::path fifo = dir.path() / "power";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  boost::asio::io_context io;
  Seen seen;
  LineFeed feed(io, LineFeedConfig{.path = fifo.string(), .retry_s = 0.05}, seen.events());
  const std::string longest(kLineFeedMaxLineBytes, 'y');  // exactly the bound: delivered
  // This writer comes first: its open waits for the feed's.
  FifoWriter writer(fifo, std::string(kLineFeedMaxLineBytes + 1, 'x') + "\nafter\n" + longest +
                              "\n" + std::string(3 * kLineFeedMaxLineBytes, 'z') + "\nend\n");
  ASSERT_TRUE(run_until(io, [&] { return writer.done() && feed.writer_hangups() == 1; }));
  ASSERT_EQ(seen.lines.size(), 3U);
  EXPECT_EQ(seen.lines[0], "after");
  EXPECT_EQ(seen.lines[1], longest);
  EXPECT_EQ(seen.lines[2], "end");
  EXPECT_EQ(feed.overlong_lines(), 2U);
}

TEST(LineFeed, FileIsFollowedFromItsEndThroughTruncationReplacementAndDeletion) {
  TempDir dir;
  const fs::path file = dir.path() / "power.csv";
  write_file(file, "old reading\n", false);  // before the feed started: history, not read
  boost::asio::io_context io;
  Seen seen;
  LineFeed feed(io, LineFeedConfig{.path = file.string(), .retry_s = 0.05, .poll_s = 0.01},
                seen.events());
  ASSERT_TRUE(run_until(io, [&] { return feed.is_open(); }));

  write_file(file, "first\nsecond\r\npart", true);
  ASSERT_TRUE(run_until(io, [&] { return seen.lines.size() == 2; }));
  write_file(file, "ial\n", true);  // the rest of a line written in two pieces
  ASSERT_TRUE(run_until(io, [&] { return seen.lines.size() == 3; }));
  EXPECT_EQ(seen.lines, (Lines{"first", "second", "partial"}));
  EXPECT_EQ(feed.restarts(), 0U);

  write_file(file, "cut\n", false);  // `program > file` started again: shorter than was read
  ASSERT_TRUE(run_until(io, [&] { return seen.lines.size() == 4; }));
  EXPECT_EQ(seen.lines.back(), "cut");
  EXPECT_EQ(feed.restarts(), 1U);

  const fs::path next = dir.path() / "power.csv.new";
  write_file(next, "replaced, and longer than everything before it\n", false);
  fs::rename(next, file);  // another inode at the path: read from its start
  ASSERT_TRUE(run_until(io, [&] { return seen.lines.size() == 5; }));
  EXPECT_EQ(seen.lines.back(), "replaced, and longer than everything before it");
  EXPECT_EQ(feed.restarts(), 2U);

  fs::remove(file);
  ASSERT_TRUE(run_until(io, [&] { return !feed.problem().empty(); }));
  EXPECT_TRUE(contains(feed.problem(), "No such file")) << feed.problem();
  write_file(file, "back\n", false);
  ASSERT_TRUE(run_until(io, [&] { return seen.lines.size() == 6; }));
  EXPECT_EQ(seen.lines.back(), "back");
  EXPECT_TRUE(feed.problem().empty());
  ASSERT_EQ(seen.problems.size(), 2U);  // said when it went, cleared when it came back
  EXPECT_TRUE(contains(seen.problems[0], file.string()));
  EXPECT_EQ(seen.problems[1], "");
}

TEST(LineFeed, MissingPathIsSaidOnceAndALaterFileIsReadWhole) {
  TempDir dir;
  const fs::path file = dir.path() / "power.txt";
  boost::asio::io_context io;
  Seen seen;
  LineFeed feed(io, LineFeedConfig{.path = file.string(), .retry_s = 0.01, .poll_s = 0.01},
                seen.events());
  ASSERT_TRUE(run_until(io, [&] { return !seen.problems.empty(); }));
  EXPECT_TRUE(contains(seen.problems[0], "No such file")) << seen.problems[0];
  // About twenty retries: still said once.
  io.run_for(std::chrono::milliseconds(200));
  io.restart();
  EXPECT_EQ(seen.problems.size(), 1U);
  // A file that appears after the feed started holds only new lines.
  write_file(file, "-3.0\n-4.0 dB\n", false);
  ASSERT_TRUE(run_until(io, [&] { return seen.lines.size() == 2; }));
  EXPECT_EQ(seen.lines, (Lines{"-3.0", "-4.0 dB"}));
  EXPECT_EQ(seen.problems, (Lines{seen.problems[0], ""}));
}

TEST(LineFeed, RefusesWhatIsNeitherAFifoNorAFile) {
  TempDir dir;
  boost::asio::io_context io;
  Seen seen;
  LineFeed feed(io, LineFeedConfig{.path = dir.path().string(), .retry_s = 0.01}, seen.events());
  ASSERT_TRUE(run_until(io, [&] { return !feed.problem().empty(); }));
  EXPECT_TRUE(contains(feed.problem(), "neither a FIFO nor a regular file")) << feed.problem();
  EXPECT_FALSE(feed.is_open());
}

TEST(LineFeed, SaysWhenItMayNotRead) {
  if (::geteuid() == 0) GTEST_SKIP() << "root reads files without permission";
  TempDir dir;
  const fs::path file = dir.path() / "power.csv";
  write_file(file, "", false);
  fs::permissions(file, fs::perms::none);
  boost::asio::io_context io;
  Seen seen;
  LineFeed feed(io, LineFeedConfig{.path = file.string(), .retry_s = 0.01}, seen.events());
  ASSERT_TRUE(run_until(io, [&] { return !feed.problem().empty(); }));
  EXPECT_TRUE(contains(feed.problem(), "Permission denied")) << feed.problem();
}

TEST(LineFeed, AThrowingOrDestroyingLineHandlerIsSafe) {
  TempDir dir;
  const fs::path file = dir.path() / "power.txt";
  boost::asio::io_context io;
  std::vector<std::string> lines;
  std::unique_ptr<LineFeed> feed;
  LineFeedEvents events;
  events.line = [&](std::string_view line) {
    lines.emplace_back(line);
    if (line == "boom") throw std::runtime_error("a fault handling one line");
    if (line == "stop") feed.reset();  // the handler ends the feed: nothing after it runs
  };
  feed = std::make_unique<LineFeed>(
      io, LineFeedConfig{.path = file.string(), .retry_s = 0.01, .poll_s = 0.01}, events);
  // The file appears after the feed found nothing there, so it is read from its start.
  ASSERT_TRUE(run_until(io, [&] { return !feed->problem().empty(); }));
  write_file(file, "one\nboom\ntwo\nstop\nnever\n", false);
  ASSERT_TRUE(run_until(io, [&] { return feed == nullptr; }));
  io.run_for(std::chrono::milliseconds(50));  // any handler left must not touch the feed
  EXPECT_EQ(lines, (Lines{"one", "boom", "two", "stop"}));
}

}  // namespace
}  // namespace azt::linux_os
