// The sysfs PWM adapter and the drives on it (the IBT-2 bridge, a stepper's STEP input), against a
// directory laid out like /sys/class/pwm/pwmchipN. The fake kernel's export is a pwmN directory
// made beforehand; the test checks what the adapter wrote into each attribute.
#include "azt/linux/sysfs_pwm.hpp"
#include "azt/linux/pwm_hbridge.hpp"
#include "azt/linux/step_dir_drive.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace azt::linux_os {
namespace {

namespace fs = std::filesystem;

class FakePwmChip : public ::testing::Test {
 protected:
  void SetUp() override {
    chip_ = fs::temp_directory_path() /
            ("azt_pwmchip_" + std::to_string(::getpid()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(chip_);
    fs::create_directories(chip_);
    std::ofstream(chip_ / "export") << "";
    std::ofstream(chip_ / "npwm") << "2\n";
  }
  void TearDown() override { fs::remove_all(chip_); }

  /// What the kernel would create on export.
  void exported(unsigned channel) {
    const fs::path dir = chip_ / ("pwm" + std::to_string(channel));
    fs::create_directories(dir);
    for (const char* f : {"period", "duty_cycle", "enable"}) std::ofstream(dir / f) << "0\n";
  }
  std::string attr(unsigned channel, const char* name) const {
    std::ifstream in(chip_ / ("pwm" + std::to_string(channel)) / name);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  std::string file(const char* name) const {
    std::ifstream in(chip_ / name);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }

  fs::path chip_;
};

TEST_F(FakePwmChip, OpenSetsThePeriodWithZeroDutyAndEnables) {
  exported(0);
  auto pwm = SysfsPwm::open(chip_.string(), 0, 1000.0);
  ASSERT_TRUE(pwm.ok()) << pwm.error().message;
  EXPECT_EQ(attr(0, "period"), "1000000");
  EXPECT_EQ(attr(0, "duty_cycle"), "0");
  EXPECT_EQ(attr(0, "enable"), "1");
  ASSERT_TRUE(pwm.value().set_duty(0.25).ok());
  EXPECT_EQ(attr(0, "duty_cycle"), "250000");
  ASSERT_TRUE(pwm.value().set_duty(7.0).ok());  // clamped
  EXPECT_EQ(attr(0, "duty_cycle"), "1000000");
  ASSERT_TRUE(pwm.value().disable().ok());
  EXPECT_EQ(attr(0, "duty_cycle"), "0");
  EXPECT_EQ(attr(0, "enable"), "0");
}

TEST_F(FakePwmChip, AChannelThatDoesNotExportIsAClearError) {
  auto pwm = SysfsPwm::open(chip_.string(), 1, 1000.0);
  ASSERT_FALSE(pwm.ok());
  EXPECT_NE(pwm.error().message.find("pwm1 did not appear"), std::string::npos)
      << pwm.error().message;
  EXPECT_EQ(file("export"), "1");  // it did ask the kernel
  auto missing = SysfsPwm::open((chip_ / "nochip").string(), 0, 1000.0);
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().message.find("no such PWM chip"), std::string::npos);
}

TEST_F(FakePwmChip, TheBridgeNeverDrivesBothSidesAndWaitsBeforeReversing) {
  exported(0);
  exported(1);
  PwmHBridgeConfig c;
  c.chip_dir = chip_.string();
  c.frequency_hz = 20000.0;  // period 50 000 ns
  c.dead_time_s = 0.1;
  auto bridge = PwmHBridge::open(c);
  ASSERT_TRUE(bridge.ok()) << bridge.error().message;
  ASSERT_TRUE(bridge.value().apply(0.0, 0.5).ok());
  EXPECT_EQ(attr(0, "duty_cycle"), "25000");
  EXPECT_EQ(attr(1, "duty_cycle"), "0");
  ASSERT_TRUE(bridge.value().apply(0.05, -0.5).ok());  // reversal requested: both off first
  EXPECT_EQ(attr(0, "duty_cycle"), "0");
  EXPECT_EQ(attr(1, "duty_cycle"), "0");
  ASSERT_TRUE(bridge.value().apply(0.16, -0.5).ok());  // after the dead time
  EXPECT_EQ(attr(0, "duty_cycle"), "0");
  EXPECT_EQ(attr(1, "duty_cycle"), "25000");
  ASSERT_TRUE(bridge.value().disable(0.2).ok());
  EXPECT_EQ(attr(0, "enable"), "0");
  EXPECT_EQ(attr(1, "enable"), "0");
}

TEST_F(FakePwmChip, AWriteErrorDisablesTheBridgeAndIsReported) {
  exported(0);
  exported(1);
  PwmHBridgeConfig c;
  c.chip_dir = chip_.string();
  auto bridge = PwmHBridge::open(c);
  ASSERT_TRUE(bridge.ok());
  fs::remove(chip_ / "pwm0" / "duty_cycle");              // the device went away
  fs::create_directories(chip_ / "pwm0" / "duty_cycle");  // and opening it for writing fails
  const auto r = bridge.value().apply(0.0, 0.5);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("pwm0/duty_cycle"), std::string::npos) << r.error().message;
  EXPECT_EQ(attr(1, "enable"), "0");
}

/// A GPIO line that records its level (DIR, ENABLE).
class RecordedLine final : public GpioOutput {
 public:
  explicit RecordedLine(std::string key) : spec_{"gpiochip0", 0, false, std::move(key)} {}
  Result<bool> set(bool active) override {
    active_ = active;
    return true;
  }
  [[nodiscard]] bool active() const override { return active_; }
  [[nodiscard]] const GpioLineSpec& spec() const override { return spec_; }

