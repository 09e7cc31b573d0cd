#include "console/software_updates.hpp"

#include <filesystem>
#include <fstream>
#include <memory>
#include <string_view>

#include "azt/software/update_status.hpp"

namespace azt::app {
namespace {

using json = nlohmann::json;

constexpr std::string_view kNoUpdatesReason =
    "this azeltrack was not started by the Debian package's unit (no --update-inbox): a source "
    "build is updated with git pull and scripts/run";

/// The helper's report, read whole but never more than its parser takes (and one byte more, so
/// that an oversized file is an error, not a cut one).
std::optional<std::string> read_small_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::string text(std::size_t{16} * 1024 + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  return text;
}

json status_json(const software::UpdateStatus& s) {
  return {{"phase", std::string(software::to_string(s.phase))},
          {"percent", s.percent},
          {"message", s.message},
          {"from", s.from_version},
          {"to", s.to_version},
          {"sha256", s.sha256_hex},
          {"signer", s.signer},
          {"at_unix_s", s.at_unix_s}};
}

}  // namespace

std::string SoftwareUpdates::request_path(const Config& config) {
  return config.inbox_dir + "/request.deb";
}

SoftwareUpdates::Look SoftwareUpdates::look(const Config& config) {
  Look found;
  std::error_code ec;
  found.pending = enabled(config) && std::filesystem::exists(request_path(config), ec);
  if (config.status_file.empty()) return found;
  const auto text = read_small_file(config.status_file);
  if (!text) return found;  // the helper has not run yet
  const auto parsed = software::parse_update_status(*text);
  if (!parsed) {
    found.helper_error = parsed.error().message;
    return found;
  }
  found.helper = status_json(*parsed);
  return found;
}

std::optional<ApiError> SoftwareUpdates::busy(const Look& now, double now_unix_s) {
  if (now.pending) {
    return ApiError(409, "package",
                    "an uploaded package is still waiting for the update helper "
                    "(azeltrack-update.path); try again when it has been taken");
  }
  if (now.helper.is_null()) return std::nullopt;
  const auto phase = now.helper.value("phase", std::string());
  const bool working = phase == "checking" || phase == "installing";
  const double age_s = now_unix_s - now.helper.value("at_unix_s", 0.0);
  if (working && age_s < kStaleWorkS) {
    return ApiError(409, "package", "the update helper is " + phase + " a package now");
  }
  return std::nullopt;
}

json SoftwareUpdates::to_json(const Look& found) const {
  json out{
      {"version", config_.version},
      {"architecture", config_.architecture.empty() ? json(nullptr) : json(config_.architecture)},
      {"updates", enabled()},
      {"pending", found.pending},
      {"helper", found.helper}};
  if (!enabled()) {
    out["updates_reason"] = kNoUpdatesReason;
  }
  if (!found.helper_error.empty()) out["helper_error"] = found.helper_error;
  out["upload"] = last_upload_ ? json{{"sha256", last_upload_->sha256_hex},
                                      {"bytes", last_upload_->bytes},
                                      {"at_unix_s", last_upload_->at_unix_s}}
                               : json(nullptr);
  return out;
}

void SoftwareUpdates::status(ActDone done) {
  auto found = std::make_shared<Look>();
  offload_([found, config = config_] { *found = look(config); },
           [this, found, done = std::move(done)] {
             done(ActResult{to_json(*found), {}});
           });
}

std::shared_ptr<PackageUpload> SoftwareUpdates::start_upload() const {
  return std::make_shared<PackageUpload>(config_.inbox_dir, offload_);
}

void SoftwareUpdates::receive(const PackageUpload& upload, ActDone done) {
  if (!enabled()) {
    throw ApiError(409, "",
                   "software updates are not set up here: " + std::string(kNoUpdatesReason));
  }
  struct Outcome {
    std::optional<ApiError> error;
    std::string sha256_hex;
    std::uint64_t bytes = 0;
  };
  auto outcome = std::make_shared<Outcome>();
  // Reading back, hashing and storing megabytes, with an fsync, never on the loop.
  offload_(
      [outcome, package = upload.received(), config = config_, now_unix_s = unix_s_()] {
        outcome->error = store(*package, config, now_unix_s);
        outcome->sha256_hex = package->finish_sha256_hex();
        outcome->bytes = package->bytes();
      },
      [this, outcome, done = std::move(done)] {
        if (outcome->error) {
          done(ActResult{{}, outcome->error});
          return;
        }
        last_upload_ = Upload{outcome->sha256_hex, outcome->bytes, unix_s_()};
        done(ActResult{{{"sha256", outcome->sha256_hex}, {"bytes", outcome->bytes}}, {}});
      });
}

std::optional<ApiError> SoftwareUpdates::store(ReceivedPackage& package, const Config& config,
                                               double now_unix_s) {
  if (!package.error().empty()) {
    return ApiError(500, "package", "cannot store the package: " + package.error());
  }
  if (const auto archive = package.check_archive(); !archive) {
    return ApiError(400, "package", archive.error().message);
  }
  if (auto refusal = busy(look(config), now_unix_s)) return refusal;
  if (auto stored = package.publish(request_path(config)); !stored) {
    return ApiError(500, "package", "cannot store the package: " + stored.error().message);
  }
  return std::nullopt;
}

}  // namespace azt::app
