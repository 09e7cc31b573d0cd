#include "azt/linux/adc_devices.hpp"

#include <cstdio>

namespace azt::linux_os {
namespace {

std::string ads_at(std::uint8_t address) {
  char text[24];
  std::snprintf(text, sizeof text, "ADS1115 at 0x%02x", static_cast<unsigned>(address));
  return text;
}

std::string ads_where(std::uint8_t address, unsigned channel) {
  return ads_at(address) + " channel " + std::to_string(channel) + ": ";
}

}  // namespace

Result<std::uint16_t> Mcp3008Reader::read(unsigned channel) {
  const auto request = proto::mcp3008_request(channel);
  if (!request) return fail("MCP3008: channel " + std::to_string(channel) + " is not 0-7");
  std::array<std::uint8_t, 3> reply{};
  if (auto r = bus_.transfer(*request, reply); !r) {
    return fail("MCP3008 channel " + std::to_string(channel) + ": " + r.error().message);
  }
  return proto::mcp3008_code(reply);
}

Result<double> Mcp3008Reader::read_average(unsigned channel, unsigned n) {
  if (n < 1 || n > 256) return fail("MCP3008: average of " + std::to_string(n) + " is not 1-256");
  std::uint32_t sum = 0;
  for (unsigned i = 0; i < n; ++i) {
    auto code = read(channel);
    if (!code) return code.error();
    sum += *code;
  }
  return static_cast<double>(sum) / static_cast<double>(n);
}

Result<bool> Ads1115Reader::read_register(std::uint8_t pointer,
                                          std::array<std::uint8_t, 2>& value) {
  const std::array<std::uint8_t, 1> select{pointer};
  if (auto r = bus_.write(address_, select); !r) return r;
  return bus_.read(address_, value);
}

Error Ads1115Reader::error(unsigned channel, const std::string& what) const {
  return fail(ads_where(address_, channel) + what);
}

Result<bool> Ads1115Reader::start(unsigned channel) {
  started_channel_.reset();
  const auto config = proto::ads1115_single_shot_config(channel, range_);
  if (!config) return error(channel, "channel is not 0-3");
  const auto start = proto::ads1115_write(proto::kAds1115PointerConfig, *config);
  if (auto r = bus_.write(address_, start); !r) return error(channel, r.error().message);
  started_channel_ = channel;
  return true;
}

Result<bool> Ads1115Reader::poll() {
  // Without a conversion started the OS bit reads 1 too (the chip idles powered down), so a
  // poll then would pass off an old result as new.
  if (!started_channel_) return fail(ads_at(address_) + ": no conversion started");
  std::array<std::uint8_t, 2> config{};
  if (auto r = read_register(proto::kAds1115PointerConfig, config); !r) {
    return error(*started_channel_, r.error().message);
  }
  return proto::ads1115_ready(config);
}

Result<std::int16_t> Ads1115Reader::fetch() {
  if (!started_channel_) return fail(ads_at(address_) + ": no conversion started");
  const unsigned channel = *started_channel_;
  started_channel_.reset();
  std::array<std::uint8_t, 2> value{};
  if (auto r = read_register(proto::kAds1115PointerConversion, value); !r) {
    return error(channel, r.error().message);
  }
  return proto::ads1115_code(value);
}

}  // namespace azt::linux_os
