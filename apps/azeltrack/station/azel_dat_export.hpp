#pragma once
// azel.dat for WSJT-X's neighbours (docs/eme.md, [export] azel_dat): once a second the Moon, the
// Sun, the tracked radio source and the echo Doppler at the station's band, in WSJT-X's format
// (eme/azel_dat.hpp). Computed on the loop (a sky snapshot is well under a millisecond), written
// off it (publish_file: renamed into place, never torn, no fsync a second). Elevations are
// refracted (where the antenna points), where WSJT-X's are airless.

#include <functional>
#include <optional>
#include <string>

#include "azt/astro/ephemeris.hpp"
#include "azt/astro/sky_snapshot.hpp"
#include "azt/astro/target.hpp"
#include "azt/eme/azel_dat.hpp"
#include "azt/linux/asio.hpp"
#include "common/off_loop.hpp"
#include "config/sky_config.hpp"

namespace azt::app {

struct AzelDatParts {
  std::string path;
  const astro::Ephemeris& ephemeris;
  const SkyConfig& sky;  ///< the running station: place, DX, frequency
  std::function<double()> unix_s;
  /// The radio source (or RA/Dec) being tracked, for the Source line; none otherwise.
  std::function<std::optional<astro::Target>()> source;
  std::function<bool()> transmitting;
  Offload offload;
  /// Writes the text to `path` (linux_os::publish_file in the daemon), on the worker.
  std::function<Result<bool>(const std::string& path, const std::string& text)> write;
  std::function<void(const std::string&)> log;
  /// WSJT-X's optional fifth line (Dpol, MNR, Dgrd, the echo widths), as its AzElExtraLines.
  bool pol_line = false;
};

class AzelDatExport {
 public:
  /// Writes at once, then every second.
  AzelDatExport(boost::asio::io_context& io, AzelDatParts parts);

  /// The file's text at `unix_s`; the Doppler rates are from the previous call's values (0 on
  /// the first, as WSJT-X). None outside the ephemeris.
  std::optional<std::string> text_at(double unix_s);
  /// Computes and writes now (skipped while the previous write is still under way).
  void write_now();

 private:
  void arm();
  eme::AzelDat::PolLine pol_line(const astro::TargetReport& moon,
                                 const astro::SkySnapshot& sky) const;

  AzelDatParts p_;
  boost::asio::steady_timer timer_;
  std::optional<double> last_unix_s_;
  double last_self_hz_ = 0.0;
  double last_dx_hz_ = 0.0;
  bool writing_ = false;
  std::string last_error_;  ///< logged once until a write succeeds
};

}  // namespace azt::app
