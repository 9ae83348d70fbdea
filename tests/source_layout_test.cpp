// The modules of the implementation (the directories of src/aerial/, and froxel/) include each
// other without a cycle (docs/design.md, "Source layout"), so that each builds, tests and reads
// with only the modules below it. A module's own tests (*_test.cpp) are left out: they may use
// the modules above it to set up what they check. And the library's code spells no option of the
// aerial command: its errors name its API's fields, and the command maps them to its options.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace aerial {
namespace {

namespace fs = std::filesystem;

struct ModuleGraph {
  // module -> the modules it includes, each with a file that does.
  std::map<std::string, std::map<std::string, std::string>> includes;
};

// The module an include names: "aerial/<module>/..." for a directory of src/aerial/, or froxel/.
std::optional<std::string> IncludedModule(const std::string& include, const fs::path& source) {
  static const std::regex pattern(R"(^(?:aerial/([a-z_]+)/|(froxel)/))");
  std::smatch match;
  if (!std::regex_search(include, match, pattern)) return std::nullopt;
  if (match[2].matched) return "froxel";
  if (!fs::is_directory(source / "src" / "aerial" / match[1].str())) return std::nullopt;
  return match[1].str();
}

ModuleGraph ReadModuleGraph(const fs::path& source) {
  ModuleGraph graph;
  std::vector<std::pair<std::string, fs::path>> modules = {{"froxel", source / "froxel"}};
  for (const fs::directory_entry& entry : fs::directory_iterator(source / "src" / "aerial"))
    if (entry.is_directory()) modules.emplace_back(entry.path().filename().string(), entry.path());
  static const std::regex include_line(R"re(^\s*#\s*include\s+"([^"]+)")re");
  for (const auto& [module, directory] : modules) {
    graph.includes[module];
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(directory)) {
      const std::string name = entry.path().filename().string();
      if (!entry.is_regular_file() || name.ends_with("_test.cpp") ||
          !(name.ends_with(".h") || name.ends_with(".cpp")))
        continue;
      std::ifstream file(entry.path());
      std::smatch match;
      for (std::string line; std::getline(file, line);) {
        if (!std::regex_search(line, match, include_line)) continue;
        std::optional<std::string> included = IncludedModule(match[1].str(), source);
        if (included && *included != module)
          graph.includes[module].emplace(*included, fs::relative(entry.path(), source).string());
      }
    }
  }
  return graph;
}

// A cycle as "a -> b (a file of a that includes b), b -> ... -> a (...)", or empty.
std::string FindCycle(const ModuleGraph& graph) {
  std::map<std::string, int> state;  // 1: on the current path, 2: done
  std::vector<std::string> path;
  std::string cycle;
  auto visit = [&](auto& self, const std::string& module) -> void {
    state[module] = 1;
    path.push_back(module);
    for (const auto& [next, file] : graph.includes.at(module)) {
      if (!cycle.empty()) break;
      if (state[next] == 1) {
        auto from = std::find(path.begin(), path.end(), next);
        for (auto it = from; it != path.end(); ++it) {
          const std::string& to = it + 1 != path.end() ? *(it + 1) : next;
          cycle += (cycle.empty() ? "" : ", ") + *it + " -> " + to + " (" + graph.includes.at(*it).at(to) + ")";
        }
      } else if (state[next] == 0) {
        self(self, next);
      }
    }
    path.pop_back();
    state[module] = 2;
  };
  for (const auto& [module, unused] : graph.includes)
    if (cycle.empty() && state[module] == 0) visit(visit, module);
  return cycle;
}

TEST(SourceLayout, ModulesIncludeEachOtherWithoutACycle) {
  const ModuleGraph graph = ReadModuleGraph(AERIAL_SOURCE_DIR);
  // The layout is read, not assumed: the renderer includes the froxel volume and the terrain
  // includes the scene.
  ASSERT_TRUE(graph.includes.at("render").contains("froxel"));
  ASSERT_TRUE(graph.includes.at("terrain").contains("scene"));
  EXPECT_EQ(FindCycle(graph), "");
}

// The search itself finds a cycle where there is one.
TEST(SourceLayout, ACycleIsFound) {
  ModuleGraph graph;
  graph.includes["a"] = {{"b", "a.cpp"}};
  graph.includes["b"] = {{"c", "b.cpp"}};
  graph.includes["c"] = {{"a", "c.cpp"}};
  graph.includes["d"] = {{"a", "d.cpp"}};
  EXPECT_EQ(FindCycle(graph), "a -> b (a.cpp), b -> c (b.cpp), c -> a (c.cpp)");
}

// The string literals of C++ source text, in order; comments and character literals are skipped,
// a raw string is read to its own delimiter, and an escape is kept as written.
std::vector<std::string> StringLiterals(const std::string& code) {
  std::vector<std::string> literals;
  for (size_t i = 0; i < code.size(); ++i) {
    if (code.compare(i, 2, "//") == 0) {
      i = code.find('\n', i);
    } else if (code.compare(i, 2, "/*") == 0) {
      const size_t end = code.find("*/", i + 2);
      i = end == std::string::npos ? end : end + 1;
    } else if (code[i] == '\'') {
      for (++i; i < code.size() && code[i] != '\''; ++i) i += code[i] == '\\';
    } else if (code.compare(i, 2, "R\"") == 0) {
      const size_t open = code.find('(', i);
      std::string close(1, ')');  // )delimiter"
      close.append(code, i + 2, open - i - 2).push_back('"');
      const size_t end = code.find(close, open);
      literals.push_back(code.substr(open + 1, end - open - 1));
      i = end + close.size() - 1;
    } else if (code[i] == '"') {
      std::string literal;
      for (++i; i < code.size() && code[i] != '"'; ++i) {
        if (code[i] == '\\') literal += code[i++];
        literal += code[i];
      }
      literals.push_back(literal);
    }
    if (i == std::string::npos) break;
  }
  return literals;
}

TEST(SourceLayout, StringLiteralsAreReadAsTheCompilerReadsThem) {
  const std::string code = "f(\"--a\\\"b\", '\"'); // \"--comment\"\n/* \"--block\" */ g(R\"x(--raw\")x\", \"\");";
  EXPECT_EQ(StringLiterals(code), (std::vector<std::string>{"--a\\\"b", "--raw\"", ""}));
}

// The library's sources: include/aerial/, froxel/ and src/aerial/, less its tests and the parts of
// src/aerial/ that are the command's own: cli/ (its options), bench/ and viewer/ (`aerial bench`
// and `aerial view`, whose messages speak of their command's options).
std::vector<fs::path> LibrarySources(const fs::path& source) {
  std::vector<fs::path> files;
  for (const char* root : {"include/aerial", "froxel", "src/aerial"}) {
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(source / root)) {
      const std::string relative = fs::relative(entry.path(), source).string();
      const std::string name = entry.path().filename().string();
      if (!entry.is_regular_file() || name.ends_with("_test.cpp") || !(name.ends_with(".h") || name.ends_with(".cpp")))
        continue;
      if (relative.starts_with("src/aerial/cli/") || relative.starts_with("src/aerial/bench/") ||
          relative.starts_with("src/aerial/viewer/"))
        continue;
      files.push_back(entry.path());
    }
  }
  return files;
}

// A program that embeds aerial sets RenderOptions::width, not --width: an error that named the
// option would point its user at a command line they do not have.
TEST(SourceLayout, LibraryCodeSpellsNoCommandLineOption) {
  static const std::regex option(R"(^--[a-z])");
  std::vector<fs::path> files = LibrarySources(AERIAL_SOURCE_DIR);
  ASSERT_GT(files.size(), 100u) << "the library's sources are found";
  std::string found;
  for (const fs::path& file : files) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    for (const std::string& literal : StringLiterals(text.str()))
      if (std::regex_search(literal, option)) found += fs::relative(file, AERIAL_SOURCE_DIR).string() + ": \"" + literal + "\"\n";
  }
  EXPECT_EQ(found, "");
}

}  // namespace
}  // namespace aerial
