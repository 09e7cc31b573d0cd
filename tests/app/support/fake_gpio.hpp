#pragma once
// A GPIO provider in memory for the station's tests: outputs record every write with the time it
// happened; inputs change level from the test and report the edge through the io_context, as the
// libgpiod adapter does when the kernel's event descriptor becomes readable.

#include <chrono>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "azt/linux/asio.hpp"
#include "azt/linux/gpio.hpp"

namespace azt::app::testing {

struct GpioWrite {
  std::string key;
  bool active = false;
  std::chrono::steady_clock::time_point at;
};

class FakeGpio final : public linux_os::GpioProvider {
 public:
  explicit FakeGpio(boost::asio::io_context& io) : io_(io) {}

  Result<std::unique_ptr<linux_os::GpioOutput>> output(const linux_os::GpioLineSpec& spec,
                                                       bool initial) override {
    if (busy_.count(spec.offset) != 0) return fail(describe(spec) + ": line busy");
    auto out = std::make_unique<Output>(*this, spec);
    (void)out->set(initial);
    return std::unique_ptr<linux_os::GpioOutput>(std::move(out));
  }

  Result<std::unique_ptr<linux_os::GpioInput>> input(const linux_os::GpioLineSpec& spec,
                                                     linux_os::GpioBias /*bias*/,
                                                     linux_os::GpioEdgeHandler on_edge) override {
    if (busy_.count(spec.offset) != 0) return fail(describe(spec) + ": line busy");
    auto in = std::make_unique<Input>(*this, spec, std::move(on_edge));
    inputs_[spec.key] = in.get();
    return std::unique_ptr<linux_os::GpioInput>(std::move(in));
  }

  /// An input reporting every edge (a pulse sensor's line or home switch).
  Result<std::unique_ptr<linux_os::GpioInput>> event_input(
      const linux_os::GpioLineSpec& spec, linux_os::GpioBias /*bias*/,
      linux_os::GpioEventHandler on_event) override {
    if (busy_.count(spec.offset) != 0) return fail(describe(spec) + ": line busy");
    auto in = std::make_unique<Input>(*this, spec, nullptr);
    in->on_event = std::move(on_event);
    inputs_[spec.key] = in.get();
    return std::unique_ptr<linux_os::GpioInput>(std::move(in));
  }
  /// An event input's line `key` goes to `active` at `at` (the kernel's stamp); delivered by the
  /// loop like set_input()'s edges.
  void edge(const std::string& key, bool active, std::chrono::steady_clock::time_point at) {
    levels_[key] = active;
    boost::asio::post(io_, [this, key, active, at] {
      auto it = inputs_.find(key);
      if (it != inputs_.end() && it->second->on_event) {
        it->second->level = active;
        it->second->on_event({active, at});
      }
    });
  }

  /// The line of `key` (e.g. "[gpio] estop") goes to `active`; the edge is delivered by the loop.
  void set_input(const std::string& key, bool active) {
    levels_[key] = active;
    boost::asio::post(io_, [this, key, active] {
      auto it = inputs_.find(key);
      if (it != inputs_.end() && it->second->on_edge) {
        it->second->level = active;
        it->second->on_edge(active);
      }
    });
  }
  /// The level an input starts at when requested.
  void preset(const std::string& key, bool active) { levels_[key] = active; }
  void make_busy(unsigned offset) { busy_[offset] = true; }
  void fail_writes(bool fail) { fail_writes_ = fail; }

  std::vector<GpioWrite> writes;
  std::map<std::string, bool> outputs;  ///< the present level of every output

 private:
  struct Output final : linux_os::GpioOutput {
    Output(FakeGpio& g, linux_os::GpioLineSpec s) : gpio(g), line(std::move(s)) {}
    ~Output() override { gpio.outputs[line.key] = false; }
    Output(const Output&) = delete;
    Output& operator=(const Output&) = delete;
    Output(Output&&) = delete;
    Output& operator=(Output&&) = delete;
    Result<bool> set(bool on) override {
      if (gpio.fail_writes_) return fail(describe(line) + ": write failed: No such device");
      level = on;
      gpio.outputs[line.key] = on;
      gpio.writes.push_back({line.key, on, std::chrono::steady_clock::now()});
      return true;
    }
    [[nodiscard]] bool active() const override { return level; }
    [[nodiscard]] const linux_os::GpioLineSpec& spec() const override { return line; }
    FakeGpio& gpio;
    linux_os::GpioLineSpec line;
    bool level = false;
  };
  struct Input final : linux_os::GpioInput {
    Input(FakeGpio& g, linux_os::GpioLineSpec s, linux_os::GpioEdgeHandler h)
        : gpio(g), line(std::move(s)), on_edge(std::move(h)), level(gpio.levels_[line.key]) {}
    ~Input() override { gpio.inputs_.erase(line.key); }
    Input(const Input&) = delete;
    Input& operator=(const Input&) = delete;
    Input(Input&&) = delete;
    Input& operator=(Input&&) = delete;
    [[nodiscard]] bool active() const override { return level; }
    [[nodiscard]] const linux_os::GpioLineSpec& spec() const override { return line; }
    FakeGpio& gpio;
    linux_os::GpioLineSpec line;
    linux_os::GpioEdgeHandler on_edge;
    linux_os::GpioEventHandler on_event;  ///< event inputs only
    bool level;
  };

  boost::asio::io_context& io_;
  std::map<std::string, Input*> inputs_;
  std::map<std::string, bool> levels_;
  std::map<unsigned, bool> busy_;
  bool fail_writes_ = false;
};

/// A reed counted on `table`'s pulse_line at `counts_per_deg`, with its home switch closed below
/// `home_deg`, on a rotator that turned from `before_deg` to `after_deg`: each count crossed closes
/// and opens the reed, and the switch changes where home is crossed, every edge stamped `at` (the
/// loop delivers them at its next poll).
inline void turn_reed(FakeGpio& gpio, const std::string& table, double before_deg, double after_deg,
                      double counts_per_deg, double home_deg,
                      std::chrono::steady_clock::time_point at) {
  const auto crossed = std::abs(std::lround(std::floor(after_deg * counts_per_deg)) -
                                std::lround(std::floor(before_deg * counts_per_deg)));
  for (long i = 0; i < crossed; ++i) {
    gpio.edge(table + " pulse_line", true, at);
    gpio.edge(table + " pulse_line", false, at);
  }
  if ((before_deg < home_deg) != (after_deg < home_deg)) {
    gpio.edge(table + " home_switch", after_deg < home_deg, at);
  }
}

}  // namespace azt::app::testing
