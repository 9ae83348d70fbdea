#include "aerial/scene/gltf_parse_memory.h"

#include <gtest/gtest.h>

#include <string>

#include "aerial/scene/tiny_gltf_config.h"

namespace aerial {
namespace {

std::string Repeated(const std::string& element, int count) {
  std::string list;
  for (int i = 0; i < count; ++i) list += (i ? "," : "") + element;
  return list;
}

// 500,000 empty materials are 1.5 MB of JSON; loading them peaked at 1,197,500 KiB of resident
// memory (/usr/bin/time -v, `aerial render` of a scene holding that model): 2,453 bytes a
// material. The estimate must cover that peak, and not by more than a factor of 4 (it counts the
// vector's growth as allocated, where resident memory counts only the pages touched; a tighter
// bound would tie the test to this tinygltf's struct sizes). Before, each `{}` was 2 values, 400
// bytes in all.
TEST(GltfParseMemory, EmptyMaterialsCountAtTheirRealSize) {
  constexpr int kCount = 500000;
  constexpr double kMeasuredBytes = 2453.0;
  std::string json = R"({"asset": {"version": "2.0"}, "materials": [)" + Repeated("{}", kCount) + "]}";
  const double estimate = double(GltfParseBytes(json, json.size()));
  EXPECT_GE(estimate, kCount * kMeasuredBytes);
  EXPECT_LE(estimate, kCount * kMeasuredBytes * 4);
}

// Each of glTF's arrays, the nested ones included, costs its elements' struct at least once over:
// the same element text in another place (an `extras` array) costs far less.
TEST(GltfParseMemory, EveryGltfArrayCountsItsStructs) {
  const std::string extras = R"({"extras": [)" + Repeated("{}", 1000) + "]}";
  const uint64_t plain = GltfParseBytes(extras, 0);
  auto at_least = [&](const std::string& json, size_t struct_bytes) {
    EXPECT_GE(GltfParseBytes(json, 0), plain + 1000 * struct_bytes) << json.substr(0, 60);
  };
  at_least(R"({"nodes": [)" + Repeated("{}", 1000) + "]}", sizeof(tinygltf::Node));
  at_least(R"({"accessors": [)" + Repeated("{}", 1000) + "]}", sizeof(tinygltf::Accessor));
  at_least(R"({"meshes": [{"primitives": [)" + Repeated("{}", 1000) + "]}]}", sizeof(tinygltf::Primitive));
  at_least(R"({"animations": [{"channels": [)" + Repeated("{}", 1000) + "]}]}", sizeof(tinygltf::AnimationChannel));
  at_least(R"({"extensions": {"KHR_lights_punctual": {"lights": [)" + Repeated("{}", 1000) + "]}}}",
           sizeof(tinygltf::Light));
  // A material's members become tinygltf::Parameters too.
  std::string material = R"({"materials": [{)";
  for (int i = 0; i < 1000; ++i) material += (i ? ",\"k" : "\"k") + std::to_string(i) + "\": 0";
  at_least(material + "}]}", sizeof(tinygltf::Parameter));
}

// Strings are skipped as JSON reads them, and text that is not JSON ends the walk without a hang.
TEST(GltfParseMemory, StringsAndMalformedTextAreWalkedThrough) {
  EXPECT_EQ(GltfParseBytes(R"({"materials": "[{},{},{}]"})", 0), GltfParseBytes(R"({"materials": "x"})", 0));
  for (const char* text : {"", "{", "[", "{\"a\"", "{:::}", "]]]]", "[1\" ,[[[[[", "{\"materials\": [{]}",
                           "\"\\", "{\"a\":}", "[,,,]"})
    EXPECT_LT(GltfParseBytes(text, 0), uint64_t{1} << 20) << text;
  // Deeper than kMaxJsonDepth, where the walk stops descending.
  EXPECT_GT(GltfParseBytes(std::string(100000, '[') + std::string(100000, ']'), 0), 0u);
}

}  // namespace
}  // namespace aerial
