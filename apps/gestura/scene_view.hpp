#pragma once
// `gestura view --scene SCENE.json [--script FILE | --do TEXT] [--camera NAME] [--size WxH]
// [--screenshot PATH --frames N] [--at S]`: performs the scene and plays it in a window.
#include <string>
#include <vector>

namespace gestura::cli {

int run_scene_view(const std::vector<std::string>& args);

}  // namespace gestura::cli
