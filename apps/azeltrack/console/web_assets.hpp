#pragma once
// The console's files (web/), embedded at build time by cmake/embed_web.cmake: no runtime files,
// no CDN, works offline.

#include <cstddef>
#include <string_view>

namespace azt::app {

struct WebAsset {
  std::string_view path;  ///< "/index.html", "/js/main.js", …
  std::string_view content_type;
  std::string_view body;
};

/// nullptr when there is no such file.
const WebAsset* find_web_asset(std::string_view path);
/// The bytes of every embedded file together (the page weight).
std::size_t web_assets_bytes();

}  // namespace azt::app
