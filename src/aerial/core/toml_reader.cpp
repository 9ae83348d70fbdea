#include "aerial/core/toml_reader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "aerial/core/bounded_file.h"
#include "aerial/core/input_limits.h"
#include "aerial/core/toml_depth.h"
#include "aerial/error.h"

namespace aerial {

std::string TomlFloat(double value) {
  char buffer[512];
  double magnitude = std::fabs(value);
  auto format = (magnitude == 0.0 || (magnitude >= 1e-3 && magnitude < 1e16))
                    ? std::chars_format::fixed
                    : std::chars_format::general;
  std::string text(buffer, std::to_chars(buffer, buffer + sizeof buffer, value, format).ptr);
  if (text.find_first_of(".ein") == std::string::npos) text += ".0";
  return text;
}

std::string TomlString(std::string_view text) {
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') {
      quoted += '\\';
      quoted += c;
    } else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\u%04x", c);
      quoted += escape;
    } else {
      quoted += c;
    }
  }
  return quoted + "\"";
}

std::string ReadTomlFile(const std::filesystem::path& path, const std::string& field) {
  std::vector<unsigned char> bytes = ReadBoundedFile(path, field, kMaxTomlFileBytes);
  return std::string(bytes.begin(), bytes.end());
}

toml::table TomlReader::Parse(std::string_view text) const {
  CheckTomlDepth(text, where_);
  try {
    return toml::parse(text, where_);
  } catch (const toml::parse_error& e) {
    throw Error("TOML syntax", std::string(e.description()), "TOML v1.0 (https://toml.io)",
                At(e.source().begin));
  }
}

std::string TomlReader::At(const toml::source_position& position) const {
  return where_ + ":" + std::to_string(position.line) + ":" + std::to_string(position.column);
}

std::string TomlReader::At(const toml::node& node) const { return At(node.source().begin); }

std::string TomlReader::WhereOf(const std::string& field) const {
  auto it = positions_.find(field);
  return it == positions_.end() ? where_ : At(it->second);
}

void TomlReader::Remember(const toml::node& node, const std::string& field) {
  positions_[field] = node.source().begin;
}

std::string TomlReader::NodeText(const toml::node& node) const {
  if (auto* v = node.as_string()) return TomlString(v->get());
  if (auto* v = node.as_integer()) return std::to_string(v->get());
  if (auto* v = node.as_floating_point()) return format_number_(v->get());
  if (auto* v = node.as_boolean()) return v->get() ? "true" : "false";
  if (auto* array = node.as_array()) {
    std::string text = "[";
    for (size_t i = 0; i < array->size(); ++i) text += (i ? ", " : "") + NodeText(*array->get(i));
    return text + "]";
  }
  if (node.is_table()) return "(a table)";
  return "(a date or time)";
}

void TomlReader::Fail(const toml::node& node, const std::string& field,
                      const std::string& allowed) const {
  throw Error(field, NodeText(node), allowed, At(node));
}

void TomlReader::RejectUnknownKeys(const toml::table& table, const std::string& prefix,
                                   std::initializer_list<std::string_view> known) const {
  for (auto&& [key, node] : table) {
    if (std::find(known.begin(), known.end(), key.str()) != known.end()) continue;
    std::string allowed = "a known key; ";
    allowed += prefix.empty() ? "top-level keys are" : "keys in " + prefix + " are";
    for (size_t i = 0; i < known.size(); ++i)
      allowed += (i ? ", " : " ") + std::string(known.begin()[i]);
    throw Error(Join(prefix, key.str()), NodeText(node), allowed, At(key.source().begin));
  }
}

const toml::table& TomlReader::Table(const toml::node& node, const std::string& field,
                                     const std::string& allowed) {
  Remember(node, field);
  if (!node.is_table()) Fail(node, field, allowed.empty() ? "a table ([" + field + "])" : allowed);
  return *node.as_table();
}

std::string TomlReader::String(const toml::node& node, const std::string& field) {
  Remember(node, field);
  if (!node.is_string()) Fail(node, field, "a string");
  return node.as_string()->get();
}

bool TomlReader::Bool(const toml::node& node, const std::string& field) {
  Remember(node, field);
  if (!node.is_boolean()) Fail(node, field, "true or false");
  return node.as_boolean()->get();
}

double TomlReader::Number(const toml::node& node, const std::string& field,
                          const std::string& unit) {
  Remember(node, field);
  if (auto* v = node.as_floating_point()) return v->get();
  if (auto* v = node.as_integer()) return static_cast<double>(v->get());
  Fail(node, field, "a number" + (unit.empty() ? "" : " (" + unit + ")"));
}

std::vector<double> TomlReader::Numbers(const toml::node& node, const std::string& field,
                                        size_t min_size, size_t max_size, const std::string& unit) {
  Remember(node, field);
  std::string count = min_size == max_size
                          ? std::to_string(min_size)
                          : std::to_string(min_size) + " or " + std::to_string(max_size);
  const toml::array* array = node.as_array();
  if (!array || array->size() < min_size || array->size() > max_size)
    Fail(node, field, "an array of " + count + " numbers (" + unit + ")");
  std::vector<double> values;
  for (size_t i = 0; i < array->size(); ++i)
    values.push_back(Number(*array->get(i), Index(field, i), unit));
  return values;
}

std::string TomlReader::Join(const std::string& prefix, std::string_view key) {
  return prefix.empty() ? std::string(key) : prefix + "." + std::string(key);
}

std::string TomlReader::Index(const std::string& field, size_t i) {
  return field + "[" + std::to_string(i) + "]";
}

}  // namespace aerial
