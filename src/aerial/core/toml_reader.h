#pragma once
// Typed reads out of a parsed TOML document, shared by the atmosphere config
// (atmosphere/config.h) and the scene file (scene/scene_file.h). Every failure throws
// aerial::Error naming the dotted key ("mie.density[0].exp_term", "mesh[1].scale"), the value as
// written and what was expected, with "file:line:column" as where.
//
//   TomlReader r(path.string());
//   toml::table root = r.Parse(ReadTomlFile(path, "scene file"));
//   r.RejectUnknownKeys(root, "", {"camera"});
//   IfPresent(root, "camera", [&](const toml::node& n) {
//     const toml::table& camera = r.Table(n, "camera");
//     ...
//   });
//
// The reader remembers where each field it read was written (WhereOf), so a range error found
// later, on the finished values, can still point at its line.
#include <toml++/toml.h>

#include <filesystem>
#include <initializer_list>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace aerial {

// Shortest text that reads back as the same double, as a TOML float: fixed notation for ordinary
// magnitudes ("6360000.0", not "6.36e+06"), and ".0" added to integral values (TOML reads
// "6360000" as an integer).
std::string TomlFloat(double value);

// A TOML basic string: quotes, backslashes and control characters escaped.
std::string TomlString(std::string_view text);

// The whole file as text, read by ReadBoundedFile (bounded_file.h) with the cap
// kMaxTomlFileBytes: a missing, unreadable, oversized or non-regular file throws
// Error(field, path, ...); field names the input ("scene file").
std::string ReadTomlFile(const std::filesystem::path& path, const std::string& field);

// Applies one optional key: calls read(node) if table has the key.
template <typename F>
void IfPresent(const toml::table& table, std::string_view key, F read) {
  if (const toml::node* node = table.get(key)) read(*node);
}

class TomlReader {
 public:
  // How a float is shown in messages (TomlFloat by default).
  using NumberFormat = std::string (*)(double);

  // where names the source in messages (usually the path).
  explicit TomlReader(std::string where, NumberFormat format_number = TomlFloat)
      : where_(std::move(where)), format_number_(format_number) {}

  // Parses text, turning a syntax error into an Error at its line and column.
  toml::table Parse(std::string_view text) const;

  const std::string& where() const { return where_; }
  // "file:line:column" of a node.
  std::string At(const toml::node& node) const;
  // "file:line:column" of a field read by the calls below, or just where() for a field never read
  // (a default value).
  std::string WhereOf(const std::string& field) const;

  // The value as the user wrote it, for messages.
  std::string NodeText(const toml::node& node) const;

  // Throws Error(field, NodeText(node), allowed, At(node)).
  [[noreturn]] void Fail(const toml::node& node, const std::string& field,
                         const std::string& allowed) const;

  // Rejects any key of table not in known (usually a typo), listing the known ones. prefix is the
  // table's dotted field, "" for the top level.
  void RejectUnknownKeys(const toml::table& table, const std::string& prefix,
                         std::initializer_list<std::string_view> known) const;

  // Typed reads: each remembers where field was written (WhereOf) and fails unless node has the
  // type. allowed defaults to "a table ([<field>])".
  const toml::table& Table(const toml::node& node, const std::string& field,
                           const std::string& allowed = "");
  std::string String(const toml::node& node, const std::string& field);
  bool Bool(const toml::node& node, const std::string& field);
  // Integers are accepted too: "bottom_radius_m = 6360000" means 6360000.0. unit goes into the
  // message ("a number (m)"); it may be empty.
  double Number(const toml::node& node, const std::string& field, const std::string& unit);
  // An array of min_size to max_size numbers, element i read as Index(field, i).
  std::vector<double> Numbers(const toml::node& node, const std::string& field, size_t min_size,
                              size_t max_size, const std::string& unit);

  // Dotted field names: Join("mie", "phase_g") is "mie.phase_g" (just the key for an empty
  // prefix), Index("mesh", 1) is "mesh[1]".
  static std::string Join(const std::string& prefix, std::string_view key);
  static std::string Index(const std::string& field, size_t i);

 private:
  std::string At(const toml::source_position& position) const;
  void Remember(const toml::node& node, const std::string& field);

  std::string where_;
  NumberFormat format_number_;
  std::map<std::string, toml::source_position> positions_;
};

}  // namespace aerial
