#pragma once
// `gestura view --scene SCENE.json`: the scene performed (app/scene.hpp) and played in a window.
#include "gestura/app/context.hpp"
#include "gestura/app/scene.hpp"

namespace gestura::cli {

int show_scene(const app::SceneViewRequest& request, const app::RunContext& context);

}  // namespace gestura::cli
