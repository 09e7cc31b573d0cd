// GpioPulseInput over the fake GPIO provider: each edge the "kernel" stamps reaches the control
// tick with its own time on the loop's clock, the lines' edges interleaved by time, none merged;
// a busy line is refused by name.
#include "azt/linux/gpio_pulse_input.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <vector>

#include "../../app/support/fake_gpio.hpp"
#include "azt/control/pulse_axis.hpp"

namespace azt::linux_os {
namespace {

using std::chrono::milliseconds;

GpioLineSpec line(unsigned offset, const char* key) {
  GpioLineSpec s;
  s.offset = offset;
  s.key = key;
  return s;
}

struct Rig {
  boost::asio::io_context io;
  app::testing::FakeGpio gpio{io};
  std::chrono::steady_clock::time_point epoch = std::chrono::steady_clock::now();
};

TEST(GpioPulseInput, HandsEveryStampedEdgeToTheTickInTimeOrder) {
  Rig r;
  r.gpio.preset("[hardware.el] home_switch", true);
  GpioPulseLines lines{{line(20, "[hardware.el] pulse_lines")},
                       line(16, "[hardware.el] home_switch")};
  auto input = GpioPulseInput::open(r.gpio, lines, r.epoch).value();
  EXPECT_TRUE(input->home_closed());
  // Two pulses close together (one loop turn would merge them as a level) and the switch opening
  // between them, delivered line by line.
  r.gpio.edge("[hardware.el] pulse_lines", true, r.epoch + milliseconds(100));
  r.gpio.edge("[hardware.el] pulse_lines", false, r.epoch + milliseconds(110));
  r.gpio.edge("[hardware.el] pulse_lines", true, r.epoch + milliseconds(130));
  r.gpio.edge("[hardware.el] home_switch", false, r.epoch + milliseconds(120));
  r.io.poll();
  const auto edges = input->take_edges();
  ASSERT_EQ(edges.size(), 4U);
  const std::vector<ports::PulseLine> order{ports::PulseLine::Pulse, ports::PulseLine::Pulse,
                                            ports::PulseLine::Home, ports::PulseLine::Pulse};
  for (std::size_t i = 0; i < edges.size(); ++i) {
    EXPECT_EQ(edges[i].line, order[i]) << i;
    if (i > 0) {
      EXPECT_LT(edges[i - 1].at_s, edges[i].at_s);
    }
  }
  EXPECT_NEAR(edges[0].at_s, 0.100, 1e-9);
  EXPECT_NEAR(edges[2].at_s, 0.120, 1e-9);
  EXPECT_FALSE(edges[2].high);
  EXPECT_FALSE(input->home_closed());
  EXPECT_TRUE(input->take_edges().empty());  // taken once
  EXPECT_EQ(input->overflowed(), 0U);

  // Into the core's counter: the two closures are two pulses, counted in the drive's direction.
  control::PulseAxisConfig c;
  c.scale = {control::PulseUnit::Degrees, 11.7, 0.0};
  auto axis = control::PulseAxis::make(c).value();
  axis.set_drive(1.0, 0.0);
  axis.on_edges(edges);
  EXPECT_EQ(axis.counter().count(), 2);
}

TEST(GpioPulseInput, TwoLinesAreAQuadraturePairAndABusyLineIsRefusedByName) {
  Rig r;
  GpioPulseLines quad{
      {line(20, "[hardware.az] pulse_lines A"), line(21, "[hardware.az] pulse_lines B")},
      line(16, "[hardware.az] home_switch")};
  auto input = GpioPulseInput::open(r.gpio, quad, r.epoch).value();
  r.gpio.edge("[hardware.az] pulse_lines B", true, r.epoch + milliseconds(2));
  r.gpio.edge("[hardware.az] pulse_lines A", true, r.epoch + milliseconds(1));
  r.io.poll();
  const auto edges = input->take_edges();
  ASSERT_EQ(edges.size(), 2U);
  EXPECT_EQ(edges[0].line, ports::PulseLine::QuadratureA);
  EXPECT_EQ(edges[1].line, ports::PulseLine::QuadratureB);

  Rig busy;
  busy.gpio.make_busy(16);
  const auto refused = GpioPulseInput::open(busy.gpio, quad, busy.epoch);
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.error().message.find("[hardware.az] home_switch"), std::string::npos)
      << refused.error().message;
  GpioPulseLines none{{}, line(16, "home")};
  EXPECT_FALSE(GpioPulseInput::open(busy.gpio, none, busy.epoch).ok());
}

}  // namespace
}  // namespace azt::linux_os
