// The console's Software page behind the API (docs/packaging.md): the version; an upload from a
// logged-in console checked as a Debian archive and left in the inbox, byte for byte, for the
// root update helper; the helper's report read back; anonymous, oversized, malformed and
// overlapping uploads refused with nothing written; a daemon without the package's unit offers
// no updates. Real files in a temporary folder; the work off the loop runs inline.
#include "console/software_updates.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include "console/web_api.hpp"

namespace azt::app {
namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

class NoModel final : public ConsoleModel {
 public:
  json state() override { return json::object(); }
  json config() override { return json::object(); }
  json targets() override { return json::object(); }
  json sky(double /*hours*/) override { return json::object(); }
  void act(const std::string& /*action*/, const json& /*body*/, const std::string& /*source*/,
           ActDone done) override {
    done(ActResult{});
  }
};

struct Rig {
  fs::path dir = fs::temp_directory_path() / ("azt-software-" + std::to_string(::getpid()));
  double unix_s = 1764241000.0;
  std::string token = "0123456789abcdef0123456789abcdef";
  NoModel model;
  WebAuth auth{WebAuth::Config{"", {{"script", sha256_hex(token), "", false}}}};
  SoftwareUpdates software{{"0.1.0", "amd64", (dir / "inbox").string(), (dir / "status").string()},
                           run_inline,
                           [this] { return unix_s; }};
  WebApi api{model, auth, WebApiConfig{}, [] { return 0.0; }};

  Rig() {
    fs::remove_all(dir);
    fs::create_directories(dir);
    api.serve_software(software);
  }
  ~Rig() { fs::remove_all(dir); }
  Rig(const Rig&) = delete;
  Rig& operator=(const Rig&) = delete;

