#include "azt/linux/adc_devices.hpp"

#include <cstdio>

namespace azt::linux_os {
namespace {

std::string ads_where(std::uint8_t address, unsigned channel) {
  char text[40];
  std::snprintf(text, sizeof text, "ADS1115 at 0x%02x channel %u: ", static_cast<unsigned>(address),
                channel);
  return text;
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

Result<std::int16_t> Ads1115Reader::read(unsigned channel) {
  const auto config = proto::ads1115_single_shot_config(channel, range_);
  if (!config) return fail(ads_where(address_, channel) + "channel is not 0-3");
  const auto start = proto::ads1115_write(proto::kAds1115PointerConfig, *config);
  if (auto r = bus_.write(address_, start); !r) {
    return fail(ads_where(address_, channel) + r.error().message);
  }
  bool ready = false;
  std::array<std::uint8_t, 2> value{};
  for (unsigned poll = 0; poll < kMaxPolls && !ready; ++poll) {
    if (poll > 0 && wait_) wait_();
    if (auto r = read_register(proto::kAds1115PointerConfig, value); !r) {
      return fail(ads_where(address_, channel) + r.error().message);
    }
    ready = proto::ads1115_ready(value);
  }
  if (!ready) {
    return fail(ads_where(address_, channel) + "conversion did not finish after " +
                std::to_string(kMaxPolls) + " polls");
  }
  if (auto r = read_register(proto::kAds1115PointerConversion, value); !r) {
    return fail(ads_where(address_, channel) + r.error().message);
  }
  return proto::ads1115_code(value);
}

}  // namespace azt::linux_os
