// Hostile input, round 3, as the command meets it: ways around round 2's rules (a string that
// blinds the TOML depth check, FIFOs the Vulkan loader reaches through its other variables, a
// memory budget counted per model), options and messages (NaN, a value printed other than typed,
// control characters), and outputs (one command's outputs against each other and its inputs,
// every bench file, a long name). Each refusal comes before any GPU work. Each case failed before
// the fix: the note on each says how.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "hostile_command.h"

namespace aerial::testing {
namespace {

namespace fs = std::filesystem;

class HostileCommandRound3 : public HostileCommand {
 protected:
  HostileCommandRound3() : HostileCommand("hostile_round3") {}
  fs::path Write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return dir_ / name;
  }
};

// "x.x.x" of parts parts.
std::string KeyParts(size_t parts) {
  std::string key = "x";
  for (size_t i = 1; i < parts; ++i) key += ".x";
  return key;
}

// Before: SIGSEGV in each of the three readers (the multi-line string closed by four quotes hid
// the key from the depth check).
TEST_F(HostileCommandRound3, ADeepKeyAfterFourQuotesIsRefusedByEveryTomlReader) {
  fs::path deep = Write("deep.toml", "t = { a = \"\"\"x\"\"\"\", " + KeyParts(400000) + " = 1 }\n");
  for (const std::string& arguments : {"precompute --quiet --atmosphere " + deep.string(),
                                       "render --scene " + deep.string() + " --out " + (dir_ / "x.png").string(),
                                       "view --camera-path " + deep.string()}) {
    Expect(arguments, 1, {deep.string() + ": TOML nesting = "});
  }
}

// Before: each hung the command for ever (the loader opened the FIFO with a blocking read).
TEST_F(HostileCommandRound3, NothingTheVulkanLoaderReadsMayBeAFifo) {
  fs::create_directories(dir_ / "icd.d");
  fs::create_directories(dir_ / "layers");
  fs::path in_directory = Fifo("icd.d/fifo.json");
  fs::path added = Fifo("added.json");
  fs::path layer = Fifo("layers/layer.json");
  Fifo("library.so");
  fs::create_directories(dir_ / "manifest");
  Write("manifest/icd.json",
        R"({"file_format_version": "1.0.0", "ICD": {"library_path": "../library.so", "api_version": "1.3.0"}})");
  const std::string command = "precompute --small-tables --quiet --no-cache";
  Expect(command, 1, {"VK_DRIVER_FILES = " + in_directory.string(), "not a FIFO"},
         "env VK_DRIVER_FILES=" + (dir_ / "icd.d").string());
  Expect(command, 1, {"VK_ADD_DRIVER_FILES = " + added.string(), "not a FIFO"},
         "env VK_ADD_DRIVER_FILES=" + added.string());
  Expect(command, 1, {"VK_LAYER_PATH = " + layer.string(), "not a FIFO"},
         "env VK_LAYER_PATH=" + (dir_ / "layers").string());
  Expect(command, 1, {"VK_ICD_FILENAMES = " + (dir_ / "manifest/icd.json").string(), "library_path", "not a FIFO"},
         "env VK_ICD_FILENAMES=" + (dir_ / "manifest/icd.json").string());
}

// 500,000 empty materials: 1.5 MB of JSON that tinygltf turns into about 1.2 GB of Material
// structs. Before: estimated at 200 MiB, it passed --max-memory-mib 300 and peaked near 1.2 GB.
TEST_F(HostileCommandRound3, EmptyGltfElementsCountAtTheirRealSize) {
  std::string materials;
  for (int i = 0; i < 500000; ++i) materials += i ? ",{}" : "{}";
  Write("materials.gltf", R"({"asset": {"version": "2.0"}, "materials": [)" + materials + "]}");
  fs::path scene = Write("materials.toml", "[[mesh]]\ngltf = \"materials.gltf\"\n");
  Expect("render --max-memory-mib 300 --scene " + scene.string() + " --out " + (dir_ / "x.png").string(), 1,
         {"mesh[0].gltf = " + (dir_ / "materials.gltf").string(), "sizes whose memory fits the budget"});
}

// Before: accepted, and NaN turned dynamic resolution off (and each of the others went on with a
// NaN or an infinity).
TEST_F(HostileCommandRound3, NoNumberOptionTakesNanOrInfinity) {
  Expect("view --target-ms nan", 1, {"--target-ms = nan is invalid; expected a finite number"});
  Expect("render --froxel-far-m NaN --out x.png", 1, {"--froxel-far-m = NaN is invalid; expected a finite number"});
  Expect("export-vdb --world-grid inf --out x.vdb", 1, {"--world-grid = inf is invalid; expected a finite number"});
  Expect("render --camera-position-m 0,nan,30 --out x.png", 1, {"--camera-position-m = nan is invalid"});
  Expect("probe --altitude-m 1e999 --view-zenith-deg 45 --sun-zenith-deg 30 --azimuth-deg 0", 1,
         {"--altitude-m = 1e999 is invalid; expected a finite number"});
}

// Before: "--altitude-m = 60000 is invalid; expected meters in [0, 60000]" (printed with six
// digits), a message that contradicts itself.
TEST_F(HostileCommandRound3, ValuesArePrintedAsTyped) {
  const std::string angles = " --view-zenith-deg 45 --sun-zenith-deg 30 --azimuth-deg 0";
  Expect("probe --altitude-m 60000.001" + angles, 1,
         {"--altitude-m = 60000.001 is invalid; expected meters in [0, 60000]"});
  Expect("probe --altitude-m 6.0000001e4" + angles, 1, {"--altitude-m = 6.0000001e4 is invalid"});
}

// Before: the escape sequences reached the terminal raw (one sets the window's title), and a NUL
// cut the message short.
TEST_F(HostileCommandRound3, ControlCharactersInMessagesAreEscaped) {
  fs::path scene = Write("escape.toml", "[[mesh]]\ngltf = \"\\u001b]0;pwned\\u0007.gltf\"\n");
  CommandRun run = Expect("render --scene " + scene.string() + " --out " + (dir_ / "x.png").string(), 1,
                          {"\\x1b]0;pwned\\x07.gltf"});
  EXPECT_EQ(run.err.find('\x1b'), std::string::npos) << run.err;
  Write("nul.gltf", R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "a\u0000b.bin", "byteLength": 4}]})");
  fs::path nul = Write("nul.toml", "[[mesh]]\ngltf = \"nul.gltf\"\n");
  run = Expect("render --scene " + nul.string() + " --out " + (dir_ / "x.png").string(), 1,
               {"buffers[0].uri = a\\x00b.bin", "without a NUL character"});
  fs::path atmosphere = Write("name.toml", "name = \"\\u001b[2Jearth\"\n");
  run = RunAerial("precompute --small-tables --quiet --colour rgb --atmosphere " + atmosphere.string());
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("(\\x1b[2Jearth)"), std::string::npos) << run.out;
  EXPECT_EQ(run.out.find('\x1b'), std::string::npos) << run.out;
}

