// A simulated scene as glTF 2.0 (tinygltf writes it), by glTF's conventions:
// y up (tumble's z-up world turned -90° about x: (x, y, z) -> (x, z, -y)),
// each body a node moved by LINEAR translation + rotation keys dense enough to
// follow the simulation (gltf/keyframes.hpp), its surfaces as a child, its
// principal axes as child nodes a viewer can hide, and the scene's camera
// with a light fixed to it (KHR_lights_punctual), as tumble renders it.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "gltf/keyframes.hpp"
#include "scene/sampled_run.hpp"
#include "scene/scene.hpp"

namespace tumble::gltf {

/// glTF's axes from tumble's world: (x, y, z) -> (x, z, -y). Blender's
/// importer turns y-up back into its own z-up, so there tumble's axes return.
Eigen::Quaterniond gltf_from_world();

/// The glTF of `s` with the motion of `tracks` (one per body, in tumble's
/// world, from key_tracks): binary (.glb) or JSON with the buffer embedded
/// (.gltf). Node names (node_names.hpp): the body's name with any character
/// outside [A-Za-z0-9_-] as '_'; "<body>_shape", "<body>_principal_axes" and
/// "<body>_axis1".."axis3" below it; "camera" with "camera_light" below it.
std::string gltf_bytes(const scene::Scene& s, const std::vector<scene::Trajectory>& tracks, bool binary);

/// Simulates `s` at key_tracks(s, keys) and writes `out` atomically; .glb or
/// .gltf by its extension (else InputError naming `option`). Returns the
/// trajectories written (tumble's world). `poll` as key_tracks takes it.
std::vector<scene::Trajectory> export_gltf(const scene::Scene& s, const std::filesystem::path& out,
                                           const KeyOptions& keys = {}, const std::string& option = "--gltf",
                                           const std::function<void()>& poll = {});

}  // namespace tumble::gltf