  linux_os::HttpRequest request(const std::string& method, const std::string& path,
                                const std::string& body = "", bool logged_in = true) const {
    linux_os::HttpRequest r;
    r.method = method;
    r.path = path;
    r.body = body;
    r.host = "127.0.0.1:8080";
    r.client = "192.0.2.7";
    if (logged_in) r.authorization = "Bearer " + token;
    return r;
  }
  linux_os::HttpReply handle(const linux_os::HttpRequest& r) {
    linux_os::HttpReply reply;
    reply.status = 0;
    api.handle(r, [&reply](linux_os::HttpReply answer) { reply = std::move(answer); });
    return reply;
  }
  /// The upload as the transport makes it: the head decides, then the body goes to the route's
  /// sink in chunks, then the handler gets the request. A refusal from either comes back.
  linux_os::HttpReply upload(const std::string& body, bool logged_in = true) {
    linux_os::HttpRequest r = request("POST", "/api/software/update", "", logged_in);
    auto allowance = api.body_allowance(r);
    if (allowance.refusal) return *allowance.refusal;
    if (!allowance.sink) {
      r.body = body;
      return handle(r);
    }
    std::optional<linux_os::HttpReply> refused;
    for (std::size_t at = 0; at < body.size() && !refused; at += kChunkBytes) {
      allowance.sink->write(
          body.substr(at, kChunkBytes),
          [&refused](const std::optional<linux_os::HttpReply>& no) { refused = no; });
    }
    if (refused) return *refused;
    r.streamed_body = allowance.sink;
    return handle(r);
  }
  static constexpr std::size_t kChunkBytes = 300;
  json software_page() {
    return json::parse(handle(request("GET", "/api/software", "", false)).body);
  }
  fs::path request_deb() const { return dir / "inbox" / "request.deb"; }
};

std::string tiny_deb() {
  return read_bytes(fs::path(AZT_TEST_DATA_DIR) / "software" / "azeltrack-test_0.1_all.deb");
}

TEST(SoftwareUpdates, ThePageShowsTheVersionToEveryone) {
  Rig rig;
  const json page = rig.software_page();
  EXPECT_EQ(page["version"], "0.1.0");
  EXPECT_EQ(page["architecture"], "amd64");
  EXPECT_EQ(page["updates"], true);
  EXPECT_EQ(page["pending"], false);
  EXPECT_TRUE(page["helper"].is_null());
  EXPECT_TRUE(page["upload"].is_null());
}

TEST(SoftwareUpdates, AnUploadIsLeftForTheHelperByteForByte) {
  Rig rig;
  const std::string deb = tiny_deb();
  const auto reply = rig.upload(deb);
  ASSERT_EQ(reply.status, 200U) << reply.body;
  const json answer = json::parse(reply.body);
  EXPECT_EQ(answer["sha256"], sha256_hex(deb));
  EXPECT_EQ(answer["bytes"], deb.size());
  EXPECT_EQ(read_bytes(rig.request_deb()), deb);
  EXPECT_EQ(fs::status(rig.request_deb()).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write);
  const json page = rig.software_page();
  EXPECT_EQ(page["pending"], true);
  EXPECT_EQ(page["upload"]["sha256"], sha256_hex(deb));

  // While it waits for the helper, a second upload is refused and the first stays as it was.
  const auto again = rig.upload(deb + "");
  EXPECT_EQ(again.status, 409U) << again.body;
  EXPECT_NE(again.body.find("waiting for the update helper"), std::string::npos);
}

TEST(SoftwareUpdates, TheHelpersReportIsShownAndAWorkingHelperHoldsNewUploads) {
  Rig rig;
  const std::string sha(64, 'c');
  write_text(rig.dir / "status",
             "phase=installing\npercent=40\nmessage=Unpacking\nfrom=0.1.0\n"
             "to=0.1.1\nsha256=" +
                 sha + "\nat=1764240990\n");
  const json helper = rig.software_page()["helper"];
  EXPECT_EQ(helper["phase"], "installing");
  EXPECT_EQ(helper["percent"], 40);
  EXPECT_EQ(helper["to"], "0.1.1");
  EXPECT_EQ(helper["sha256"], sha);
  EXPECT_EQ(rig.upload(tiny_deb()).status, 409U);
  EXPECT_FALSE(fs::exists(rig.request_deb()));

  // The same report half an hour later is a helper that died (a power cut): uploads go again.
  rig.unix_s += SoftwareUpdates::kStaleWorkS + 11.0;
  EXPECT_EQ(rig.upload(tiny_deb()).status, 200U);

  write_text(rig.dir / "status", "phase=installed\nnot a line\n");
  const json broken = rig.software_page();
  EXPECT_TRUE(broken["helper"].is_null());
  EXPECT_NE(broken["helper_error"].get<std::string>().find("line 2"), std::string::npos);
}

TEST(SoftwareUpdates, RefusedUploadsWriteNothing) {
  Rig rig;
  const auto anonymous = rig.upload(tiny_deb(), false);
  EXPECT_EQ(anonymous.status, 401U);
  const auto garbage = rig.upload("MZ\x90 an exe");
  EXPECT_EQ(garbage.status, 400U);
  EXPECT_NE(garbage.body.find("not a Debian package"), std::string::npos) << garbage.body;
  const std::string cut = tiny_deb().substr(0, 500);
  EXPECT_EQ(rig.upload(cut).status, 400U);
  EXPECT_FALSE(fs::exists(rig.request_deb()));
  EXPECT_TRUE(rig.software_page()["upload"].is_null());
}

TEST(SoftwareUpdates, OnlyALoggedInUploadMayBeLarge) {
  Rig rig;
  const auto upload = rig.api.body_allowance(rig.request("POST", "/api/software/update"));
  EXPECT_EQ(upload.max_bytes, SoftwareUpdates::kMaxPackageBytes);
  EXPECT_FALSE(upload.refusal);
  // Without a login, the answer comes from the head: the body is never taken in.
  const auto anonymous =
      rig.api.body_allowance(rig.request("POST", "/api/software/update", "", false));
  ASSERT_TRUE(anonymous.refusal);
  EXPECT_EQ(anonymous.refusal->status, 401U);
  for (const auto& other :
       {rig.request("POST", "/api/target"), rig.request("GET", "/api/software/update"),
        rig.request("POST", "/api/target", "", false)}) {
    const auto a = rig.api.body_allowance(other);
    EXPECT_EQ(a.max_bytes, linux_os::HttpServer::kMaxBodyBytes) << other.method << other.path;
    EXPECT_FALSE(a.refusal);
  }
}

// docs/reliability.md "Hardening, round three" row 10: eight concurrent 60 MiB uploads were all
// read into memory (15 → 496 MiB RSS) before seven were refused. The second is refused from its
// head while the first holds the slot.
TEST(SoftwareUpdates, OneUploadAtATimeIsDecidedFromTheHead) {
  Rig rig;
  auto first = rig.api.body_allowance(rig.request("POST", "/api/software/update"));
  ASSERT_FALSE(first.refusal);
  ASSERT_TRUE(first.hold) << "the connection keeps the slot until it is answered";
  for (int i = 0; i < 7; ++i) {
    const auto next = rig.api.body_allowance(rig.request("POST", "/api/software/update"));
    ASSERT_TRUE(next.refusal) << i;
    EXPECT_EQ(next.refusal->status, 409U);
    EXPECT_EQ(next.max_bytes, linux_os::HttpServer::kMaxBodyBytes) << "no large body allowed";
  }
  // Small requests are never held up by an upload.
  EXPECT_FALSE(rig.api.body_allowance(rig.request("POST", "/api/target")).refusal);
  first.hold.reset();  // answered, or its connection closed
  const auto after = rig.api.body_allowance(rig.request("POST", "/api/software/update"));
  EXPECT_FALSE(after.refusal);
  EXPECT_EQ(after.max_bytes, SoftwareUpdates::kMaxPackageBytes);
}

TEST(SoftwareUpdates, WithoutThePackagesUnitThereAreNoUpdates) {
  NoModel model;
  WebAuth auth{WebAuth::Config{"", {{"script", sha256_hex("t"), "", false}}}};
  SoftwareUpdates software{{"0.1.0", "", "", ""}, run_inline, [] { return 0.0; }};
  WebApi api{model, auth, WebApiConfig{}, [] { return 0.0; }};
  api.serve_software(software);
  linux_os::HttpRequest r;
  r.method = "GET";
  r.path = "/api/software";
  r.host = "127.0.0.1";
  linux_os::HttpReply reply;
  api.handle(r, [&reply](linux_os::HttpReply a) { reply = std::move(a); });
  const json page = json::parse(reply.body);
  EXPECT_EQ(page["updates"], false);
  EXPECT_TRUE(page["architecture"].is_null());
  EXPECT_NE(page["updates_reason"].get<std::string>().find("source build"), std::string::npos);
  r.method = "POST";
  r.path = "/api/software/update";
  r.authorization = "Bearer t";
  api.handle(r, [&reply](linux_os::HttpReply a) { reply = std::move(a); });
  EXPECT_EQ(reply.status, 409U) << reply.body;
  EXPECT_EQ(api.body_allowance(r).max_bytes, linux_os::HttpServer::kMaxBodyBytes);
}

// docs/reliability.md "Hardening, round three" row 5: at a SIGTERM the daemon destroyed the console
// (and this object) while an upload's job still waited on the worker, whose work half then read the
// freed object (26 invalid reads under valgrind, and a folder with a garbage name created). The
// work halves hold what they need by value: here the object is destroyed and its memory overwritten
// before the queued jobs run, and the package still lands in the inbox. (The done halves, which run
// only on the loop, are dropped with it, as after the daemon's loop ends.)
TEST(SoftwareUpdates, QueuedWorkOutlivesTheObjectThatQueuedIt) {
  Rig rig;
  std::vector<std::function<void()>> queued;
  const Offload later = [&queued](const std::function<void()>& work,
                                  const std::function<void()>& /*done*/) {
    queued.push_back(work);
  };
  alignas(SoftwareUpdates) std::array<unsigned char, sizeof(SoftwareUpdates)> storage{};
  auto* updates = new (storage.data()) SoftwareUpdates(
      {"0.1.0", "amd64", (rig.dir / "inbox").string(), (rig.dir / "status").string()}, later,
      [] { return 1764241000.0; });
  const std::string deb = tiny_deb();
  const auto upload = updates->start_upload();
  upload->write(deb, [](const std::optional<linux_os::HttpReply>&) {});
  updates->status([](const ActResult&) {});
  updates->receive(*upload, [](const ActResult&) {});
  updates->~SoftwareUpdates();
  std::memset(storage.data(), 0xA5, storage.size());
  ASSERT_EQ(queued.size(), 3U);
  for (const auto& work : queued) work();
  EXPECT_EQ(read_bytes(rig.request_deb()), deb);
}

// docs/reliability.md "Hardening, round three" row 10: an accepted upload is not held whole (60 MiB
// each in RAM before): each chunk is written to an unnamed file in the inbox as it comes, so until
// the last one nothing in the inbox has a name for the helper to take, and an upload abandoned
// half-way leaves nothing there.
TEST(SoftwareUpdates, AnUploadGoesToTheInboxAsItArrivesAndHasNoNameUntilWhole) {
  Rig rig;
  const std::string deb = tiny_deb();
  auto allowance = rig.api.body_allowance(rig.request("POST", "/api/software/update"));
  ASSERT_TRUE(allowance.sink);
  const auto* upload = dynamic_cast<const PackageUpload*>(allowance.sink.get());
  ASSERT_NE(upload, nullptr);
  int taken = 0;
  for (std::size_t at = 0; at < deb.size(); at += Rig::kChunkBytes) {
    allowance.sink->write(deb.substr(at, Rig::kChunkBytes),
                          [&taken](const std::optional<linux_os::HttpReply>& refusal) {
                            EXPECT_FALSE(refusal);
                            ++taken;
                          });
    EXPECT_EQ(upload->received()->bytes(), std::min(deb.size(), at + Rig::kChunkBytes));
    EXPECT_TRUE(fs::is_empty(rig.dir / "inbox")) << "a part of a package has no name";
  }
  EXPECT_EQ(taken, static_cast<int>((deb.size() + Rig::kChunkBytes - 1) / Rig::kChunkBytes));
  allowance.sink.reset();  // the client went away: no request, nothing kept
  allowance.hold.reset();
  EXPECT_TRUE(fs::is_empty(rig.dir / "inbox"));
  EXPECT_EQ(rig.upload(deb).status, 200U);
  EXPECT_EQ(read_bytes(rig.request_deb()), deb);
}

TEST(SoftwareUpdates, AnInboxThatCannotTakeThePackageRefusesItsFirstChunk) {
  Rig rig;
  write_text(rig.dir / "inbox", "a file where the folder should be");
  const auto reply = rig.upload(tiny_deb());
  EXPECT_EQ(reply.status, 500U) << reply.body;
  EXPECT_NE(reply.body.find("cannot store the package"), std::string::npos) << reply.body;
  // The slot is free again once the refusal is answered: nothing stays held.
  EXPECT_FALSE(rig.api.body_allowance(rig.request("POST", "/api/software/update")).refusal);
}

}  // namespace
}  // namespace azt::app
