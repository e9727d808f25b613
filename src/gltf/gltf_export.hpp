// A simulated scene as glTF 2.0 (tinygltf writes it): each body a node moved by
// translation + rotation keyframes, its mesh surfaces (else its principal box)
// as a child, and its principal axes as child nodes that a viewer can hide.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "scene/sampled_run.hpp"
#include "scene/scene.hpp"

namespace tumble::gltf {

/// The keyframe times of an export: k/fps up to the scene's duration (the
/// last is the duration), fps = `fps` or, when 0, the scene's output fps.
std::vector<double> keyframe_times(const scene::Scene& s, double fps = 0);

/// The glTF of `s` with the motion of `tracks` (one per body, from
/// scene::sample_run at keyframe_times): binary (.glb) or JSON with the
/// buffer embedded (.gltf). Node names: the body's name; "<body>/shape",
/// "<body>/principal_axes" and "<body>/axis1".."axis3" below it.
std::string gltf_bytes(const scene::Scene& s, const std::vector<scene::Trajectory>& tracks, bool binary);

/// Simulates `s` at keyframe_times(s, fps) and writes `out` atomically; .glb
/// or .gltf by its extension (else InputError naming `option`). Returns the
/// trajectories written.
std::vector<scene::Trajectory> export_gltf(const scene::Scene& s, const std::filesystem::path& out, double fps = 0,
                                           const std::string& option = "--gltf");

}  // namespace tumble::gltf
