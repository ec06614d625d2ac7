#include <gtest/gtest.h>

#include <fstream>

#include "support/input_error.hpp"
#include "support/paths.hpp"
#include "ussnav/core/config.hpp"
#include "ussnav/core/error.hpp"

using namespace ussnav;

namespace {
std::filesystem::path writeYaml(const std::string& name, const std::string& text) {
  auto p = test::tempDir("config") / name;
  std::ofstream(p) << text;
  return p;
}
using test::errorOf;
}  // namespace

TEST(Config, DefaultYamlEqualsBuiltInDefaults) {
  const auto path = std::filesystem::path(USSNAV_SOURCE_DIR) / "configs/default.yaml";
  ASSERT_TRUE(std::filesystem::exists(path));
  // Same YAML text out means every key in the file matches the struct default and vice versa.
  EXPECT_EQ(configToYaml(loadConfig(path)), configToYaml(Config{}));
}

TEST(Config, PaperValuesAreDefaults) {
  Config c;
  EXPECT_DOUBLE_EQ(c.mapping.grid.resolution, 0.1);
  EXPECT_DOUBLE_EQ(c.mapping.grid.size_x, 8.0);
  EXPECT_DOUBLE_EQ(c.mapping.grid.size_z, 4.0);
  EXPECT_EQ(c.skeleton.sphere_samples, 50);
  EXPECT_DOUBLE_EQ(c.skeleton.max_radius, 1.4);
  EXPECT_DOUBLE_EQ(c.skeleton.max_extension, 2.0);
}

TEST(Config, UnknownKeyNamesFileAndKey) {
  auto p = writeYaml("typo.yaml", "skeleton:\n  max_radiuss: 1.0\n");
  const std::string e = errorOf([&] { loadConfig(p); });
  EXPECT_NE(e.find("typo.yaml"), std::string::npos) << e;
  EXPECT_NE(e.find("skeleton.max_radiuss"), std::string::npos) << e;
  EXPECT_NE(e.find("unknown key"), std::string::npos) << e;
}

TEST(Config, WrongTypeIsAnError) {
  auto p = writeYaml("type.yaml", "sim:\n  camera:\n    width: wide\n");
  const std::string e = errorOf([&] { loadConfig(p); });
  EXPECT_NE(e.find("sim.camera.width"), std::string::npos) << e;
  EXPECT_NE(e.find("integer"), std::string::npos) << e;
}

TEST(Config, OutOfRangeIsAnError) {
  auto p = writeYaml("range.yaml", "mapping:\n  grid:\n    resolution: 0\n");
  const std::string e = errorOf([&] { loadConfig(p); });
  EXPECT_NE(e.find("mapping.grid.resolution"), std::string::npos) << e;
  EXPECT_NE(e.find("out of range"), std::string::npos) << e;
}

TEST(Config, BadChoiceIsAnError) {
  const std::string e = errorOf([&] { defaultConfig({"sim.map_sensor=radar"}); });
  EXPECT_NE(e.find("sim.map_sensor"), std::string::npos) << e;
}

TEST(Config, OverridesApplyAfterFile) {
  auto p = writeYaml("ok.yaml", "skeleton:\n  max_radius: 1.0\n");
  Config c = loadConfig(p, {"skeleton.max_radius=1.2", "sim.camera.width=320"});
  EXPECT_DOUBLE_EQ(c.skeleton.max_radius, 1.2);
  EXPECT_EQ(c.sim.camera.width, 320);
  const std::string e = errorOf([&] { defaultConfig({"skeleton.nope=1"}); });
  EXPECT_NE(e.find("skeleton.nope"), std::string::npos) << e;
  EXPECT_NE(errorOf([&] { defaultConfig({"novalue"}); }).find("key.path=value"), std::string::npos);
}

TEST(Config, CrossFieldValidation) {
  const std::string e = errorOf([&] { defaultConfig({"sim.lidar.vmin_deg=60"}); });
  EXPECT_NE(e.find("sim.lidar.vmin_deg"), std::string::npos) << e;
}

TEST(Config, MalformedYamlNamesFile) {
  auto p = writeYaml("broken.yaml", "sim: [unclosed\n");
  const std::string e = errorOf([&] { loadConfig(p); });
  EXPECT_NE(e.find("broken.yaml"), std::string::npos) << e;
}
