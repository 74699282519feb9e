#pragma once
// Driving the real studio window in the tests: under a virtual X server, with a --script of UI
// actions. Shared by the sign-editor, timeline/figure and environment-editor tests.
#include <string>

#include <nlohmann/json.hpp>

#include "lexicon/temp_dir.hpp"
#include "support/cli.hpp"

namespace gestura { struct BvhFile; }

namespace gestura::test {

bool have_xvfb();

// Runs `gestura studio DB --size SIZE --script FILE` under xvfb-run, the script written as
// `script_name` in `dir` (at most 300 s).
CliRun run_studio(const gestura::testing::TempDir& dir, const std::string& db, const std::string& script_name,
                  const std::string& script, const std::string& size = "1280x800");

// A JSON file the studio wrote (a dump); null when missing or malformed.
nlohmann::json read_json_file(const std::string& path);

// Where screenshots go: $GESTURA_STUDIO_SCREENSHOTS when set (docs/studio.md uses them), else `dir`.
std::string shot_dir(const gestura::testing::TempDir& dir);

// The time at which `joint` is turned furthest from its first frame in an exported BVH (-1 if absent).
float peak_time(const gestura::BvhFile& bvh, const std::string& joint);

}  // namespace gestura::test
