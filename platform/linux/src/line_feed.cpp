#include "azt/linux/line_feed.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <exception>
#include <string>
#include <utility>

namespace azt::linux_os {
namespace {

namespace asio = boost::asio;

asio::steady_timer::duration seconds(double s) {
  return std::chrono::duration_cast<asio::steady_timer::duration>(
      std::chrono::duration<double>(std::max(s, 0.0)));
}

/// "path: reason" for a failed system call; `err` is errno, read before anything can change it.
std::string failed(const std::string& path, int err) { return path + ": " + std::strerror(err); }

}  // namespace

LineFeed::LineFeed(asio::io_context& io, LineFeedConfig config, LineFeedEvents events)
    : fifo_(io), timer_(io), config_(std::move(config)), events_(std::move(events)) {
  // Posted, so the status callback never runs inside the constructor.
  asio::post(io, [this, alive = alive_] {
    if (*alive) open_source();
  });
}

LineFeed::~LineFeed() {
  *alive_ = false;  // the timer's and the FIFO's handlers still queued see this and return
  boost::system::error_code ignored;
  fifo_.close(ignored);
}

void LineFeed::open_source() {
  const bool from_start = std::exchange(started_, true);
  struct stat st {};
  if (::stat(config_.path.c_str(), &st) != 0) {
    return fail_and_retry(failed(config_.path, errno));
  }
  if (S_ISFIFO(st.st_mode)) return open_fifo();
  if (S_ISREG(st.st_mode)) return open_file(from_start);
  fail_and_retry(config_.path + ": neither a FIFO nor a regular file");
}

void LineFeed::open_fifo() {
  // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer, blocking the loop.
  // Opened before the old descriptor (after a writer left) is closed, so the FIFO always has a
  // reader: a writer arriving in between neither loses what it wrote nor dies of SIGPIPE.
  const int fd = ::open(config_.path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return fail_and_retry(failed(config_.path, errno));
  close_source();
  boost::system::error_code ec;
  fifo_.assign(fd, ec);
  if (ec) {
    ::close(fd);
    return fail_and_retry(config_.path + ": " + ec.message());
  }
  report({});
  fifo_data_ = false;
  wait_fifo();
}

void LineFeed::wait_fifo() {
  // Waited for, not read: a FIFO opened before any writer reads as EOF at once, but the kernel
  // reports it readable only when a writer has written or come and gone (Linux fs/pipe.c keeps
  // POLLHUP back until a reader has seen a writer), so no writer yet costs nothing.
  fifo_.async_wait(asio::posix::stream_descriptor::wait_read,
                   [this, alive = alive_](const boost::system::error_code& ec) {
                     if (!*alive || ec == asio::error::operation_aborted) return;
                     if (ec) return fail_and_retry(config_.path + ": " + ec.message());
                     read_fifo();
                   });
}

void LineFeed::read_fifo() {
  fifo_.async_read_some(asio::buffer(chunk_),
                        [this, alive = alive_](const boost::system::error_code& ec, std::size_t n) {
                          if (!*alive || ec == asio::error::operation_aborted) return;
                          if (n > 0) {
                            fifo_data_ = true;
                            feed(std::string_view(chunk_.data(), n));
                            if (!*alive) return;  // the line callback destroyed the feed
                          }
                          if (ec == asio::error::eof) {
                            // Every writer closed it: its last line, if unfinished, is a writer
                            // killed mid-line and is dropped (open_fifo clears it). A FIFO that has
                            // had a writer reads as EOF for good, so it is opened again, at once,
                            // to wait for the next one.
                            if (fifo_data_) ++hangups_;
                            return open_source();
                          }
                          if (ec) return fail_and_retry(config_.path + ": " + ec.message());
                          read_fifo();
                        });
}

void LineFeed::open_file(bool from_start) {
  close_source();
  UniqueFd fd(::open(config_.path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC));
  struct stat st {};
  if (!fd.valid() || ::fstat(fd.get(), &st) != 0) {
    return fail_and_retry(failed(config_.path, errno));
  }
  file_ = std::move(fd);
  file_dev_ = static_cast<std::uint64_t>(st.st_dev);
  file_ino_ = static_cast<std::uint64_t>(st.st_ino);
  // The first file's old lines were written before the feed started: not readings.
  offset_ = from_start ? 0 : static_cast<std::uint64_t>(st.st_size);
  if (from_start) ++restarts_;
  report({});
  poll_later(from_start ? 0.0 : config_.poll_s);
}

void LineFeed::poll_file() {
  const auto alive = alive_;  // the line handler may end the feed while its lines are read
  struct stat at_path {};
  if (::stat(config_.path.c_str(), &at_path) != 0) {
    // Deleted or renamed away: what the old inode still receives is not at the path any more.
    return fail_and_retry(failed(config_.path, errno));
  }
  if (static_cast<std::uint64_t>(at_path.st_dev) != file_dev_ ||
      static_cast<std::uint64_t>(at_path.st_ino) != file_ino_) {
    return open_source();  // replaced: read the new file from its start
  }
  const bool more = read_file_growth();
  if (!*alive || !file_.valid()) return;
  poll_later(more ? 0.0 : config_.poll_s);
}

bool LineFeed::read_file_growth() {
  struct stat st {};
  if (::fstat(file_.get(), &st) != 0) {
    fail_and_retry(failed(config_.path, errno));
    return false;
  }
  const auto size = static_cast<std::uint64_t>(st.st_size);
  if (size < offset_) {  // truncated (`>` again): the unfinished line went with it
    ++restarts_;
    offset_ = 0;
    pending_.clear();
    discarding_ = false;
  }
  const auto alive = alive_;
  std::size_t budget = kLineFeedReadBudgetBytes;
  while (offset_ < size && budget > 0) {
    const std::size_t want =
        std::min({chunk_.size(), budget, static_cast<std::size_t>(size - offset_)});
    const ssize_t n = ::pread(file_.get(), chunk_.data(), want, static_cast<off_t>(offset_));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // an error or a file cut since fstat: the next poll sees which
    offset_ += static_cast<std::uint64_t>(n);
    budget -= static_cast<std::size_t>(n);
    feed(std::string_view(chunk_.data(), static_cast<std::size_t>(n)));
    if (!*alive || !file_.valid()) return false;
  }
  return offset_ < size && budget == 0;
}

void LineFeed::close_source() {
  boost::system::error_code ignored;
  fifo_.close(ignored);
  file_.reset();
  pending_.clear();
  discarding_ = false;
}

void LineFeed::fail_and_retry(std::string problem) {
  report(std::move(problem));
  close_source();
  retry_later();
}

void LineFeed::retry_later() {
  timer_.expires_after(seconds(config_.retry_s));
  timer_.async_wait([this, alive = alive_](const boost::system::error_code& ec) {
    if (!ec && *alive) open_source();
  });
}

void LineFeed::poll_later(double delay_s) {
  timer_.expires_after(seconds(delay_s));
  timer_.async_wait([this, alive = alive_](const boost::system::error_code& ec) {
    if (!ec && *alive && file_.valid()) poll_file();
  });
}

void LineFeed::feed(std::string_view bytes) {
  const auto alive = alive_;
  while (!bytes.empty()) {
    const std::size_t newline = bytes.find('\n');
    const std::string_view piece = bytes.substr(0, newline);
    if (!discarding_ && pending_.size() + piece.size() > config_.max_line_bytes) {
      ++overlong_;
      discarding_ = true;
      pending_.clear();
    }
    if (!discarding_) pending_.append(piece);
    if (newline == std::string_view::npos) return;
    bytes.remove_prefix(newline + 1);
    if (std::exchange(discarding_, false)) continue;
    deliver();
    if (!*alive) return;
  }
}

void LineFeed::deliver() {
  std::string line = std::move(pending_);
  pending_.clear();
  if (!line.empty() && line.back() == '\r') line.pop_back();
  ++lines_;
  if (!events_.line) return;
  try {
    events_.line(line);
  } catch (const std::exception&) {
    // A fault handling one line drops that line, never the daemon.
  }
}

void LineFeed::report(std::string problem) {
  if (problem == problem_) return;
  problem_ = std::move(problem);
  if (!events_.status) return;
  try {
    events_.status(problem_);
  } catch (const std::exception&) {
    // The status is kept in problem(); a failing observer changes nothing here.
  }
}

}  // namespace azt::linux_os
