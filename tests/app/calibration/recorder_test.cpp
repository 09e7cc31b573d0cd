// Recording (docs/calibration.md "Recording"): rows at the chosen rate on an injected clock
// whatever the ticks' jitter, handed on in batches (the header first, the first batch creating
// the file), the size cap and a failed write ending the recording with the reason, the file's
// name and the names a download may ask for; the files appended, listed and read back; the noise
// log read newest first.
#include "calibration/recorder.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "calibration/noise_log.hpp"
#include "calibration/recording_files.hpp"

namespace azt::app {
namespace {

constexpr double kUnix = 1764433800.0;  // 2025-11-29T16:30:00Z

struct Batch {
  std::string name;
  std::string text;
  bool first;
};

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, sep)) parts.push_back(part);
  if (!text.empty() && text.back() == sep && sep == ',') parts.emplace_back();
  return parts;
}

RecordingSample sample_at(double t) {
  RecordingSample s;
  s.unix_s = kUnix + t;
  s.demand = control::AzEl{180.0 + 0.01 * t, 45.0};
  s.reading = control::AzEl{180.0 + 0.01 * t - 0.02, 45.01};
  s.power_db = -60.0 + t;
  s.mode = "TRACK";
  return s;
}

class RecorderTest : public ::testing::Test {
 protected:
  std::vector<Batch> batches;
  Recorder recorder{[this](const std::string& name, std::string text, bool first) {
    batches.push_back({name, std::move(text), first});
  }};
  [[nodiscard]] std::string written() const {
    std::string all;
    for (const auto& b : batches) all += b.text;
    return all;
  }
};

TEST_F(RecorderTest, RowsAtTheRateWhateverTheTicksJitterInBatches) {
  ASSERT_TRUE(recorder.start(10.0, 1 << 20, 100.0, kUnix));
  // A 20 Hz loop whose ticks come up to 4 ms late, for 5 s.
  for (int i = 0; i <= 100; ++i) {
    const double t = 0.05 * i + 0.004 * ((i * 7) % 3) / 2.0;
    recorder.sample(100.0 + t, sample_at(t));
  }
  recorder.stop("stopped by test");
  const auto j = recorder.to_json();
  EXPECT_EQ(j["state"], "stopped");
  EXPECT_EQ(j["reason"], "stopped by test");
  EXPECT_EQ(j["file"], "recording-20251129T163000Z.csv");
  EXPECT_NEAR(j["rows"].get<double>(), 51.0, 1.0);  // 0, 0.1 … 5.0 s
  ASSERT_GE(batches.size(), 3U);                    // every 2 s, and the rest at the stop
  EXPECT_TRUE(batches.front().first);
  for (std::size_t i = 1; i < batches.size(); ++i) EXPECT_FALSE(batches[i].first);
  const auto lines = split(written(), '\n');
  ASSERT_EQ(lines.size(), j["rows"].get<std::size_t>() + 1);
  EXPECT_EQ(lines[0], recording_csv_header());
  EXPECT_EQ(written().size(), j["bytes"].get<std::size_t>());
  const auto first = split(lines[1], ',');
  ASSERT_EQ(first.size(), 9U);
  EXPECT_EQ(first[0], "2025-11-29T16:30:00.000Z");
  EXPECT_EQ(first[1], "180.00000");
  EXPECT_EQ(first[5], "0.02000");  // demand − reading
  EXPECT_EQ(first[6], "-0.01000");
  EXPECT_EQ(first[7], "-60.000");
  EXPECT_EQ(first[8], "TRACK");
}

TEST_F(RecorderTest, UnknownPartsAreEmptyAndTheErrorWrapsAt360) {
  ASSERT_TRUE(recorder.start(1.0, 1 << 20, 0.0, kUnix));
  RecordingSample s;
  s.unix_s = kUnix;
  s.demand = control::AzEl{359.9, 10.0};
  s.reading = control::AzEl{0.1, 10.0};
  s.mode = "STOP";
  recorder.sample(0.0, s);
  RecordingSample holding;
  holding.unix_s = kUnix + 1.0;
  holding.mode = "STOP";
  recorder.sample(1.0, holding);
  recorder.stop("done");
  const auto lines = split(written(), '\n');
  ASSERT_EQ(lines.size(), 3U);
  const auto row = split(lines[1], ',');
  EXPECT_EQ(row[5], "-0.20000");
  EXPECT_EQ(row[7], "");  // no receiver
  EXPECT_EQ(lines[2], "2025-11-29T16:30:01.000Z,,,,,,,,STOP");
}

TEST_F(RecorderTest, ARateOutOfRangeOrASecondStartIsRefused) {
  auto bad = recorder.start(60.0, 1 << 20, 0.0, kUnix);
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error().message.rfind("rate_hz", 0), 0U);
  EXPECT_FALSE(recorder.start(0.05, 1 << 20, 0.0, kUnix));
  EXPECT_FALSE(recorder.running());
  ASSERT_TRUE(recorder.start(0.1, 1 << 20, 0.0, kUnix));
  EXPECT_FALSE(recorder.start(1.0, 1 << 20, 0.0, kUnix));
  EXPECT_EQ(recorder.to_json()["rate_hz"], 0.1);
}

