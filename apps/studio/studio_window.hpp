#pragma once
// The studio's window: GLFW + Dear ImGui over the shared renderer. A thin adapter: the sign editor's
// state and every change live in gestura/studio (StudioModel); this draws it and turns clicks, keys
// and --script steps into its actions.
#include "gestura/app/context.hpp"
#include "gestura/app/studio.hpp"

namespace gestura::studio_ui {

// Runs until the window closes (or --frames / the script's quit). Returns the exit status.
int run_studio(const app::StudioRequest& request, const app::RunContext& context);

}  // namespace gestura::studio_ui
