#include "azt/linux/gpsd_client.hpp"

#include <gps.h>

#include <cmath>
#include <istream>
#include <optional>
#include <utility>

namespace azt::linux_os {
namespace {

namespace asio = boost::asio;

/// gpsd's longest reports (a SKY with every constellation's satellites) are a few KB.
constexpr std::size_t kMaxLineBytes = std::size_t{64} * 1024;
constexpr const char* kWatch = "?WATCH={\"enable\":true,\"json\":true}\n";

std::optional<double> finite(double v) {
  return std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

gnss::FixMode fix_mode(int mode) {
  if (mode == MODE_3D) return gnss::FixMode::Fix3d;
  if (mode == MODE_2D) return gnss::FixMode::Fix2d;
  return gnss::FixMode::None;
}

gnss::GpsFix to_fix(const gps_data_t& d) {
  gnss::GpsFix fix;
  fix.mode = fix_mode(d.fix.mode);
  const bool placed = std::isfinite(d.fix.latitude) && std::isfinite(d.fix.longitude);
  if (!placed) fix.mode = gnss::FixMode::None;  // a fix without a place is no fix
  if (placed) {
    fix.lat_deg = d.fix.latitude;
    fix.lon_deg = d.fix.longitude;
  }
  if (fix.mode == gnss::FixMode::Fix3d) fix.alt_m = finite(d.fix.altMSL);
  if ((d.set & TIME_SET) != 0 && d.fix.time.tv_sec > 0) {
    fix.time_unix_s =
        static_cast<double>(d.fix.time.tv_sec) + static_cast<double>(d.fix.time.tv_nsec) * 1e-9;
  }
  return fix;
}

gnss::GpsSky to_sky(const gps_data_t& d) {
  gnss::GpsSky sky;
  sky.sats_used = d.satellites_used;
  sky.sats_visible = d.satellites_visible;
  sky.hdop = finite(d.dop.hdop);
  const int n = std::min(d.satellites_visible, MAXCHANNELS);
  for (int i = 0; i < n; ++i) {
    const satellite_t& s = d.skyview[i];
    sky.satellites.push_back(gnss::GpsSatellite{
        s.PRN, std::isfinite(s.elevation) ? s.elevation : 0.0,
        std::isfinite(s.azimuth) ? s.azimuth : 0.0, std::isfinite(s.ss) ? s.ss : 0.0, s.used});
  }
  return sky;
}

}  // namespace

struct GpsdClient::Impl {
  gps_data_t data{};
};

GpsdClient::GpsdClient(asio::io_context& io, GpsdClientConfig config, GpsdEvents events)
    : resolver_(io),
      socket_(io),
      retry_timer_(io),
      in_(kMaxLineBytes),
      config_(std::move(config)),
      events_(std::move(events)),
      impl_(std::make_unique<Impl>()) {
  connect();
}

GpsdClient::~GpsdClient() {
  *alive_ = false;
  boost::system::error_code ignored;
  socket_.close(ignored);
}

std::string GpsdClient::describe() const { return "gpsd at " + config_.host + ":" + config_.port; }

void GpsdClient::connect() {
  resolver_.async_resolve(
      config_.host, config_.port,
      [this, alive = alive_](const boost::system::error_code& ec,
                             const asio::ip::tcp::resolver::results_type& endpoints) {
        if (!*alive) return;
        if (ec) return lost("cannot resolve " + config_.host + ": " + ec.message());
        asio::async_connect(socket_, endpoints,
                            [this, alive](const boost::system::error_code& e,
                                          const asio::ip::tcp::endpoint& /*endpoint*/) {
                              if (!*alive) return;
                              if (e) return lost(describe() + ": " + e.message());
                              connected_ = true;
                              down_reported_ = false;
                              impl_->data = gps_data_t{};
                              asio::async_write(
                                  socket_, asio::buffer(std::string_view(kWatch)),
                                  [](const boost::system::error_code&, std::size_t) {});
                              if (events_.connected) events_.connected();
                              read();
                            });
      });
}

void GpsdClient::read() {
  asio::async_read_until(
      socket_, in_, '\n',
      [this, alive = alive_](const boost::system::error_code& ec, std::size_t n) {
        if (!*alive) return;
        if (ec == asio::error::not_found) {
          // A line longer than any report gpsd sends: not gpsd, or broken. Start afresh.
          ++rejected_;
          return lost(describe() + ": a line longer than " + std::to_string(kMaxLineBytes) +
                      " bytes");
        }
        if (ec) return lost(describe() + ": " + ec.message());
        std::string line(n, '\0');
        std::istream(&in_).read(line.data(), static_cast<std::streamsize>(n));
        on_line(line);
        read();
      });
}

void GpsdClient::on_line(const std::string& line) {
  gps_data_t& d = impl_->data;
  if (line.empty() || line.front() != '{') {
    ++rejected_;
    return;
  }
  d.set = 0;
  std::string text = line;  // gps_unpack wants a writable, NUL-terminated buffer
  if (gps_unpack(text.data(), &d) != 0 || d.set == 0) {
    ++rejected_;
    return;
  }
  if ((d.set & SATELLITE_SET) != 0) {
    if (events_.sky) events_.sky(to_sky(d));
  } else if ((d.set & MODE_SET) != 0) {
    if (events_.fix) events_.fix(to_fix(d));
  }
  // VERSION, DEVICES, WATCH and the rest: nothing the station needs.
}

void GpsdClient::lost(const std::string& why) {
  boost::system::error_code ignored;
  socket_.close(ignored);
  in_.consume(in_.size());
  // Said once per loss: a gpsd that is not running is not news every retry.
  const bool was = std::exchange(connected_, false);
  if (events_.disconnected && (was || !down_reported_)) events_.disconnected(why);
  down_reported_ = true;
  retry_timer_.expires_after(std::chrono::duration_cast<asio::steady_timer::duration>(
      std::chrono::duration<double>(config_.retry_s)));
  retry_timer_.async_wait([this, alive = alive_](const boost::system::error_code& ec) {
    if (!ec && *alive) connect();
  });
}

}  // namespace azt::linux_os
