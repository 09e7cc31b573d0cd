#include "azt/linux/step_dir_drive.hpp"

#include <utility>

namespace azt::linux_os {
namespace {

class StepDirDrive final : public ports::AxisDrive {
 public:
  StepDirDrive(SysfsPwm step, std::unique_ptr<GpioOutput> dir, std::unique_ptr<GpioOutput> enable,
               const control::StepDirConfig& config, std::string what)
      : step_(std::move(step)),
        dir_(std::move(dir)),
        enable_(std::move(enable)),
        steps_(config),
        what_(std::move(what)) {}
  ~StepDirDrive() override {
    off(0.0);
    (void)step_.disable();
  }
  StepDirDrive(const StepDirDrive&) = delete;
  StepDirDrive& operator=(const StepDirDrive&) = delete;
  StepDirDrive(StepDirDrive&&) = delete;
  StepDirDrive& operator=(StepDirDrive&&) = delete;

  Result<bool> apply(double now_s, double duty, std::optional<double> /*setpoint*/) override {
    auto written = write(steps_.drive(now_s, duty));
    if (!written) off(now_s);
    return written;
  }
  void off(double now_s) override {
    (void)steps_.disable(now_s);
    (void)step_.set_duty(0.0);
    if (enable_) (void)enable_->set(false);
  }
  [[nodiscard]] std::string describe() const override { return what_; }

 private:
  Result<bool> write(const control::StepDirOutputs& o) {
    // StepDir turns DIR only in a tick without pulses, after one without pulses: stopping the
    // pulses first and setting DIR before starting them keeps every edge in the right way.
    if (o.step_hz == 0.0) {
      if (auto r = step_.set_duty(0.0); !r) return r;
    }
    if (enable_ && enable_->active() != o.enable) {
      if (auto r = enable_->set(o.enable); !r) return r;
    }
    if (o.direction != 0 && dir_->active() != (o.direction > 0)) {
      if (auto r = dir_->set(o.direction > 0); !r) return r;
    }
    if (o.step_hz == 0.0) return true;
    return step_.set_rate(o.step_hz, 0.5);
  }

  SysfsPwm step_;
  std::unique_ptr<GpioOutput> dir_;
  std::unique_ptr<GpioOutput> enable_;
  control::StepDir steps_;
  std::string what_;
};

}  // namespace

std::unique_ptr<ports::AxisDrive> make_step_dir_drive(SysfsPwm step,
                                                      std::unique_ptr<GpioOutput> dir,
                                                      std::unique_ptr<GpioOutput> enable,
                                                      const control::StepDirConfig& config,
                                                      std::string what) {
  return std::make_unique<StepDirDrive>(std::move(step), std::move(dir), std::move(enable), config,
                                        std::move(what));
}

}  // namespace azt::linux_os
