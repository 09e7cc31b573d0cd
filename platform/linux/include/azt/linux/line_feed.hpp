#pragma once
// Text lines from another program, on the daemon's Asio loop (docs/calibration.md: the receiver
// power for pointing scans, rtl_power's CSV or one dB value a line). The path names either
//   - a FIFO (mkfifo; `rtl_power ... > /run/azeltrack/power`): opened non-blocking and waited
//     on through a stream descriptor until a writer has written (Linux reports a FIFO readable
//     only once a writer came, so waiting for the first writer costs nothing). EOF means every
//     writer has closed it: the unfinished line is dropped and the FIFO is opened again at once
//     for the next writer, the new descriptor before the old is closed, so a writer never finds
//     the FIFO without a reader (which would lose its lines and kill it with SIGPIPE). A
//     writer's open blocks until a reader has the FIFO open, so one started first waits for the
//     daemon and loses nothing.
//   - a regular file another program appends to (`rtl_power ... > power.csv`): polled every
//     poll_s for growth, from its end as it was when the feed started (old lines are history,
//     not readings); a file that appears later, is truncated (its size falls below what was
//     read) or is replaced (another inode at the path) is read again from its start. A file
//     truncated and rewritten past the read position between two polls cannot be told from one
//     that grew: poll_s keeps that window short.
// Nothing blocks the loop: the FIFO is non-blocking, and a regular file's reads come from the
// page cache, at most kLineFeedReadBudgetBytes a turn (the rest on the next turn of the loop).
//
// Each complete line is handed to `line` without its "\n" and a trailing "\r". A line longer
// than max_line_bytes is dropped and counted, and everything up to the next newline with it, so
// a writer that never sends a newline cannot grow memory. Problems (the path is missing, not
// readable, neither a FIFO nor a regular file) are said once through `status` and kept in
// problem(), never thrown; the feed keeps trying every retry_s and says "" when it reads again.

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "azt/linux/asio.hpp"
#include "azt/linux/unique_fd.hpp"

namespace azt::linux_os {

/// The longest line delivered: an rtl_power line of 100000 bins is about 800 KB.
inline constexpr std::size_t kLineFeedMaxLineBytes = std::size_t{1} << 20;
/// The most of a regular file read in one turn of the loop.
inline constexpr std::size_t kLineFeedReadBudgetBytes = std::size_t{4} << 20;

struct LineFeedConfig {
  std::string path;
  double retry_s = 2.0;  ///< a missing or unreadable path is tried again this often
  double poll_s = 0.2;   ///< a regular file's growth is looked for this often
  std::size_t max_line_bytes = kLineFeedMaxLineBytes;
};

struct LineFeedEvents {
  /// Each complete line, on the loop. The view is valid only during the call. It may destroy
  /// the feed (nothing more is read then); an exception from it drops that line only.
  std::function<void(std::string_view line)> line;
  /// A problem when it starts or changes, "" when it clears; never repeated for each retry.
  /// It must not destroy the feed.
  std::function<void(const std::string& problem)> status;
};

class LineFeed {
 public:
  /// Starts at once; `events` are called on the loop, never from the constructor.
  LineFeed(boost::asio::io_context& io, LineFeedConfig config, LineFeedEvents events);
  ~LineFeed();
  LineFeed(const LineFeed&) = delete;
  LineFeed& operator=(const LineFeed&) = delete;
  LineFeed(LineFeed&&) = delete;
  LineFeed& operator=(LineFeed&&) = delete;

  /// The current problem, empty while the feed can read (or waits for a FIFO's writer).
  [[nodiscard]] const std::string& problem() const { return problem_; }
  /// A FIFO or file is open now (a FIFO also while it waits for a writer).
  [[nodiscard]] bool is_open() const { return file_.valid() || fifo_.is_open(); }
  /// Lines delivered.
  [[nodiscard]] std::uint64_t lines() const { return lines_; }
  /// Lines dropped for being longer than max_line_bytes.
  [[nodiscard]] std::uint64_t overlong_lines() const { return overlong_; }
  /// Times a regular file was read again from its start (truncated, replaced, reappeared).
  [[nodiscard]] std::uint64_t restarts() const { return restarts_; }
  /// Times a FIFO's writers all went away after sending something.
  [[nodiscard]] std::uint64_t writer_hangups() const { return hangups_; }
  [[nodiscard]] std::string describe() const { return "line feed " + config_.path; }

 private:
  void open_source();
  void open_fifo();
  void open_file(bool from_start);
  void wait_fifo();
  void read_fifo();
  void poll_file();
  bool read_file_growth();
  void close_source();
  void fail_and_retry(std::string problem);
  void retry_later();
  void poll_later(double delay_s);
  void feed(std::string_view bytes);
  void deliver();
  void report(std::string problem);

  boost::asio::posix::stream_descriptor fifo_;
  boost::asio::steady_timer timer_;
  LineFeedConfig config_;
  LineFeedEvents events_;
  UniqueFd file_;  ///< the regular file, while one is open
  std::uint64_t file_dev_ = 0;
  std::uint64_t file_ino_ = 0;
  std::uint64_t offset_ = 0;  ///< bytes of the regular file read so far
  bool started_ = false;      ///< the first open has been tried (later files are read whole)
  bool fifo_data_ = false;    ///< the FIFO has sent something since it was opened
  std::string pending_;       ///< the unfinished line, at most max_line_bytes
  bool discarding_ = false;   ///< inside an overlong line: dropping up to the next newline
  std::array<char, 64 * 1024> chunk_{};
  std::string problem_;
  std::uint64_t lines_ = 0;
  std::uint64_t overlong_ = 0;
  std::uint64_t restarts_ = 0;
  std::uint64_t hangups_ = 0;
  std::shared_ptr<bool> alive_ = std::make_shared<bool>(true);
};

}  // namespace azt::linux_os
