// Hostile paths, round two: no output replaces an input of the same run (by
// identity: any spelling or link of it) or a special file, nothing blocks on a
// FIFO or reads /dev/zero, and the late errors come early with their exit
// codes. None needs GL; each case failed on the code before its fix.
#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace {

class HostileOutput : public Cli {
 protected:
  fs::path write(const std::string& name, const std::string& text) const {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << text;
    return p;
  }
  fs::path fifo(const std::string& name) const {
    const fs::path p = dir_ / name;
    EXPECT_EQ(::mkfifo(p.c_str(), 0644), 0);
    return p;
  }
  static bool is_fifo(const fs::path& p) {
    struct stat st {};
    return ::lstat(p.c_str(), &st) == 0 && S_ISFIFO(st.st_mode);
  }
  // A one-body scene that reads its particles from cloud.csv beside it.
  fs::path cloud_scene() const {
    write("cloud.csv", "x,y,z,m\n1,0,0,1\n-1,0,0,1\n0,1,0,2\n0,0,1,3\n");
    return write("s.toml", "name = \"s\"\n[simulation]\nduration = 0.2\nfps = 10\n[[bodies]]\ncloud = \"cloud.csv\"\n");
  }
};

TEST_F(HostileOutput, CsvNamingTheSceneOrItsCloudByAnySpellingIsRefused) {
  const fs::path scene = cloud_scene();
  const std::string before = slurp(scene), cloud = slurp(dir_ / "cloud.csv");
  ASSERT_EQ(::link(scene.c_str(), (dir_ / "hard.csv").c_str()), 0);
  fs::create_symlink(dir_ / "cloud.csv", dir_ / "soft.csv");
  const std::pair<std::string, std::string> cases[] = {
      {scene.string(), "scene file"},
      {(dir_ / "." / "s.toml").string(), "scene file"},
      {(dir_ / "hard.csv").string(), "scene file"},  // a hard link: same inode
      {(dir_ / "cloud.csv").string(), "cloud file"},
      {(dir_ / "soft.csv").string(), "cloud file"}};
  for (const auto& [csv, what] : cases) {
    SCOPED_TRACE(csv);
    const Result r = bounded("simulate '" + scene.string() + "' --csv '" + csv + "'");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("refusing to write over " + what), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("an input of this run"), std::string::npos) << r.err;
  }
  EXPECT_EQ(slurp(scene), before);
  EXPECT_EQ(slurp(dir_ / "cloud.csv"), cloud);
  EXPECT_TRUE(fs::is_symlink(dir_ / "soft.csv"));
}

TEST_F(HostileOutput, LayoutAndGltfNamingTheSceneAreRefused) {
  const fs::path scene = cloud_scene();
  const std::string before = slurp(scene);
  Result r = bounded("render '" + scene.string() + "' --layout '" + scene.string() + "'");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("--layout " + scene.string() + ": refusing to write over scene file"), std::string::npos) << r.err;
  fs::copy_file(scene, dir_ / "s.gltf");
  r = bounded("export '" + (dir_ / "s.gltf").string() + "' --gltf '" + (dir_ / "s.gltf").string() + "'");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("refusing to write over scene file"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(scene), before);
  EXPECT_EQ(slurp(dir_ / "s.gltf"), before);
}

TEST_F(HostileOutput, GoldenTrajectoryNamedLikeTheSceneIsRefused) {
  // The scene `x`, kept in x.trajectory.csv: --update would write its golden trajectory over it.
  const fs::path scene = write("x.trajectory.csv", "name = \"x\"\n[simulation]\nduration = 0.5\nfps = 10\n"
                                                   "[[bodies]]\nparticles = [[1, 0, 0, 1], [-1, 0, 0, 1], [0, 1, 0, 2]]\n");
  const std::string before = slurp(scene);
  const Result r = bounded("golden '" + scene.string() + "' --dir '" + dir_.string() +
                           "' --frames 2 --update --physics-only --report '" + (dir_ / "rep").string() + "'");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("refusing to write over scene file"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(scene), before);
}

