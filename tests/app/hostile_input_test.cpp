// Hostile inputs and bad options, as a user meets them. Each fails at
// once, with the documented exit code and a message saying what the path is or
// which option is wrong, before any work. None needs GL.
#include <sys/stat.h>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace {

class HostileInput : public Cli {
 protected:
  // A scene whose one body reads its cloud from `cloud` (a path as written in TOML).
  std::string cloud_scene(const std::string& cloud) const {
    const fs::path p = dir_ / "cloud_scene.toml";
    std::ofstream(p) << "[[bodies]]\ncloud = \"" << cloud << "\"\n";
    return "'" + p.string() + "'";
  }
  // Runs tumble unable to read what its mode bits forbid, even as root: without
  // CAP_DAC_OVERRIDE / CAP_DAC_READ_SEARCH (setpriv drops them from the bounding
  // set, so the exec'd tumble never gets them back).
  Result without_root_bypass(const std::string& args) const {
    if (::geteuid() != 0) return run(args);
    return run(args, "", "setpriv --bounding-set=-dac_override,-dac_read_search --");
  }
};

TEST_F(HostileInput, InfoOnDevZeroFailsAtOnce) {
  const Result r = bounded("info /dev/zero");
  EXPECT_EQ(r.code, 1) << r.err;  // 137 = killed by the timeout: it hung
  EXPECT_NE(r.err.find("/dev/zero: scene file is a character device, not a regular file"), std::string::npos) << r.err;
}

TEST_F(HostileInput, InfoOnADirectorySaysSo) {
  const Result r = bounded("info '" + dir_.string() + "'");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("scene file is a directory"), std::string::npos) << r.err;
}

TEST_F(HostileInput, InfoOnAFifoDoesNotWaitForAWriter) {
  const fs::path fifo = dir_ / "scene.fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  const Result r = bounded("info '" + fifo.string() + "'");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("scene file is a FIFO"), std::string::npos) << r.err;
}

TEST_F(HostileInput, UnreadableSceneIsAPermissionError) {
  const fs::path p = dir_ / "locked.toml";
  std::ofstream(p) << "[[bodies]]\nparticles = [[1, 0, 0, 1], [-1, 0, 0, 1], [0, 1, 0, 1], [0, 0, 1, 1]]\n";
  ::chmod(p.c_str(), 0);
  const Result r = without_root_bypass("info '" + p.string() + "'");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("locked.toml: scene file cannot be read: permission denied"), std::string::npos) << r.err;
}

TEST_F(HostileInput, CloudThatIsNotARegularFileSaysWhatItIs) {
  fs::create_directories(dir_ / "cloud_dir");
  ASSERT_EQ(::mkfifo((dir_ / "cloud.fifo").c_str(), 0644), 0);
  const std::pair<std::string, std::string> cases[] = {
      {"cloud_dir", "is a directory"}, {"cloud.fifo", "is a FIFO (named pipe)"}, {"/dev/zero", "is a character device"}};
  for (const auto& [cloud, what] : cases) {
    SCOPED_TRACE(cloud);
    const Result r = bounded("info " + cloud_scene(cloud));
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_NE(r.err.find("cloud_scene.toml:2:9: error: bodies[0].cloud: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("cloud file " + what), std::string::npos) << r.err;
  }
}

TEST_F(HostileInput, UnreadableCloudIsAPermissionErrorNotAMissingFile) {
  std::ofstream(dir_ / "locked.xyz") << "1 0 0 1\n-1 0 0 1\n0 1 0 1\n0 0 1 1\n";
  ::chmod((dir_ / "locked.xyz").c_str(), 0);
  const Result r = without_root_bypass("info " + cloud_scene("locked.xyz"));
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("locked.xyz: cloud file cannot be read: permission denied"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("does it exist"), std::string::npos) << r.err;
}

TEST_F(HostileInput, EmptyCloudFileSaysItIsEmpty) {
  std::ofstream(dir_ / "empty.xyz");
  const Result r = run("info " + cloud_scene("empty.xyz"));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("empty.xyz: cloud file holds no particles (it is empty)"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("give `particles`"), std::string::npos) << r.err;
}

// ---- Command-line overrides: validated like the scene, before any work ------

class BadOption : public Cli {
 protected:
  std::string tiny() const { return "'" + (kSource / "tests/app/data/tiny_render.toml").string() + "'"; }
  // `tumble render tiny ARGS` into a folder that must not be created.
  Result render(const std::string& args) const {
    return run("render " + tiny() + " -o '" + (dir_ / "out").string() + "' --progress none " + args);
  }
  void expect_refused(const Result& r, const std::string& text) const {
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find(text), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "out")) << "work started before the option was checked";
  }
};

