#include "azt/linux/pwm_hbridge.hpp"

namespace azt::linux_os {

Result<PwmHBridge> PwmHBridge::open(const PwmHBridgeConfig& config) {
  if (config.rpwm_channel == config.lpwm_channel) return fail("RPWM and LPWM need two channels");
  auto r = SysfsPwm::open(config.chip_dir, config.rpwm_channel, config.frequency_hz);
  if (!r) return fail("RPWM: " + r.error().message);
  auto l = SysfsPwm::open(config.chip_dir, config.lpwm_channel, config.frequency_hz);
  if (!l) {
    (void)r.value().disable();
    return fail("LPWM: " + l.error().message);
  }
  return PwmHBridge(std::move(r).value(), std::move(l).value(), config.dead_time_s);
}

Result<bool> PwmHBridge::apply(double now_s, double duty) {
  const control::HBridgeOutputs o = bridge_.drive(now_s, duty);
  // The side going to zero is written first, so the two are never on together even briefly.
  auto first = o.rpwm > 0.0 ? lpwm_.set_duty(o.lpwm) : rpwm_.set_duty(o.rpwm);
  auto second = o.rpwm > 0.0 ? rpwm_.set_duty(o.rpwm) : lpwm_.set_duty(o.lpwm);
  if (!first || !second) {
    const Error e = !first ? first.error() : second.error();
    (void)disable(now_s);
    return e;
  }
  return true;
}

Result<bool> PwmHBridge::disable(double now_s) {
  bridge_.disable(now_s);
  auto r = rpwm_.disable();
  auto l = lpwm_.disable();
  if (!r) return r;
  return l;
}

}  // namespace azt::linux_os
