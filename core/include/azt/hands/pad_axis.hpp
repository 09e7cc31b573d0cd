#pragma once
// A game pad's or joystick's stick as a deflection: Linux reports an absolute axis as a value
// between the minimum and maximum of its `input_absinfo`, with a `flat` zone around the centre
// that the driver calls rest (linux/input.h; libevdev_get_abs_info). Pure, so recorded event
// streams and every pad's range are tested without a device.

namespace azt::hands {

/// One absolute axis's range as the kernel reports it.
struct PadAxisRange {
  int minimum = -32768;
  int maximum = 32767;
  int flat = 0;  ///< the driver's rest zone around the centre, in the axis's units
};

/// The deflection of `value` from the centre of `range`, −1…+1 (+1 at the maximum). Inside the
/// larger of the driver's flat zone and the operator's `dead_zone` (a fraction of the half
/// range) it is 0; beyond it the rest is rescaled, so a deflection starts from 0 at the zone's
/// edge instead of jumping to the zone's width. A range with no width gives 0.
double pad_deflection(int value, const PadAxisRange& range, double dead_zone);

}  // namespace azt::hands
