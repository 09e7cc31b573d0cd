#pragma once
// What this program is: its version (the Debian package's when built by debian/rules, else the
// CMake project's) and the package's architecture ("" for a source build). One generated file
// (program_version.cpp.in) holds them, so a new version rebuilds one file, not every room.

#include <string_view>

namespace azt::app {

/// "0.1.0", or the package's version ("0.1.0-1", "0.1.0+1").
std::string_view program_version();
/// The Debian architecture the package was built for ("amd64", "arm64"); "" when not a package.
std::string_view package_architecture();

}  // namespace azt::app
