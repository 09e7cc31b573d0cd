// The SPI and I2C chip drivers (docs/hardware.md) against recording fakes of the buses: the bytes
// each one puts on the wire, checked bit for bit against the datasheets (MCP3008 DS21295
// figure 6-1, MCP41010 DS11195 section 5, ADS1115 SBAS444 section 8.6), and the real spidev and
// i2c-dev adapters' refusals of a missing device and of a file that is not one.
#include <gtest/gtest.h>
#include <linux/i2c.h>
#include <unistd.h>

#include <array>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <type_traits>
#include <vector>

#include "azt/linux/adc_devices.hpp"
#include "azt/linux/i2c_device.hpp"
#include "azt/linux/mcp41010.hpp"
#include "azt/linux/spi_device.hpp"

namespace azt::linux_os {
namespace {

using Bytes = std::vector<std::uint8_t>;

/// Records what goes out on each transfer and clocks in scripted replies (zeros when none).
class RecordingSpi : public SpiBus {
 public:
  Result<bool> transfer(std::span<const std::uint8_t> tx, std::span<std::uint8_t> rx) override {
    sent.emplace_back(tx.begin(), tx.end());
    rx_sizes.push_back(rx.size());
    if (!error.empty()) return fail(error);
    Bytes reply = replies.empty() ? Bytes(rx.size(), 0) : replies.front();
    if (!replies.empty()) replies.pop_front();
    for (std::size_t i = 0; i < rx.size() && i < reply.size(); ++i) rx[i] = reply[i];
    return true;
  }

  std::vector<Bytes> sent;
  std::vector<std::size_t> rx_sizes;
  std::deque<Bytes> replies;
  std::string error;
};

/// Records each transaction as text ("W 48: 01 c1 83", "R 48: 2") and answers reads in order.
class RecordingI2c : public I2cBus {
 public:
  Result<bool> write(std::uint8_t addr, std::span<const std::uint8_t> bytes) override {
    std::string line = "W " + hex(addr) + ":";
    for (auto b : bytes) line += " " + hex(b);
    log.push_back(line);
    if (!error.empty()) return fail(error);
    return true;
  }
  Result<bool> read(std::uint8_t addr, std::span<std::uint8_t> bytes) override {
    log.push_back("R " + hex(addr) + ": " + std::to_string(bytes.size()));
    if (!error.empty()) return fail(error);
    if (reads.empty()) return fail("fake: no read scripted");
    const Bytes reply = reads.front();
    reads.pop_front();
    for (std::size_t i = 0; i < bytes.size() && i < reply.size(); ++i) bytes[i] = reply[i];
    return true;
  }

  static std::string hex(std::uint8_t b) {
    const char* digits = "0123456789abcdef";
    return {digits[b >> 4U], digits[b & 0xFU]};
  }

