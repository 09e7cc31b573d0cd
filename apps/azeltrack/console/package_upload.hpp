#pragma once
// A package upload as it arrives: the transport hands each chunk of the body to
// this sink on the loop; the worker appends it to an unnamed file in the update inbox and adds it
// to the SHA-256, and only then is the next chunk read. So one chunk at a time is in memory, not
// the package, and nothing on the loop touches the disk or hashes. An upload cut short or
// refused leaves nothing in the inbox (the file has no name until it is stored).
// SoftwareUpdates::receive checks and stores the package once the body is whole.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "azt/linux/http_server.hpp"
#include "azt/linux/staged_file.hpp"
#include "azt/software/deb_archive.hpp"
#include "common/off_loop.hpp"

struct crypto_hash_sha256_state;  // libsodium's; only package_upload.cpp needs its layout

namespace azt::app {

/// The package received so far. Worker thread only.
class ReceivedPackage {
 public:
  explicit ReceivedPackage(std::string inbox_dir);
  ~ReceivedPackage();
  ReceivedPackage(const ReceivedPackage&) = delete;
  ReceivedPackage& operator=(const ReceivedPackage&) = delete;

  /// Adds `chunk` (the first one creates the file); after a failure it records why and
  /// takes nothing more.
  void append(std::string_view chunk);
  /// Why the package could not be kept ("" while it could).
  [[nodiscard]] const std::string& error() const { return error_; }
  [[nodiscard]] std::uint64_t bytes() const { return file_ ? file_->size() : 0; }
  /// The SHA-256 of every byte appended, as 64 hex digits; call once, at the end.
  [[nodiscard]] std::string finish_sha256_hex();
  /// Its ar members as deb(5) requires them, read back from the file.
  [[nodiscard]] Result<software::DebArchive> check_archive() const;
  /// Makes it durable at `path`, replacing what is there.
  Result<bool> publish(const std::string& path);

 private:
  std::string inbox_dir_;
  std::optional<linux_os::StagedFile> file_;
  std::unique_ptr<crypto_hash_sha256_state> hash_;
  std::string error_;
};

class PackageUpload final : public linux_os::HttpBodySink {
 public:
  PackageUpload(std::string inbox_dir, Offload offload)
      : received_(std::make_shared<ReceivedPackage>(std::move(inbox_dir))),
        offload_(std::move(offload)) {}

  void write(std::string chunk, Next next) override;
  /// What arrived, for SoftwareUpdates::receive's work on the worker once the body is whole.
  [[nodiscard]] std::shared_ptr<ReceivedPackage> received() const { return received_; }

 private:
  std::shared_ptr<ReceivedPackage> received_;
  Offload offload_;
};

}  // namespace azt::app