TEST_F(HostileOutput, ACsvOntoAFifoOrDeviceIsRefusedAndLeftAsItWas) {
  const fs::path scene = cloud_scene(), pipe = fifo("out.fifo");
  Result r = bounded("simulate '" + scene.string() + "' --csv '" + pipe.string() + "'");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("is a FIFO (named pipe), not a regular file"), std::string::npos) << r.err;
  EXPECT_TRUE(is_fifo(pipe)) << "the FIFO was replaced";
  r = bounded("simulate '" + scene.string() + "' --csv -");  // what to give instead: standard output
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("t,body,", 0), 0u) << r.out;
  // A character device: as root the rename used to turn /dev/null into a
  // regular file. Root gets a null device of its own here, so a broken tumble
  // breaks only that one; anyone else uses /dev/null, whose folder they cannot
  // write. Root without CAP_MKNOD (some containers) has no device to offer:
  // the FIFO above stands for the special files then.
  const fs::path null = ::geteuid() == 0 ? dir_ / "null" : fs::path("/dev/null");
  if (::geteuid() == 0 && ::mknod(null.c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0) return;
  r = bounded("simulate '" + scene.string() + "' --csv '" + null.string() + "'");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find(null.string() + ": is a character device"), std::string::npos) << r.err;
  struct stat st {};
  ASSERT_EQ(::stat(null.c_str(), &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode)) << null << " was replaced";
}

TEST_F(HostileOutput, AnEmptyPathIsRefusedNotTakenAsTheDefault) {
  const fs::path scene = cloud_scene();
  const std::string in_dir = "cd '" + dir_.string() + "' &&";
  for (const char* args : {"render s.toml -o ''", "render s.toml --layout ''", "simulate s.toml --csv ''",
                           "export s.toml --gltf ''", "golden s.toml --dir '' --frames 1 --physics-only",
                           "assemble ''", "info ''"}) {
    SCOPED_TRACE(args);
    const Result r = bounded(args, 20, in_dir);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("expected a path, found an empty string"), std::string::npos) << r.err;
  }
  EXPECT_FALSE(fs::exists(dir_ / "out")) << "-o '' rendered into ./out";
}

TEST_F(HostileOutput, SpecialFilesWhereTumbleReadsItsOwnFilesNeverBlock) {
  const fs::path scene = cloud_scene();
  // A FIFO as an existing render's manifest, as a golden trajectory, as a PNG compared.
  fs::create_directories(dir_ / "render");
  fifo("render/manifest.json");
  Result r = bounded("render '" + scene.string() + "' -o '" + (dir_ / "render").string() + "'", 20);
  EXPECT_EQ(r.code, 1) << r.err;  // 137: killed by the timeout, it blocked
  EXPECT_NE(r.err.find("manifest.json: is a FIFO (named pipe), not a regular file"), std::string::npos) << r.err;
  fs::create_directories(dir_ / "golden");
  fifo("golden/s.trajectory.csv");
  r = bounded("golden '" + scene.string() + "' --dir '" + (dir_ / "golden").string() + "' --frames 1 --physics-only",
              20);
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("s.trajectory.csv: golden trajectory is a FIFO"), std::string::npos) << r.err;
  fifo("a.png");
  r = bounded("compare '" + (dir_ / "a.png").string() + "' '" + (dir_ / "a.png").string() + "'", 20);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("a.png: PNG file is a FIFO"), std::string::npos) << r.err;
}

// A shard's part, as `tumble render --frames 0:1` writes it, of a 2-frame render.
std::string part_json(const std::string& video_format = "none") {
  return "{\"tool\": \"tumble\", \"scene\": \"s.toml\", \"scene_name\": \"s\", \"scene_hash\": \"a\", "
         "\"settings_hash\": \"b\", \"fps\": 10, \"width\": 96, \"height\": 72, \"frame_count\": 2, "
         "\"frames\": [0, 1], \"frames_written\": 2, \"video_format\": \"" + video_format + "\", \"crf\": 18, "
         "\"complete\": true}\n";
}

