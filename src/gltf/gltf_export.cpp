#include "gltf/gltf_export.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "base/error.hpp"
#include "compose/camera_fit.hpp"
#include "compose/world_views.hpp"
#include "gltf/model_builder.hpp"
#include "gltf/node_names.hpp"
#include "io/atomic_file.hpp"
#include "viz/body_look.hpp"
#include "viz/scene_view.hpp"

namespace tumble::gltf {

namespace {

/// The light of tumble's renderer (render/renderer.cpp): fixed to the camera,
/// from the upper left, towards the light in view space.
const Eigen::Vector3d kLightFromCamera = Eigen::Vector3d(-0.35, 0.55, 0.75).normalized();
/// Its KHR_lights_punctual intensity (lux): what three.js lights a matte body
/// with as tumble does; Blender's importer reads it in its "Unitless" mode.
constexpr double kLightLux = 3.0;

/// How the world view fits the scene's camera (compose/views/world.cpp): an
/// automatic camera moves up to 10× closer to fill the frame, 10 % clear at
/// its edges; a camera the scene places only backs off, 4 % clear.
constexpr double kAutoClosest = 0.1, kAutoMargin = 0.1, kFixedMargin = 0.04;
constexpr int kFitSamples = 240;

Eigen::Vector3d to_gltf(const Eigen::Vector3d& world) { return gltf_from_world() * world; }
glm::dvec3 to_glm(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

/// A body's pose at time t as a viewer plays its keys (lerp, slerp), tumble's world.
std::pair<Eigen::Vector3d, Eigen::Quaterniond> pose_at(const scene::Trajectory& tr, double t) {
  std::size_t k = 0;
  while (k + 2 < tr.size() && tr.t[k + 1] <= t) ++k;
  if (tr.size() < 2) return {Eigen::Vector3d(tr["c"][0], tr["c"][1], tr["c"][2]), Eigen::Quaterniond(tr["q"][0], tr["q"][1], tr["q"][2], tr["q"][3])};
  const double u = std::clamp((t - tr.t[k]) / (tr.t[k + 1] - tr.t[k]), 0.0, 1.0);
  const Eigen::Vector3d a(tr["c"][3 * k], tr["c"][3 * k + 1], tr["c"][3 * k + 2]), b(tr["c"][3 * k + 3], tr["c"][3 * k + 4], tr["c"][3 * k + 5]);
  const Eigen::Quaterniond qa(tr["q"][4 * k], tr["q"][4 * k + 1], tr["q"][4 * k + 2], tr["q"][4 * k + 3]);
  const Eigen::Quaterniond qb(tr["q"][4 * k + 4], tr["q"][4 * k + 5], tr["q"][4 * k + 6], tr["q"][4 * k + 7]);
  return {(1 - u) * a + u * b, qa.slerp(u, qb)};
}

/// The scene's camera (compose::scene_camera) fitted as the world view fits
/// it, to the bodies' principal boxes over the run, for a frame of `aspect`.
viz::Camera fitted_camera(const scene::Scene& s, const std::vector<scene::Trajectory>& tracks, double aspect,
                          std::size_t follow) {
  std::vector<std::vector<glm::dvec3>> centres(tracks.size());
  for (std::size_t i = 0; i < tracks.size(); ++i)
    for (std::size_t k = 0; k < tracks[i].size(); ++k)
      centres[i].emplace_back(tracks[i]["c"][3 * k], tracks[i]["c"][3 * k + 1], tracks[i]["c"][3 * k + 2]);
  const viz::Camera cam = compose::scene_camera(s, centres, aspect);
  std::vector<compose::Shot> shots;
  for (int j = 0; j < kFitSamples && !tracks.empty(); ++j) {
    const double t = s.simulation.duration * j / (kFitSamples - 1);
    compose::Shot shot{cam, {}};
    for (std::size_t i = 0; i < tracks.size(); ++i) {
      const auto [c, q] = pose_at(tracks[i], t);
      const RigidBodyModel& m = s.bodies[i].model;
      for (int bits = 0; bits < 8; ++bits) {
        const Eigen::Vector3d h = m.box.half_extents.cwiseProduct(Eigen::Vector3d(bits & 1 ? 1 : -1, bits & 2 ? 1 : -1, bits & 4 ? 1 : -1));
        shot.points.push_back(to_glm(c + q * (m.cloud_from_principal * (m.box.center + h))));
      }
      if (i == follow) {  // the camera keeps its offset from the body it follows
        shot.camera.position += to_glm(c) - cam.target;
        shot.camera.target = to_glm(c);
      }
    }
    shots.push_back(std::move(shot));
  }
  const bool automatic = s.render.camera.automatic;
  return compose::backed_off(cam, compose::backoff(shots, aspect, automatic ? kAutoMargin : kFixedMargin,
                                                   automatic ? kAutoClosest : 1.0));
}

/// The body's node tree; returns the node the keyframes move.
int add_body(Builder& b, NodeNames& names, const scene::Body& body) {
  const RigidBodyModel& m = body.model;
  const int root = b.node(names.add(body.name), -1);
  // Cloud axes about the centre of mass (the keyframes move the centre of mass).
  const int shape = b.node(names.add(body.name, "_shape"), root);
  const int axes = b.node(names.add(body.name, "_principal_axes"), root);
  b.at(axes).rotation = rotation(m.cloud_from_principal);
  // Its surfaces, as the renderer draws them: mesh files' and generated shapes' (a T-handle as a T).
  int mesh = -1;
  auto add = [&](const Geometry& g, const Eigen::Vector3d& color, const std::string& what) {
    if (!g.indices.empty()) mesh = b.primitive(mesh, b.at(root).name, g, b.material(color, b.at(root).name + what));
  };
  for (std::size_t i = 0; i < body.meshes.size(); ++i) {
    Geometry g;
    append_mesh(g, body.meshes[i].surface);
    add(g, body.meshes[i].color, "_mesh" + std::to_string(i));
  }
  for (std::size_t i = 0; i < body.shapes.size(); ++i)
    add(surface_geometry(*viz::solid_surface(body.shapes[i].shape)), body.shapes[i].color, "_solid" + std::to_string(i));
  if (mesh >= 0) {
    b.at(shape).mesh = mesh;
    b.at(shape).translation = vec(-m.com_cloud);
  } else {  // particles alone: the principal box, in the principal frame
    b.at(shape).rotation = rotation(m.cloud_from_principal);
    b.at(shape).mesh = b.primitive(-1, b.at(root).name + "_box",
                                   box_geometry(m.box.center - m.box.half_extents, m.box.center + m.box.half_extents),
                                   b.material(body.color, b.at(root).name));
  }
  // The axes as the renderer draws them (viz::axis_tip), as square bars.
  const double size = std::max(m.box.half_extents.maxCoeff(), 1e-3), w = 0.03 * size;
  for (int i = 0; i < 3; ++i) {
    const glm::dvec3 tip = viz::axis_tip(m, BodyState{}, i);
    const Eigen::Vector3d hi = Eigen::Vector3d(tip.x, tip.y, tip.z) + Eigen::Vector3d::Constant(w);
    const viz::Color& c = viz::kAxisColors[i];
    const std::string name = names.add(body.name, "_axis" + std::to_string(i + 1));
    b.node(name, axes, b.primitive(-1, name, box_geometry(Eigen::Vector3d::Constant(-w), hi),
                                   b.material(Eigen::Vector3d(c.r, c.g, c.b), name)));
  }
  return root;
}

/// The keys of `tr` as glTF values: positions (x, z, -y) and rotations
/// glTF ← cloud, each on the hemisphere of the one before (q·q_prev >= 0:
/// viewers slerp the short way, which the keys are dense enough to be right).
std::pair<std::vector<float>, std::vector<float>> key_values(const scene::Trajectory& tr) {
  const std::size_t n = tr.size();
  std::vector<float> pos(3 * n), rot(4 * n);
  Eigen::Quaterniond prev = Eigen::Quaterniond::Identity();
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Vector3d c = to_gltf(Eigen::Vector3d(tr["c"][3 * k], tr["c"][3 * k + 1], tr["c"][3 * k + 2]));
    Eigen::Quaterniond q = gltf_from_world() * Eigen::Quaterniond(tr["q"][4 * k], tr["q"][4 * k + 1], tr["q"][4 * k + 2], tr["q"][4 * k + 3]);
    if (k > 0 && q.dot(prev) < 0) q.coeffs() = -q.coeffs();
    prev = q;
    for (int i = 0; i < 3; ++i) pos[3 * k + i] = static_cast<float>(c[i]);
    const std::vector<double> r = rotation(q);
    for (int i = 0; i < 4; ++i) rot[4 * k + i] = static_cast<float>(r[i]);
  }
  return {pos, rot};
}

/// The body's LINEAR translation and rotation channels; returns its times' accessor.
int add_motion(Builder& b, tinygltf::Animation& anim, int node, const scene::Trajectory& tr) {
  const auto [pos, rot] = key_values(tr);
  b.at(node).translation = {pos[0], pos[1], pos[2]};
  b.at(node).rotation = {rot[0], rot[1], rot[2], rot[3]};
  if (tr.size() < 2) return -1;  // one keyframe is no animation: the node's pose says it
  const int times = b.floats(std::vector<float>(tr.t.begin(), tr.t.end()), TINYGLTF_TYPE_SCALAR, 1, 0, true);
  b.channel(anim, node, "translation", times, b.floats(pos, TINYGLTF_TYPE_VEC3, 3, 0, false));
  b.channel(anim, node, "rotation", times, b.floats(rot, TINYGLTF_TYPE_VEC4, 4, 0, false));
  return times;
}

/// The rotation of a glTF camera (looking along its -z, +y up) at `eye`
/// looking at `target` with `up`, all in glTF's axes.
Eigen::Quaterniond look_at(const Eigen::Vector3d& eye, const Eigen::Vector3d& target, const Eigen::Vector3d& up) {
  const Eigen::Vector3d back = (eye - target).normalized();
  const Eigen::Vector3d right = up.cross(back).normalized();
  Eigen::Matrix3d r;
  r << right, back.cross(right), back;
  return Eigen::Quaterniond(r).normalized();
}

/// The scene's camera as the renderer places it (fitted_camera, also
/// following a body), and the renderer's light fixed to it.
void add_camera(Builder& b, NodeNames& names, tinygltf::Animation& anim, const scene::Scene& s,
                const std::vector<scene::Trajectory>& tracks, const std::vector<int>& times) {
  const double aspect = static_cast<double>(s.render.output.width) / s.render.output.height;
  const scene::Body* follow = s.find_body(s.render.camera.follow);
  const std::size_t f = follow ? static_cast<std::size_t>(follow - s.bodies.data()) : tracks.size();
  const viz::Camera cam = fitted_camera(s, tracks, aspect, f);
  auto eig = [](const glm::dvec3& v) { return Eigen::Vector3d(v.x, v.y, v.z); };
  tinygltf::Camera c;
  c.type = "perspective";
  c.name = "camera";
  c.perspective.aspectRatio = aspect;
  c.perspective.yfov = cam.fov_y_deg * std::numbers::pi / 180;
  c.perspective.znear = cam.near_m;
  c.perspective.zfar = cam.far_m;
  b.model().cameras.push_back(c);
  const int node = b.node(names.add("camera"), -1);
  b.at(node).camera = static_cast<int>(b.model().cameras.size() - 1);
  b.at(node).translation = vec(to_gltf(eig(cam.position)));
  b.at(node).rotation = rotation(look_at(to_gltf(eig(cam.position)), to_gltf(eig(cam.target)), to_gltf(eig(viz::view_up(cam)))));
  // A camera that follows a body keeps its offset from the body's centre of mass.
  if (f < tracks.size() && times[f] >= 0) {
    std::vector<float> pos;
    const Eigen::Vector3d offset = eig(cam.position - cam.target);
    for (std::size_t k = 0; k < tracks[f].size(); ++k) {
      const Eigen::Vector3d p = to_gltf(Eigen::Vector3d(tracks[f]["c"][3 * k], tracks[f]["c"][3 * k + 1], tracks[f]["c"][3 * k + 2]) + offset);
      pos.insert(pos.end(), {static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())});
    }
    b.channel(anim, node, "translation", times[f], b.floats(pos, TINYGLTF_TYPE_VEC3, 3, 0, false));
  }
  tinygltf::Light light;
  light.name = "light";
  light.type = "directional";
  light.color = {1.0, 1.0, 1.0};
  light.intensity = kLightLux;
  b.model().lights.push_back(light);
  const int l = b.node(names.add("camera", "_light"), node);
  // A directional light shines along its node's -z: +z towards the light.
  b.at(l).rotation = rotation(Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), kLightFromCamera));
  tinygltf::Value::Object ext{{"light", tinygltf::Value(static_cast<int>(b.model().lights.size() - 1))}};
  b.at(l).extensions["KHR_lights_punctual"] = tinygltf::Value(ext);
}

}  // namespace