 private:
  GpioLineSpec spec_;
  bool active_ = false;
};

TEST_F(FakePwmChip, TheStepRateIsThePeriodAtHalfDutyAndDirTurnsOnlyWithoutPulses) {
  exported(0);
  auto step = SysfsPwm::open(chip_.string(), 0, 1000.0);
  ASSERT_TRUE(step.ok());
  auto dir = std::make_unique<RecordedLine>("[hardware.az] dir");
  auto enable = std::make_unique<RecordedLine>("[hardware.az] enable");
  const RecordedLine* dir_line = dir.get();
  const RecordedLine* enable_line = enable.get();
  auto drive = make_step_dir_drive(std::move(step).value(), std::move(dir), std::move(enable),
                                   control::StepDirConfig{2000.0, 200.0, 4000.0}, "stepper");
  ASSERT_TRUE(drive->apply(0.0, 1.0, std::nullopt).ok());  // DIR's set-up tick: no pulses
  EXPECT_TRUE(dir_line->active());
  EXPECT_TRUE(enable_line->active());
  EXPECT_EQ(attr(0, "duty_cycle"), "0");
  ASSERT_TRUE(drive->apply(0.05, 1.0, std::nullopt).ok());
  EXPECT_EQ(attr(0, "period"), "5000000");  // 200 Hz, the pull-in rate
  EXPECT_EQ(attr(0, "duty_cycle"), "2500000");
  ASSERT_TRUE(drive->apply(0.10, 1.0, std::nullopt).ok());
  EXPECT_EQ(attr(0, "period"), "2500000");  // 400 Hz: 4000 Hz/s for one 50 ms tick
  EXPECT_EQ(attr(0, "duty_cycle"), "1250000");
  // Reversed: the pulses stop (the band's edge, then none) before DIR turns.
  ASSERT_TRUE(drive->apply(0.15, -1.0, std::nullopt).ok());
  EXPECT_EQ(attr(0, "period"), "5000000");
  EXPECT_TRUE(dir_line->active());
  ASSERT_TRUE(drive->apply(0.20, -1.0, std::nullopt).ok());
  EXPECT_EQ(attr(0, "duty_cycle"), "0");
  EXPECT_TRUE(dir_line->active());
  ASSERT_TRUE(drive->apply(0.25, -1.0, std::nullopt).ok());
  EXPECT_FALSE(dir_line->active());
  EXPECT_EQ(attr(0, "duty_cycle"), "0");
  drive->off(0.3);
  EXPECT_FALSE(enable_line->active());
  EXPECT_EQ(attr(0, "duty_cycle"), "0");
}

TEST_F(FakePwmChip, AStepRateOutsideWhatThePwmCanMakeIsRefused) {
  exported(0);
  auto step = SysfsPwm::open(chip_.string(), 0, 1000.0);
  ASSERT_TRUE(step.ok());
  EXPECT_FALSE(step.value().set_rate(0.5, 0.5).ok());
  EXPECT_FALSE(step.value().set_rate(std::nan(""), 0.5).ok());
  EXPECT_EQ(attr(0, "period"), "1000000");
}

}  // namespace
}  // namespace azt::linux_os
