#include "aerial/scene/toml_reader.h"

#include <algorithm>

#include "aerial/core/error.h"
#include "aerial/scene/scene_limits.h"

namespace aerial {

std::string TomlNodeText(const toml::node& node) {
  if (auto* v = node.as_string()) return "\"" + v->get() + "\"";
  if (auto* v = node.as_integer()) return std::to_string(v->get());
  if (auto* v = node.as_floating_point()) return FormatNumber(v->get());
  if (auto* v = node.as_boolean()) return v->get() ? "true" : "false";
  if (auto* array = node.as_array()) {
    std::string text = "[";
    for (size_t i = 0; i < array->size(); ++i)
      text += (i ? ", " : "") + TomlNodeText(*array->get(i));
    return text + "]";
  }
  if (node.is_table()) return "(a table)";
  return "(a date or time)";
}

toml::table TomlReader::Parse(std::string_view text) const {
  try {
    return toml::parse(text, where_);
  } catch (const toml::parse_error& e) {
    const auto& begin = e.source().begin;
    throw Error("TOML syntax", std::string(e.description()), "TOML v1.0 (https://toml.io)",
                where_ + ":" + std::to_string(begin.line) + ":" + std::to_string(begin.column));
  }
}

std::string TomlReader::At(const toml::node& node) const {
  const toml::source_position& begin = node.source().begin;
  return where_ + ":" + std::to_string(begin.line) + ":" + std::to_string(begin.column);
}

void TomlReader::Fail(const toml::node& node, const std::string& field,
                      const std::string& allowed) const {
  throw Error(field, TomlNodeText(node), allowed, At(node));
}

void TomlReader::RejectUnknownKeys(const toml::table& table, const std::string& prefix,
                                   std::initializer_list<std::string_view> known) const {
  for (auto&& [key, node] : table) {
    if (std::find(known.begin(), known.end(), key.str()) != known.end()) continue;
    std::string allowed = "a known key; ";
    allowed += prefix.empty() ? "top-level keys are" : "keys in " + prefix + " are";
    for (size_t i = 0; i < known.size(); ++i)
      allowed += (i ? ", " : " ") + std::string(known.begin()[i]);
    const toml::source_position& begin = key.source().begin;
    throw Error(Join(prefix, key.str()), TomlNodeText(node), allowed,
                where_ + ":" + std::to_string(begin.line) + ":" + std::to_string(begin.column));
  }
}

const toml::table& TomlReader::Table(const toml::node& node, const std::string& field) const {
  if (!node.is_table()) Fail(node, field, "a table ([" + field + "])");
  return *node.as_table();
}

std::string TomlReader::String(const toml::node& node, const std::string& field) const {
  if (!node.is_string()) Fail(node, field, "a string");
  return node.as_string()->get();
}

bool TomlReader::Bool(const toml::node& node, const std::string& field) const {
  if (!node.is_boolean()) Fail(node, field, "true or false");
  return node.as_boolean()->get();
}

double TomlReader::Number(const toml::node& node, const std::string& field,
                          const std::string& unit) const {
  if (auto* v = node.as_floating_point()) return v->get();
  if (auto* v = node.as_integer()) return static_cast<double>(v->get());
  Fail(node, field, "a number" + (unit.empty() ? "" : " (" + unit + ")"));
}

std::vector<double> TomlReader::Numbers(const toml::node& node, const std::string& field,
                                        size_t min_size, size_t max_size,
                                        const std::string& unit) const {
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
