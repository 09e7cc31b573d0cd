#pragma once
// What may name an API token ([[token]] label): the console lists and revokes tokens by it, and
// it travels in an address (DELETE /api/tokens/LABEL), so it is short and plain.

#include <optional>
#include <string>

namespace azt::app {

/// Why `label` cannot name an API token, or nothing.
std::optional<std::string> token_label_problem(const std::string& label);

}  // namespace azt::app
