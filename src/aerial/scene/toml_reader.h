#pragma once
// Typed reads out of a parsed TOML document for the scene file, in the manner of the atmosphere
// config (atmosphere/config.cpp): every failure throws aerial::Error naming the dotted key
// ("mesh[1].scale"), the value as written and what was expected, at "file:line:column".
#include <toml++/toml.h>

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace aerial {

class TomlReader {
 public:
  explicit TomlReader(std::string where) : where_(std::move(where)) {}

  // Parses text, turning a syntax error into an Error at its line and column.
  toml::table Parse(std::string_view text) const;

  // "file:line:column" of a node.
  std::string At(const toml::node& node) const;
  const std::string& where() const { return where_; }

  [[noreturn]] void Fail(const toml::node& node, const std::string& field,
                         const std::string& allowed) const;

  // Rejects any key of table not in known (usually a typo), listing the known ones.
  void RejectUnknownKeys(const toml::table& table, const std::string& prefix,
                         std::initializer_list<std::string_view> known) const;

  const toml::table& Table(const toml::node& node, const std::string& field) const;
  std::string String(const toml::node& node, const std::string& field) const;
  bool Bool(const toml::node& node, const std::string& field) const;
  // Integers are accepted too: "fov_deg = 50" means 50.0.
  double Number(const toml::node& node, const std::string& field, const std::string& unit) const;
  // An array of min_size to max_size numbers.
  std::vector<double> Numbers(const toml::node& node, const std::string& field, size_t min_size,
                              size_t max_size, const std::string& unit) const;

  static std::string Join(const std::string& prefix, std::string_view key);
  static std::string Index(const std::string& field, size_t i);

 private:
  std::string where_;
};

// The value as the user wrote it, for messages.
std::string TomlNodeText(const toml::node& node);

}  // namespace aerial
