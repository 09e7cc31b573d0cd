#pragma once
// The OMM syntaxes read with a library: XML (pugixml) and JSON (nlohmann-json). They collect
// keywords into the core's OmmRecords (azt/orbit/omm_record.hpp) like the KVN and CSV readers.

#include <string_view>

#include "azt/orbit/omm_record.hpp"

namespace azt::app {

orbit::OmmRecords read_omm_xml(std::string_view text);
orbit::OmmRecords read_omm_json(std::string_view text);

}  // namespace azt::app