Eigen::Quaterniond gltf_from_world() {
  return Eigen::Quaterniond(Eigen::AngleAxisd(-std::numbers::pi / 2, Eigen::Vector3d::UnitX()));
}

std::string gltf_bytes(const scene::Scene& s, const std::vector<scene::Trajectory>& tracks, bool binary) {
  Builder b;
  b.model().scenes[0].name = s.name;
  NodeNames names;
  tinygltf::Animation anim;
  anim.name = "motion";
  std::vector<int> times;
  for (std::size_t i = 0; i < s.bodies.size() && i < tracks.size(); ++i)
    times.push_back(add_motion(b, anim, add_body(b, names, s.bodies[i]), tracks[i]));
  add_camera(b, names, anim, s, tracks, times);
  if (!anim.channels.empty()) b.model().animations.push_back(std::move(anim));
  std::ostringstream out;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&b.model(), out, !binary, binary)) throw std::runtime_error("glTF: tinygltf could not write the model");
  return std::move(out).str();
}

std::vector<scene::Trajectory> export_gltf(const scene::Scene& s, const std::filesystem::path& out, const KeyOptions& keys,
                                           const std::string& option, const std::function<void()>& poll) {
  const std::string ext = out.extension().string();
  if (ext != ".glb" && ext != ".gltf")
    throw InputError(option + " " + out.string() + ": expected a file name ending in .glb or .gltf");
  std::vector<scene::Trajectory> tracks = key_tracks(s, keys, poll);
  io::atomic_write_file(out, gltf_bytes(s, tracks, ext == ".glb"));
  return tracks;
}

}  // namespace tumble::gltf
