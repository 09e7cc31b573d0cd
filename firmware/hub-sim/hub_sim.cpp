// hub-sim: the EncoderHub firmware on a simulated ATmega328P (docs/encoder-hub.md). Loads the ELF,
// fits the jumpers for the encoders asked for, puts encoder models on the SSI pins and writes the
// bytes the firmware's USART sends to stdout, or to a pseudo-terminal linked at --pty (paced in
// real time there, as a hub on a serial port is).
//
//   hub-sim --elf build/firmware/encoder-hub.elf --az-bits 12 --az-raw 1024 --el-bits 12
//           --el-raw 512 --seconds 1 | azeltrack hub decode
#include <fcntl.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <thread>

#include "azt/avr/avr_hub.hpp"

namespace {

using azt::avr::EncoderFault;
using azt::avr::EncoderModelKind;

struct Options {
  std::string elf;
  unsigned az_bits = 12;
  unsigned el_bits = 12;
  unsigned az_raw = 0;
  unsigned el_raw = 0;
  std::string az_code = "as5045";
  std::string el_code = "as5045";
  std::string fault = "none";
  std::string fault_axis = "az";
  unsigned baud = 38400;
  double seconds = 1.0;
  std::string pty;
};

EncoderModelKind kind_of(const std::string& code) {
  if (code == "binary") return EncoderModelKind::SsiBinary;
  if (code == "gray") return EncoderModelKind::SsiGray;
  return EncoderModelKind::As5045;
}

EncoderFault fault_of(const std::string& fault) {
  if (fault == "stuck") return EncoderFault::Stuck;
  if (fault == "open") return EncoderFault::Open;
  if (fault == "flip") return EncoderFault::Flip;
  if (fault == "glitch") return EncoderFault::Glitch;
  return EncoderFault::None;
}

/// A pseudo-terminal in raw mode, its slave linked at `link`; returns the master (or −1).
int open_pty(const std::string& link) {
  int master = -1;
  int slave = -1;
  if (::openpty(&master, &slave, nullptr, nullptr, nullptr) != 0) return -1;
  termios t{};
  ::tcgetattr(slave, &t);
  ::cfmakeraw(&t);
  ::tcsetattr(slave, TCSANOW, &t);
  std::error_code ec;
  std::filesystem::remove(link, ec);
  std::filesystem::create_symlink(::ptsname(master), link, ec);
  if (ec) {
    std::cerr << "hub-sim: --pty " << link << ": " << ec.message() << '\n';
    return -1;
  }
  return master;  // the slave stays open so that writes do not fail while no reader is there
}

int run(const Options& o) {
  azt::avr::AvrHubSetup setup;
  setup.elf_path = o.elf;
  setup.az = {kind_of(o.az_code), static_cast<std::uint8_t>(o.az_bits)};
  setup.el = {kind_of(o.el_code), static_cast<std::uint8_t>(o.el_bits)};
  setup.baud = o.baud;
  auto hub = azt::avr::AvrHub::load(setup);
  if (!hub) {
    std::cerr << "hub-sim: " << hub.error().message << '\n';
    return 2;
  }
  auto& h = *hub.value();
  h.set_counts(static_cast<std::uint16_t>(o.az_raw), static_cast<std::uint16_t>(o.el_raw));
  h.set_fault(o.fault_axis == "az", fault_of(o.fault));
  const int out = o.pty.empty() ? STDOUT_FILENO : open_pty(o.pty);
  if (out < 0) return 1;
  // A byte the reader is not there to take is dropped, as on a serial line with nobody listening.
  h.on_byte = [out](std::uint8_t byte, double /*at_us*/) {
    if (::write(out, &byte, 1) != 1) return;
  };
  const auto start = std::chrono::steady_clock::now();
  constexpr double kSliceS = 0.01;
  for (double t = 0.0; o.seconds <= 0.0 || t < o.seconds; t += kSliceS) {
    h.run_for(kSliceS);
    if (!o.pty.empty()) {
      std::this_thread::sleep_until(start + std::chrono::duration<double>(t + kSliceS));
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The EncoderHub firmware on a simulated ATmega328P: its frames to stdout or a pty"};
  Options o;
  app.add_option("--elf", o.elf, "the firmware (build/firmware/encoder-hub.elf)")->required();
  app.add_option("--az-bits", o.az_bits, "azimuth encoder resolution, 9-16 (as5045: 12)")
      ->check(CLI::Range(9, 16));
  app.add_option("--el-bits", o.el_bits, "elevation encoder resolution, 9-16")
      ->check(CLI::Range(9, 16));
  app.add_option("--az-raw", o.az_raw, "azimuth count the encoder reports")->required();
  app.add_option("--el-raw", o.el_raw, "elevation count")->required();
  app.add_option("--az-code", o.az_code, "as5045, binary or gray (generic SSI)")
      ->check(CLI::IsMember({"as5045", "binary", "gray"}));
  app.add_option("--el-code", o.el_code, "as5045, binary or gray")
      ->check(CLI::IsMember({"as5045", "binary", "gray"}));
  app.add_option("--fault", o.fault, "none, stuck, open, flip or glitch")
      ->check(CLI::IsMember({"none", "stuck", "open", "flip", "glitch"}));
  app.add_option("--fault-axis", o.fault_axis, "az or el")->check(CLI::IsMember({"az", "el"}));
  app.add_option("--baud", o.baud, "the BAUD jumpers' rate")
      ->check(CLI::IsMember({9600U, 38400U, 115200U}));
  app.add_option("--seconds", o.seconds, "simulated time to run (0: for ever)");
  app.add_option("--pty", o.pty, "link a pseudo-terminal here and write to it in real time");
  CLI11_PARSE(app, argc, argv);
  if (o.az_code == "as5045") o.az_bits = 12;
  if (o.el_code == "as5045") o.el_bits = 12;
  const unsigned az_limit = 1U << o.az_bits;
  const unsigned el_limit = 1U << o.el_bits;
  if (o.az_raw >= az_limit || o.el_raw >= el_limit) {
    std::cerr << "hub-sim: a raw count must be below 2^bits\n";
    return 2;
  }
  return run(o);
}
