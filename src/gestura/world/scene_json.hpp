#pragma once
// The scene's JSON form (docs/scene.md): reading with every error located at file:line:column and
// the value's JSON pointer, and writing back (what an editor saves).
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "gestura/world/scene.hpp"

namespace gestura {

inline constexpr std::size_t kMaxSceneBytes = std::size_t{16} << 20;

// Reads a scene file. Mesh files named in it are relative to its folder. Throws gestura::Error
// ("room.json:12:15: /objects/3/shape: unknown shape 'cube' (box, plane, cylinder, sphere, mesh)")
// for unreadable files, JSON syntax errors, unknown members, wrong types, unknown names, cycles of
// prototypes, non-finite or out-of-range numbers.
Scene read_scene(const std::string& path);

// The same from text; `name` is used in messages, `base_dir` resolves mesh files.
Scene parse_scene(std::string_view text, const std::string& name, const std::string& base_dir = ".");

// The scene as JSON in the documented form (reads back to an equal scene).
nlohmann::json scene_to_json(const Scene& scene);

// "#rrggbb" or [r, g, b] (0..1) → sRGB; throws gestura::Error mentioning `what` otherwise.
vec3 parse_scene_color(const nlohmann::json& value, const std::string& what);

}  // namespace gestura
