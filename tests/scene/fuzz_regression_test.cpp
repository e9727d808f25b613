// Replays the fuzzing corpora (tests/fuzz/regressions: every input the fuzzers
// ever crashed on, plus the seeds) through the scene loader, the cloud reader
// the PLY vertex reader and the guarded mesh import: each must load or fail
// with InputError, nothing else. The mesh corpus holds files on which assimp
// itself hung or crashed (assimp_hang_*, assimp_sig*_*): each is refused.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "base/input_file.hpp"
#include "core/mass_properties.hpp"
#include "core/particle_cloud.hpp"
#include "io/cloud_file.hpp"
#include "scene/mesh_file.hpp"
#include "scene/ply_vertices.hpp"
#include "scene/scene.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kSource = TUMBLE_SOURCE_DIR;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<fs::path> files(const fs::path& dir) {
  std::vector<fs::path> out;
  if (fs::exists(dir))
    for (const auto& e : fs::directory_iterator(dir))
      if (e.is_regular_file()) out.push_back(e.path());
  return out;
}

TEST(FuzzRegressions, SceneInputsLoadOrFailWithInputError) {
  std::vector<fs::path> inputs = files(kSource / "tests/fuzz/regressions/scene");
  for (const fs::path& p : files(kSource / "tests/scene/broken")) inputs.push_back(p);
  for (const fs::path& p : files(kSource / "scenes"))
    if (p.extension() == ".toml") inputs.push_back(p);
  ASSERT_FALSE(inputs.empty());
  for (const fs::path& p : inputs) {
    SCOPED_TRACE(p.string());
    try {
      (void)tumble::scene::load_scene_from_string(slurp(p), "fuzz.toml", "/nonexistent-tumble-fuzz");
    } catch (const tumble::InputError&) {
    } catch (const tumble::UnreadableFile&) {  // a cloud path naming a device or folder
    } catch (const std::exception& e) {
      ADD_FAILURE() << "unexpected exception: " << e.what();
    }
  }
}

TEST(FuzzRegressions, CloudInputsParseOrFailWithInputError) {
  const std::vector<fs::path> inputs = files(kSource / "tests/fuzz/regressions/cloud");
  ASSERT_FALSE(inputs.empty()) << "no cloud corpus: the replay would check nothing";
  for (const fs::path& p : inputs) {
    SCOPED_TRACE(p.string());
    try {
      const tumble::ParticleCloud c = tumble::io::parse_cloud_text(slurp(p), "fuzz.txt");
      if (!c.empty()) (void)tumble::compute_mass_properties(c, "fuzz");
    } catch (const tumble::InputError&) {
    } catch (const std::exception& e) {
      ADD_FAILURE() << "unexpected exception: " << e.what();
    }
  }
}

TEST(FuzzRegressions, PlyInputsParseOrFailWithInputError) {
  const std::vector<fs::path> inputs = files(kSource / "tests/fuzz/regressions/ply");
  ASSERT_FALSE(inputs.empty()) << "no PLY corpus: the replay would check nothing";
  for (const fs::path& p : inputs) {
    SCOPED_TRACE(p.string());
    std::istringstream in(slurp(p));
    try {
      (void)tumble::scene::read_ply_vertices(in, "fuzz.ply");
    } catch (const tumble::InputError&) {
    } catch (const std::exception& e) {
      ADD_FAILURE() << "unexpected exception: " << e.what();
    }
  }
}

TEST(FuzzRegressions, MeshInputsLoadOrFailWithInputError) {
  const std::vector<fs::path> inputs = files(kSource / "tests/fuzz/regressions/mesh");
  ASSERT_GE(inputs.size(), 17u) << "the mesh corpus is missing: the replay would check little";
  const tumble::scene::MeshFormat formats[] = {tumble::scene::MeshFormat::obj, tumble::scene::MeshFormat::stl,
                                               tumble::scene::MeshFormat::ply, tumble::scene::MeshFormat::off};
  for (const fs::path& p : inputs) {
    SCOPED_TRACE(p.string());
    const std::string bytes = slurp(p);
    const char k = bytes.empty() ? 'o' : bytes[0];  // as fuzz_mesh reads it
    const auto f = k == 'o' ? formats[0] : k == 's' ? formats[1] : k == 'p' ? formats[2] : k == 'f' ? formats[3]
                                                                                     : formats[static_cast<unsigned char>(k) % 4];
    const bool known_bad = p.filename().string().rfind("assimp_", 0) == 0;
    try {
      (void)tumble::scene::read_mesh_bytes(bytes.substr(bytes.empty() ? 0 : 1), f, "fuzz.mesh", {5.0, std::size_t{1} << 30});
      EXPECT_FALSE(known_bad) << "a file assimp hangs or crashes on was accepted";
    } catch (const tumble::InputError& e) {
      EXPECT_EQ(std::string(e.what()).find("the import time limit"), std::string::npos) << e.what();
    } catch (const std::exception& e) {
      ADD_FAILURE() << "unexpected exception: " << e.what();
    }
  }
}

}  // namespace
