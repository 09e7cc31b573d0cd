#pragma once
// One file fetched by URL with libcurl (https://curl.se/libcurl/c/easy_setopt_options.html):
// HTTPS verified against the system's CAs (or a given CA file), HTTP, and file://. Blocking: for
// the daemon's worker thread, never the event loop. Hostile answers are ordinary failures: a
// non-200 status, a body over the size cap, a stall past the timeouts, a redirect loop, a body
// cut short (its Content-Length not reached) each come back as an error naming what happened,
// never as a partial body.

#include <atomic>
#include <cstddef>
#include <string>

#include "azt/util/result.hpp"

namespace azt::linux_os {

struct DownloadOptions {
  std::string ca_file;  ///< PEM bundle to verify servers with; empty: the system's CAs
  /// "http://host:port" or "socks5h://…"; empty: libcurl's default (the http_proxy and
  /// https_proxy variables of the environment, if set).
  std::string proxy;
  long max_redirects = 5;
  double connect_timeout_s = 20.0;
  double total_timeout_s = 120.0;  ///< the whole transfer, redirects included
  std::size_t max_bytes = std::size_t{32} * 1024 * 1024;
  std::string user_agent = "azeltrack";
  /// Set from another thread to abandon the transfer at once (the daemon stopping).
  const std::atomic<bool>* cancel = nullptr;
};

/// The body of `url` when it came whole with status 200 (file:// has no status); else an error
/// such as "HTTP 404 (Not found)", "timed out after 2000 ms", "more than 10 redirects",
/// "over the 1048576-byte limit", "transfer closed with 100 bytes remaining to read".
Result<std::string> download(const std::string& url, const DownloadOptions& options);

}  // namespace azt::linux_os