// Before: --stats replaced the screenshot (or the camera path) with JSON, with exit status 0.
TEST_F(HostileCommandRound3, ViewsOutputsMayNotBeEachOtherOrItsInputs) {
  fs::path shot = dir_ / "shot.png", path = dir_ / "path.toml";
  fs::copy_file(AERIAL_SOURCE_DIR "/examples/paths/corridor.toml", path);
  Write("shot.png", "an earlier picture");
  fs::create_symlink("shot.png", dir_ / "link.json");
  const std::string view = "view --frames 1 --screenshot " + shot.string();
  Expect(view + " --stats " + shot.string(), 1, {"--stats = " + shot.string(), "a file other than --screenshot"});
  Expect(view + " --stats " + (dir_ / "link.json").string(), 1, {"a file other than --screenshot"});
  Expect("view --stats " + path.string() + " --camera-path " + path.string(), 1,
         {"--stats = " + path.string(), "a file other than --camera-path", "which this command reads"});
  // A new file through two links to the same place is found too.
  fs::create_symlink("new.png", dir_ / "a.png");
  fs::create_symlink("new.png", dir_ / "b.json");
  Expect("view --frames 1 --screenshot " + (dir_ / "a.png").string() + " --stats " + (dir_ / "b.json").string(), 1,
         {"a file other than --screenshot"});
  EXPECT_FALSE(fs::exists(dir_ / "new.png"));
  std::ifstream in(shot);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "an earlier picture");
}

// Before: only report.md was checked before the run; a directory at results.csv was found after
// it, when the figures and results.json had been replaced. And --out's directory chain was made
// before the work, so a run that ended early (an error, SIGTERM) left it behind, empty.
TEST_F(HostileCommandRound3, BenchChecksEveryFileBeforeItsWorkAndMakesNothing) {
  fs::create_directories(dir_ / "out" / "results.csv");
  Write("out/results.json", "an earlier run's");
  Expect("bench --quick --quiet --out " + (dir_ / "out").string(), 1,
         {(dir_ / "out" / "results.csv").string(), "Is a directory"});
  std::ifstream in(dir_ / "out" / "results.json");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "an earlier run's");
  fs::remove(dir_ / "out" / "results.csv");
  fs::create_symlink("report.md", dir_ / "out" / "results.csv");
  Expect("bench --quick --quiet --out " + (dir_ / "out").string(), 1,
         {"--out = " + (dir_ / "out" / "report.md").string(),
          "a file other than --out " + (dir_ / "out" / "results.csv").string()});
  // Checked, then stopped before any work: nothing is left.
  Expect("bench --quick --quiet --device no-such-device --out " + (dir_ / "a" / "b" / "c").string(), 1,
         {"no-such-device"});
  EXPECT_FALSE(fs::exists(dir_ / "a"));
}

// A name of 244 bytes is valid, but its temporary "<name>.tmp-<pid>-<16 digits>" was not: the
// output check failed, blaming the user's path ("File name too long"). Here the check passes and
// the next one, on --width, fails.
TEST_F(HostileCommandRound3, ALongValidOutputNameIsAccepted) {
  fs::path out = dir_ / (std::string(240, 'n') + ".png");
  Expect("render --width 0 --out " + out.string(), 1, {"--width/--height = 0x720 is invalid"});
}

// Before: a wavelength of 350 nm passed (300-1000 allowed), the spectral sun was black, and probe
// printed null with exit status 0.
TEST_F(HostileCommandRound3, SpectralInputsAreCheckedAgainstTheirData) {
  fs::path atmosphere = Write("uv.toml", "wavelengths_nm = [680.0, 550.0, 350.0]\n");
  Expect("probe --reference --colour spectral --atmosphere " + atmosphere.string() +
             " --altitude-m 1 --view-zenith-deg 45 --sun-zenith-deg 30 --azimuth-deg 0",
         1, {"wavelengths_nm[2] = 350.0 is invalid; expected in [360.0, 830.0]"});
  fs::path dark = Write("dark.toml", "solar_irradiance = [0.0, 0.0, 0.0]\n");
  Expect("render --atmosphere " + dark.string() + " --out " + (dir_ / "x.png").string(), 1,
         {"solar_irradiance = [0.0, 0.0, 0.0] is invalid"});
}

}  // namespace
}  // namespace aerial::testing