TEST_F(BadOption, FpsBeyondTheFrameCapOrRangeNamesTheOption) {
  expect_refused(render("--fps 1e8"), "--fps: error: output.fps: expected a number in [0.001, 1000]");
  expect_refused(render("--fps 0"), "--fps: error: output.fps:");
}

TEST_F(BadOption, WidthZeroIsRefusedNotIgnored) {
  expect_refused(render("--width 0"), "--width: error: output.width: expected an integer in [16, 16384], found 0");
  expect_refused(render("--height 99999"), "--height: error: output.height:");
  expect_refused(render("--msaa 3"), "--msaa: error: output.msaa: expected 0, 2 or 4, found 3");
  expect_refused(render("--video avi"), "--video: error: output.video:");
  expect_refused(render("--aa smaa"), "--aa: error: output.aa: expected \"fxaa\", \"msaa\" or \"none\", found \"smaa\"");
  expect_refused(render("--aa msaa --msaa 0"), "--msaa: error: output.msaa: aa = \"msaa\" needs msaa = 2 or 4, found 0");
}

TEST_F(BadOption, UnknownGlBackendIsAnInputErrorBeforeTheSimulation) {
  expect_refused(render("--gl vulkan"), "--gl: unknown GL backend 'vulkan' (expected osmesa or egl)");
  const Result r = run("render " + tiny() + " -o '" + (dir_ / "out").string() + "' --progress none", "TUMBLE_GL=vulkan");
  expect_refused(r, "TUMBLE_GL: unknown GL backend 'vulkan'");
}

TEST_F(BadOption, GoldenWithAnUnknownGlBackendWritesNoGolden) {
  // It used to write the golden trajectory first and fail late, with exit 1.
  const fs::path gold = dir_ / "gold";
  const std::string scene = "'" + (kSource / "scenes/dzhanibekov.toml").string() + "'";
  const Result r = run("golden " + scene + " --at 1 --update --gl vulkan --dir '" + gold.string() + "'");
  expect_refused(r, "--gl: unknown GL backend 'vulkan' (expected osmesa or egl)");
  EXPECT_FALSE(fs::exists(gold / "dzhanibekov.trajectory.csv"));
}

TEST_F(BadOption, BackwardsFrameRangeNamesAAfterB) {
  expect_refused(render("--frames 10:5"), "--frames 10:5: the first frame (10) is after the last (5); expected A <= B");
}

TEST_F(BadOption, CsvInAMissingFolderNamesTheFileNotItsTempName) {
  const Result r = run("simulate '" + (kSource / "scenes/dzhanibekov.toml").string() + "' --csv '" +
                       (dir_ / "nodir/x.csv").string() + "'");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("--csv " + (dir_ / "nodir/x.csv").string() + ": cannot write there"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find(".tmp"), std::string::npos) << r.err;
}

TEST_F(BadOption, SimulateOverridesAreCheckedByTheScenesRules) {
  const std::string scene = "'" + (kSource / "scenes/dzhanibekov.toml").string() + "' --csv '" + (dir_ / "x.csv").string() + "'";
  Result r = run("simulate " + scene + " --dt 1e6");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("--dt: error: simulation.dt: expected dt <= duration"), std::string::npos) << r.err;
  r = run("simulate " + scene + " --method rk5");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("--method: error: simulation.method: "), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "x.csv"));
}

// ---- CLI polish --------------------------------------------------------------

TEST_F(BadOption, NoArgumentsPrintsHelp) {
  const Result r = run("");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("render"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Usage"), std::string::npos) << r.out;
}

TEST_F(BadOption, UnknownCommandGetsADidYouMean) {
  const Result r = run("rendr x.toml");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("unknown command 'rendr'; did you mean 'render'?"), std::string::npos) << r.err;
}

TEST_F(BadOption, HelpPrintsFloatsAsWritten) {
  const Result r = run("compare --help");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("default 0.0005)"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("0.000500000"), std::string::npos) << r.out;
}

TEST_F(BadOption, BenchIntoAnUnwritableFolderSaysWhy) {
  std::ofstream(dir_ / "file") << "x";
  const Result r = run("bench --quick -o '" + (dir_ / "file/sub").string() + "'");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("bench -o " + (dir_ / "file/sub").string() + ": cannot create the folder"), std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
}

// ---- hostile inputs and environments ----------------------------------------