  std::vector<std::string> log;
  std::deque<Bytes> reads;
  std::string error;
};

// ---- MCP41010 -----------------------------------------------------------------------------

TEST(Mcp41010Spi, WritesCommand0x11ThenTheWiperForEveryCode) {
  // DS11195 section 5: command byte 0b0001'0001 = write data, pot 0; then the data byte.
  for (const std::uint8_t wiper : std::array<std::uint8_t, 6>{0, 1, 127, 128, 200, 255}) {
    RecordingSpi bus;
    Mcp41010Writer pot(bus);
    ASSERT_TRUE(pot.write(wiper).ok());
    ASSERT_EQ(bus.sent.size(), 1U);
    EXPECT_EQ(bus.sent[0], (Bytes{0x11, wiper})) << "wiper " << int{wiper};
    EXPECT_EQ(bus.rx_sizes[0], 0U) << "the MCP41010 has nothing to read back";
  }
}

TEST(Mcp41010Spi, BusErrorPropagatesWithItsMessage) {
  RecordingSpi bus;
  bus.error = "/dev/spidev0.1: SPI transfer: Input/output error";
  Mcp41010Writer pot(bus);
  auto r = pot.write(42);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("/dev/spidev0.1: SPI transfer: Input/output error"),
            std::string::npos)
      << r.error().message;
  EXPECT_NE(r.error().message.find("MCP41010"), std::string::npos);
}

// ---- MCP3008 ------------------------------------------------------------------------------

TEST(Mcp3008Spi, RequestBytesForChannels0And7) {
  // Figure 6-1: start bit alone in the first byte; SGL/DIFF=1 and D2..D0 in the top nibble of
  // the second: channel 0 -> 1000'0000, channel 7 -> 1111'0000; a don't-care third byte.
  RecordingSpi bus;
  Mcp3008Reader adc(bus);
  ASSERT_TRUE(adc.read(0).ok());
  ASSERT_TRUE(adc.read(7).ok());
  ASSERT_EQ(bus.sent.size(), 2U);
  EXPECT_EQ(bus.sent[0], (Bytes{0x01, 0x80, 0x00}));
  EXPECT_EQ(bus.sent[1], (Bytes{0x01, 0xF0, 0x00}));
  EXPECT_EQ(bus.rx_sizes[0], 3U);
}

TEST(Mcp3008Spi, CodeIsTheLowTwoBitsOfByte1AndAllOfByte2) {
  RecordingSpi bus;
  // B9 B8 arrive last in the second byte (after a null bit); the upper bits there are
  // undefined and must be masked off: 0xFE = ???? ??10 -> 0b10'0101'1010 = 602.
  bus.replies = {Bytes{0xFF, 0xFE, 0x5A}, Bytes{0x00, 0x03, 0xFF}, Bytes{0x00, 0x00, 0x00}};
  Mcp3008Reader adc(bus);
  auto a = adc.read(3);
  auto b = adc.read(3);
  auto c = adc.read(3);
  ASSERT_TRUE(a.ok() && b.ok() && c.ok());
  EXPECT_EQ(*a, 602);
  EXPECT_EQ(*b, 1023);
  EXPECT_EQ(*c, 0);
}

TEST(Mcp3008Spi, AverageOfSeveralReads) {
  RecordingSpi bus;
  bus.replies = {Bytes{0, 0x01, 0x00}, Bytes{0, 0x01, 0x02}, Bytes{0, 0x01, 0x01},
                 Bytes{0, 0x01, 0x03}};  // 256, 258, 257, 259
  Mcp3008Reader adc(bus);
  auto mean = adc.read_average(5, 4);
  ASSERT_TRUE(mean.ok()) << mean.error().message;
  EXPECT_DOUBLE_EQ(*mean, 257.5);
  EXPECT_EQ(bus.sent.size(), 4U);
  EXPECT_FALSE(adc.read_average(5, 0).ok());
}

TEST(Mcp3008Spi, RejectsChannel8WithoutTouchingTheBus) {
  RecordingSpi bus;
  Mcp3008Reader adc(bus);
  auto r = adc.read(8);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("channel 8"), std::string::npos) << r.error().message;
  EXPECT_TRUE(bus.sent.empty());
}

TEST(Mcp3008Spi, BusErrorPropagatesWithItsMessage) {
  RecordingSpi bus;
  bus.error = "/dev/spidev0.0: SPI transfer: Connection timed out";
  Mcp3008Reader adc(bus);
  auto r = adc.read(2);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find(bus.error), std::string::npos) << r.error().message;
  EXPECT_FALSE(adc.read_average(2, 3).ok());
}

// ---- ADS1115 ------------------------------------------------------------------------------

// Nothing in the reader waits: a reading is three steps, each of one or two I2C messages, and
// the caller (Ads1115Chip in pot_sensors.cpp) spreads them over its control ticks.
template <typename R>
constexpr bool kHasBlockingRead = requires(R r) {
  r.read(0U);
};
static_assert(!kHasBlockingRead<Ads1115Reader>, "a blocking read() would wait out a conversion");
static_assert(!std::is_constructible_v<Ads1115Reader, I2cBus&, std::uint8_t, proto::Ads1115Range,
                                       std::function<void()>>,
              "no wait function between polls");

