#include "console/package_upload.hpp"

#include <sodium.h>

#include <array>
#include <filesystem>
#include <utility>

#include "console/api_reply.hpp"
#include "console/web_auth.hpp"

namespace azt::app {

ReceivedPackage::ReceivedPackage(std::string inbox_dir)
    : inbox_dir_(std::move(inbox_dir)), hash_(std::make_unique<crypto_hash_sha256_state>()) {
  crypto_hash_sha256_init(hash_.get());
}

ReceivedPackage::~ReceivedPackage() = default;

void ReceivedPackage::append(std::string_view chunk) {
  if (!error_.empty()) return;
  if (!file_) {
    std::error_code ec;
    std::filesystem::create_directories(inbox_dir_, ec);
    auto created = linux_os::StagedFile::create(inbox_dir_, 0600);
    if (!created) {
      error_ = created.error().message;
      return;
    }
    file_.emplace(std::move(created).value());
  }
  if (auto written = file_->append(chunk); !written) {
    error_ = written.error().message;
    return;
  }
  crypto_hash_sha256_update(hash_.get(), reinterpret_cast<const unsigned char*>(chunk.data()),
                            chunk.size());
}

std::string ReceivedPackage::finish_sha256_hex() {
  std::array<unsigned char, crypto_hash_sha256_BYTES> digest{};
  crypto_hash_sha256_final(hash_.get(), digest.data());
  return to_hex(digest.data(), digest.size());
}

Result<software::DebArchive> ReceivedPackage::check_archive() const {
  if (!file_) return software::check_deb_archive(std::string_view());
  return software::check_deb_archive(file_->size(), [this](std::uint64_t offset, std::size_t n) {
    return file_->read_at(offset, n);
  });
}

Result<bool> ReceivedPackage::publish(const std::string& path) {
  if (!error_.empty()) return fail(error_);
  if (!file_) return fail("no package was received");  // check_archive refuses this first
  return file_->publish(path);
}

void PackageUpload::write(std::string chunk, Next next) {
  auto bytes = std::make_shared<const std::string>(std::move(chunk));
  // Disk and hash on the worker; the next chunk is read when this one is taken (flow control).
  offload_([received = received_, bytes] { received->append(*bytes); },
           [received = received_, next = std::move(next)] {
             if (received->error().empty()) {
               next(std::nullopt);
             } else {
               next(error_reply(500, "cannot store the package: " + received->error(), "package"));
             }
           });
}

}  // namespace azt::app
