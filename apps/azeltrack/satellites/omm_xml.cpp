// OMM in CCSDS NDM/XML (502.0-B-3 and the NDM/XML schema): `<ndm>` holding one `<omm>` per object
// (CelesTrak's FORMAT=xml), or a lone `<omm>`. The keywords are the leaf elements of
// body/segment/metadata, data/meanElements and data/tleParameters. pugixml does the XML; it does
// not throw and records each node's offset, which gives the line numbers.

#include <pugixml.hpp>

#include <cstddef>
#include <string>
#include <string_view>

#include "satellites/omm_library_readers.hpp"

namespace azt::app {

namespace {

/// The element's name without a namespace prefix ("ndm:omm" → "omm").
std::string_view local_name(const pugi::xml_node& node) {
  const std::string_view name = node.name();
  const std::size_t colon = name.find(':');
  return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

pugi::xml_node child_named(const pugi::xml_node& parent, std::string_view name) {
  for (const pugi::xml_node& child : parent.children()) {
    if (child.type() == pugi::node_element && local_name(child) == name) return child;
  }
  return {};
}

int line_of(const pugi::xml_node& node, const orbit::LineIndex& lines) {
  const std::ptrdiff_t offset = node.offset_debug();
  return offset < 0 ? 0 : lines.line_at(static_cast<std::size_t>(offset));
}

/// Every leaf element of `group` as a keyword (COMMENT elements are remarks, not values).
void collect(const pugi::xml_node& group, const orbit::LineIndex& lines, orbit::OmmRecord& record) {
  for (const pugi::xml_node& leaf : group.children()) {
    if (leaf.type() != pugi::node_element || local_name(leaf) == "COMMENT") continue;
    orbit::add_field(record, local_name(leaf), leaf.text().get(), line_of(leaf, lines));
  }
}

orbit::OmmRecord read_omm(const pugi::xml_node& omm, const orbit::LineIndex& lines) {
  orbit::OmmRecord record;
  record.line = line_of(omm, lines);
  record.theory_required = true;
  const pugi::xml_node segment = child_named(child_named(omm, "body"), "segment");
  if (!segment) {
    record.problem = "line " + std::to_string(record.line) + ": no <body><segment> in this <omm>";
    return record;
  }
  const pugi::xml_node data = child_named(segment, "data");
  collect(child_named(segment, "metadata"), lines, record);
  collect(child_named(data, "meanElements"), lines, record);
  collect(child_named(data, "tleParameters"), lines, record);
  return record;
}

}  // namespace

orbit::OmmRecords read_omm_xml(std::string_view text) {
  orbit::OmmRecords out;
  const orbit::LineIndex lines(text);
  pugi::xml_document document;
  const pugi::xml_parse_result parsed =
      document.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_utf8);
  if (!parsed) {
    const auto offset = static_cast<std::size_t>(parsed.offset < 0 ? 0 : parsed.offset);
    out.errors.push_back("line " + std::to_string(lines.line_at(offset)) +
                         ": not well-formed XML: " + parsed.description());
    return out;
  }
  const pugi::xml_node root = document.document_element();
  if (local_name(root) == "omm") {
    out.records.push_back(read_omm(root, lines));
  } else if (local_name(root) == "ndm") {
    for (const pugi::xml_node& child : root.children()) {
      if (child.type() == pugi::node_element && local_name(child) == "omm") {
        out.records.push_back(read_omm(child, lines));
      }
    }
  } else {
    constexpr std::size_t kShown = 40;
    out.errors.push_back("line " + std::to_string(line_of(root, lines)) + ": <" +
                         std::string(local_name(root).substr(0, kShown)) +
                         "> is neither <ndm> nor <omm>");
  }
  return out;
}

}  // namespace azt::app
