// One run of a scene (SceneRun): the frames, the sampled run behind the
// Python arrays and the glTF keys, and `simulate --every` see the same samples.
#include <gtest/gtest.h>

#include "base/error.hpp"
#include "scene/frame_runs.hpp"
#include "scene/sampled_run.hpp"
#include "scene/scene.hpp"
#include "scene/scene_run.hpp"

namespace {

using namespace tumble;

// Two bodies spinning at different rates, with trails (sub-frame samples between frames).
scene::Scene two_bodies(const std::string& method) {
  const std::string box = "shape = { type = \"box\", size = [0.3, 0.1, 0.02], resolution = 4, mass = 1.0 }\n";
  return scene::load_scene_from_string("[simulation]\nmethod = \"" + method + "\"\ndt = 1e-3\nduration = 1\nfps = 30\n"
                                       "[[bodies]]\nname = \"a\"\n" + box + "omega_body = [0.02, 10.0, 0.02]\n"
                                       "[[bodies]]\nname = \"b\"\n" + box + "position = [1, 0, 0]\n"
                                       "omega_body = [3.0, 0.1, 0.5]\n[draw]\ntrails = 1.0\n",
                                       "two.toml");
}

void expect_same(const scene::Trajectory& a, const scene::Trajectory& b, const std::string& what) {
  ASSERT_EQ(a.t, b.t) << what;
  ASSERT_EQ(a.arrays.size(), b.arrays.size());
  for (std::size_t i = 0; i < a.arrays.size(); ++i) EXPECT_EQ(a.arrays[i], b.arrays[i]) << what << ", array " << i;
}

TEST(SceneRun, TheFramesAndTheSampledRunSeeTheSameSamples) {
  for (const char* method : {"rk4", "splitting", "rk45", "exact"}) {
    const scene::Scene s = two_bodies(method);
    const std::vector<double> times = scene::sample_times(s.simulation.duration, s.simulation.fps);
    const scene::Run frames = scene::simulate_runs(s, static_cast<long>(times.size()), s.simulation.fps).front();
    ASSERT_GT(frames.path.size(), frames.frames.size()) << method;  // sub-frame samples were taken in between
    const std::vector<scene::Trajectory> sampled = scene::sample_run(s, s.simulation, times);
    ASSERT_EQ(frames.frames.size(), times.size()) << method;
    for (std::size_t b = 0; b < s.bodies.size(); ++b) {
      scene::Trajectory from_frames;
      for (std::size_t k = 0; k < times.size(); ++k)
        scene::append_sample(from_frames, times[k], s.bodies[b].model, frames.frames[k][b]);
      expect_same(from_frames, sampled[b], std::string(method) + " body " + s.bodies[b].name);
    }
  }
}

TEST(SceneRun, HandsEachTimeToEveryBodyInOrder) {
  const scene::Scene s = two_bodies("rk4");
  scene::SceneRun run(s, s.simulation);
  std::vector<std::pair<double, std::size_t>> seen;
  int after = 0;
  const std::vector<double> times{0.0, 0.25, 0.5};
  run.sample(times, [&](const scene::Sample& x) { seen.emplace_back(x.t, x.body); }, [&] { ++after; });
  const std::vector<std::pair<double, std::size_t>> want{{0.0, 0}, {0.0, 1}, {0.25, 0}, {0.25, 1}, {0.5, 0}, {0.5, 1}};
  EXPECT_EQ(seen, want);
  EXPECT_EQ(after, 3);
}

TEST(SceneRun, EveryNStepsLandsOnTheGridAndOnTheEnd) {
  scene::Scene s = two_bodies("rk4");
  s.simulation.duration = 0.0105;  // 10.5 steps of 1 ms: blocks of 4 end at 4, 8 ms, then the end
  scene::SceneRun run(s, s.simulation);
  std::vector<double> t;
  run.sample_every(4, s.simulation.duration, [&](const scene::Sample& x) {
    if (x.body == 0) t.push_back(x.t);
  });
  EXPECT_EQ(t, (std::vector<double>{0.0, 0.004, 0.008, 0.0105}));
  EXPECT_EQ(run.body(0).steps(), 10);  // grid steps taken; the end is a partial step from the 10th
}

}  // namespace