TEST(Ads1115I2c, Channel0At6V144StartPollPollFetchAreOneStepEach) {
  // Config for AIN0 vs GND, ±6.144 V, single shot, 128 SPS, comparator off (SBAS444 table 8):
  // OS=1 MUX=100 PGA=000 MODE=1 | DR=100 COMP_MODE=0 POL=0 LAT=0 QUE=11 = 1100'0001 1000'0011.
  RecordingI2c bus;
  bus.reads = {Bytes{0x41, 0x83}, Bytes{0xC1, 0x83}, Bytes{0x12, 0x34}};  // busy, done, result
  Ads1115Reader adc(bus, 0x48, proto::Ads1115Range::Fs6V144);
  ASSERT_TRUE(adc.start(0).ok());
  EXPECT_EQ(bus.log, (std::vector<std::string>{"W 48: 01 c1 83"})) << "start: one write";
  auto busy = adc.poll();
  ASSERT_TRUE(busy.ok()) << busy.error().message;
  EXPECT_FALSE(*busy);
  EXPECT_EQ(bus.log.size(), 3U) << "poll: the pointer, then one read";
  auto done = adc.poll();
  ASSERT_TRUE(done.ok()) << done.error().message;
  EXPECT_TRUE(*done);
  auto code = adc.fetch();
  ASSERT_TRUE(code.ok()) << code.error().message;
  EXPECT_EQ(*code, 0x1234);
  const std::vector<std::string> expected = {
      "W 48: 01 c1 83",             // start the conversion
      "W 48: 01",       "R 48: 2",  // poll: busy
      "W 48: 01",       "R 48: 2",  // poll: done
      "W 48: 00",       "R 48: 2",  // fetch: the Conversion register
  };
  EXPECT_EQ(bus.log, expected);
}

TEST(Ads1115I2c, Channel3At4V096OtherAddressAndNegativeCode) {
  // AIN3: MUX=111; ±4.096 V: PGA=001 -> 1111'0011 1000'0011.
  RecordingI2c bus;
  bus.reads = {Bytes{0xF3, 0x83}, Bytes{0xFF, 0xFE}};
  Ads1115Reader adc(bus, 0x49, proto::Ads1115Range::Fs4V096);
  ASSERT_TRUE(adc.start(3).ok());
  auto done = adc.poll();
  ASSERT_TRUE(done.ok() && *done);
  auto code = adc.fetch();
  ASSERT_TRUE(code.ok()) << code.error().message;
  EXPECT_EQ(*code, -2);
  const std::vector<std::string> expected = {"W 49: 01 f3 83", "W 49: 01", "R 49: 2", "W 49: 00",
                                             "R 49: 2"};
  EXPECT_EQ(bus.log, expected);
}

TEST(Ads1115I2c, PollAndFetchNeedAStartedConversion) {
  // An idle ADS1115 reads OS = 1 too: a poll without a start would pass off an old result.
  RecordingI2c bus;
  Ads1115Reader adc(bus, 0x48);
  EXPECT_FALSE(adc.poll().ok());
  EXPECT_FALSE(adc.fetch().ok());
  EXPECT_TRUE(bus.log.empty());
  bus.reads = {Bytes{0xC3, 0x83}, Bytes{0x00, 0x10}};
  ASSERT_TRUE(adc.start(0).ok());
  ASSERT_TRUE(adc.poll().ok());
  ASSERT_TRUE(adc.fetch().ok());
  auto again = adc.fetch();
  ASSERT_FALSE(again.ok()) << "a second fetch of one conversion";
  EXPECT_NE(again.error().message.find("no conversion started"), std::string::npos)
      << again.error().message;
  EXPECT_EQ(bus.log.size(), 5U);
}

TEST(Ads1115I2c, BusErrorPropagatesWithItsMessage) {
  RecordingI2c bus;
  bus.error = "/dev/i2c-1 addr 0x48: Remote I/O error (nothing answers at this address?)";
  Ads1115Reader adc(bus, 0x48, proto::Ads1115Range::Fs6V144);
  auto r = adc.start(1);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find(bus.error), std::string::npos) << r.error().message;
  EXPECT_NE(r.error().message.find("ADS1115 at 0x48 channel 1"), std::string::npos)
      << r.error().message;
  EXPECT_EQ(bus.log.size(), 1U) << "stops at the first failed transaction";
  EXPECT_FALSE(adc.poll().ok()) << "a failed start started nothing";
  EXPECT_EQ(bus.log.size(), 1U);
}

TEST(Ads1115I2c, PollErrorNamesTheChannel) {
  RecordingI2c bus;
  Ads1115Reader adc(bus, 0x4B);
  ASSERT_TRUE(adc.start(2).ok());
  bus.error = "/dev/i2c-1 addr 0x4b: Input/output error";
  auto r = adc.poll();
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message, "ADS1115 at 0x4b channel 2: " + bus.error);
  EXPECT_EQ(bus.log.size(), 2U) << "the pointer write failed; no read after it";
}

TEST(Ads1115I2c, RejectsChannel4WithoutTouchingTheBus) {
  RecordingI2c bus;
  Ads1115Reader adc(bus, 0x48, proto::Ads1115Range::Fs6V144);
  EXPECT_FALSE(adc.start(4).ok());
  EXPECT_TRUE(bus.log.empty());
}

