// Downloads with libcurl's easy interface (azt/linux/http_download.hpp).
#include "azt/linux/http_download.hpp"

#include <curl/curl.h>

#include <algorithm>
#include <cctype>
#include <memory>
#include <mutex>
#include <string>

namespace azt::linux_os {
namespace {

struct Transfer {
  std::string body;
  std::size_t max_bytes = 0;
  bool oversized = false;
  const std::atomic<bool>* cancel = nullptr;
};

std::size_t on_data(char* data, std::size_t size, std::size_t count, void* user) {
  auto* t = static_cast<Transfer*>(user);
  const std::size_t bytes = size * count;
  if (t->body.size() + bytes > t->max_bytes) {
    t->oversized = true;
    return 0;  // libcurl ends the transfer with CURLE_WRITE_ERROR
  }
  t->body.append(data, bytes);
  return bytes;
}

int on_progress(void* user, curl_off_t /*dltotal*/, curl_off_t /*dlnow*/, curl_off_t /*ultotal*/,
                curl_off_t /*ulnow*/) {
  const auto* t = static_cast<const Transfer*>(user);
  return t->cancel != nullptr && t->cancel->load() ? 1 : 0;  // non-zero aborts
}

/// curl_global_init is not thread-safe; once, from whichever thread downloads first.
void init_once() {
  static std::once_flag once;
  std::call_once(once, [] { curl_global_init(CURL_GLOBAL_DEFAULT); });
}

long milliseconds(double seconds) { return std::max(1L, static_cast<long>(seconds * 1000.0)); }

/// A server's error page may say why (CelesTrak's 403 does: "GP data has not updated since your
/// last successful download"): its first line, printable, at most 120 characters.
std::string first_line(const std::string& body) {
  std::string line = body.substr(0, std::min(body.find('\n'), std::size_t{120}));
  std::replace_if(
      line.begin(), line.end(), [](unsigned char c) { return c < 0x20 || c >= 0x7F; }, ' ');
  return line;
}

void set_options(CURL* curl, const std::string& url, const DownloadOptions& o, Transfer& t,
                 char* error_text) {
  curl_easy_setopt(curl, CURLOPT_URL, url.c_str());
  // http and https, and file:// for a local mirror; redirects only to http(s): a server must
  // not send us to file:// or another scheme.
  curl_easy_setopt(curl, CURLOPT_PROTOCOLS_STR, "http,https,file");
  curl_easy_setopt(curl, CURLOPT_REDIR_PROTOCOLS_STR, "http,https");
  curl_easy_setopt(curl, CURLOPT_FOLLOWLOCATION, 1L);
  curl_easy_setopt(curl, CURLOPT_MAXREDIRS, o.max_redirects);
  curl_easy_setopt(curl, CURLOPT_CONNECTTIMEOUT_MS, milliseconds(o.connect_timeout_s));
  curl_easy_setopt(curl, CURLOPT_TIMEOUT_MS, milliseconds(o.total_timeout_s));
  curl_easy_setopt(curl, CURLOPT_MAXFILESIZE_LARGE, static_cast<curl_off_t>(o.max_bytes));
  curl_easy_setopt(curl, CURLOPT_NOSIGNAL, 1L);  // threads: no SIGALRM for DNS timeouts
  curl_easy_setopt(curl, CURLOPT_USERAGENT, o.user_agent.c_str());
  curl_easy_setopt(curl, CURLOPT_ACCEPT_ENCODING, "");  // whatever libcurl can decode
  curl_easy_setopt(curl, CURLOPT_ERRORBUFFER, error_text);
  curl_easy_setopt(curl, CURLOPT_WRITEFUNCTION, on_data);
  curl_easy_setopt(curl, CURLOPT_WRITEDATA, &t);
  curl_easy_setopt(curl, CURLOPT_XFERINFOFUNCTION, on_progress);
  curl_easy_setopt(curl, CURLOPT_XFERINFODATA, &t);
  curl_easy_setopt(curl, CURLOPT_NOPROGRESS, 0L);
  if (!o.ca_file.empty()) curl_easy_setopt(curl, CURLOPT_CAINFO, o.ca_file.c_str());
  if (!o.proxy.empty()) curl_easy_setopt(curl, CURLOPT_PROXY, o.proxy.c_str());
}

std::string failure(CURLcode code, const Transfer& t, const DownloadOptions& o,
                    const char* error_text) {
  if (t.oversized || code == CURLE_FILESIZE_EXCEEDED) {
    return "over the " + std::to_string(o.max_bytes) + "-byte limit";
  }
  if (code == CURLE_ABORTED_BY_CALLBACK) return "abandoned: the daemon is stopping";
  if (code == CURLE_TOO_MANY_REDIRECTS) {
    return "more than " + std::to_string(o.max_redirects) + " redirects (a redirect loop?)";
  }
  return error_text[0] != '\0' ? std::string(error_text) : std::string(curl_easy_strerror(code));
}

}  // namespace

Result<std::string> download(const std::string& url, const DownloadOptions& options) {
  init_once();
  const std::unique_ptr<CURL, decltype(&curl_easy_cleanup)> curl(curl_easy_init(),
                                                                 curl_easy_cleanup);
  if (!curl) return fail("libcurl: cannot start a transfer");
  Transfer t;
  t.max_bytes = options.max_bytes;
  t.cancel = options.cancel;
  char error_text[CURL_ERROR_SIZE] = {};
  set_options(curl.get(), url, options, t, error_text);
  const CURLcode code = curl_easy_perform(curl.get());
  if (code != CURLE_OK) return fail(failure(code, t, options, error_text));
  long status = 0;
  curl_easy_getinfo(curl.get(), CURLINFO_RESPONSE_CODE, &status);
  // file:// reports 0. Anything but 200 is a failure to tell a human, not data (CelesTrak's
  // usage policy asks exactly this of automatic clients: https://celestrak.org/usage-policy.php).
  if (status != 0 && status != 200) {
    const std::string why = first_line(t.body);
    return fail("HTTP " + std::to_string(status) + (why.empty() ? "" : " (" + why + ")"));
  }
  return std::move(t.body);
}

}  // namespace azt::linux_os
