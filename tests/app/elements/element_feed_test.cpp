// The element feed (elements/element_feed.hpp) over a fake network: what each source serves is
// set by the test, the clock is the test's, and every offload runs inline. A refused or failed
// download leaves the catalogue as it was and says why; the cache brings a restart's catalogue
// and history back without the network.
#include "elements/element_feed.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <string>

#include "azt/orbit/tle.hpp"

namespace azt::app {
namespace {

constexpr double kNowUnixS = 1709296200.0;  // 2024-03-01 12:30 UTC

std::string with_checksum(std::string line) {
  line.resize(68);
  line += static_cast<char>('0' + orbit::tle_checksum(line));
  return line;
}

/// A three-line set of the ISS's orbit under another number and name, at `day` of 2024.
std::string tle(int norad, double day, const std::string& name) {
  std::string l1 = "1 25544U 98067A   24061.52083333  .00016717  00000-0  30119-3 0  999";
  std::string l2 = "2 25544  51.6416 247.4627 0006703 130.5360 325.0288 15.4981548844111";
  char number[8];
  std::snprintf(number, sizeof number, "%05d", norad);
  l1.replace(2, 5, number);
  l2.replace(2, 5, number);
  char epoch[16];
  std::snprintf(epoch, sizeof epoch, "24%012.8f", day);
  l1.replace(18, 14, epoch);
  return name + "\n" + with_checksum(l1) + "\n" + with_checksum(l2) + "\n";
}

std::string catalogue_of(int first, int count, double day) {
  std::string text;
  for (int i = 0; i < count; ++i) text += tle(first + i, day, "SAT " + std::to_string(first + i));
  return text;
}

struct Rig {
  std::map<std::string, Result<std::string>> served;
  void serve(const std::string& url, Result<std::string> what) {
    served.insert_or_assign(url, std::move(what));
  }
  int fetches = 0;
  double now = kNowUnixS;
  std::optional<SatelliteCatalogue> published;
  int publishes = 0;
  std::vector<std::string> lines;
  std::filesystem::path dir;