TEST_F(HostileOutput, AssembleRefusesFrameSumsThatAreADeviceAndPartsThatAreFolders) {
  fs::create_directories(dir_ / "shards");
  write("shards/manifest.part-000000-000001.json", part_json());
  fs::create_symlink("/dev/zero", dir_ / "shards" / "frames.sums");
  Result r = bounded("assemble '" + (dir_ / "shards").string() + "' --progress none");
  EXPECT_EQ(r.code, 1) << r.err;  // read /dev/zero until std::bad_alloc before
  EXPECT_NE(r.err.find("frames.sums: frame record is a character device"), std::string::npos) << r.err;
  fs::remove(dir_ / "shards" / "frames.sums");
  fs::create_directories(dir_ / "shards" / "manifest.part-000002-000003.json");
  r = bounded("assemble '" + (dir_ / "shards").string() + "' --progress none");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("manifest.part-000002-000003.json: JSON file is a directory"), std::string::npos) << r.err;
}

TEST_F(HostileOutput, AssembleRefusesAPartWhoseVideoFieldsNoRenderWrites) {
  fs::create_directories(dir_ / "shards");
  write("shards/manifest.part-000000-000001.json", part_json("avi"));
  const Result r = bounded("assemble '" + (dir_ / "shards").string() + "' --progress none");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("video_format 'avi' is not mp4, gif or none"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "shards" / "manifest.json"));
}

TEST_F(HostileOutput, GoldenReportKeepsWhatItDidNotWrite) {
  const fs::path scene = cloud_scene(), report = dir_ / "report";
  fs::create_directories(report / "img");
  write("report/index.html", "<html>my own page</html>\n");
  write("report/img/photo.png", "mine");
  const std::string args = "golden '" + scene.string() + "' --dir '" + (dir_ / "g").string() +
                           "' --frames 1 --physics-only --report '" + report.string() + "'";
  Result r = bounded(args);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("index.html was not written by tumble golden"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(report / "index.html"), "<html>my own page</html>\n");
  EXPECT_EQ(slurp(report / "img" / "photo.png"), "mine");
  // A report tumble wrote goes, with only its own images.
  write("report/index.html", "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>tumble golden: s</title>"
                             "<img src=\"img/s_f1.actual.png\"></html>\n");
  write("report/img/s_f1.actual.png", "old");
  r = bounded(args);
  EXPECT_EQ(r.code, 1) << r.err;  // no golden yet: MISSING
  EXPECT_FALSE(fs::exists(report / "img" / "s_f1.actual.png"));
  EXPECT_EQ(slurp(report / "img" / "photo.png"), "mine");
}

TEST_F(HostileOutput, AFileSizeLimitGivesAMessageAndLeavesNoTempFile) {
  const fs::path scene = write("long.toml", "name = \"long\"\n[simulation]\nduration = 200\nfps = 100\n"
                                            "[[bodies]]\nparticles = [[1, 0, 0, 1], [-1, 0, 0, 1], [0, 1, 0, 2]]\n");
  const Result r = bounded("simulate '" + scene.string() + "' --csv '" + (dir_ / "t.csv").string() + "'", 60,
                           "ulimit -f 64;");  // 64 KiB; the CSV is some 4 MB
  EXPECT_EQ(r.code, 1) << r.err;  // 153 = killed by SIGXFSZ
  EXPECT_NE(r.err.find("File too large (over the file-size limit"), std::string::npos) << r.err;
  for (const auto& e : fs::directory_iterator(dir_))
    EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();
  EXPECT_FALSE(fs::exists(dir_ / "t.csv"));
}

TEST_F(HostileOutput, GoldenUpdateOfADivergingSceneExits3AndWritesNothing) {
  const fs::path scene = kSource / "tests/app/data/diverges_under_euler.toml";
  const Result r = bounded("golden '" + scene.string() + "' --dir '" + (dir_ / "g").string() +
                           "' --at 50 --update --physics-only --report '" + (dir_ / "rep").string() + "'");
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("no golden was written"), std::string::npos) << r.err;
  EXPECT_TRUE(!fs::exists(dir_ / "g") || fs::is_empty(dir_ / "g")) << "a partial golden was left";
}

}  // namespace