// ---- the real adapters' error paths -------------------------------------------------------

class SpiI2cNotADevice : public ::testing::Test {
 protected:
  void SetUp() override {
    file_ = std::filesystem::temp_directory_path() /
            ("azt_not_a_device_" + std::to_string(::getpid()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::ofstream(file_) << "plain file\n";
  }
  void TearDown() override { std::filesystem::remove(file_); }
  std::filesystem::path file_;
};

TEST(SpidevBusOpen, MissingDeviceNamesThePathAndTheHint) {
  auto bus = SpidevBus::open("/dev/azt-no-such-spidev9.9", 1000000);
  ASSERT_FALSE(bus.ok());
  EXPECT_EQ(bus.error().message,
            "/dev/azt-no-such-spidev9.9: No such file or directory (is SPI enabled? "
            "dtparam=spi=on)");
}

TEST_F(SpiI2cNotADevice, SpidevBusOpenRefusesARegularFile) {
  auto bus = SpidevBus::open(file_.string(), 1000000);
  ASSERT_FALSE(bus.ok());
  EXPECT_NE(bus.error().message.find(file_.string() + ": not a spidev device"), std::string::npos)
      << bus.error().message;
}

TEST(SpidevBusOpen, RejectsBadModeAndSpeed) {
  EXPECT_FALSE(SpidevBus::open("/dev/spidev0.0", 1000000, 4).ok());
  EXPECT_FALSE(SpidevBus::open("/dev/spidev0.0", 0).ok());
}

// On an SMBus-only adapter (the system test's i2c-stub) the ADS1115's transactions travel as
// SMBus word transfers carrying the same bytes: Config 0xC383 written is the word 0x83C3.
TEST(SmbusForm, APointerWriteIsASendByteAndARegisterWriteAWordLowByteFirst) {
  const std::array<std::uint8_t, 1> pointer{0x01};
  auto send = smbus_write_form(pointer);
  ASSERT_TRUE(send.ok());
  EXPECT_FALSE(send->read);
  EXPECT_EQ(send->command, 0x01);
  EXPECT_EQ(send->size, static_cast<std::uint32_t>(I2C_SMBUS_BYTE));
  const std::array<std::uint8_t, 3> config{0x01, 0xC3, 0x83};
  auto word = smbus_write_form(config);
  ASSERT_TRUE(word.ok());
  EXPECT_EQ(word->command, 0x01);
  EXPECT_EQ(word->size, static_cast<std::uint32_t>(I2C_SMBUS_WORD_DATA));
  EXPECT_EQ(word->word, 0x83C3);
}

TEST(SmbusForm, OtherWriteLengthsHaveNone) {
  const std::array<std::uint8_t, 2> two{0x01, 0xC3};
  auto form = smbus_write_form(two);
  ASSERT_FALSE(form.ok());
  EXPECT_NE(form.error().message.find("a write of 2 bytes has no SMBus form"), std::string::npos);
  EXPECT_FALSE(smbus_write_form(std::span<const std::uint8_t>{}).ok());
}

TEST(SmbusForm, AReadNamesTheRegisterLastWrittenAndIsTwoBytes) {
  auto read = smbus_read_form(std::uint8_t{0x00}, 2);
  ASSERT_TRUE(read.ok());
  EXPECT_TRUE(read->read);
  EXPECT_EQ(read->command, 0x00);
  EXPECT_EQ(read->size, static_cast<std::uint32_t>(I2C_SMBUS_WORD_DATA));
  EXPECT_FALSE(smbus_read_form(std::nullopt, 2).ok());
  EXPECT_FALSE(smbus_read_form(std::uint8_t{0x00}, 3).ok());
}

TEST(I2cDevBusOpen, MissingDeviceNamesThePathAndTheHint) {
  auto bus = I2cDevBus::open("/dev/azt-no-such-i2c-99");
  ASSERT_FALSE(bus.ok());
  EXPECT_EQ(bus.error().message,
            "/dev/azt-no-such-i2c-99: No such file or directory (is I2C enabled? "
            "dtparam=i2c_arm=on)");
}

TEST_F(SpiI2cNotADevice, I2cDevBusOpenRefusesARegularFile) {
  auto bus = I2cDevBus::open(file_.string());
  ASSERT_FALSE(bus.ok());
  EXPECT_NE(bus.error().message.find(file_.string() + ": not an i2c-dev device"), std::string::npos)
      << bus.error().message;
}

}  // namespace
}  // namespace azt::linux_os