  Rig() {
    dir = std::filesystem::temp_directory_path() /
          ("azt_feed_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
           ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
  }
  ~Rig() { std::filesystem::remove_all(dir); }

  std::unique_ptr<ElementFeed> feed(std::vector<std::string> urls, std::string file = "") {
    ElementFeedSettings s;
    s.sources = std::move(urls);
    s.file = std::move(file);
    s.cache_path = (dir / "elements-cache.json").string();
    return std::make_unique<ElementFeed>(ElementFeedParts{
        s,
        [this](const std::string& url) -> Result<std::string> {
          ++fetches;
          const auto it = served.find(url);
          return it == served.end() ? Result<std::string>(fail("HTTP 404 (Not found)"))
                                    : it->second;
        },
        run_inline, run_inline, [this] { return now; },
        [this](SatelliteCatalogue c, double) {
          published = std::move(c);
          ++publishes;
        },
        [this](const std::string& line) { lines.push_back(line); }});
  }
  [[nodiscard]] std::size_t count() const { return published ? published->satellites().size() : 0; }
};

nlohmann::json source(const ElementFeed& feed, std::size_t i) { return feed.to_json().at(i); }

TEST(ElementFeed, AGoodDownloadIsPublishedAndReported) {
  Rig rig;
  rig.serve("https://a/amateur", catalogue_of(40000, 20, 60.5));
  auto feed = rig.feed({"https://a/amateur"});
  feed->start(rig.now);
  EXPECT_EQ(rig.count(), 0U);  // no cache, no file: nothing until the first tick
  feed->tick(rig.now);
  EXPECT_EQ(rig.count(), 20U);
  const auto s = source(*feed, 0);
  EXPECT_EQ(s["url"], "https://a/amateur");
  EXPECT_EQ(s["count"], 20);
  EXPECT_EQ(s["last_ok"], "2024-03-01T12:30:00.000Z");
  EXPECT_TRUE(s["last_error"].is_null());
  // Not again until refresh_h has passed.
  feed->tick(rig.now + 3600.0);
  EXPECT_EQ(rig.fetches, 1);
  feed->tick(rig.now + 12 * 3600.0);
  EXPECT_EQ(rig.fetches, 2);
}

/// The source first serves 20 good sets, then `bad`: the catalogue keeps the 20 and the source
/// says why.
void expect_refused(const Result<std::string>& bad, const std::string& reason) {
  Rig rig;
  rig.serve("https://a/x", catalogue_of(40000, 20, 60.5));
  auto feed = rig.feed({"https://a/x"});
  feed->start(rig.now);
  feed->tick(rig.now);
  ASSERT_EQ(rig.count(), 20U);
  const int publishes = rig.publishes;
  rig.serve("https://a/x", bad);
  rig.now += 3600.0;
  ASSERT_TRUE(feed->refresh_now(rig.now));
  EXPECT_EQ(rig.publishes, publishes) << "nothing new is published";
  EXPECT_EQ(rig.count(), 20U);
  const auto s = source(*feed, 0);
  EXPECT_EQ(s["count"], 20);
  EXPECT_EQ(s["last_ok"], "2024-03-01T12:30:00.000Z");
  ASSERT_TRUE(s["last_error"].is_string());
  EXPECT_NE(s["last_error"].get<std::string>().find(reason), std::string::npos) << s["last_error"];
  EXPECT_EQ(s["last_error_at"], "2024-03-01T13:30:00.000Z");
}

TEST(ElementFeed, AFailedDownloadKeepsTheOldSets) {
  expect_refused(fail("HTTP 404 (Not found)"), "HTTP 404");
  expect_refused(fail("timed out after 2000 ms"), "timed out");
}

TEST(ElementFeed, GarbageATruncatedFileOlderEpochsAndATenthAreRefused) {
  expect_refused(std::string("<html><body>Service unavailable</body></html>"), "does not parse");
  std::string cut = catalogue_of(40000, 20, 61.0);
  cut.resize(cut.size() - 30);
  expect_refused(cut, "does not parse");
  expect_refused(catalogue_of(40000, 20, 59.0), "went back in time: SAT 40000");
  expect_refused(catalogue_of(40000, 1, 61.0), "suspicious: 1 element sets");
  expect_refused(std::string(""), "does not parse");
}

TEST(ElementFeed, SourcesAndTheFileAreMergedNewestFirst) {
  Rig rig;
  const std::string file = (rig.dir / "mine.tle").string();
  {
    std::FILE* f = std::fopen(file.c_str(), "w");
    const std::string text = tle(40000, 61.4, "MINE NEWER") + tle(50000, 60.0, "ONLY MINE");
    std::fputs(text.c_str(), f);
    std::fclose(f);
  }
  rig.serve("https://a/x", catalogue_of(40000, 3, 61.0));
  auto feed = rig.feed({"https://a/x"}, file);
  feed->start(rig.now);
  EXPECT_EQ(rig.count(), 2U);  // the file at once
  feed->tick(rig.now);
  ASSERT_EQ(rig.count(), 4U);
  EXPECT_EQ(rig.published->find("40000").elements.name, "MINE NEWER");
  EXPECT_EQ(rig.published->find("40001").elements.name, "SAT 40001");
  EXPECT_EQ(source(*feed, 1)["kind"], "file");
  EXPECT_EQ(source(*feed, 1)["count"], 2);
}

TEST(ElementFeed, TheCacheBringsBackTheCatalogueAndTheHistory) {
  Rig rig;
  rig.serve("https://a/x", catalogue_of(40000, 20, 60.5));
  {
    auto feed = rig.feed({"https://a/x"});
    feed->start(rig.now);
    feed->tick(rig.now);
  }
  // A restart an hour later without the network: the cache's sets at once, no fetch before
  // CelesTrak's two hours have passed.
  rig.served.clear();
  rig.published.reset();
  rig.now += 3600.0;
  auto again = rig.feed({"https://a/x"});
  again->start(rig.now);
  EXPECT_EQ(rig.count(), 20U);
  again->tick(rig.now);
  EXPECT_EQ(rig.fetches, 1);
  EXPECT_EQ(source(*again, 0)["last_ok"], "2024-03-01T12:30:00.000Z");
  // The history survived: an older file is still a step back.
  rig.serve("https://a/x", catalogue_of(40000, 20, 59.0));
  again->tick(rig.now + 2 * 3600.0);
  EXPECT_EQ(rig.fetches, 2);
  EXPECT_NE(source(*again, 0)["last_error"].get<std::string>().find("went back in time"),
            std::string::npos);
  EXPECT_EQ(rig.count(), 20U);
}

TEST(ElementFeed, AnUploadIsScreenedThenMerged) {
  Rig rig;
  rig.serve("https://a/x", catalogue_of(40000, 2, 60.5));
  auto feed = rig.feed({"https://a/x"});
  feed->start(rig.now);
  feed->tick(rig.now);
  std::optional<Result<nlohmann::json>> answer;
  feed->upload("garbage\nmore garbage\n", rig.now, [&](Result<nlohmann::json> r) { answer = r; });
  ASSERT_TRUE(answer && !*answer);
  EXPECT_NE(answer->error().message.find("does not parse"), std::string::npos);
  EXPECT_EQ(rig.count(), 2U);
  feed->upload(
      tle(40000, 61.5, "UP NEWER") + tle(40001, 59.0, "UP OLDER") + tle(60000, 61.0, "UP NEW"),
      rig.now, [&](Result<nlohmann::json> r) { answer = r; });
  ASSERT_TRUE(answer && *answer) << answer->error().message;
  EXPECT_EQ(answer->value()["count"], 3);
  EXPECT_EQ(answer->value()["newer"], 2);
  EXPECT_EQ(answer->value()["not_newer"], 1);
  ASSERT_EQ(rig.count(), 3U);
  EXPECT_EQ(rig.published->find("40000").elements.name, "UP NEWER");
  EXPECT_EQ(rig.published->find("40001").elements.name, "SAT 40001");
  EXPECT_EQ(feed->to_json().back()["kind"], "upload");
}

TEST(ElementFeed, AnUploadFromTheFutureIsRefused) {
  Rig rig;
  auto feed = rig.feed({});
  feed->start(rig.now);
  std::optional<Result<nlohmann::json>> answer;
  feed->upload(tle(40000, 70.0, "AHEAD"), rig.now, [&](Result<nlohmann::json> r) { answer = r; });
  ASSERT_TRUE(answer && !*answer);
  EXPECT_NE(answer->error().message.find("implausible epoch: AHEAD"), std::string::npos);
}

}  // namespace
}  // namespace azt::app
