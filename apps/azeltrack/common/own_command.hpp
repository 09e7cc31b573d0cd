#pragma once
// How to name this program in a hint the operator copies: a hint must work as
// printed, from any directory, whether azeltrack was installed or built in a checkout.

#include <string>

namespace azt::app {

/// The running binary's absolute path (/proc/self/exe), or "azeltrack" when it cannot be read.
std::string own_command();

/// `own_command() web password --config ABSOLUTE_PATH`: the command that sets the console's
/// password for the configuration at `config_path`.
std::string password_command(const std::string& config_path);

}  // namespace azt::app
