// The message a scene's text is refused with, for the tests of the loader's checks.
#pragma once

#include <string>

#include "scene/scene.hpp"

/// load_scene_from_string(text, name)'s SceneError message, or "" when the scene loads.
inline std::string scene_error(const std::string& text, const std::string& name) {
  try {
    (void)tumble::scene::load_scene_from_string(text, name);
  } catch (const tumble::scene::SceneError& e) {
    return e.what();
  }
  return "";
}
