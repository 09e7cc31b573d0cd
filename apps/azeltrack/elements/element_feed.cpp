// The element feed's schedule, screening and publishing (element_feed.hpp).
#include "elements/element_feed.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <unordered_map>
#include <utility>

#include "azt/linux/atomic_file.hpp"
#include "elements/element_cache.hpp"

namespace azt::app {
namespace {

/// CelesTrak updates its GP data every 2 hours and answers a repeat within that time with 403
/// (round3 notes §4.1, https://celestrak.org/usage-policy.php): a restart does not fetch what the
/// cache holds from less than this ago.
constexpr double kMinRefetchS = 2.0 * 3600.0;
/// A source that did not answer at all (no network yet at boot, DNS) is asked again this soon;
/// one that answered with an error waits its full refresh, as CelesTrak's policy asks.
constexpr double kTransportRetryS = 1800.0;
constexpr double kFilePollS = 10.0;
constexpr std::size_t kLoggedErrors = 5;

std::optional<double> modification_time(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return std::nullopt;
  return static_cast<double>(st.st_mtim.tv_sec) + static_cast<double>(st.st_mtim.tv_nsec) * 1e-9;
}

/// What a download came to, on the download worker: fetched, read and screened.
orbit::ElementDownload fetch_and_read(const FetchElements& fetch, const std::string& url,
                                      std::string& error, bool& transport) {
  Result<std::string> body = fetch(url);
  if (!body) {
    error = body.error().message;
    transport = error.rfind("HTTP ", 0) != 0;
    return {};
  }
  return read_element_text(body.value(), url);
}

/// How an upload compares with the catalogue in use: how many sets are newer than the set in use
/// for their satellite (or new to it), and how many are not (they lose the merge).
nlohmann::json upload_summary(const std::vector<orbit::Elements>& sets,
                              const std::vector<ElementSets>& in_use) {
  std::vector<const std::vector<orbit::Elements>*> pointers;
  pointers.reserve(in_use.size());
  for (const ElementSets& s : in_use) pointers.push_back(s.get());
  std::unordered_map<std::string, double> newest;
  for (const orbit::Elements& e : orbit::merge_newest(pointers)) {
    newest[orbit::norad_key(e.catalog)] = orbit::epoch_jd(e);
  }
  std::size_t newer = 0;
  for (const orbit::Elements& e : sets) {
    const auto it = newest.find(orbit::norad_key(e.catalog));
    if (it == newest.end() || orbit::epoch_jd(e) > it->second) ++newer;
  }
  return {{"count", sets.size()}, {"newer", newer}, {"not_newer", sets.size() - newer}};
}

}  // namespace

ElementFeed::ElementFeed(ElementFeedParts parts) : p_(std::move(parts)) {
  const auto add = [this](SourceKind kind, const std::string& url) {
    ElementSource source;
    source.kind = kind;
    source.url = url;
    sources_.push_back(std::move(source));
  };
  for (const std::string& url : p_.settings.sources) add(SourceKind::Download, url);
  if (!p_.settings.file.empty()) add(SourceKind::File, p_.settings.file);
  add(SourceKind::Upload, "upload");
}

ElementSource* ElementFeed::file_source() {
  for (auto& s : sources_) {
    if (s.kind == SourceKind::File) return &s;
  }
  return nullptr;
}

ElementSource& ElementFeed::upload_source() { return sources_.back(); }

void ElementFeed::start(double unix_s) {
  load_cache();
  for (auto& s : sources_) {
    if (s.kind != SourceKind::Download) continue;
    s.due_unix_s = s.last_ok_unix_s
                       ? std::min(*s.last_ok_unix_s + kMinRefetchS, unix_s + p_.settings.refresh_s)
                       : unix_s;
  }
  read_file(true);
  publish(unix_s, true);
}

void ElementFeed::load_cache() {
  if (p_.settings.cache_path.empty()) return;
  auto text = read_text_file(p_.settings.cache_path, p_.settings.max_cache_bytes);
  if (!text) return;  // none yet: the first start, or no source ever succeeded
  auto cached = read_element_cache(text.value());
  if (!cached) {
    p_.log("satellites: " + p_.settings.cache_path + ": " + cached.error().message + "; ignored");
    return;
  }
  for (CachedSource& c : cached.value()) {
    for (auto& s : sources_) {
      if (s.kind == SourceKind::File || s.url != c.url) continue;
      s.sets = std::make_shared<const std::vector<orbit::Elements>>(std::move(c.sets));
      s.last_ok_unix_s = c.last_ok_unix_s;
      p_.log("satellites: " + std::to_string(s.sets->size()) + " element sets of " + s.url +
             " from the cache");
    }
  }
}

void ElementFeed::tick(double unix_s) {
  poll_file(unix_s);
  fetch_due(unix_s);
}

void ElementFeed::poll_file(double unix_s) {
  if (p_.settings.file.empty() || unix_s - last_poll_s_ < kFilePollS || reading_file_) return;
  last_poll_s_ = unix_s;
  const auto mtime = modification_time(p_.settings.file);
  if (mtime == file_mtime_) return;
  read_file(false);
}

void ElementFeed::read_file(bool at_once) {
  ElementSource* source = file_source();
  if (source == nullptr) return;
  file_mtime_ = modification_time(p_.settings.file);
  auto read = std::make_shared<orbit::ElementDownload>();
  auto error = std::make_shared<std::string>();
  auto work = [read, error, path = p_.settings.file, limit = p_.settings.max_cache_bytes] {
    auto text = read_text_file(path, limit);
    if (!text) {
      *error = text.error().message;
      return;
    }
    *read = read_element_text(text.value(), path);
  };
  auto done = [this, read, error, at_once] {
    reading_file_ = false;
    ElementSource& s = *file_source();
    const double now = p_.unix_now();
    // The operator's own file: a bad entry is named and skipped, the rest used (as before
    // downloads existed); a file that cannot be read keeps the previous sets.
    if (!error->empty() || read->sets.empty()) {
      s.failed(error->empty() ? read->errors.front() : *error, now);
      p_.log("satellites: " + s.last_error + "; keeping the previous element sets");
      return;
    }
    for (std::size_t i = 0; i < std::min(read->errors.size(), kLoggedErrors); ++i) {
      p_.log("satellites: " + read->errors[i]);
    }
    s.succeeded(std::make_shared<const std::vector<orbit::Elements>>(std::move(read->sets)), now);
    if (!read->errors.empty()) {
      s.last_error =
          std::to_string(read->errors.size()) + " entries skipped: " + read->errors.front();
    }
    if (!at_once) publish(now, false);
  };
  if (at_once || !p_.offload) {
    work();
    done();
    return;
  }
  reading_file_ = true;
  p_.offload(std::move(work), std::move(done));
}

void ElementFeed::fetch_due(double unix_s) {
  if (fetching_ || !p_.download_offload) return;
  struct Job {
    std::size_t index;
    std::string url;
    ElementSets previous;
  };
  auto jobs = std::make_shared<std::vector<Job>>();
  for (std::size_t i = 0; i < sources_.size(); ++i) {
    const ElementSource& s = sources_[i];
    if (s.kind == SourceKind::Download && s.due_unix_s <= unix_s)
      jobs->push_back({i, s.url, s.sets});
  }
  if (jobs->empty()) return;
  fetching_ = true;
  auto results = std::make_shared<std::vector<Fetched>>();
  auto work = [jobs, results, fetch = p_.fetch, limits = p_.settings.limits, unix_s] {
    for (const Job& job : *jobs) {
      Fetched f{job.index, nullptr, "", false};
      orbit::ElementDownload d = fetch_and_read(fetch, job.url, f.error, f.transport);
      if (f.error.empty())
        f.error = orbit::screen_download(d, *job.previous, unix_s, limits).refusal;
      if (f.error.empty())
        f.sets = std::make_shared<const std::vector<orbit::Elements>>(std::move(d.sets));
      results->push_back(std::move(f));
    }
  };
  p_.download_offload(std::move(work), [this, results] { take_fetched(*results, p_.unix_now()); });
}

double ElementFeed::retry_s(const Fetched& fetched) const {
  return fetched.transport ? std::min(kTransportRetryS, p_.settings.refresh_s)
                           : p_.settings.refresh_s;
}

void ElementFeed::take_fetched(const std::vector<Fetched>& results, double unix_s) {
  fetching_ = false;
  bool changed = false;
  for (const Fetched& f : results) {
    ElementSource& s = sources_[f.index];
    if (f.sets) {
      s.succeeded(f.sets, unix_s);
      s.due_unix_s = unix_s + p_.settings.refresh_s;
      p_.log("satellites: " + std::to_string(f.sets->size()) + " element sets from " + s.url);
      changed = true;
      continue;
    }
    s.failed(f.error.empty() ? "no answer" : f.error, unix_s);
    s.due_unix_s = unix_s + retry_s(f);
    p_.log("satellites: " + s.url + ": " + s.last_error + "; its previous " +
           std::to_string(s.sets->size()) + " element sets stay in use");
  }
  if (changed) publish(unix_s, false);
}

bool ElementFeed::refresh_now(double unix_s) {
  if (fetching_) return false;
  for (auto& s : sources_) {
    if (s.kind == SourceKind::Download) s.due_unix_s = unix_s;
  }
  fetch_due(unix_s);
  return true;
}

void ElementFeed::publish(double unix_s, bool at_once) {
  struct Input {
    ElementSets sets;
    std::string url;
    std::optional<double> last_ok_unix_s;
    bool cached;  ///< downloads and uploads; the file is on disk already
  };
  std::vector<Input> inputs;
  inputs.reserve(sources_.size());
  for (const ElementSource& s : sources_) {
    inputs.push_back({s.sets, s.url, s.last_ok_unix_s, s.kind != SourceKind::File});
  }
  const unsigned generation = ++publishes_;
  auto catalogue = std::make_shared<SatelliteCatalogue>();
  auto cache_error = std::make_shared<std::string>();
  const bool write_cache = !at_once && !p_.settings.cache_path.empty();
  auto work = [inputs, catalogue, cache_error, write_cache, path = p_.settings.cache_path] {
    std::vector<const std::vector<orbit::Elements>*> pointers;
    pointers.reserve(inputs.size());
    std::vector<CachedSource> cache;
    for (const Input& in : inputs) {
      pointers.push_back(in.sets.get());
      if (in.cached && in.last_ok_unix_s) cache.push_back({in.url, *in.last_ok_unix_s, *in.sets});
    }
    *catalogue = SatelliteCatalogue::from_sets(orbit::merge_newest(pointers), "satellites");
    if (!write_cache) return;
    // Atomic (a temp file renamed over it, fsynced): a reader or a power cut sees the old cache
    // or the new one, never a part.
    auto written = linux_os::write_file_atomically(path, element_cache_text(cache), 0644);
    if (!written) *cache_error = written.error().message;
  };
  auto done = [this, catalogue, cache_error, generation, unix_s] {
    if (!cache_error->empty()) p_.log("satellites: the element cache: " + *cache_error);
    if (generation != publishes_) return;  // a newer merge is on its way
    for (std::size_t i = 0; i < std::min(catalogue->errors().size(), kLoggedErrors); ++i) {
      p_.log("satellites: " + catalogue->errors()[i]);
    }
    // Said when it changes (a station without satellites says nothing: a refusal to start is
    // one line, docs/command-line.md).
    if (catalogue->satellites().size() != last_count_) {
      p_.log("satellites: " + std::to_string(catalogue->satellites().size()) +
             " satellites in the catalogue");
    }
    last_count_ = catalogue->satellites().size();
    p_.publish(std::move(*catalogue), unix_s);
  };
  if (at_once || !p_.offload) {
    work();
    done();
    return;
  }
  p_.offload(std::move(work), std::move(done));
}

void ElementFeed::upload(std::string text, double unix_s,
                         std::function<void(Result<nlohmann::json>)> done) {
  std::vector<ElementSets> in_use;
  in_use.reserve(sources_.size());
  for (const ElementSource& s : sources_) in_use.push_back(s.sets);
  auto body = std::make_shared<std::string>(std::move(text));
  auto merged = std::make_shared<ElementSets>();
  auto reply = std::make_shared<nlohmann::json>();
  auto refusal = std::make_shared<std::string>();
  auto work = [body, merged, reply, refusal, in_use, unix_s, limits = p_.settings.limits] {
    orbit::ElementDownload d = read_element_text(*body, "upload");
    // An upload is checked as a download is, less the count and history rules: it is a few
    // satellites on purpose, and an older set simply loses the merge.
    *refusal = orbit::screen_download(d, {}, unix_s, limits).refusal;
    if (!refusal->empty()) return;
    *reply = upload_summary(d.sets, in_use);
    std::vector<const std::vector<orbit::Elements>*> both{in_use.back().get(), &d.sets};
    *merged = std::make_shared<const std::vector<orbit::Elements>>(orbit::merge_newest(both));
  };
  auto finish = [this, merged, reply, refusal, done = std::move(done)] {
    const double now = p_.unix_now();
    ElementSource& s = upload_source();
    if (!refusal->empty()) {
      s.failed(*refusal, now);
      p_.log("satellites: an uploaded element file was refused: " + *refusal);
      done(fail(*refusal));
      return;
    }
    s.succeeded(*merged, now);
    p_.log("satellites: " + std::to_string((*reply)["count"].get<std::size_t>()) +
           " element sets uploaded");
    publish(now, false);
    done(*reply);
  };
  if (!p_.offload) {
    work();
    finish();
    return;
  }
  p_.offload(std::move(work), std::move(finish));
}

nlohmann::json ElementFeed::to_json() const {
  nlohmann::json out = nlohmann::json::array();
  for (const ElementSource& s : sources_) {
    const bool unused_upload =
        s.kind == SourceKind::Upload && s.sets->empty() && !s.last_error_unix_s;
    if (!unused_upload) out.push_back(s.to_json());
  }
  return out;
}

}  // namespace azt::app