TEST_F(RecorderTest, TheSizeCapEndsTheRecordingWithTheReason) {
  ASSERT_TRUE(recorder.start(50.0, 8192, 0.0, kUnix));
  int ticks = 0;
  for (; ticks < 10000 && recorder.running(); ++ticks) {
    recorder.sample(0.02 * ticks, sample_at(0.02 * ticks));
  }
  const auto j = recorder.to_json();
  EXPECT_EQ(j["state"], "stopped");
  EXPECT_NE(j["reason"].get<std::string>().find("size cap"), std::string::npos) << j.dump();
  EXPECT_LE(j["bytes"].get<std::size_t>(), 8192U);
  EXPECT_GT(j["bytes"].get<std::size_t>(), 8192U - 200U);  // stopped at the row that did not fit
  EXPECT_EQ(written().size(), j["bytes"].get<std::size_t>());
  EXPECT_LT(ticks, 10000);
}

TEST_F(RecorderTest, AFailedWriteEndsItsOwnRecordingOnly) {
  ASSERT_TRUE(recorder.start(1.0, 1 << 20, 0.0, kUnix));
  recorder.write_failed("recording-20000101T000000Z.csv", "an old one");
  EXPECT_TRUE(recorder.running());
  recorder.write_failed("recording-20251129T163000Z.csv", "No space left on device");
  EXPECT_FALSE(recorder.running());
  EXPECT_EQ(recorder.to_json()["state"], "failed");
  EXPECT_NE(recorder.to_json()["reason"].get<std::string>().find("No space"), std::string::npos);
}

TEST(RecordingFiles, NamesAreTheOnlyWayIn) {
  EXPECT_EQ(recording_file_name(kUnix + 0.7), "recording-20251129T163000Z.csv");
  EXPECT_TRUE(is_recording_file_name("recording-20251129T163000Z.csv"));
  for (const char* bad : {"../recording-20251129T163000Z.csv", "recording-20251129T163000Z.csv/",
                          "recording-2025112xT163000Z.csv", "noise-log.jsonl", "",
                          "recording-20251129T163000Z.csvx", "/etc/passwd"}) {
    EXPECT_FALSE(is_recording_file_name(bad)) << bad;
  }
}

TEST(RecordingFiles, AppendedListedAndReadBack) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("azt-rec-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                    std::to_string(reinterpret_cast<std::uintptr_t>(&kUnix)));
  std::filesystem::remove_all(dir);
  const std::string a = "recording-20251129T163000Z.csv";
  const std::string b = "recording-20251129T170000Z.csv";
  ASSERT_TRUE(append_recording(dir.string(), a, "h\n1\n2\n", true));
  ASSERT_TRUE(append_recording(dir.string(), a, "3\n", false));
  EXPECT_FALSE(append_recording(dir.string(), a, "h\n", true));  // exists: never overwritten
  ASSERT_TRUE(append_recording(dir.string(), b, "h\n", true));
  std::ofstream(dir / "notes.txt") << "not a recording\n";
  const auto list = list_recordings(dir.string())["recordings"];
  ASSERT_EQ(list.size(), 2U);
  EXPECT_EQ(list[0]["name"], b);  // newest first
  EXPECT_EQ(list[1]["rows"], 3);
  EXPECT_EQ(list[1]["bytes"], 8);
  EXPECT_EQ(*read_recording(dir.string(), a), "h\n1\n2\n3\n");
  EXPECT_FALSE(read_recording(dir.string(), "notes.txt"));
  EXPECT_FALSE(read_recording(dir.string(), "../" + a));
  EXPECT_FALSE(read_recording(dir.string(), "recording-20000101T000000Z.csv"));
  EXPECT_EQ(list_recordings((dir / "none").string())["recordings"].size(), 0U);
  std::filesystem::remove_all(dir);
}

TEST(NoiseLog, NewestFirstWithBadLinesCounted) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("azt-noise-log-" + std::to_string(reinterpret_cast<std::uintptr_t>(&kUnix)));
  std::ofstream(path) << R"({"utc":"a","y_factor_db":1})"
                      << "\n{torn\n\n"
                      << R"({"utc":"b","y_factor_db":2})"
                      << "\n[1]\n"
                      << R"({"utc":"c","y_factor_db":3})"
                      << "\n";
  const auto log = read_noise_log(path.string(), 2);
  ASSERT_EQ(log["entries"].size(), 2U);
  EXPECT_EQ(log["entries"][0]["utc"], "c");
  EXPECT_EQ(log["entries"][1]["utc"], "b");
  EXPECT_EQ(log["bad_lines"], 2);
  EXPECT_EQ(read_noise_log(path.string() + ".none")["entries"].size(), 0U);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace azt::app