TEST_F(HostileInput, CompareDiffThatIsAnInputIsRefusedBeforeAnyWork) {
  const fs::path golden = kSource / "tests/golden/stable_spin/stable_spin_f000015_fxaa.png";  // any PNG of the tree; not a lesson's, whose frames move
  fs::copy_file(golden, dir_ / "a.png");
  fs::copy_file(golden, dir_ / "b.png");
  fs::create_directories(dir_ / "sub");
  const std::string ab = "compare '" + (dir_ / "a.png").string() + "' '" + (dir_ / "b.png").string() + "'";
  for (const fs::path& diff : {dir_ / "b.png", dir_ / "sub/../a.png"}) {
    SCOPED_TRACE(diff.string());
    const Result r = run(ab + " --diff '" + diff.string() + "'");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("--diff " + diff.string() + ": is the input "), std::string::npos) << r.err;
    EXPECT_EQ(r.out.find("same"), std::string::npos) << "compared before refusing: " << r.out;
  }
  EXPECT_EQ(slurp(dir_ / "b.png"), slurp(golden)) << "the expected image was overwritten";
  const Result r = run(ab + " --diff '" + (dir_ / "no/such/folder/d.png").string() + "'");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("/no/such/folder/d.png: cannot write there: No such file or directory"), std::string::npos) << r.err;
}

TEST_F(HostileInput, DeeplyDottedTomlKeyIsExitTwoNamingTheLimit) {
  std::string key = "a";
  for (int i = 0; i < 50000; ++i) key += ".a";
  std::ofstream(dir_ / "deep.toml") << key << " = 1\n";
  const Result r = bounded("info '" + (dir_ / "deep.toml").string() + "'");
  EXPECT_EQ(r.code, 2) << r.err.substr(0, 400);  // was a segfault in toml++ (-1 here)
  EXPECT_NE(r.err.find("deep.toml:1:64: error: the scene has a key of more than 32 dotted parts (the key-depth limit)"),
            std::string::npos) << r.err.substr(0, 400);
}

TEST_F(HostileInput, PlyWhoseHeaderNeverEndsFailsAtOnceForEveryFill) {
  // assimp spun at 100 % CPU forever on this one.
  std::ofstream(dir_ / "endless.ply") << "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\n";
  for (const char* fill : {"volume", "surface", "vertices"}) {
    SCOPED_TRACE(fill);
    std::ofstream(dir_ / "m.toml") << "[[bodies]]\nshape = { type = \"mesh\", file = \"endless.ply\", fill = \"" << fill
                                   << "\" }\n";
    const Result r = bounded("info '" + (dir_ / "m.toml").string() + "'");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("endless.ply:5:1: the file ends before 'end_header'"), std::string::npos) << r.err;
  }
}

TEST_F(HostileInput, CloudCsvWithAByteOrderMarkLoads) {
  std::ofstream(dir_ / "excel.csv") << "\xEF\xBB\xBFx,y,z,m\r\n1,0,0,1\r\n-1,0,0,1\r\n0,1,0,0.5\r\n0,-1,0,0.5\r\n0,0,1,0.2\r\n";
  const Result r = bounded("info " + cloud_scene("excel.csv"));
  EXPECT_EQ(r.code, 0) << r.err;
}

TEST_F(HostileInput, InterruptedSimulateLeavesNoTempFileAndNoCsv) {
  const std::string csv = (dir_ / "run.csv").string();
  for (const char* sig : {"INT", "TERM"}) {
    SCOPED_TRACE(sig);
    // About 1e9 RK4 steps: minutes of work, stopped once its temp file exists
    // (killed at 60 s if the signal is lost: exit 137, a failure).
    const std::string cmd = "timeout -s KILL 60 '" + tumble_bin() + "' simulate " + scene("dzhanibekov.toml") +
                            " --csv '" + csv + "' --method rk4 --dt 1e-6 --duration 900 2>'" + (dir_ / "err").string() +
                            "' & p=$!; for i in $(seq 600); do ls '" + dir_.string() + "' | grep -q tmp- && break; sleep 0.05; done; "
                            "pkill -" + sig + " -P $p; wait $p; echo $? >'" + (dir_ / "code").string() + "'";
    std::ofstream(dir_ / "run.sh") << cmd << "\n";
    ASSERT_EQ(std::system(("bash '" + (dir_ / "run.sh").string() + "'").c_str()), 0);
    const std::string err = slurp(dir_ / "err");
    EXPECT_EQ(std::stoi(slurp(dir_ / "code")), 128 + (std::string(sig) == "INT" ? 2 : 15)) << err;
    EXPECT_NE(err.find(std::string("interrupted (SIG") + sig + "): no CSV written"), std::string::npos) << err;
    for (const auto& e : fs::directory_iterator(dir_))
      EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << "left behind: " << e.path();
    EXPECT_FALSE(fs::exists(csv));
  }
}

}  // namespace
