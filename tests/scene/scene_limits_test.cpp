// Limits checked on a scene's text before toml++ parses it, each
// refused with file:line:column naming the limit; and long or binary tokens
// quoted short in messages.
#include <string>

#include <gtest/gtest.h>

#include "scene/scene.hpp"
#include "scene/toml_limits.hpp"
#include "scene_error.hpp"

using namespace tumble;

namespace {

std::string error_of(const std::string& text) {
  const std::string msg = scene_error(text, "s.toml");
  if (msg.empty()) ADD_FAILURE() << "loaded";
  return msg;
}

TEST(SceneLimits, ADeeplyDottedKeyIsRefusedBeforeTomlRecursesOnIt) {
  // 50 000 dots in 100 KB crashed toml++ (stack overflow).
  std::string key = "a";
  for (int i = 0; i < 50000; ++i) key += ".a";
  const std::string msg = error_of("name = \"x\"\n" + key + " = 1\n");
  EXPECT_NE(msg.find("s.toml:2:64: error: the scene has a key of more than 32 dotted parts (the key-depth limit)"),
            std::string::npos) << msg.substr(0, 300);
  EXPECT_NE(error_of("[" + key + "]\n").find("(the key-depth limit)"), std::string::npos);
}

TEST(SceneLimits, DottedNumbersAndQuotedDotsAreNotKeyParts) {
  std::string many = "[";
  for (int i = 0; i < 100; ++i) many += "1.5, ";
  many += "2.5]";
  const std::string msg = error_of("\"a.b.c.d.e.f.g.h.i.j.k.l.m.n.o.p.q.r.s.t.u.v.w.x.y.z.0.1.2.3.4.5.6.7\" = " + many + "\n");
  EXPECT_EQ(msg.find("limit"), std::string::npos) << msg;
  EXPECT_NE(msg.find("unknown key"), std::string::npos) << msg;
}

TEST(SceneLimits, NestingDeeperThanTheLimitIsRefused) {
  const std::string msg = error_of("x = " + std::string(40, '[') + std::string(40, ']') + "\n");
  EXPECT_NE(msg.find("s.toml:1:37: error: the scene has arrays or inline tables nested more than 32 deep (the nesting limit)"),
            std::string::npos) << msg;
}

TEST(SceneLimits, BodiesBeyondTheCapAreRefusedBeforeParsing) {
  std::string text;
  for (std::size_t i = 0; i <= scene::kMaxBodies; ++i) text += "[[ bodies ]]\n";
  const std::string msg = error_of(text);
  EXPECT_NE(msg.find("s.toml:1001:2: error: the scene has more than 1000 [[bodies]] (the body cap)"), std::string::npos) << msg;
}

TEST(SceneLimits, ValuesBeyondTheSceneSizeLimitAreRefused) {
  std::string text = "x = [";
  text.reserve(2 * scene::kMaxSceneValues + 16);
  for (std::size_t i = 0; i <= scene::kMaxSceneValues; ++i) text += "0,";
  const std::string msg = error_of(text + "]\n");
  EXPECT_NE(msg.find("more than 2000000 values (the scene-size limit; put large clouds in a cloud file)"),
            std::string::npos) << msg;
}

TEST(SceneLimits, LongAndBinaryTokensAreQuotedShort) {
  const std::string msg = error_of("name = \"" + std::string(100000, 'n') + "\"\n[simulation]\nmethod = \"a\\u0000b\"\n");
  EXPECT_LT(msg.size(), 1000u) << msg.size();
  EXPECT_NE(msg.find("\"" + std::string(80, 'n') + "\"... (100000 bytes)"), std::string::npos) << msg;
  EXPECT_NE(msg.find("found \"a\\x00b\""), std::string::npos) << msg;
}

}  // namespace

namespace {

TEST(SceneCamera, AnUpAlongTheViewIsReplacedWithAWarning) {
  const std::string body = "[[bodies]]\nparticles = [[1, 0, 0, 1], [-1, 0, 0, 1], [0, 1, 0, 0.5], [0, 0, 1, 0.5]]\n";
  scene::Scene s = scene::load_scene_from_string(body + "[camera]\nposition = [0, 0, 5]\ntarget = [0, 0, 0]\n", "c.toml");
  EXPECT_EQ(s.render.camera.up, Eigen::Vector3d(0, 1, 0));
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("c.toml:3:1: warning: camera.up: parallel to the view direction"), std::string::npos)
      << s.warnings[0];
  s = scene::load_scene_from_string(body + "[camera]\nposition = [0, -4, 0]\nup = [0, 2, 0]\n", "c.toml");
  EXPECT_EQ(s.render.camera.up, Eigen::Vector3d(1, 0, 0));  // looking along y: +x
  s = scene::load_scene_from_string(body + "[camera]\nposition = [3, -4, 1]\n", "c.toml");
  EXPECT_EQ(s.render.camera.up, Eigen::Vector3d(0, 0, 1));
  EXPECT_TRUE(s.warnings.empty());
}

}  // namespace
